// vtkVolGridSurfacePrep: a thin adapter from VTK surfaces to Core/Surface/SurfacePreparation.h (merge the
// parts, then Core diagnoses, repairs, encloses, orients and diagnoses again; here the report becomes
// arrays, field data and the summary table).
#include "vtkVolGridSurfacePrep.h"
#include "VolGridConversion.h"

#include "VolGridFilterProgress.h"
#include "VolGridParallel.h"
#include "VolGridSurfaceConversion.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include "SurfaceMesh.h"
#include "SurfacePreparation.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVolGridSurfacePrep);

namespace
{
void addCount(vtkFieldData* fd, const std::string& name, int64_t value)
{
  auto a = vtkSmartPointer<vtkIdTypeArray>::New();
  a->SetName(name.c_str());
  a->InsertNextValue(static_cast<vtkIdType>(value));
  fd->AddArray(a);
}

void addIds(vtkFieldData* fd, const char* name, const std::vector<int32_t>& ids)
{
  auto a = vtkSmartPointer<vtkIdTypeArray>::New();
  a->SetName(name);
  for (int32_t id : ids)
    a->InsertNextValue(id);
  fd->AddArray(a);
}

vtkSmartPointer<vtkUnsignedCharArray> flagArray(const char* name, const std::vector<uint8_t>& flags, uint8_t mask)
{
  auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
  a->SetName(name);
  a->SetNumberOfValues(static_cast<vtkIdType>(flags.size()));
  for (size_t i = 0; i < flags.size(); ++i)
    a->SetValue(static_cast<vtkIdType>(i), (flags[i] & mask) ? 1 : 0);
  return a;
}

volgrid::EnclosureShape shapeOf(int enclosure)
{
  switch (enclosure)
  {
    case vtkVolGridSurfacePrep::ENCLOSURE_BOX:
      return volgrid::EnclosureShape::Box;
    case vtkVolGridSurfacePrep::ENCLOSURE_CYLINDER:
      return volgrid::EnclosureShape::Cylinder;
    case vtkVolGridSurfacePrep::ENCLOSURE_HEMISPHERE:
      return volgrid::EnclosureShape::Hemisphere;
    case vtkVolGridSurfacePrep::ENCLOSURE_ELLIPSOID:
      return volgrid::EnclosureShape::Ellipsoid;
    default:
      return volgrid::EnclosureShape::Sphere;
  }
}

// The parts of the input, merged into one SurfaceMesh: each part's patches get ids after the previous
// part's (its PatchNames shifted with them), a part without a PatchId array is one patch "part<k>".
struct PartMerger
{
  explicit PartMerger(vtkVolGridSurfacePrep* self)
    : Self(self)
  {
  }

  // One part: an input connection or a leaf of a composite input; under MPI, its pieces on all ranks.
  void add(const std::vector<vtkSmartPointer<vtkDataSet>>& pieces)
  {
    bool hasCells = false, hasPatchArray = false;
    for (vtkDataSet* piece : pieces)
    {
      hasCells = hasCells || (piece && piece->GetNumberOfCells() > 0);
      hasPatchArray = hasPatchArray || (piece && piece->GetCellData()->GetArray("PatchId"));
    }
    if (!hasCells)
      return;
    const int32_t before = mesh.numberOfTriangles();
    bool appended = false;
    for (vtkDataSet* piece : pieces)
    {
      if (piece && piece->GetNumberOfCells() > 0)
        appended = VolGridAppendSurface(piece, mesh, "PatchId", nextPatch, nextPatch, &conversion) || appended;
    }
    if (!appended)
    {
      vtkWarningWithObjectMacro(this->Self, << "Part " << parts << " has no triangles, quads or polygons: skipped.");
      ++parts;
      return;
    }
    // Names: the part's PatchNames (shifted like its ids), else "part<k>" for a part without patches.
    for (vtkDataSet* piece : pieces)
      if (piece && hasPatchArray)
        for (const auto& name : VolGridReadLabelNames(piece, "PatchNames"))
          mesh.patchNames[name.first + nextPatch] = name.second;
    if (!hasPatchArray)
      mesh.patchNames[nextPatch] = "part" + std::to_string(parts);
    int32_t maxPatch = nextPatch;
    if (hasPatchArray)
    {
      for (int32_t t = before; t < mesh.numberOfTriangles(); ++t)
        maxPatch = std::max(maxPatch, mesh.patchIds[t]);
    }
    nextPatch = maxPatch + 1;
    ++parts;
  }

  vtkVolGridSurfacePrep* Self; // for its warnings
  volgrid::SurfaceMesh mesh;
  int32_t nextPatch = 0; // the first patch id of the next part
  int64_t parts = 0;
  VolGridSurfaceConversionInfo conversion;
};

// The data sets of every input connection: the connection's, or every leaf of a composite one (empty
// leaves included, so that every rank lists the same slots).
std::vector<vtkDataSet*> inputLeaves(vtkInformationVector* inputs)
{
  std::vector<vtkDataSet*> leaves;
  const int connections = inputs ? inputs->GetNumberOfInformationObjects() : 0;
  for (int c = 0; c < connections; ++c)
  {
    vtkDataObject* object = inputs->GetInformationObject(c)->Get(vtkDataObject::DATA_OBJECT());
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(object))
    {
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(composite->NewIterator());
      it->SkipEmptyNodesOff(); // the same slots on every rank, even where a rank's block is empty
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
        leaves.push_back(vtkDataSet::SafeDownCast(it->GetCurrentDataObject()));
    }
    else
    {
      leaves.push_back(vtkDataSet::SafeDownCast(object));
    }
  }
  return leaves;
}

// Core's options from the filter's properties (progress left to the caller).
volgrid::SurfacePreparationOptions optionsOf(vtkVolGridSurfacePrep* f)
{
  volgrid::SurfacePreparationOptions options;
  options.mergeTolerance = f->GetExactMergeOnly() ? 0.0 : f->GetMergeTolerance();
  options.removeDegenerate = f->GetRemoveDegenerate();
  options.removeDuplicates = f->GetRemoveDuplicates();
  options.maxHoleEdges = f->GetFillHoles() ? f->GetMaxHoleEdges() : 0;
  options.orientShells = f->GetOrientShells();
  options.checkIntersections = f->GetCheckIntersections();
  options.enclosure = f->GetEnclosure() != vtkVolGridSurfacePrep::ENCLOSURE_NONE;
  options.aroundInput = !f->GetExplicitEnclosure();
  options.shape = shapeOf(f->GetEnclosure());
  options.explicitEnclosure.shape = options.shape;
  std::copy(f->GetEnclosureCenter(), f->GetEnclosureCenter() + 3, options.explicitEnclosure.center);
  std::copy(f->GetEnclosureDimensions(), f->GetEnclosureDimensions() + 3, options.explicitEnclosure.dimensions);
  options.explicitEnclosure.axis = f->GetEnclosureAxis();
  options.enclosureScale = f->GetEnclosureScale();
  options.axis = f->GetEnclosureAxis();
  options.enclosureEdgeLength = f->GetEnclosureEdgeLength();
  return options;
}

// Output 0's cell and point arrays: PatchId (0 when the surface has none), ShellId, and with `diagnostic`
// DefectFlags, one 0/1 array per defect and NonManifoldVertex.
void addDiagnosticArrays(const volgrid::SurfaceMesh& mesh, const volgrid::SurfaceCheckReport& report, bool diagnostic,
                         vtkPolyData* output)
{
  vtkCellData* cd = output->GetCellData();
  if (!mesh.hasPatchIds() && mesh.numberOfTriangles() > 0)
  {
    auto patches = vtkSmartPointer<vtkIntArray>::New();
    patches->SetName("PatchId");
    patches->SetNumberOfValues(mesh.numberOfTriangles());
    patches->FillValue(0);
    cd->AddArray(patches);
  }
  if (diagnostic && static_cast<int32_t>(report.triangleFlags.size()) == mesh.numberOfTriangles())
  {
    auto flags = vtkSmartPointer<vtkUnsignedCharArray>::New();
    flags->SetName("DefectFlags");
    flags->SetNumberOfValues(mesh.numberOfTriangles());
    std::copy(report.triangleFlags.begin(), report.triangleFlags.end(), flags->GetPointer(0));
    cd->AddArray(flags);
    cd->AddArray(flagArray("OpenEdge", report.triangleFlags, volgrid::TriangleBoundaryEdge));
    cd->AddArray(flagArray("NonManifoldEdge", report.triangleFlags, volgrid::TriangleNonManifoldEdge));
    cd->AddArray(flagArray("SelfIntersecting", report.triangleFlags,
                           volgrid::TriangleSelfIntersecting | volgrid::TriangleShellIntersecting));
    cd->AddArray(flagArray("Degenerate", report.triangleFlags, volgrid::TriangleDegenerate));
  }
  if (static_cast<int32_t>(report.triangleShell.size()) == mesh.numberOfTriangles())
  {
    auto shells = vtkSmartPointer<vtkIntArray>::New();
    shells->SetName("ShellId");
    shells->SetNumberOfValues(mesh.numberOfTriangles());
    std::copy(report.triangleShell.begin(), report.triangleShell.end(), shells->GetPointer(0));
    cd->AddArray(shells);
  }
  cd->SetActiveScalars("PatchId");
  if (diagnostic && static_cast<int32_t>(report.pointNonManifold.size()) == mesh.numberOfPoints())
  {
    output->GetPointData()->AddArray(flagArray("NonManifoldVertex", report.pointNonManifold, 1));
  }
}

// Output 0's field data: every row's count (Input<Key> for the input's), Meshable, EnclosurePatchId, the
// first ids of each defect and the report as text (SurfacePrepReport).
void addFieldData(const volgrid::SurfacePreparationReport& prepared,
                  const std::vector<volgrid::SurfacePreparationRow>& rows, int enclosurePatchId, vtkFieldData* fd)
{
  const volgrid::SurfaceCheckReport& report = prepared.output;
  for (const volgrid::SurfacePreparationRow& row : rows)
  {
    addCount(fd, row.key, row.output);
    if (row.input >= 0)
      addCount(fd, std::string("Input") + row.key, row.input);
  }
  addCount(fd, "Meshable", prepared.meshable ? 1 : 0);
  addCount(fd, "EnclosurePatchId", enclosurePatchId);
  addIds(fd, "FirstBoundaryEdgeTriangles", report.firstBoundaryEdgeTriangles);
  addIds(fd, "FirstNonManifoldEdgeTriangles", report.firstNonManifoldEdgeTriangles);
  addIds(fd, "FirstSelfIntersectingPairs", report.firstSelfIntersectingPairs);
  addIds(fd, "FirstShellIntersectingPairs", report.firstShellIntersectingPairs);
  addIds(fd, "FirstDegenerateTriangles", report.firstDegenerateTriangles);
  std::string text = "repair: " + prepared.repair.summary() + "\n" + volgrid::formatSurfaceReport(report);
  auto textArray = vtkSmartPointer<vtkStringArray>::New();
  textArray->SetName("SurfacePrepReport");
  textArray->InsertNextValue(text);
  fd->AddArray(textArray);
}

// Output 1: one row per count (Category, Item, Input, Output, FirstIds), the counts as text so that one
// that was not measured says so in words.
void fillSummaryTable(const std::vector<volgrid::SurfacePreparationRow>& rows, vtkTable* table)
{
  auto category = vtkSmartPointer<vtkStringArray>::New();
  category->SetName("Category");
  auto item = vtkSmartPointer<vtkStringArray>::New();
  item->SetName("Item");
  auto inputCount = vtkSmartPointer<vtkStringArray>::New();
  inputCount->SetName("Input");
  auto outputCount = vtkSmartPointer<vtkStringArray>::New();
  outputCount->SetName("Output");
  auto words = [](int64_t v) { return v < 0 ? std::string("not computed") : std::to_string(v); };
  auto firstIds = vtkSmartPointer<vtkStringArray>::New();
  firstIds->SetName("FirstIds");
  for (const volgrid::SurfacePreparationRow& row : rows)
  {
    category->InsertNextValue(row.category);
    item->InsertNextValue(row.item);
    inputCount->InsertNextValue(words(row.input));
    outputCount->InsertNextValue(words(row.output));
    firstIds->InsertNextValue(row.firstIds);
  }
  table->AddColumn(category);
  table->AddColumn(item);
  table->AddColumn(inputCount);
  table->AddColumn(outputCount);
  table->AddColumn(firstIds);
}

// Output 2: the defective edges of the report as lines on output 0's points, with EdgeFlags and Valence.
void fillDefectEdges(const volgrid::SurfaceCheckReport& report, vtkPoints* points, vtkPolyData* edges)
{
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto edgeFlags = vtkSmartPointer<vtkUnsignedCharArray>::New();
  edgeFlags->SetName("EdgeFlags");
  auto valence = vtkSmartPointer<vtkIntArray>::New();
  valence->SetName("Valence");
  for (size_t e = 0; e < report.edgeFlags.size(); ++e)
  {
    if (!report.edgeFlags[e])
      continue;
    const vtkIdType pts[2] = { report.edgePoints[2 * e], report.edgePoints[2 * e + 1] };
    lines->InsertNextCell(2, pts);
    edgeFlags->InsertNextValue(report.edgeFlags[e]);
    valence->InsertNextValue(report.edgeValence[e]);
  }
  edges->SetPoints(points);
  edges->SetLines(lines);
  edges->GetCellData()->AddArray(edgeFlags);
  edges->GetCellData()->AddArray(valence);
  edges->GetCellData()->SetActiveScalars("EdgeFlags");
}
} // namespace

vtkVolGridSurfacePrep::vtkVolGridSurfacePrep()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
}

int vtkVolGridSurfacePrep::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkVolGridSurfacePrep::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkVolGridSurfacePrep::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = VolGridParallelController();
  const int ok = this->Prepare(inputVector, outputVector, controller);
  VolGridConsumeAbort(this);
  // Under MPI every rank reports rank 0's outcome, so that all ranks run (or skip) the filters downstream
  // together.
  return controller ? (VolGridBroadcastFlag(controller, ok != 0) ? 1 : 0) : ok;
}

int vtkVolGridSurfacePrep::Prepare(vtkInformationVector** inputVector, vtkInformationVector* outputVector,
                                   vtkMultiProcessController* controller)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkTable* table = vtkTable::GetData(outputVector, 1);
  vtkPolyData* edges = vtkPolyData::GetData(outputVector, 2);
  output->Initialize();
  table->Initialize();
  edges->Initialize();
  this->EnclosurePatchId = -1;
  this->Meshable = false;

  // ----- parts: every connection, every leaf of a composite input -----
  this->SetProgressText("Merging parts");
  PartMerger merger(this);
  vtkInformationVector* inputs = inputVector[0];
  const int connections = inputs ? inputs->GetNumberOfInformationObjects() : 0;
  const std::vector<vtkDataSet*> leaves = inputLeaves(inputs);
  if (controller)
  {
    const auto gathered = VolGridGatherParts(controller, leaves);
    if (controller->GetLocalProcessId() != 0)
    {
      return 1;
    }
    for (const auto& part : gathered)
      merger.add(part);
  }
  else
  {
    for (vtkDataSet* leaf : leaves)
      merger.add({ leaf });
  }
  volgrid::SurfaceMesh& mesh = merger.mesh;
  const VolGridSurfaceConversionInfo& conversion = merger.conversion;
  const int64_t parts = merger.parts;
  const int32_t nextPatch = merger.nextPatch;
  if (conversion.skippedCells > 0 || conversion.invalidCells > 0)
  {
    vtkWarningMacro(<< conversion.skippedCells << " cell(s) that are not surface cells (vertices, lines, volume cells)"
                    << " and " << conversion.invalidCells << " cell(s) with point ids out of range were skipped.");
  }
  if (connections > 0 && mesh.numberOfTriangles() == 0)
  {
    // Never an enclosure around nothing: a connected but empty input is an error.
    vtkErrorMacro(<< "VolGrid Surface Prep: the input has no surface triangles (on any rank); nothing to prepare.");
    return 0;
  }
  this->UpdateProgress(0.05);

  // ----- diagnosis, repair, enclosure, orientation, diagnosis (Core/Surface/SurfacePreparation.h) -----
  VolGridFilterProgress progress(this);
  volgrid::SurfacePreparationOptions options = optionsOf(this);
  options.progress = &progress;
  volgrid::SurfacePreparationReport prepared;
  const volgrid::Status status = volgrid::prepareSurface(mesh, nextPatch, options, prepared);
  if (status.kind == volgrid::ErrorKind::Cancelled)
  {
    output->Initialize();
    return 1;
  }
  if (!status.ok())
  {
    vtkErrorMacro(<< status.message);
    return 0;
  }
  if (!prepared.repairStatus.ok())
  {
    vtkWarningMacro(<< "Repair: " << prepared.repairStatus.message);
  }
  this->EnclosurePatchId = prepared.enclosurePatchId;
  const volgrid::SurfaceCheckReport& report = prepared.output;
  const volgrid::SurfaceRepairReport& repair = prepared.repair;

  // ----- output 0: surface, diagnostic arrays, field data -----
  VolGridSurfaceMeshToPolyData(mesh, output, "PatchId");
  addDiagnosticArrays(mesh, report, this->DiagnosticArrays, output);

  const std::vector<volgrid::SurfacePreparationRow> rows = volgrid::surfacePreparationRows(prepared, parts);
  this->Meshable = prepared.meshable;
  vtkFieldData* fd = output->GetFieldData();
  addFieldData(prepared, rows, this->EnclosurePatchId, fd);

  // ----- output 1: the summary table -----
  fillSummaryTable(rows, table);
  table->GetFieldData()->PassData(fd);

  // ----- output 2: the defective edges as lines -----
  if (report.edgeFlags.size() * 2 == report.edgePoints.size() && output->GetPoints())
    fillDefectEdges(report, output->GetPoints(), edges);

  // ----- log and warnings -----
  vtkLog(TRACE, "VolGrid Surface Prep: " << parts << " part(s); " << repair.summary());
  const std::string warning = volgrid::surfacePreparationWarning(prepared, rows, mesh.numberOfTriangles());
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkVolGridSurfacePrep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MergeTolerance: " << this->MergeTolerance << "\n";
  os << indent << "ExactMergeOnly: " << this->ExactMergeOnly << "\n";
  os << indent << "RemoveDegenerate: " << this->RemoveDegenerate << "\n";
  os << indent << "RemoveDuplicates: " << this->RemoveDuplicates << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "MaxHoleEdges: " << this->MaxHoleEdges << "\n";
  os << indent << "OrientShells: " << this->OrientShells << "\n";
  os << indent << "CheckIntersections: " << this->CheckIntersections << "\n";
  os << indent << "DiagnosticArrays: " << this->DiagnosticArrays << "\n";
  os << indent << "Enclosure: " << this->Enclosure << "\n";
  os << indent << "EnclosureScale: " << this->EnclosureScale << "\n";
  os << indent << "ExplicitEnclosure: " << this->ExplicitEnclosure << "\n";
  os << indent << "EnclosureCenter: " << this->EnclosureCenter[0] << " " << this->EnclosureCenter[1] << " "
     << this->EnclosureCenter[2] << "\n";
  os << indent << "EnclosureDimensions: " << this->EnclosureDimensions[0] << " " << this->EnclosureDimensions[1] << " "
     << this->EnclosureDimensions[2] << "\n";
  os << indent << "EnclosureAxis: " << this->EnclosureAxis << "\n";
  os << indent << "EnclosureEdgeLength: " << this->EnclosureEdgeLength << "\n";
}
