#include "Delaunay.h"
#include "ParallelFor.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "DelaunayInserterImpl.h"
#include "SpatialSort.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

namespace volgrid
{

namespace
{
// Lattice inputs (regular grids, integer or dyadic coordinates with few significant bits): every
// coordinate is an integer multiple of a unit 2^k and below 2^25 units, so coordinate differences are
// exact, and when they are at most D units the determinants evaluated in doubles are exact too (all
// intermediate values are integers times a power of two below 2^53): orient3d <= 6 D^3 (D <= 2^16),
// insphere <= 72 D^5 (D <= 2^9). For such inputs (cospherical by the thousand) this replaces the slow
// exact expansion path that proves a determinant to be zero; the SoS tie-break is still
// predicates::detail::insphereSoSTie, and anything outside the limits goes through the predicates.
bool latticeUnit(const double* xyz, size_t n, double& unit)
{
  int lowest = 4096, highest = -4096;
  for (size_t i = 0; i < 3 * n; ++i)
  {
    uint64_t bits;
    std::memcpy(&bits, xyz + i, sizeof bits);
    const int e = static_cast<int>((bits >> 52) & 0x7ff);
    const uint64_t frac = bits & ((uint64_t(1) << 52) - 1);
    if (e == 0 && frac == 0)
      continue; // zero
    if (e == 0 || e == 0x7ff)
      return false; // subnormal or non-finite
    const uint64_t mant = frac | (uint64_t(1) << 52);
    lowest = std::min(lowest, e - 1075 + __builtin_ctzll(mant));
    highest = std::max(highest, e - 1023);
  }
  if (lowest > highest || highest - lowest > 24 || lowest < -150 || highest > 150)
    return false;
  unit = std::ldexp(1.0, lowest);
  return true;
}

// Merge exact duplicates among Hilbert-sorted ids (equal coordinates have equal keys). Fills
// inputToVertex for the merged ones and removes them from ids; the representative is the lowest id.
void mergeDuplicates(const double* xyz, std::vector<int32_t>& ids, const std::vector<uint64_t>& keys,
                     std::vector<int32_t>& inputToVertex)
{
  size_t out = 0;
  const size_t n = ids.size();
  std::vector<int32_t> run;
  for (size_t i = 0; i < n;)
  {
    size_t j = i + 1;
    while (j < n && keys[j] == keys[i])
      ++j;
    if (j == i + 1)
    {
      ids[out++] = ids[i];
      i = j;
      continue;
    }
    run.assign(ids.begin() + static_cast<std::ptrdiff_t>(i), ids.begin() + static_cast<std::ptrdiff_t>(j));
    std::sort(run.begin(), run.end(),
              [&](int32_t a, int32_t b)
              {
                const double* p = xyz + 3 * static_cast<size_t>(a);
                const double* q = xyz + 3 * static_cast<size_t>(b);
                if (p[0] != q[0])
                  return p[0] < q[0];
                if (p[1] != q[1])
                  return p[1] < q[1];
                if (p[2] != q[2])
                  return p[2] < q[2];
                return a < b;
              });
    int32_t rep = -1;
    for (size_t k = 0; k < run.size(); ++k)
    {
      if (k > 0 && samePoint(xyz + 3 * static_cast<size_t>(run[k]), xyz + 3 * static_cast<size_t>(rep)))
      {
        inputToVertex[run[k]] = rep;
        continue;
      }
      rep = run[k];
      ids[out++] = rep;
    }
    i = j;
  }
  ids.resize(out);
}

bool collinear(const double* a, const double* b, const double* c)
{
  return predicates::orient2dProjected(a, b, c, 0) == 0 && predicates::orient2dProjected(a, b, c, 1) == 0 &&
    predicates::orient2dProjected(a, b, c, 2) == 0;
}

// Refuses an empty point set, one too large for the tet index encoding, and non-finite coordinates.
Status checkPoints(const double* xyz, size_t n)
{
  if (n == 0 || !xyz)
    return Status::failure(ErrorKind::EmptyInput, "The point set is empty.");
  // Tet indices are stored as (tet<<2)|face in int32: about 6.5 tets per point -> 2^29 / 7 points.
  if (n > (size_t(1) << 29) / 8)
    return Status::failure(ErrorKind::InvalidOption,
                           "Too many points (" + std::to_string(n) + "); at most " +
                             std::to_string((size_t(1) << 29) / 8) + " are supported.");
  size_t bad = 0;
  std::vector<int64_t> first;
  for (size_t i = 0; i < n; ++i)
  {
    const double* p = xyz + 3 * i;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      if (first.size() < 5)
        first.push_back(static_cast<int64_t>(i));
      ++bad;
    }
  }
  if (bad)
    return Status::failure(ErrorKind::NonFinitePoint,
                           std::to_string(bad) + " point(s) have NaN or infinite coordinates (first id " +
                             std::to_string(first[0]) + ").",
                           first);
  return Status::success();
}

// The insertion order `order` (input ids): with options.spatialSort, Hilbert-sorted in BRIO rounds
// (roundStarts: their offsets) with exact duplicates merged (inputToVertex maps them to the lowest id);
// else the input order. inputToVertex: the identity apart from those.
void insertionOrder(const double* xyz, size_t n, const DelaunayOptions& options, std::vector<int32_t>& inputToVertex,
                    std::vector<int32_t>& order, std::vector<size_t>& roundStarts)
{
  inputToVertex.resize(n);
  for (size_t i = 0; i < n; ++i)
    inputToVertex[i] = static_cast<int32_t>(i);
  order.resize(n);
  for (size_t i = 0; i < n; ++i)
    order[i] = static_cast<int32_t>(i);
  if (options.spatialSort)
  {
    std::vector<uint64_t> keys;
    hilbertSort(xyz, order, &keys);
    mergeDuplicates(xyz, order, keys, inputToVertex);
    std::vector<uint64_t>().swap(keys);
    brioRounds(order, options.seed, 64, &roundStarts);
  }
}

// The first tet: four affinely independent vertices of `mesh`, the earliest in insertion order; a
// failure naming the degeneracy (of all n input points) when there are none.
Status findFirstTet(const TetMesh& mesh, size_t n, int32_t firstTet[4])
{
  const int32_t im = mesh.numVertices();
  int32_t ia = 0, ib = im, ic = im, id = im;
  for (int32_t k = 1; k < im && ib == im; ++k)
    if (!samePoint(mesh.point(k), mesh.point(ia)))
      ib = k;
  for (int32_t k = ib + 1; k < im && ic == im; ++k)
    if (!collinear(mesh.point(ia), mesh.point(ib), mesh.point(k)))
      ic = k;
  for (int32_t k = ic + 1; k < im && id == im; ++k)
    if (predicates::orient3d(mesh.point(ia), mesh.point(ib), mesh.point(ic), mesh.point(k)) != 0)
      id = k;
  if (id >= im)
  {
    const char* what = ib >= im ? "identical" : ic >= im ? "collinear" : "coplanar";
    return Status::failure(ErrorKind::DegenerateInput,
                           "All " + std::to_string(n) + " points are " + what +
                             ": a tetrahedralization needs at least four affinely independent points.");
  }
  firstTet[0] = ia;
  firstTet[1] = ib;
  firstTet[2] = ic;
  firstTet[3] = id;
  return Status::success();
}

// PointLocation::BucketGrid: the grid over the input's bounding box (m vertices to come), the first tet's
// vertices registered in it.
void enableBuckets(DelaunayInserter& inserter, const TetMesh& mesh, const double* xyz, size_t n, size_t m)
{
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
    lo[a] = hi[a] = xyz[a];
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], xyz[3 * i + a]);
      hi[a] = std::max(hi[a], xyz[3 * i + a]);
    }
  inserter.enableBucketGrid(lo, hi, m);
  for (int32_t t = 0; t < mesh.tetCapacity(); ++t)
    if (!mesh.isGhost(t))
      for (int k = 0; k < 4; ++k)
        inserter.registerVertex(mesh.vertex(t, k), t);
}

// Inserts every vertex but the first tet's, in insertion order: the BRIO rounds large enough for it on
// `threads` workers (insertParallel), the others and the points those leave over sequentially. A
// duplicate found on the way maps to its twin in inputToVertex. Fails when cancelled (the mesh cleared).
Status insertPoints(TetMesh& mesh, DelaunayInserter& inserter, const std::vector<int32_t>& order,
                    const std::vector<size_t>& roundStarts, const int32_t firstTet[4], const DelaunayOptions& options,
                    int threads, std::vector<int32_t>& inputToVertex, DelaunayReport& rep, Progress* progress)
{
  const size_t m = order.size();
  const int32_t im = static_cast<int32_t>(m);
  constexpr int32_t kReportEvery = 1 << 16;
  auto isFirstTet = [&](int32_t k)
  { return k == firstTet[0] || k == firstTet[1] || k == firstTet[2] || k == firstTet[3]; };
  auto cancelled = [&]()
  {
    if (!progress->cancelled())
      return false;
    mesh.clear();
    return true;
  };
  // Sequential insertion of order[from..to).
  auto insertRange = [&](int32_t from, int32_t to)
  {
    for (int32_t k = from; k < to; ++k)
    {
      if (isFirstTet(k))
        continue;
      const DelaunayInserter::Result r = inserter.insert(k, -1, k + 1 < im ? mesh.point(k + 1) : nullptr);
      if (r.duplicateOf >= 0)
        inputToVertex[order[k]] = order[r.duplicateOf];
      if ((k & (kReportEvery - 1)) == 0)
      {
        progress->report(static_cast<double>(k) / static_cast<double>(m), "Inserting points");
        if (cancelled())
          return false;
      }
    }
    return true;
  };

  int32_t done = 0;          // order[0..done) handled
  std::vector<int32_t> rest; // points left over by the parallel stage
  if (threads > 1 && options.location == PointLocation::Walk && roundStarts.size() > 2 && m >= kParallelMinPoints)
  {
    // Rounds with enough points run on `threads` workers (chunks of the Hilbert order of the round).
    size_t r0 = 0;
    while (r0 + 1 < roundStarts.size() && roundStarts[r0 + 1] - roundStarts[r0] < kParallelMinRound)
      ++r0;
    if (r0 + 1 < roundStarts.size())
    {
      if (!insertRange(0, static_cast<int32_t>(roundStarts[r0])))
        return Status::failure(ErrorKind::Cancelled, "Delaunay tetrahedralization cancelled.");
      done = static_cast<int32_t>(roundStarts[r0]);
      const Status st = insertParallel(mesh, inserter, order, roundStarts, r0, firstTet, inputToVertex, rest, rep,
                                       progress, options.seed, threads);
      if (!st.ok())
      {
        mesh.clear();
        return st;
      }
      done = im;
    }
  }
  if (!insertRange(done, im))
    return Status::failure(ErrorKind::Cancelled, "Delaunay tetrahedralization cancelled.");
  for (int32_t k : rest)
  {
    const DelaunayInserter::Result r = inserter.insert(k, -1, nullptr);
    if (r.duplicateOf >= 0)
      inputToVertex[order[k]] = order[r.duplicateOf];
  }
  return Status::success();
}

// rep's duplicate count and first ids: the input points mapped to another one.
void countDuplicates(const std::vector<int32_t>& inputToVertex, DelaunayReport& rep)
{
  for (size_t i = 0; i < inputToVertex.size(); ++i)
    if (inputToVertex[i] != static_cast<int32_t>(i))
    {
      ++rep.numDuplicates;
      if (rep.firstDuplicates.size() < 5)
        rep.firstDuplicates.push_back(static_cast<int64_t>(i));
    }
}

} // namespace

Status buildDelaunay(const double* xyz, size_t n, const DelaunayOptions& options, TetMesh& mesh,
                     std::vector<int32_t>& inputToVertex, Progress* progress, DelaunayReport* report)
{
  SilentProgress silent;
  if (!progress)
    progress = &silent;
  DelaunayReport localReport;
  DelaunayReport& rep = report ? *report : localReport;
  rep = DelaunayReport();
  rep.numInput = n;
  mesh.clear();
  inputToVertex.clear();
  const Status valid = checkPoints(xyz, n);
  if (!valid.ok())
    return valid;
  progress->report(0.0, "Sorting points");
  std::vector<int32_t> order;
  std::vector<size_t> roundStarts; // BRIO rounds (offsets into order)
  insertionOrder(xyz, n, options, inputToVertex, order, roundStarts);

  // During the construction vertex k is the k-th point in insertion order (order[k] is its input id):
  // consecutive insertions then touch nearby memory. The SoS ids are the input ids, so the result does
  // not depend on the order. The tets are renumbered to input ids at the end.
  const size_t m = order.size();
  // Tets: ~6.75 per point for uniform random points, ~7.0 for jittered grids; reserve 7.25 (then 1.5x
  // growth) so that the big arrays are allocated once.
  mesh.reserve(n, static_cast<size_t>(7.25 * static_cast<double>(m)) + 64);
  mesh.points.resize(3 * m);
  for (size_t k = 0; k < m; ++k)
    for (int a = 0; a < 3; ++a)
      mesh.points[3 * k + a] = xyz[3 * static_cast<size_t>(order[k]) + a];
  int32_t firstTet[4];
  const Status first = findFirstTet(mesh, n, firstTet);
  if (!first.ok())
  {
    mesh.clear();
    return first;
  }
  initDelaunayTet(mesh, firstTet[0], firstTet[1], firstTet[2], firstTet[3]);

  DelaunayInserter inserter(mesh, options.seed);
  inserter.setSoSIds(order.data());
  double unit = 0;
  if (latticeUnit(xyz, n, unit))
  {
    inserter.impl_->latticeOrientLimit = 65536.0 * unit;
    // |p_i - e|^2 <= (512 u)^2 implies every difference is at most 512 units.
    inserter.impl_->latticeInsphereLimit2 = (512.0 * unit) * (512.0 * unit);
  }
  if (options.location == PointLocation::BucketGrid)
    enableBuckets(inserter, mesh, xyz, n, m);
  progress->report(0.0, "Inserting points");
  if (progress->cancelled())
  {
    mesh.clear();
    return Status::failure(ErrorKind::Cancelled, "Delaunay tetrahedralization cancelled.");
  }
  const int threads = std::min(resolveThreads(options.threads), kMaxParallelWorkers);
  const Status inserted =
    insertPoints(mesh, inserter, order, roundStarts, firstTet, options, threads, inputToVertex, rep, progress);
  if (!inserted.ok())
    return inserted;
  // Back to input vertex numbering; optionally canonical tet numbering (independent of the thread count
  // and of the construction's history).
  rep.walkSteps += inserter.walkSteps();
  rep.cavityTets += inserter.cavityTets();
  const bool parallelPossible =
    options.location == PointLocation::Walk && options.spatialSort && m >= kParallelMinPoints;
  if (options.canonicalNumbering || parallelPossible)
  {
    // The inserter's per-vertex buffers are not needed any more: free them before the canonical pass
    // (it sets the peak memory).
    std::vector<int8_t>().swap(inserter.impl_->vlocal);
    std::vector<int32_t>().swap(inserter.impl_->vertexNext);
    std::vector<int32_t>().swap(inserter.impl_->vertexTet);
#ifdef __GLIBC__
    malloc_trim(0); // and give back what the parallel stage's threads freed in their own arenas
#endif
    canonicalizeTets(mesh, options.spatialSort ? order.data() : nullptr, threads);
  }
  else if (options.spatialSort)
  {
    for (int32_t& v : mesh.tetVertices)
      if (v >= 0)
        v = order[v];
  }
  mesh.points.assign(xyz, xyz + 3 * n);
  // Duplicates found during insertion (input order, no sorting) map to the earlier-inserted point,
  // which is the lowest id: insertion follows the input order apart from the first four points, and
  // none of those can have an earlier twin (they are the first points that differ / are not collinear
  // / not coplanar).
  countDuplicates(inputToVertex, rep);
  rep.numVertices = n - rep.numDuplicates;
  if (!options.keepGhosts)
    mesh.removeGhostTets();
  progress->report(1.0, "Inserting points");
  return Status::success();
}

} // namespace volgrid
