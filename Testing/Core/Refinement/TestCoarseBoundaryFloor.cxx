// The floor that a size cap meets next to coarse boundary triangles (CoarseBoundaryFloor.h): the boundary's
// spacing, shrinking away from it at the gradation's rate, the largest cone winning.
#include "CoarseBoundaryFloor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

using namespace volgrid;

namespace
{
// Boundary nodes on the plane z = 0 over [0, 10]^2 (spacing 0.5, jittered so that no five nodes are
// cospherical): size `coarse` for x < 5, `fine` for x >= 5; then a jittered lattice of unsized nodes over
// [0, 10]^2 x (0, 10].
struct Nodes
{
  std::vector<double> xyz, size;
  size_t boundary = 0;
};

Nodes planeAndLattice(double coarse, double fine)
{
  Nodes n;
  uint64_t state = 12345;
  auto jitter = [&]()
  {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 0.05;
  };
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
    {
      n.xyz.insert(n.xyz.end(), { 0.5 * i + jitter(), 0.5 * j + jitter(), 1e-3 * jitter() });
      n.size.push_back(0.5 * i < 5 ? coarse : fine);
    }
  n.boundary = n.size.size();
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int k = 1; k <= 10; ++k)
        n.xyz.insert(n.xyz.end(), { 1.0 * i + jitter(), 1.0 * j + jitter(), 1.0 * k + jitter() });
  return n;
}
} // namespace

TEST(CoarseBoundaryFloor, IsTheBoundarySpacingShrinkingAtTheGradationRate)
{
  const double coarse = 4, fine = 0.25, slope = 0.5;
  const Nodes n = planeAndLattice(coarse, fine);
  CoarseBoundaryFloor floor;
  ASSERT_TRUE(floor.build(n.xyz.data(), n.size.data(), n.boundary, n.xyz.size() / 3, slope).ok());
  EXPECT_EQ(floor.largestBoundarySize(), coarse);
  // The floor at distance d from the nearest coarse node is 4 - 0.5 d, but along graph paths, which are up
  // to a fifth longer than straight lines, and linear between nodes: between 4 - 0.5 * 1.2 d and 4 - 0.5 d
  // (0.1 of slack for the interpolation), and 0 where that reaches 0.
  auto expectCone = [&](double x, double z, double d)
  {
    const double p[3] = { x, 5.0, z };
    const double h = floor.evaluate(p);
    EXPECT_LE(h, std::max(0.0, coarse - slope * d) + 0.1) << "x " << x << " z " << z;
    EXPECT_GE(h, std::max(0.0, coarse - slope * 1.2 * d) - 0.1) << "x " << x << " z " << z;
  };
  // Over the coarse half (x = 2.5), going up: 4 at the plane, 0 from z = 8 on.
  for (double z = 0; z <= 10; z += 0.5)
    expectCone(2.5, z, z);
  // Over the fine half, 5 from the last coarse nodes (x = 4.5): the largest cone is the coarse half's,
  // not the fine boundary's own 0.25.
  for (double z : { 0.0, 1.0, 2.0 })
    expectCone(9.5, z, std::sqrt(25 + z * z));
  const double p[3] = { 9.5, 5.0, 0.0 };
  EXPECT_GT(floor.evaluate(p), 2 * fine);
}

TEST(CoarseBoundaryFloor, IsZeroBeforeBuildAndWithoutBoundaryNodes)
{
  CoarseBoundaryFloor floor;
  const double p[3] = { 1, 2, 3 };
  EXPECT_EQ(floor.evaluate(p), 0.0);
  const Nodes n = planeAndLattice(1, 1);
  ASSERT_TRUE(floor.build(n.xyz.data(), n.size.data(), 0, n.xyz.size() / 3, 0.5).ok());
  EXPECT_EQ(floor.largestBoundarySize(), 0.0);
  EXPECT_EQ(floor.evaluate(p), 0.0);
}
