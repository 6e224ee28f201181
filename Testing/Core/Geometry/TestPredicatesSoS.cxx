// Tests of insphereSoS (Simulation of Simplicity, Predicates.h): never 0, alternating, the literal
// perturbation rule against rationals, and exactly one Delaunay triangulation of five cospherical points.
// Separate from TestPredicates.cxx because they test the tie-break, not exact signs.
#include "Predicates.h"
#include "PredicatesTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace predicates_test;

namespace
{
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
    ASSERT_EQ(P::insphereSoS(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), ids[0], ids[1], ids[2],
                             ids[3], ids[4]),
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
  auto outside = [&](Pt a, Pt b, Pt c, Pt d, const Pt& q, int64_t ia, int64_t ib, int64_t ic, int64_t id, int64_t iq)
  {
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
    ASSERT_EQ(P::insphereSoS(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), ids[0], ids[1], ids[2],
                             ids[3], ids[4]),
              refInsphereSoS(p, ids));
    ++checked;
  }
}
