#include "SurfacePreparation.h"

#include <algorithm>
#include <sstream>

namespace volgrid
{

namespace
{
// A stage's progress mapped into the [begin, end] slice of the whole preparation.
class SliceProgress final : public Progress
{
public:
  SliceProgress(Progress& whole, double begin, double end)
    : Whole(whole)
    , Begin(begin)
    , End(end)
  {
  }
  void report(double fraction, const char* stage) override
  {
    this->Whole.report(this->Begin + fraction * (this->End - this->Begin), stage);
  }
  bool cancelled() override { return this->Whole.cancelled(); }

private:
  Progress& Whole;
  double Begin, End;
};

Status cancelled()
{
  return Status::failure(ErrorKind::Cancelled, "Surface preparation cancelled.");
}

// Merges exactly coincident points, diagnoses the input's topology and repairs it.
Status repairInput(SurfaceMesh& mesh, const SurfacePreparationOptions& options, Progress& progress,
                   SurfacePreparationReport& report)
{
  progress.report(0.05, "Checking the input");
  mergeCoincidentPoints(mesh);
  SurfaceCheckOptions quick;
  quick.selfIntersections = false;
  quick.nesting = false;
  report.input = checkSurface(mesh, quick);
  progress.report(0.1, "Checking the input");

  SliceProgress repairProgress(progress, 0.1, 0.5);
  SurfaceRepairOptions repair;
  repair.weldTolerance = options.mergeTolerance;
  repair.stitchTolerance = options.mergeTolerance;
  repair.stitch = true;
  repair.removeDegenerate = options.removeDegenerate;
  repair.removeDuplicates = options.removeDuplicates;
  repair.maxHoleEdges = options.maxHoleEdges;
  repair.orientConsistently = options.orientShells;
  repair.orientForDomain = false; // after the enclosure is added
  repair.progress = &repairProgress;
  const Status status = repairSurface(mesh, repair, &report.repair);
  if (status.kind == ErrorKind::Cancelled || progress.cancelled())
    return cancelled();
  report.repairStatus = status;
  return Status::success();
}

// Appends the enclosure (patch `patchId`) to `mesh`.
Status addEnclosure(SurfaceMesh& mesh, int32_t patchId, const SurfacePreparationOptions& options, bool haveInput)
{
  EnclosureOptions enclosure = options.explicitEnclosure;
  if (options.aroundInput && haveInput)
    enclosure = enclosureAround(boundingBox(mesh, true), options.shape, options.enclosureScale, options.axis);
  enclosure.targetEdgeLength = options.enclosureEdgeLength;
  enclosure.patchId = patchId;
  SurfaceMesh primitive;
  Status status = makeEnclosure(enclosure, primitive);
  if (!status.ok())
  {
    status.message = "Enclosure: " + status.message;
    return status;
  }
  mesh.append(primitive);
  return Status::success();
}

int64_t closedShells(const SurfaceCheckReport& r)
{
  return std::count_if(r.shells.begin(), r.shells.end(), [](const SurfaceShell& s) { return s.closed; });
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
} // namespace

Status prepareSurface(SurfaceMesh& mesh, int32_t nextPatch, const SurfacePreparationOptions& options,
                      SurfacePreparationReport& report)
{
  SilentProgress silent;
  Progress& progress = options.progress ? *options.progress : silent;
  report = SurfacePreparationReport();
  report.haveInput = mesh.numberOfTriangles() > 0;
  if (report.haveInput)
  {
    const Status status = repairInput(mesh, options, progress, report);
    if (!status.ok())
      return status;
  }
  progress.report(0.5, "Building the enclosure");
  if (options.enclosure)
  {
    const Status status = addEnclosure(mesh, nextPatch, options, report.haveInput);
    if (!status.ok())
      return status;
    report.enclosurePatchId = nextPatch;
  }
  if (options.orientShells && mesh.numberOfTriangles() > 0)
  {
    progress.report(0.5, "Orienting shells");
    report.repair.shellsFlipped += orientShellsForDomain(mesh);
  }
  progress.report(0.55, "Checking the output");
  if (progress.cancelled())
    return cancelled();

  SliceProgress checkProgress(progress, 0.55, 0.95);
  SurfaceCheckOptions check;
  check.selfIntersections = options.checkIntersections;
  check.nesting = true;
  check.progress = &checkProgress;
  report.output = checkSurface(mesh, check);
  if (progress.cancelled())
    return cancelled();
  report.meshable = mesh.numberOfTriangles() > 0 && report.output.meshable();
  return Status::success();
}

int64_t misorientedShells(const SurfaceCheckReport& r)
{
  int64_t n = 0;
  for (const SurfaceShell& s : r.shells)
  {
    if (s.closed && s.consistent && s.signedVolume != 0.0 && ((s.depth % 2 == 0) != (s.signedVolume > 0.0)))
      ++n;
  }
  return n;
}

std::vector<SurfacePreparationRow> surfacePreparationRows(const SurfacePreparationReport& report, int64_t parts)
{
  const SurfaceCheckReport* in = report.haveInput ? &report.input : nullptr;
  const SurfaceCheckReport& out = report.output;
  const SurfaceRepairReport& rep = report.repair;
  auto before = [&](int64_t v) { return in ? v : -1; };
  std::vector<SurfacePreparationRow> rows = {
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

std::string surfacePreparationWarning(const SurfacePreparationReport& report,
                                      const std::vector<SurfacePreparationRow>& rows, int32_t triangles)
{
  std::ostringstream os;
  if (triangles > 0 && !report.meshable)
  {
    os << "The surface is not meshable: " << surfaceStatus(report.output).message;
    for (const SurfacePreparationRow& row : rows)
    {
      if (std::string(row.category) == "defect" && row.output > 0)
        os << "\n  " << row.item << ": " << row.output << (row.firstIds.empty() ? "" : " (") << row.firstIds
           << (row.firstIds.empty() ? "" : ")");
    }
  }
  else if (misorientedShells(report.output) > 0)
  {
    os << misorientedShells(report.output) << " closed shell(s) are not oriented away from the domain.";
  }
  return os.str();
}

} // namespace volgrid
