// The quality measure of the quality stage (tetSineQuality, TetEditor.h): the smallest sine of a tet's six
// dihedral angles, negative for an inverted tet. Checked against the sines computed here another way (the
// cross product of the two face normals at each edge), on the shapes the stage meets: well-shaped tets,
// needles, slivers, caps and wedges, from 1e-6 to 1e6 in size, and past the fast path's range.
#include "Predicates.h"
#include "TetEditor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace volgrid;

namespace
{
using Point = std::array<double, 3>;

Point sub(const Point& a, const Point& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Point cross(const Point& a, const Point& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double norm(const Point& a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// The smallest sin(dihedral angle) over the six edges: at edge (i, j) the faces through it are those
// opposite the other two vertices k and l, and sin = |n_k x n_l| / (|n_k| |n_l|).
double referenceSine(const std::array<Point, 4>& p)
{
  std::array<Point, 4> n;
  for (int i = 0; i < 4; ++i)
  {
    const Point& a = p[(i + 1) % 4];
    const Point& b = p[(i + 2) % 4];
    const Point& c = p[(i + 3) % 4];
    n[i] = cross(sub(b, a), sub(c, a));
  }
  double q = 1;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l)
      q = std::min(q, norm(cross(n[k], n[l])) / (norm(n[k]) * norm(n[l])));
  return q;
}

// Tets of every shape the quality stage sees, at random scales and places.
std::vector<std::array<Point, 4>> sampleTets()
{
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::array<Point, 4>> tets;
  auto jitter = [&](double e) { return Point{ e * u(rng), e * u(rng), e * u(rng) }; };
  for (int n = 0; n < 4000; ++n)
  {
    std::array<Point, 4> p;
    const double thin = std::pow(10.0, -1 - 4 * (u(rng) + 1) / 2); // 1e-1 .. 1e-5
    switch (n % 5)
    {
      case 0: // random
        for (Point& x : p)
          x = jitter(1);
        break;
      case 1: // needle: three close vertices, one far
        p = { Point{ 0, 0, 0 }, Point{ thin, 0, 0 }, Point{ 0, thin, 0 }, Point{ 1, 0.3, 0.2 } };
        break;
      case 2: // sliver: a square's corners, two lifted a little
        p = { Point{ 0, 0, 0 }, Point{ 1, 0, thin }, Point{ 1, 1, 0 }, Point{ 0, 1, thin } };
        break;
      case 3: // cap: a vertex just over the middle of a triangle
        p = { Point{ 0, 0, 0 }, Point{ 1, 0, 0 }, Point{ 0.5, 0.9, 0 }, Point{ 0.5, 0.3, thin } };
        break;
      default: // wedge: two close vertices
        p = { Point{ 0, 0, 0 }, Point{ thin, thin, 0 }, Point{ 1, 0, 0.5 }, Point{ 0, 1, -0.5 } };
        break;
    }
    const double scale = std::pow(10.0, 6 * u(rng));
    const Point shift = jitter(10 * scale);
    for (Point& x : p)
    {
      const Point j = jitter(1e-3 * thin);
      for (int k = 0; k < 3; ++k)
        x[k] = (x[k] + j[k]) * scale + shift[k];
    }
    if (n % 2 == 1) // every shape in both orientations
      std::swap(p[0], p[1]);
    tets.push_back(p);
  }
  return tets;
}

double sineOf(const std::array<Point, 4>& p)
{
  return tetSineQuality(p[0].data(), p[1].data(), p[2].data(), p[3].data());
}
} // namespace

TEST(TetSineQuality, IsTheSmallestSineOfTheDihedralAnglesSignedByOrientation)
{
  int positive = 0, negative = 0;
  for (const std::array<Point, 4>& p : sampleTets())
  {
    const int orientation = predicates::orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data());
    ASSERT_NE(orientation, 0);
    const double q = sineOf(p), reference = referenceSine(p);
    EXPECT_EQ(q > 0, orientation > 0);
    // Both are computed in doubles; a sliver's sines carry the rounding of its small volume.
    EXPECT_NEAR(std::fabs(q), reference, 1e-7 * reference + 1e-12) << "reference " << reference;
    (q > 0 ? positive : negative) += 1;
  }
  EXPECT_GT(positive, 1000);
  EXPECT_GT(negative, 1000);
}

TEST(TetSineQuality, KnownShapes)
{
  // The regular tet: every dihedral angle is acos(1/3), sine 2 sqrt(2) / 3.
  const std::array<Point, 4> regular = { Point{ 1, 1, 1 }, Point{ 1, -1, -1 }, Point{ -1, 1, -1 }, Point{ -1, -1, 1 } };
  const double q = sineOf(regular);
  EXPECT_NEAR(std::fabs(q), 2 * std::sqrt(2.0) / 3, 1e-15);
  // The corner of a cube: three right angles and three of acos(1/sqrt(3)), whose sine is sqrt(2/3).
  const std::array<Point, 4> corner = { Point{ 0, 0, 0 }, Point{ 1, 0, 0 }, Point{ 0, 1, 0 }, Point{ 0, 0, 1 } };
  EXPECT_NEAR(std::fabs(sineOf(corner)), std::sqrt(2.0 / 3.0), 1e-15);
  // Swapping two vertices turns the tet over: the same magnitude, the other sign.
  const std::array<Point, 4> turned = { corner[1], corner[0], corner[2], corner[3] };
  EXPECT_NEAR(sineOf(turned), -sineOf(corner), 1e-15);
  // Flat: zero.
  const std::array<Point, 4> flat = { Point{ 0, 0, 0 }, Point{ 1, 0, 0 }, Point{ 0, 1, 0 }, Point{ 1, 1, 0 } };
  EXPECT_EQ(sineOf(flat), 0.0);
}

TEST(TetSineQuality, CoordinatesPastTheFastPathsRange)
{
  // Squared areas multiplied (the fast path's products) of 1e+-60 coordinates leave the double range: the
  // plain formula answers, with the same value as the same shape at unit size.
  const std::array<Point, 4> corner = { Point{ 0, 0, 0 }, Point{ 1, 0, 0 }, Point{ 0, 1, 0 }, Point{ 0, 0.3, 1 } };
  const double unit = sineOf(corner);
  for (const double scale : { 1e-60, 1e60 })
  {
    std::array<Point, 4> p = corner;
    for (Point& x : p)
      for (double& c : x)
        c *= scale;
    EXPECT_NEAR(sineOf(p), unit, 1e-12 * unit) << scale;
  }
}
