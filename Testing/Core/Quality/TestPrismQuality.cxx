// Prism metrics (Core/Quality/PrismQuality.h) on prisms whose values follow by hand: right prisms of any
// height, a sheared one, one with its top pushed through its base, one with a single corner folded.
#include "PrismQuality.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace volgrid::quality;

namespace
{
// Base (0 0 0) (1 0 0) (bx by 0), top = base + (sx, 0, h), in SolverMesh's order.
PrismMetrics prism(double bx, double by, double h, double sx = 0.0)
{
  const double pts[6][3] = {
    { 0, 0, 0 }, { 1, 0, 0 }, { bx, by, 0 }, { sx, 0, h }, { 1 + sx, 0, h }, { bx + sx, by, h }
  };
  const double* p[6] = { pts[0], pts[1], pts[2], pts[3], pts[4], pts[5] };
  return prismMetrics(p);
}
const double kEquilateralY = std::sqrt(3.0) / 2.0;
} // namespace

TEST(PrismQuality, RightPrismOnAnEquilateralTriangleIsOneAtAnyHeight)
{
  for (double h : { 1.0, 1e-3, 1e-6 })
  {
    const PrismMetrics m = prism(0.5, kEquilateralY, h);
    EXPECT_NEAR(m.minScaledJacobian, 1.0, 1e-12) << h;
    EXPECT_NEAR(m.volume, kEquilateralY / 2.0 * h, 1e-15) << h;
    EXPECT_EQ(m.nonPositiveCorners, 0) << h;
  }
  // A right-angled base: the 45-degree corners give sin 45 / sin 60.
  const PrismMetrics r = prism(0.0, 1.0, 0.1);
  EXPECT_NEAR(r.minScaledJacobian, std::sqrt(2.0) / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(r.volume, 0.05, 1e-15);
}

TEST(PrismQuality, ShearLowersTheJacobianButKeepsTheVolume)
{
  // The column leans by 45 degrees along x: cos 45 at the corners where it is orthogonal to neither edge.
  const PrismMetrics m = prism(0.5, kEquilateralY, 1.0, 1.0);
  EXPECT_NEAR(m.volume, kEquilateralY / 2.0, 1e-12);
  EXPECT_NEAR(m.minScaledJacobian, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(m.nonPositiveCorners, 0);
}

TEST(PrismQuality, InvertedAndFoldedCornersAreCountedExactly)
{
  const PrismMetrics flipped = prism(0.5, kEquilateralY, -1e-3); // the top below the base: every corner
  EXPECT_EQ(flipped.nonPositiveCorners, 6);
  EXPECT_LT(flipped.volume, 0.0);
  EXPECT_NEAR(flipped.minScaledJacobian, -1.0, 1e-12);
  const PrismMetrics flat = prism(0.5, kEquilateralY, 0.0); // zero height: no corner is positive
  EXPECT_EQ(flat.nonPositiveCorners, 6);
  EXPECT_EQ(flat.minScaledJacobian, 0.0);
  // One top point pushed below the base plane: its corner and those next to it along the top fold.
  const double pts[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, kEquilateralY, 0 },
                             { 0, 0, 1 }, { 1, 0, 1 }, { 0.5, kEquilateralY, -0.5 } };
  const double* p[6] = { pts[0], pts[1], pts[2], pts[3], pts[4], pts[5] };
  const PrismMetrics folded = prismMetrics(p);
  EXPECT_GE(folded.nonPositiveCorners, 1);
  EXPECT_LE(folded.minScaledJacobian, 0.0);
}
