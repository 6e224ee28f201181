// Size estimates before work: the right order of magnitude for ordinary runs, huge for absurd options,
// never NaN, and the option that drives them.
#include "SizeEstimate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace volgrid;

// The octahedron |x|+|y|+|z| <= 1 (volume 4/3), outward oriented.
SurfaceMesh octahedron()
{
  SurfaceMesh m;
  m.points = { 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 };
  const int32_t f[8][3] = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
                            { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  for (const auto& t : f)
    m.addTriangle(t[0], t[1], t[2]);
  return m;
}
} // namespace

TEST(SizeEstimate, MaxEdgeGivesTheMeasuredOrderOfMagnitude)
{
  ImprovementOptions o;
  o.sizing.maxEdgeLength = 0.1; // measured: 21431 tets (volgrid mesh octa.off --max-edge 0.1)
  const SizeEstimate e = estimateMeshSize(octahedron(), o);
  EXPECT_GT(e.tets, 21431 / 3.0);
  EXPECT_LT(e.tets, 21431 * 3.0);
  EXPECT_EQ(e.driver, SizeDriver::MaxEdge);
}

TEST(SizeEstimate, AbsurdOptionsAreHugeAndNamed)
{
  ImprovementOptions o;
  o.sizing.maxEdgeLength = 1e-9;
  EXPECT_GT(estimateMeshSize(octahedron(), o).tets, 1e25);
  ImprovementOptions v;
  v.fieldPointOptions.maxVolume = 1e-30;
  const SizeEstimate ev = estimateMeshSize(octahedron(), v);
  EXPECT_GT(ev.tets, 1e25);
  EXPECT_EQ(ev.driver, SizeDriver::MaxVolume);
  ImprovementOptions s;
  s.sizing.scale = 1e-300;
  const SizeEstimate es = estimateMeshSize(octahedron(), s);
  EXPECT_FALSE(std::isnan(es.tets));
  EXPECT_GT(es.tets, 1e300);
  EXPECT_EQ(es.driver, SizeDriver::SizeScale);
}

TEST(SizeEstimate, RefineCountsOnlyWhereTargetsAreSmaller)
{
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const std::vector<int32_t> tets = { 0, 1, 2, 3 };
  EXPECT_EQ(estimateRefineSize(points, tets, { 0, 0, 0, 0 }, 0.75).tets, 1.0); // no targets: as is
  EXPECT_GT(estimateRefineSize(points, tets, { 1e-9, 1, 1, 1 }, 0.75).tets, 1e25);
  EXPECT_LT(estimateRefineSize(points, tets, { 0.25, 0.25, 0.25, 0.25 }, 0.75).tets, 1000.0);
}

TEST(SizeEstimate, DelaunayScalesWithThePoints)
{
  const SizeEstimate e = estimateDelaunaySize(1e6);
  EXPECT_NEAR(e.tets, 6.6e6, 1e6);
  EXPECT_GT(e.bytes, 4e8); // measured: 448 MB peak without --out, 823 MB with it
}
