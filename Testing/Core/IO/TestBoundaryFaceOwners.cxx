// BoundaryFaceOwners.h: each boundary triangle's owning tet and side, against a brute-force search over
// every tet face, on a meshed sphere (its triangles are faces; most tet faces touch no triangle, and the
// search skips those) with triangles that are no face added (their owner stays -1 and the call fails).
#include "BoundaryFaceOwners.h"
#include "Mesher.h"
#include "MesherTestShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

using namespace volgrid;
using volgrid::testshapes::addSphere;

namespace
{
std::array<int32_t, 3> sorted(int32_t a, int32_t b, int32_t c)
{
  std::array<int32_t, 3> k = { a, b, c };
  std::sort(k.begin(), k.end());
  return k;
}
} // namespace

TEST(BoundaryFaceOwners, SameOwnersAsABruteForceSearch)
{
  SurfaceMesh s;
  const double centre[3] = { 0, 0, 0 };
  addSphere(s, centre, 1.0, 2);
  MesherResult m;
  ASSERT_TRUE(meshSurface(s, MesherOptions(), m).ok());
  std::vector<int32_t> triangles = m.boundaryTriangles;
  const size_t faces = triangles.size() / 3;
  ASSERT_GT(m.points.size() / 3, static_cast<size_t>(m.numInputPoints)); // interior points exist
  // No faces: two boundary points with an interior point, and three boundary points not forming a face.
  triangles.insert(triangles.end(), { triangles[0], triangles[1], m.numInputPoints });
  triangles.insert(triangles.end(), { triangles[0], triangles[4], triangles[8] });
  std::vector<FaceOwner> owners;
  const Status st = findBoundaryFaceOwners(m.tets, triangles, owners);
  ASSERT_EQ(owners.size(), faces + 2);
  for (size_t t = 0; t < owners.size(); ++t)
  {
    const int32_t* v = triangles.data() + 3 * t;
    int64_t expected = -1;
    int expectedSide = -1;
    for (size_t u = 0; u < m.tets.size() / 4 && expected < 0; ++u)
      for (int side = 0; side < 4 && expected < 0; ++side)
      {
        const int* f = kExodusTetSide[side];
        const int32_t* q = m.tets.data() + 4 * u;
        if (sorted(q[f[0]], q[f[1]], q[f[2]]) == sorted(v[0], v[1], v[2]))
        {
          expected = static_cast<int64_t>(u);
          expectedSide = side;
        }
      }
    EXPECT_EQ(owners[t].tet, expected) << t;
    EXPECT_EQ(owners[t].side, expectedSide) << t;
    if (t < faces)
    {
      EXPECT_GE(owners[t].tet, 0) << t;
    }
  }
  EXPECT_FALSE(st.ok()); // the interior-point triangle at least is no face
  EXPECT_EQ(owners[faces].tet, -1);
}
