// vtkVolGridSurfacePrep: a thin adapter from VTK surfaces to Core/Surface/SurfaceRepair.h, Core/Surface/SurfaceChecks.h
// and Core/Surface/Enclosures.h.
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
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include "Enclosures.h"
#include "SurfaceChecks.h"
#include "SurfaceMesh.h"
#include "SurfaceRepair.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVolGridSurfacePrep);

namespace
{
// Closed, consistent shells whose orientation disagrees with their nesting depth (even depth outward).
int64_t misorientedShells(const volgrid::SurfaceCheckReport& r)
{
  int64_t n = 0;
  for (const volgrid::SurfaceShell& s : r.shells)
  {
    if (s.closed && s.consistent && s.signedVolume != 0.0 && ((s.depth % 2 == 0) != (s.signedVolume > 0.0)))
      ++n;
  }
  return n;
}

int64_t closedShells(const volgrid::SurfaceCheckReport& r)
{
  return std::count_if(r.shells.begin(), r.shells.end(), [](const volgrid::SurfaceShell& s) { return s.closed; });
}

std::string idList(const char* what, const std::vector<int32_t>& ids, bool pairs = false)
{
  if (ids.empty())
    return std::string();
  std::ostringstream os;
  os << what;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    if (pairs)
      os << (i % 2 == 0 ? " (" : " ") << ids[i] << (i % 2 == 1 ? ")" : "");
    else
      os << " " << ids[i];
  }
  return os.str();
}

// One row of the summary: a defect class (input and output counts) or a repair action (output only).
struct Row
{
  const char* category;
  const char* item;
  const char* key; // field-data name (the input's count is "Input" + key)
  int64_t input;   // -1: not measured
  int64_t output;
  std::string firstIds;
};

std::vector<Row> summaryRows(const volgrid::SurfaceCheckReport* in, const volgrid::SurfaceCheckReport& out,
                             const volgrid::SurfaceRepairReport& rep, int64_t parts)
{
  auto before = [&](int64_t v) { return in ? v : -1; };
  std::vector<Row> rows = {
    { "defect", "Open edges", "BoundaryEdges", before(in ? in->boundaryEdges : 0), out.boundaryEdges,
      idList("triangles", out.firstBoundaryEdgeTriangles) },
    { "defect", "Boundary loops", "BoundaryLoops", before(in ? in->boundaryLoops : 0), out.boundaryLoops, "" },
    { "defect", "Non-manifold edges", "NonManifoldEdges", before(in ? in->nonManifoldEdges : 0), out.nonManifoldEdges,
      idList("triangles", out.firstNonManifoldEdgeTriangles) },
    { "defect", "Non-manifold vertices", "NonManifoldVertices", before(in ? in->nonManifoldVertices : 0),
      out.nonManifoldVertices, idList("points", out.firstNonManifoldVertices) },
    { "defect", "Inconsistent edges", "InconsistentEdges", before(in ? in->inconsistentEdges : 0),
      out.inconsistentEdges, idList("triangles", out.firstInconsistentTriangles) },
    { "defect", "Degenerate triangles", "DegenerateTriangles", before(in ? in->degenerateTriangles : 0),
      out.degenerateTriangles, idList("triangles", out.firstDegenerateTriangles) },
    { "defect", "Duplicate triangles", "DuplicateTriangles", before(in ? in->duplicateTriangles : 0),
      out.duplicateTriangles, idList("triangles", out.firstDuplicateTriangles) },
    { "defect", "Self-intersecting pairs", "SelfIntersectingPairs", -1,
      out.intersectionsChecked ? out.selfIntersectingPairs : -1,
      idList("triangle pairs", out.firstSelfIntersectingPairs, true) },
    { "defect", "Intersecting shell pairs", "ShellIntersectingPairs", -1,
      out.intersectionsChecked ? out.shellIntersectingPairs : -1,
      idList("triangle pairs", out.firstShellIntersectingPairs, true) },
    { "defect", "Invalid triangles", "InvalidTriangles", before(in ? in->invalidTriangles : 0), out.invalidTriangles,
      idList("triangles", out.firstInvalidTriangles) },
    { "defect", "Non-finite points", "NonFinitePoints", before(in ? in->nonFinitePoints : 0), out.nonFinitePoints, "" },
    { "defect", "Misoriented shells", "MisorientedShells", -1, misorientedShells(out), "" },
    { "shells", "Shells", "Shells", before(in ? static_cast<int64_t>(in->shells.size()) : 0),
      static_cast<int64_t>(out.shells.size()), "" },
    { "shells", "Closed shells", "ClosedShells", before(in ? closedShells(*in) : 0), closedShells(out), "" },
    { "shells", "Inward shells", "InwardShells", before(in ? in->inwardShells() : 0), out.inwardShells(), "" },
    { "size", "Points", "Points", before(in ? in->points : 0), out.points, "" },
    { "size", "Triangles", "Triangles", before(in ? in->triangles : 0), out.triangles, "" },
    { "size", "Parts", "Parts", -1, parts, "" },
    { "repair", "Welded points", "WeldedPoints", -1, rep.weldedPoints, "" },
    { "repair", "Degenerate triangles removed", "RemovedDegenerate", -1, rep.removedDegenerate, "" },
    { "repair", "Duplicate triangles removed", "RemovedDuplicates", -1, rep.removedDuplicates, "" },
    { "repair", "Stitched points", "StitchedPoints", -1, rep.stitchedPoints, "" },
    { "repair", "Unreferenced points removed", "UnreferencedPointsRemoved", -1, rep.unreferencedPointsRemoved, "" },
    { "repair", "Holes filled", "LoopsFilled", -1, rep.loopsFilled, "" },
    { "repair", "Holes left open", "LoopsLeftOpen", -1, rep.loopsLeftOpen, "" },
    { "repair", "Triangles added", "TrianglesAdded", -1, rep.trianglesAdded, "" },
    { "repair", "Points added", "PointsAdded", -1, rep.pointsAdded, "" },
    { "repair", "Triangles flipped", "TrianglesFlipped", -1, rep.trianglesFlipped, "" },
    { "repair", "Shells flipped", "ShellsFlipped", -1, rep.shellsFlipped, "" },
    { "repair", "Non-orientable shells", "NonOrientableShells", -1, rep.nonOrientableShells, "" },
  };
  return rows;
}

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
  volgrid::SurfaceMesh mesh;
  int32_t nextPatch = 0;
  int64_t parts = 0;
  VolGridSurfaceConversionInfo conversion;
  // A part is one input connection or one leaf of a composite input; under MPI, the pieces of a part on
  // all ranks are gathered onto rank 0, which prepares the whole surface (the other ranks output nothing).
  auto addPart = [&](const std::vector<vtkSmartPointer<vtkDataSet>>& pieces)
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
      vtkWarningMacro(<< "Part " << parts << " has no triangles, quads or polygons: skipped.");
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
  };
  vtkInformationVector* inputs = inputVector[0];
  const int connections = inputs ? inputs->GetNumberOfInformationObjects() : 0;
  std::vector<vtkDataSet*> leaves;
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
  if (controller)
  {
    const auto gathered = VolGridGatherParts(controller, leaves);
    if (controller->GetLocalProcessId() != 0)
    {
      return 1;
    }
    for (const auto& part : gathered)
      addPart(part);
  }
  else
  {
    for (vtkDataSet* leaf : leaves)
      addPart({ leaf });
  }
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

  // ----- diagnosis of the input (topology: exactly coincident points joined) -----
  const bool haveInput = mesh.numberOfTriangles() > 0;
  volgrid::SurfaceCheckReport inputReport;
  volgrid::SurfaceRepairReport repair;
  if (haveInput)
  {
    this->SetProgressText("Checking the input");
    volgrid::mergeCoincidentPoints(mesh);
    volgrid::SurfaceCheckOptions quick;
    quick.selfIntersections = false;
    quick.nesting = false;
    inputReport = volgrid::checkSurface(mesh, quick);
    this->UpdateProgress(0.1);

    // ----- repair -----
    VolGridFilterProgress repairProgress(this, 0.1, 0.5);
    volgrid::SurfaceRepairOptions options;
    const double tolerance = this->ExactMergeOnly ? 0.0 : this->MergeTolerance;
    options.weldTolerance = tolerance;
    options.stitchTolerance = tolerance;
    options.stitch = true;
    options.removeDegenerate = this->RemoveDegenerate;
    options.removeDuplicates = this->RemoveDuplicates;
    options.maxHoleEdges = this->FillHoles ? this->MaxHoleEdges : 0;
    options.orientConsistently = this->OrientShells;
    options.orientForDomain = false; // after the enclosure is added
    options.progress = &repairProgress;
    const volgrid::Status status = volgrid::repairSurface(mesh, options, &repair);
    if (status.kind == volgrid::ErrorKind::Cancelled || this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
    if (!status.ok())
    {
      vtkWarningMacro(<< "Repair: " << status.message);
    }
  }
  this->UpdateProgress(0.5);

  // ----- enclosure -----
  if (this->Enclosure != ENCLOSURE_NONE)
  {
    this->SetProgressText("Building the enclosure");
    volgrid::EnclosureOptions options;
    if (this->ExplicitEnclosure || !haveInput)
    {
      options.shape = shapeOf(this->Enclosure);
      std::copy(this->EnclosureCenter, this->EnclosureCenter + 3, options.center);
      std::copy(this->EnclosureDimensions, this->EnclosureDimensions + 3, options.dimensions);
      options.axis = this->EnclosureAxis;
    }
    else
    {
      options = volgrid::enclosureAround(volgrid::boundingBox(mesh, true), shapeOf(this->Enclosure),
                                         this->EnclosureScale, this->EnclosureAxis);
    }
    options.targetEdgeLength = this->EnclosureEdgeLength;
    options.patchId = nextPatch;
    volgrid::SurfaceMesh enclosure;
    const volgrid::Status status = volgrid::makeEnclosure(options, enclosure);
    if (!status.ok())
    {
      vtkErrorMacro(<< "Enclosure: " << status.message);
      return 0;
    }
    mesh.append(enclosure);
    this->EnclosurePatchId = nextPatch;
  }
  if (this->OrientShells && mesh.numberOfTriangles() > 0)
  {
    this->SetProgressText("Orienting shells");
    repair.shellsFlipped += volgrid::orientShellsForDomain(mesh);
  }
  this->UpdateProgress(0.55);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // ----- diagnosis of the output -----
  this->SetProgressText("Checking the output");
  VolGridFilterProgress checkProgress(this, 0.55, 0.95);
  volgrid::SurfaceCheckOptions checkOptions;
  checkOptions.selfIntersections = this->CheckIntersections;
  checkOptions.nesting = true;
  checkOptions.progress = &checkProgress;
  const volgrid::SurfaceCheckReport report = volgrid::checkSurface(mesh, checkOptions);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // ----- output 0: surface, diagnostic arrays, field data -----
  VolGridSurfaceMeshToPolyData(mesh, output, "PatchId");
  vtkCellData* cd = output->GetCellData();
  if (!mesh.hasPatchIds() && mesh.numberOfTriangles() > 0)
  {
    auto patches = vtkSmartPointer<vtkIntArray>::New();
    patches->SetName("PatchId");
    patches->SetNumberOfValues(mesh.numberOfTriangles());
    patches->FillValue(0);
    cd->AddArray(patches);
  }
  if (this->DiagnosticArrays && static_cast<int32_t>(report.triangleFlags.size()) == mesh.numberOfTriangles())
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
  if (this->DiagnosticArrays && static_cast<int32_t>(report.pointNonManifold.size()) == mesh.numberOfPoints())
  {
    output->GetPointData()->AddArray(flagArray("NonManifoldVertex", report.pointNonManifold, 1));
  }

  const std::vector<Row> rows = summaryRows(haveInput ? &inputReport : nullptr, report, repair, parts);
  vtkFieldData* fd = output->GetFieldData();
  for (const Row& row : rows)
  {
    addCount(fd, row.key, row.output);
    if (row.input >= 0)
      addCount(fd, std::string("Input") + row.key, row.input);
  }
  this->Meshable = mesh.numberOfTriangles() > 0 && report.meshable();
  addCount(fd, "Meshable", this->Meshable ? 1 : 0);
  addCount(fd, "EnclosurePatchId", this->EnclosurePatchId);
  addIds(fd, "FirstBoundaryEdgeTriangles", report.firstBoundaryEdgeTriangles);
  addIds(fd, "FirstNonManifoldEdgeTriangles", report.firstNonManifoldEdgeTriangles);
  addIds(fd, "FirstSelfIntersectingPairs", report.firstSelfIntersectingPairs);
  addIds(fd, "FirstShellIntersectingPairs", report.firstShellIntersectingPairs);
  addIds(fd, "FirstDegenerateTriangles", report.firstDegenerateTriangles);
  std::string text = "repair: " + repair.summary() + "\n" + volgrid::formatSurfaceReport(report);
  auto textArray = vtkSmartPointer<vtkStringArray>::New();
  textArray->SetName("SurfacePrepReport");
  textArray->InsertNextValue(text);
  fd->AddArray(textArray);

  // ----- output 1: the summary table -----
  auto category = vtkSmartPointer<vtkStringArray>::New();
  category->SetName("Category");
  auto item = vtkSmartPointer<vtkStringArray>::New();
  item->SetName("Item");
  // Text columns, so that a count that was not measured says so in words.
  auto inputCount = vtkSmartPointer<vtkStringArray>::New();
  inputCount->SetName("Input");
  auto outputCount = vtkSmartPointer<vtkStringArray>::New();
  outputCount->SetName("Output");
  auto words = [](int64_t v) { return v < 0 ? std::string("not computed") : std::to_string(v); };
  auto firstIds = vtkSmartPointer<vtkStringArray>::New();
  firstIds->SetName("FirstIds");
  for (const Row& row : rows)
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
  table->GetFieldData()->PassData(fd);

  // ----- output 2: the defective edges as lines -----
  if (report.edgeFlags.size() * 2 == report.edgePoints.size() && output->GetPoints())
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
    edges->SetPoints(output->GetPoints());
    edges->SetLines(lines);
    edges->GetCellData()->AddArray(edgeFlags);
    edges->GetCellData()->AddArray(valence);
    edges->GetCellData()->SetActiveScalars("EdgeFlags");
  }

  // ----- log and warnings -----
  vtkLog(TRACE, "VolGrid Surface Prep: " << parts << " part(s); " << repair.summary());
  if (mesh.numberOfTriangles() > 0 && !this->Meshable)
  {
    const volgrid::Status status = volgrid::surfaceStatus(report);
    std::ostringstream os;
    os << "The surface is not meshable: " << status.message;
    for (const Row& row : rows)
    {
      if (std::string(row.category) == "defect" && row.output > 0)
        os << "\n  " << row.item << ": " << row.output << (row.firstIds.empty() ? "" : " (") << row.firstIds
           << (row.firstIds.empty() ? "" : ")");
    }
    vtkWarningMacro(<< os.str());
  }
  else if (misorientedShells(report) > 0)
  {
    vtkWarningMacro(<< misorientedShells(report) << " closed shell(s) are not oriented away from the domain.");
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
