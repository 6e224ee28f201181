// Internal helpers of the exact predicates, shared by Predicates.cxx, PredicatesAdaptive.cxx and
// PredicatesWide.cxx. Private to Core (not part of the API; Predicates.h and PredicatesInline.h are).
//
// Kept in a header, inline, because the exact paths of every predicate call them: the fixed-capacity
// expansion type, the scaling of the inputs into the safe exponent window, the exact 2x2 / 3x3 minors
// over plain doubles, and the entry points of the big-integer fallback (PredicatesWide.cxx) for inputs
// that do not fit the window.
#pragma once

#include "ExpansionArithmetic.h"

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace volgrid
{
namespace predicates
{
namespace internal
{
using namespace expansion;

// A small fixed-capacity expansion (stack storage; no allocation anywhere in the predicates).
template<int N>
struct Exp
{
  double v[N];
  int n = 0;
};

// ---------------------------------------------------------------------------------------------------
// Scaling into the safe exponent window.

// Exponents of the largest and of the lowest set bit over a set of doubles (zeros ignored).
struct BitRange
{
  int top = INT_MIN; // floor(log2 |x|) of the largest |x|
  int low = INT_MAX; // exponent of the least significant set bit over all x
};

inline int countTrailingZeros(uint64_t m)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(m);
#else
  int n = 0;
  while ((m & 1u) == 0)
  {
    m >>= 1;
    ++n;
  }
  return n;
#endif
}

inline int floorLog2(uint64_t m)
{
  int n = -1;
  while (m)
  {
    m >>= 1;
    ++n;
  }
  return n;
}

inline void includeInRange(BitRange& r, double x)
{
  if (x == 0.0)
  {
    return;
  }
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  uint64_t mant = bits & ((uint64_t(1) << 52) - 1);
  int top;
  int low;
  if (biased == 0)
  { // subnormal: mant * 2^-1074
    top = -1074 + floorLog2(mant);
    low = -1074 + countTrailingZeros(mant);
  }
  else
  {
    mant |= uint64_t(1) << 52;
    top = biased - 1023;
    low = biased - 1075 + countTrailingZeros(mant);
  }
  r.top = top > r.top ? top : r.top;
  r.low = low < r.low ? low : r.low;
}

// Copies n points into out, scaled by a power of two chosen so that every coordinate x satisfies
// |x| < 2^(maxTop+1) and has no set bit below 2^minLow. For a determinant of degree k the caller picks
// maxTop so that no partial result can overflow (nor the splitter, 2^27 x), and minLow = -960/k so
// that every nonzero product of components has magnitude >= 2^-960, where two-product is exact.
// Returns false when the inputs span more bits than the window (only for absurd mixes such as 1e-300
// and 1e+300 in one call); the caller then uses the big-integer path below.
inline bool scaleInto(const double* const* pts, int n, int maxTop, int minLow, double (*out)[3])
{
  BitRange r;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      includeInRange(r, pts[i][k]);
    }
  }
  int shift = 0;
  bool exact = true;
  if (r.top != INT_MIN && (r.top > maxTop || r.low < minLow))
  {
    shift = maxTop - r.top;
    exact = r.low + shift >= minLow;
  }
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      out[i][k] = shift ? std::ldexp(pts[i][k], shift) : pts[i][k];
    }
  }
  return exact;
}

// ---------------------------------------------------------------------------------------------------
// Exact building blocks over points given as plain doubles (raw coordinates or exact differences).

// p[i] * q[j] - q[i] * p[j], exactly (<= 4 components).
inline void minor2(double pi, double pj, double qi, double qj, Exp<4>& h)
{
  double a1, a0, b1, b0;
  twoProduct(pi, qj, a1, a0);
  twoProduct(qi, pj, b1, b0);
  const double e[2] = { a0, a1 };
  const double f[2] = { -b0, -b1 };
  h.n = sumExpansions(2, e, 2, f, h.v);
}

// det of rows p,q,r (columns x,y,z) expanded along z: pz*m(q,r) - qz*m(p,r) + rz*m(p,q), with the xy
// minors given. <= 24 components.
inline void det3FromMinors(double pz, double qz, double rz, const Exp<4>& mqr, const Exp<4>& mpr, const Exp<4>& mpq,
                           Exp<24>& h)
{
  double t1[8], t2[8], t3[8], t12[16];
  const int n1 = scaleExpansion(mqr.n, mqr.v, pz, t1);
  const int n2 = scaleExpansion(mpr.n, mpr.v, -qz, t2);
  const int n3 = scaleExpansion(mpq.n, mpq.v, rz, t3);
  const int n12 = sumExpansions(n1, t1, n2, t2, t12);
  h.n = sumExpansions(n12, t12, n3, t3, h.v);
}

// |p|^2 exactly (<= 6 components).
inline void squaredNorm(const double* p, Exp<6>& h)
{
  double x[2], y[2], z[2], xy[4];
  twoSquare(p[0], x[1], x[0]);
  twoSquare(p[1], y[1], y[0]);
  twoSquare(p[2], z[1], z[0]);
  const int nxy = sumExpansions(2, x, 2, y, xy);
  h.n = sumExpansions(nxy, xy, 2, z, h.v);
}

// Index of the xy minor of points i < j among 5, and of the triple i < j < k (bit masks keep it simple).
inline int pairMask(int i, int j)
{
  return (1 << i) | (1 << j);
}

// All xy minors and z-expanded 3x3 determinants among up to 5 points (raw coordinates).
struct Minors
{
  Exp<4> m2[32];  // by pair mask
  Exp<24> m3[32]; // by triple mask

  void computePairs(const double (*p)[3], int n)
  {
    for (int i = 0; i < n; ++i)
    {
      for (int j = i + 1; j < n; ++j)
      {
        minor2(p[i][0], p[i][1], p[j][0], p[j][1], m2[pairMask(i, j)]);
      }
    }
  }
  // det3 of rows p[i], p[j], p[k] in that order, i < j < k.
  void computeTriple(const double (*p)[3], int i, int j, int k)
  {
    det3FromMinors(p[i][2], p[j][2], p[k][2], m2[pairMask(j, k)], m2[pairMask(i, k)], m2[pairMask(i, j)],
                   m3[pairMask(i, j) | (1 << k)]);
  }
  const Exp<24>& triple(int i, int j, int k) const { return m3[(1 << i) | (1 << j) | (1 << k)]; }
};

// Orientation determinant O(q0,q1,q2,q3) = det[q1-q0; q2-q0; q3-q0] of the points with indices
// i < j < k < l, from the 3x3 determinants of raw coordinates:
//   O = det3(j,k,l) - det3(i,k,l) + det3(i,j,l) - det3(i,j,k)   (<= 96 components)
// (expand det[q 1] along the column of ones; det[q 1] = -O).
inline int orientFromTriples(const Minors& m, int i, int j, int k, int l, double* h)
{
  double neg[24], s1[48], s2[48];
  const Exp<24>& jkl = m.triple(j, k, l);
  const Exp<24>& ikl = m.triple(i, k, l);
  const Exp<24>& ijl = m.triple(i, j, l);
  const Exp<24>& ijk = m.triple(i, j, k);
  negateExpansion(ikl.n, ikl.v, neg);
  const int n1 = sumExpansions(jkl.n, jkl.v, ikl.n, neg, s1);
  negateExpansion(ijk.n, ijk.v, neg);
  const int n2 = sumExpansions(ijl.n, ijl.v, ijk.n, neg, s2);
  return sumExpansions(n1, s1, n2, s2, h);
}

// ---------------------------------------------------------------------------------------------------
// Exact big-integer evaluations (PredicatesWide.cxx), for the inputs scaleInto rejects. Same signs as
// the predicates: orient3d, insphere, the orientation in the (i, j) plane, and the incircle determinant
// E of incircleDeterminantExact (Predicates.cxx).
int orient3dWide(const double* const* in);
int insphereWide(const double* const* in);
int orient2dWide(const double* const* in, int i, int j);
int incircleDeterminantWide(const double* const* in, int i, int j);

} // namespace internal
} // namespace predicates
} // namespace volgrid
