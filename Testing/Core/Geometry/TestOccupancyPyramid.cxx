// The pyramid must never call a box empty when an added box overlaps it (the sizing octree would leave a
// part of the domain coarse), and must call boxes well away from every added box empty (or it saves
// nothing).
#include "OccupancyPyramid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

using namespace volgrid;

namespace
{
struct Box
{
  std::array<double, 3> lo, hi;
};

bool overlap(const Box& a, const Box& b)
{
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k])
      return false;
  return true;
}

Box clipped(Box b) // to the cube [-0.1, 1.1]^3
{
  for (int k = 0; k < 3; ++k)
  {
    b.lo[k] = std::max(b.lo[k], -0.1);
    b.hi[k] = std::min(b.hi[k], 1.1);
  }
  return b;
}

double gap(const Box& a, const Box& b) // the largest separation along an axis
{
  double g = 0;
  for (int k = 0; k < 3; ++k)
    g = std::max({ g, b.lo[k] - a.hi[k], a.lo[k] - b.hi[k] });
  return g;
}

double extent(const Box& a)
{
  return std::max({ a.hi[0] - a.lo[0], a.hi[1] - a.lo[1], a.hi[2] - a.lo[2] });
}

Box randomBox(std::mt19937& rng, double lo, double hi, double maxSize)
{
  std::uniform_real_distribution<double> at(lo, hi), size(0, maxSize);
  Box b;
  for (int k = 0; k < 3; ++k)
  {
    b.lo[k] = at(rng);
    b.hi[k] = b.lo[k] + size(rng);
  }
  return b;
}
} // namespace

// Boxes of every size, from points to a fifth of the cube, some reaching out of it (the parts out of it
// are not marked).
TEST(OccupancyPyramid, NeverMissesAnOverlapAndSeesTheGaps)
{
  std::mt19937 rng(7);
  std::vector<Box> boxes;
  for (int i = 0; i < 300; ++i)
  {
    boxes.push_back(randomBox(rng, -0.1, 1.0, i % 3 == 0 ? 0.0 : (i % 3 == 1 ? 0.01 : 0.2)));
    boxes.back().lo[0] *= 0.4; // all in x < 0.5, so that the rest of the cube is empty
    boxes.back().hi[0] = boxes.back().lo[0] + (boxes.back().hi[0] - boxes.back().lo[0]) * 0.4;
  }
  OccupancyPyramid pyramid;
  const double lo[3] = { -0.1, -0.1, -0.1 };
  pyramid.reset(lo, 1.2, 7);
  for (const Box& b : boxes)
    pyramid.addBox(b.lo.data(), b.hi.data());

  int farFromAll = 0, reportedEmpty = 0;
  for (int q = 0; q < 20000; ++q)
  {
    const Box query = randomBox(rng, -0.3, 1.3, q % 2 ? 0.002 : 0.05);
    bool overlapsOne = false;
    double nearest = 1e300;
    for (const Box& b : boxes)
    {
      overlapsOne = overlapsOne || overlap(clipped(query), clipped(b));
      // Marking and asking each round a box up to one cell of at most twice its extent (and the finest
      // cell) outwards.
      nearest = std::min(nearest, gap(query, b) - 2 * extent(b) - 1.2 / 128);
    }
    const bool may = pyramid.mayOverlap(query.lo.data(), query.hi.data());
    if (overlapsOne)
    {
      ASSERT_TRUE(may) << "query " << q << " overlaps an added box";
    }
    if (nearest > 2 * extent(query) + 1.2 / 128)
    {
      ++farFromAll;
      reportedEmpty += may ? 0 : 1;
    }
  }
  EXPECT_GT(farFromAll, 200);
  EXPECT_EQ(reportedEmpty, farFromAll);
}

TEST(OccupancyPyramid, EmptyUntilABoxIsAdded)
{
  OccupancyPyramid pyramid;
  const double lo[3] = { 0, 0, 0 };
  pyramid.reset(lo, 1, 5);
  const double a[3] = { 0.2, 0.2, 0.2 }, b[3] = { 0.3, 0.3, 0.3 };
  EXPECT_FALSE(pyramid.mayOverlap(lo, b));
  pyramid.addBox(a, b);
  EXPECT_TRUE(pyramid.mayOverlap(lo, b));
  const double outsideLo[3] = { 2, 2, 2 }, outsideHi[3] = { 3, 3, 3 };
  EXPECT_FALSE(pyramid.mayOverlap(outsideLo, outsideHi));
}
