// The octree the field points query: it follows the field, and a cap on its cells leaves the error where the
// field is coarse. The case is what a size cap on a large far field does: a uniform size everywhere (the
// cap) and one small feature (a boundary point of size 0.001, the size growing away from it by the
// gradation). The far field alone asks for 8^6 leaves; with 50,000 cells the old breadth-first order
// stopped splitting at depth 5 and gave the feature 12 times its size (0.0126 against 0.001).
#include "CoarseBoundaryFloor.h"
#include "Enclosures.h"
#include "OctreeSizing.h"
#include "SizingField.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <memory>
#include <vector>

using namespace volgrid;

namespace
{
const double kFeature[3] = { 0.5137, 0.4871, 0.5029 }; // off the octree lattice
const double kAround[3] = { -5, -5, -5 };              // the cube of gradedFieldWithAFloor's trees

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

// A field of walks on three background meshes: a fine sphere (r = 1) inside a coarse one (r = 4), graded,
// under a cap of 0.5 that a floor raises next to the coarse sphere's triangles (CoarseBoundaryFloor.h).
SizingField gradedFieldWithAFloor()
{
  std::vector<double> xyz;
  std::vector<int32_t> tris;
  size_t nOuter = 0;
  for (const double r : { 1.0, 4.0 })
  {
    EnclosureOptions o;
    o.shape = EnclosureShape::Sphere;
    o.dimensions[0] = r;
    o.center[1] = 0.0123; // off the octree's lattice
    o.targetEdgeLength = r < 2 ? 0.08 : 1.0;
    SurfaceMesh s;
    EXPECT_TRUE(makeEnclosure(o, s).ok());
    const int32_t offset = static_cast<int32_t>(xyz.size() / 3);
    xyz.insert(xyz.end(), s.points.begin(), s.points.end());
    for (int32_t v : s.triangles)
      tris.push_back(v + offset);
    nOuter = s.points.size() / 3;
  }
  const size_t n = xyz.size() / 3;
  std::vector<double> spacing(n, 0.0);
  std::fill(spacing.end() - static_cast<std::ptrdiff_t>(nOuter), spacing.end(), 1.0);
  auto floor = std::make_shared<CoarseBoundaryFloor>();
  // The floor's nodes: the outer sphere's, with its spacing, then the inner sphere's, of no size.
  std::vector<double> floorXYZ(xyz.end() - static_cast<std::ptrdiff_t>(3 * nOuter), xyz.end());
  floorXYZ.insert(floorXYZ.end(), xyz.begin(), xyz.end() - static_cast<std::ptrdiff_t>(3 * nOuter));
  std::vector<double> floorSpacing(nOuter, 1.0);
  EXPECT_TRUE(floor->build(floorXYZ.data(), floorSpacing.data(), nOuter, n, 0.5).ok());
  SizingField field;
  field.setCapFloor(floor);
  SizingOptions options;
  options.gradation = 1.5;
  options.maxEdgeLength = 0.5;
  EXPECT_TRUE(
    field.build(xyz.data(), static_cast<int32_t>(n), tris.data(), static_cast<int32_t>(tris.size() / 3), options).ok());
  return field;
}

// Whether two trees give the same bits at a spread of points through the cube [lo, lo + size]^3.
void expectSameSizes(const OctreeSizing& a, const OctreeSizing& b, const char* what, const double lo[3] = kAround,
                     double size = 10.0)
{
  for (double x = lo[0] + 0.0071 * size; x < lo[0] + size; x += 0.0377 * size)
    for (double y = lo[1] + 0.0033 * size; y < lo[1] + size; y += 0.0411 * size)
      for (double z = lo[2] + 0.0089 * size; z < lo[2] + size; z += 0.0353 * size)
      {
        const double p[3] = { x, y, z };
        const double ha = a.evaluate(p), hb = b.evaluate(p);
        ASSERT_EQ(std::memcmp(&ha, &hb, sizeof ha), 0) << what << " at " << x << " " << y << " " << z;
      }
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

// Without a cap the tree is built a level at a time on the threads: the same cells and the same samples on
// any thread count, and as the most-oversized-first order gives them one at a time (taken when the field
// may be queried by one thread only: here a user function, not declared thread-safe, that changes no
// size).
TEST(OctreeSizing, SameTreeOnAnyThreadCountAndInEitherOrder)
{
  SizingField field = gradedFieldWithAFloor();
  ASSERT_TRUE(field.evaluatesWithWalks());
  const double* lo = kAround;
  OctreeSizing one, two, eight;
  one.build(field, lo, 10.0, 18, size_t(1) << 22, nullptr, nullptr, 1);
  two.build(field, lo, 10.0, 18, size_t(1) << 22, nullptr, nullptr, 2);
  eight.build(field, lo, 10.0, 18, size_t(1) << 22, nullptr, nullptr, 8);
  EXPECT_FALSE(one.capped());
  EXPECT_GT(one.cells(), 20000u); // levels of thousands of cells: several ranges each
  EXPECT_EQ(two.cells(), one.cells());
  EXPECT_EQ(eight.cells(), one.cells());
  expectSameSizes(one, two, "2 threads");
  expectSameSizes(one, eight, "8 threads");

  field.setUserFunction([](const double*) { return std::numeric_limits<double>::infinity(); });
  ASSERT_FALSE(field.evaluatesWithWalks());
  OctreeSizing byPriority;
  byPriority.build(field, lo, 10.0, 18, size_t(1) << 22, nullptr, nullptr, 8);
  EXPECT_FALSE(byPriority.capped());
  EXPECT_EQ(byPriority.cells(), one.cells());
  expectSameSizes(one, byPriority, "most oversized first");

  // The tree follows the field: near the fine sphere and under the floor alike.
  for (const double r : { 1.02, 2.5, 3.9 })
  {
    const double p[3] = { r, 0.0123, 0.0 };
    EXPECT_LE(one.evaluate(p), 2 * field.evaluate(p)) << "at r " << r;
    EXPECT_GE(one.evaluate(p), 0.5 * field.evaluate(p)) << "at r " << r;
  }
}

// Under a cap the order is most oversized first. Built on the threads (the level build's splits taken
// again, the rest split in batches and taken one after the other), the tree is the one-at-a-time order's
// (one thread, or a field only one thread may query). The feature's field has children that outrank the
// cells after their parent (a cell's corners miss the feature its children's corners come near).
TEST(OctreeSizing, UnderACapTheThreadsGiveTheOneAtATimeOrder)
{
  struct Case
  {
    SizingField field;
    double lo[3], size;
    size_t cap;
  };
  Case cases[2] = { { capWithOneFeature(), { 0, 0, 0 }, 1.0, 50000 },
                    { gradedFieldWithAFloor(), { -5, -5, -5 }, 10.0, 0 } };
  OctreeSizing uncapped;
  uncapped.build(cases[1].field, cases[1].lo, cases[1].size, 18, size_t(1) << 22, nullptr, nullptr, 2);
  cases[1].cap = uncapped.cells() / 2;
  for (Case& c : cases)
  {
    ASSERT_TRUE(c.field.evaluatesWithWalks());
    OctreeSizing one, two, eight, oneAtATime;
    one.build(c.field, c.lo, c.size, 18, c.cap, nullptr, nullptr, 1);
    two.build(c.field, c.lo, c.size, 18, c.cap, nullptr, nullptr, 2);
    eight.build(c.field, c.lo, c.size, 18, c.cap, nullptr, nullptr, 8);
    c.field.setUserFunction([](const double*) { return std::numeric_limits<double>::infinity(); });
    oneAtATime.build(c.field, c.lo, c.size, 18, c.cap, nullptr, nullptr, 8);
    EXPECT_TRUE(oneAtATime.capped());
    EXPECT_GT(oneAtATime.cells(), c.cap - 8);
    EXPECT_LE(oneAtATime.cells(), c.cap);
    for (const OctreeSizing* t : { &one, &two, &eight })
    {
      EXPECT_EQ(t->cells(), oneAtATime.cells());
      expectSameSizes(*t, oneAtATime, "capped", c.lo, c.size);
    }
    // Near the feature the capped tree still follows the field.
    if (&c == &cases[0])
      expectFeatureResolved(eight, c.field);
  }
}

// A build asks its progress whether to stop every 1024 splits (the octree of a 10M-tet domain takes about a
// second; a level on the threads asks as each 1024 more cells begin) and stops there when told:
// cancelled() says so, and the tree has only the cells made until then.
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
  // The root and eight children for each split made before the 2nd question: more than 1024, at most 2048.
  EXPECT_GT(stopped.cells(), 1 + 8 * 1024u);
  EXPECT_LE(stopped.cells(), 1 + 8 * 2048u);
  EXPECT_GT(whole.cells(), stopped.cells());
}
