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
