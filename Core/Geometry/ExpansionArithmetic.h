// Floating-point expansion arithmetic (exact sums and products of doubles), after the theory of
// D. Priest and J. R. Shewchuk ("Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", 1997). Written for VolGrid's exact predicates (Predicates.cxx).
//
// An expansion is an array of doubles e[0..n) whose exact (real) sum is the value it represents. All
// expansions produced here are nonoverlapping and sorted by increasing magnitude, with zero components
// removed ("zero elimination"), so the last component carries the sign and approximates the value.
// A zero value is represented by the single component 0.
//
// Requirements (checked by the tests, relied upon by the proofs):
//   * IEEE-754 binary64 with round-to-nearest-even (no x87 extended precision: x86-64 uses SSE2);
//   * no fused multiply-add contraction: compile users with -ffp-contract=off (Core does). A compiler
//     that fuses `x = a*b` into a later `x - p` would break twoProduct. split() is written so that
//     even a contracted form gives the same result, but the rest is not;
//   * no overflow, and no underflow that loses bits: every product formed must have magnitude in
//     roughly [2^-960, 2^995]. Predicates.cxx guarantees this by scaling its inputs by a power of two.
#pragma once

#include <cmath>

namespace volgrid
{
namespace expansion
{

// x + y == a + b exactly, x = fl(a + b). Any a, b (Knuth).
inline void twoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bVirtual = x - a;
  const double aVirtual = x - bVirtual;
  const double bRound = b - bVirtual;
  const double aRound = a - aVirtual;
  y = aRound + bRound;
}

// Same as twoSum but requires |a| >= |b| (or a == 0): three flops instead of six (Dekker).
inline void fastTwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bVirtual = x - a;
  y = b - bVirtual;
}

// x + y == a - b exactly, x = fl(a - b).
inline void twoDiff(double a, double b, double& x, double& y)
{
  x = a - b;
  const double bVirtual = a - x;
  const double aVirtual = x + bVirtual;
  const double bRound = bVirtual - b;
  const double aRound = a - aVirtual;
  y = aRound + bRound;
}

// a == hi + lo with hi and lo each fitting in 26 bits (Veltkamp). c = (2^27 + 1) a is formed as
// 2^27 a + a: the product by a power of two is exact, so fused or not the rounding is the same.
inline void split(double a, double& hi, double& lo)
{
  const double c = a * 134217728.0 + a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly, x = fl(a * b) (Dekker), with b already split into bhi + blo.
inline void twoProductPresplit(double a, double b, double bhi, double blo, double& x, double& y)
{
  x = a * b;
  double ahi, alo;
  split(a, ahi, alo);
  // The four partial products are exact (26 x 26 bits); subtracting them from x peels off the error.
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

// x + y == a * b exactly, x = fl(a * b).
inline void twoProduct(double a, double b, double& x, double& y)
{
  double bhi, blo;
  split(b, bhi, blo);
  twoProductPresplit(a, b, bhi, blo, x, y);
}

// x + y == a * a exactly: one split instead of two, and the cross term 2*ahi*alo in one product.
inline void twoSquare(double a, double& x, double& y)
{
  x = a * a;
  double ahi, alo;
  split(a, ahi, alo);
  const double err1 = x - ahi * ahi;
  const double err3 = err1 - (ahi + ahi) * alo;
  y = alo * alo - err3;
}

// Appends q to h unless it is zero (zero elimination keeps expansions short).
inline void appendNonZero(double q, double* h, int& hlen)
{
  if (q != 0.0)
  {
    h[hlen++] = q;
  }
}

// Expansion of a single double or of a two-term sum (head + tail), zero-eliminated. Returns length.
inline int makeExpansion(double head, double tail, double* h)
{
  int n = 0;
  appendNonZero(tail, h, n);
  if (head != 0.0 || n == 0)
  {
    h[n++] = head;
  }
  return n;
}

// h = e + f. Lengths: |h| <= elen + flen. h must not alias e or f.
// Merges the components by magnitude, then accumulates them with a two-sum cascade; the output is
// nonoverlapping when the inputs are strongly nonoverlapping (true of everything built here, with
// round-to-even).
inline int sumExpansions(int elen, const double* e, int flen, const double* f, double* h)
{
  int i = 0;
  int j = 0;
  const int total = elen + flen;
  // Next component in order of increasing magnitude (ties: take e first, any order is fine).
  auto next = [&]() -> double
  {
    if (j >= flen || (i < elen && std::fabs(e[i]) <= std::fabs(f[j])))
    {
      return e[i++];
    }
    return f[j++];
  };
  int hlen = 0;
  double q = next();
  if (total > 1)
  {
    double err;
    // The second component is at least as large as the first: the fast form is exact.
    fastTwoSum(next(), q, q, err);
    appendNonZero(err, h, hlen);
    while (i + j < total)
    {
      const double c = next();
      double sum;
      twoSum(q, c, sum, err);
      q = sum;
      appendNonZero(err, h, hlen);
    }
  }
  if (q != 0.0 || hlen == 0)
  {
    h[hlen++] = q;
  }
  return hlen;
}

// h = -e, in place allowed.
inline void negateExpansion(int elen, const double* e, double* h)
{
  for (int i = 0; i < elen; ++i)
  {
    h[i] = -e[i];
  }
}

// h = b * e. Lengths: |h| <= 2 * elen. h must not alias e.
inline int scaleExpansion(int elen, const double* e, double b, double* h)
{
  double bhi, blo;
  split(b, bhi, blo);
  int hlen = 0;
  double q, err;
  twoProductPresplit(e[0], b, bhi, blo, q, err);
  appendNonZero(err, h, hlen);
  for (int i = 1; i < elen; ++i)
  {
    double p1, p0;
    twoProductPresplit(e[i], b, bhi, blo, p1, p0);
    double sum;
    twoSum(q, p0, sum, err);
    appendNonZero(err, h, hlen);
    // p1 dominates sum (sum is at most about an ulp of the previous product): the fast form is exact.
    fastTwoSum(p1, sum, q, err);
    appendNonZero(err, h, hlen);
  }
  if (q != 0.0 || hlen == 0)
  {
    h[hlen++] = q;
  }
  return hlen;
}

// Scratch size needed by multiplyExpansions.
constexpr int multiplyScratchSize(int elen, int flen)
{
  return 2 * elen + 2 * elen * flen;
}

// h = e * f, as the sum over the components of f of scaled copies of e. Lengths: |h| <= 2*elen*flen.
// scratch must hold multiplyScratchSize(elen, flen) doubles; none of h, scratch may alias e or f.
inline int multiplyExpansions(int elen, const double* e, int flen, const double* f, double* h, double* scratch)
{
  double* term = scratch;             // one scaled copy, 2 * elen
  double* other = scratch + 2 * elen; // ping-pong partner of h
  double* acc = h;
  double* spare = other;
  int accLen = scaleExpansion(elen, e, f[0], acc);
  for (int j = 1; j < flen; ++j)
  {
    const int termLen = scaleExpansion(elen, e, f[j], term);
    const int newLen = sumExpansions(accLen, acc, termLen, term, spare);
    double* t = acc;
    acc = spare;
    spare = t;
    accLen = newLen;
  }
  if (acc != h)
  {
    for (int k = 0; k < accLen; ++k)
    {
      h[k] = acc[k];
    }
  }
  return accLen;
}

// Sign of the value of a zero-eliminated expansion: that of its largest (last) component.
inline int expansionSign(int elen, const double* e)
{
  const double top = e[elen - 1];
  return (top > 0.0) - (top < 0.0);
}

// Double-precision approximation of the value (for diagnostics).
inline double expansionEstimate(int elen, const double* e)
{
  double s = 0.0;
  for (int i = 0; i < elen; ++i)
  {
    s += e[i];
  }
  return s;
}

} // namespace expansion
} // namespace volgrid
