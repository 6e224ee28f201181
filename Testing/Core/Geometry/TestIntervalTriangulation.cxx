// The one ring-triangulation DP (Core/Geometry/IntervalTriangulation.h) that recovery's and the
// optimiser's edge removal share: its value against every triangulation of the polygon, its tie rule
// (the first best apex), its floor, early-stopping scores, and the two read-back orders.
#include "IntervalTriangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace
{
using namespace volgrid;
using Tri = std::array<int, 3>;

// A fixed pseudo-random score per triangle (i < k < j) of an n-gon, in [0, 1).
std::vector<double> scoreTable(int n, uint32_t seed)
{
  std::vector<double> s(static_cast<size_t>(n * n * n));
  for (double& v : s)
  {
    seed = seed * 1664525u + 1013904223u;
    v = (seed >> 8) / double(1u << 24);
  }
  return s;
}

// The best smallest score over every triangulation of the polygon i..j (brute force, Catalan many).
double bruteForce(const std::vector<double>& s, int n, int i, int j)
{
  if (j - i < 2)
    return std::numeric_limits<double>::infinity();
  double best = -std::numeric_limits<double>::infinity();
  for (int k = i + 1; k < j; ++k)
    best = std::max(best, std::min({ bruteForce(s, n, i, k), bruteForce(s, n, k, j), s[(i * n + k) * n + j] }));
  return best;
}

std::vector<Tri> readBack(const std::vector<int>& choice, int n, ChordOrder order)
{
  std::vector<Tri> out;
  forEachChosenTriangle(
    choice, n,
    [&](int i, int k, int j) {
      out.push_back({ i, k, j });
    },
    order);
  return out;
}

TEST(IntervalTriangulation, BestSmallestScoreOfEveryTriangulation)
{
  for (int n = 3; n <= 8; ++n)
    for (uint32_t seed = 1; seed <= 20; ++seed)
    {
      const std::vector<double> s = scoreTable(n, seed);
      auto score = [&](int i, int k, int j, double) { return s[(i * n + k) * n + j]; };
      std::vector<double> best;
      std::vector<int> choice;
      const double kNone = -std::numeric_limits<double>::infinity();
      ASSERT_TRUE(maxMinTriangulation(n, kNone, best, choice, score));
      EXPECT_EQ(best[n - 1], bruteForce(s, n, 0, n - 1)) << n << " " << seed;
      // The triangles read back are a triangulation reaching that value.
      const std::vector<Tri> tris = readBack(choice, n, ChordOrder::PieceAfterApexFirst);
      ASSERT_EQ(tris.size(), static_cast<size_t>(n - 2));
      double worst = std::numeric_limits<double>::infinity();
      for (const Tri& t : tris)
        worst = std::min(worst, s[(t[0] * n + t[1]) * n + t[2]]);
      EXPECT_EQ(worst, best[n - 1]);

      // A score that stops early (any value <= bound once it cannot beat it) makes the same choices.
      std::vector<double> best2;
      std::vector<int> choice2;
      auto lazy = [&](int i, int k, int j, double bound)
      {
        const double q = s[(i * n + k) * n + j];
        return q > bound ? q : bound - 1;
      };
      ASSERT_TRUE(maxMinTriangulation(n, kNone, best2, choice2, lazy));
      EXPECT_EQ(choice2, choice);
      EXPECT_EQ(best2[n - 1], best[n - 1]);
    }
}

TEST(IntervalTriangulation, TiesKeepTheFirstApexAndTheFloorMustBeBeaten)
{
  const int n = 6;
  std::vector<double> best;
  std::vector<int> choice;
  auto flat = [](int, int, int, double) { return 0.5; };
  ASSERT_TRUE(maxMinTriangulation(n, 0.0, best, choice, flat));
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j)
      EXPECT_EQ(choice[i * n + j], i + 1) << i << " " << j;
  // Equal to the floor is not better: nothing is chosen.
  EXPECT_FALSE(maxMinTriangulation(n, 0.5, best, choice, flat));
  EXPECT_EQ(choice[n - 1], -1);
  EXPECT_EQ(best[n - 1], 0.5);
  // Fewer than three vertices: no triangle.
  EXPECT_FALSE(maxMinTriangulation(2, 0.0, best, choice, flat));
}

TEST(IntervalTriangulation, ReadBackOrders)
{
  // Apex 2 on the chord (0, 5) (every other triangle on it scores lower), first apexes elsewhere.
  const int n = 6;
  auto score = [](int i, int k, int j, double) { return i == 0 && j == 5 && k != 2 ? 0.25 : 1.0; };
  std::vector<double> best;
  std::vector<int> choice;
  ASSERT_TRUE(maxMinTriangulation(n, 0.0, best, choice, score));
  ASSERT_EQ(choice[n - 1], 2);
  EXPECT_EQ(readBack(choice, n, ChordOrder::PieceAfterApexFirst),
            (std::vector<Tri>{ { 0, 2, 5 }, { 2, 3, 5 }, { 3, 4, 5 }, { 0, 1, 2 } }));
  EXPECT_EQ(readBack(choice, n, ChordOrder::PieceBeforeApexFirst),
            (std::vector<Tri>{ { 0, 2, 5 }, { 0, 1, 2 }, { 2, 3, 5 }, { 3, 4, 5 } }));
}

} // namespace
