// Smoothing (paper 7.6) and topological optimisation: every tet stays positive (checker), the boundary
// faces and vertices do not change, and the minimum dihedral angle improves.
#include "Delaunay.h"
#include "Enclosures.h"
#include "FieldPoints.h"
#include "MeshChecker.h"
#include "MeshImprovement.h"
#include "MeshOptimization.h"
#include "MeshSmoothing.h"
#include "MeshTestFaces.h"
#include "Predicates.h"
#include "Quality.h"
#include "SizingField.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

using namespace volgrid;
using testmesh::hullFaces;

namespace
{
void fieldMesh(EnclosureShape shape, double edge, TetMesh& mesh)
{
  SurfaceMesh s;
  EnclosureOptions o;
  o.shape = shape;
  o.targetEdgeLength = edge;
  ASSERT_TRUE(makeEnclosure(o, s).ok());
  std::vector<int32_t> map;
  DelaunayOptions opt;
  opt.keepGhosts = false;
  ASSERT_TRUE(buildDelaunay(s.points.data(), s.numberOfPoints(), opt, mesh, map).ok());
  SizingField f;
  ASSERT_TRUE(
    f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), SizingOptions()).ok());
  ASSERT_TRUE(insertFieldPoints(mesh, f, FieldPointOptions()).ok());
}

std::vector<double> boundaryCoordinates(const TetMesh& m, const std::set<std::array<int32_t, 3>>& faces)
{
  std::vector<double> xyz;
  for (const auto& f : faces)
    for (int32_t v : f)
      xyz.insert(xyz.end(), m.point(v), m.point(v) + 3);
  return xyz;
}

MeshCheckOptions noDelaunay()
{
  MeshCheckOptions o;
  o.delaunay = false;
  return o;
}

// optimizeMesh, then the checks every optimisation must pass: a valid mesh with its boundary faces and
// their coordinates unchanged.
OptimizationReport optimiseAndCheck(TetMesh& mesh, const OptimizationOptions& oo)
{
  const auto faces0 = hullFaces(mesh);
  const auto xyz0 = boundaryCoordinates(mesh, faces0);
  OptimizationReport rep;
  EXPECT_TRUE(optimizeMesh(mesh, nullptr, nullptr, nullptr, oo, nullptr, &rep).ok());
  const MeshCheckReport check = checkMesh(mesh, noDelaunay());
  EXPECT_TRUE(check.valid) << check.summary();
  EXPECT_EQ(hullFaces(mesh), faces0);
  EXPECT_EQ(boundaryCoordinates(mesh, faces0), xyz0);
  return rep;
}
// The meshes are the same: points, tets and adjacency, slot by slot.
void expectTheSameMeshes(const std::vector<TetMesh>& results)
{
  for (size_t k = 1; k < results.size(); ++k)
  {
    EXPECT_EQ(results[k].points, results[0].points) << k;
    EXPECT_EQ(results[k].tetVertices, results[0].tetVertices) << k;
    EXPECT_EQ(results[k].tetNeighbors, results[0].tetNeighbors) << k;
  }
}
} // namespace

TEST(MeshOptimization, ImprovesMinDihedralAndKeepsBoundary)
{
  for (EnclosureShape shape : { EnclosureShape::Box, EnclosureShape::Sphere })
  {
    TetMesh mesh;
    fieldMesh(shape, 0.15, mesh);
    const int32_t nv = mesh.numVertices();
    const OptimizationReport rep = optimiseAndCheck(mesh, OptimizationOptions());
    EXPECT_EQ(mesh.numVertices(), nv);
    EXPECT_LT(rep.before.minDihedral, 10.0); // the raw mesh has slivers
    EXPECT_GT(rep.after.minDihedral, rep.before.minDihedral);
    EXPECT_GE(rep.after.minDihedral, 15.0);
    EXPECT_LE(rep.after.maxDihedral, 165.0);
    EXPECT_EQ(rep.after.inverted, 0);
    EXPECT_EQ(rep.after.below10, 0);
    EXPECT_GT(rep.edgeRemovals + rep.flips23, 0);
  }
}

TEST(MeshOptimization, SmoothingOnlyMovesInteriorVerticesAndNeverWorsens)
{
  TetMesh mesh;
  fieldMesh(EnclosureShape::Sphere, 0.2, mesh);
  const auto faces0 = hullFaces(mesh);
  const auto xyz0 = boundaryCoordinates(mesh, faces0);
  // Lock one interior vertex explicitly too.
  std::vector<uint8_t> locked(static_cast<size_t>(mesh.numVertices()), 0);
  const int32_t pinned = mesh.numVertices() - 1;
  locked[pinned] = 1;
  const std::vector<double> pinnedXYZ(mesh.point(pinned), mesh.point(pinned) + 3);
  // Star minimum of every vertex before.
  TetEditor editor(mesh);
  auto starMin = [&](int32_t v)
  {
    std::vector<int32_t> star;
    editor.star(v, star);
    double q = 2;
    for (int32_t t : star)
    {
      const int32_t* w = mesh.vertices(t);
      q = std::min(q, tetSineQuality(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3])));
    }
    return q;
  };
  double globalBefore = 2;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    globalBefore = std::min(globalBefore, starMin(v));
  SmoothingOptions so;
  SmoothingReport rep;
  ASSERT_TRUE(smoothMesh(mesh, nullptr, &locked, so, nullptr, &rep).ok());
  EXPECT_GT(rep.laplacianMoves, 0);
  EXPECT_GT(rep.optimizedMoves, 0);
  const MeshCheckReport check = checkMesh(mesh, noDelaunay());
  EXPECT_TRUE(check.valid) << check.summary();
  EXPECT_EQ(hullFaces(mesh), faces0);
  EXPECT_EQ(boundaryCoordinates(mesh, faces0), xyz0);
  EXPECT_EQ(std::vector<double>(mesh.point(pinned), mesh.point(pinned) + 3), pinnedXYZ);
  double globalAfter = 2;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    globalAfter = std::min(globalAfter, starMin(v));
  EXPECT_GE(globalAfter, globalBefore);
}

TEST(MeshOptimization, ConstrainedInteriorFacesSurviveAndTheirVerticesStay)
{
  TetMesh mesh;
  fieldMesh(EnclosureShape::Box, 0.2, mesh);
  FaceConstraints fc;
  std::vector<std::array<int32_t, 3>> frozen;
  mesh.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        if (mesh.neighbor(t, i) > t && t % 11 == 0)
        {
          int32_t f[3];
          mesh.faceVertices(t, i, f);
          fc.add(f[0], f[1], f[2]);
          std::sort(f, f + 3);
          frozen.push_back({ f[0], f[1], f[2] });
        }
    });
  std::vector<double> xyz0;
  for (const auto& f : frozen)
    for (int32_t v : f)
      xyz0.insert(xyz0.end(), mesh.point(v), mesh.point(v) + 3);
  std::vector<int32_t> labels(static_cast<size_t>(mesh.tetCapacity()), 7);
  OptimizationReport rep;
  ASSERT_TRUE(optimizeMesh(mesh, &fc, nullptr, &labels, OptimizationOptions(), nullptr, &rep).ok());
  EXPECT_GT(rep.after.minDihedral, rep.before.minDihedral);
  std::set<std::array<int32_t, 3>> faces;
  mesh.forEachTet(
    [&](int32_t t)
    {
      EXPECT_EQ(labels[t], 7);
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        mesh.faceVertices(t, i, f);
        std::sort(f, f + 3);
        faces.insert({ f[0], f[1], f[2] });
      }
    });
  for (const auto& f : frozen)
    EXPECT_TRUE(faces.count(f));
  std::vector<double> xyz1;
  for (const auto& f : frozen)
    for (int32_t v : f)
      xyz1.insert(xyz1.end(), mesh.point(v), mesh.point(v) + 3);
  EXPECT_EQ(xyz1, xyz0);
  const MeshCheckReport check = checkMesh(mesh, noDelaunay());
  EXPECT_TRUE(check.valid) << check.summary();
}

TEST(MeshOptimization, ThreeTwoAndTwoThreeFlips)
{
  // Three tets around the edge xy of a flat triangle ring: the 3-2 flip replaces them by two.
  TetMesh m;
  const double pts[5][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { -0.5, 0.866, 0 }, { -0.5, -0.866, 0 } };
  for (const auto& p : pts)
    m.addPoint(p);
  // x = 0 (top), y = 1 (bottom), ring 2,3,4; orient(x,y,r_i,r_i+1) > 0 needs the ring clockwise from x.
  const int32_t x = 0, y = 1;
  std::vector<std::array<int32_t, 4>> tets;
  const int32_t ring[3] = { 2, 4, 3 };
  for (int i = 0; i < 3; ++i)
    tets.push_back({ x, y, ring[i], ring[(i + 1) % 3] });
  for (const auto& q : tets)
    ASSERT_GT(predicates::orient3d(m.point(q[0]), m.point(q[1]), m.point(q[2]), m.point(q[3])), 0);
  std::vector<int32_t> ids;
  for (const auto& q : tets)
    ids.push_back(m.newTet(q[0], q[1], q[2], q[3]));
  // Link the faces around the edge: tet i's face opposite ring[i] is shared with tet i+1's face opposite ring[i+2].
  for (int i = 0; i < 3; ++i)
  {
    const int32_t a = ids[i], b = ids[(i + 1) % 3];
    m.link(a, 2, b, 3);
  }
  ASSERT_TRUE(checkMesh(m, noDelaunay()).valid) << checkMesh(m, noDelaunay()).summary();
  TetEditor editor(m);
  std::vector<int32_t> created;
  ASSERT_TRUE(tryEdgeRemoval(editor, ids[0], x, y, 9, &created));
  EXPECT_EQ(created.size(), 2u);
  EXPECT_EQ(m.numTets(), 2);
  EXPECT_TRUE(checkMesh(m, noDelaunay()).valid) << checkMesh(m, noDelaunay()).summary();
  // The two tets are better than the three: the reverse 2-3 flip does not improve, so it is refused.
  const int32_t t = created[0];
  int shared = -1;
  for (int i = 0; i < 4; ++i)
    if (m.neighbor(t, i) >= 0)
      shared = i;
  ASSERT_GE(shared, 0);
  EXPECT_FALSE(tryFlip23(editor, t, shared, nullptr));
  EXPECT_EQ(m.numTets(), 2);
}

TEST(MeshOptimization, SummaryAgreesWithTheQualityModule)
{
  // summarizeDihedrals() ranks the six angles by cosine and converts two: it must report the extremes
  // quality::tetDihedralAngles() gives, including for flat tets (caps, slivers, needles).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20000; ++k)
  {
    std::vector<double> p(12);
    for (double& x : p)
      x = u(rng);
    if (k % 2) // a flattened copy: the fourth point close to the plane of the others
      for (int i = 0; i < 3; ++i)
        p[9 + i] = (p[i] + p[3 + i] + p[6 + i]) / 3 + 1e-3 * u(rng);
    TetMesh m;
    if (!tetMeshFromTets(p, { 0, 1, 2, 3 }, m).ok())
      continue;
    const int32_t* v = m.vertices(0);
    double ang[6];
    quality::tetDihedralAngles(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), ang);
    const DihedralSummary s = summarizeDihedrals(m);
    EXPECT_NEAR(s.minDihedral, *std::min_element(ang, ang + 6), 1e-9);
    EXPECT_NEAR(s.maxDihedral, *std::max_element(ang, ang + 6), 1e-9);
  }
}

TEST(MeshOptimization, VertexCollapseRemovesAnInteriorPointSqueezedAgainstAFace)
{
  // A regular tet and an interior point 1e-6 above the centroid of one of its faces: the four tets of
  // the point's star include a flat one no flip can replace (every face but the hull is through the
  // point). Collapsing the point onto a corner leaves the regular tet.
  const double corners[4][3] = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  std::vector<double> pts;
  for (const auto& c : corners)
    pts.insert(pts.end(), c, c + 3);
  // Face (1, 2, 3) has its centroid at -corner 0 / 3; inwards is towards corner 0.
  for (int k = 0; k < 3; ++k)
    pts.push_back(-corners[0][k] / 3 + 1e-6 * corners[0][k]);
  TetMesh m;
  std::vector<int32_t> map;
  DelaunayOptions opt;
  opt.keepGhosts = false;
  ASSERT_TRUE(buildDelaunay(pts.data(), 5, opt, m, map).ok());
  ASSERT_EQ(m.numTets(), 4);
  int32_t p = -1;
  for (int32_t v = 0; v < 5; ++v)
    if (map[v] >= 0 && m.point(map[v])[0] == pts[12])
      p = map[v];
  ASSERT_GE(p, 0);
  const auto hull = hullFaces(m);
  EXPECT_LT(summarizeDihedrals(m).minDihedral, 0.01);

  // A constrained face through the point forbids the collapse.
  FaceConstraints fc;
  m.forEachTet(
    [&](int32_t t)
    {
      if (fc.empty() && m.localIndex(t, p) >= 0)
      {
        const int32_t* v = m.vertices(t);
        const int ip = m.localIndex(t, p);
        const int32_t f[3] = { v[(ip + 1) % 4], v[(ip + 2) % 4], p };
        fc.add(f[0], f[1], f[2]);
      }
    });
  {
    TetEditor constrained(m, &fc);
    constrained.rebuildVertexMap();
    EXPECT_FALSE(tryVertexCollapse(constrained, p, nullptr));
    EXPECT_EQ(m.numTets(), 4);
  }

  TetEditor editor(m);
  editor.rebuildVertexMap();
  std::vector<int32_t> created;
  ASSERT_TRUE(tryVertexCollapse(editor, p, &created));
  EXPECT_EQ(created.size(), 1u);
  EXPECT_EQ(m.numTets(), 1);
  EXPECT_EQ(editor.tetOf(p), -1);
  EXPECT_TRUE(checkMesh(m, noDelaunay()).valid) << checkMesh(m, noDelaunay()).summary();
  EXPECT_EQ(hullFaces(m), hull);
  EXPECT_NEAR(summarizeDihedrals(m).minDihedral, 70.5288, 1e-3); // the regular tet
  EXPECT_FALSE(tryVertexCollapse(editor, p, nullptr));           // in no tet any more
}

// Large meshes flip their many bad tets by regions of space on all threads first (RegionFlips.h; forced
// here on a small mesh with regions of 64 bad tets): the result is the same mesh at 1, 2 and 8 threads,
// valid with the boundary untouched, the regions made many of the flips, and the mesh is as good as the
// slot-order sweep's on one thread without regions.
TEST(MeshOptimization, FlipsByRegionsGiveTheSameMeshOnAnyThreadCount)
{
  TetMesh start;
  fieldMesh(EnclosureShape::Sphere, 0.12, start);
  OptimizationOptions oo;
  oo.targetDegrees = 35; // many tets below: thousands of flips
  oo.largeMeshTets = 0;
  oo.regionTets = int64_t{ 1 } << 40; // no regions: the slot-order sweep
  TetMesh bySlot = start;
  const OptimizationReport slotReport = optimiseAndCheck(bySlot, oo);
  EXPECT_EQ(slotReport.flipsInRegions, 0);
  oo.regionTets = 64;
  std::vector<TetMesh> results;
  for (int threads : { 1, 2, 8 })
  {
    oo.threads = threads;
    TetMesh mesh = start;
    const OptimizationReport rep = optimiseAndCheck(mesh, oo);
    const int64_t flips = rep.flips23 + rep.edgeRemovals;
    std::printf("threads %d: %lld flips, %lld by regions; min %.2f (slot order %.2f), %lld under the target (%lld)\n",
                threads, static_cast<long long>(flips), static_cast<long long>(rep.flipsInRegions),
                rep.after.minDihedral, slotReport.after.minDihedral, static_cast<long long>(rep.belowTargetAfter),
                static_cast<long long>(slotReport.belowTargetAfter));
    EXPECT_GT(rep.flipsInRegions, flips / 3); // the later passes have too few bad tets for regions
    EXPECT_GE(rep.after.minDihedral, slotReport.after.minDihedral - 3.0);
    EXPECT_LE(rep.belowTargetAfter, slotReport.belowTargetAfter * 5 / 4 + 10);
    results.push_back(std::move(mesh));
  }
  expectTheSameMeshes(results);
  EXPECT_NE(results[0].tetVertices, bySlot.tetVertices); // the regions flipped in another order
}

// Large meshes smooth in colour classes on all threads (largeMeshTets, forced here on a small
// mesh): the result is the same mesh at 1, 2 and 8 threads, valid, with the boundary untouched, and as
// good as the one-by-one order's.
TEST(MeshOptimization, SmoothingInColourClassesGivesTheSameMeshOnAnyThreadCount)
{
  TetMesh start;
  fieldMesh(EnclosureShape::Sphere, 0.12, start);
  OptimizationOptions oo;
  oo.targetDegrees = 35; // many tets below: neighbouring vertices move in the same pass
  OptimizationReport sequentialReport;
  TetMesh sequential = start;
  ASSERT_TRUE(optimizeMesh(sequential, nullptr, nullptr, nullptr, oo, nullptr, &sequentialReport).ok());
  oo.largeMeshTets = 0;
  std::vector<TetMesh> results;
  for (int threads : { 1, 2, 8 })
  {
    oo.threads = threads;
    TetMesh mesh = start;
    const OptimizationReport rep = optimiseAndCheck(mesh, oo);
    EXPECT_GT(rep.smoothMoves, 0);
    EXPECT_GE(rep.after.minDihedral, 15.0);
    EXPECT_GE(rep.after.minDihedral, sequentialReport.after.minDihedral - 3.0);
    EXPECT_LE(rep.belowTargetAfter, sequentialReport.belowTargetAfter * 5 / 4 + 10);
    results.push_back(std::move(mesh));
  }
  expectTheSameMeshes(results);
  // The colour classes do move differently from the one-by-one order (else this test shows nothing).
  EXPECT_NE(results[0].points, sequential.points);
}
