// Exterior removal and region selection: even-odd over nesting (any orientation), orientation rule,
// keep-all with labels.
#include "Mesher.h"
#include "MesherTestShapes.h"

#include <gtest/gtest.h>

#include <set>

using namespace volgrid;

namespace
{

SurfaceMesh nested(bool innerInward, bool outerInward)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 4, 4, 4 }, lo2[3] = { 1, 1, 1 }, hi2[3] = { 3, 3, 3 };
  testshapes::addBox(s, lo, hi, false, outerInward);
  testshapes::addBox(s, lo2, hi2, true, innerInward);
  return s;
}

double volumeOf(const SurfaceMesh& s, RegionRule rule, int* regions = nullptr, Status* status = nullptr)
{
  MesherOptions o;
  o.regionRule = rule;
  o.verify = true;
  MesherResult r;
  Status st = meshSurface(s, o, r);
  if (status)
    *status = st;
  EXPECT_TRUE(st.ok() || status) << st.message;
  if (regions)
    *regions = static_cast<int>(r.stats.regions);
  return r.stats.tetVolume;
}

} // namespace

TEST(Regions, EvenOddIgnoresOrientation)
{
  for (int o = 0; o < 4; ++o)
    EXPECT_NEAR(volumeOf(nested(o & 1, o & 2), RegionRule::EvenOdd), 64.0 - 8.0, 1e-9) << o;
}

TEST(Regions, KeepAllLabelsEveryEnclosedRegion)
{
  int regions = 0;
  MesherOptions o;
  o.regionRule = RegionRule::KeepAll;
  MesherResult r;
  ASSERT_TRUE(meshSurface(nested(false, false), o, r).ok());
  EXPECT_EQ(r.stats.regions, 2);
  std::set<int32_t> labels(r.tetRegion.begin(), r.tetRegion.end());
  EXPECT_EQ(labels.size(), 2u);
  EXPECT_NEAR(r.stats.tetVolume, 64.0, 1e-9);
  (void)regions;
  // The interface triangles are faces with tets on both sides.
  EXPECT_EQ(r.boundaryTriangles.size(), nested(false, false).triangles.size());
}

TEST(Regions, OrientationRuleFollowsNormals)
{
  // Normals away from the domain: outer outward + inner inward -> the shell between (56).
  EXPECT_NEAR(volumeOf(nested(true, false), RegionRule::Orientation), 56.0, 1e-9);
  // Outer outward + inner outward: the inner box's normals point away from the inner box -> the inner
  // box is a domain too? No: it points into the shell region, which then has mixed normals: error.
  Status st;
  volumeOf(nested(false, false), RegionRule::Orientation, nullptr, &st);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption) << st.message;
}

TEST(Regions, InwardSingleShellOrientationRuleSelectsNothing)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi, false, true);
  Status st;
  volumeOf(s, RegionRule::Orientation, nullptr, &st);
  EXPECT_EQ(st.kind, ErrorKind::InvalidOption);
}
