// Tests of the exact predicates (Core/Geometry/Predicates.h) and of the expansion arithmetic behind them: basic
// signs, permutation symmetry, power-of-two scaling, wide exponent ranges, incircle3d / orient2dProjected,
// against rational references (PredicatesTestSupport.h). The exact stages are tested in
// TestPredicatesStages.cxx, Simulation of Simplicity in TestPredicatesSoS.cxx.
#include "ExpansionArithmetic.h"
#include "Predicates.h"
#include "PredicatesInline.h"
#include "PredicatesTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>

using namespace predicates_test;

namespace
{
// ---- Expansion arithmetic ----------------------------------------------------------------------------
namespace E = volgrid::expansion;

Q valueOf(int n, const double* e)
{
  Q s = 0;
  for (int i = 0; i < n; ++i)
    s += Q(e[i]);
  return s;
}

#if !defined(__FP_FAST_FMA)
// (With FMA instructions enabled the test TU might contract; Core itself is built with -ffp-contract=off.)
TEST(Predicates, ExpansionArithmeticIsExact)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-300, 300);
  for (int t = 0; t < 2000; ++t)
  {
    const double a = std::ldexp(u(rng), ex(rng)), b = std::ldexp(u(rng), ex(rng));
    double x, y;
    E::twoSum(a, b, x, y);
    ASSERT_EQ(Q(x) + Q(y), Q(a) + Q(b));
    E::twoDiff(a, b, x, y);
    ASSERT_EQ(Q(x) + Q(y), Q(a) - Q(b));
    E::twoProduct(a, b, x, y);
    ASSERT_EQ(Q(x) + Q(y), Q(a) * Q(b));
    ASSERT_EQ(x, a * b);
    E::twoSquare(a, x, y);
    ASSERT_EQ(Q(x) + Q(y), Q(a) * Q(a));
  }
  // Products and sums of random expansions built from exact sums of doubles.
  for (int t = 0; t < 300; ++t)
  {
    auto randomExpansion = [&](double* h)
    {
      double acc[64];
      int n = 1;
      acc[0] = std::ldexp(u(rng), ex(rng) / 10);
      for (int k = 0; k < 5; ++k)
      {
        double tmp[64];
        const double term[1] = { std::ldexp(u(rng), ex(rng) / 10) };
        n = E::sumExpansions(n, acc, 1, term, tmp);
        std::copy(tmp, tmp + n, acc);
      }
      std::copy(acc, acc + n, h);
      return n;
    };
    double e[64], f[64], s[128], p[2 * 64 * 64], scratch[E::multiplyScratchSize(64, 64)], sc[128];
    const int en = randomExpansion(e), fn = randomExpansion(f);
    for (int k = 1; k < en; ++k)
      ASSERT_LT(std::fabs(e[k - 1]), std::fabs(e[k])) << "increasing magnitude";
    const int sn = E::sumExpansions(en, e, fn, f, s);
    ASSERT_EQ(valueOf(sn, s), valueOf(en, e) + valueOf(fn, f));
    const int pn = E::multiplyExpansions(en, e, fn, f, p, scratch);
    ASSERT_EQ(valueOf(pn, p), valueOf(en, e) * valueOf(fn, f));
    ASSERT_EQ(E::expansionSign(pn, p), sgn(valueOf(en, e) * valueOf(fn, f)));
    const int cn = E::scaleExpansion(en, e, f[fn - 1], sc);
    ASSERT_EQ(valueOf(cn, sc), valueOf(en, e) * Q(f[fn - 1]));
    for (int k = 0; k < pn; ++k)
      ASSERT_NE(p[k], 0.0) << "zero elimination";
  }
}
#endif

// ---- orient3d ------------------------------------------------------------------------------------------
TEST(Predicates, Orient3dBasicAndDegenerate)
{
  const Pt o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, z = { 0, 0, 1 };
  EXPECT_EQ(orient(o, x, y, z), 1) << "d on the side of (b-a)x(c-a)";
  EXPECT_EQ(orient(o, y, x, z), -1);
  EXPECT_EQ(orient(o, x, y, Pt{ 0.3, 0.7, 0 }), 0) << "coplanar";
  EXPECT_EQ(orient(o, x, y, Pt{ 1e30, -1e30, 0 }), 0);
  EXPECT_EQ(orient(o, x, Pt{ 2, 0, 0 }, z), 0) << "collinear";
  EXPECT_EQ(orient(o, x, x, z), 0) << "duplicate";
  // The same plane, exactly, far from the origin: z = x + y with dyadic coordinates.
  const Pt a = { 0.5, 0.25, 0.75 }, b = { 3, 1, 4 }, c = { -2, 5, 3 }, d = { 7.125, -1.5, 5.625 };
  EXPECT_EQ(orient(a, b, c, d), 0);
  EXPECT_EQ(orient(affine(a, 1, 1e9), affine(b, 1, 1e9), affine(c, 1, 1e9), affine(d, 1, 1e9)), 0);
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_EQ(orient(a, b, c, nudge(d, axis, 1)), refOrient3d(a, b, c, nudge(d, axis, 1)));
    EXPECT_EQ(orient(a, b, c, nudge(d, axis, -1)), -orient(a, b, c, nudge(d, axis, 1)));
    EXPECT_NE(orient(a, b, c, nudge(d, axis, -1)), 0);
  }
}

TEST(Predicates, Orient3dPermutationSymmetry)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 200; ++t)
  {
    std::array<Pt, 4> p;
    for (auto& q : p)
      q = { u(rng), u(rng), u(rng) };
    if (t % 2) // coplanar-ish
      p[3] = { (p[0][0] + p[1][0]) * 0.5, (p[0][1] + p[1][1]) * 0.5, (p[0][2] + p[1][2]) * 0.5 };
    const int s = orient(p[0], p[1], p[2], p[3]);
    std::array<int, 5> perm = { 0, 1, 2, 3, 4 };
    do
    {
      ASSERT_EQ(orient(p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]]), permutationParity(perm, 4) * s);
    } while (std::next_permutation(perm.begin(), perm.begin() + 4));
  }
}

TEST(Predicates, Orient3dRandomNearDegenerateAgainstRational)
{
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ulp(-3, 3), axis(0, 2);
  const double offsets[] = { 0, 1e9, -3.5e-7 };
  const double scales[] = { 1, 1e-9, 1e7 };
  int zeros = 0, checks = 0;
  for (double off : offsets)
    for (double sc : scales)
      for (int t = 0; t < 1500; ++t)
      {
        Pt a = affine({ u(rng), u(rng), u(rng) }, sc, off);
        Pt b = affine({ u(rng), u(rng), u(rng) }, sc, off);
        Pt c = affine({ u(rng), u(rng), u(rng) }, sc, off);
        const double s = u(rng), r = u(rng);
        Pt d; // on the plane abc, rounded
        for (int k = 0; k < 3; ++k)
          d[k] = a[k] + s * (b[k] - a[k]) + r * (c[k] - a[k]);
        if (t % 3 == 1)
          d = nudge(d, axis(rng), ulp(rng));
        if (t % 3 == 2)
        {
          d = { std::round(d[0]), std::round(d[1]), std::round(d[2]) };
          a = { 0, 0, 0 };
          b = { std::round(b[0]), 1, 2 };
          c = { 2, 4, std::round(c[2]) };
        }
        const int ref = refOrient3d(a, b, c, d);
        ASSERT_EQ(orient(a, b, c, d), ref) << "t=" << t << " off=" << off << " scale=" << sc;
        zeros += ref == 0;
        ++checks;
      }
  EXPECT_GT(zeros, 0);
  EXPECT_EQ(checks, 13500);
}

// ---- insphere -------------------------------------------------------------------------------------------
TEST(Predicates, InsphereBasicAndCospherical)
{
  const Pt o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, z = { 0, 0, 1 };
  ASSERT_EQ(orient(o, x, y, z), 1);
  EXPECT_EQ(insph(o, x, y, z, Pt{ 0.25, 0.25, 0.25 }), 1);
  EXPECT_EQ(insph(o, x, y, z, Pt{ 2, 2, 2 }), -1);
  EXPECT_EQ(insph(o, x, y, z, Pt{ 1, 1, 1 }), 0) << "cube vertex on the sphere";
  EXPECT_EQ(insph(o, y, x, z, Pt{ 0.25, 0.25, 0.25 }), -1) << "negative orientation flips";
  // All 5-subsets of the cube's vertices are cospherical, in every placement and scale.
  const auto& C = cube();
  for (double off : { 0.0, 1e9, -12345.5 })
    for (double sc : { 1.0, 0x1p-40, 0x1p+40, 0.75 })
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
          for (int k = 0; k < 8; ++k)
            for (int l = 0; l < 8; ++l)
            {
              const int m = (i + j + k + l) % 8;
              EXPECT_EQ(insph(affine(C[i], sc, off), affine(C[j], sc, off), affine(C[k], sc, off),
                              affine(C[l], sc, off), affine(C[m], sc, off)),
                        0);
            }
  // Integer points on a sphere of radius 3, and 1-ulp nudges across it.
  const auto S = sphere9();
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<size_t> pick(0, S.size() - 1);
  int tested = 0;
  while (tested < 300)
  {
    const Pt a = S[pick(rng)], b = S[pick(rng)], c = S[pick(rng)], d = S[pick(rng)], e = S[pick(rng)];
    if (orient(a, b, c, d) == 0)
      continue;
    ASSERT_EQ(insph(a, b, c, d, e), 0);
    const Pt ein = { e[0] * (1 - 0x1p-52), e[1] * (1 - 0x1p-52), e[2] * (1 - 0x1p-52) };
    const Pt eout = { e[0] * (1 + 0x1p-52), e[1] * (1 + 0x1p-52), e[2] * (1 + 0x1p-52) };
    ASSERT_EQ(insph(a, b, c, d, ein), orient(a, b, c, d));
    ASSERT_EQ(insph(a, b, c, d, eout), -orient(a, b, c, d));
    ++tested;
  }
}

TEST(Predicates, InspherePermutationSymmetry)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto S = sphere9();
  for (int t = 0; t < 100; ++t)
  {
    std::array<Pt, 5> p;
    for (auto& q : p)
      q = (t % 2) ? S[static_cast<size_t>(u(rng) * 13 + 13)] : Pt{ u(rng), u(rng), u(rng) };
    if (orient(p[0], p[1], p[2], p[3]) == 0)
      continue;
    const int s = insph(p[0], p[1], p[2], p[3], p[4]);
    std::array<int, 5> perm = { 0, 1, 2, 3, 4 };
    do
    { // insphere is minus the sign of an alternating 5x5 determinant: odd permutations flip.
      if (orient(p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]]) == 0)
        continue;
      ASSERT_EQ(insph(p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]], p[perm[4]]), permutationParity(perm, 5) * s);
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
}

TEST(Predicates, InsphereRandomNearDegenerateAgainstRational)
{
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ulp(-2, 2), axis(0, 2);
  auto onSphere = [&](const Pt& c, double r)
  {
    Pt v = { u(rng), u(rng), u(rng) };
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return Pt{ c[0] + r * v[0] / n, c[1] + r * v[1] / n, c[2] + r * v[2] / n };
  };
  int checks = 0, zeros = 0;
  for (double off : { 0.0, 1e9, 1e-5 })
    for (double r : { 1.0, 1e-9, 1e5 })
      for (int t = 0; t < 400; ++t)
      {
        const Pt c = { off + u(rng) * r, off, off - u(rng) * r };
        std::array<Pt, 5> p;
        for (auto& q : p)
          q = onSphere(c, r);
        if (t % 2)
          p[4] = nudge(p[4], axis(rng), ulp(rng));
        if (t % 5 == 0) // exactly cospherical, scaled copies of the radius-3 lattice sphere
        {
          const auto S = sphere9();
          for (auto& q : p)
            q = affine(S[static_cast<size_t>((u(rng) + 1) * 12.99)], 0x1p-3, off);
        }
        if (refOrient3d(p[0], p[1], p[2], p[3]) == 0)
          continue;
        const int ref = refInsphere(p[0], p[1], p[2], p[3], p[4]);
        ASSERT_EQ(insph(p[0], p[1], p[2], p[3], p[4]), ref) << "t=" << t << " off=" << off << " r=" << r;
        zeros += ref == 0;
        ++checks;
      }
  EXPECT_GT(checks, 3000);
  EXPECT_GT(zeros, 10);
}

// Scaling by powers of two is exact, so signs must not change, even deep in the subnormal range or
// where the double evaluation overflows.
TEST(Predicates, SignsInvariantUnderPowerOfTwoScalingAndTranslation)
{
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int> small(-6, 6);
  int checks = 0;
  for (int t = 0; t < 300; ++t)
  {
    std::array<Pt, 5> p;
    for (auto& q : p)
      q = { double(small(rng)), double(small(rng)), double(small(rng)) };
    if (t % 3 == 0)
      p[4] = p[0]; // degenerate on purpose
    if (t % 3 == 1)
      p[3] = { p[0][0] + p[1][0] - p[2][0], p[0][1] + p[1][1] - p[2][1], p[0][2] + p[1][2] - p[2][2] };
    const int o = orient(p[0], p[1], p[2], p[3]);
    const int s = o ? insph(p[0], p[1], p[2], p[3], p[4]) : 0;
    const int o2 = P::orient2dProjected(p[0].data(), p[1].data(), p[2].data(), t % 3);
    for (int k : { -1070, -1000, -700, -300, -40, 40, 100, 300, 600, 900 })
    {
      std::array<Pt, 5> q;
      for (int i = 0; i < 5; ++i)
        q[i] = affine(p[i], std::ldexp(1.0, k), 0.0);
      ASSERT_EQ(orient(q[0], q[1], q[2], q[3]), o) << k;
      if (o)
      {
        ASSERT_EQ(insph(q[0], q[1], q[2], q[3], q[4]), s) << k;
      }
      ASSERT_EQ(P::orient2dProjected(q[0].data(), q[1].data(), q[2].data(), t % 3), o2) << k;
      ++checks;
    }
    for (double off : { 1e9, -1e9, 0x1p40 })
    {
      std::array<Pt, 5> q;
      for (int i = 0; i < 5; ++i)
        q[i] = affine(p[i], 0.125, off); // exact: few bits
      ASSERT_EQ(orient(q[0], q[1], q[2], q[3]), o);
      if (o)
      {
        ASSERT_EQ(insph(q[0], q[1], q[2], q[3], q[4]), s);
      }
      ++checks;
    }
  }
  EXPECT_EQ(checks, 3900);
}

// Any finite doubles: coordinates spread over the whole exponent range in one call (the exact path then
// cannot scale into a safe window and uses big integers), including subnormals, against rationals.
TEST(Predicates, WideExponentRangeAgainstRational)
{
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> ex(-1074, 1000), axis(0, 2), ulp(-2, 2);
  auto wide = [&]()
  {
    Pt p;
    for (auto& x : p)
      x = (rng() % 4 == 0) ? 0.0 : std::ldexp(u(rng), ex(rng) / static_cast<int>(rng() % 3 + 1));
    return p;
  };
  int zeros = 0;
  for (int t = 0; t < 1500; ++t)
  {
    std::array<Pt, 5> p;
    for (auto& q : p)
      q = wide();
    if (t % 4 == 1) // flat: shared z, or e on a vertex (nudged or not)
      p[3][2] = p[2][2] = p[1][2] = p[0][2];
    if (t % 4 == 2)
      p[4] = nudge(p[rng() % 4], axis(rng), (t % 8 == 2) ? 0 : ulp(rng));
    const int ro = refOrient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(orient(p[0], p[1], p[2], p[3]), ro) << t;
    zeros += ro == 0;
    if (ro != 0)
    {
      const int rs = refInsphere(p[0], p[1], p[2], p[3], p[4]);
      ASSERT_EQ(insph(p[0], p[1], p[2], p[3], p[4]), rs) << t;
      zeros += rs == 0;
    }
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(P::orient2dProjected(p[0].data(), p[1].data(), p[2].data(), k),
                refOrient2dProjected(p[0], p[1], p[2], k));
    // Coplanar quadruple for incircle3d: all on the plane z = p0.z.
    Pt q[4] = { p[0], p[1], p[2], p[4] };
    for (auto& v : q)
      v[2] = p[0][2];
    if (refOrient2dProjected(q[0], q[1], q[2], 2) != 0)
    {
      ASSERT_EQ(incirc(q[0], q[1], q[2], q[3]), refIncircle3d(q[0], q[1], q[2], q[3])) << t;
    }
  }
  EXPECT_GT(zeros, 150);
}

// ---- incircle3d and orient2dProjected --------------------------------------------------------------------
TEST(Predicates, Orient2dProjectedConvention)
{
  // orient2dProjected(a,b,c,k) is the sign of the k-th component of (b-a)x(c-a): the projected frame is
  // (u, v) = ((k+1)%3, (k+2)%3).
  const Pt o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, z = { 0, 0, 1 };
  EXPECT_EQ(P::orient2dProjected(o.data(), x.data(), y.data(), 2), 1);
  EXPECT_EQ(P::orient2dProjected(o.data(), y.data(), z.data(), 0), 1);
  EXPECT_EQ(P::orient2dProjected(o.data(), z.data(), x.data(), 1), 1);
  EXPECT_EQ(P::orient2dProjected(o.data(), x.data(), z.data(), 1), -1);
  EXPECT_EQ(P::orient2dProjected(o.data(), x.data(), z.data(), 2), 0);
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 3000; ++t)
  {
    const double off = (t % 3 == 0) ? 1e9 : 0.0;
    const Pt a = affine({ u(rng), u(rng), u(rng) }, 1, off), b = affine({ u(rng), u(rng), u(rng) }, 1, off);
    const double s = u(rng);
    Pt c = { a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]) };
    if (t % 2)
      c = nudge(c, t % 3, 1);
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(P::orient2dProjected(a.data(), b.data(), c.data(), k), refOrient2dProjected(a, b, c, k));
  }
}

TEST(Predicates, Incircle3dCoplanar)
{
  // Unit square in a tilted plane z = x + 2y (exact for dyadic coordinates): its corners are cocircular.
  auto lift = [](double x, double y) { return Pt{ x, y, x + 2 * y }; };
  const Pt a = lift(0, 0), b = lift(1, 0), c = lift(0, 1), d = lift(1, 1);
  EXPECT_EQ(refIncircle3d(a, b, c, lift(0.25, 0.25)), 1);
  EXPECT_EQ(incirc(a, b, c, lift(0.25, 0.25)), 1);
  EXPECT_EQ(incirc(a, c, b, lift(0.25, 0.25)), 1) << "independent of the orientation of abc";
  EXPECT_EQ(incirc(a, b, c, lift(3, 3)), -1);
  // Circumcircle in the plane, not in the projection: the point (1,1) of the xy projection is cocircular
  // with the projected triangle but not in 3D.
  EXPECT_EQ(incirc(a, b, c, d), refIncircle3d(a, b, c, d));
  const Pt sq[4] = { { 0, 0, 5 }, { 1, 0, 5 }, { 1, 1, 5 }, { 0, 1, 5 } };
  EXPECT_EQ(incirc(sq[0], sq[1], sq[2], sq[3]), 0);
  EXPECT_EQ(incirc(sq[0], sq[2], sq[1], sq[3]), 0);
  EXPECT_EQ(incirc(a, b, lift(2, 0), c), 0) << "collinear a, b, c";
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> coef(-3, 3);
  int zeros = 0;
  for (int t = 0; t < 4000; ++t)
  {
    // Exact plane: w = alpha*u + beta*v + gamma with small integers; u, v rounded to multiples of 2^-20
    // so that the third coordinate is exact. The plane's axis order is permuted.
    const double al = coef(rng), be = coef(rng), ga = (t % 4 == 0) ? 1e6 : 0.5;
    const int perm = t % 3;
    auto planePoint = [&](double pu, double pv)
    {
      const double fu = std::ldexp(std::round(std::ldexp(pu, 20)), -20);
      const double fv = std::ldexp(std::round(std::ldexp(pv, 20)), -20);
      Pt p;
      p[perm] = fu;
      p[(perm + 1) % 3] = fv;
      p[(perm + 2) % 3] = al * fu + be * fv + ga;
      return p;
    };
    const double cu = u(rng), cv = u(rng), r = 0.5 + 0.25 * u(rng);
    std::array<Pt, 4> p;
    for (auto& q : p)
    {
      const double th = 3.14159 * u(rng);
      q = planePoint(cu + r * std::cos(th), cv + r * std::sin(th));
    }
    if (t % 5 == 0) // exactly cocircular (a rectangle in the plane)
    {
      p = { planePoint(0.25, 0.5), planePoint(0.75, 0.5), planePoint(0.75, 2), planePoint(0.25, 2) };
      std::swap(p[1], p[t % 2 + 1]);
    }
    ASSERT_EQ(refOrient3d(p[0], p[1], p[2], p[3]), 0);
    if (refOrient2dProjected(p[0], p[1], p[2], 0) == 0 && refOrient2dProjected(p[0], p[1], p[2], 1) == 0 &&
        refOrient2dProjected(p[0], p[1], p[2], 2) == 0)
      continue;
    const int ref = refIncircle3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(incirc(p[0], p[1], p[2], p[3]), ref) << t;
    zeros += ref == 0;
  }
  EXPECT_GT(zeros, 100);
}

TEST(Predicates, InlineVersionsAgree)
{
  std::mt19937_64 rng(47);
  std::uniform_int_distribution<int> small(0, 2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 5000; ++t)
  {
    std::array<Pt, 5> p;
    for (auto& q : p)
      q = (t % 2) ? Pt{ double(small(rng)), double(small(rng)), double(small(rng)) } : Pt{ u(rng), u(rng), u(rng) };
    const double *a = p[0].data(), *b = p[1].data(), *c = p[2].data(), *d = p[3].data(), *e = p[4].data();
    ASSERT_EQ(P::orient3dInline(a, b, c, d), P::orient3d(a, b, c, d));
    ASSERT_EQ(P::insphereInline(a, b, c, d, e), P::insphere(a, b, c, d, e));
    ASSERT_EQ(P::orient2dProjectedInline(a, b, c, t % 3), P::orient2dProjected(a, b, c, t % 3));
    if (P::orient3d(a, b, c, d) != 0)
    {
      ASSERT_EQ(P::insphereSoSInline(a, b, c, d, e, 1, 2, 3, 4, 5), P::insphereSoS(a, b, c, d, e, 1, 2, 3, 4, 5));
    }
  }
}

} // namespace
