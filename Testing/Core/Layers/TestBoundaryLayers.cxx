// Boundary layers (Core/Layers/BoundaryLayers.h): exact prism checks, option errors, marching, thinning.
#include "BoundaryLayers.h"

#include "LayerTestShapes.h"
#include "MesherTestShapes.h"
#include "Predicates.h"
#include "SurfaceChecks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace volgrid;

namespace
{
const double* at(const LayerResult& r, int32_t id)
{
  return r.points.data() + 3 * size_t(id);
}

bool prismOk(const LayerResult& r, size_t p)
{
  const int32_t* v = r.prisms.data() + 6 * p;
  return prismIsValid(at(r, v[0]), at(r, v[1]), at(r, v[2]), at(r, v[3]), at(r, v[4]), at(r, v[5]));
}

double distance(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

LayerOptions options(int layers, double first, double growth)
{
  LayerOptions o;
  o.layers = layers;
  o.firstHeight = first;
  o.growth = growth;
  return o;
}
} // namespace

TEST(BoundaryLayers, PrismValidityIsExact)
{
  const double p[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1e-9 }, { 1, 0, 1e-9 }, { 0, 1, 1e-9 } };
  EXPECT_TRUE(prismIsValid(p[0], p[1], p[2], p[3], p[4], p[5]));
  // Top below the base: inverted.
  EXPECT_FALSE(prismIsValid(p[3], p[4], p[5], p[0], p[1], p[2]));
  // Flat: a zero-volume decomposition is not accepted.
  EXPECT_FALSE(prismIsValid(p[0], p[1], p[2], p[0], p[1], p[2]));
  // Twisted top (Schoenhardt-like): some decomposition has a negative tet although the base tets are positive.
  const double twisted[3][3] = { { 0.9, 0.1, 0.05 }, { 0.1, 0.9, 0.05 }, { -0.2, -0.2, 0.05 } };
  EXPECT_FALSE(prismIsValid(p[0], p[1], p[2], twisted[0], twisted[1], twisted[2]));
}

TEST(BoundaryLayers, CollapsedCornersMakePyramidsAndTetsCheckedExactly)
{
  // Points 0..2: the base; 3..5 above them; 6: below the base plane.
  const double pts[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.1, 1, 0, 0.1, 0, 1, 0.1, 1, 0, -0.1 };
  const int32_t prism[6] = { 0, 1, 2, 3, 4, 5 };
  EXPECT_TRUE(layerCellIsValid(prism, pts));
  const int32_t pyramid[6] = { 0, 1, 2, 0, 4, 5 }; // corner 0 collapsed
  EXPECT_TRUE(layerCellIsValid(pyramid, pts));
  const int32_t fallenPyramid[6] = { 0, 1, 2, 0, 6, 5 }; // corner 1's top below the base
  EXPECT_FALSE(layerCellIsValid(fallenPyramid, pts));
  const int32_t tet[6] = { 0, 1, 2, 0, 1, 5 };
  EXPECT_TRUE(layerCellIsValid(tet, pts));
  const int32_t fallenTet[6] = { 0, 1, 2, 0, 6, 2 }; // a tet standing below the base
  EXPECT_FALSE(layerCellIsValid(fallenTet, pts));
  const int32_t none[6] = { 0, 1, 2, 0, 1, 2 };
  EXPECT_TRUE(layerCellIsValid(none, pts));
  // The pyramid's quad (1, 2, 5, 4), cut through its smallest id, as the prism beside it cuts it.
  int32_t p[5] = { 1, 2, 5, 4, 0 };
  if (predicates::orient3d(pts + 3, pts + 6, pts + 15, pts) < 0)
    std::swap(p[1], p[3]);
  int32_t split[8], prismSplit[12];
  splitPyramid(p, split);
  splitPrism(prism, pts, prismSplit);
  for (int t = 0; t < 8; t += 4)
    EXPECT_GT(
      predicates::orient3d(pts + 3 * split[t], pts + 3 * split[t + 1], pts + 3 * split[t + 2], pts + 3 * split[t + 3]),
      0);
  const auto hasEdge = [](const int32_t* tets, int n, int32_t a, int32_t b)
  {
    for (int t = 0; t < n; ++t)
    {
      const std::set<int32_t> v(tets + 4 * t, tets + 4 * t + 4);
      if (v.count(a) && v.count(b))
        return true;
    }
    return false;
  };
  EXPECT_TRUE(hasEdge(split, 2, 1, 5));
  EXPECT_FALSE(hasEdge(split, 2, 2, 4));
  EXPECT_EQ(hasEdge(prismSplit, 3, 1, 5), true);
  EXPECT_EQ(hasEdge(prismSplit, 3, 2, 4), false);
}

TEST(BoundaryLayers, SplitAgreesAcrossSharedQuads)
{
  // Two prisms sharing the quad (1,2,4,5) -> ids (1,2,5,6) in both; split each, the shared quad must be
  // cut by the same diagonal, and every tet must be positive.
  const double pts[] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1 };
  const int32_t a[6] = { 0, 1, 2, 4, 5, 6 }, b[6] = { 1, 3, 2, 5, 7, 6 };
  int32_t ta[12], tb[12];
  splitPrism(a, pts, ta);
  splitPrism(b, pts, tb);
  double volume = 0;
  std::set<std::pair<int, int>> diagonals[2];
  for (int which = 0; which < 2; ++which)
    for (int t = 0; t < 3; ++t)
    {
      const int32_t* v = (which ? tb : ta) + 4 * t;
      ASSERT_GT(predicates::orient3d(pts + 3 * v[0], pts + 3 * v[1], pts + 3 * v[2], pts + 3 * v[3]), 0);
      const double* q[4] = { pts + 3 * v[0], pts + 3 * v[1], pts + 3 * v[2], pts + 3 * v[3] };
      double u[3], w[3], z[3];
      for (int i = 0; i < 3; ++i)
        u[i] = q[1][i] - q[0][i], w[i] = q[2][i] - q[0][i], z[i] = q[3][i] - q[0][i];
      volume +=
        (u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) + u[2] * (w[0] * z[1] - w[1] * z[0])) /
        6;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
        {
          const std::set<int> quad = { 1, 2, 5, 6 };
          const std::pair<int, int> e(std::min(v[i], v[j]), std::max(v[i], v[j]));
          if (quad.count(e.first) && quad.count(e.second) && (e == std::make_pair(1, 6) || e == std::make_pair(2, 5)))
            diagonals[which].insert(e);
        }
    }
  EXPECT_NEAR(volume, 1.0, 1e-12); // two half-cube prisms
  EXPECT_EQ(diagonals[0].size(), 1u);
  EXPECT_EQ(diagonals[0], diagonals[1]);
}

TEST(BoundaryLayers, BadParametersAreRefusedWithNothingPartial)
{
  const SurfaceMesh s = layertest::sphereInSphere(1);
  LayerResult r;
  Status st = growLayers(s, options(10, -1e-3, 1.2), r);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("first layer height"), std::string::npos) << st.message;
  st = growLayers(s, options(10, 1e-3, 0.8), r);
  EXPECT_NE(st.message.find("growth"), std::string::npos) << st.message;
  st = growLayers(s, options(0, 1e-3, 1.2), r);
  EXPECT_NE(st.message.find("number of layers"), std::string::npos) << st.message;
  // 20 layers of 1 in a gap of 9 (bounding diagonal of the far field ~34.6): thinning everywhere.
  st = growLayers(s, options(20, 1.0, 1.0), r);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("more than the domain allows"), std::string::npos) << st.message;
  EXPECT_TRUE(r.prisms.empty());
  LayerOptions unknown = options(3, 1e-3, 1.2);
  unknown.patchNames = { "wing" };
  st = growLayers(s, unknown, r);
  EXPECT_NE(st.message.find("'wing' is not a patch"), std::string::npos) << st.message;
}

TEST(BoundaryLayers, SphereInSphereGetsEveryLayerAtItsHeight)
{
  const SurfaceMesh s = layertest::sphereInSphere(3);
  LayerResult r;
  const LayerOptions o = options(10, 1e-3, 1.2);
  ASSERT_TRUE(growLayers(s, o, r).ok());
  const int32_t bodyTriangles = 20 * 64;
  EXPECT_EQ(r.stats.layeredTriangles, bodyTriangles); // the far field is not a wall
  EXPECT_EQ(r.stats.fullTriangles, bodyTriangles);
  EXPECT_EQ(r.stats.thinnedColumns, 0);
  EXPECT_DOUBLE_EQ(r.stats.coverage(), 1.0);
  ASSERT_EQ(r.prisms.size(), size_t(6 * 10 * bodyTriangles));
  for (size_t p = 0; p < r.prismLayer.size(); ++p)
  {
    ASSERT_TRUE(prismOk(r, p)) << "prism " << p;
    const int32_t* v = r.prisms.data() + 6 * p;
    const double expected = 1e-3 * std::pow(1.2, r.prismLayer[p]);
    for (int i = 0; i < 3; ++i)
      ASSERT_NEAR(distance(at(r, v[i]), at(r, v[i + 3])) / expected, 1.0, 1e-9) << "prism " << p;
  }
  // The tet region's boundary: the last layer's outer surface plus the far field, closed and clean.
  int64_t interface = 0;
  for (const int32_t patch : r.tetBoundary.patchIds)
    interface += patch == r.interfacePatch ? 1 : 0;
  EXPECT_EQ(interface, bodyTriangles);
  EXPECT_TRUE(surfaceStatus(checkSurface(r.tetBoundary)).ok());
}

TEST(BoundaryLayers, CloseBodiesAreThinnedNotCrossed)
{
  // Two unit spheres 0.06 apart, 0.1 of layers each: the columns facing each other must be thinned.
  SurfaceMesh s;
  const double c1[3] = { -1.03, 0, 0 }, c2[3] = { 1.03, 0, 0 }, o[3] = { 0, 0, 0 };
  layertest::addIcosphere(s, c1, 1.0, 3, 1);
  layertest::addIcosphere(s, c2, 1.0, 3, 1);
  layertest::addIcosphere(s, o, 10.0, 1, 2);
  s.patchNames = { { 1, "wall" }, { 2, "farfield" } };
  LayerResult r;
  ASSERT_TRUE(growLayers(s, options(5, 0.01, 1.5), r).ok());
  EXPECT_GT(r.stats.thinnedColumns, 0);
  EXPECT_GT(r.stats.thinnedBy[int(ThinnedReason::Collision)], 0);
  EXPECT_GT(r.stats.coverage(), 0.6); // measured 0.78: thinning spreads smoothly (1.5x per neighbour)
  EXPECT_LT(r.stats.coverage(), 1.0);
  for (size_t p = 0; p < r.prismLayer.size(); ++p)
    ASSERT_TRUE(prismOk(r, p)) << "prism " << p;
  EXPECT_TRUE(surfaceStatus(checkSurface(r.tetBoundary)).ok());
}

TEST(BoundaryLayers, InternalFlowCornersStayValid)
{
  // A box as the only shell: the layers march inwards, the box's corners are concave for them.
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  LayerResult r;
  ASSERT_TRUE(growLayers(s, options(8, 0.01, 1.3), r).ok());
  EXPECT_EQ(r.stats.layeredTriangles, 12);
  for (size_t p = 0; p < r.prismLayer.size(); ++p)
    ASSERT_TRUE(prismOk(r, p)) << "prism " << p;
  EXPECT_TRUE(surfaceStatus(checkSurface(r.tetBoundary)).ok());
}

TEST(BoundaryLayers, LayersMarchInASymmetryPlane)
{
  // A box whose z = 0 face is a symmetry plane: the walls' points on it march in it (z stays 0 exactly), the
  // plane's triangles move with them, and each wall edge on the plane gets a side quad per layer.
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  s.patchIds.assign(12, 1);
  s.patchIds[0] = s.patchIds[1] = 2; // the quad {0,2,3,1}: z = 0
  s.patchNames = { { 1, "wall" }, { 2, "symmetry" } };
  LayerResult r;
  const Status st = growLayers(s, options(3, 0.01, 1.2), r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.stats.layeredTriangles, 10);
  EXPECT_EQ(r.sideQuads.size(), size_t(4 * 4 * 3));
  for (size_t p = 0; p < r.prismLayer.size(); ++p)
    ASSERT_TRUE(prismOk(r, p)) << "prism " << p;
  for (const int32_t v : r.sideQuads)
    EXPECT_EQ(r.points[3 * size_t(v) + 2], 0.0);
  EXPECT_TRUE(surfaceStatus(checkSurface(r.tetBoundary)).ok());
}

TEST(BoundaryLayers, LayersAlongACurvedOrSecondPatchAreRefused)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  s.patchIds.assign(12, 1);
  s.patchIds[0] = s.patchIds[1] = s.patchIds[8] = s.patchIds[9] = 2; // z = 0 and x = 0: not flat
  s.patchNames = { { 1, "wing" }, { 2, "inlet" }, { 3, "outlet" } };
  LayerResult r;
  Status st = growLayers(s, options(3, 0.01, 1.2), r);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("'inlet'"), std::string::npos) << st.message;
  EXPECT_NE(st.message.find("symmetry plane"), std::string::npos) << st.message;
  EXPECT_TRUE(r.prisms.empty());
  s.patchIds[8] = s.patchIds[9] = 3; // two flat patches meeting at the wall: a point on both
  st = growLayers(s, options(3, 0.01, 1.2), r);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("also on patch"), std::string::npos) << st.message;
}

TEST(BoundaryLayers, UnnamedFarFieldAndBoxSidesGetNoLayersByDefault)
{
  // A far-field box with one unnamed patch per side around an unnamed unit sphere (a Medit file's references):
  // only the sphere is a wall by default, whether the box is six patches or one.
  SurfaceMesh s;
  const double lo[3] = { -5, -5, -5 }, hi[3] = { 5, 5, 5 }, o[3] = { 0, 0, 0 };
  testshapes::addBox(s, lo, hi);
  for (int32_t t = 0; t < 12; ++t)
    s.patchIds.push_back(1 + t / 2);
  layertest::addIcosphere(s, o, 1.0, 2, 7);
  LayerResult r;
  Status st = growLayers(s, options(3, 0.01, 1.2), r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.stats.layeredTriangles, 20 * 16);
  std::fill(s.patchIds.begin(), s.patchIds.begin() + 12, 1);
  st = growLayers(s, options(3, 0.01, 1.2), r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.stats.layeredTriangles, 20 * 16);
  // Named, the names decide: a box side called "wall" is layered too.
  s.patchNames = { { 1, "wall" }, { 7, "body" } };
  st = growLayers(s, options(3, 0.01, 1.2), r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.stats.layeredTriangles, 20 * 16 + 12);
  // A box alone, split into unnamed patches: every patch spans the domain, none is taken for a wall.
  SurfaceMesh box;
  testshapes::addBox(box, lo, hi);
  box.patchIds.assign(12, 1);
  box.patchIds[0] = box.patchIds[1] = 2;
  st = growLayers(box, options(3, 0.01, 1.2), r);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("no wall patch"), std::string::npos) << st.message;
  EXPECT_NE(st.message.find("--layer-patches"), std::string::npos) << st.message;
}

TEST(BoundaryLayers, WallSkewnessIsOpenFoamsFaceSkewnessInTheSurface)
{
  // Edge (0,0,0)-(1,0,0) between two triangles. Mirror-symmetric apexes: the centroid line crosses the edge
  // at its midpoint (0). Both apexes at x = -10: it crosses at x = -3, 3.5 from the midpoint, over the
  // face's half-extent 0.5 (more than 0.2 * |d| = 0.2 * 2/3): exactly 7, above checkMesh's 4.
  const std::vector<int32_t> triangles = { 0, 1, 2, 1, 0, 3 };
  const auto skew = [&](double ax, double bx)
  {
    const std::vector<double> points = { 0, 0, 0, 1, 0, 0, ax, 1, 0, bx, -1, 0 };
    return wallFaceQuality(points, triangles).skewness;
  };
  EXPECT_NEAR(skew(0.5, 0.5).worst, 0.0, 1e-12);
  EXPECT_EQ(skew(0.5, 0.5).edgesOverLimit, 0);
  const WallEdgeExtreme sheared = skew(-10, -10);
  EXPECT_NEAR(sheared.worst, 7.0, 1e-12);
  EXPECT_EQ(sheared.edgesOverLimit, 1);
  EXPECT_DOUBLE_EQ(sheared.worstPoint[0], 0.5);
  // Sheared the opposite ways: centroids (-3, 1/3) and (4, -1/3), a line through the midpoint again.
  EXPECT_NEAR(skew(-10, 11).worst, 0.0, 1e-12);
}

TEST(BoundaryLayers, WallNonOrthogonalityIsTheAngleOfTheCentroidLine)
{
  // The same edge along x, both triangles in z = 0 (marching along z: the side face's normal is y). Apexes
  // at x = 0.5 +- s: the centroids (0.5 + s/3, 1/3) and (0.5 - s/3, -1/3), a line at atan(s) from y.
  const std::vector<int32_t> triangles = { 0, 1, 2, 1, 0, 3 };
  const auto ortho = [&](double s, double fold)
  {
    const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0.5 + s, 1, fold, 0.5 - s, -1, fold };
    return wallFaceQuality(points, triangles).nonOrthogonality;
  };
  EXPECT_NEAR(ortho(0, 0).worst, 0.0, 1e-12);
  EXPECT_NEAR(ortho(1, 0).worst, 45.0, 1e-12);
  const WallEdgeExtreme steep = ortho(3, 0);
  EXPECT_NEAR(steep.worst, std::atan(3.0) * 180 / 3.14159265358979323846, 1e-12); // 71.57 deg
  EXPECT_EQ(steep.edgesOverLimit, 1);
  EXPECT_EQ(ortho(2.7, 0).edgesOverLimit, 0); // 69.68 deg
  // Folded about the edge (a ridge, both apexes raised): the marching direction is the mean normal and the
  // side face stays upright, so the fold alone adds no angle.
  EXPECT_NEAR(ortho(0, 0.5).worst, 0.0, 1e-12);
  EXPECT_NEAR(ortho(1, 0.5).worst, 45.0, 1e-9);
  // One warning per measure over its limit, naming the worst edge's midpoint.
  const std::vector<std::string> warnings =
    wallFaceWarnings(wallFaceQuality({ 0, 0, 0, 1, 0, 0, 3.5, 1, 0, -2.5, -1, 0 }, triangles));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("non-orthogonality above 70 deg"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("(0.5, 0, 0)"), std::string::npos) << warnings[0];
}

TEST(BoundaryLayers, TotalThicknessGivesTheGrowthOrTheFirstHeight)
{
  // 10 layers from 1e-3 to a total of 0.02: the ratio r with 1e-3 (r^10 - 1) / (r - 1) = 0.02 (1.1469...).
  LayerOptions o = options(10, 1e-3, 1.2);
  o.thickness = 0.02;
  const LayerOptions solved = o.resolved();
  EXPECT_GT(solved.growth, 1.146);
  EXPECT_LT(solved.growth, 1.148);
  EXPECT_NEAR(solved.totalThickness() / 0.02, 1.0, 1e-12);
  const SurfaceMesh s = layertest::sphereInSphere(2);
  LayerResult r;
  ASSERT_TRUE(growLayers(s, o, r).ok());
  for (size_t p = 0; p < r.prismLayer.size(); ++p)
    if (r.prismLayer[p] == 9)
    {
      const int32_t* v = r.prisms.data() + 6 * p;
      ASSERT_NEAR(distance(at(r, v[0]), at(r, v[3])) / (1e-3 * std::pow(solved.growth, 9)), 1.0, 1e-9);
    }
  // Without a first height: the one that stacks 10 layers of ratio 1.2 to 0.02.
  o.firstHeight = 0;
  EXPECT_NEAR(o.resolved().firstHeight / (0.02 * 0.2 / (std::pow(1.2, 10) - 1)), 1.0, 1e-12);
  EXPECT_TRUE(validateLayerOptions(o).ok());
  // Thinner than 10 first layers, or thicker than ratio 10 allows: no ratio, a message.
  o.firstHeight = 1e-3;
  o.thickness = 0.009;
  Status st = validateLayerOptions(o);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
  EXPECT_NE(st.message.find("no growth ratio"), std::string::npos) << st.message;
  o.thickness = 1e8;
  EXPECT_FALSE(validateLayerOptions(o).ok());
  o.thickness = -1;
  EXPECT_FALSE(validateLayerOptions(o).ok());
}

TEST(BoundaryLayers, FirstHeightFromYPlus)
{
  // Re = 1e6, L = 1, y+ = 1: Cf = 0.026 / 1e6^(1/7) = 3.6126e-3, sqrt(Cf/2) = 4.2501e-2, y = 2.3529e-5.
  EXPECT_NEAR(firstHeightForYPlus(1, 1e6, 1), 2.3529e-5, 1e-8);
  // Linear in y+ and in the length; thinner for a higher Reynolds number.
  EXPECT_NEAR(firstHeightForYPlus(30, 1e6, 2) / firstHeightForYPlus(1, 1e6, 1), 60.0, 1e-9);
  EXPECT_LT(firstHeightForYPlus(1, 1e7, 1), firstHeightForYPlus(1, 1e6, 1));
  EXPECT_EQ(firstHeightForYPlus(-1, 1e6, 1), 0.0);
}
