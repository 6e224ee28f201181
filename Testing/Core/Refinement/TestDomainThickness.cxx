// The domain's depth at its boundary points (DomainThickness.h), on the Delaunay mesh of a jittered grid
// filling the slab [0, 8] x [0, 8] x [0, 2]: from the middle of its large faces the inward ray crosses
// the slab (2); from a corner it runs along the inward diagonal.
#include "Delaunay.h"
#include "DomainThickness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace volgrid;

TEST(DomainThickness, IsTheDepthAlongTheInwardDirection)
{
  std::vector<double> xyz;
  uint64_t state = 7;
  auto jitter = [&]()
  {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 0.1;
  };
  auto on = [](int i, int n) { return i == 0 || i == n; };
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j)
      for (int k = 0; k <= 4; ++k)
      {
        // Boundary points stay on the slab's faces (jittered within them), interior ones anywhere.
        const double x = 0.5 * i + (on(i, 16) ? 0 : jitter());
        const double y = 0.5 * j + (on(j, 16) ? 0 : jitter());
        const double z = 0.5 * k + (on(k, 4) ? 0 : jitter());
        xyz.insert(xyz.end(), { x, y, z });
      }
  TetMesh mesh;
  std::vector<int32_t> ids;
  DelaunayOptions options;
  ASSERT_TRUE(buildDelaunay(xyz.data(), xyz.size() / 3, options, mesh, ids).ok());
  mesh.removeGhostTets();
  const std::vector<double> depth = inwardThickness(mesh, mesh.numVertices());
  auto id = [](int i, int j, int k) { return (i * 17 + j) * 5 + k; };
  // The middle of the bottom and top faces: across the slab.
  EXPECT_NEAR(depth[id(8, 8, 0)], 2.0, 0.2);
  EXPECT_NEAR(depth[id(8, 8, 4)], 2.0, 0.2);
  // The middle of a side face: along x, the slab is 8 wide there.
  EXPECT_GT(depth[id(0, 8, 2)], 6.0);
  // A corner: into the slab, at most through to the far side along a diagonal-ish direction (> 2) and
  // never longer than the slab's diagonal.
  EXPECT_GT(depth[id(0, 0, 0)], 2.0);
  EXPECT_LT(depth[id(0, 0, 0)], std::sqrt(8.0 * 8 + 8 * 8 + 2 * 2) + 1e-9);
  // An interior point has a ray that leaves the slab too, but no boundary question; every value is finite.
  for (double d : depth)
    EXPECT_TRUE(std::isfinite(d) && d >= 0);
}
