#include "vtkVolGridTetrahedralize.h"

#include "PatchNames.h"

#include "VolGridConversion.h"
#include "VolGridFilterProgress.h"
#include "VolGridLayeredConversion.h"
#include "VolGridMesherProgress.h"
#include "VolGridParallel.h"
#include "VolGridSurfaceConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include "AvailableMemory.h"
#include "BoundaryLayers.h"
#include "Delaunay.h"
#include "LayeredMesher.h"
#include "MeshChecker.h"
#include "Mesher.h"
#include "OptionTable.h"
#include "SizeEstimate.h"
#include "SurfaceMesh.h"

#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkVolGridTetrahedralize);

vtkVolGridTetrahedralize::vtkVolGridTetrahedralize()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  // The Core defaults are the filter's defaults.
  const volgrid::ImprovementOptions defaults;
  this->FieldPoints = defaults.fieldPoints;
  this->Alpha = defaults.fieldPointOptions.alpha;
  this->Beta = defaults.fieldPointOptions.beta;
  this->Gradation = defaults.sizing.gradation;
  this->SizeScale = defaults.sizing.scale;
  this->Optimize = defaults.optimize;
  this->TargetMinDihedral = defaults.optimization.targetDegrees;
  this->MaxPasses = defaults.optimization.maxPasses;
  this->Smoothing = defaults.optimization.smoothing;
  this->OrthogonalityFirst = defaults.orthogonalityFirst;
  const volgrid::LayerOptions layerDefaults;
  this->NumberOfLayers = layerDefaults.layers;
  this->FirstLayerHeight = layerDefaults.firstHeight;
  this->LayerGrowthRatio = layerDefaults.growth;
  this->TotalLayerThickness = layerDefaults.thickness;
  this->SplitPrisms = layerDefaults.splitPrisms;
  this->KeepWallTriangles = layerDefaults.keepWallTriangles;
}

namespace
{
// Sets `member` to `value` clamped to the option's valid range; true when it changed.
template<typename T>
bool setClamped(T& member, double value, const volgrid::OptionSpec& spec)
{
  const T clamped = static_cast<T>(spec.clamp(value));
  if (member == clamped)
    return false;
  member = clamped;
  return true;
}
} // namespace

#define VOLGRID_OPTION_SETTER(Name, Type, Spec)                                                                        \
  void vtkVolGridTetrahedralize::Set##Name(Type value)                                                                 \
  {                                                                                                                    \
    if (setClamped(this->Name, value, volgrid::option::Spec))                                                          \
      this->Modified();                                                                                                \
  }
VOLGRID_OPTION_SETTER(Alpha, double, alpha)
VOLGRID_OPTION_SETTER(Beta, double, beta)
VOLGRID_OPTION_SETTER(Gradation, double, gradation)
VOLGRID_OPTION_SETTER(SizeScale, double, sizeScale)
VOLGRID_OPTION_SETTER(MaxEdgeLength, double, maxEdge)
VOLGRID_OPTION_SETTER(MaxVolume, double, maxVolume)
VOLGRID_OPTION_SETTER(TargetMinDihedral, double, targetAngle)
VOLGRID_OPTION_SETTER(MaxPasses, int, passes)
VOLGRID_OPTION_SETTER(NumberOfLayers, int, layers)
VOLGRID_OPTION_SETTER(FirstLayerHeight, double, firstHeight)
VOLGRID_OPTION_SETTER(LayerGrowthRatio, double, growth)
VOLGRID_OPTION_SETTER(TotalLayerThickness, double, layerThickness)
#undef VOLGRID_OPTION_SETTER

vtkVolGridTetrahedralize::~vtkVolGridTetrahedralize()
{
  this->SetSourceSizeArray(nullptr);
  this->SetPatchAssignment(nullptr);
  this->SetLayerPatches(nullptr);
}

void vtkVolGridTetrahedralize::SetSourceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

int vtkVolGridTetrahedralize::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkVolGridTetrahedralize::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

namespace
{
// True when the data set has cells a surface is made of (triangles, polygons, strips).
bool hasSurfaceCells(vtkPointSet* input)
{
  if (auto* poly = vtkPolyData::SafeDownCast(input))
  {
    return poly->GetNumberOfPolys() + poly->GetNumberOfStrips() > 0;
  }
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const int type = input->GetCellType(c);
    if (type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON || type == VTK_TRIANGLE_STRIP)
    {
      return true;
    }
  }
  return false;
}

// BlockId = Region + 1 (1 without regions): the EnSight writer needs it (one EnSight part per region).
void addBlockIds(vtkUnstructuredGrid* mesh)
{
  vtkDataArray* region = mesh->GetCellData()->GetArray("Region");
  auto block = vtkSmartPointer<vtkIntArray>::New();
  block->SetName("BlockId");
  block->SetNumberOfValues(mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    block->SetValue(c, region ? static_cast<int>(region->GetComponent(c, 0)) + 1 : 1);
  }
  mesh->GetCellData()->AddArray(block);
}
} // namespace

namespace
{
// The point data of the input points on the output points (the first input point of each merged
// location); the points the mesher added get the arrays' null values.
void copyInputPointData(vtkPointSet* input, const volgrid::MesherResult& result, vtkUnstructuredGrid* output)
{
  const vtkIdType numPoints = output->GetNumberOfPoints();
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  std::vector<vtkIdType> outputToInput(static_cast<size_t>(numPoints), -1);
  for (size_t i = 0; i < result.inputToOutputPoint.size(); ++i)
  {
    const int32_t o = result.inputToOutputPoint[i];
    if (o >= 0 && outputToInput[o] < 0)
      outputToInput[o] = static_cast<vtkIdType>(i);
  }
  outPD->CopyAllocate(inPD, numPoints);
  for (vtkIdType o = 0; o < numPoints; ++o)
  {
    if (outputToInput[o] >= 0)
      outPD->CopyData(inPD, outputToInput[o], o);
    else
      outPD->NullData(o);
  }
}

// The input's cell data on the boundary triangles (each from its input triangle), the mesher's
// PatchId kept; only when every input cell was one triangle, so that the ids correspond.
void copyInputCellData(vtkPointSet* input, const volgrid::MesherResult& result, vtkPolyData* boundary)
{
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = boundary->GetCellData();
  const vtkIdType numBoundary = static_cast<vtkIdType>(result.boundaryInputTriangle.size());
  // CopyAllocate clears the output's arrays: keep the mesher's PatchId aside.
  vtkSmartPointer<vtkDataArray> patch = outCD->GetArray("PatchId");
  outCD->CopyAllocate(inCD, numBoundary);
  for (vtkIdType b = 0; b < numBoundary; ++b)
    outCD->CopyData(inCD, result.boundaryInputTriangle[b], b);
  outCD->RemoveArray("PatchId");
  outCD->AddArray(patch);
}

// Surface Prep's diagnostic arrays describe its surface, not the mesh: they stop here.
void dropSurfaceDiagnostics(vtkUnstructuredGrid* output, vtkPolyData* boundary)
{
  for (const char* name : { "DefectFlags", "OpenEdge", "NonManifoldEdge", "SelfIntersecting", "Degenerate" })
  {
    boundary->GetCellData()->RemoveArray(name);
  }
  output->GetPointData()->RemoveArray("NonManifoldVertex");
  boundary->GetPointData()->RemoveArray("NonManifoldVertex");
}
} // namespace

int vtkVolGridTetrahedralize::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                          vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  boundary->Initialize();
  vtkDataSet* sources = this->GetNumberOfInputConnections(1) > 0 ? vtkDataSet::GetData(inputVector[1]) : nullptr;
  vtkMultiProcessController* controller = VolGridParallelController();
  if (!controller)
  {
    const int ok = this->Execute(input, sources, output, boundary);
    VolGridConsumeAbort(this);
    return ok;
  }
  // Several ranks: the whole input is meshed once on rank 0 (the boundary stays there), and the tets are
  // handed out in compact pieces with global ids. A rank's empty piece is normal; an empty whole is an error.
  vtkSmartPointer<vtkPointSet> whole = VolGridGatherPointSet(controller, input);
  vtkSmartPointer<vtkDataSet> wholeSources;
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    wholeSources = VolGridGatherPointSet(controller, sources);
  }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  const bool root = controller->GetLocalProcessId() == 0;
  const int ok = root ? this->Execute(whole, wholeSources, mesh, boundary) : 1;
  VolGridConsumeAbort(this);
  if (!VolGridBroadcastFlag(controller, ok != 0))
  {
    return 0; // on every rank, so that no rank runs the filters downstream alone
  }
  VolGridDistributeCells(controller, mesh, output);
  return 1;
}

int vtkVolGridTetrahedralize::Execute(vtkPointSet* input, vtkDataSet* sources, vtkUnstructuredGrid* output,
                                      vtkPolyData* boundary)
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: the input is empty (no points).");
    return 0;
  }
  const bool surface = this->InputMode == SURFACE || (this->InputMode == AUTOMATIC && hasSurfaceCells(input));
  const int ok =
    surface ? this->MeshSurface(input, sources, output, boundary) : this->TetrahedralizePoints(input, output);
  if (ok)
  {
    addBlockIds(output);
  }
  return ok;
}

// The filter's properties as the mesher's options.
volgrid::MesherOptions vtkVolGridTetrahedralize::MakeMesherOptions() const
{
  volgrid::MesherOptions options;
  options.regionRule = this->RegionRule == ORIENTATION ? volgrid::RegionRule::Orientation
    : this->RegionRule == KEEP_ALL                     ? volgrid::RegionRule::KeepAll
                                                       : volgrid::RegionRule::EvenOdd;
  options.allowSteinerPoints = this->AllowSteinerPoints;
  options.verify = this->CheckOutput;
  volgrid::ImprovementOptions& im = options.improvement;
  im.fieldPoints = this->FieldPoints;
  im.fieldPointOptions.alpha = this->Alpha;
  im.fieldPointOptions.beta = this->Beta;
  im.fieldPointOptions.maxVolume = this->MaxVolume;
  im.sizing.gradation = this->Gradation;
  im.sizing.scale = this->SizeScale;
  im.sizing.maxEdgeLength = this->MaxEdgeLength;
  im.optimize = this->Optimize;
  im.optimization.targetDegrees = this->TargetMinDihedral;
  im.optimization.maxPasses = this->MaxPasses;
  im.optimization.smoothing = this->Smoothing;
  im.orthogonalityFirst = this->OrthogonalityFirst;
  return options;
}

// The Sources points as sizing samples (SizingFromSources) and/or cluster points (ClusterSourcePoints),
// with their SourceSizeArray values; false (after the error) when a named array is missing.
bool vtkVolGridTetrahedralize::TakeSourcePoints(vtkDataSet* sources, volgrid::ImprovementOptions& im)
{
  if (!sources || sources->GetNumberOfPoints() == 0)
  {
    return true;
  }
  const vtkIdType n = sources->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<size_t>(n)), sizes;
  for (vtkIdType i = 0; i < n; ++i)
    sources->GetPoint(i, xyz.data() + 3 * i);
  vtkDataArray* sizeArray = nullptr;
  if (this->SourceSizeArray && *this->SourceSizeArray)
  {
    sizeArray = sources->GetPointData()->GetArray(this->SourceSizeArray);
    if (!sizeArray)
    {
      vtkErrorMacro(<< "VolGrid Tetrahedralize: Sources has no point array '" << this->SourceSizeArray << "'.");
      return false;
    }
    sizes.resize(static_cast<size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      sizes[i] = sizeArray->GetComponent(i, 0);
  }
  if (this->SizingFromSources)
  {
    if (!sizeArray)
    {
      vtkErrorMacro(<< "VolGrid Tetrahedralize: SizingFromSources needs SourceSizeArray.");
      return false;
    }
    im.sizingPoints = xyz;
    im.sizingValues = sizes;
  }
  if (this->ClusterSourcePoints)
  {
    im.clusterPoints = std::move(xyz);
    im.clusterSizes = std::move(sizes);
  }
  return true;
}

// The input's triangles (polygons and strips triangulated, with a warning; other cells ignored, with a
// warning); false (after the error) when there are none.
bool vtkVolGridTetrahedralize::ConvertInput(vtkPointSet* input, volgrid::SurfaceMesh& surface,
                                            VolGridSurfaceConversionInfo& converted)
{
  if (!VolGridPolyDataToSurfaceMesh(input, surface, &converted))
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: the input has no triangles or polygons to mesh.");
    return false;
  }
  if (converted.polygons + converted.strips > 0)
  {
    vtkWarningMacro(<< converted.polygons << " polygon(s) and " << converted.strips
                    << " strip(s) were triangulated before meshing.");
  }
  if (converted.skippedCells + converted.invalidCells > 0)
  {
    vtkWarningMacro(<< converted.skippedCells << " cell(s) that are not surface cells and " << converted.invalidCells
                    << " cell(s) with invalid point ids were ignored.");
  }
  return true;
}

// False (after the error) when the estimated mesh would not fit in the available memory.
bool vtkVolGridTetrahedralize::FitsInMemory(const volgrid::SurfaceMesh& surface, const volgrid::MesherOptions& options)
{
  const volgrid::SizeEstimate estimate = volgrid::estimateMeshSize(surface, options.improvement);
  if (estimate.bytes > volgrid::availableMemoryBytes())
  {
    vtkErrorMacro(
      << "VolGrid Tetrahedralize: these sizes would make about " << estimate.tets << " tets on " << estimate.points
      << " points, needing about " << estimate.bytes / 1073741824.0 << " GiB of memory, more than the "
      << volgrid::availableMemoryBytes() / 1073741824.0
      << " GiB available: refused before any work (choose a larger MaxEdgeLength, MaxVolume or SizeScale).");
    return false;
  }
  return true;
}

// The names of the boundary patches: the input's PatchNames, then the PatchAssignment property (which
// also renumbers result.boundaryPatch); false (after the error) on a bad assignment.
bool vtkVolGridTetrahedralize::AssignPatches(vtkPointSet* input, volgrid::MesherResult& result,
                                             std::map<int32_t, std::string>& patchNames)
{
  patchNames = VolGridReadLabelNames(input, "PatchNames");
  if (this->PatchAssignment && *this->PatchAssignment)
  {
    volgrid::PatchAssignment assignment;
    volgrid::Status s = volgrid::parsePatchAssignment(this->PatchAssignment, assignment);
    if (s.ok())
      s = volgrid::applyPatchAssignment(assignment, result.boundaryPatch, patchNames);
    if (!s.ok())
    {
      vtkErrorMacro(<< "VolGrid Tetrahedralize: PatchAssignment: " << s.message);
      return false;
    }
  }
  return true;
}

int vtkVolGridTetrahedralize::MeshSurface(vtkPointSet* input, vtkDataSet* sources, vtkUnstructuredGrid* output,
                                          vtkPolyData* boundary)
{
  volgrid::SurfaceMesh surface;
  VolGridSurfaceConversionInfo converted;
  volgrid::MesherOptions options = this->MakeMesherOptions();
  if (!this->ConvertInput(input, surface, converted) || !this->TakeSourcePoints(sources, options.improvement) ||
      !this->FitsInMemory(surface, options))
  {
    return 0;
  }
  if (this->NumberOfLayers > 0)
    return this->MeshWithLayers(surface, options, output, boundary);
  volgrid::MesherResult result;
  VolGridMesherProgress progress(this);
  const volgrid::Status status = volgrid::meshSurface(surface, options, result, &progress);
  if (!status.ok())
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: " << status.message);
    return 0;
  }
  for (const std::string& warning : result.warnings)
  {
    vtkWarningMacro(<< warning);
  }
  std::map<int32_t, std::string> patchNames;
  if (!this->AssignPatches(input, result, patchNames))
  {
    return 0;
  }
  VolGridFillFromMesherResult(result, output, boundary);
  VolGridSetPatchAndRegionNames(result, patchNames, VolGridReadLabelNames(input, "RegionNames"), output, boundary);
  copyInputPointData(input, result, output);
  // Port 1 (boundary triangles with PatchId): the point data, and the input's cell data.
  boundary->GetPointData()->ShallowCopy(output->GetPointData());
  const bool allTriangles =
    converted.polygons + converted.strips + converted.skippedCells + converted.invalidCells == 0 &&
    input->GetNumberOfCells() == surface.numberOfTriangles();
  if (allTriangles)
  {
    copyInputCellData(input, result, boundary);
  }
  dropSurfaceDiagnostics(output, boundary);
  output->GetCellData()->SetActiveScalars("Region");
  boundary->GetCellData()->SetActiveScalars("PatchId");
  this->UpdateProgress(1.0);
  return 1;
}

int vtkVolGridTetrahedralize::MeshWithLayers(const volgrid::SurfaceMesh& surface, const volgrid::MesherOptions& options,
                                             vtkUnstructuredGrid* output, vtkPolyData* boundary)
{
  if (this->PatchAssignment && *this->PatchAssignment)
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: PatchAssignment is not supported together with boundary layers yet.");
    return 0;
  }
  volgrid::LayerOptions layers;
  layers.layers = this->NumberOfLayers;
  layers.firstHeight = this->FirstLayerHeight;
  layers.growth = this->LayerGrowthRatio;
  layers.thickness = this->TotalLayerThickness;
  layers.splitPrisms = this->SplitPrisms;
  layers.keepWallTriangles = this->KeepWallTriangles;
  if (this->LayerPatches)
    volgrid::addLayerPatches(this->LayerPatches, layers);
  volgrid::LayeredMeshResult result;
  VolGridMesherProgress progress(this);
  const volgrid::Status status = volgrid::meshSurfaceWithLayers(surface, options, layers, result, &progress);
  if (!status.ok())
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: " << status.message);
    return 0;
  }
  for (const std::string& warning : result.warnings)
  {
    vtkWarningMacro(<< warning);
  }
  VolGridFillFromLayeredResult(result, output, boundary);
  this->UpdateProgress(1.0);
  return 1;
}

int vtkVolGridTetrahedralize::TetrahedralizePoints(vtkPointSet* input, vtkUnstructuredGrid* output)
{
  const vtkIdType numInput = input->GetNumberOfPoints();
  const volgrid::SizeEstimate estimate = volgrid::estimateDelaunaySize(static_cast<double>(numInput));
  if (estimate.bytes > volgrid::availableMemoryBytes())
  {
    vtkErrorMacro(<< "VolGrid Tetrahedralize: " << numInput << " points would make about " << estimate.tets
                  << " tets, needing about " << estimate.bytes / 1073741824.0 << " GiB of memory, more than the "
                  << volgrid::availableMemoryBytes() / 1073741824.0 << " GiB available: refused before any work.");
    return 0;
  }
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
  os << indent << "InputMode: " << this->InputMode << "\n";
  os << indent << "RegionRule: " << this->RegionRule << "\n";
  os << indent << "AllowSteinerPoints: " << this->AllowSteinerPoints << "\n";
  os << indent << "PatchAssignment: " << (this->PatchAssignment ? this->PatchAssignment : "(none)") << "\n";
  os << indent << "SpatialSort: " << this->SpatialSort << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "CheckOutput: " << this->CheckOutput << "\n";
  os << indent << "FieldPoints: " << this->FieldPoints << "\n";
  os << indent << "Alpha: " << this->Alpha << "\n";
  os << indent << "Beta: " << this->Beta << "\n";
  os << indent << "Gradation: " << this->Gradation << "\n";
  os << indent << "SizeScale: " << this->SizeScale << "\n";
  os << indent << "MaxEdgeLength: " << this->MaxEdgeLength << "\n";
  os << indent << "MaxVolume: " << this->MaxVolume << "\n";
  os << indent << "ClusterSourcePoints: " << this->ClusterSourcePoints << "\n";
  os << indent << "SourceSizeArray: " << (this->SourceSizeArray ? this->SourceSizeArray : "(none)") << "\n";
  os << indent << "SizingFromSources: " << this->SizingFromSources << "\n";
  os << indent << "Optimize: " << this->Optimize << "\n";
  os << indent << "TargetMinDihedral: " << this->TargetMinDihedral << "\n";
  os << indent << "MaxPasses: " << this->MaxPasses << "\n";
  os << indent << "Smoothing: " << this->Smoothing << "\n";
  os << indent << "OrthogonalityFirst: " << this->OrthogonalityFirst << "\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers << "\n";
  os << indent << "FirstLayerHeight: " << this->FirstLayerHeight << "\n";
  os << indent << "LayerGrowthRatio: " << this->LayerGrowthRatio << "\n";
  os << indent << "TotalLayerThickness: " << this->TotalLayerThickness << "\n";
  os << indent << "LayerPatches: " << (this->LayerPatches ? this->LayerPatches : "(none)") << "\n";
  os << indent << "SplitPrisms: " << this->SplitPrisms << "\n";
  os << indent << "KeepWallTriangles: " << this->KeepWallTriangles << "\n";
}
