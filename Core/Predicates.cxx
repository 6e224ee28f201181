// Exact geometric predicates: filtered double evaluation, exact fallback with expansion arithmetic.
//
// Structure of every predicate:
//   1. Fast path: evaluate the determinant in doubles from coordinate differences, and a sound forward
//      error bound B = c * permanent + U (see "Error bounds" below). If |det| > B the sign is certain.
//   2. Exact path (rare): scale the inputs by a power of two so that no product can overflow or lose
//      bits to underflow (the sign of a homogeneous determinant is invariant under positive scaling),
//      then evaluate with expansions, adaptively (orient3d and insphere). Before that, where long double
//      is wider than double, the determinant is filtered once more in long double (same bound, with
//      long double's unit roundoff), which settles nearly all near-degenerate calls cheaply.
//      The expansion stages:
//        stage B: the determinant of the rounded differences, exactly; it is the answer when the
//                 differences are exact (grids, near-duplicate coordinates), else accepted when its
//                 magnitude exceeds a bound covering the tails the rounding dropped;
//        stage C: the same plus the first-order tail terms evaluated in doubles, with a bound of order
//                 u^2 times the permanent;
//        full:    the determinant expanded over the raw coordinates, where every product is exact
//                 (reached by exactly degenerate inputs whose differences are not exact).
//      See "Adaptive stages" below for the bounds.
//      Before all of these, inputs whose coordinates span at most 61 bits (from the highest to the lowest
//      set bit over the call: the usual case, e.g. structured grids x0 + i h with non-dyadic h, whose
//      exactly cospherical cells defeat every filter) are evaluated exactly on fixed-point integers
//      with 64/128/192/320-bit arithmetic (PredicatesFixed.h, bit bounds in PredicatesFixed.cxx):
//      ~10x cheaper than the full expansion evaluation, and it certifies exact zeros.
//   3. Inputs whose bits span more than the scaling window (e.g. 1e-300 and 1e+300 in one call) are
//      evaluated with exact big integers instead (BigInt below), so any finite doubles are handled.
// No heap allocation anywhere; the largest stack frame (insphere over raw coordinates) is ~130 KB.
//
// Error bounds. With the standard model fl(x op y) = (x op y)(1 + d), |d| <= eps = 2^-53, every monomial
// of a determinant evaluated by a tree of + and * comes out multiplied by prod(1 + d_j) over the n
// roundings on its path (input differences included), so |computed - exact| <= gamma_n * permanent,
// gamma_n = n eps / (1 - n eps). The permanent is itself computed in doubles (same tree, absolute
// values), and the bound c * permanent once more; the constants c below take all of that into account
// with slack (n = 8 for orient3d, 16 for insphere, 12 for incircle3d, 3 for orient2d).
// Gradual underflow adds an absolute error <= 2^-1075 per product, amplified by the factors that later
// multiply it; U is a (generous) bound on that, tiny unless the inputs are tiny or huge. It is applied as
// B = c * (permanent + U / c) so that no subnormal number is formed for ordinary inputs (on x86 an
// operation with a subnormal result costs ~100 cycles): U / c is >= 2^-1022, a normal number.
// Overflow gives inf/NaN in det or in the permanent, the comparison fails and the exact path decides.
//   orient3d:   U = 2^-1071 (|ux|+|uy|+|uz|+1)          >= 2 x [2 eta (sum |u|) + 3 eta], eta = 2^-1075
//   insphere:   U = 2^-1069 ((sum w + 4)^2 + sum P3)    (P3 the 3x3 permanents; |z| <= 1 + w)
//   incircle3d: U = 2^-1072 (sum W + sum P2 + 1)
//   orient2d:   U = 2^-1073
#include "Predicates.h"
#include "PredicatesInline.h"

#include "ExpansionArithmetic.h"
#include "PredicatesFixed.h"

#include <climits>
#include <limits>
#include <cmath>
#include <cstring>
#include <utility>

namespace volgrid
{
namespace predicates
{
namespace
{
using namespace expansion;

using detail::kEps;
using detail::signOf;
constexpr double kIncircleBound = (12.0 + 512.0 * kEps) * kEps;

// A small fixed-capacity expansion (stack storage; no allocation anywhere in this file).
template <int N>
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
bool scaleInto(const double* const* pts, int n, int maxTop, int minLow, double (*out)[3])
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
inline void det3FromMinors(double pz, double qz, double rz, const Exp<4>& mqr, const Exp<4>& mpr,
  const Exp<4>& mpq, Exp<24>& h)
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
// Last resort for inputs whose bits span more than the scaling window (e.g. 1e-300 and 1e+300 in one
// call): exact integer arithmetic. Every coordinate is an integer multiple of 2^low (low = the least
// significant set bit over the inputs), so the determinants are evaluated on those integers, from plain
// differences. Sizes: a coordinate spans <= 2098 bits, a degree-5 product <= 10495 bits plus carries,
// hence 340 32-bit limbs. Slow (microseconds) but never taken by sane data.

struct BigInt
{
  static constexpr int kLimbs = 340;
  uint32_t limb[kLimbs]; // magnitude, little endian; limb[0..n) valid, limb[n-1] != 0
  int n = 0;
  bool negative = false;
  int sign() const { return n == 0 ? 0 : (negative ? -1 : 1); }
};

int compareMagnitude(const BigInt& a, const BigInt& b)
{
  if (a.n != b.n)
  {
    return a.n < b.n ? -1 : 1;
  }
  for (int i = a.n - 1; i >= 0; --i)
  {
    if (a.limb[i] != b.limb[i])
    {
      return a.limb[i] < b.limb[i] ? -1 : 1;
    }
  }
  return 0;
}

// r = |a| + |b| (r may alias a or b).
void addMagnitude(const BigInt& a, const BigInt& b, BigInt& r)
{
  const int n = a.n > b.n ? a.n : b.n;
  uint64_t carry = 0;
  for (int i = 0; i < n; ++i)
  {
    const uint64_t s = uint64_t(i < a.n ? a.limb[i] : 0) + (i < b.n ? b.limb[i] : 0) + carry;
    r.limb[i] = static_cast<uint32_t>(s);
    carry = s >> 32;
  }
  r.n = n;
  if (carry)
  {
    r.limb[r.n++] = static_cast<uint32_t>(carry);
  }
}

// r = |a| - |b|, requires |a| >= |b| (r may alias a or b).
void subtractMagnitude(const BigInt& a, const BigInt& b, BigInt& r)
{
  int64_t borrow = 0;
  for (int i = 0; i < a.n; ++i)
  {
    int64_t d = int64_t(a.limb[i]) - (i < b.n ? b.limb[i] : 0) - borrow;
    borrow = d < 0;
    r.limb[i] = static_cast<uint32_t>(d + (borrow << 32));
  }
  r.n = a.n;
  while (r.n > 0 && r.limb[r.n - 1] == 0)
  {
    --r.n;
  }
}

// r = a + (negateB ? -b : b) (r may alias a or b).
void addSigned(const BigInt& a, const BigInt& b, bool negateB, BigInt& r)
{
  const bool bNegative = b.negative != negateB;
  if (a.negative == bNegative)
  {
    addMagnitude(a, b, r);
    r.negative = a.negative;
  }
  else if (compareMagnitude(a, b) >= 0)
  {
    const bool s = a.negative;
    subtractMagnitude(a, b, r);
    r.negative = s;
  }
  else
  {
    subtractMagnitude(b, a, r);
    r.negative = bNegative;
  }
  if (r.n == 0)
  {
    r.negative = false;
  }
}

BigInt operator+(const BigInt& a, const BigInt& b)
{
  BigInt r;
  addSigned(a, b, false, r);
  return r;
}

BigInt operator-(const BigInt& a, const BigInt& b)
{
  BigInt r;
  addSigned(a, b, true, r);
  return r;
}

BigInt operator*(const BigInt& a, const BigInt& b)
{
  BigInt r;
  if (a.n == 0 || b.n == 0)
  {
    return r;
  }
  r.n = a.n + b.n; // callers stay within kLimbs by the degree bound above
  std::memset(r.limb, 0, sizeof(uint32_t) * r.n);
  for (int i = 0; i < a.n; ++i)
  {
    uint64_t carry = 0;
    for (int j = 0; j < b.n; ++j)
    {
      const uint64_t t = uint64_t(a.limb[i]) * b.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<uint32_t>(t);
      carry = t >> 32;
    }
    r.limb[i + b.n] = static_cast<uint32_t>(carry);
  }
  while (r.n > 0 && r.limb[r.n - 1] == 0)
  {
    --r.n;
  }
  r.negative = a.negative != b.negative;
  return r;
}

// x / 2^low as an integer (x must be a multiple of 2^low).
BigInt toBigInt(double x, int low)
{
  BigInt r;
  if (x == 0.0)
  {
    return r;
  }
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  uint64_t mant = bits & ((uint64_t(1) << 52) - 1);
  int exponent = -1074; // x = mant * 2^exponent
  if (biased != 0)
  {
    mant |= uint64_t(1) << 52;
    exponent = biased - 1075;
  }
  const int zeros = countTrailingZeros(mant);
  mant >>= zeros;
  exponent += zeros;                // now the exponent of the lowest set bit, >= low
  const int shift = exponent - low;
  const int limbShift = shift / 32;
  const int bitShift = shift % 32;
  std::memset(r.limb, 0, sizeof(uint32_t) * (limbShift + 4));
  // mant << bitShift spans at most 85 bits: three limbs.
  const uint64_t lo = mant << bitShift;
  const uint64_t hi = bitShift ? (mant >> (64 - bitShift)) : 0;
  r.limb[limbShift] = static_cast<uint32_t>(lo);
  r.limb[limbShift + 1] = static_cast<uint32_t>(lo >> 32);
  r.limb[limbShift + 2] = static_cast<uint32_t>(hi);
  r.n = limbShift + 3;
  while (r.n > 0 && r.limb[r.n - 1] == 0)
  {
    --r.n;
  }
  r.negative = x < 0;
  return r;
}

// The n input points as integer vectors (coordinates divided by the common 2^low).
void toBigInts(const double* const* pts, int n, BigInt (*out)[3])
{
  BitRange r;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      includeInRange(r, pts[i][k]);
    }
  }
  const int low = r.low == INT_MAX ? 0 : r.low;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      out[i][k] = toBigInt(pts[i][k], low);
    }
  }
}

// p . (q x r)
BigInt tripleProduct(const BigInt* p, const BigInt* q, const BigInt* r)
{
  return (p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2])) +
    p[2] * (q[0] * r[1] - q[1] * r[0]);
}

int orient3dWide(const double* const* in)
{
  BigInt p[4][3];
  toBigInts(in, 4, p);
  BigInt u[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      u[r][k] = p[r + 1][k] - p[0][k];
    }
  }
  return tripleProduct(u[0], u[1], u[2]).sign();
}

int insphereWide(const double* const* in)
{
  BigInt p[5][3];
  toBigInts(in, 5, p);
  BigInt q[4][3];
  BigInt w[4];
  for (int r = 0; r < 4; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      q[r][k] = p[r][k] - p[4][k];
    }
    w[r] = (q[r][0] * q[r][0] + q[r][1] * q[r][1]) + q[r][2] * q[r][2];
  }
  // D = -w0 det(q1,q2,q3) + w1 det(q0,q2,q3) - w2 det(q0,q1,q3) + w3 det(q0,q1,q2); insphere = -sign(D)
  const BigInt d = (w[1] * tripleProduct(q[0], q[2], q[3]) - w[0] * tripleProduct(q[1], q[2], q[3])) +
    (w[3] * tripleProduct(q[0], q[1], q[2]) - w[2] * tripleProduct(q[0], q[1], q[3]));
  return -d.sign();
}

// det[b-a; c-a] in the (i, j) plane.
int orient2dWide(const double* const* in, int i, int j)
{
  BigInt p[3][3];
  toBigInts(in, 3, p);
  return ((p[1][i] - p[0][i]) * (p[2][j] - p[0][j]) - (p[1][j] - p[0][j]) * (p[2][i] - p[0][i])).sign();
}

// The incircle determinant E (see incircleDeterminantExact).
int incircleDeterminantWide(const double* const* in, int i, int j)
{
  BigInt p[4][3];
  toBigInts(in, 4, p);
  BigInt X[3], Y[3], W[3];
  for (int r = 0; r < 3; ++r)
  {
    BigInt d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = p[r + 1][k] - p[0][k];
    }
    X[r] = d[i];
    Y[r] = d[j];
    W[r] = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
  }
  const BigInt e = (W[0] * (X[1] * Y[2] - X[2] * Y[1]) - W[1] * (X[0] * Y[2] - X[2] * Y[0])) +
    W[2] * (X[0] * Y[1] - X[1] * Y[0]);
  return e.sign();
}

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
// The error analysis of the double filter (header of this file) holds with the unit roundoff
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
  static const bool usable = [] {
    if (kLDDigits < 60)
    {
      return false;
    }
    // The arithmetic really rounds to kLDDigits bits (not, e.g., to 53 under a reduced precision control).
    volatile LD one = 1.0L;
    volatile LD tiny = std::ldexp(1.0L, -(kLDDigits - 1));
    volatile LD half = std::ldexp(1.0L, -kLDDigits);
    const LD a = one + tiny;  // representable: must differ from 1
    const LD b = one + half;  // a tie: rounds to even, i.e. to 1
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
  const LD perm = (std::fabs(ux) * (std::fabs(vywz) + std::fabs(vzwy)) +
                    std::fabs(uy) * (std::fabs(vzwx) + std::fabs(vxwz))) +
    std::fabs(uz) * (std::fabs(vxwy) + std::fabs(vywx));
  const LD bound = (9 * kUnitLD) * perm;
  return det > bound ? 1 : (-det > bound ? -1 : 0);
}

// Sign of D = det[p - e, |p - e|^2] (insphere = -sign(D)) when certain, 0 when not decided.
int insphereDExtended(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const LD x0 = LD(a[0]) - e[0], y0 = LD(a[1]) - e[1], z0 = LD(a[2]) - e[2];
  const LD x1 = LD(b[0]) - e[0], y1 = LD(b[1]) - e[1], z1 = LD(b[2]) - e[2];
  const LD x2 = LD(c[0]) - e[0], y2 = LD(c[1]) - e[1], z2 = LD(c[2]) - e[2];
  const LD x3 = LD(d[0]) - e[0], y3 = LD(d[1]) - e[1], z3 = LD(d[2]) - e[2];
  const LD x0y1 = x0 * y1, x1y0 = x1 * y0, x0y2 = x0 * y2, x2y0 = x2 * y0;
  const LD x0y3 = x0 * y3, x3y0 = x3 * y0, x1y2 = x1 * y2, x2y1 = x2 * y1;
  const LD x1y3 = x1 * y3, x3y1 = x3 * y1, x2y3 = x2 * y3, x3y2 = x3 * y2;
  const LD m01 = x0y1 - x1y0, m02 = x0y2 - x2y0, m03 = x0y3 - x3y0;
  const LD m12 = x1y2 - x2y1, m13 = x1y3 - x3y1, m23 = x2y3 - x3y2;
  const LD d123 = (z1 * m23 - z2 * m13) + z3 * m12;
  const LD d023 = (z0 * m23 - z2 * m03) + z3 * m02;
  const LD d013 = (z0 * m13 - z1 * m03) + z3 * m01;
  const LD d012 = (z0 * m12 - z1 * m02) + z2 * m01;
  const LD w0 = (x0 * x0 + y0 * y0) + z0 * z0;
  const LD w1 = (x1 * x1 + y1 * y1) + z1 * z1;
  const LD w2 = (x2 * x2 + y2 * y2) + z2 * z2;
  const LD w3 = (x3 * x3 + y3 * y3) + z3 * z3;
  const LD det = (w1 * d023 - w0 * d123) + (w3 * d012 - w2 * d013);
  const LD p01 = std::fabs(x0y1) + std::fabs(x1y0), p02 = std::fabs(x0y2) + std::fabs(x2y0);
  const LD p03 = std::fabs(x0y3) + std::fabs(x3y0), p12 = std::fabs(x1y2) + std::fabs(x2y1);
  const LD p13 = std::fabs(x1y3) + std::fabs(x3y1), p23 = std::fabs(x2y3) + std::fabs(x3y2);
  const LD az0 = std::fabs(z0), az1 = std::fabs(z1), az2 = std::fabs(z2), az3 = std::fabs(z3);
  const LD q123 = (az1 * p23 + az2 * p13) + az3 * p12;
  const LD q023 = (az0 * p23 + az2 * p03) + az3 * p02;
  const LD q013 = (az0 * p13 + az1 * p03) + az3 * p01;
  const LD q012 = (az0 * p12 + az1 * p02) + az2 * p01;
  const LD perm = (w1 * q023 + w0 * q123) + (w3 * q012 + w2 * q013);
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

// ---------------------------------------------------------------------------------------------------
// Exact orient2d on the plane (i, j) = ((k+1)%3, (k+2)%3): det[b-a; c-a] = m(b,c) - m(a,c) + m(a,b).

constexpr int kOrient2dTop = 500;
constexpr int kOrient2dLow = -480;

int orient2dExactImpl(const double* a, const double* b, const double* c, int i, int j)
{
  const double* in[3] = { a, b, c };
  double p[3][3];
  if (!scaleInto(in, 3, kOrient2dTop, kOrient2dLow, p))
  {
    return orient2dWide(in, i, j);
  }
  Exp<4> mbc, mac, mab;
  minor2(p[1][i], p[1][j], p[2][i], p[2][j], mbc);
  minor2(p[0][i], p[0][j], p[2][i], p[2][j], mac);
  minor2(p[0][i], p[0][j], p[1][i], p[1][j], mab);
  double neg[4], s[8], h[12];
  negateExpansion(mac.n, mac.v, neg);
  const int ns = sumExpansions(mbc.n, mbc.v, mac.n, neg, s);
  const int n = sumExpansions(ns, s, mab.n, mab.v, h);
  return expansionSign(n, h);
}

// ---------------------------------------------------------------------------------------------------
// Exact incircle3d determinant, relative to a, in the projected frame (i, j):
//   E = det[[X_p, Y_p, W_p]]_{p=b,c,d},  X = p_i - a_i, Y = p_j - a_j, W = |p - a|^2 (all 3 axes).
// Differences are kept as exact two-term expansions.

constexpr int kIncircleTop = 250; // |E| <= 288 M^4
constexpr int kIncircleLow = -240;

int incircleDeterminantExact(const double* a, const double* b, const double* c, const double* d, int i, int j)
{
  const double* in[4] = { a, b, c, d };
  double p[4][3];
  if (!scaleInto(in, 4, kIncircleTop, kIncircleLow, p))
  {
    return incircleDeterminantWide(in, i, j);
  }
  Exp<2> X[3], Y[3];
  Exp<24> W[3];
  for (int r = 0; r < 3; ++r)
  {
    double h, t;
    twoDiff(p[r + 1][i], p[0][i], h, t);
    X[r].n = makeExpansion(h, t, X[r].v);
    twoDiff(p[r + 1][j], p[0][j], h, t);
    Y[r].n = makeExpansion(h, t, Y[r].v);
    double sq[3][8];
    int sn[3];
    for (int k = 0; k < 3; ++k)
    {
      double dk[2];
      twoDiff(p[r + 1][k], p[0][k], h, t);
      const int dn = makeExpansion(h, t, dk);
      double scratch[multiplyScratchSize(2, 2)];
      sn[k] = multiplyExpansions(dn, dk, dn, dk, sq[k], scratch);
    }
    double s01[16];
    const int n01 = sumExpansions(sn[0], sq[0], sn[1], sq[1], s01);
    W[r].n = sumExpansions(n01, s01, sn[2], sq[2], W[r].v);
  }
  // Minor M(r,s) = X_r Y_s - X_s Y_r (<= 16 components).
  auto minor = [&](int r, int s, double* out) {
    double p1[8], p2[8], scratch[multiplyScratchSize(2, 2)];
    const int n1 = multiplyExpansions(X[r].n, X[r].v, Y[s].n, Y[s].v, p1, scratch);
    const int n2 = multiplyExpansions(X[s].n, X[s].v, Y[r].n, Y[r].v, p2, scratch);
    negateExpansion(n2, p2, p2);
    return sumExpansions(n1, p1, n2, p2, out);
  };
  // E = W_b M(c,d) - W_c M(b,d) + W_d M(b,c)
  double terms[3][768];
  int tn[3];
  const int pairs[3][2] = { { 1, 2 }, { 0, 2 }, { 0, 1 } };
  for (int r = 0; r < 3; ++r)
  {
    double mm[16];
    const int mn = minor(pairs[r][0], pairs[r][1], mm);
    double scratch[multiplyScratchSize(16, 24)];
    tn[r] = multiplyExpansions(mn, mm, W[r].n, W[r].v, terms[r], scratch);
  }
  negateExpansion(tn[1], terms[1], terms[1]);
  double s01[1536], e[2304];
  const int n01 = sumExpansions(tn[0], terms[0], tn[1], terms[1], s01);
  const int n = sumExpansions(n01, s01, tn[2], terms[2], e);
  return expansionSign(n, e);
}

inline void projectedAxes(int dropAxis, int& i, int& j)
{
  i = dropAxis == 0 ? 1 : (dropAxis == 1 ? 2 : 0);
  j = dropAxis == 0 ? 2 : (dropAxis == 1 ? 0 : 1);
}

// Filtered incircle determinant sign (see incircleDeterminantExact for the definition).
int incircleDeterminant(const double* a, const double* b, const double* c, const double* d, int i, int j)
{
  const double xb = b[i] - a[i], yb = b[j] - a[j];
  const double xc = c[i] - a[i], yc = c[j] - a[j];
  const double xd = d[i] - a[i], yd = d[j] - a[j];
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const double wb = (bx * bx + by * by) + bz * bz;
  const double wc = (cx * cx + cy * cy) + cz * cz;
  const double wd = (dx * dx + dy * dy) + dz * dz;
  const double mcd = xc * yd - xd * yc;
  const double mbd = xb * yd - xd * yb;
  const double mbc = xb * yc - xc * yb;
  const double det = (wb * mcd - wc * mbd) + wd * mbc;
  const double pcd = std::fabs(xc * yd) + std::fabs(xd * yc);
  const double pbd = std::fabs(xb * yd) + std::fabs(xd * yb);
  const double pbc = std::fabs(xb * yc) + std::fabs(xc * yb);
  const double perm = (wb * pcd + wc * pbd) + wd * pbc;
  const double under = 0x1p-1022 * (((wb + wc) + wd) + ((pcd + pbd) + pbc) + 1.0);
  const double bound = kIncircleBound * (perm + under);
  if (det > bound || -det > bound)
  {
    return signOf(det);
  }
  return incircleDeterminantExact(a, b, c, d, i, j);
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

int orient3dExactStaged(const double* a, const double* b, const double* c, const double* d, bool extended,
  int* stage, bool fixedPoint)
{
  return orient3dExactImpl(a, b, c, d, extended, fixedPoint, stage);
}

int insphereExactStaged(const double* a, const double* b, const double* c, const double* d, const double* e,
  bool extended, int* stage, bool fixedPoint)
{
  return insphereExactImpl(a, b, c, d, e, extended, fixedPoint, stage);
}

int orient2dExact(const double* a, const double* b, const double* c, int i, int j)
{
  return orient2dExactImpl(a, b, c, i, j);
}

int insphereSoSTie(const double* a, const double* b, const double* c, const double* d, const double* e,
  int64_t ida, int64_t idb, int64_t idc, int64_t idd, int64_t ide)
{
  // Exactly cospherical. Lifting perturbation: point i is lifted to |p_i|^2 + eps^(r_i), where r_i is
  // the rank of id_i in DECREASING order (the largest id gets the largest perturbation, eps^1). This is
  // the power-distance (weight -eps^(r_i)) regular triangulation of a generic weighted set for every
  // small eps > 0: unique, independent of insertion order, and without flat tetrahedra. The 5x5 lifted
  // determinant is linear in the lifted column, so
  //   L_eps = L + sum_i eps^(r_i) C_i,   L = 0 here,
  // so sign(L_eps) = sign(C_i) for the largest id with C_i != 0, and the result is -sign(L_eps). C_e is
  // orient3d(a,b,c,d) != 0, so the search ends. Cofactors of the lifted column (i = 0..4 for a..e):
  //   C_a = +O(b,c,d,e), C_b = -O(a,c,d,e), C_c = +O(a,b,d,e), C_d = -O(a,b,c,e), C_e = +O(a,b,c,d).
  const double* pts[5] = { a, b, c, d, e };
  int64_t ids[5] = { ida, idb, idc, idd, ide };
  int order[5] = { 0, 1, 2, 3, 4 };
  // Sort indices by decreasing id (insertion sort on 5 elements).
  for (int i = 1; i < 5; ++i)
  {
    const int v = order[i];
    int j = i - 1;
    while (j >= 0 && ids[order[j]] < ids[v])
    {
      order[j + 1] = order[j];
      --j;
    }
    order[j + 1] = v;
  }
  // The cofactors of exactly cospherical points are often 0 as well (coplanar faces of grid boxes):
  // with the five points as fixed-point integers each one is a few exact integer products.
  int64_t fixedPts[5][3];
  if (fixedpoint::toFixed(pts, 5, fixedPts))
  {
    for (int r = 0; r < 5; ++r)
    {
      const int i = order[r];
      const int64_t* q[4];
      for (int j = 0, k = 0; j < 5; ++j)
      {
        if (j != i)
        {
          q[k++] = fixedPts[j];
        }
      }
      const int o = fixedpoint::orient3dFixed(q[0], q[1], q[2], q[3]);
      if (o != 0)
      {
        return (i & 1) ? o : -o; // -cofactor
      }
    }
    return 0;
  }
  for (int r = 0; r < 5; ++r)
  {
    const int i = order[r];
    const double* q[4];
    for (int j = 0, k = 0; j < 5; ++j)
    {
      if (j != i)
      {
        q[k++] = pts[j];
      }
    }
    const int o = orient3dInline(q[0], q[1], q[2], q[3]);
    if (o != 0)
    {
      const int cofactor = (i & 1) ? -o : o;
      return -cofactor;
    }
  }
  return 0; // unreachable when orient3d(a,b,c,d) != 0 (the precondition)
}
} // namespace detail

int orient3d(const double* a, const double* b, const double* c, const double* d)
{
  return orient3dInline(a, b, c, d);
}

int insphere(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  return insphereInline(a, b, c, d, e);
}

int insphereSoS(const double* a, const double* b, const double* c, const double* d, const double* e,
  int64_t ida, int64_t idb, int64_t idc, int64_t idd, int64_t ide)
{
  return insphereSoSInline(a, b, c, d, e, ida, idb, idc, idd, ide);
}

int orient2dProjected(const double* a, const double* b, const double* c, int dropAxis)
{
  return orient2dProjectedInline(a, b, c, dropAxis);
}

int incircle3d(const double* a, const double* b, const double* c, const double* d)
{
  // Drop the axis along which the triangle's normal is largest (so the projection is not degenerate);
  // the answer does not depend on the choice for coplanar input, only exactness needs a nonzero
  // projected orientation.
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double n[3] = { std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
    std::fabs(ux * vy - uy * vx) };
  int axes[3] = { 0, 1, 2 };
  if (n[axes[1]] > n[axes[0]])
  {
    std::swap(axes[0], axes[1]);
  }
  if (n[axes[2]] > n[axes[1]])
  {
    std::swap(axes[1], axes[2]);
  }
  if (n[axes[1]] > n[axes[0]])
  {
    std::swap(axes[0], axes[1]);
  }
  for (int t = 0; t < 3; ++t)
  {
    const int k = axes[t];
    const int o = orient2dProjected(a, b, c, k);
    if (o != 0)
    {
      int i, j;
      projectedAxes(k, i, j);
      // Lifting argument: E = (W_d - h(d)) * orient2d, h the plane through the lifted a, b, c; d is
      // inside the circle iff W_d < h(d).
      return -incircleDeterminant(a, b, c, d, i, j) * o;
    }
  }
  return 0; // a, b, c collinear
}

} // namespace predicates
} // namespace volgrid
