// checkSurface runs the checks in order: ids and finiteness, coincident points, degenerate and
// duplicate triangles, edge topology and shells (SurfaceTopology), self-intersections
// (IntersectingPairs, exact test in TriangleIntersection), nesting of closed shells (ShellNesting).
// surfaceStatus and formatSurfaceReport turn the report into the mesher's verdict and a text summary.
#include "SurfaceChecks.h"

#include "IntersectingPairs.h"
#include "ShellNesting.h"
#include "SurfaceTopology.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace volgrid
{

using detail::keepFirstId;

// ---------------------------------------------------------------------------------------------------
// The report

int SurfaceCheckReport::inwardShells() const
{
  int n = 0;
  for (const auto& s : shells)
  {
    if (s.closed && s.consistent && s.signedVolume < 0)
    {
      ++n;
    }
  }
  return n;
}

bool SurfaceCheckReport::meshable() const
{
  return triangles > 0 && invalidTriangles == 0 && nonFinitePoints == 0 && degenerateTriangles == 0 &&
    duplicateTriangles == 0 && nonManifoldEdges == 0 && boundaryEdges == 0 && selfIntersectingPairs == 0 &&
    shellIntersectingPairs == 0;
}

namespace
{
// Marks the triangles whose ids are all in range (valid) and the points they use (referenced); counts
// invalid triangles, unreferenced points and non-finite referenced points into r.
void checkIdsAndPoints(const SurfaceMesh& mesh, int maxIds, SurfaceCheckReport& r, std::vector<char>& valid,
                       std::vector<char>& referenced)
{
  const int32_t np = mesh.numberOfPoints();
  const int32_t nt = mesh.numberOfTriangles();
  valid.assign(nt, 1);
  referenced.assign(np, 0);
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t* v = mesh.triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      if (v[k] < 0 || v[k] >= np)
      {
        valid[t] = 0;
      }
    }
    if (!valid[t])
    {
      ++r.invalidTriangles;
      keepFirstId(r.firstInvalidTriangles, t, maxIds);
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      referenced[v[k]] = 1;
    }
  }
  for (int32_t i = 0; i < np; ++i)
  {
    if (!referenced[i])
    {
      ++r.unreferencedPoints;
    }
    else
    {
      const double* p = mesh.point(i);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        ++r.nonFinitePoints;
      }
    }
  }
}

// Counts the referenced points that coincide exactly with an earlier referenced one (canon: each point's
// canonical id, exactCoincidenceMap).
void countCoincidentPoints(const std::vector<char>& referenced, const std::vector<int32_t>& canon,
                           SurfaceCheckReport& r)
{
  std::vector<char> seen(referenced.size(), 0);
  for (size_t i = 0; i < referenced.size(); ++i)
  {
    if (referenced[i])
    {
      if (seen[canon[i]])
      {
        ++r.coincidentPoints;
      }
      seen[canon[i]] = 1;
    }
  }
}

// Flags the valid triangles with a repeated vertex or collinear corners (exact); returns the flags.
std::vector<char> flagDegenerateTriangles(const SurfaceMesh& mesh, const std::vector<char>& valid, int maxIds,
                                          SurfaceCheckReport& r)
{
  const int32_t nt = mesh.numberOfTriangles();
  std::vector<char> degenerate(nt, 0);
  for (int32_t t = 0; t < nt; ++t)
  {
    if (!valid[t])
    {
      continue;
    }
    const int32_t* v = mesh.triangle(t);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        triangleIsDegenerate(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])))
    {
      degenerate[t] = 1;
      r.triangleFlags[t] |= TriangleDegenerate;
      ++r.degenerateTriangles;
      keepFirstId(r.firstDegenerateTriangles, t, maxIds);
    }
  }
  return degenerate;
}

// Flags every valid triangle with the same vertex set as a lower-numbered one as a duplicate.
void flagDuplicateTriangles(const SurfaceMesh& mesh, const std::vector<char>& valid, int maxIds, SurfaceCheckReport& r)
{
  struct Key
  {
    int32_t v[3];
    int32_t t;
  };
  const int32_t nt = mesh.numberOfTriangles();
  std::vector<Key> keys;
  keys.reserve(nt);
  for (int32_t t = 0; t < nt; ++t)
  {
    if (valid[t])
    {
      Key k;
      std::copy(mesh.triangle(t), mesh.triangle(t) + 3, k.v);
      std::sort(k.v, k.v + 3);
      k.t = t;
      keys.push_back(k);
    }
  }
  std::sort(keys.begin(), keys.end(),
            [](const Key& a, const Key& b) {
              return std::lexicographical_compare(a.v, a.v + 3, b.v, b.v + 3) ||
                (std::equal(a.v, a.v + 3, b.v) && a.t < b.t);
            });
  for (size_t i = 1; i < keys.size(); ++i)
  {
    if (std::equal(keys[i].v, keys[i].v + 3, keys[i - 1].v))
    {
      const int32_t t = keys[i].t;
      r.triangleFlags[t] |= TriangleDuplicate;
      ++r.duplicateTriangles;
      keepFirstId(r.firstDuplicateTriangles, t, maxIds);
    }
  }
  std::sort(r.firstDuplicateTriangles.begin(), r.firstDuplicateTriangles.end());
}

// Finds the intersecting pairs among the valid, non-degenerate triangles (exact) and sorts them into
// self-intersections (same shell; r.triangleShell must be set) and intersections between shells.
void checkIntersections(const SurfaceMesh& mesh, const std::vector<char>& valid, const std::vector<char>& degenerate,
                        const std::vector<int32_t>& canon, int threads, int maxIds, SurfaceCheckReport& r)
{
  r.intersectionsChecked = true;
  std::vector<int32_t> candidates;
  candidates.reserve(valid.size());
  for (int32_t t = 0; t < static_cast<int32_t>(valid.size()); ++t)
  {
    if (valid[t] && !degenerate[t])
    {
      candidates.push_back(t);
    }
  }
  const std::vector<std::pair<int32_t, int32_t>> pairs =
    detail::findIntersectingPairs(mesh, candidates, canon, threads);
  for (const auto& pr : pairs)
  {
    const int32_t sa = r.triangleShell[pr.first], sb = r.triangleShell[pr.second];
    const bool self = sa == sb;
    const int flag = self ? TriangleSelfIntersecting : TriangleShellIntersecting;
    ++(self ? r.selfIntersectingPairs : r.shellIntersectingPairs);
    r.triangleFlags[pr.first] |= flag;
    r.triangleFlags[pr.second] |= flag;
    if (!self)
    {
      r.shells[sa].intersectsOtherShell = true;
      r.shells[sb].intersectsOtherShell = true;
    }
    std::vector<int32_t>& first = self ? r.firstSelfIntersectingPairs : r.firstShellIntersectingPairs;
    if (static_cast<int>(first.size()) < 2 * maxIds)
    {
      first.push_back(pr.first);
      first.push_back(pr.second);
    }
  }
}
} // namespace

SurfaceCheckReport checkSurface(const SurfaceMesh& mesh, const SurfaceCheckOptions& options)
{
  SilentProgress silent;
  Progress* progress = options.progress ? options.progress : &silent;
  const int maxIds = std::max(0, options.maxReportedIds);
  SurfaceCheckReport r;
  const int32_t np = mesh.numberOfPoints();
  const int32_t nt = mesh.numberOfTriangles();
  r.points = np;
  r.triangles = nt;
  r.triangleFlags.assign(nt, 0);
  r.triangleShell.assign(nt, -1);
  r.pointNonManifold.assign(np, 0);
  progress->report(0.0, "Checking surface");

  std::vector<char> valid, referenced;
  checkIdsAndPoints(mesh, maxIds, r, valid, referenced);
  if (r.nonFinitePoints > 0)
  {
    return r; // no geometry can be trusted
  }
  // Exactly coincident points: canonical ids for the geometric tests.
  std::vector<int32_t> canon;
  exactCoincidenceMap(mesh.points, canon);
  countCoincidentPoints(referenced, canon, r);
  const std::vector<char> degenerate = flagDegenerateTriangles(mesh, valid, maxIds, r);
  flagDuplicateTriangles(mesh, valid, maxIds, r);
  progress->report(0.1, "Checking surface");

  const std::vector<std::vector<int32_t>> shellTris = detail::checkEdgeTopology(mesh, valid, maxIds, r);
  progress->report(0.2, "Checking surface");

  if (options.selfIntersections && !progress->cancelled())
  {
    checkIntersections(mesh, valid, degenerate, canon, options.threads, maxIds, r);
  }
  progress->report(0.8, "Checking surface");

  // Nesting of closed shells.
  if (options.nesting && !progress->cancelled())
  {
    r.nestingChecked = true;
    detail::nestShells(mesh, shellTris, r);
  }
  progress->report(1.0, "Checking surface");
  return r;
}

// ---------------------------------------------------------------------------------------------------

namespace
{
std::string idList(const std::vector<int32_t>& ids)
{
  std::ostringstream os;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    os << (i ? ", " : "") << ids[i];
  }
  return os.str();
}

std::string pairList(const std::vector<int32_t>& ids)
{
  std::ostringstream os;
  for (size_t i = 0; i + 1 < ids.size(); i += 2)
  {
    os << (i ? ", " : "") << "(" << ids[i] << "," << ids[i + 1] << ")";
  }
  return os.str();
}

std::string edgeList(const SurfaceCheckReport& r, const std::vector<int32_t>& edges)
{
  std::ostringstream os;
  for (size_t i = 0; i < edges.size(); ++i)
  {
    os << (i ? ", " : "") << r.edgePoints[2 * size_t(edges[i])] << "-" << r.edgePoints[2 * size_t(edges[i]) + 1];
  }
  return os.str();
}

std::vector<int64_t> toIds(const std::vector<int32_t>& v)
{
  return std::vector<int64_t>(v.begin(), v.end());
}
} // namespace

// Every defect class present, in the order the mesher cares about (the first decides the error kind).
static std::vector<Status> defectStatuses(const SurfaceCheckReport& r)
{
  std::vector<Status> found;
  if (r.triangles == 0)
  {
    found.push_back(Status::failure(ErrorKind::EmptyInput, "The surface has no triangles."));
    return found;
  }
  if (r.invalidTriangles > 0)
  {
    found.push_back(Status::failure(
      ErrorKind::InvalidOption,
      std::to_string(r.invalidTriangles) +
        " triangle(s) refer to point ids that do not exist; first triangles: " + idList(r.firstInvalidTriangles) + ".",
      toIds(r.firstInvalidTriangles)));
  }
  if (r.nonFinitePoints > 0)
  {
    found.push_back(Status::failure(ErrorKind::NonFinitePoint,
                                    std::to_string(r.nonFinitePoints) + " point(s) have NaN or infinite coordinates."));
  }
  if (r.degenerateTriangles > 0)
  {
    found.push_back(Status::failure(
      ErrorKind::DegenerateTriangle,
      std::to_string(r.degenerateTriangles) +
        " degenerate (zero-area) triangle(s); first triangles: " + idList(r.firstDegenerateTriangles) + ".",
      toIds(r.firstDegenerateTriangles)));
  }
  if (r.duplicateTriangles > 0)
  {
    found.push_back(
      Status::failure(ErrorKind::DuplicateTriangle,
                      std::to_string(r.duplicateTriangles) +
                        " duplicate triangle(s) (same three points as an earlier triangle); first triangles: " +
                        idList(r.firstDuplicateTriangles) + ".",
                      toIds(r.firstDuplicateTriangles)));
  }
  if (r.nonManifoldEdges > 0)
  {
    found.push_back(Status::failure(
      ErrorKind::NonManifoldEdge,
      std::to_string(r.nonManifoldEdges) +
        " non-manifold edge(s) (used by more than two triangles); first edges (points): " +
        edgeList(r, r.firstNonManifoldEdges) + "; first triangles: " + idList(r.firstNonManifoldEdgeTriangles) + ".",
      toIds(r.firstNonManifoldEdgeTriangles)));
  }
  if (r.boundaryEdges > 0)
  {
    found.push_back(Status::failure(ErrorKind::OpenSurface,
                                    "The surface is open: " + std::to_string(r.boundaryEdges) +
                                      " boundary edge(s) in " + std::to_string(r.boundaryLoops) +
                                      " boundary loop(s); first edges (points): " + edgeList(r, r.firstBoundaryEdges) +
                                      "; first triangles: " + idList(r.firstBoundaryEdgeTriangles) + ".",
                                    toIds(r.firstBoundaryEdgeTriangles)));
  }
  if (r.selfIntersectingPairs > 0)
  {
    found.push_back(Status::failure(
      ErrorKind::SelfIntersection,
      std::to_string(r.selfIntersectingPairs) +
        " pair(s) of triangles intersect or overlap; first pairs: " + pairList(r.firstSelfIntersectingPairs) + ".",
      toIds(r.firstSelfIntersectingPairs)));
  }
  if (r.shellIntersectingPairs > 0)
  {
    found.push_back(Status::failure(ErrorKind::IntersectingShells,
                                    std::to_string(r.shellIntersectingPairs) +
                                      " pair(s) of triangles from different shells intersect; first pairs: " +
                                      pairList(r.firstShellIntersectingPairs) + ".",
                                    toIds(r.firstShellIntersectingPairs)));
  }
  return found;
}

Status surfaceStatus(const SurfaceCheckReport& r)
{
  const std::vector<Status> found = defectStatuses(r);
  if (found.empty())
  {
    return Status::success();
  }
  // All classes are named, not just the first: "3 degenerate ... ; 59 non-manifold edge(s) ...".
  Status first = found.front();
  for (size_t k = 1; k < found.size(); ++k)
  {
    first.message += " " + found[k].message;
  }
  if (found.size() > 1)
  {
    first.message = std::to_string(found.size()) + " kinds of defect: " + first.message;
  }
  return first;
}

std::string formatSurfaceReport(const SurfaceCheckReport& r)
{
  std::ostringstream os;
  os << "points                     " << r.points << "\n";
  os << "triangles                  " << r.triangles << "\n";
  os << "edges                      " << r.edges << "\n";
  os << "shells                     " << r.shells.size() << "\n";
  os << "watertight                 " << (r.watertight() ? "yes" : "no") << "\n";
  os << "consistently oriented      " << (r.consistentlyOriented() ? "yes" : "no") << "\n";
  os << "boundary edges             " << r.boundaryEdges << " in " << r.boundaryLoops << " loop(s)\n";
  os << "non-manifold edges         " << r.nonManifoldEdges << "\n";
  os << "inconsistent edges         " << r.inconsistentEdges << "\n";
  os << "non-manifold vertices      " << r.nonManifoldVertices << "\n";
  os << "degenerate triangles       " << r.degenerateTriangles << "\n";
  os << "duplicate triangles        " << r.duplicateTriangles << "\n";
  if (r.intersectionsChecked)
  {
    os << "self-intersecting pairs    " << r.selfIntersectingPairs << "\n";
    os << "shell-intersecting pairs   " << r.shellIntersectingPairs << "\n";
  }
  os << "coincident points          " << r.coincidentPoints << "\n";
  os << "unreferenced points        " << r.unreferencedPoints << "\n";
  if (r.invalidTriangles)
  {
    os << "invalid triangles          " << r.invalidTriangles << "\n";
  }
  for (size_t s = 0; s < r.shells.size() && s < 50; ++s)
  {
    const SurfaceShell& sh = r.shells[s];
    os << "shell " << s << ": " << sh.triangles << " triangles, " << (sh.closed ? "closed" : "open") << ", "
       << (sh.consistent ? "consistent" : "inconsistent");
    if (sh.closed && sh.consistent)
    {
      os << ", " << (sh.signedVolume >= 0 ? "outward" : "INWARD") << ", volume " << sh.signedVolume;
    }
    if (r.nestingChecked && sh.closed)
    {
      os << ", depth " << sh.depth;
      if (sh.parent >= 0)
      {
        os << " (inside shell " << sh.parent << ")";
      }
    }
    if (sh.intersectsOtherShell)
    {
      os << ", intersects another shell";
    }
    os << "\n";
  }
  if (r.shells.size() > 50)
  {
    os << "... " << (r.shells.size() - 50) << " more shells\n";
  }
  const Status st = surfaceStatus(r);
  os << "verdict                    " << (st.ok() ? "meshable" : st.message) << "\n";
  return os.str();
}

} // namespace volgrid
