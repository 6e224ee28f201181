// Exact predicates, last resort: big-integer evaluation for inputs whose bits span more than the
// scaling window of the expansion paths (PredicatesInternal.h, scaleInto). Separate from the expansion
// code because it shares nothing with it but the bit-range helpers, and sane data never reaches it.
#include "PredicatesInternal.h"

#include <climits>
#include <cstdint>
#include <cstring>

namespace volgrid
{
namespace predicates
{
namespace internal
{
namespace
{
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
  exponent += zeros; // now the exponent of the lowest set bit, >= low
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
  return (p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2])) + p[2] * (q[0] * r[1] - q[1] * r[0]);
}
} // namespace

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
  const BigInt e =
    (W[0] * (X[1] * Y[2] - X[2] * Y[1]) - W[1] * (X[0] * Y[2] - X[2] * Y[0])) + W[2] * (X[0] * Y[1] - X[1] * Y[0]);
  return e.sign();
}

} // namespace internal
} // namespace predicates
} // namespace volgrid
