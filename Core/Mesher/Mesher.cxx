#include "Mesher.h"

#include "BoundaryCensus.h"
#include "BoundaryCheck.h"
#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "SteinerRemoval.h"
#include "SurfaceChecks.h"
#include "UnionFind.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>

namespace volgrid
{

namespace
{

double since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Shells by edge connectivity (used when the surface checks are off).
std::vector<int32_t> shellsOf(const SurfaceMesh& s, int32_t* count)
{
  const int32_t nt = s.numberOfTriangles();
  UnionFind<int32_t> sets(static_cast<size_t>(nt));
  std::unordered_map<uint64_t, int32_t> first;
  first.reserve(static_cast<size_t>(nt) * 2);
  for (int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
    {
      auto [it, fresh] = first.emplace(edgeKey(s.triangle(t)[k], s.triangle(t)[(k + 1) % 3]), t);
      if (!fresh)
        sets.unite(t, it->second);
    }
  // Shells are numbered in the order of their first triangle.
  std::vector<int32_t> id(static_cast<size_t>(nt), -1), shell(static_cast<size_t>(nt));
  int32_t n = 0;
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t r = sets.find(t);
    if (id[r] < 0)
      id[r] = n++;
    shell[t] = id[r];
  }
  *count = n;
  return shell;
}

// MesherResult::tetForced: the output tets whose four vertices are input points (all on the boundary)
// with a sine quality under 10 degrees.
void markForcedTets(MesherResult& result)
{
  const double q10 = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  const size_t nt = result.tets.size() / 4;
  result.tetForced.assign(nt, 0);
  const int32_t* tet = result.tets.data();
  for (size_t t = 0; t < nt; ++t, tet += 4)
  {
    if (tet[0] >= result.numInputPoints || tet[1] >= result.numInputPoints || tet[2] >= result.numInputPoints ||
        tet[3] >= result.numInputPoints)
      continue;
    const double* p = result.points.data();
    const bool forced = tetSineQuality(p + 3 * static_cast<size_t>(tet[0]), p + 3 * static_cast<size_t>(tet[1]),
                                       p + 3 * static_cast<size_t>(tet[2]), p + 3 * static_cast<size_t>(tet[3])) < q10;
    result.tetForced[t] = forced;
    result.stats.forcedTets += forced;
  }
}

// Step 1: the input's ids checked and its coincident points merged into `surf`; with options.checkSurface
// the surface checks (closed, manifold, not self-intersecting, nesting) decide whether it can be meshed.
// Fills result.inputToOutputPoint, result.triangleShell, the statistics of the input, and shellDepth.
Status checkAndMerge(const SurfaceMesh& input, const MesherOptions& options, Progress* pr, SurfaceMesh& surf,
                     MesherResult& result, std::vector<int>& shellDepth)
{
  MesherStatistics& st = result.stats;
  surf = input;
  for (int32_t t = 0; t < surf.numberOfTriangles(); ++t)
    for (int k = 0; k < 3; ++k)
    {
      const int32_t v = surf.triangle(t)[k];
      if (v < 0 || v >= surf.numberOfPoints())
        return Status::failure(
          ErrorKind::InvalidOption,
          "Triangle " + std::to_string(t) + " refers to point " + std::to_string(v) + ", which does not exist.", { t });
    }
  MergeResult merge = mergeCoincidentPoints(surf);
  st.mergedPoints = merge.mergedPoints;
  result.inputToOutputPoint = merge.oldToNew;
  st.inputPoints = surf.numberOfPoints();
  st.inputTriangles = surf.numberOfTriangles();
  int32_t nshell = 0;
  if (options.checkSurface)
  {
    SurfaceCheckOptions co;
    co.selfIntersections = options.checkSelfIntersections;
    co.nesting = true;
    co.threads = options.threads;
    co.progress = pr;
    SurfaceCheckReport rep = checkSurface(surf, co);
    if (pr->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Meshing was cancelled.");
    Status s = surfaceStatus(rep);
    if (!s.ok())
      return s;
    result.triangleShell = rep.triangleShell;
    for (auto& sh : rep.shells)
      shellDepth.push_back(sh.depth);
  }
  else
  {
    result.triangleShell = shellsOf(surf, &nshell);
    shellDepth.assign(static_cast<size_t>(nshell), 0); // unknown nesting: volume check not meaningful
  }
  return Status::success();
}

// Step 2: the Delaunay tetrahedralisation of the points the triangles use plus the 8 corners of a box
// around them (one extent away). Vertex i of `mesh` is merged input point i; the corners are N..N+7.
// `used` marks the referenced points.
Status delaunayInFarBox(const SurfaceMesh& surf, const MesherOptions& options, Progress* pr, TetMesh& mesh,
                        std::vector<uint8_t>& used)
{
  const int32_t N = surf.numberOfPoints();
  used.assign(static_cast<size_t>(N), 0);
  for (int32_t v : surf.triangles)
    used[v] = 1;
  std::vector<int32_t> compactToFull;
  std::vector<double> xyz;
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (int32_t v = 0; v < N; ++v)
    if (used[v])
    {
      compactToFull.push_back(v);
      for (int k = 0; k < 3; ++k)
      {
        const double x = surf.points[3 * static_cast<size_t>(v) + k];
        if (!std::isfinite(x))
          return Status::failure(ErrorKind::NonFinitePoint, "Point " + std::to_string(v) + " is not finite.", { v });
        xyz.push_back(x);
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
    }
  double ext = 0;
  for (int k = 0; k < 3; ++k)
    ext = std::max(ext, hi[k] - lo[k]);
  if (!(ext > 0))
    return Status::failure(ErrorKind::DegenerateInput, "All surface points coincide.");
  std::vector<double> corners;
  for (int c = 0; c < 8; ++c)
    for (int k = 0; k < 3; ++k)
      corners.push_back(((c >> k) & 1) ? hi[k] + ext : lo[k] - ext);
  for (int c = 0; c < 8; ++c)
  {
    compactToFull.push_back(N + c);
    xyz.insert(xyz.end(), corners.begin() + 3 * c, corners.begin() + 3 * c + 3);
  }
  std::vector<int32_t> inputToVertex;
  DelaunayOptions dopt;
  dopt.keepGhosts = false;
  dopt.threads = options.threads;
  Status s = buildDelaunay(xyz.data(), xyz.size() / 3, dopt, mesh, inputToVertex, pr);
  if (!s.ok())
    return s;
  // Renumber: vertex i = merged input point i, box corners N..N+7.
  mesh.points = surf.points;
  mesh.points.insert(mesh.points.end(), corners.begin(), corners.end());
  for (auto& v : mesh.tetVertices)
    if (v >= 0)
      v = compactToFull[v];
  return Status::success();
}

// Steps 3-5: recovery, exterior removal, removal of the boundary Steiner points. When recovery or that
// removal fails, both are retried from the Delaunay mesh: first splitting the input segments the first
// attempt had to split while the mesh is still Delaunay (RecoveryOptions::presplitSegments), then, as the
// last resort, with segment cones (RecoveryOptions::segmentCones). On success `ed`'s mesh is the domain
// with its regions, and `kinds` says what each vertex is.
Status recoverDomain(const SurfaceMesh& surf, const MesherOptions& options, Progress* pr, MeshEditor& ed,
                     BoundaryConstraints& bc, std::vector<VertexKind>& kinds, RegionResult& regions,
                     MesherStatistics& st)
{
  TetMesh& mesh = ed.mesh;
  const bool mayRetry = options.allowSteinerPoints && options.removeBoundarySteiner;
  TetMesh delaunayMesh = mayRetry ? mesh : TetMesh();
  const std::vector<VertexKind> delaunayKinds = kinds;
  std::unordered_set<uint64_t> presplit;
  Status firstFailure = Status::success();
  Status s = Status::success();
  constexpr int kAttempts = 3;
  for (int attempt = 0; attempt < kAttempts; ++attempt)
  {
    if (attempt > 0)
    {
      mesh = delaunayMesh;
      kinds = delaunayKinds;
      ed.rebuildVertexMap();
      regions = RegionResult();
    }
    auto t0 = std::chrono::steady_clock::now();
    bc = BoundaryConstraints();
    bc.init(surf.triangles.data(), surf.numberOfTriangles());
    RecoveryOptions ro;
    ro.allowSteiner = options.allowSteinerPoints;
    ro.maxSteinerPoints = options.maxSteinerPoints;
    ro.presplitSegments = attempt == 1 ? &presplit : nullptr;
    ro.segmentCones = attempt == 2;
    RecoveryReport rr;
    s = recoverBoundary(ed, bc, kinds, ro, pr, &rr);
    st.missingEdges = rr.missingEdgesInitially;
    st.missingFacets = rr.missingFacetsInitially;
    st.flips = static_cast<int64_t>(rr.flips23 + rr.flips32 + rr.flipsEdgeRemoval);
    st.steinerInserted = rr.steinerSegment + rr.steinerFacet;
    st.recoveryAttempts = attempt + 1;
    st.secondsRecovery += since(t0);
    // 4. Exterior removal.
    if (s.ok())
    {
      t0 = std::chrono::steady_clock::now();
      s = removeExterior(ed, bc, options.regionRule, regions, pr);
      if (!s.ok())
        return s;
      st.regions = regions.numRegions;
      st.secondsExterior += since(t0);
      // 5. Boundary Steiner points.
      t0 = std::chrono::steady_clock::now();
      if (options.removeBoundarySteiner)
      {
        SteinerRemovalReport sr;
        s = removeBoundarySteinerPoints(ed, bc, kinds, &regions.tetRegion, pr, &sr);
      }
      st.secondsSteiner += since(t0);
    }
    if (attempt + 1 == kAttempts && !s.ok())
    {
      // Report the first attempt's diagnosis (it names what flips and Steiner points could not do).
      s = firstFailure;
      s.message += " Retries that first split the " + std::to_string(presplit.size()) +
        " segments involved, and that split segments by cones, failed too.";
      break;
    }
    if (s.ok() || s.kind != ErrorKind::RecoveryFailed || !mayRetry || (attempt == 0 && rr.splitSegments.empty()))
      break;
    if (attempt == 0)
    {
      firstFailure = s;
      presplit = rr.splitSegments;
    }
  }
  return s;
}

// Step 6: the domain's tets and the points they use into `result` (input points first, with their ids),
// the Forced flags, and the input triangles that are faces of the mesh with their patch.
Status emitResult(const TetMesh& mesh, const SurfaceMesh& surf, const std::vector<VertexKind>& kinds,
                  const std::vector<int32_t>& tetRegion, MesherResult& result, Progress* pr)
{
  MesherStatistics& st = result.stats;
  const int32_t N = surf.numberOfPoints();
  const int32_t nv = mesh.numVertices();
  std::vector<int32_t> outId(static_cast<size_t>(nv), -1);
  std::vector<uint8_t> inTet(static_cast<size_t>(nv), 0);
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        inTet[mesh.vertex(t, i)] = 1;
    });
  result.points.assign(mesh.points.begin(), mesh.points.begin() + 3 * static_cast<size_t>(N));
  result.numInputPoints = N;
  for (int32_t v = 0; v < N; ++v)
    outId[v] = v;
  for (int32_t v = N; v < nv; ++v)
  {
    if (!inTet[v])
      continue;
    if (kinds[v] == VertexKind::Box)
      return Status::failure(ErrorKind::InternalError, "A far-box corner is still used by a domain tet.");
    outId[v] = static_cast<int32_t>(result.points.size() / 3);
    result.points.insert(result.points.end(), mesh.points.begin() + 3 * static_cast<size_t>(v),
                         mesh.points.begin() + 3 * static_cast<size_t>(v) + 3);
    if (kinds[v] == VertexKind::SteinerInterior)
      ++st.steinerInterior;
    else
      ++st.steinerBoundary;
  }
  result.tets.reserve(static_cast<size_t>(mesh.numTets()) * 4);
  result.tetRegion.reserve(static_cast<size_t>(mesh.numTets()));
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        result.tets.push_back(outId[mesh.vertex(t, i)]);
      result.tetRegion.push_back(tetRegion[t]);
    });
  // Each step here is about a tenth of a second at 10M tets (the caller empties a cancelled result).
  const Status cancelled = Status::failure(ErrorKind::Cancelled, "Meshing was cancelled.");
  if (pr->cancelled())
    return cancelled;
  markForcedTets(result);
  if (pr->cancelled())
    return cancelled;
  // Boundary triangles: input triangles that are faces of the mesh (all of them unless keep-all
  // interfaces... which are faces too), found by one sweep over the tets.
  BoundaryCensus inputFaces;
  inputFaces.take(mesh, surf.triangles.data(), surf.numberOfTriangles(), /*withEdges=*/false);
  for (int32_t t = 0; t < surf.numberOfTriangles(); ++t)
  {
    const int32_t* v = surf.triangle(t);
    if (inputFaces.faceCode(t) < 0)
      continue;
    result.boundaryTriangles.insert(result.boundaryTriangles.end(), v, v + 3);
    result.boundaryInputTriangle.push_back(t);
    result.boundaryPatch.push_back(surf.hasPatchIds() ? surf.patchIds[t] : result.triangleShell[t]);
  }
  return Status::success();
}

// The volume of the output tets, summed with compensation (Kahan) so that it can be compared with the
// enclosed volume at 1e-9.
double compensatedTetVolume(const MesherResult& result)
{
  double sum = 0, c = 0;
  for (size_t t = 0; t < result.tets.size(); t += 4)
  {
    const double* a = &result.points[3 * static_cast<size_t>(result.tets[t])];
    const double* b = &result.points[3 * static_cast<size_t>(result.tets[t + 1])];
    const double* cc = &result.points[3 * static_cast<size_t>(result.tets[t + 2])];
    const double* d = &result.points[3 * static_cast<size_t>(result.tets[t + 3])];
    double e[3][3];
    for (int k = 0; k < 3; ++k)
    {
      e[0][k] = b[k] - a[k];
      e[1][k] = cc[k] - a[k];
      e[2][k] = d[k] - a[k];
    }
    const double v =
      (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
      6.0;
    const double y = v - c, tt = sum + y;
    c = (tt - sum) - y;
    sum = tt;
  }
  return sum;
}

} // namespace

Status meshSurface(const SurfaceMesh& input, const MesherOptions& options, MesherResult& result, Progress* progress)
{
  const auto tStart = std::chrono::steady_clock::now();
  result = MesherResult();
  SilentProgress silent;
  Progress* pr = progress ? progress : &silent;
  MesherStatistics& st = result.stats;
  if (input.numberOfTriangles() == 0)
    return Status::failure(ErrorKind::EmptyInput, "The surface has no triangles.");
  if (options.maxSteinerPoints < -1)
    return Status::failure(ErrorKind::InvalidOption, "maxSteinerPoints must be -1 (automatic) or >= 0.");

  // 1. Merge and validate.
  auto t0 = std::chrono::steady_clock::now();
  SurfaceMesh surf;
  std::vector<int> shellDepth;
  Status s = checkAndMerge(input, options, pr, surf, result, shellDepth);
  if (!s.ok())
    return s;
  const int32_t N = surf.numberOfPoints();
  st.secondsCheck = since(t0);

  // 2. Delaunay of the referenced points and a far box.
  t0 = std::chrono::steady_clock::now();
  TetMesh mesh;
  std::vector<uint8_t> used;
  s = delaunayInFarBox(surf, options, pr, mesh, used);
  if (!s.ok())
    return s;
  st.secondsDelaunay = since(t0);
  if (pr->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Meshing was cancelled.");

  // 3-5. Recovery, exterior removal, removal of the boundary Steiner points (with retries).
  std::vector<VertexKind> kinds(static_cast<size_t>(N + 8), VertexKind::Unused);
  for (int32_t v = 0; v < N; ++v)
    if (used[v])
      kinds[v] = VertexKind::Boundary;
  for (int c = 0; c < 8; ++c)
    kinds[N + c] = VertexKind::Box;
  BoundaryConstraints bc;
  MeshEditor ed(mesh);
  RegionResult regions;
  s = recoverDomain(surf, options, pr, ed, bc, kinds, regions, st);
  if (!s.ok())
    return s;

  // 5b. Grid control and quality (MeshImprovement.h).
  t0 = std::chrono::steady_clock::now();
  ImprovementOptions improvement = options.improvement;
  improvement.threads = options.threads;
  s = improveDomainMesh(ed, bc, surf, kinds, regions.tetRegion, improvement, st.improvement, pr);
  if (!s.ok())
    return s;
  st.secondsImprovement = since(t0);

  // 6. Output (a few tenths of a second at 5M tets: the user is asked between its steps; a result left
  //    unfinished is emptied).
  const Status cancelled = Status::failure(ErrorKind::Cancelled, "Meshing was cancelled.");
  if (pr->cancelled())
    return cancelled;
  s = emitResult(mesh, surf, kinds, regions.tetRegion, result, pr);
  if (s.ok() && pr->cancelled())
    s = cancelled;
  if (!s.ok())
  {
    result = MesherResult();
    return s;
  }
  st.steinerInterior -= st.improvement.fieldPoints + st.improvement.clusterPoints + st.improvement.splitPoints;
  st.points = static_cast<int64_t>(result.points.size() / 3);
  st.tets = static_cast<int64_t>(result.tets.size() / 4);
  st.enclosedVolume = enclosedVolume(surf.points, surf.triangles, result.triangleShell, shellDepth, options.regionRule);
  st.tetVolume = compensatedTetVolume(result);
  if (pr->cancelled())
  {
    result = MesherResult();
    return cancelled;
  }
  if (options.verify)
  {
    BoundaryCheckReport br = checkBoundaryConformity(result.points, N, result.tets, surf.triangles, st.enclosedVolume,
                                                     nullptr, options.threads);
    const bool boundaryOk =
      options.regionRule == RegionRule::EvenOdd ? br.boundaryEqualsInput() : br.inputTrianglesNotFaces == 0;
    if (!br.meshValid() || !boundaryOk || (options.checkSurface && br.relativeVolumeError > 1e-9))
    {
      std::vector<int64_t> ids = br.firstProblems;
      result = MesherResult();
      return Status::failure(ErrorKind::InternalError, "The mesh failed its final check: " + br.summary(), ids);
    }
  }
  st.secondsTotal = since(tStart);
  pr->report(1.0, "Done");
  return Status::success();
}

} // namespace volgrid
