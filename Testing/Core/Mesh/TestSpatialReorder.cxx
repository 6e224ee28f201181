// The spatial renumbering (SpatialReorder.h) must give the same mesh under new numbers: the same tets as
// point quadruples in the same orientation, valid adjacency, the vertices before firstVertex unchanged,
// per-tet and per-vertex arrays carried over, the same result on every call, and memory order that
// follows space.
#include "Delaunay.h"
#include "MeshChecker.h"
#include "SpatialReorder.h"
#include "SpatialSort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace volgrid;

namespace
{

TetMesh scatteredMesh(size_t n, uint64_t seed)
{
  SplitMix64 rng(seed);
  std::vector<double> xyz(3 * n);
  for (double& x : xyz)
    x = static_cast<double>(rng.next() >> 11) * 0x1p-53;
  TetMesh mesh;
  std::vector<int32_t> map;
  DelaunayOptions opt;
  opt.keepGhosts = false;
  EXPECT_TRUE(buildDelaunay(xyz.data(), n, opt, mesh, map).ok());
  // Free a few slots, as insertions leave them, so that compaction is exercised too.
  std::vector<int32_t> freed;
  mesh.forEachTet(
    [&](int32_t t)
    {
      bool boundary = false;
      for (int i = 0; i < 4; ++i)
        boundary |= mesh.neighbor(t, i) < 0;
      if (boundary && freed.size() < 40 && t % 7 == 0)
        freed.push_back(t);
    });
  for (int32_t t : freed)
  {
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = mesh.neighbor(t, i);
      if (u >= 0)
        mesh.unlink(u, mesh.mirrorFace(t, i));
    }
    mesh.freeTet(t);
  }
  return mesh;
}

using Quad = std::array<std::array<double, 3>, 4>;

// Every live tet as its four points in its vertex order, sorted: the mesh without its numbers.
std::vector<Quad> geometry(const TetMesh& mesh)
{
  std::vector<Quad> out;
  mesh.forEachTet(
    [&](int32_t t)
    {
      Quad q;
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k)
          q[i][k] = mesh.point(mesh.vertex(t, i))[k];
      out.push_back(q);
    });
  std::sort(out.begin(), out.end());
  return out;
}

// The mean distance between the centroids of consecutive tet slots.
double meanStep(const TetMesh& mesh)
{
  double sum = 0, prev[3] = { 0, 0, 0 };
  int64_t n = 0;
  mesh.forEachTet(
    [&](int32_t t)
    {
      double c[3] = { 0, 0, 0 };
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k)
          c[k] += mesh.point(mesh.vertex(t, i))[k] / 4;
      if (n++ > 0)
        sum += std::sqrt((c[0] - prev[0]) * (c[0] - prev[0]) + (c[1] - prev[1]) * (c[1] - prev[1]) +
                         (c[2] - prev[2]) * (c[2] - prev[2]));
      std::copy(c, c + 3, prev);
    });
  return sum / static_cast<double>(n - 1);
}

} // namespace

TEST(SpatialReorder, SameMeshUnderNewNumbers)
{
  TetMesh mesh = scatteredMesh(4000, 3);
  const std::vector<Quad> before = geometry(mesh);
  const int32_t live = mesh.numTets();
  ASSERT_GT(mesh.numFreeTets(), 0);
  const TetMesh original = mesh;
  MeshCheckOptions opt;
  opt.delaunay = false;
  opt.euler = false;
  const MeshCheckReport was = checkMesh(original, opt);
  std::vector<int32_t> perTet(static_cast<size_t>(mesh.tetCapacity()));
  for (size_t t = 0; t < perTet.size(); ++t)
    perTet[t] = static_cast<int32_t>(t);
  std::vector<uint8_t> perVertex(static_cast<size_t>(mesh.numVertices()), 0);
  perVertex[3000] = 1; // a vertex past firstVertex

  const int32_t firstVertex = 1000;
  const SpatialRenumbering r = reorderSpatially(mesh, firstVertex);
  EXPECT_EQ(geometry(mesh), before);
  EXPECT_EQ(mesh.numTets(), live);
  EXPECT_EQ(mesh.numFreeTets(), 0);
  const MeshCheckReport is = checkMesh(mesh, opt);
  EXPECT_EQ(is.valid, was.valid);
  EXPECT_EQ(is.badVertices + is.invertedTets + is.badNeighbors + is.asymmetricNeighbors + is.faceMismatches, 0);
  EXPECT_EQ(is.finiteTets, was.finiteTets);
  for (int32_t v = 0; v < firstVertex; ++v)
  {
    EXPECT_EQ(r.vertexOldToNew[v], v);
    EXPECT_TRUE(std::equal(mesh.point(v), mesh.point(v) + 3, original.point(v)));
  }
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    EXPECT_TRUE(std::equal(mesh.point(r.vertexOldToNew[v]), mesh.point(r.vertexOldToNew[v]) + 3, original.point(v)));

  renumberTetArray(r, perTet, -1);
  renumberVertexArray(r, perVertex, uint8_t{ 0 });
  ASSERT_EQ(perTet.size(), static_cast<size_t>(mesh.tetCapacity()));
  for (int32_t t = 0; t < original.tetCapacity(); ++t)
    if (!original.isFree(t))
    {
      const int32_t n = r.tetOldToNew[t];
      ASSERT_GE(n, 0);
      EXPECT_EQ(perTet[n], t);
      for (int i = 0; i < 4; ++i)
        EXPECT_EQ(mesh.vertex(n, i), r.vertexOldToNew[original.vertex(t, i)]);
    }
  EXPECT_EQ(perVertex[r.vertexOldToNew[3000]], 1);
  EXPECT_EQ(std::count(perVertex.begin(), perVertex.end(), 1), 1);
}

TEST(SpatialReorder, DeterministicAndLocal)
{
  TetMesh a = scatteredMesh(6000, 5);
  TetMesh b = a;
  const double stepBefore = meanStep(a);
  reorderSpatially(a, 0);
  reorderSpatially(b, 0);
  EXPECT_EQ(a.tetVertices, b.tetVertices);
  EXPECT_EQ(a.tetNeighbors, b.tetNeighbors);
  EXPECT_EQ(a.points, b.points);
  // Consecutive slots are neighbours in space: the mean step between their centroids shrinks well below
  // that of the kernel's order (canonical, by vertex number of random points).
  EXPECT_LT(meanStep(a), 0.5 * stepBefore);
}

TEST(SpatialReorder, GhostMeshLeftAlone)
{
  SplitMix64 rng(9);
  std::vector<double> xyz(300);
  for (double& x : xyz)
    x = static_cast<double>(rng.next() >> 11) * 0x1p-53;
  TetMesh mesh;
  std::vector<int32_t> map;
  ASSERT_TRUE(buildDelaunay(xyz.data(), 100, DelaunayOptions(), mesh, map).ok());
  ASSERT_GT(mesh.numGhostTets(), 0);
  const TetMesh copy = mesh;
  const SpatialRenumbering r = reorderSpatially(mesh, 0);
  EXPECT_TRUE(r.vertexOldToNew.empty());
  EXPECT_EQ(mesh.tetVertices, copy.tetVertices);
}

// On several threads (counting sort of the tets, arrays permuted in parallel) the renumbering is the one
// thread's, array for array.
TEST(SpatialReorder, SameOnAnyThreadCount)
{
  TetMesh one = scatteredMesh(30000, 11);
  TetMesh four = one;
  const SpatialRenumbering r1 = reorderSpatially(one, 100, 1);
  const SpatialRenumbering r4 = reorderSpatially(four, 100, 4);
  EXPECT_EQ(r1.vertexOldToNew, r4.vertexOldToNew);
  EXPECT_EQ(r1.tetOldToNew, r4.tetOldToNew);
  EXPECT_EQ(one.points, four.points);
  EXPECT_EQ(one.tetVertices, four.tetVertices);
  EXPECT_EQ(one.tetNeighbors, four.tetNeighbors);
  EXPECT_EQ(one.tetFlags, four.tetFlags);
}
