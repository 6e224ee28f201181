// Tests of the exact predicates (Core/Predicates.h) and of the expansion arithmetic behind them.
// The reference for "exact" is rational arithmetic (GMP mpq_class): every double is a rational, so the
// references below are the true signs, computed from independent geometric definitions where possible
// (circumcentres rather than lifted determinants).
#include "ExpansionArithmetic.h"
#include "Predicates.h"
#include "PredicatesInline.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace
{
namespace P = volgrid::predicates;
using Pt = std::array<double, 3>;
using Q = mpq_class;
using QPt = std::array<Q, 3>;

QPt toQ(const Pt& p)
{
  return { Q(p[0]), Q(p[1]), Q(p[2]) };
}
QPt sub(const QPt& a, const QPt& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Q dot(const QPt& a, const QPt& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
QPt cross(const QPt& a, const QPt& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

// ---- Exact references --------------------------------------------------------------------------
int refOrient3d(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  const QPt qa = toQ(a);
  return sgn(dot(sub(toQ(b), qa), cross(sub(toQ(c), qa), sub(toQ(d), qa))));
}

// Circumcentre of the tetrahedron by Cramer's rule; inside <=> |e - o| < |a - o|.
int refInsphere(const Pt& a, const Pt& b, const Pt& c, const Pt& d, const Pt& e)
{
  const QPt qa = toQ(a);
  const QPt u = sub(toQ(b), qa), v = sub(toQ(c), qa), w = sub(toQ(d), qa), x = sub(toQ(e), qa);
  const Q det = dot(u, cross(v, w));
  if (sgn(det) == 0)
  {
    ADD_FAILURE() << "refInsphere on a flat tetrahedron";
    return 0;
  }
  // o - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 det)
  const QPt vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  QPt o;
  for (int k = 0; k < 3; ++k)
  {
    o[k] = (dot(u, u) * vw[k] + dot(v, v) * wu[k] + dot(w, w) * uv[k]) / (2 * det);
  }
  const QPt ex = sub(x, o);
  const Q power = dot(o, o) - dot(ex, ex); // r^2 - |e - o|^2 (a is the origin)
  return sgn(power) * sgn(det);
}

// Circumcentre of a triangle in 3D; d must be coplanar.
int refIncircle3d(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  const QPt qa = toQ(a);
  const QPt u = sub(toQ(b), qa), v = sub(toQ(c), qa), x = sub(toQ(d), qa);
  const QPt n = cross(u, v);
  const QPt vn = cross(v, n), nu = cross(n, u);
  const Q nn = dot(n, n);
  QPt o;
  for (int k = 0; k < 3; ++k)
  {
    o[k] = (dot(u, u) * vn[k] + dot(v, v) * nu[k]) / (2 * nn);
  }
  const QPt dx = sub(x, o);
  return sgn(dot(o, o) - dot(dx, dx));
}

int refOrient2dProjected(const Pt& a, const Pt& b, const Pt& c, int k)
{
  const QPt qa = toQ(a);
  return sgn(cross(sub(toQ(b), qa), sub(toQ(c), qa))[k]);
}

// ---- Helpers ---------------------------------------------------------------------------------------
int orient(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  return P::orient3d(a.data(), b.data(), c.data(), d.data());
}
int insph(const Pt& a, const Pt& b, const Pt& c, const Pt& d, const Pt& e)
{
  return P::insphere(a.data(), b.data(), c.data(), d.data(), e.data());
}
int incirc(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  return P::incircle3d(a.data(), b.data(), c.data(), d.data());
}
Pt affine(const Pt& p, double scale, double shift)
{
  return { p[0] * scale + shift, p[1] * scale + shift, p[2] * scale + shift };
}
Pt nudge(Pt p, int axis, int ulps)
{
  for (int i = 0; i < std::abs(ulps); ++i)
  {
    p[axis] = std::nextafter(p[axis], ulps > 0 ? HUGE_VAL : -HUGE_VAL);
  }
  return p;
}

const std::vector<Pt>& cube()
{
  static const std::vector<Pt> c = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };
  return c;
}

// Integer points on the sphere x^2 + y^2 + z^2 = 9: permutations and signs of (1,2,2) and (3,0,0).
std::vector<Pt> sphere9()
{
  std::vector<Pt> s;
  for (int k = 0; k < 3; ++k)
  {
    for (int sg : { -3, 3 })
    {
      Pt p = { 0, 0, 0 };
      p[k] = sg;
      s.push_back(p);
    }
    for (int s1 : { -1, 1 })
      for (int s2 : { -2, 2 })
        for (int s3 : { -2, 2 })
        {
          Pt p;
          p[k] = s1;
          p[(k + 1) % 3] = s2;
          p[(k + 2) % 3] = s3;
          s.push_back(p);
        }
  }
  return s;
}

int permutationParity(const std::array<int, 5>& p, int n)
{
  int inv = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      inv += p[i] > p[j];
  return (inv & 1) ? -1 : 1;
}

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
    auto randomExpansion = [&](double* h) {
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
  auto onSphere = [&](const Pt& c, double r) {
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
  auto wide = [&]() {
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
      ASSERT_EQ(P::orient2dProjected(p[0].data(), p[1].data(), p[2].data(), k), refOrient2dProjected(p[0], p[1], p[2], k));
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
    auto planePoint = [&](double pu, double pv) {
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
  auto onSphere = [&](const Pt& c, double r, const Pt& around, double spread) {
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
    EXPECT_GT(count[1][1], 1000);
  else
    EXPECT_EQ(count[1][1], 0);
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
    EXPECT_GT(count[1][1], 1000);
}

// ---- Simulation of Simplicity ------------------------------------------------------------------------------
int sos(const std::vector<Pt>& pts, const std::vector<int64_t>& ids, const std::array<int, 5>& v)
{
  return P::insphereSoS(pts[v[0]].data(), pts[v[1]].data(), pts[v[2]].data(), pts[v[3]].data(), pts[v[4]].data(),
    ids[v[0]], ids[v[1]], ids[v[2]], ids[v[3]], ids[v[4]]);
}

// Exact determinant of a 5x5 rational matrix (Gaussian elimination).
Q det5(std::array<std::array<Q, 5>, 5> m)
{
  Q det = 1;
  for (int c = 0; c < 5; ++c)
  {
    int piv = c;
    while (piv < 5 && sgn(m[piv][c]) == 0)
      ++piv;
    if (piv == 5)
      return 0;
    if (piv != c)
    {
      std::swap(m[piv], m[c]);
      det = -det;
    }
    det *= m[c][c];
    for (int r = c + 1; r < 5; ++r)
    {
      const Q f = m[r][c] / m[c][c];
      for (int k = c; k < 5; ++k)
        m[r][k] -= f * m[c][k];
    }
  }
  return det;
}

// The SoS definition taken literally, for integer points with small cofactors: lift_i = |p_i|^2 +
// delta^(rank_i), rank 1 for the largest id, with a concrete delta = 1/64 small enough for the leading
// term to dominate; insphere = -sign(det[p, lift, 1]).
int refInsphereSoS(const std::array<Pt, 5>& p, const std::array<int64_t, 5>& ids)
{
  std::array<std::array<Q, 5>, 5> m;
  for (int i = 0; i < 5; ++i)
  {
    int rank = 1;
    for (int j = 0; j < 5; ++j)
      rank += ids[j] > ids[i];
    Q delta = 1;
    for (int r = 0; r < rank; ++r)
      delta /= 64;
    const QPt q = toQ(p[i]);
    m[i] = { q[0], q[1], q[2], dot(q, q) + delta, Q(1) };
  }
  return -sgn(det5(m));
}

TEST(Predicates, InsphereSoSMatchesLiteralPerturbation)
{
  std::mt19937_64 rng(41);
  const auto& C = cube();
  std::uniform_int_distribution<int> pick(0, 7);
  std::uniform_int_distribution<int64_t> id(0, 1000000);
  int checked = 0;
  while (checked < 2000)
  {
    std::array<Pt, 5> p;
    std::array<int64_t, 5> ids;
    for (int i = 0; i < 5; ++i)
    {
      p[i] = C[pick(rng)];
      ids[i] = id(rng);
    }
    if (orient(p[0], p[1], p[2], p[3]) == 0 || std::set<int64_t>(ids.begin(), ids.end()).size() < 5 ||
      std::set<Pt>(p.begin(), p.end()).size() < 5)
      continue;
    ASSERT_EQ(P::insphereSoS(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), ids[0], ids[1],
                ids[2], ids[3], ids[4]),
      refInsphereSoS(p, ids));
    ++checked;
  }
}

TEST(Predicates, InsphereSoSNeverZeroAndAlternating)
{
  // insphereSoS is minus the sign of the perturbed, alternating 5x5 lifted determinant: it is never 0
  // and changes sign under every odd permutation of its five points (e swapped in included), as long as
  // the first four are not flat. Checked on the cube's 8 cospherical vertices with random ids.
  std::mt19937_64 rng(29);
  std::vector<Pt> pts = cube();
  for (double off : { 0.0, 1e9 })
  {
    std::vector<Pt> P8;
    for (const auto& p : pts)
      P8.push_back(affine(p, 1, off));
    for (int trial = 0; trial < 4; ++trial)
    {
      std::vector<int64_t> ids = { 10, 20, 30, 40, 50, 60, 70, 80 };
      std::shuffle(ids.begin(), ids.end(), rng);
      int checked = 0;
      for (int m = 0; m < 256; ++m)
      {
        if (__builtin_popcount(m) != 5)
          continue;
        std::array<int, 5> v;
        for (int i = 0, r = 0; i < 8; ++i)
          if (m & (1 << i))
            v[r++] = i;
        int base = 0;
        std::array<int, 5> perm = { 0, 1, 2, 3, 4 };
        do
        {
          const std::array<int, 5> w = { v[perm[0]], v[perm[1]], v[perm[2]], v[perm[3]], v[perm[4]] };
          if (orient(P8[w[0]], P8[w[1]], P8[w[2]], P8[w[3]]) == 0)
            continue;
          ASSERT_EQ(insph(P8[w[0]], P8[w[1]], P8[w[2]], P8[w[3]], P8[w[4]]), 0);
          const int s = sos(P8, ids, w);
          ASSERT_NE(s, 0);
          if (base == 0)
            base = s * permutationParity(perm, 5);
          ASSERT_EQ(s, base * permutationParity(perm, 5));
          ++checked;
        } while (std::next_permutation(perm.begin(), perm.end()));
      }
      EXPECT_GT(checked, 1000);
    }
  }
}

TEST(Predicates, InsphereSoSRuleAndAgreementWithExactSign)
{
  const Pt o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, z = { 0, 0, 1 }, e = { 1, 1, 1 };
  // Largest id on the query point: its lift is raised most, it counts as outside.
  EXPECT_EQ(P::insphereSoS(o.data(), x.data(), y.data(), z.data(), e.data(), 1, 2, 3, 4, 5), -1);
  EXPECT_EQ(P::insphereSoS(x.data(), o.data(), y.data(), z.data(), e.data(), 1, 2, 3, 4, 5), 1);
  // Largest id on a: the sign is that of -C_a = -orient3d(x, y, z, e) = -1 (see also the rational check
  // with an explicit small epsilon below).
  EXPECT_EQ(P::insphereSoS(o.data(), x.data(), y.data(), z.data(), e.data(), 9, 2, 3, 4, 5), -1);
  // Off the sphere, SoS agrees with the exact sign.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 1000; ++t)
  {
    std::array<Pt, 5> p;
    for (auto& q : p)
      q = { u(rng), u(rng), u(rng) };
    if (orient(p[0], p[1], p[2], p[3]) == 0)
      continue;
    const int s = insph(p[0], p[1], p[2], p[3], p[4]);
    ASSERT_EQ(P::insphereSoS(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), 5, 4, 3, 2, 1), s);
  }
}

TEST(Predicates, InsphereSoSFlip23ExactlyOneDelaunay)
{
  // Five cospherical points a,b,c,d,e with segment de through triangle abc admit two triangulations:
  // {abcd, abce} (2 tets) and {abde, bcde, cade} (3 tets). Under SoS exactly one is locally Delaunay
  // (every tet has the fifth point outside), for any assignment of ids.
  const auto S = sphere9();
  std::mt19937_64 rng(37);
  std::uniform_int_distribution<size_t> pick(0, S.size() - 1);
  auto outside = [&](Pt a, Pt b, Pt c, Pt d, const Pt& q, int64_t ia, int64_t ib, int64_t ic, int64_t id,
                   int64_t iq) {
    if (orient(a, b, c, d) < 0)
    {
      std::swap(a, b);
      std::swap(ia, ib);
    }
    return P::insphereSoS(a.data(), b.data(), c.data(), d.data(), q.data(), ia, ib, ic, id, iq) < 0;
  };
  int configs = 0;
  while (configs < 400)
  {
    const Pt a = S[pick(rng)], b = S[pick(rng)], c = S[pick(rng)], d = S[pick(rng)], e = S[pick(rng)];
    const int od = orient(a, b, c, d), oe = orient(a, b, c, e);
    if (od == 0 || oe == 0 || od == oe)
      continue;
    const int s1 = orient(d, e, a, b), s2 = orient(d, e, b, c), s3 = orient(d, e, c, a);
    if (s1 == 0 || s1 != s2 || s2 != s3)
      continue;
    std::array<int64_t, 5> id = { 1, 2, 3, 4, 5 };
    std::shuffle(id.begin(), id.end(), rng);
    const bool t2a = outside(a, b, c, d, e, id[0], id[1], id[2], id[3], id[4]);
    const bool t2b = outside(a, b, c, e, d, id[0], id[1], id[2], id[4], id[3]);
    const bool t3a = outside(a, b, d, e, c, id[0], id[1], id[3], id[4], id[2]);
    const bool t3b = outside(b, c, d, e, a, id[1], id[2], id[3], id[4], id[0]);
    const bool t3c = outside(c, a, d, e, b, id[2], id[0], id[3], id[4], id[1]);
    ASSERT_EQ(t2a, t2b);
    ASSERT_EQ(t3a, t3b);
    ASSERT_EQ(t3b, t3c);
    ASSERT_NE(t2a, t3a) << "exactly one of the two triangulations is Delaunay";
    ++configs;
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
  return P::detail::orient3dExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), true, &stage,
    fixedPoint);
}
int stagedInsphereFixed(const std::array<Pt, 5>& p, bool fixedPoint, int& stage)
{
  return P::detail::insphereExactStaged(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), true,
    &stage, fixedPoint);
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
  const Grid grids[] = { { 0, 0, 100, true }, { 0, 0, 40, true }, { 0.3, 0.01, 100, false },
    { -1.7, 1.0 / 7.0, 30, false }, { 1234.5, 0.1, 50, false }, { -2e-3, 1e-4 / 3.0, 60, false } };
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
  const double big61 = std::ldexp(double((uint64_t(1) << 53) - 1), 8);  // 2^61 - 2^8, top bit 2^60
  const double big62 = std::ldexp(double((uint64_t(1) << 53) - 1), 9);  // top bit 2^61: span 62
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
      EXPECT_EQ(localFixed, 0) << "a 62-bit span must take the expansion path";
    else
      EXPECT_GT(localFixed, 2000);
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

TEST(Predicates, InsphereSoSOnNonDyadicGridBoxes)
{
  // The SoS tie-break (orient3d cofactors, also decided by the fixed-point stage) on exactly cospherical
  // corners of i/99 grid boxes agrees with the literal perturbation.
  std::mt19937_64 rng(67);
  std::uniform_int_distribution<int> cell(0, 97), pick(0, 7);
  std::uniform_int_distribution<int64_t> id(0, 1000000);
  int checked = 0;
  while (checked < 2000)
  {
    const int i0 = cell(rng), j0 = cell(rng), k0 = cell(rng);
    std::array<Pt, 5> p;
    std::array<int64_t, 5> ids;
    for (int i = 0; i < 5; ++i)
    {
      const int c = pick(rng);
      p[i] = { (i0 + (c & 1)) / 99.0, (j0 + ((c >> 1) & 1)) / 99.0, (k0 + ((c >> 2) & 1)) / 99.0 };
      ids[i] = id(rng);
    }
    if (orient(p[0], p[1], p[2], p[3]) == 0 || std::set<int64_t>(ids.begin(), ids.end()).size() < 5 ||
      std::set<Pt>(p.begin(), p.end()).size() < 5)
      continue;
    ASSERT_EQ(insph(p[0], p[1], p[2], p[3], p[4]), 0);
    ASSERT_EQ(P::insphereSoS(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), ids[0], ids[1],
                ids[2], ids[3], ids[4]),
      refInsphereSoS(p, ids));
    ++checked;
  }
}
