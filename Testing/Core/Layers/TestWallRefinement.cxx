// Wall refinement around skewed edges (Core/Layers/WallRefinement.h): the skewed edges go, the surface keeps
// its shape and stays closed and conforming, the same input gives the same output; and growLayers uses it.
#include "WallRefinement.h"

#include "BoundaryLayers.h"
#include "LayerTestShapes.h"
#include "SurfaceChecks.h"
#include "WallFaceQuality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <algorithm>
#include <utility>

using namespace volgrid;

namespace
{
// A closed needle tetrahedron: the short edge 0-1 along x, both apexes 10 behind it, so the centroids of
// its two triangles pass far from it (skewness 7, as in WallSkewnessIsOpenFoamsFaceSkewnessInTheSurface).
SurfaceMesh needleTetrahedron(double shift = 0)
{
  SurfaceMesh s;
  s.addPoint(shift, 0, 0);
  s.addPoint(shift + 1, 0, 0);
  s.addPoint(shift - 10, 1, 0.3);
  s.addPoint(shift - 10, -1, 0.3);
  for (const int32_t t : { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 })
    s.triangles.push_back(t);
  return s;
}

// Every directed edge once and its reverse once: closed, conforming (no point on another's edge) and
// consistently oriented.
bool closedAndConforming(const SurfaceMesh& s)
{
  std::map<std::pair<int32_t, int32_t>, int> directed;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    for (int i = 0; i < 3; ++i)
      ++directed[{ s.triangle(t)[i], s.triangle(t)[(i + 1) % 3] }];
  for (const auto& [edge, count] : directed)
    if (count != 1 || directed.count({ edge.second, edge.first }) == 0)
      return false;
  return true;
}

// Distance from p to the segment ab.
double distanceToSegment(const double* p, const double* a, const double* b)
{
  double ab[3], ap[3], t = 0, l = 0;
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    t += ab[k] * ap[k];
    l += ab[k] * ab[k];
  }
  t = std::clamp(t / l, 0.0, 1.0);
  double d = 0;
  for (int k = 0; k < 3; ++k)
    d += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
  return std::sqrt(d);
}
} // namespace

TEST(WallRefinement, SkewedEdgesGoAndTheSurfaceKeepsItsShape)
{
  const SurfaceMesh input = needleTetrahedron();
  // Only the two triangles of the skewed edge are walls: the others are split where they share a bisected
  // edge, and the surface stays conforming.
  std::vector<uint8_t> isWall = { 1, 1, 0, 0 };
  ASSERT_EQ(skewedWallEdges(input.points, wallTriangles(input, isWall)).size(), 2u);
  SurfaceMesh s = input;
  const WallRefinement r = refineSkewedWall(s, isWall);
  EXPECT_EQ(r.skewedEdgesBefore, 1);
  EXPECT_EQ(r.skewedEdgesAfter, 0);
  EXPECT_GT(r.splitEdges, 0);
  EXPECT_EQ(s.numberOfPoints(), input.numberOfPoints() + r.splitEdges);
  EXPECT_EQ(s.numberOfTriangles(), input.numberOfTriangles() + r.addedTriangles);
  ASSERT_EQ(isWall.size(), size_t(s.numberOfTriangles()));
  EXPECT_TRUE(skewedWallEdges(s.points, wallTriangles(s, isWall)).empty());
  EXPECT_TRUE(closedAndConforming(s));
  EXPECT_TRUE(surfaceStatus(checkSurface(s)).ok());
  // The same shape: the input's points kept, every new one on an input edge (to rounding), the same volume.
  for (int32_t p = 0; p < input.numberOfPoints(); ++p)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(s.point(p)[k], input.point(p)[k]);
  for (int32_t p = input.numberOfPoints(); p < s.numberOfPoints(); ++p)
  {
    double nearest = 1e300;
    for (int32_t a = 0; a < 4; ++a)
      for (int32_t b = a + 1; b < 4; ++b)
        nearest = std::min(nearest, distanceToSegment(s.point(p), input.point(a), input.point(b)));
    EXPECT_LT(nearest, 1e-14) << "point " << p;
  }
  EXPECT_NEAR(signedVolume(s), signedVolume(input), 1e-13 * std::abs(signedVolume(input)));
  // The same input gives the same surface.
  SurfaceMesh again = input;
  std::vector<uint8_t> wallAgain = { 1, 1, 0, 0 };
  refineSkewedWall(again, wallAgain);
  EXPECT_EQ(again.points, s.points);
  EXPECT_EQ(again.triangles, s.triangles);
}

TEST(WallRefinement, AWallWithoutSkewedEdgesIsLeftAlone)
{
  const SurfaceMesh input = layertest::sphereInSphere(2);
  SurfaceMesh s = input;
  std::vector<uint8_t> isWall(s.numberOfTriangles(), 1);
  const WallRefinement r = refineSkewedWall(s, isWall);
  EXPECT_EQ(r.skewedEdgesBefore, 0);
  EXPECT_EQ(r.splitEdges, 0);
  EXPECT_EQ(r.rounds, 0);
  EXPECT_EQ(s.points, input.points);
  EXPECT_EQ(s.triangles, input.triangles);
  EXPECT_TRUE(wallRefinementNote(r).empty());
}

namespace
{
// A box [0,1]x[0,2]x[0,1] shifted by `at`, its top triangulated as a fan from corner (0,0,1) to 16 points
// along x = 1 and 8 along y = 2, its faces x = 1 and y = 2 as fans that share those points, the other
// three as two triangles: the top's long fan triangles meet the side fans' at skewed edges, as a wing's
// root fan meets its leading edge. Outward (a convex body: each triangle faces away from the centre).
SurfaceMesh fannedBox(const double at[3], int32_t patch)
{
  SurfaceMesh s;
  const auto point = [&](double x, double y, double z) { return s.addPoint(at[0] + x, at[1] + y, at[2] + z); };
  const auto fan = [&](int32_t hub, const std::vector<int32_t>& rim)
  {
    for (size_t k = 0; k + 1 < rim.size(); ++k)
      s.addTriangle(hub, rim[k], rim[k + 1], patch);
  };
  std::vector<int32_t> alongX1, alongY2; // top points on x = 1 (y up), on y = 2 (x down)
  for (int k = 0; k <= 16; ++k)
    alongX1.push_back(point(1, k / 8.0, 1));
  for (int k = 7; k >= 0; --k)
    alongY2.push_back(point(k / 8.0, 2, 1));
  const int32_t o = point(0, 0, 0), x = point(1, 0, 0), xy = point(1, 2, 0), y = point(0, 2, 0), top = point(0, 0, 1);
  std::vector<int32_t> rim = alongX1;
  rim.insert(rim.end(), alongY2.begin(), alongY2.end());
  fan(top, rim);                                         // z = 1
  std::vector<int32_t> sideX = alongX1;
  sideX.push_back(xy);
  fan(x, sideX);                                         // x = 1
  std::vector<int32_t> sideY = { xy, alongX1.back() };
  sideY.insert(sideY.end(), alongY2.begin(), alongY2.end());
  fan(y, sideY);                                         // y = 2
  fan(o, { x, xy, y });                                  // z = 0
  fan(o, { x, alongX1.front(), top });                   // y = 0
  fan(o, { top, alongY2.back(), y });                    // x = 0
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
  {
    int32_t* v = s.triangles.data() + 3 * size_t(t);
    double u[3], w[3], c[3], n[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = s.point(v[1])[k] - s.point(v[0])[k];
      w[k] = s.point(v[2])[k] - s.point(v[0])[k];
      c[k] = s.point(v[0])[k] - at[k] - (k == 1 ? 1.0 : 0.5);
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    if (n[0] * c[0] + n[1] * c[1] + n[2] * c[2] < 0)
      std::swap(v[1], v[2]);
  }
  return s;
}

} // namespace

TEST(WallRefinement, LayersSplitTheWallUnlessAskedToKeepIt)
{
  // The fanned box as the wall inside a far-field sphere of radius 10.
  SurfaceMesh s;
  const double o[3] = { 0, 0, 0 }, at[3] = { -0.5, -1, -0.5 };
  layertest::addIcosphere(s, o, 10.0, 1, 2);
  const SurfaceMesh box = fannedBox(at, 1);
  s.append(box);
  s.patchNames[1] = "wall";
  s.patchNames[2] = "farfield";
  LayerOptions o3;
  o3.layers = 3;
  o3.firstHeight = 1e-3;
  LayerResult refined, kept;
  const Status status = growLayers(s, o3, refined);
  ASSERT_TRUE(status.ok()) << status.message;
  const WallRefinement& r = refined.stats.wallRefinement;
  EXPECT_GT(r.skewedEdgesBefore, 0);
  EXPECT_GT(r.splitEdges, 0);
  EXPECT_EQ(r.skewedEdgesAfter, 0);
  EXPECT_EQ(refined.stats.wallFaceQuality.skewness.edgesOverLimit, 0);
  EXPECT_EQ(refined.stats.layeredTriangles, box.numberOfTriangles() + r.addedTriangles);
  EXPECT_EQ(refined.stats.coverage(), 1.0);
  EXPECT_FALSE(wallRefinementNote(r).empty());
  o3.keepWallTriangles = true;
  ASSERT_TRUE(growLayers(s, o3, kept).ok());
  EXPECT_EQ(kept.stats.wallRefinement.splitEdges, 0);
  EXPECT_EQ(kept.stats.wallFaceQuality.skewness.edgesOverLimit, r.skewedEdgesBefore);
  EXPECT_EQ(kept.stats.layeredTriangles, box.numberOfTriangles());
}
