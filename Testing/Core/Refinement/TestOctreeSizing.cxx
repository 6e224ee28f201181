// The octree the field points query: it follows the field, and a cap on its cells leaves the error where the
// field is coarse. The case is what a size cap on a large far field does: a uniform size everywhere (the
// cap) and one small feature (a boundary point of size 0.001, the size growing away from it by the
// gradation). The far field alone asks for 8^6 leaves; with 50,000 cells the old breadth-first order
// stopped splitting at depth 5 and gave the feature 12 times its size (0.0126 against 0.001).
#include "OctreeSizing.h"
#include "SizingField.h"

#include <gtest/gtest.h>

#include <vector>

using namespace volgrid;

namespace
{
const double kFeature[3] = { 0.5137, 0.4871, 0.5029 }; // off the octree lattice

SizingField capWithOneFeature()
{
  SizingField field;
  const double size = 0.001;
  field.addSizedPoints(kFeature, &size, 1);
  SizingOptions options;
  options.gradation = 1.5; // h(p) = min(0.02, 0.001 + 0.5 |p - feature|)
  EXPECT_TRUE(field.buildUniform(0.02, options).ok());
  return field;
}

// The octree's size near the feature is within twice the field's.
void expectFeatureResolved(const OctreeSizing& octree, const SizingField& field)
{
  for (const double dx : { 0.0, 0.002, -0.004, 0.008 })
  {
    const double p[3] = { kFeature[0] + dx, kFeature[1] - dx / 2, kFeature[2] + dx / 3 };
    EXPECT_LE(octree.evaluate(p), 2 * field.evaluate(p)) << "at dx " << dx;
    EXPECT_GE(octree.evaluate(p), 0.5 * field.evaluate(p)) << "at dx " << dx;
  }
}
} // namespace

TEST(OctreeSizing, FollowsTheFieldWithoutACap)
{
  const SizingField field = capWithOneFeature();
  OctreeSizing octree;
  const double lo[3] = { 0, 0, 0 };
  octree.build(field, lo, 1.0, 18, size_t(1) << 22);
  EXPECT_FALSE(octree.capped());
  expectFeatureResolved(octree, field);
  const double far[3] = { 0.1, 0.9, 0.2 };
  EXPECT_NEAR(octree.evaluate(far), 0.02, 1e-6);
}

TEST(OctreeSizing, ACapLeavesTheFarFieldCoarseNotTheSmallSizes)
{
  const SizingField field = capWithOneFeature();
  OctreeSizing octree;
  const double lo[3] = { 0, 0, 0 };
  octree.build(field, lo, 1.0, 18, 50000);
  EXPECT_TRUE(octree.capped());
  EXPECT_LE(octree.cells(), 50000u);
  expectFeatureResolved(octree, field);
  // The far field is uniform: unsplit cells there interpolate it exactly.
  const double far[3] = { 0.1, 0.9, 0.2 };
  EXPECT_NEAR(octree.evaluate(far), 0.02, 1e-6);
}

// Cells outside where the domain is are not split (no query reaches them), and the sizes where it is are
// the same as without the restriction.
TEST(OctreeSizing, SplitsOnlyWhereTheDomainIs)
{
  const SizingField field = capWithOneFeature();
  const double lo[3] = { 0, 0, 0 };
  OctreeSizing everywhere, inDomain;
  everywhere.build(field, lo, 1.0, 18, size_t(1) << 22);
  OccupancyPyramid domain; // a slab through the feature, a tenth of the cube, as tiles of a tet's size
  domain.reset(lo, 1.0, 7);
  for (double x = 0; x < 1; x += 0.05)
    for (double y = 0; y < 1; y += 0.05)
    {
      const double tileLo[3] = { x, y, 0.45 }, tileHi[3] = { x + 0.05, y + 0.05, 0.55 };
      domain.addBox(tileLo, tileHi);
    }
  inDomain.build(field, lo, 1.0, 18, size_t(1) << 22, &domain);
  EXPECT_LT(inDomain.cells(), everywhere.cells() * 3 / 4);
  expectFeatureResolved(inDomain, field);
  for (double x = 0.01; x < 1; x += 0.0731)
    for (double y = 0.02; y < 1; y += 0.0617)
      for (double z = 0.45; z <= 0.55; z += 0.0193)
      {
        const double p[3] = { x, y, z };
        ASSERT_EQ(inDomain.evaluate(p), everywhere.evaluate(p)) << x << " " << y << " " << z;
      }
}

// A build asks its progress whether to stop every 1024 splits (the octree of a 10M-tet domain takes about a
// second) and stops there when told: cancelled() says so, and the tree has only the cells made until then.
TEST(OctreeSizing, StopsWhenCancelled)
{
  const SizingField field = capWithOneFeature();
  const double lo[3] = { 0, 0, 0 };
  OctreeSizing whole;
  whole.build(field, lo, 1.0, 18, size_t(1) << 22);
  struct StopOnSecondQuestion final : Progress
  {
    int questions = 0;
    void report(double, const char*) override {}
    bool cancelled() override { return ++questions >= 2; }
  } progress;
  OctreeSizing stopped;
  stopped.build(field, lo, 1.0, 18, size_t(1) << 22, nullptr, &progress);
  EXPECT_FALSE(whole.cancelled());
  EXPECT_TRUE(stopped.cancelled());
  EXPECT_EQ(progress.questions, 2);
  EXPECT_EQ(stopped.cells(), 1 + 8 * 2047u); // the root, and eight children for each split before the 2nd question
  EXPECT_GT(whole.cells(), stopped.cells());
}
