// Field points (paper 7.2) and clustering on convex-hull domains: the Delaunay mesh of a closed surface's
// points without ghosts, whose hull faces are the boundary (no recovery needed).
#include "Delaunay.h"
#include "Enclosures.h"
#include "FieldPoints.h"
#include "MeshChecker.h"
#include "MeshTestFaces.h"
#include "SizingField.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

using namespace volgrid;
using testmesh::hullFaces;

namespace
{
double dist(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

struct Domain
{
  SurfaceMesh surface;
  TetMesh mesh;
  SizingField sizing;
};

void makeDomain(Domain& d, EnclosureShape shape, double edge, const SizingOptions& so = SizingOptions())
{
  EnclosureOptions o;
  o.shape = shape;
  o.targetEdgeLength = edge;
  ASSERT_TRUE(makeEnclosure(o, d.surface).ok());
  std::vector<int32_t> map;
  DelaunayOptions opt;
  opt.keepGhosts = false;
  ASSERT_TRUE(buildDelaunay(d.surface.points.data(), d.surface.numberOfPoints(), opt, d.mesh, map).ok());
  ASSERT_TRUE(d.sizing
                .build(d.surface.points.data(), d.surface.numberOfPoints(), d.surface.triangles.data(),
                       d.surface.numberOfTriangles(), so)
                .ok());
}

// Pairs of vertices closer than eq. 5 allows, a field point (number n0 on) being one of them: beta x its size
// from an earlier vertex, beta x the smaller size from another field point (whichever came first).
int64_t spacingViolations(const TetMesh& m, int32_t n0, const SizingField& sizing, double beta)
{
  const int32_t n = m.numVertices();
  std::vector<double> h(static_cast<size_t>(n));
  for (int32_t v = n0; v < n; ++v)
    h[v] = sizing.evaluate(m.point(v));
  int64_t violations = 0;
  for (int32_t a = n0; a < n; ++a)
    for (int32_t b = 0; b < a; ++b)
    {
      const double limit = b < n0 ? beta * h[a] : beta * std::min(h[a], h[b]);
      violations += dist(m.point(a), m.point(b)) < limit * (1 - 1e-9);
    }
  return violations;
}

// Mean length of the distinct edges with both ends within radius r of c.
double meanEdgeNear(const TetMesh& m, const double* c, double r)
{
  std::set<std::pair<int32_t, int32_t>> edges;
  m.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = m.vertices(t);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (dist(m.point(v[i]), c) < r && dist(m.point(v[j]), c) < r)
            edges.insert({ std::min(v[i], v[j]), std::max(v[i], v[j]) });
    });
  double s = 0;
  for (const auto& e : edges)
    s += dist(m.point(e.first), m.point(e.second));
  return edges.empty() ? 0 : s / edges.size();
}
} // namespace

TEST(FieldPoints, TetCountGrowsAsAlphaDecreases)
{
  int32_t previous = 0;
  // (Very large alpha values insert only a few points, and a few points in the middle of a boundary-only
  // Delaunay mesh can lower the tet count: its cavities are large. The range starts where that is over.)
  for (double alpha : { 1.4, 1.1, 0.9, 0.75, 0.6, 0.5 })
  {
    Domain d;
    makeDomain(d, EnclosureShape::Box, 0.15);
    FieldPointOptions fo;
    fo.alpha = alpha;
    fo.beta = 0.5;
    FieldPointReport rep;
    ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, fo, nullptr, nullptr, nullptr, nullptr, &rep).ok());
    EXPECT_GT(d.mesh.numTets(), previous) << "alpha " << alpha;
    previous = d.mesh.numTets();
    const MeshCheckReport check = checkMesh(d.mesh);
    EXPECT_TRUE(check.valid) << check.summary();
    EXPECT_GT(rep.passes, 1);
    EXPECT_EQ(rep.insertedPerPass.back(), 0); // ran to completion
  }
}

TEST(FieldPoints, BetaSpacingHoldsAndBoundaryIsKept)
{
  for (double beta : { 0.3, 0.6, 0.9 })
  {
    Domain d;
    makeDomain(d, EnclosureShape::Sphere, 0.25);
    const int32_t n0 = d.mesh.numVertices();
    const auto faces0 = hullFaces(d.mesh);
    FieldPointOptions fo;
    fo.alpha = 0.6;
    fo.beta = beta;
    FieldPointReport rep;
    ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, fo, nullptr, nullptr, nullptr, nullptr, &rep).ok());
    const int32_t n = d.mesh.numVertices();
    ASSERT_GT(n, n0 + 50);
    if (beta >= 0.6)
    {
      EXPECT_GT(rep.rejectedSpacing, 0);
    }
    EXPECT_EQ(spacingViolations(d.mesh, n0, d.sizing, beta), 0) << "beta " << beta;
    EXPECT_EQ(hullFaces(d.mesh), faces0);
    const MeshCheckReport check = checkMesh(d.mesh); // still Delaunay: insertion is Bowyer-Watson
    EXPECT_TRUE(check.valid) << check.summary();
  }
}

TEST(FieldPoints, MeanEdgeLengthFollowsTheSizingField)
{
  // A cube of side 1 with boundary edges ~0.1; a user field asks for 0.05 in the half x < 0.
  for (int variant = 0; variant < 2; ++variant)
  {
    Domain d;
    SizingOptions so;
    makeDomain(d, EnclosureShape::Box, 0.1, so);
    if (variant == 1)
    {
      d.sizing.setUserFunction([](const double* p) { return p[0] < 0 ? 0.05 : 1e9; });
      ASSERT_TRUE(d.sizing
                    .build(d.surface.points.data(), d.surface.numberOfPoints(), d.surface.triangles.data(),
                           d.surface.numberOfTriangles(), so)
                    .ok());
    }
    ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, FieldPointOptions()).ok());
    const double left[3] = { -0.25, 0, 0 }, right[3] = { 0.25, 0, 0 };
    const double hl = d.sizing.evaluate(left), hr = d.sizing.evaluate(right);
    const double ml = meanEdgeNear(d.mesh, left, 0.2), mr = meanEdgeNear(d.mesh, right, 0.2);
    // Stated factor: the mean edge length in a region is within [0.8, 1.6] x the target size.
    EXPECT_GT(ml, 0.8 * hl) << variant;
    EXPECT_LT(ml, 1.6 * hl) << variant;
    EXPECT_GT(mr, 0.8 * hr) << variant;
    EXPECT_LT(mr, 1.6 * hr) << variant;
    if (variant == 1)
    {
      EXPECT_LT(ml, 0.75 * mr);
    }
  }
}

TEST(FieldPoints, ClusterPointsAppearAndDensifyTheirNeighbourhood)
{
  const double c[3] = { 0.1, -0.05, 0.0 };
  std::vector<double> cluster;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
      {
        const double p[3] = { c[0] + 0.03 * (i - 2), c[1] + 0.03 * (j - 2), c[2] + 0.03 * (k - 2) };
        cluster.insert(cluster.end(), p, p + 3);
      }
  const size_t nc = cluster.size() / 3;
  double meanPlain = 0, meanCluster = 0;
  for (int variant = 0; variant < 2; ++variant)
  {
    Domain d;
    EnclosureOptions o;
    makeDomain(d, EnclosureShape::Sphere, 0.2);
    const auto faces0 = hullFaces(d.mesh);
    if (variant == 1)
    {
      const std::vector<double> sizes(nc, 0.03);
      d.sizing.addSizedPoints(cluster.data(), sizes.data(), nc);
      ASSERT_TRUE(d.sizing
                    .build(d.surface.points.data(), d.surface.numberOfPoints(), d.surface.triangles.data(),
                           d.surface.numberOfTriangles(), SizingOptions())
                    .ok());
      std::vector<int32_t> ids;
      FieldPointReport rep;
      ASSERT_TRUE(insertClusterPoints(d.mesh, cluster.data(), nc, 0.0, nullptr, nullptr, &ids, nullptr, &rep).ok());
      EXPECT_EQ(rep.clusterInserted, static_cast<int64_t>(nc));
      for (size_t i = 0; i < nc; ++i)
      {
        ASSERT_GE(ids[i], 0);
        EXPECT_EQ(dist(d.mesh.point(ids[i]), &cluster[3 * i]), 0.0);
      }
      // Outside points and duplicates are skipped, not inserted.
      const double outside[6] = { 5, 5, 5, cluster[0], cluster[1], cluster[2] };
      FieldPointReport rep2;
      ASSERT_TRUE(insertClusterPoints(d.mesh, outside, 2, 0.0, nullptr, nullptr, &ids, nullptr, &rep2).ok());
      EXPECT_EQ(rep2.clusterOutside, 1);
      EXPECT_EQ(rep2.clusterRejected, 1);
      EXPECT_EQ(ids[0], -1);
      EXPECT_EQ(ids[1], -1);
    }
    ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, FieldPointOptions()).ok());
    const MeshCheckReport check = checkMesh(d.mesh);
    EXPECT_TRUE(check.valid) << check.summary();
    EXPECT_EQ(hullFaces(d.mesh), faces0);
    (variant ? meanCluster : meanPlain) = meanEdgeNear(d.mesh, c, 0.2);
  }
  EXPECT_GT(meanPlain, 0);
  EXPECT_GT(meanCluster, 0);
  EXPECT_LT(meanCluster, 0.6 * meanPlain);
}

TEST(FieldPoints, ConstrainedFacesStopTheCavity)
{
  // Freeze a band of interior faces: insertion must keep every one of them.
  Domain d;
  makeDomain(d, EnclosureShape::Box, 0.2);
  FaceConstraints fc;
  std::vector<std::array<int32_t, 3>> frozen;
  d.mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = d.mesh.neighbor(t, i);
        if (u > t && (t % 7) == 0)
        {
          int32_t f[3];
          d.mesh.faceVertices(t, i, f);
          fc.add(f[0], f[1], f[2]);
          frozen.push_back({ f[0], f[1], f[2] });
        }
      }
    });
  ASSERT_GT(frozen.size(), 20u);
  std::vector<int32_t> labels(static_cast<size_t>(d.mesh.tetCapacity()), 3);
  FieldPointReport rep;
  ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, FieldPointOptions(), &fc, &labels, nullptr, nullptr, &rep).ok());
  EXPECT_GT(rep.inserted, 50);
  std::set<std::array<int32_t, 3>> faces;
  d.mesh.forEachTet(
    [&](int32_t t)
    {
      EXPECT_EQ(labels[t], 3);
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        d.mesh.faceVertices(t, i, f);
        std::sort(f, f + 3);
        faces.insert({ f[0], f[1], f[2] });
      }
    });
  for (auto f : frozen)
  {
    std::sort(f.begin(), f.end());
    EXPECT_TRUE(faces.count(f)) << f[0] << " " << f[1] << " " << f[2];
  }
  MeshCheckOptions co;
  co.delaunay = false; // constrained: not Delaunay across the frozen faces
  const MeshCheckReport check = checkMesh(d.mesh, co);
  EXPECT_TRUE(check.valid) << check.summary();
}

TEST(FieldPoints, MaxVolumeAndOptionErrors)
{
  Domain a, b;
  makeDomain(a, EnclosureShape::Box, 0.25);
  makeDomain(b, EnclosureShape::Box, 0.25);
  ASSERT_TRUE(insertFieldPoints(a.mesh, a.sizing, FieldPointOptions()).ok());
  FieldPointOptions fo;
  fo.maxVolume = 1e-4;
  ASSERT_TRUE(insertFieldPoints(b.mesh, b.sizing, fo).ok());
  EXPECT_GT(b.mesh.numTets(), 2 * a.mesh.numTets());
  fo.alpha = 0;
  EXPECT_EQ(insertFieldPoints(b.mesh, b.sizing, fo).kind, ErrorKind::InvalidOption);
  TetMesh ghosts;
  std::vector<int32_t> map;
  ASSERT_TRUE(buildDelaunay(a.surface.points.data(), a.surface.numberOfPoints(), DelaunayOptions(), ghosts, map).ok());
  EXPECT_EQ(insertFieldPoints(ghosts, a.sizing, FieldPointOptions()).kind, ErrorKind::InvalidOption);
}

TEST(FieldPoints, AdaptivityRefinesWhereTheTargetIsSmaller)
{
  // Paper section 4: an existing mesh plus a target size per vertex (e.g. from a solver's error estimate)
  // -> the vertices and the array become the sizing field's background cloud; field points refine the
  // mesh where the target is smaller than the current spacing, and nowhere else; the boundary is kept.
  Domain d;
  makeDomain(d, EnclosureShape::Box, 0.12);
  ASSERT_TRUE(insertFieldPoints(d.mesh, d.sizing, FieldPointOptions()).ok());
  const auto faces0 = hullFaces(d.mesh);
  auto inBox = [](const double* p) { return p[0] > 0 && p[1] > 0 && p[2] > 0; }; // one octant
  std::vector<double> target(static_cast<size_t>(d.mesh.numVertices()));
  for (int32_t v = 0; v < d.mesh.numVertices(); ++v)
    target[v] = d.sizing.evaluate(d.mesh.point(v)) * (inBox(d.mesh.point(v)) ? 0.5 : 1.0);
  auto countIn = [&](bool inside)
  {
    int64_t n = 0;
    for (int32_t v = 0; v < d.mesh.numVertices(); ++v)
    {
      const double* p = d.mesh.point(v);
      const bool deep = inside ? (p[0] > 0.1 && p[1] > 0.1 && p[2] > 0.1) : (p[0] < -0.1 && p[1] < -0.1);
      n += deep;
    }
    return n;
  };
  const int64_t inBefore = countIn(true), outBefore = countIn(false);
  SizingField adapt;
  adapt.setBackgroundCloud(d.mesh.points.data(), target.data(), target.size());
  SizingOptions so;
  ASSERT_TRUE(adapt.buildUniform(1e30, so).ok());
  FieldPointReport rep;
  ASSERT_TRUE(insertFieldPoints(d.mesh, adapt, FieldPointOptions(), nullptr, nullptr, nullptr, nullptr, &rep).ok());
  const int64_t inAfter = countIn(true), outAfter = countIn(false);
  EXPECT_GT(inAfter, 4 * inBefore); // half the size: about eight times the points
  EXPECT_LT(outAfter, outBefore + outBefore / 10 + 5);
  EXPECT_EQ(hullFaces(d.mesh), faces0);
  const MeshCheckReport check = checkMesh(d.mesh);
  EXPECT_TRUE(check.valid) << check.summary();
}

// Whether a field may be evaluated from several threads: only a uniform one whose user function is
// declared thread-safe (the octree lookup the mesher uses), never one that walks an interpolant.
TEST(FieldPoints, OnlyAThreadSafeFieldIsEvaluatedConcurrently)
{
  Domain d;
  makeDomain(d, EnclosureShape::Box, 0.1);
  EXPECT_FALSE(d.sizing.evaluatesConcurrently()); // graded boundary nodes
  SizingField uniform;
  uniform.setUserFunction([](const double* p) { return 0.05 + 0.01 * p[0]; });
  ASSERT_TRUE(uniform.buildUniform(1e300, SizingOptions()).ok());
  EXPECT_FALSE(uniform.evaluatesConcurrently()); // a function not declared thread-safe
  uniform.setUserFunction([](const double* p) { return 0.05 + 0.01 * p[0]; }, /*threadSafe=*/true);
  EXPECT_TRUE(uniform.evaluatesConcurrently());
}

// Field points with `o` on copies of a box's boundary mesh, on 1, 2 and 8 threads, with a size that grows
// along x: every mesh is a valid Delaunay mesh (insertion is Bowyer-Watson; a region inserts a point whole
// or defers it) with the box's boundary, and the same bit for bit as on one thread. onOneThread sees the
// first run's mesh, report and number of vertices before the field points.
void expectTheSameMeshOnAnyThreadCount(
  FieldPointOptions o, const std::function<void(const TetMesh&, const FieldPointReport&, int32_t)>& onOneThread)
{
  Domain base;
  makeDomain(base, EnclosureShape::Box, 0.1);
  SizingField sizing;
  sizing.setUserFunction([](const double* p) { return 0.032 + 0.02 * (p[0] + 0.5); }, /*threadSafe=*/true);
  ASSERT_TRUE(sizing.buildUniform(1e300, SizingOptions()).ok());
  const auto boundary = hullFaces(base.mesh);
  TetMesh reference;
  for (const int threads : { 1, 2, 8 })
  {
    TetMesh mesh = base.mesh;
    o.threads = threads;
    FieldPointReport report;
    ASSERT_TRUE(insertFieldPoints(mesh, sizing, o, nullptr, nullptr, nullptr, nullptr, &report).ok());
    const MeshCheckReport check = checkMesh(mesh);
    EXPECT_TRUE(check.valid) << threads << ": " << check.summary();
    EXPECT_EQ(hullFaces(mesh), boundary) << threads;
    if (threads == 1)
    {
      onOneThread(mesh, report, base.mesh.numVertices());
      reference = mesh;
      continue;
    }
    EXPECT_EQ(mesh.points, reference.points) << threads;
    EXPECT_EQ(mesh.tetVertices, reference.tetVertices) << threads;
    EXPECT_EQ(mesh.tetNeighbors, reference.tetNeighbors) << threads;
    EXPECT_EQ(mesh.tetFlags, reference.tetFlags) << threads;
  }
}

// The tets of a pass are tested on several threads, and from largeMeshTets (lowered here, so that this
// small mesh reaches it) the passes take their tets in the order the insertions created them.
TEST(FieldPoints, SameMeshOnAnyThreadCount)
{
  FieldPointOptions o;
  o.largeMeshTets = 20000;
  expectTheSameMeshOnAnyThreadCount(o,
                                    [](const TetMesh&, const FieldPointReport& report, int32_t)
                                    {
                                      // A pass that creates more than largeMeshTets tets (at least 20 a
                                      // point), so that the next one takes them in creation order and
                                      // splits them across threads (from 2 x 8192 tets).
                                      const int64_t most =
                                        *std::max_element(report.insertedPerPass.begin(), report.insertedPerPass.end());
                                      EXPECT_GT(most * 20, 20000);
                                      EXPECT_EQ(report.insertedInRegions, 0);
                                    });
}

// A large pass is inserted by regions of space on the threads (FieldPointRegions.h; regionTets lowered here
// so that this small mesh is cut into up to 16 regions): the same mesh on any thread count; eq. 5's spacing
// holds across region borders; most points were inserted by the regions, the rest by one thread after them.
TEST(FieldPoints, RegionsGiveTheSameMeshOnAnyThreadCount)
{
  FieldPointOptions o;
  o.beta = 0.6;
  o.largeMeshTets = 20000;
  o.regionTets = 1024;
  SizingField sizing;
  sizing.setUserFunction([](const double* p) { return 0.032 + 0.02 * (p[0] + 0.5); }, /*threadSafe=*/true);
  ASSERT_TRUE(sizing.buildUniform(1e300, SizingOptions()).ok());
  expectTheSameMeshOnAnyThreadCount(o,
                                    [&](const TetMesh& mesh, const FieldPointReport& report, int32_t n0)
                                    {
                                      EXPECT_GT(report.insertedInRegions, report.inserted / 2);
                                      EXPECT_GT(report.deferredToOneThread, 0);
                                      EXPECT_EQ(spacingViolations(mesh, n0, sizing, o.beta), 0);
                                    });
}

// Cancelled while the regions run: Cancelled, and the mesh left behind is still valid (the regions' points
// renumbered, their spare slots on the free list).
TEST(FieldPoints, CancelledRegionsLeaveAValidMesh)
{
  Domain d;
  makeDomain(d, EnclosureShape::Box, 0.1);
  SizingField sizing;
  sizing.setUserFunction([](const double*) { return 0.03; }, /*threadSafe=*/true);
  ASSERT_TRUE(sizing.buildUniform(1e300, SizingOptions()).ok());
  struct CancelLater final : Progress
  {
    int calls = 0;
    void report(double, const char*) override {}
    bool cancelled() override { return ++calls > 12; }
  } progress;
  FieldPointOptions o;
  o.threads = 2;
  o.regionTets = 1024;
  FieldPointReport report;
  const Status s = insertFieldPoints(d.mesh, sizing, o, nullptr, nullptr, nullptr, &progress, &report);
  EXPECT_EQ(s.kind, ErrorKind::Cancelled);
  EXPECT_GT(report.insertedInRegions, 0);
  const MeshCheckReport check = checkMesh(d.mesh);
  EXPECT_TRUE(check.valid) << check.summary();
  int32_t freeSlots = 0; // every slot marked free is counted free (the regions gave back all they kept)
  for (int32_t t = 0; t < d.mesh.tetCapacity(); ++t)
    freeSlots += d.mesh.isFree(t);
  EXPECT_EQ(freeSlots, d.mesh.numFreeTets());
}
