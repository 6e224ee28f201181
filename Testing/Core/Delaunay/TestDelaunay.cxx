// Delaunay kernel: exactness (brute-force reference, SoS uniqueness on cospherical grids), degenerate
// and bad input, duplicates, scaling/offset invariance, incremental insertion.
#include "Delaunay.h"
#include "MeshChecker.h"
#include "Predicates.h"
#include "SpatialSort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace volgrid;

namespace
{

using Tet = std::array<int32_t, 4>;

// Uniform points in [0,1)^3 on the dyadic grid 2^-bits (exactly scalable/translatable).
std::vector<double> randomPoints(size_t n, uint64_t seed, int bits = 20)
{
  SplitMix64 rng(seed);
  std::vector<double> xyz(3 * n);
  for (double& x : xyz)
    x = std::ldexp(static_cast<double>(rng.next() >> (64 - bits)), -bits);
  return xyz;
}

std::vector<double> gridPoints(int m, double jitter = 0.0, uint64_t seed = 1)
{
  SplitMix64 rng(seed);
  std::vector<double> xyz;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
        for (int v : { i, j, k })
          xyz.push_back(v + jitter * (static_cast<double>(rng.next() >> 11) * 0x1p-53 - 0.5));
  return xyz;
}

// Sorted vertex tuples of the finite tets.
std::vector<Tet> tetSet(const TetMesh& mesh)
{
  std::vector<Tet> tets;
  mesh.forEachFiniteTet(
    [&](int32_t t)
    {
      Tet a{ mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3) };
      std::sort(a.begin(), a.end());
      tets.push_back(a);
    });
  std::sort(tets.begin(), tets.end());
  return tets;
}

// Brute force: every non-flat 4-subset whose circumsphere (with the same SoS rule) contains no other
// point. O(n^5), tiny inputs only.
std::vector<Tet> bruteForceDelaunay(const std::vector<double>& xyz)
{
  const int n = static_cast<int>(xyz.size() / 3);
  auto P = [&](int i) { return xyz.data() + 3 * i; };
  std::vector<Tet> tets;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c)
        for (int d = c + 1; d < n; ++d)
        {
          const int o = predicates::orient3d(P(a), P(b), P(c), P(d));
          if (o == 0)
            continue;
          int v[4] = { a, b, c, d };
          if (o < 0)
            std::swap(v[0], v[1]);
          bool empty = true;
          for (int e = 0; e < n && empty; ++e)
            if (e != a && e != b && e != c && e != d)
              empty = predicates::insphereSoS(P(v[0]), P(v[1]), P(v[2]), P(v[3]), P(e), v[0], v[1], v[2], v[3], e) < 0;
          if (empty)
            tets.push_back({ a, b, c, d });
        }
  std::sort(tets.begin(), tets.end());
  return tets;
}

double totalVolume6(const TetMesh& mesh) // sum of 6 * volume of the finite tets
{
  double sum = 0;
  mesh.forEachFiniteTet(
    [&](int32_t t)
    {
      const double* a = mesh.point(mesh.vertex(t, 0));
      const double* b = mesh.point(mesh.vertex(t, 1));
      const double* c = mesh.point(mesh.vertex(t, 2));
      const double* d = mesh.point(mesh.vertex(t, 3));
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      sum +=
        u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    });
  return sum;
}

struct Built
{
  Status status;
  TetMesh mesh;
  std::vector<int32_t> map;
  DelaunayReport report;
};

Built build(const std::vector<double>& xyz, DelaunayOptions opt = DelaunayOptions())
{
  Built b;
  b.status = buildDelaunay(xyz.data(), xyz.size() / 3, opt, b.mesh, b.map, nullptr, &b.report);
  return b;
}

void expectValid(const TetMesh& mesh)
{
  const MeshCheckReport r = checkMesh(mesh);
  EXPECT_TRUE(r.valid) << r.summary();
}

} // namespace

TEST(Delaunay, RandomPointsGiveValidDelaunayMesh)
{
  const auto xyz = randomPoints(3000, 11);
  for (bool sorted : { true, false })
    for (bool ghosts : { true, false })
    {
      DelaunayOptions opt;
      opt.spatialSort = sorted;
      opt.keepGhosts = ghosts;
      Built b = build(xyz, opt);
      ASSERT_TRUE(b.status.ok()) << b.status.message;
      const MeshCheckReport r = checkMesh(b.mesh);
      EXPECT_TRUE(r.valid) << r.summary();
      EXPECT_EQ(r.vertices, 3000);
      // Euler for a triangulated ball: T = E - V - H/2 + 1.
      EXPECT_EQ(r.finiteTets, r.edges - r.vertices - r.hullFaces / 2 + 1);
      EXPECT_EQ(b.mesh.numGhostTets(), ghosts ? r.hullFaces : 0);
      EXPECT_EQ(b.report.numDuplicates, 0u);
      // Uniform random points: about 6.3-6.8 tets per point at this size.
      EXPECT_GT(r.finiteTets, 6 * 3000);
      EXPECT_LT(r.finiteTets, 7 * 3000);
    }
}

TEST(Delaunay, MatchesBruteForceOnTinyInputs)
{
  for (uint64_t seed = 1; seed <= 12; ++seed)
    for (size_t n : { 4, 5, 7, 10, 16 })
    {
      const auto xyz = randomPoints(n, seed * 100 + n, 6); // coarse grid: many exact degeneracies
      Built b = build(xyz);
      ASSERT_TRUE(b.status.ok() || b.status.kind == ErrorKind::DegenerateInput);
      if (!b.status.ok())
        continue;
      // Merged duplicates are not vertices: compare with the brute force on the distinct points.
      std::vector<double> unique;
      std::vector<int32_t> ids;
      for (size_t i = 0; i < n; ++i)
        if (b.map[i] == static_cast<int32_t>(i))
        {
          unique.insert(unique.end(), xyz.begin() + 3 * i, xyz.begin() + 3 * i + 3);
          ids.push_back(static_cast<int32_t>(i));
        }
      std::vector<Tet> ref = bruteForceDelaunay(unique);
      for (Tet& t : ref)
      {
        for (int32_t& v : t)
          v = ids[v];
        std::sort(t.begin(), t.end());
      }
      std::sort(ref.begin(), ref.end());
      EXPECT_EQ(tetSet(b.mesh), ref) << "seed " << seed << " n " << n;
      expectValid(b.mesh);
    }
}

TEST(Delaunay, SmallGridMatchesBruteForce)
{
  const auto xyz = gridPoints(3); // 27 cospherical-rich points: SoS decides every tie
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  EXPECT_EQ(tetSet(b.mesh), bruteForceDelaunay(xyz));
  EXPECT_DOUBLE_EQ(totalVolume6(b.mesh), 6.0 * 8);
}

TEST(Delaunay, RegularGridIsUniqueForAnyInsertionOrder)
{
  const auto xyz = gridPoints(10);
  DelaunayOptions a, c, d;
  a.seed = 1;
  c.seed = 987654321;
  d.spatialSort = false;
  Built ba = build(xyz, a), bc = build(xyz, c), bd = build(xyz, d);
  ASSERT_TRUE(ba.status.ok() && bc.status.ok() && bd.status.ok());
  expectValid(ba.mesh);
  expectValid(bd.mesh);
  const auto ref = tetSet(ba.mesh);
  EXPECT_EQ(tetSet(bc.mesh), ref);
  EXPECT_EQ(tetSet(bd.mesh), ref);
  // The tets tile the cube exactly (integer coordinates: the volume sum is exact).
  EXPECT_EQ(totalVolume6(ba.mesh), 6.0 * 729);
}

TEST(Delaunay, JitteredGridIsValid)
{
  const auto xyz = gridPoints(12, 1e-6, 5);
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  expectValid(b.mesh);
  EXPECT_NEAR(totalVolume6(b.mesh), 6.0 * 11 * 11 * 11, 0.05); // the jittered hull bulges by ~1e-6
}

TEST(Delaunay, BucketGridLocationGivesTheSameMesh)
{
  const auto xyz = randomPoints(5000, 3);
  DelaunayOptions grid;
  grid.location = PointLocation::BucketGrid;
  DelaunayOptions unsortedGrid = grid;
  unsortedGrid.spatialSort = false;
  Built a = build(xyz), b = build(xyz, grid), c = build(xyz, unsortedGrid);
  ASSERT_TRUE(a.status.ok() && b.status.ok() && c.status.ok());
  expectValid(b.mesh);
  EXPECT_EQ(tetSet(a.mesh), tetSet(b.mesh));
  EXPECT_EQ(tetSet(a.mesh), tetSet(c.mesh));
}

TEST(Delaunay, DuplicatesAreMergedIntoTheFirstOccurrence)
{
  const size_t n = 400;
  const auto base = randomPoints(n, 21);
  // base, then each point again (reversed), then every third point a third time.
  std::vector<double> xyz = base;
  for (size_t i = n; i-- > 0;)
    xyz.insert(xyz.end(), base.begin() + 3 * i, base.begin() + 3 * i + 3);
  for (size_t i = 0; i < n; i += 3)
    xyz.insert(xyz.end(), base.begin() + 3 * i, base.begin() + 3 * i + 3);
  const size_t total = xyz.size() / 3;
  for (bool sorted : { true, false })
  {
    DelaunayOptions opt;
    opt.spatialSort = sorted;
    Built b = build(xyz, opt);
    ASSERT_TRUE(b.status.ok());
    EXPECT_EQ(b.report.numDuplicates, total - n);
    EXPECT_EQ(b.report.numVertices, n);
    ASSERT_FALSE(b.report.firstDuplicates.empty());
    EXPECT_EQ(b.report.firstDuplicates[0], static_cast<int64_t>(n));
    ASSERT_EQ(b.map.size(), total);
    for (size_t i = 0; i < n; ++i)
      EXPECT_EQ(b.map[i], static_cast<int32_t>(i));
    for (size_t i = 0; i < n; ++i)
      EXPECT_EQ(b.map[n + i], static_cast<int32_t>(n - 1 - i));
    for (size_t k = 2 * n, i = 0; k < total; ++k, i += 3)
      EXPECT_EQ(b.map[k], static_cast<int32_t>(i));
    // Duplicates are used by no tet; the mesh equals the one of the distinct points.
    const MeshCheckReport r = checkMesh(b.mesh);
    EXPECT_TRUE(r.valid) << r.summary();
    EXPECT_EQ(r.vertices, static_cast<int64_t>(n));
    EXPECT_EQ(tetSet(b.mesh), tetSet(build(base).mesh));
    EXPECT_EQ(b.mesh.numVertices(), static_cast<int32_t>(total));
  }
}

TEST(Delaunay, AllCoplanarButFourIsValid)
{
  SplitMix64 rng(4);
  std::vector<double> xyz;
  for (int i = 0; i < 300; ++i)
  {
    xyz.push_back(static_cast<double>(rng.next() % 1000));
    xyz.push_back(static_cast<double>(rng.next() % 1000));
    xyz.push_back(0.0);
  }
  for (double z : { 100.0, 250.0, -80.0, 300.0 })
  {
    xyz.push_back(static_cast<double>(rng.next() % 1000));
    xyz.push_back(static_cast<double>(rng.next() % 1000));
    xyz.push_back(z);
  }
  for (bool sorted : { true, false })
  {
    DelaunayOptions opt;
    opt.spatialSort = sorted;
    Built b = build(xyz, opt);
    ASSERT_TRUE(b.status.ok()) << b.status.message;
    const MeshCheckReport r = checkMesh(b.mesh);
    EXPECT_TRUE(r.valid) << r.summary();
    EXPECT_EQ(r.vertices + static_cast<int64_t>(b.report.numDuplicates), 304);
  }
  // Only one point off the plane: a cone, many coplanar hull faces.
  xyz.resize(3 * 301);
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  expectValid(b.mesh);
}

TEST(Delaunay, DegenerateInputsAreErrors)
{
  std::vector<double> coplanar;
  for (int i = 0; i < 50; ++i)
    coplanar.insert(coplanar.end(), { double(i % 7), double(i / 7), 1.0 * i + 2.0 * (i % 7) - 0.5 * (i / 7) });
  // z = i + 2x - 0.5y with i = x + 7y  ->  z = 3x + 6.5y: a plane.
  Built b = build(coplanar);
  EXPECT_EQ(b.status.kind, ErrorKind::DegenerateInput);
  EXPECT_NE(b.status.message.find("coplanar"), std::string::npos) << b.status.message;
  EXPECT_EQ(b.mesh.numTets(), 0);

  std::vector<double> collinear;
  for (int i = 0; i < 10; ++i)
    collinear.insert(collinear.end(), { 1.0 * i, 2.0 * i, -3.0 * i });
  b = build(collinear);
  EXPECT_EQ(b.status.kind, ErrorKind::DegenerateInput);
  EXPECT_NE(b.status.message.find("collinear"), std::string::npos);

  std::vector<double> same(30, 0.25);
  b = build(same);
  EXPECT_EQ(b.status.kind, ErrorKind::DegenerateInput);
  EXPECT_NE(b.status.message.find("identical"), std::string::npos);

  b = build({ 0, 0, 0, 1, 0, 0, 0, 1, 0 });
  EXPECT_EQ(b.status.kind, ErrorKind::DegenerateInput);

  b = build({});
  EXPECT_EQ(b.status.kind, ErrorKind::EmptyInput);
}

TEST(Delaunay, NonFiniteCoordinatesAreErrors)
{
  auto xyz = randomPoints(100, 8);
  xyz[3 * 17 + 1] = std::numeric_limits<double>::quiet_NaN();
  xyz[3 * 42 + 2] = std::numeric_limits<double>::infinity();
  xyz[3 * 99 + 0] = -std::numeric_limits<double>::infinity();
  Built b = build(xyz);
  EXPECT_EQ(b.status.kind, ErrorKind::NonFinitePoint);
  EXPECT_EQ(b.status.firstIds, (std::vector<int64_t>{ 17, 42, 99 }));
  EXPECT_NE(b.status.message.find("3 point"), std::string::npos) << b.status.message;
}

TEST(Delaunay, ScalingByPowersOfTwoAndOffsetsKeepTheCombinatorics)
{
  const auto xyz = randomPoints(2000, 31, 20);
  const auto ref = tetSet(build(xyz).mesh);
  auto transformed = [&](double scale, double offset)
  {
    std::vector<double> t(xyz);
    for (double& x : t)
      x = x * scale + offset; // exact: 20-bit mantissas, power-of-two scale, 30-bit integer offset
    return t;
  };
  for (double scale : { 0x1p-30, 0x1p-60, 0x1p20 })
  {
    Built b = build(transformed(scale, 0.0));
    ASSERT_TRUE(b.status.ok());
    EXPECT_EQ(tetSet(b.mesh), ref) << "scale " << scale;
  }
  Built off = build(transformed(1.0, 1e9));
  ASSERT_TRUE(off.status.ok());
  EXPECT_EQ(tetSet(off.mesh), ref);
  expectValid(off.mesh);
  // Non-dyadic scaling (rounded coordinates): still an exact Delaunay mesh.
  Built nano = build(transformed(1e-9, 0.0));
  ASSERT_TRUE(nano.status.ok());
  expectValid(nano.mesh);
  // Large offset with non-representable sums (rounded coordinates, many near-degeneracies).
  const auto fine = randomPoints(2000, 32, 52);
  std::vector<double> big(fine);
  for (double& x : big)
    x += 1e9;
  Built bb = build(big);
  ASSERT_TRUE(bb.status.ok());
  expectValid(bb.mesh);
}

TEST(Delaunay, TwoConcentricSpheres)
{
  SplitMix64 rng(77);
  std::vector<double> xyz;
  for (double radius : { 1.0, 2.0 })
    for (int i = 0; i < 1500; ++i)
    {
      double d[3], len2;
      do
      {
        for (double& c : d)
          c = 2.0 * (static_cast<double>(rng.next() >> 11) * 0x1p-53) - 1.0;
        len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      } while (len2 < 1e-4 || len2 > 1.0);
      for (double c : d)
        xyz.push_back(radius * c / std::sqrt(len2));
    }
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  const MeshCheckReport r = checkMesh(b.mesh);
  EXPECT_TRUE(r.valid) << r.summary();
  EXPECT_EQ(r.vertices, 3000);
  // The hull is the outer sphere: 1500 hull vertices -> 2*1500-4 faces.
  EXPECT_EQ(r.hullFaces, 2 * 1500 - 4);
}

TEST(Delaunay, IncrementalInsertionKeepsTheMeshDelaunay)
{
  const auto xyz = randomPoints(1000, 41);
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  DelaunayInserter inserter(b.mesh, 5);
  const auto extra = randomPoints(300, 42);
  int32_t hint = -1;
  for (size_t i = 0; i < 300; ++i)
  {
    double p[3] = { extra[3 * i] * 1.6 - 0.3, extra[3 * i + 1] * 1.6 - 0.3, extra[3 * i + 2] }; // some outside
    const int32_t v = b.mesh.addPoint(p);
    const DelaunayInserter::Result r = inserter.insert(v, hint);
    ASSERT_LT(r.duplicateOf, 0);
    ASSERT_GE(r.tet, 0);
    EXPECT_GE(b.mesh.localIndex(r.tet, v), 0);
    hint = r.tet;
  }
  // A duplicate of an existing vertex is reported, not inserted.
  const int32_t dup = b.mesh.addPoint(b.mesh.point(17));
  const DelaunayInserter::Result r = inserter.insert(dup);
  EXPECT_EQ(r.duplicateOf, 17);
  const MeshCheckReport rep = checkMesh(b.mesh);
  EXPECT_TRUE(rep.valid) << rep.summary();
  EXPECT_EQ(rep.vertices, 1300);
  // The same points built at once give the same tets.
  std::vector<double> all(b.mesh.points.begin(), b.mesh.points.end() - 3);
  EXPECT_EQ(tetSet(build(all).mesh), tetSet(b.mesh));
  // locate() returns a tet containing the point.
  const double q[3] = { 0.5, 0.5, 0.5 };
  const int32_t t = inserter.locate(q);
  ASSERT_GE(t, 0);
  ASSERT_FALSE(b.mesh.isGhost(t));
  for (int i = 0; i < 4; ++i)
  {
    int32_t f[3];
    b.mesh.faceVertices(t, i, f);
    EXPECT_GE(predicates::orient3d(b.mesh.point(f[0]), b.mesh.point(f[1]), b.mesh.point(f[2]), q), 0);
  }
}

TEST(Delaunay, GhostRemovalAndCompaction)
{
  const auto xyz = randomPoints(2000, 51);
  Built b = build(xyz);
  ASSERT_TRUE(b.status.ok());
  const auto ref = tetSet(b.mesh);
  const int32_t finite = b.mesh.numFiniteTets();
  const int32_t removed = b.mesh.removeGhostTets();
  EXPECT_GT(removed, 0);
  EXPECT_EQ(b.mesh.numGhostTets(), 0);
  EXPECT_EQ(b.mesh.numFreeTets(), removed);
  expectValid(b.mesh);
  b.mesh.compact();
  EXPECT_EQ(b.mesh.numTets(), finite);
  EXPECT_EQ(b.mesh.tetCapacity(), finite);
  EXPECT_EQ(tetSet(b.mesh), ref);
  expectValid(b.mesh);
}

namespace
{
struct CancelAfter : Progress
{
  int calls = 0, cancelAt;
  double lastFraction = -1;
  explicit CancelAfter(int n)
    : cancelAt(n)
  {
  }
  void report(double f, const char*) override
  {
    lastFraction = f;
    ++calls;
  }
  bool cancelled() override { return calls >= cancelAt; }
};
} // namespace

TEST(Delaunay, ProgressIsReportedAndCancellationHonoured)
{
  const auto xyz = randomPoints(70000, 61);
  CancelAfter never(1 << 30);
  TetMesh mesh;
  std::vector<int32_t> map;
  Status s = buildDelaunay(xyz.data(), 70000, DelaunayOptions(), mesh, map, &never);
  ASSERT_TRUE(s.ok());
  EXPECT_GE(never.calls, 3);
  EXPECT_EQ(never.lastFraction, 1.0);
  CancelAfter soon(2);
  s = buildDelaunay(xyz.data(), 70000, DelaunayOptions(), mesh, map, &soon);
  EXPECT_EQ(s.kind, ErrorKind::Cancelled);
}

TEST(Delaunay, SpatialSortIsADeterministicPermutation)
{
  const auto xyz = randomPoints(20000, 71);
  std::vector<int32_t> a, b, c;
  brioHilbertOrder(xyz.data(), 20000, 5, a);
  brioHilbertOrder(xyz.data(), 20000, 5, b);
  brioHilbertOrder(xyz.data(), 20000, 6, c);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  std::vector<int32_t> sorted(a);
  std::sort(sorted.begin(), sorted.end());
  for (int32_t i = 0; i < 20000; ++i)
    ASSERT_EQ(sorted[i], i);
  // Hilbert order on a full 8x8x8 grid visits face-adjacent cells consecutively.
  const auto grid = gridPoints(8);
  std::vector<int32_t> ids(512);
  for (int32_t i = 0; i < 512; ++i)
    ids[i] = i;
  hilbertSort(grid.data(), ids);
  for (size_t k = 1; k < ids.size(); ++k)
  {
    double d = 0;
    for (int a3 = 0; a3 < 3; ++a3)
      d += std::fabs(grid[3 * ids[k] + a3] - grid[3 * ids[k - 1] + a3]);
    ASSERT_EQ(d, 1.0) << k;
  }
}

TEST(Delaunay, TwoThreadsGiveTheSameMesh)
{
  // Large enough for the parallel rounds (>= 200k points); duplicates and a regular grid included.
  auto xyz = randomPoints(230000, 81, 30);
  const auto grid = gridPoints(20);
  xyz.insert(xyz.end(), grid.begin(), grid.end());
  xyz.insert(xyz.end(), xyz.begin(), xyz.begin() + 3 * 1000);
  DelaunayOptions one, two;
  one.threads = 1;
  two.threads = 2; // default options otherwise: large inputs are numbered canonically
  Built a = build(xyz, one), b = build(xyz, two);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  EXPECT_EQ(tetSet(a.mesh), tetSet(b.mesh));
  // The same mesh ARRAYS (tet numbering, vertex order, neighbours) whatever the thread count, and from
  // run to run.
  EXPECT_EQ(a.mesh.tetVertices, b.mesh.tetVertices);
  EXPECT_EQ(a.mesh.tetNeighbors, b.mesh.tetNeighbors);
  EXPECT_EQ(a.mesh.tetFlags, b.mesh.tetFlags);
  EXPECT_EQ(b.mesh.numFreeTets(), 0);
  Built c = build(xyz, two);
  EXPECT_EQ(b.mesh.tetVertices, c.mesh.tetVertices);
  EXPECT_EQ(b.mesh.tetNeighbors, c.mesh.tetNeighbors);
  EXPECT_EQ(a.map, b.map);
  EXPECT_EQ(b.report.numDuplicates, 1000u);
  EXPECT_EQ(a.mesh.numGhostTets(), b.mesh.numGhostTets());
  MeshCheckOptions fast;
  fast.euler = false;
  const MeshCheckReport r = checkMesh(b.mesh, fast);
  EXPECT_TRUE(r.valid) << r.summary();
}

// The parallel construction with more workers than this machine has cores (workers then share cores
// and interleave arbitrarily): 1, 2, 3 and 8 threads give the same arrays, and that mesh is valid and
// locally Delaunay on every face (with the symbolic rule on ties). Inputs: random points with
// duplicates, and a pure lattice, where every cell's eight corners are cospherical and only the symbolic
// rule decides.
TEST(Delaunay, AnyThreadCountGivesTheSameMesh)
{
  auto mixed = randomPoints(230000, 82, 30);
  mixed.insert(mixed.end(), mixed.begin(), mixed.begin() + 3 * 500);
  const std::vector<double> lattice = gridPoints(61); // 226,981 points
  const std::vector<double>* inputs[] = { &mixed, &lattice };
  for (const std::vector<double>* xyz : inputs)
  {
    DelaunayOptions options;
    options.threads = 1;
    const Built ref = build(*xyz, options);
    ASSERT_TRUE(ref.status.ok()) << ref.status.message;
    const MeshCheckReport r = checkMesh(ref.mesh, MeshCheckOptions{ true, false, 10 });
    EXPECT_TRUE(r.valid) << r.summary();
    EXPECT_EQ(r.nonDelaunayFaces, 0);
    EXPECT_EQ(ref.mesh.numFreeTets(), 0);
    for (int threads : { 2, 3, 8 })
    {
      SCOPED_TRACE(threads);
      options.threads = threads;
      const Built b = build(*xyz, options);
      ASSERT_TRUE(b.status.ok()) << b.status.message;
      EXPECT_EQ(ref.mesh.tetVertices, b.mesh.tetVertices);
      EXPECT_EQ(ref.mesh.tetNeighbors, b.mesh.tetNeighbors);
      EXPECT_EQ(ref.mesh.tetFlags, b.mesh.tetFlags);
      EXPECT_EQ(ref.mesh.numGhostTets(), b.mesh.numGhostTets());
      EXPECT_EQ(ref.map, b.map);
      EXPECT_EQ(ref.report.numDuplicates, b.report.numDuplicates);
      if (threads == 8) // the arrays are equal; the check is the independent witness of validity
      {
        EXPECT_TRUE(checkMesh(b.mesh, MeshCheckOptions{ true, false, 10 }).valid);
      }
    }
  }
}

TEST(Delaunay, CanonicalTetNumbering)
{
  // Canonical form of the output (canonicalNumbering): within each tet the earliest inserted vertex comes
  // first and the next earliest second (orientation kept by an even permutation; the vertex at infinity
  // counts as the last); without spatial sorting that is the smallest vertex id. No free slots, and the
  // same arrays from run to run, with and without spatial sorting.
  for (bool sort : { true, false })
  {
    const auto xyz = randomPoints(3000, 5, 1);
    DelaunayOptions options;
    options.spatialSort = sort;
    options.canonicalNumbering = true;
    Built a = build(xyz, options);
    ASSERT_TRUE(a.status.ok());
    EXPECT_EQ(a.mesh.numFreeTets(), 0);
    for (int32_t t = 0; t < a.mesh.tetCapacity() && !sort; ++t)
    {
      const int32_t* w = a.mesh.vertices(t);
      const uint32_t u[4] = { uint32_t(w[0]), uint32_t(w[1]), uint32_t(w[2]), uint32_t(w[3]) };
      ASSERT_LT(u[0], u[1]);
      ASSERT_LT(u[0], u[2]);
      ASSERT_LT(u[0], u[3]);
      ASSERT_LT(u[1], u[2]);
      ASSERT_LT(u[1], u[3]);
    }
    MeshCheckOptions fast;
    fast.euler = false;
    const MeshCheckReport r = checkMesh(a.mesh, fast);
    EXPECT_TRUE(r.valid) << r.summary();
    Built b = build(xyz, options);
    EXPECT_EQ(a.mesh.tetVertices, b.mesh.tetVertices);
    EXPECT_EQ(a.mesh.tetNeighbors, b.mesh.tetNeighbors);
  }
}
