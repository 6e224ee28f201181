// After a split of the bad tets, the tets it left alone and the tets it reports as created hold every tet
// still under the target: the quality stage takes its next worklist from them instead of sweeping the mesh
// (QualityRounds::splitBelow), so they must give exactly what a sweep gives.
#include "BadTetSplitting.h"
#include "Mesh/RandomDelaunay.h"
#include "MeshScan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace volgrid;

namespace
{
std::vector<std::pair<double, int32_t>> sortedSweep(const TetMesh& mesh, double q)
{
  std::vector<std::pair<double, int32_t>> out;
  collectSineBelow(mesh, q, 1, out);
  std::sort(out.begin(), out.end());
  return out;
}
} // namespace

TEST(BadTetSplitting, TheTetsLeftAndTheTetsCreatedGiveWhatASweepGives)
{
  TetMesh mesh;
  randomDelaunay(mesh, 2500, 21); // slivers: hundreds of tets under 20 degrees
  const double degrees = 20;
  const double q = std::sin(degrees * 3.14159265358979323846 / 180.0);
  std::vector<std::pair<double, int32_t>> below = sortedSweep(mesh, q);
  ASSERT_GT(below.size(), 100u);

  std::vector<int32_t> created;
  SplitRequest request;
  request.degrees = degrees;
  request.maxPoints = 60; // some of the bad tets: the rest must come back from `below`
  request.below = &below;
  request.created = &created;
  const int64_t inserted = splitBadTets(mesh, nullptr, nullptr, request);
  ASSERT_GT(inserted, 10);
  EXPECT_GE(created.size(), static_cast<size_t>(4 * inserted)); // at least four new tets per point

  std::vector<int32_t> candidates = created;
  for (const auto& b : below)
    candidates.push_back(b.second);
  std::vector<std::pair<double, int32_t>> among;
  collectSineBelowAmong(mesh, q, candidates, among);
  EXPECT_EQ(among, sortedSweep(mesh, q));
  // Without the created tets the list misses some (the splits do make tets under the target), so the
  // comparison above depends on them.
  std::vector<int32_t> leftOnly;
  for (const auto& b : below)
    leftOnly.push_back(b.second);
  std::vector<std::pair<double, int32_t>> partial;
  collectSineBelowAmong(mesh, q, leftOnly, partial);
  EXPECT_LT(partial.size(), among.size());
}
