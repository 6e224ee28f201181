// Exact orient3d and insphere, the adaptive path taken when the filters of PredicatesInline.h cannot
// decide: the fixed-point stage (PredicatesFixed.h), the long double filter, then expansion stages B
// and C on the rounded differences and the full evaluation over the raw coordinates (the big-integer
// fallback of PredicatesWide.cxx for extreme exponents). Separate from Predicates.cxx (the filtered
// entry points, orient2d / incircle3d, the SoS rule) because these stages, their bounds and their large
// stack frames form one piece of numerical analysis, only reached through detail::*Exact.
#include "PredicatesInline.h"

#include "ExpansionArithmetic.h"
#include "PredicatesFixed.h"
#include "PredicatesInternal.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace volgrid
{
namespace predicates
{
namespace
{
using namespace internal; // and expansion::, which internal uses
using detail::kEps;

// ---------------------------------------------------------------------------------------------------
// Adaptive stages on rounded differences (the idea of Shewchuk's stages B and C; the bounds below are
// derived for this code's own evaluation order).
//
// The exact paths work on points scaled into the window of scaleInto, with u = 2^-53. A determinant D
// of degree k in the coordinate differences d = p - o is a signed sum of monomials, each a product of
// k difference factors (|q|^2 = x^2 + y^2 + z^2 counts as two factors per monomial). Write
// a = fl(d) (the rounded difference) and t = d - a (its tail, exact by twoDiff). Then |t| <= u |a|:
// round to nearest, and no underflow (see below). Let P = sum of |monomials| at a, and P~ the same sum
// evaluated in doubles by a tree of depth n_P over nonnegative values, so P <= P~ / (1 - u)^n_P.
//   * Every monomial at d is the monomial at a times prod_j (1 + theta_j), |theta_j| <= u, so
//       |D(d) - D(a)| <= ((1 + u)^k - 1) P.                                               (B)
//   * Expanding the product, D(d) = D(a) + L + R with L = sum over monomials and factors of the
//     monomial with that factor replaced by its tail (first order), and
//       |R| <= ((1 + u)^k - 1 - k u) P.
//     The absolute-value tree of L (each of its products is a monomial of D with one factor replaced by
//     a tail) is at most k u P, so evaluating L in doubles by a tree of depth n_L gives L~ with
//       |L - L~| <= gamma(n_L) k u P,   gamma(n) = n u / (1 - n u).                     (C)
// Stage B: D(a) exactly (expansions). If |D(a)| > bound(B) the sign is D(a)'s.
// Stage C: S = D(a) + L~ exactly. If |S| > bound(C) >= |L - L~| + |R| the sign is S's.
// Both comparisons are exact: the sign of |E| - bound is that of the expansion E - sign(E) bound.
// The bounds are computed as fl(c * P~) + 2^-1073 with c >= (the constant above) * (1 + 2 n_P u) / (1 - u),
// which covers the rounding of the product, also if it is subnormal.
// No underflow: after scaling every coordinate is a multiple of 2^minLow with minLow = -960 / k, hence
// so are the differences and the tails; a product of j <= k such values is a multiple of 2^(j minLow),
// and rounding keeps that (the grid of a double at least as coarse as 2^(j minLow) is made of its
// multiples, a finer grid contains the value). So every nonzero intermediate value of stages B and C is
// >= 2^-960, a normal number, and the relative model of rounding holds everywhere.

// |e| > bound, exactly (bound >= 0). `scratch` holds n + 1 doubles.
inline bool magnitudeExceeds(int n, const double* e, double bound, double* scratch)
{
  const int s = expansionSign(n, e);
  if (s == 0)
  {
    return false;
  }
  const double b = s > 0 ? -bound : bound;
  const int m = sumExpansions(n, e, 1, &b, scratch);
  return expansionSign(m, scratch) == s;
}

inline double dot3(const double* a, const double* b)
{
  return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
}

inline void cross3(const double* a, const double* b, double* c)
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

inline double absDot3(const double* a, const double* b)
{
  return (std::fabs(a[0] * b[0]) + std::fabs(a[1] * b[1])) + std::fabs(a[2] * b[2]);
}

// Permanent of a . (b x c) evaluated with the tree of the filter (depth 5).
inline double absTriple(const double* a, const double* b, const double* c)
{
  return (std::fabs(a[0]) * (std::fabs(b[1] * c[2]) + std::fabs(b[2] * c[1])) +
          std::fabs(a[1]) * (std::fabs(b[2] * c[0]) + std::fabs(b[0] * c[2]))) +
    std::fabs(a[2]) * (std::fabs(b[0] * c[1]) + std::fabs(b[1] * c[0]));
}

// ---------------------------------------------------------------------------------------------------
// Extended-precision filter (first step of the exact paths of orient3d and insphere).
//
// Where long double has a wider significand than double (x87 80-bit: 64 bits), the determinant is
// evaluated once more in long double, from the raw input doubles, with the tree of the double filter.
// The error analysis of the double filter (header of Predicates.cxx) holds with the unit roundoff
// uL = 2^-digits of long double: every monomial of the exact determinant (in the exact differences)
// comes out multiplied by at most n factors (1 + delta), |delta| <= uL, n = 8 for orient3d and 16 for
// insphere (the roundings on the union of the monomial's paths, differences included), so
//   |det~ - det| <= gamma(n) P,  P = sum of |monomials| at the exact differences,
// and the permanent P~ computed from the rounded differences with absolute values satisfies
// P <= P~ / (1 - uL)^n. The test |det~| > c P~ with c = (n + 1) uL covers both and the rounding of c P~.
// Exponent range: long double has 15 exponent bits, so products of up to five doubles (or of their
// differences, multiples of 2^-1074) can neither overflow nor underflow: no scaling is needed.
// Where long double is no wider than double (e.g. MSVC), or the x87 precision control has been set
// below the advertised significand (checked once at run time), the step is skipped. Decides nearly all
// of the uncertain calls of near-cospherical inputs for ~100 ns instead of microseconds of expansions.

using LD = long double;
constexpr int kLDDigits = std::numeric_limits<LD>::digits;

bool extendedPrecisionUsable()
{
  static const bool usable = []
  {
    if (kLDDigits < 60)
    {
      return false;
    }
    // The arithmetic really rounds to kLDDigits bits (not, e.g., to 53 under a reduced precision control).
    volatile LD one = 1.0L;
    volatile LD tiny = std::ldexp(1.0L, -(kLDDigits - 1));
    volatile LD half = std::ldexp(1.0L, -kLDDigits);
    const LD a = one + tiny;          // representable: must differ from 1
    const LD b = one + half;          // a tie: rounds to even, i.e. to 1
    const LD c = (one + tiny) + half; // a tie above an odd significand: rounds up
    return a != one && b == one && c == one + 2 * tiny;
  }();
  return usable;
}

constexpr LD unitRoundoffLD()
{
  LD x = 1;
  for (int i = 0; i < kLDDigits; ++i)
  {
    x /= 2;
  }
  return x;
}
constexpr LD kUnitLD = unitRoundoffLD();

// 1 / -1 when certain, 0 when not decided.
int orient3dExtended(const double* a, const double* b, const double* c, const double* d)
{
  const LD ux = LD(b[0]) - a[0], uy = LD(b[1]) - a[1], uz = LD(b[2]) - a[2];
  const LD vx = LD(c[0]) - a[0], vy = LD(c[1]) - a[1], vz = LD(c[2]) - a[2];
  const LD wx = LD(d[0]) - a[0], wy = LD(d[1]) - a[1], wz = LD(d[2]) - a[2];
  const LD vywz = vy * wz, vzwy = vz * wy, vzwx = vz * wx, vxwz = vx * wz, vxwy = vx * wy, vywx = vy * wx;
  const LD det = (ux * (vywz - vzwy) + uy * (vzwx - vxwz)) + uz * (vxwy - vywx);
  const LD perm =
    (std::fabs(ux) * (std::fabs(vywz) + std::fabs(vzwy)) + std::fabs(uy) * (std::fabs(vzwx) + std::fabs(vxwz))) +
    std::fabs(uz) * (std::fabs(vxwy) + std::fabs(vywx));
  const LD bound = (9 * kUnitLD) * perm;
  return det > bound ? 1 : (-det > bound ? -1 : 0);
}

// Sign of D = det[p - e, |p - e|^2] (insphere = -sign(D)) when certain, 0 when not decided.
int insphereDExtended(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const detail::InsphereTerms<LD> t = detail::insphereTerms<LD>(a, b, c, d, e);
  const LD det = t.det;
  const LD perm = t.permanent();
  const LD bound = (17 * kUnitLD) * perm;
  return det > bound ? 1 : (-det > bound ? -1 : 0);
}

// Which stage decided (detail::*ExactStaged): see PredicatesInline.h.
enum Stage
{
  kStageExtended = 1,
  kStageExactDifferences = 2,
  kStageB = 3,
  kStageC = 4,
  kStageFull = 5,
  kStageWide = 6,
  kStageFixed = 7
};

inline int report(int* stage, int s, int sign)
{
  if (stage)
  {
    *stage = s;
  }
  return sign;
}

// ---------------------------------------------------------------------------------------------------
// Exact orient3d: det[u; v; w], u = b - a, v = c - a, w = d - a (degree k = 3).
//   P~ = absTriple(u, v, w), depth n_P = 5.
//   bound(B): (1+u)^3 - 1 = 3u + 3u^2 + u^3; with (1 + 10u)/(1 - u): <= (3 + 34 u) u  -> c = (3 + 64u) u.
//   L = t_u . (v x w) + t_v . (w x u) + t_w . (u x v): cross 2, dot 3, two sums: depth n_L = 7.
//   bound(C): 7u/(1-7u) * 3u + 3u^2 + u^3 <= 24.01 u^2; with (1 + 10u)/(1 - u): c = 26 u^2.

constexpr int kOrient3dTop = 330; // |det| <= 24 M^3 < 2^1023
constexpr int kOrient3dLow = -320;
constexpr double kOrient3dBoundB = (3.0 + 64.0 * kEps) * kEps;
constexpr double kOrient3dBoundC = 26.0 * kEps * kEps;
constexpr double kTiny = 0x1p-1073;

int orient3dExactImpl(const double* a, const double* b, const double* c, const double* d, bool extended,
                      bool fixedPoint, int* stage)
{
  int fixedSign;
  if (fixedPoint && fixedpoint::orient3d(a, b, c, d, &fixedSign))
  {
    return report(stage, kStageFixed, fixedSign);
  }
  if (extended && extendedPrecisionUsable())
  {
    const int s = orient3dExtended(a, b, c, d);
    if (s != 0)
    {
      return report(stage, kStageExtended, s);
    }
  }
  const double* in[4] = { a, b, c, d };
  double p[4][3];
  if (!scaleInto(in, 4, kOrient3dTop, kOrient3dLow, p))
  {
    return report(stage, kStageWide, orient3dWide(in));
  }

  // Rounded differences and their tails.
  double u[3][3], t[3][3];
  bool exact = true;
  for (int r = 0; r < 3; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      twoDiff(p[r + 1][k], p[0][k], u[r][k], t[r][k]);
      exact = exact && t[r][k] == 0.0;
    }
  }
  // Stage B (exact when the differences are): det[u; v; w] of single doubles (<= 24 components).
  Exp<4> m01, m02, m12;
  minor2(u[0][0], u[0][1], u[1][0], u[1][1], m01);
  minor2(u[0][0], u[0][1], u[2][0], u[2][1], m02);
  minor2(u[1][0], u[1][1], u[2][0], u[2][1], m12);
  Exp<24> det;
  det3FromMinors(u[0][2], u[1][2], u[2][2], m12, m02, m01, det);
  if (exact)
  {
    return report(stage, kStageExactDifferences, expansionSign(det.n, det.v));
  }
  const double perm = absTriple(u[0], u[1], u[2]);
  double scratch[26];
  if (magnitudeExceeds(det.n, det.v, kOrient3dBoundB * perm + kTiny, scratch))
  {
    return report(stage, kStageB, expansionSign(det.n, det.v));
  }
  // Stage C: first-order correction.
  double vw[3], wu[3], uv[3];
  cross3(u[1], u[2], vw);
  cross3(u[2], u[0], wu);
  cross3(u[0], u[1], uv);
  const double first = (dot3(t[0], vw) + dot3(t[1], wu)) + dot3(t[2], uv);
  double s[26];
  const int sn = sumExpansions(det.n, det.v, 1, &first, s);
  if (magnitudeExceeds(sn, s, kOrient3dBoundC * perm + kTiny, scratch))
  {
    return report(stage, kStageC, expansionSign(sn, s));
  }

  // Full exact evaluation over the raw coordinates.
  Minors m;
  m.computePairs(p, 4);
  m.computeTriple(p, 1, 2, 3);
  m.computeTriple(p, 0, 2, 3);
  m.computeTriple(p, 0, 1, 3);
  m.computeTriple(p, 0, 1, 2);
  double o[96];
  const int n = orientFromTriples(m, 0, 1, 2, 3, o);
  return report(stage, kStageFull, expansionSign(n, o));
}

// ---------------------------------------------------------------------------------------------------
// Exact insphere. The lifted determinant
//   L = det | p_i  |p_i|^2  1 |_{i = a,b,c,d,e}   (5x5)
// equals D = det[p'_i, |p'_i|^2]_{i=a..d} with p' = p - e (subtract row e, then use that the lifted
// column differs from |p'|^2 by a combination of the coordinate columns). Raising the lift of e raises L
// by the cofactor orient3d(a,b,c,d) > 0 (positive tet) and moves e outside, so inside <=> L < 0 and
// insphere = -sign(L).
//
// With rows q_0..q_3 = p' and w_i = |q_i|^2, M_i = det3 of the other three rows (in increasing order):
//   D = -w_0 M_0 + w_1 M_1 - w_2 M_2 + w_3 M_3    (degree k = 5).
// P~ = sum_i w_i |M_i|~ with the filter's tree (depth n_P = 8: products 1, pair sums 2, z products 3,
// minor sums 5, times w 6, two sums 8; w itself 3).
//   bound(B): (1+u)^5 - 1 <= 5u + 10.01 u^2; with (1 + 16u)/(1 - u): <= (5 + 96 u) u -> c = (5 + 128u) u.
//   L = sum_i +-(tw_i M_i + w_i dM_i), tw_i = 2 q_i . t_i (first order of w_i), dM_i the first order of
//   M_i: for rows (p, q, r), dM = t_p . (q x r) + t_q . (r x p) + t_r . (p x q). Depths: cross 2,
//   dot with a tail 5, dM 7, w dM 8; M 5, tw 3, tw M 6; term 9; sum of four 11: n_L = 11. The absolute
//   tree of term i is <= (2u + 3u) w_i |M_i|, so the one of L is <= 5u P as stated above.
//   bound(C): 11u/(1-11u) * 5u + ((1+u)^5 - 1 - 5u) <= 65.01 u^2; with (1 + 16u)/(1 - u): c = 66 u^2.

constexpr int kInsphereTop = 200; // |L| <= 360 M^5 < 2^1023, components <= 24 M^3 < 2^995 for split
constexpr int kInsphereLow = -192;
constexpr double kInsphereBoundB = (5.0 + 128.0 * kEps) * kEps;
constexpr double kInsphereBoundC = 66.0 * kEps * kEps;

int insphereRaw(const double (*p)[3]);

// D of single-double rows q (exact differences or rounded ones), exactly. h holds 1152 doubles.
int insphereFromRows(const double (*q)[3], double* h)
{
  Minors m;
  m.computePairs(q, 4);
  m.computeTriple(q, 1, 2, 3);
  m.computeTriple(q, 0, 2, 3);
  m.computeTriple(q, 0, 1, 3);
  m.computeTriple(q, 0, 1, 2);
  const Exp<24>* minors[4] = { &m.triple(1, 2, 3), &m.triple(0, 2, 3), &m.triple(0, 1, 3), &m.triple(0, 1, 2) };
  double terms[4][288];
  int tn[4];
  double scratch[multiplyScratchSize(24, 6)];
  for (int i = 0; i < 4; ++i)
  {
    Exp<6> w;
    squaredNorm(q[i], w);
    const Exp<24>& t = *minors[i];
    tn[i] = multiplyExpansions(t.n, t.v, w.n, w.v, terms[i], scratch);
    if ((i & 1) == 0)
    {
      negateExpansion(tn[i], terms[i], terms[i]);
    }
  }
  double s01[576], s23[576];
  const int n01 = sumExpansions(tn[0], terms[0], tn[1], terms[1], s01);
  const int n23 = sumExpansions(tn[2], terms[2], tn[3], terms[3], s23);
  return sumExpansions(n01, s01, n23, s23, h);
}

// P~ (see above).
double inspherePermanent(const double (*q)[3])
{
  double w[4], am[4];
  for (int i = 0; i < 4; ++i)
  {
    w[i] = (q[i][0] * q[i][0] + q[i][1] * q[i][1]) + q[i][2] * q[i][2];
  }
  am[0] = absTriple(q[1], q[2], q[3]);
  am[1] = absTriple(q[0], q[2], q[3]);
  am[2] = absTriple(q[0], q[1], q[3]);
  am[3] = absTriple(q[0], q[1], q[2]);
  return (w[0] * am[0] + w[1] * am[1]) + (w[2] * am[2] + w[3] * am[3]);
}

// L~ (see above).
double insphereFirstOrder(const double (*q)[3], const double (*t)[3])
{
  double cr[4][4][3]; // cr[j][k] = q_j x q_k, j < k
  for (int j = 0; j < 4; ++j)
  {
    for (int k = j + 1; k < 4; ++k)
    {
      cross3(q[j], q[k], cr[j][k]);
    }
  }
  double term[4];
  for (int i = 0; i < 4; ++i)
  {
    int r3[3];
    for (int j = 0, n = 0; j < 4; ++j)
    {
      if (j != i)
      {
        r3[n++] = j;
      }
    }
    const int a = r3[0], b = r3[1], c = r3[2];
    const double M = dot3(q[a], cr[b][c]);
    // t_b . (c x a) = -t_b . (a x c)
    const double dM = (dot3(t[a], cr[b][c]) - dot3(t[b], cr[a][c])) + dot3(t[c], cr[a][b]);
    const double w = (q[i][0] * q[i][0] + q[i][1] * q[i][1]) + q[i][2] * q[i][2];
    const double tw = 2.0 * ((q[i][0] * t[i][0] + q[i][1] * t[i][1]) + q[i][2] * t[i][2]);
    term[i] = tw * M + w * dM;
  }
  return (term[1] - term[0]) + (term[3] - term[2]);
}

int insphereExactImpl(const double* a, const double* b, const double* c, const double* d, const double* e,
                      bool extended, bool fixedPoint, int* stage)
{
  int fixedSign;
  if (fixedPoint && fixedpoint::insphere(a, b, c, d, e, &fixedSign))
  {
    return report(stage, kStageFixed, fixedSign);
  }
  if (extended && extendedPrecisionUsable())
  {
    const int s = insphereDExtended(a, b, c, d, e);
    if (s != 0)
    {
      return report(stage, kStageExtended, -s);
    }
  }
  const double* in[5] = { a, b, c, d, e };
  double p[5][3];
  if (!scaleInto(in, 5, kInsphereTop, kInsphereLow, p))
  {
    return report(stage, kStageWide, insphereWide(in));
  }

  double q[4][3], t[4][3];
  bool exact = true;
  for (int i = 0; i < 4; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      twoDiff(p[i][k], p[4][k], q[i][k], t[i][k]);
      exact = exact && t[i][k] == 0.0;
    }
  }
  // Stage B (exact when the differences are).
  double det[1152];
  const int n = insphereFromRows(q, det);
  if (exact)
  {
    return report(stage, kStageExactDifferences, -expansionSign(n, det));
  }
  const double perm = inspherePermanent(q);
  double scratch[1154];
  if (magnitudeExceeds(n, det, kInsphereBoundB * perm + kTiny, scratch))
  {
    return report(stage, kStageB, -expansionSign(n, det));
  }
  // Stage C: first-order correction.
  const double first = insphereFirstOrder(q, t);
  double s[1153];
  const int sn = sumExpansions(n, det, 1, &first, s);
  if (magnitudeExceeds(sn, s, kInsphereBoundC * perm + kTiny, scratch))
  {
    return report(stage, kStageC, -expansionSign(sn, s));
  }
  return report(stage, kStageFull, insphereRaw(p));
}

// Stage 2 of insphereExactImpl (kept out of line: its frame is ~120 KB of expansions), on the scaled
// points: L = sum_i C_i |p_i|^2 with the cofactors of the lifted column
//   C_i = (-1)^i * O(the other four points in order)   (i = 0..4 for a..e).
#if defined(__GNUC__)
__attribute__((noinline))
#endif
int insphereRaw(const double (*p)[3])
{
  Minors m;
  m.computePairs(p, 5);
  for (int i = 0; i < 5; ++i)
  {
    for (int j = i + 1; j < 5; ++j)
    {
      for (int k = j + 1; k < 5; ++k)
      {
        m.computeTriple(p, i, j, k);
      }
    }
  }
  double acc[2][5760];
  int accLen = 0;
  int cur = 0;
  for (int i = 0; i < 5; ++i)
  {
    int idx[4];
    for (int j = 0, r = 0; j < 5; ++j)
    {
      if (j != i)
      {
        idx[r++] = j;
      }
    }
    double cof[96];
    int cn = orientFromTriples(m, idx[0], idx[1], idx[2], idx[3], cof);
    if (i & 1)
    {
      negateExpansion(cn, cof, cof);
    }
    Exp<6> w;
    squaredNorm(p[i], w);
    double term[1152];
    double scratch[multiplyScratchSize(96, 6)];
    const int tn = multiplyExpansions(cn, cof, w.n, w.v, term, scratch);
    if (i == 0)
    {
      std::memcpy(acc[cur], term, sizeof(double) * tn);
      accLen = tn;
    }
    else
    {
      accLen = sumExpansions(accLen, acc[cur], tn, term, acc[1 - cur]);
      cur = 1 - cur;
    }
  }
  return -expansionSign(accLen, acc[cur]);
}

} // namespace

// ---------------------------------------------------------------------------------------------------

namespace detail
{
int orient3dExact(const double* a, const double* b, const double* c, const double* d)
{
  return orient3dExactImpl(a, b, c, d, true, true, nullptr);
}

int insphereExact(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  return insphereExactImpl(a, b, c, d, e, true, true, nullptr);
}

int orient3dExactStaged(const double* a, const double* b, const double* c, const double* d, bool extended, int* stage,
                        bool fixedPoint)
{
  return orient3dExactImpl(a, b, c, d, extended, fixedPoint, stage);
}

int insphereExactStaged(const double* a, const double* b, const double* c, const double* d, const double* e,
                        bool extended, int* stage, bool fixedPoint)
{
  return insphereExactImpl(a, b, c, d, e, extended, fixedPoint, stage);
}
} // namespace detail

} // namespace predicates
} // namespace volgrid
