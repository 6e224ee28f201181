#include "vtkVolGridTetrahedralize.h"

#include "VolGridConversion.h"
#include "VolGridFilterProgress.h"

#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include "Delaunay.h"
#include "MeshChecker.h"

#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkVolGridTetrahedralize);

vtkVolGridTetrahedralize::vtkVolGridTetrahedralize() = default;

int vtkVolGridTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}


int vtkVolGridTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  output->Initialize();
  const vtkIdType numInput = input ? input->GetNumberOfPoints() : 0;

  std::vector<double> xyz(3 * static_cast<size_t>(numInput));
  for (vtkIdType i = 0; i < numInput; ++i)
  {
    input->GetPoint(i, xyz.data() + 3 * i);
  }

  volgrid::DelaunayOptions options;
  options.spatialSort = this->SpatialSort;
  options.seed = static_cast<uint64_t>(this->RandomSeed) + 1;
  options.keepGhosts = this->CheckOutput; // the checker verifies the hull through the ghost tets
  volgrid::TetMesh mesh;
  std::vector<int32_t> inputToVertex;
  VolGridFilterProgress progress(this, 0.0, this->CheckOutput ? 0.7 : 0.95);
  volgrid::DelaunayReport report;
  const volgrid::Status status =
    volgrid::buildDelaunay(xyz.data(), xyz.size() / 3, options, mesh, inputToVertex, &progress, &report);
  if (!status.ok())
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: " << status.message);
    return 0;
  }
  if (report.numDuplicates > 0)
  {
    vtkWarningMacro(<< report.numDuplicates << " duplicate point(s) merged (first input id "
                    << (report.firstDuplicates.empty() ? -1 : report.firstDuplicates[0])
                    << "); InputPointId maps output points to input points.");
  }
  if (this->CheckOutput)
  {
    this->SetProgressText("Checking the mesh");
    const volgrid::MeshCheckReport check = volgrid::checkMesh(mesh);
    if (!check.valid)
    {
      vtkErrorMacro(<< "VolGrid Tetrahedralize: the output failed its check: " << check.summary());
      return 0;
    }
    mesh.removeGhostTets();
  }

  // Output points: one per distinct location, in input order (vertex i is input point i).
  std::vector<int32_t> keptVertices;
  keptVertices.reserve(static_cast<size_t>(numInput));
  for (vtkIdType i = 0; i < numInput; ++i)
  {
    if (inputToVertex[i] == i)
    {
      keptVertices.push_back(static_cast<int32_t>(i));
    }
  }
  VolGridFillUnstructuredGrid(mesh, keptVertices, output);
  const vtkIdType numOutput = static_cast<vtkIdType>(keptVertices.size());
  auto kept = vtkSmartPointer<vtkIdTypeArray>::New();
  kept->SetName("InputPointId");
  kept->SetNumberOfValues(numOutput);
  for (vtkIdType o = 0; o < numOutput; ++o)
  {
    kept->SetValue(o, keptVertices[o]);
  }

  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  if (numOutput == numInput)
  {
    outPD->PassData(inPD);
  }
  else
  {
    outPD->CopyAllocate(inPD, numOutput);
    for (vtkIdType o = 0; o < numOutput; ++o)
    {
      outPD->CopyData(inPD, kept->GetValue(o), o);
    }
  }
  outPD->AddArray(kept);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkVolGridTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SpatialSort: " << this->SpatialSort << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "CheckOutput: " << this->CheckOutput << "\n";
}
