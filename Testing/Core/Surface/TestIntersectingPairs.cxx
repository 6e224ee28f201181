// The self-intersection search (bounding volume hierarchy traversed by node pairs, on worker threads)
// against the brute-force test of every pair.
#include "IntersectingPairs.h"
#include "SurfaceChecks.h"

#include <gtest/gtest.h>

#include <random>

using namespace volgrid;

TEST(IntersectingPairs, EqualsBruteForceOnATriangleSoup)
{
  // Small random triangles in a unit box, sharing some corners (shared corners do not count as an
  // intersection), some excluded from the candidates: many pairs overlap and some really intersect.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(0.0, 1.0), off(-0.08, 0.08);
  SurfaceMesh s;
  for (int i = 0; i < 1500; ++i)
  {
    const double c[3] = { pos(rng), pos(rng), pos(rng) };
    int32_t v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = (k == 0 && i > 0 && i % 5 == 0) ? s.triangle(i - 1)[1]
                                             : s.addPoint(c[0] + off(rng), c[1] + off(rng), c[2] + off(rng));
    s.addTriangle(v[0], v[1], v[2]);
  }
  std::vector<int32_t> canon(static_cast<size_t>(s.numberOfPoints()));
  for (int32_t p = 0; p < s.numberOfPoints(); ++p)
    canon[p] = p;
  std::vector<int32_t> candidates;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    if (t % 17 != 3 &&
        !triangleIsDegenerate(s.point(s.triangle(t)[0]), s.point(s.triangle(t)[1]), s.point(s.triangle(t)[2])))
      candidates.push_back(t);
  std::vector<std::pair<int32_t, int32_t>> expected;
  for (size_t i = 0; i < candidates.size(); ++i)
    for (size_t j = i + 1; j < candidates.size(); ++j)
    {
      const int32_t* a = s.triangle(candidates[i]);
      const int32_t* b = s.triangle(candidates[j]);
      const double* p[3] = { s.point(a[0]), s.point(a[1]), s.point(a[2]) };
      const double* q[3] = { s.point(b[0]), s.point(b[1]), s.point(b[2]) };
      if (trianglesIntersect(p, a, q, b))
        expected.push_back({ candidates[i], candidates[j] });
    }
  ASSERT_GT(expected.size(), 100u);
  for (int threads : { 1, 2, 3 })
    EXPECT_EQ(detail::findIntersectingPairs(s, candidates, canon, threads), expected) << threads << " threads";
  EXPECT_TRUE(detail::findIntersectingPairs(s, {}, canon, 2).empty());
}
