// The mesh checker must accept valid meshes and find each kind of deliberate damage.
#include "Delaunay.h"
#include "MeshChecker.h"
#include "SpatialSort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

using namespace volgrid;

namespace
{

TetMesh delaunayOf(const std::vector<double>& xyz, bool ghosts = true)
{
  TetMesh mesh;
  std::vector<int32_t> map;
  DelaunayOptions opt;
  opt.keepGhosts = ghosts;
  EXPECT_TRUE(buildDelaunay(xyz.data(), xyz.size() / 3, opt, mesh, map).ok());
  return mesh;
}

std::vector<double> randomPoints(size_t n, uint64_t seed)
{
  SplitMix64 rng(seed);
  std::vector<double> xyz(3 * n);
  for (double& x : xyz)
    x = static_cast<double>(rng.next() >> 11) * 0x1p-53;
  return xyz;
}

int32_t someInteriorTet(const TetMesh& mesh)
{
  int32_t found = -1;
  mesh.forEachFiniteTet(
    [&](int32_t t)
    {
      if (found >= 0)
        return;
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = mesh.neighbor(t, i);
        if (u < 0 || mesh.isGhost(u))
          return;
      }
      found = t;
    });
  return found;
}

// Two tets glued on triangle abc, apexes d above and e below; closed boundary without ghosts.
TetMesh twoTets(double apexHeight)
{
  TetMesh mesh;
  const double pts[5][3] = {
    { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, apexHeight }, { 0.3, 0.3, -apexHeight }
  };
  for (const auto& p : pts)
    mesh.addPoint(p);
  const int32_t t = mesh.newTet(0, 1, 2, 3); // positive: 3 above the ccw triangle 012
  const int32_t u = mesh.newTet(1, 0, 2, 4); // positive: 4 below
  mesh.link(t, 3, u, 3);
  return mesh;
}

} // namespace

TEST(MeshChecker, AcceptsDelaunayMeshesWithAndWithoutGhosts)
{
  const auto xyz = randomPoints(2000, 1);
  for (bool ghosts : { true, false })
  {
    const TetMesh mesh = delaunayOf(xyz, ghosts);
    const MeshCheckReport r = checkMesh(mesh);
    EXPECT_TRUE(r.valid) << r.summary();
    EXPECT_TRUE(r.eulerOk);
    EXPECT_EQ(r.finiteTets, mesh.numFiniteTets());
    EXPECT_EQ(r.ghostTets, ghosts ? r.hullFaces : 0);
    EXPECT_TRUE(r.firstBadTets.empty());
  }
}

TEST(MeshChecker, DetectsAnInvertedTet)
{
  TetMesh mesh = delaunayOf(randomPoints(500, 2));
  const int32_t t = someInteriorTet(mesh);
  ASSERT_GE(t, 0);
  int32_t* v = mesh.tetVertices.data() + 4 * t;
  std::swap(v[0], v[1]);
  const MeshCheckReport r = checkMesh(mesh);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.invertedTets, 1);
  EXPECT_GT(r.faceMismatches, 0); // the shared faces now have the wrong orientation
  ASSERT_FALSE(r.firstBadTets.empty());
  EXPECT_NE(std::find(r.firstBadTets.begin(), r.firstBadTets.end(), t), r.firstBadTets.end());
}

TEST(MeshChecker, DetectsBrokenAdjacency)
{
  TetMesh mesh = delaunayOf(randomPoints(500, 3));
  const int32_t t = someInteriorTet(mesh);
  ASSERT_GE(t, 0);
  // Point face 0 at face 0 of another tet (which does not point back).
  int32_t other = (t + 7) % mesh.tetCapacity();
  mesh.tetNeighbors[4 * t] = TetMesh::encode(other, 0);
  MeshCheckReport r = checkMesh(mesh);
  EXPECT_FALSE(r.valid);
  EXPECT_GT(r.asymmetricNeighbors, 0);

  TetMesh mesh2 = delaunayOf(randomPoints(500, 3));
  // Symmetric but geometrically wrong: swap the neighbours of two faces of one tet.
  const int32_t c0 = mesh2.neighborCode(t, 0), c1 = mesh2.neighborCode(t, 1);
  mesh2.link(t, 0, c1 >> 2, c1 & 3);
  mesh2.link(t, 1, c0 >> 2, c0 & 3);
  r = checkMesh(mesh2);
  EXPECT_FALSE(r.valid);
  EXPECT_GT(r.faceMismatches, 0);

  TetMesh mesh3 = delaunayOf(randomPoints(500, 3));
  mesh3.tetNeighbors[4 * t + 2] = TetMesh::kNoNeighbor; // open face while ghosts are present
  r = checkMesh(mesh3);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.openFaces, 1);

  TetMesh mesh4 = delaunayOf(randomPoints(500, 3));
  mesh4.tetVertices[4 * t + 1] = mesh4.numVertices() + 5; // out of range
  r = checkMesh(mesh4);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.badVertices, 1);
}

TEST(MeshChecker, DetectsANonDelaunayFace)
{
  // Flat apexes: each apex is inside the other tet's (huge) circumsphere.
  MeshCheckReport r = checkMesh(twoTets(0.1));
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.nonDelaunayFaces, 1);
  EXPECT_EQ(r.invertedTets + r.faceMismatches + r.asymmetricNeighbors + r.hullErrors, 0) << r.summary();
  // Tall apexes: Delaunay, and the 6 faces without neighbour form a closed surface.
  r = checkMesh(twoTets(2.0));
  EXPECT_TRUE(r.valid) << r.summary();
  EXPECT_EQ(r.hullFaces, 6);
}

TEST(MeshChecker, DetectsAnOpenHullWithoutGhosts)
{
  TetMesh mesh = delaunayOf(randomPoints(300, 4), false);
  const int32_t t = someInteriorTet(mesh);
  ASSERT_GE(t, 0);
  mesh.tetNeighbors[4 * t] = TetMesh::kNoNeighbor; // one-sided: asymmetric, and a hull face that is open
  const MeshCheckReport r = checkMesh(mesh);
  EXPECT_FALSE(r.valid);
  EXPECT_GT(r.hullErrors, 0);
  EXPECT_GT(r.asymmetricNeighbors, 0);
}

TEST(MeshChecker, DetectsANonConvexHull)
{
  // Cube corners and centre: the hull faces come in coplanar pairs. Push the far vertex of one pair
  // slightly outwards: the hull edge between the two triangles becomes reflex.
  std::vector<double> xyz;
  for (int i = 0; i < 8; ++i)
    xyz.insert(xyz.end(), { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  xyz.insert(xyz.end(), { 0.5, 0.5, 0.5 });
  TetMesh mesh = delaunayOf(xyz);
  ASSERT_TRUE(checkMesh(mesh).valid);
  int32_t moved = -1;
  int axis = -1;
  double value = 0;
  mesh.forEachTet(
    [&](int32_t g)
    {
      const int k = mesh.ghostIndex(g);
      if (moved >= 0 || k < 0)
        return;
      int32_t f[3];
      mesh.faceVertices(g, k, f);
      for (int a = 0; a < 3 && axis < 0; ++a)
        if (mesh.point(f[0])[a] == mesh.point(f[1])[a] && mesh.point(f[1])[a] == mesh.point(f[2])[a])
        {
          axis = a;
          value = mesh.point(f[0])[a];
        }
      for (int i = 0; i < 4 && moved < 0; ++i)
      {
        if (i == k)
          continue;
        const int32_t h = mesh.neighbor(g, i);
        const int32_t x = mesh.vertex(h, mesh.mirrorFace(g, i));
        if (mesh.point(x)[axis] == value)
          moved = x; // coplanar neighbour hull face
      }
    });
  ASSERT_GE(moved, 0);
  mesh.points[3 * moved + axis] += value == 0 ? -0.01 : 0.01;
  const MeshCheckReport r = checkMesh(mesh);
  EXPECT_FALSE(r.valid);
  EXPECT_GT(r.nonConvexHullEdges, 0) << r.summary();
  EXPECT_EQ(r.invertedTets, 0);
}

TEST(MeshChecker, DetectsBadEulerCharacteristic)
{
  // Two disjoint tets: each is valid locally but the complex is not a ball (V-E+F-T = 2).
  TetMesh mesh;
  const double pts[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
                             { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 }, { 5, 0, 1 } };
  for (const auto& p : pts)
    mesh.addPoint(p);
  mesh.newTet(0, 1, 2, 3);
  mesh.newTet(4, 5, 6, 7);
  const MeshCheckReport r = checkMesh(mesh);
  EXPECT_FALSE(r.valid);
  EXPECT_FALSE(r.eulerOk);
  EXPECT_GT(r.hullErrors, 0); // the hull has two components: Euler characteristic 4
}
