#include "VolGridSolverMeshFromGrid.h"

#include "VolGridConversion.h"

#include "vtkCellData.h"
#include "vtkCellIterator.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include "BoundaryFaceOwners.h"
#include "SolverMesh.h"

bool VolGridSolverMeshFromGrid(vtkUnstructuredGrid* grid, volgrid::SolverMesh& mesh, std::string& error)
{
  mesh = volgrid::SolverMesh();
  const vtkIdType numCells = grid ? grid->GetNumberOfCells() : 0;
  if (numCells == 0)
  {
    error = "the input has no cells";
    return false;
  }
  vtkDataArray* facePatch = grid->GetCellData()->GetArray("BoundaryFacePatch");
  if (!facePatch || facePatch->GetNumberOfComponents() != 4)
  {
    error = "the input has no BoundaryFacePatch cell array (4 components), so its boundary patches are unknown; "
            "write the volume output of VolGrid Tetrahedralize or a mesh read by VolGrid";
    return false;
  }
  vtkDataArray* region = grid->GetCellData()->GetArray("Region");
  vtkIdType nonTets = 0;
  auto cells = vtkSmartPointer<vtkCellIterator>::Take(grid->NewCellIterator());
  for (cells->InitTraversal(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    if (cells->GetCellType() != VTK_TETRA)
    {
      ++nonTets;
      continue;
    }
    const vtkIdType c = cells->GetCellId();
    const vtkIdType* ids = cells->GetPointIds()->GetPointer(0);
    for (int k = 0; k < 4; ++k)
      mesh.tets.push_back(static_cast<int32_t>(ids[k]));
    mesh.tetRegion.push_back(region ? static_cast<int32_t>(region->GetComponent(c, 0)) : 1);
    for (int side = 0; side < 4; ++side)
    {
      const double patch = facePatch->GetComponent(c, side);
      if (patch < 0)
        continue;
      for (int corner : volgrid::kExodusTetSide[side])
        mesh.triangles.push_back(static_cast<int32_t>(ids[corner]));
      mesh.trianglePatch.push_back(static_cast<int32_t>(patch));
    }
  }
  if (nonTets > 0)
  {
    error = std::to_string(nonTets) + " of the input's " + std::to_string(numCells) +
      " cells are not tetrahedra (the solver formats take tet meshes)";
    return false;
  }
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  mesh.points.resize(static_cast<size_t>(3 * numPoints));
  for (vtkIdType i = 0; i < numPoints; ++i)
    grid->GetPoint(i, mesh.points.data() + 3 * i);
  vtkPointData* pointData = grid->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pointData->GetArray(a);
    if (!array || !array->GetName() || array->GetNumberOfComponents() != 1)
      continue; // the solver formats' point fields are scalars
    std::vector<double>& values = mesh.pointData[array->GetName()];
    values.resize(static_cast<size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
      values[i] = array->GetComponent(i, 0);
  }
  mesh.patchNames = VolGridReadLabelNames(grid, "PatchNames");
  mesh.regionNames = VolGridReadLabelNames(grid, "RegionNames");
  return true;
}
