// SizeRatio.h: the size ratio between face-neighbouring tets (size = mean edge length).
#include "SizeRatio.h"

#include "BoundaryCheck.h"
#include "Mesh/RandomDelaunay.h"
#include "MeshImprovement.h"
#include "TetMesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace volgrid;

namespace
{
// Two tets on the face (0, 1, 2) of the unit right corner: apex 3 at z = 1 above, apex 4 at z = -a below.
double meanEdgeBelow(double a)
{
  const double s2 = std::sqrt(2.0), s = std::sqrt(1 + a * a);
  return (1 + 1 + s2 + a + s + s) / 6;
}
} // namespace

TEST(SizeRatio, TwoTetsShareOneFace)
{
  const double a = 3;
  const std::vector<double> p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -a };
  const std::vector<int32_t> t = { 0, 1, 2, 3, 0, 2, 1, 4 };
  const SizeRatioSummary s = summarizeSizeRatios(p.data(), t.data(), 2, 1.5);
  const double above = (3 + 3 * std::sqrt(2.0)) / 6;
  const double expected = meanEdgeBelow(a) / above;
  EXPECT_EQ(s.faces, 1); // the six other faces are on the boundary
  EXPECT_NEAR(s.max, expected, 1e-6 * expected);
  EXPECT_NEAR(s.p99, expected, 1e-6 * expected);
  EXPECT_NEAR(s.median, expected, 1e-6 * expected);
  EXPECT_EQ(s.aboveThreshold, expected > 1.5 ? 1 : 0);
  EXPECT_EQ(summarizeSizeRatios(p.data(), t.data(), 2, 3.0).aboveThreshold, expected > 3.0 ? 1 : 0);
}

TEST(SizeRatio, EqualTetsGiveOne)
{
  // Mirror images through the shared face z = 0: same size, ratio 1.
  const std::vector<double> p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1 };
  const std::vector<int32_t> t = { 0, 1, 2, 3, 0, 2, 1, 4 };
  const SizeRatioSummary s = summarizeSizeRatios(p.data(), t.data(), 2, 1.0);
  EXPECT_EQ(s.faces, 1);
  EXPECT_DOUBLE_EQ(s.max, 1.0);
  EXPECT_EQ(s.aboveThreshold, 0);
}

TEST(SizeRatio, NoInteriorFace)
{
  const std::vector<double> p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const std::vector<int32_t> t = { 0, 1, 2, 3 };
  const SizeRatioSummary s = summarizeSizeRatios(p.data(), t.data(), 1, 1.5);
  EXPECT_EQ(s.faces, 0);
  EXPECT_EQ(s.p99, 1.0);
  EXPECT_EQ(s.max, 1.0);
}

TEST(SizeRatio, MeshWithAdjacencyGivesTheSameFigures)
{
  // Three tets in a fan around the z axis edge (0, 3), plus one below: four interior faces.
  const std::vector<double> p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, -0.2, 0, 0.3, 0.2, -2 };
  const std::vector<int32_t> t = { 0, 1, 2, 3, 0, 2, 4, 3, 0, 4, 1, 3, 0, 2, 1, 5 };
  TetMesh mesh;
  ASSERT_TRUE(tetMeshFromTets(p, t, mesh).ok());
  const SizeRatioSummary flat = summarizeSizeRatios(p.data(), t.data(), 4, 1.2);
  const SizeRatioSummary adj = summarizeSizeRatios(mesh, 1.2);
  EXPECT_EQ(flat.faces, 4);
  EXPECT_EQ(adj.faces, flat.faces);
  EXPECT_EQ(adj.p99, flat.p99);
  EXPECT_EQ(adj.max, flat.max);
  EXPECT_EQ(adj.median, flat.median);
  EXPECT_EQ(adj.aboveThreshold, flat.aboveThreshold);
}

TEST(SizeRatio, SameFiguresOnAnyThreadCountAndAsTheMeshWithAdjacency)
{
  // 20,000 random points: about 130,000 tets, so that 2 and 8 threads cut both loops into ranges.
  TetMesh mesh;
  randomDelaunay(mesh, 20000, 5);
  std::vector<int32_t> t = flatTets(mesh);
  ASSERT_GT(t.size() / 4, 100000u);
  const SizeRatioSummary adj = summarizeSizeRatios(mesh, 1.5);
  ASSERT_GT(adj.aboveThreshold, 0);
  for (int threads : { 1, 2, 8 })
  {
    const SizeRatioSummary s = summarizeSizeRatios(mesh.points.data(), t.data(), t.size() / 4, 1.5, threads);
    EXPECT_EQ(s.faces, adj.faces) << threads;
    EXPECT_EQ(s.median, adj.median) << threads;
    EXPECT_EQ(s.p99, adj.p99) << threads;
    EXPECT_EQ(s.max, adj.max) << threads;
    EXPECT_EQ(s.aboveThreshold, adj.aboveThreshold) << threads;
    // From the boundary check's shared faces (the CLI's way): no matching of its own, the same figures.
    std::vector<std::pair<int32_t, int32_t>> shared;
    checkBoundaryConformity(mesh.points, 0, t, {}, 1.0, &shared, threads);
    const SizeRatioSummary fromPairs =
      summarizeSizeRatios(mesh.points.data(), t.data(), t.size() / 4, shared, 1.5, threads);
    EXPECT_EQ(fromPairs.faces, adj.faces) << threads;
    EXPECT_EQ(fromPairs.median, adj.median) << threads;
    EXPECT_EQ(fromPairs.p99, adj.p99) << threads;
    EXPECT_EQ(fromPairs.max, adj.max) << threads;
    EXPECT_EQ(fromPairs.aboveThreshold, adj.aboveThreshold) << threads;
  }
}
