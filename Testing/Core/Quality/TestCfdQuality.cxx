// CFD face metrics (Core/Quality/CfdQuality.h) on two tets sharing the face z = 0, where the values follow by
// hand from checkMesh's definitions; the comparison with checkMesh itself on real meshes is
// Testing/Export/test_solver_export.py.
#include "CfdQuality.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace volgrid::quality;

namespace
{
// Tet 0 = (p0 p1 p2 p3) above the triangle p0 p1 p2 in z = 0, tet 1 = (p0 p2 p1 p4) below it.
std::vector<double> pair(double ax, double below)
{
  return { 0, 0, 0, 1, 0, 0, 0, 1, 0, ax, 1.0 / 3.0, 1, 1.0 / 3.0, 1.0 / 3.0, -below };
}
const std::vector<int32_t> kTets = { 0, 1, 2, 3, 0, 2, 1, 4 };
} // namespace

TEST(CfdQuality, MirrorPairIsOrthogonalAndUnskewed)
{
  const CfdSummary s = cfdMetrics(pair(1.0 / 3.0, 1.0), kTets, nullptr);
  EXPECT_EQ(s.internalFaces, 1);
  EXPECT_EQ(s.boundaryFaces, 6);
  EXPECT_NEAR(s.maxNonOrthogonality, 0.0, 1e-6);
  EXPECT_NEAR(s.maxVolumeRatio, 1.0, 1e-12);
  // The apex projects onto the base's centroid: the base (a boundary face) has no skewness either.
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 0, 1, 0 };
  const double centre[3] = { 1.0 / 3.0, 1.0 / 3.0, 0.25 };
  EXPECT_NEAR(boundaryFaceSkewness(a, b, c, centre), 0.0, 1e-12);
}

TEST(CfdQuality, ShearedPairByHand)
{
  // Apex 3 moved by 2 in x: d = (c1 - c0) = (-2, 0, -2) / 4, so 45 degrees from the face normal; the
  // centre line crosses z = 0 at x = 7/12, 1/4 from the face centre (x = 1/3) whose farthest point
  // along x is 2/3 away: skewness 0.25 / (2/3) = 0.375.
  CfdCellMetrics cells;
  const CfdSummary s = cfdMetrics(pair(1.0 / 3.0 + 2.0, 1.0), kTets, &cells);
  EXPECT_NEAR(s.maxNonOrthogonality, 45.0, 1e-9);
  EXPECT_NEAR(s.averageNonOrthogonality, 45.0, 1e-9);
  EXPECT_EQ(s.severelyNonOrthogonalFaces, 0);
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 0, 1, 0 };
  const double c0[3] = { (1 + 1.0 / 3.0 + 2.0) / 4, (1 + 1.0 / 3.0) / 4, 0.25 };
  const double c1[3] = { (1 + 1.0 / 3.0) / 4, (1 + 1.0 / 3.0) / 4, -0.25 };
  EXPECT_NEAR(internalFaceSkewness(a, b, c, c0, c1), 0.375, 1e-12);
  EXPECT_NEAR(cells.nonOrthogonality[0], 45.0, 1e-9);
  EXPECT_NEAR(cells.nonOrthogonality[1], 45.0, 1e-9);
  EXPECT_GE(cells.skewness[0], 0.375 - 1e-12);
}

TEST(CfdQuality, SevereFacesAndVolumeRatio)
{
  // A far-sheared apex and a lower tet three times as tall: d = (-20, 0, -4) / 4, atan(5) = 78.7 degrees
  // from the face normal (> 70), volumes 1/6 and 1/2.
  CfdCellMetrics cells;
  const CfdSummary s = cfdMetrics(pair(1.0 / 3.0 + 20.0, 3.0), kTets, &cells);
  const double d[3] = { -20.0 / 4, 0, -4.0 / 4 };
  EXPECT_NEAR(s.maxNonOrthogonality, std::atan2(std::hypot(d[0], d[1]), -d[2]) * 180 / M_PI, 1e-9);
  EXPECT_EQ(s.severelyNonOrthogonalFaces, 1);
  EXPECT_NEAR(s.maxVolumeRatio, 3.0, 1e-12);
  EXPECT_NEAR(cells.volumeRatio[0], 3.0, 1e-12);
  EXPECT_NEAR(cells.volumeRatio[1], 3.0, 1e-12);
}

// Mixed meshes (cfdMetricsMixed): tets measured alike, prisms and pyramids by hand.
TEST(CfdQualityMixed, TetsAloneGiveTheTetFigures)
{
  for (double ax : { 1.0 / 3.0, 1.0 / 3.0 + 2.0, 1.0 / 3.0 + 20.0 })
  {
    const std::vector<double> points = pair(ax, 3.0);
    CfdCellMetrics a, b;
    const CfdSummary s = cfdMetrics(points, kTets, &a);
    MixedCells cells;
    cells.tets = &kTets;
    const CfdSummary m = cfdMetricsMixed(points, cells, &b);
    EXPECT_EQ(m.internalFaces, s.internalFaces);
    EXPECT_EQ(m.boundaryFaces, s.boundaryFaces);
    EXPECT_EQ(m.severelyNonOrthogonalFaces, s.severelyNonOrthogonalFaces);
    EXPECT_NEAR(m.maxNonOrthogonality, s.maxNonOrthogonality, 1e-9);
    EXPECT_NEAR(m.maxSkewness, s.maxSkewness, 1e-9 * s.maxSkewness);
    EXPECT_NEAR(m.maxVolumeRatio, s.maxVolumeRatio, 1e-9 * s.maxVolumeRatio);
    for (int t = 0; t < 2; ++t)
    {
      EXPECT_NEAR(b.volume[t], a.volume[t], 1e-12);
      EXPECT_NEAR(b.skewness[t], a.skewness[t], 1e-9 * (1 + a.skewness[t]));
    }
  }
}

TEST(CfdQualityMixed, ShearedPrismOnAPrismByHand)
{
  // Prism 0: triangle (0,0,0) (1,0,0) (0,1,0) extruded to z = 1; prism 1 on top of it, its top moved by
  // (2, 0, 0). Centres: (1/3, 1/3, 1/2) and (4/3, 1/3, 3/2), so d = (1, 0, 1): 45 degrees from the shared
  // face's normal. Both volumes 1/2; the shared face and the six quads bound them.
  const std::vector<double> points = {
    0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 2, 0, 2, 3, 0, 2, 2, 1, 2
  };
  const std::vector<int32_t> prisms = { 0, 1, 2, 3, 4, 5, 3, 4, 5, 6, 7, 8 };
  MixedCells cells;
  cells.prisms = &prisms;
  CfdCellMetrics m;
  const CfdSummary s = cfdMetricsMixed(points, cells, &m);
  EXPECT_EQ(s.internalFaces, 1);
  EXPECT_EQ(s.boundaryFaces, 8);
  EXPECT_NEAR(s.maxNonOrthogonality, 45.0, 1e-9);
  EXPECT_NEAR(m.volume[0], 0.5, 1e-12);
  EXPECT_NEAR(m.volume[1], 0.5, 1e-12);
  EXPECT_NEAR(s.maxVolumeRatio, 1.0, 1e-12);
  // The centre line crosses z = 1 at (5/6, 1/3), 1/2 from the face centre (1/3, 1/3); the face reaches
  // 2/3 along x from its centre: skewness 0.75.
  EXPECT_NEAR(m.skewness[0], 0.75, 1e-9);
}

TEST(CfdQualityMixed, CubeOfSixPyramids)
{
  // The unit cube cut into six pyramids, one per face, apex at the centre: each of volume 1/6, twelve
  // shared triangles, each orthogonal to the line between the two pyramids' centres. Given either way
  // round, the same figures.
  std::vector<double> points;
  for (int i = 0; i < 8; ++i)
    points.insert(points.end(), { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  points.insert(points.end(), { 0.5, 0.5, 0.5 });
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                            { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } }; // normals out of the cube
  for (bool reversed : { false, true })
  {
    std::vector<int32_t> pyramids;
    for (const auto& q : quads) // the quad turns towards the apex: inward, against the outward normals
      if (reversed)
        pyramids.insert(pyramids.end(), { q[0], q[1], q[2], q[3], 8 });
      else
        pyramids.insert(pyramids.end(), { q[0], q[3], q[2], q[1], 8 });
    MixedCells cells;
    cells.pyramids = &pyramids;
    CfdCellMetrics m;
    const CfdSummary s = cfdMetricsMixed(points, cells, &m);
    EXPECT_EQ(s.internalFaces, 12);
    EXPECT_EQ(s.boundaryFaces, 6);
    EXPECT_NEAR(s.maxNonOrthogonality, 0.0, 1e-6);
    EXPECT_EQ(s.severelyNonOrthogonalFaces, 0);
    for (double v : m.volume)
      EXPECT_NEAR(v, 1.0 / 6.0, 1e-12);
  }
}
