// Tests of the exact paths of orient3d and insphere stage by stage (PredicatesInline.h, detail::*Staged):
// the adaptive expansion stages and the fixed-point integer stage, each against rational references
// (PredicatesTestSupport.h). Separate from TestPredicates.cxx because they test which stage decides, not
// only the sign.
#include "PredicatesInline.h"
#include "PredicatesTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <utility>

using namespace predicates_test;

namespace
{
// ---- Adaptive stages ----------------------------------------------------------------------------------------
// Near-degenerate inputs whose coordinate differences are NOT exact (coordinates of different binades
// around the origin): the exact paths decide them in stages (long double filter, stage B on the rounded
// differences, stage C with the first-order tail terms, full evaluation). Every stage must give the
// rational sign, and every stage must be reached, with and without the long double filter.
int stagedInsphere(const std::array<Pt, 5>& p, bool extended, int& stage)
{
  return P::detail::insphereExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), extended,
                                        &stage);
}

TEST(Predicates, InsphereAdaptiveStagesAgainstRational)
{
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> axis(0, 2), which(0, 4), sign(0, 1);
  auto onSphere = [&](const Pt& c, double r, const Pt& around, double spread)
  {
    Pt v = { around[0] + spread * u(rng), around[1] + spread * u(rng), around[2] + spread * u(rng) };
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return Pt{ c[0] + r * v[0] / n, c[1] + r * v[1] / n, c[2] + r * v[2] / n };
  };
  int count[2][7] = {};
  int checks = 0, inexact = 0;
  for (int t = 0; t < 6000; ++t)
  {
    std::array<Pt, 5> p;
    const int kind = t % 4;
    if (kind < 3)
    { // rounded points of a sphere around (near) the origin, spread over it or clustered (mesh-like)
      const double r = kind == 0 ? 1.0 : (kind == 1 ? 0x1p-20 * 3 : 37.25);
      const Pt c = { 0.25 * r * u(rng), 0.25 * r * u(rng), 0.25 * r * u(rng) };
      const Pt around = { u(rng), u(rng), u(rng) };
      const double spread = (t / 4) % 3 == 0 ? 4.0 : ((t / 4) % 3 == 1 ? 0.1 : 0.01);
      for (auto& q : p)
        q = onSphere(c, r, around, spread);
    }
    else
    { // signed permutations of (x, y, z): exactly cospherical around the origin, differences such as
      // x - y mostly inexact
      const double v[3] = { u(rng), u(rng) * 0.3, u(rng) * 1e-3 };
      std::array<int, 48> m;
      for (int i = 0; i < 48; ++i)
        m[i] = i;
      std::shuffle(m.begin(), m.end(), rng);
      static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
      for (int i = 0; i < 5; ++i)
      {
        const int* pm = perms[m[i] / 8];
        const int sg = m[i] % 8;
        p[i] = { (sg & 1) ? -v[pm[0]] : v[pm[0]], (sg & 2) ? -v[pm[1]] : v[pm[1]], (sg & 4) ? -v[pm[2]] : v[pm[2]] };
      }
    }
    if ((t / 2) % 3 == 1) // one coordinate of one point 1 ulp off
      p[which(rng)] = nudge(p[which(rng)], axis(rng), sign(rng) ? 1 : -1);
    if (refOrient3d(p[0], p[1], p[2], p[3]) == 0)
      continue;
    const int ref = refInsphere(p[0], p[1], p[2], p[3], p[4]);
    for (int ext = 0; ext < 2; ++ext)
    {
      int stage = 0;
      ASSERT_EQ(stagedInsphere(p, ext == 1, stage), ref) << "t=" << t << " extended=" << ext << " stage=" << stage;
      ASSERT_GE(stage, 1);
      ASSERT_LE(stage, 6);
      ++count[ext][stage];
      inexact += ext == 0 && stage >= 3;
    }
    ASSERT_EQ(insph(p[0], p[1], p[2], p[3], p[4]), ref) << "t=" << t;
    ++checks;
  }
  EXPECT_GT(checks, 5000);
  EXPECT_GT(inexact, 1000);
  // Without the long double filter: stage B, stage C and the full evaluation all decide some.
  EXPECT_EQ(count[0][1], 0);
  EXPECT_GT(count[0][3], 50) << "stage B";
  EXPECT_GT(count[0][4], 50) << "stage C";
  EXPECT_GT(count[0][5], 50) << "full";
  // With it (where long double is wider than double), it decides most of the near-degenerate calls.
  if (std::numeric_limits<long double>::digits > 60)
  {
    EXPECT_GT(count[1][1], 1000);
  }
  else
  {
    EXPECT_EQ(count[1][1], 0);
  }
}

TEST(Predicates, Orient3dAdaptiveStagesAgainstRational)
{
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> axis(0, 2), which(0, 3), sign(0, 1);
  int count[2][7] = {};
  int checks = 0;
  for (int t = 0; t < 6000; ++t)
  {
    // Near the origin, so that differences mix binades; d on the plane abc (rounded), or a plane through
    // points of one binade per axis (x, y, 0)-like with a nudge.
    const double sc = (t % 3 == 0) ? 1.0 : ((t % 3 == 1) ? 1e-7 : 3e5);
    Pt a = { u(rng) * sc, u(rng) * sc, u(rng) * sc };
    Pt b = { u(rng) * sc, u(rng) * sc, u(rng) * sc };
    Pt c = { u(rng) * sc, u(rng) * sc, u(rng) * sc };
    const double s = u(rng), r = u(rng);
    Pt d;
    for (int k = 0; k < 3; ++k)
      d[k] = a[k] + s * (b[k] - a[k]) + r * (c[k] - a[k]);
    if ((t / 3) % 4 == 1)
      d = nudge(d, axis(rng), sign(rng) ? 1 : -1);
    if ((t / 3) % 4 == 2)
    { // exactly coplanar (z = 0 plane, tilted by swapping axes), differences inexact
      a[2] = b[2] = c[2] = d[2] = 0.0;
      const int k = axis(rng);
      for (Pt* q : { &a, &b, &c, &d })
        std::swap((*q)[2], (*q)[k]);
    }
    std::array<Pt, 4> p = { a, b, c, d };
    if ((t / 3) % 4 == 3)
      p[which(rng)] = nudge(p[which(rng)], axis(rng), sign(rng) ? 1 : -1);
    const int ref = refOrient3d(p[0], p[1], p[2], p[3]);
    for (int ext = 0; ext < 2; ++ext)
    {
      int stage = 0;
      ASSERT_EQ(P::detail::orient3dExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), ext == 1, &stage),
                ref)
        << "t=" << t << " extended=" << ext << " stage=" << stage;
      ++count[ext][stage];
    }
    ASSERT_EQ(orient(p[0], p[1], p[2], p[3]), ref);
    ++checks;
  }
  EXPECT_EQ(checks, 6000);
  EXPECT_GT(count[0][3], 50) << "stage B";
  EXPECT_GT(count[0][4], 50) << "stage C";
  EXPECT_GT(count[0][5], 50) << "full";
  if (std::numeric_limits<long double>::digits > 60)
  {
    EXPECT_GT(count[1][1], 1000);
  }
}

} // namespace

// ---- Fixed-point integer stage (PredicatesFixed.h) ----------------------------------------------------------
// Structured grids with non-dyadic spacing (i/99, x0 + i h): every cell's 8 corners are exactly
// cospherical and its faces coplanar, but the coordinate differences are not exact, so the filters fail and
// the exact path decides. Narrow exponent spreads must be decided by the fixed-point stage (7), with the
// rational sign; wide spreads must fall back to the expansion stages, still exact.
namespace
{
int stagedOrient(const std::array<Pt, 5>& p, bool fixedPoint, int& stage)
{
  return P::detail::orient3dExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), true, &stage, fixedPoint);
}
int stagedInsphereFixed(const std::array<Pt, 5>& p, bool fixedPoint, int& stage)
{
  return P::detail::insphereExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), true, &stage,
                                        fixedPoint);
}

// Checks orient3d of p[0..3] and insphere of p (when not flat) through the public predicates and through
// the staged exact paths with and without the fixed-point stage; counts the calls stage 7 decided.
void checkAgainstRational(const std::array<Pt, 5>& p, int& fixedStage, int& zeros, const char* what, int t)
{
  const int ro = refOrient3d(p[0], p[1], p[2], p[3]);
  ASSERT_EQ(orient(p[0], p[1], p[2], p[3]), ro) << what << " t=" << t;
  int stage = 0;
  ASSERT_EQ(stagedOrient(p, true, stage), ro) << what << " t=" << t << " stage=" << stage;
  fixedStage += stage == 7;
  ASSERT_EQ(stagedOrient(p, false, stage), ro) << what << " t=" << t << " stage=" << stage;
  ASSERT_NE(stage, 7);
  zeros += ro == 0;
  if (ro == 0)
    return;
  const int rs = refInsphere(p[0], p[1], p[2], p[3], p[4]);
  ASSERT_EQ(insph(p[0], p[1], p[2], p[3], p[4]), rs) << what << " t=" << t;
  ASSERT_EQ(stagedInsphereFixed(p, true, stage), rs) << what << " t=" << t << " stage=" << stage;
  fixedStage += stage == 7;
  ASSERT_EQ(stagedInsphereFixed(p, false, stage), rs) << what << " t=" << t << " stage=" << stage;
  ASSERT_NE(stage, 7);
  zeros += rs == 0;
}
} // namespace

TEST(Predicates, FixedPointNonDyadicGridsAgainstRational)
{
  std::mt19937_64 rng(53);
  struct Grid
  {
    double x0, h;
    int n;
    bool divide; // coordinate i / (n - 1) instead of x0 + i h
  };
  const Grid grids[] = { { 0, 0, 100, true },        { 0, 0, 40, true },
                         { 0.3, 0.01, 100, false },  { -1.7, 1.0 / 7.0, 30, false },
                         { 1234.5, 0.1, 50, false }, { -2e-3, 1e-4 / 3.0, 60, false } };
  std::uniform_int_distribution<int> axis(0, 2), ulp(-3, 3), off(0, 2);
  int fixedStage = 0, zeros = 0, checks = 0;
  for (const Grid& g : grids)
  {
    auto coord = [&](int i) { return g.divide ? double(i) / double(g.n - 1) : g.x0 + i * g.h; };
    std::uniform_int_distribution<int> cell(0, g.n - 4);
    for (int t = 0; t < 1500; ++t)
    {
      // Five points among the corners of a random box of 1..3 cells per axis (exactly cospherical when
      // all five are corners of the same box), or of a 3x3x3 block of grid points.
      const int i0 = cell(rng), j0 = cell(rng), k0 = cell(rng);
      const int di = 1 + off(rng), dj = 1 + off(rng), dk = 1 + off(rng);
      std::array<Pt, 5> p;
      for (auto& q : p)
      {
        if (t % 3 == 2)
          q = { coord(i0 + off(rng)), coord(j0 + off(rng)), coord(k0 + off(rng)) };
        else
          q = { coord(i0 + di * int(rng() % 2)), coord(j0 + dj * int(rng() % 2)), coord(k0 + dk * int(rng() % 2)) };
      }
      if (t % 5 == 4) // near-degenerate: one coordinate a few ulps off
      {
        const int v = int(rng() % 5);
        p[v] = nudge(p[v], axis(rng), ulp(rng));
      }
      if (std::set<Pt>(p.begin(), p.end()).size() < 5)
        continue;
      checkAgainstRational(p, fixedStage, zeros, "grid", t);
      if (HasFatalFailure())
        return;
      ++checks;
    }
  }
  EXPECT_GT(checks, 3000);
  EXPECT_GT(zeros, 1500) << "exactly coplanar / cospherical cases";
  EXPECT_GT(fixedStage, 5000) << "decided by the fixed-point stage";
}

TEST(Predicates, FixedPointBitBoundsAndFallbackAgainstRational)
{
  std::mt19937_64 rng(59);
  // Extremes of the fixed-point window: coordinates whose integers (over the common lowest bit) reach
  // 2^61 - 2^8 in magnitude while 1 (the lowest bit) is present, so differences, minors, norms and the
  // final sums reach their bounds; then one step wider (2^62 - 2^9 with 1), which must fall back.
  const double big61 = std::ldexp(double((uint64_t(1) << 53) - 1), 8); // 2^61 - 2^8, top bit 2^60
  const double big62 = std::ldexp(double((uint64_t(1) << 53) - 1), 9); // top bit 2^61: span 62
  std::uniform_int_distribution<int> axis(0, 2), ulp(-2, 2);
  int fixedStage = 0, zeros = 0;
  for (int wide = 0; wide < 2; ++wide)
  {
    const double big = wide ? big62 : big61;
    const double values[] = { big, -big, big / 2 + 1, -(big / 2) - 1, 1, -1, 0, 3, big - 2, -big + 2 };
    int localFixed = 0;
    for (int t = 0; t < 3000; ++t)
    {
      std::array<Pt, 5> p;
      for (auto& q : p)
        for (auto& x : q)
          x = values[rng() % 10];
      if (t % 4 == 1)
        p[3][2] = p[2][2] = p[1][2] = p[0][2];
      if (std::set<Pt>(p.begin(), p.end()).size() < 5)
        continue;
      // Keep the lowest bit 1 and the top bit in the call so the span is exactly at the bound.
      p[0][0] = 1;
      p[1][1] = big;
      checkAgainstRational(p, localFixed, zeros, wide ? "span 62" : "span 61", t);
      if (HasFatalFailure())
        return;
    }
    if (wide)
    {
      EXPECT_EQ(localFixed, 0) << "a 62-bit span must take the expansion path";
    }
    else
    {
      EXPECT_GT(localFixed, 2000);
    }
    fixedStage += localFixed;
  }
  // Wide spreads (a coordinate 2^-70 beside 1, or subnormal) fall back, exactly.
  std::uniform_real_distribution<double> u(-1, 1);
  int fallback = 0;
  for (int t = 0; t < 2000; ++t)
  {
    std::array<Pt, 5> p;
    for (int i = 0; i < 5; ++i)
      p[i] = cube()[(i * 3 + t) % 8];
    for (auto& q : p)
      q = affine(q, 1.0 / 3.0, 0.1);
    if (std::set<Pt>(p.begin(), p.end()).size() < 5)
      continue;
    const int kind = t % 3;
    const double tiny = kind == 0 ? 0x1p-70 : (kind == 1 ? 4.9e-324 * double(1 + t % 7) : 0x1p-9 * u(rng));
    const int tinyAxis = axis(rng);
    p[t % 4][tinyAxis] = tiny; // in both the orient3d and the insphere call
    if (t % 2)
    {
      const int v = int(rng() % 5);
      p[v] = nudge(p[v], axis(rng), ulp(rng));
    }
    int localFixed = 0;
    checkAgainstRational(p, localFixed, zeros, "spread", t);
    if (HasFatalFailure())
      return;
    if (kind < 2 && p[t % 4][tinyAxis] != 0.0) // (a nudge may have taken a subnormal to 0)
    {
      EXPECT_EQ(localFixed, 0) << t;
      ++fallback;
    }
  }
  EXPECT_GT(fallback, 1000);
  EXPECT_GT(zeros, 300);
}

TEST(Predicates, FixedPointRandomNearDegenerateAgainstRational)
{
  // Rounded near-cospherical / near-coplanar points in one binade range, a few ulps off: signs must be the
  // rational ones, whichever stage decides.
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> axis(0, 2), ulp(-2, 2);
  int fixedStage = 0, zeros = 0;
  for (int t = 0; t < 4000; ++t)
  {
    const Pt c = { 0.5 + 0.25 * u(rng), 0.5 + 0.25 * u(rng), 0.5 + 0.25 * u(rng) };
    const double r = 0.2;
    std::array<Pt, 5> p;
    for (auto& q : p)
    {
      Pt v = { u(rng), u(rng), u(rng) };
      const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      q = { c[0] + r * v[0] / n, c[1] + r * v[1] / n, c[2] + r * v[2] / n };
    }
    if (t % 2)
      for (int k = 0; k < 3; ++k)
        p[3][k] = p[0][k] + 0.375 * (p[1][k] - p[0][k]) + 0.25 * (p[2][k] - p[0][k]);
    if (t % 3)
    {
      const int v = int(rng() % 5);
      p[v] = nudge(p[v], axis(rng), ulp(rng));
    }
    checkAgainstRational(p, fixedStage, zeros, "sphere", t);
    if (HasFatalFailure())
      return;
  }
  EXPECT_GT(fixedStage, 4000);
}
