// The cavity search both mesh editors share (Core/Mesh/ConflictCavity.h): on a Delaunay mesh the grown
// cavity is exactly the set of tets whose circumsphere holds the point, and a cavity grown past that is
// shrunk to a connected, strictly star-shaped part holding the tets that must stay (or refused).
#include "ConflictCavity.h"
#include "Delaunay.h"
#include "Predicates.h"
#include "RandomDelaunay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

using namespace volgrid;

namespace
{
// Hull faces stop growth and bound the cavity; `all` makes every tet a conflict (a blob, not a cavity).
struct TestRule
{
  const TetMesh& mesh;
  const double* p;
  bool all = false;
  bool keepAll = false;
  static constexpr bool kBlocksAreWalls = true;
  bool wall(int32_t t, int i) const { return mesh.neighbor(t, i) < 0; }
  bool blocks(int32_t t, int i) const { return wall(t, i); }
  bool conflicts(int32_t u) const
  {
    const int32_t* w = mesh.vertices(u);
    return all || predicates::insphere(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]), p) > 0;
  }
  int side(int32_t t, int i) const
  {
    int32_t f[3];
    mesh.faceVertices(t, i, f);
    return predicates::orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), p);
  }
  bool mustKeep(int32_t t) const
  {
    if (keepAll)
      return true;
    for (int i = 0; i < 4; ++i)
      if (side(t, i) < 0)
        return false;
    return true;
  }
};

int32_t containing(const TetMesh& mesh, const TestRule& rule)
{
  for (int32_t t = 0; t < mesh.tetCapacity(); ++t)
    if (!mesh.isFree(t) && rule.mustKeep(t))
      return t;
  return -1;
}

class MeshConflictCavity : public ::testing::Test
{
protected:
  void SetUp() override { randomDelaunay(mesh, 400, 11); }
  TetMesh mesh;
  MeshNavigator nav{ mesh, MeshNavigator::StaleEntries::Trust };
  ConflictCavity cavity{ nav };
};
} // namespace

TEST_F(MeshConflictCavity, DelaunayCavityIsTheConflictSet)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  for (int trial = 0; trial < 50; ++trial)
  {
    const double p[3] = { u(rng), u(rng), u(rng) };
    TestRule rule{ mesh, p };
    const int32_t t0 = containing(mesh, rule);
    ASSERT_GE(t0, 0);
    cavity.start(&t0, 1);
    cavity.grow(rule, SIZE_MAX);
    std::set<int32_t> expected;
    for (int32_t t = 0; t < mesh.tetCapacity(); ++t)
      if (!mesh.isFree(t) && rule.conflicts(t))
        expected.insert(t);
    EXPECT_EQ(std::set<int32_t>(cavity.tets.begin(), cavity.tets.end()), expected);
    ASSERT_TRUE(cavity.shrinkToStar(p, rule, &t0, 1, 64));
    EXPECT_EQ(cavity.tets.size(), expected.size()); // a Delaunay cavity is star-shaped already
    size_t faces = 0, expectedFaces = 0;
    EXPECT_TRUE(cavity.forBoundaryFaces(rule,
                                        [&](int32_t t, int i)
                                        {
                                          ++faces;
                                          return rule.side(t, i) > 0;
                                        }));
    for (int32_t t : expected)
      for (int i = 0; i < 4; ++i)
        expectedFaces += mesh.neighbor(t, i) < 0 || !expected.count(mesh.neighbor(t, i));
    EXPECT_EQ(faces, expectedFaces);
    cavity.release();
    EXPECT_FALSE(cavity.contains(t0));
  }
}

TEST_F(MeshConflictCavity, ShrinksABlobToAStarShapedCavity)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.3, 0.7);
  int shrunk = 0, refused = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    const double p[3] = { u(rng), u(rng), u(rng) };
    TestRule rule{ mesh, p, true };
    const int32_t t0 = containing(mesh, rule);
    ASSERT_GE(t0, 0);
    cavity.start(&t0, 1);
    cavity.grow(rule, 60);
    const std::set<int32_t> blob(cavity.tets.begin(), cavity.tets.end());
    ASSERT_GE(blob.size(), 60u);
    // Every tet must stay: refused unless the blob happens to be star-shaped.
    rule.keepAll = true;
    const bool kept = cavity.shrinkToStar(p, rule, &t0, 1, 1000);
    if (!kept)
    {
      ++refused;
      for (int32_t t : blob)
        EXPECT_FALSE(cavity.contains(t));
    }
    // Only the tets holding p must stay: a star-shaped part containing t0 is left.
    rule.keepAll = false;
    cavity.start(std::vector<int32_t>(blob.begin(), blob.end()).data(), blob.size());
    ASSERT_TRUE(cavity.shrinkToStar(p, rule, &t0, 1, 1000));
    shrunk += cavity.tets.size() < blob.size();
    EXPECT_TRUE(cavity.contains(t0));
    for (int32_t t : cavity.tets)
      EXPECT_TRUE(blob.count(t));
    EXPECT_TRUE(cavity.forBoundaryFaces(rule, [&](int32_t t, int i) { return rule.side(t, i) > 0; }));
    cavity.release();
  }
  EXPECT_GT(shrunk, 0);
  EXPECT_GT(refused, 0);
}
