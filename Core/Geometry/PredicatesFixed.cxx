// Exact orient3d / insphere on fixed-point integers (see PredicatesFixed.h).
//
// Conversion. A nonzero finite normal double x = +-m 2^(E - 52), m a 53-bit integer, E = floor(log2|x|):
// its least significant set bit is 2^(E - 52 + ctz(m)). Over the coordinates of one call let
// top = max E and low = min (E - 52 + ctz m). Then X = x / 2^low is an integer, obtained from m by a
// shift of (E - 52 - low) bits (left, or right by at most ctz m: no bit is lost), and |X| < 2^(top+1-low).
// The fast path requires top + 1 - low <= 61, i.e. |X| < 2^61 for every coordinate (zeros are X = 0).
// (toIntegers tests this condition by scaling with 2^(60 - top) and checking integrality, see there.)
//
// Bit bounds (B = 2^61 bounds every |X|; all bounds strict):
//   differences      |X_p - X_q|                 < 2^62                 int64
//   2x2 minors       |x_i y_j - x_j y_i|         < 2 * 2^124 = 2^125    int128 (each product < 2^124)
//   squared norms    w = x^2 + y^2 + z^2         < 3 * 2^124 < 2^126    int128
//   3x3 determinants sum of 3 |z| |minor|        < 3 * 2^187 < 2^189    3 limbs (signed range 2^191),
//                    formed from two int128 sums (see det3)
//   insphere D       sum of 4 w |det3|           < 4 * 2^315 = 2^317    5 limbs (signed range 2^319)
//   orient3d         a 3x3 determinant           < 2^189                3 limbs
// Every partial sum is bounded by the same sums of absolute values, so nothing overflows. The wide
// values are two's complement little-endian 64-bit limbs; products multiply magnitudes (schoolbook,
// 64x64 -> 128-bit partial products) and negate, so a truncated product is exact whenever the true
// product fits, which the bounds guarantee.
#include "PredicatesFixed.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace volgrid
{
namespace predicates
{
namespace fixedpoint
{
#if defined(__SIZEOF_INT128__)
namespace
{
using i128 = __int128;
using u128 = unsigned __int128;

constexpr int kMaxBits = 61; // |X| < 2^kMaxBits

// Two's complement integer of N 64-bit limbs, least significant first.
template<int N>
struct Wide
{
  uint64_t v[N];
};

template<int N>
inline Wide<N> fromI128(i128 x)
{
  Wide<N> r;
  const u128 u = static_cast<u128>(x);
  r.v[0] = static_cast<uint64_t>(u);
  if (N > 1)
  {
    r.v[1] = static_cast<uint64_t>(u >> 64);
  }
  const uint64_t ext = x < 0 ? ~uint64_t(0) : 0;
  for (int i = 2; i < N; ++i)
  {
    r.v[i] = ext;
  }
  return r;
}

template<int N>
inline bool isNegative(const Wide<N>& a)
{
  return (a.v[N - 1] >> 63) != 0;
}

// a = -a when mask is all ones, unchanged when mask is 0; branch-free (the signs of minors are
// unpredictable, a mispredicted branch per product would cost more than the product).
template<int N>
inline void negateIf(Wide<N>& a, uint64_t mask)
{
  uint64_t carry = mask & 1;
  for (int i = 0; i < N; ++i)
  {
    const uint64_t x = (a.v[i] ^ mask) + carry;
    carry = x < carry ? 1 : 0;
    a.v[i] = x;
  }
}

// a += s * b, s = +1 or -1.
template<int N>
inline void accumulate(Wide<N>& a, const Wide<N>& b, bool subtract)
{
  if (!subtract)
  {
    uint64_t carry = 0;
    for (int i = 0; i < N; ++i)
    {
      const u128 t = u128(a.v[i]) + b.v[i] + carry;
      a.v[i] = static_cast<uint64_t>(t);
      carry = static_cast<uint64_t>(t >> 64);
    }
  }
  else
  {
    uint64_t borrow = 0;
    for (int i = 0; i < N; ++i)
    {
      const u128 t = u128(a.v[i]) - b.v[i] - borrow;
      a.v[i] = static_cast<uint64_t>(t);
      borrow = static_cast<uint64_t>(t >> 64) ? 1 : 0;
    }
  }
}

template<int N>
inline int signOf(const Wide<N>& a)
{
  if (isNegative(a))
  {
    return -1;
  }
  for (int i = 0; i < N; ++i)
  {
    if (a.v[i] != 0)
    {
      return 1;
    }
  }
  return 0;
}

// r = a * b (a magnitude of A limbs, b of B limbs), truncated to R limbs; r must not alias.
template<int R, int A, int B>
inline void multiplyMagnitudes(const uint64_t* a, const uint64_t* b, uint64_t* r)
{
  for (int i = 0; i < R; ++i)
  {
    r[i] = 0;
  }
  for (int i = 0; i < A && i < R; ++i)
  {
    uint64_t carry = 0;
    for (int j = 0; j < B && i + j < R; ++j)
    {
      const u128 t = u128(a[i]) * b[j] + r[i + j] + carry;
      r[i + j] = static_cast<uint64_t>(t);
      carry = static_cast<uint64_t>(t >> 64);
    }
    if (i + B < R)
    {
      r[i + B] = carry;
    }
  }
}

// Nonnegative 128-bit w times a signed 3-limb value, as 5 limbs (the caller's bounds: |result| < 2^319).
inline Wide<5> mul128x192(u128 w, Wide<3> m)
{
  const uint64_t sm = static_cast<uint64_t>(static_cast<int64_t>(m.v[2]) >> 63);
  negateIf(m, sm); // |m| < 2^191: the magnitude fits
  const uint64_t bw[2] = { static_cast<uint64_t>(w), static_cast<uint64_t>(w >> 64) };
  Wide<5> r;
  multiplyMagnitudes<5, 2, 3>(bw, m.v, r.v);
  negateIf(r, sm);
  return r;
}

// Coordinates of n points as integers X = x / 2^low (common low); false when they do not fit.
// With T = floor(log2 max |x|), every X = x 2^(60 - T) has |X| < 2^61, and the call fits iff all these
// are integers (low >= T - 60, i.e. top + 1 - low <= 61 with top = T). (The integers are those of the
// common exponent T - 60 rather than low: the same up to a positive power of two, which changes no
// sign.) Non-finite inputs are rejected.
inline bool toIntegers(const double* const* pts, int n, int64_t (*out)[3])
{
  double m = 0.0;
  bool finite = true;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double a = std::fabs(pts[i][k]);
      m = a > m ? a : m;
      finite = finite & (a <= 0x1.fffffffffffffp1023); // false for inf and NaN
    }
  }
  if (!finite)
  {
    return false; // not ours to judge
  }
  if (m == 0.0)
  {
    for (int i = 0; i < n; ++i)
    {
      out[i][0] = out[i][1] = out[i][2] = 0;
    }
    return true;
  }
  uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  const int T = static_cast<int>(bits >> 52) - 1023; // m is positive; subnormal m gives -1023
  if (T < -960 || T > 960)
  {
    return false; // extreme magnitudes: left to the expansion path
  }
  // X = x 2^(60 - T) from the bits: the 53-bit significand m (value m 2^(E - 1075), E the biased
  // exponent; subnormals have E = 1 and no hidden bit) is placed at bit 11 (m 2^11 < 2^64) and shifted
  // right by r = 11 - (E - 1075 - (T - 60)) >= 11 - 8 = 3; the call fits iff no set bit is shifted out
  // (r <= 63 for a nonzero m). Integer operations only, no branch per coordinate.
  bool ok = true;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      uint64_t b;
      std::memcpy(&b, &pts[i][k], sizeof b);
      const int biased = static_cast<int>((b >> 52) & 0x7ff);
      const uint64_t hidden = biased != 0 ? (uint64_t(1) << 52) : 0;
      const uint64_t m = ((b & ((uint64_t(1) << 52) - 1)) | hidden) << 11;
      const int e = biased != 0 ? biased : 1;
      const int r = 11 - (e - 1075 - (T - 60));
      const int rc = r > 63 ? 63 : r;
      ok = ok & ((m & ((uint64_t(1) << rc) - 1)) == 0) & ((r <= 63) | (m == 0));
      const uint64_t mag = m >> rc;
      const uint64_t neg = static_cast<uint64_t>(static_cast<int64_t>(b) >> 63);
      out[i][k] = static_cast<int64_t>((mag ^ neg) - neg);
    }
  }
  return ok;
}

inline i128 minor2(int64_t a0, int64_t a1, int64_t b0, int64_t b1)
{
  return i128(a0) * b1 - i128(b0) * a1;
}

// det of rows p, q, r (x, y, z), expanded along z with the xy minors given, as 3 limbs. Each minor m
// (|m| < 2^125) is split as m = mh 2^63 + ml, mh = m >> 63 (|mh| <= 2^62), ml in [0, 2^63): all four
// fit in int64, so z mh and z ml are single 64x64 -> 128-bit products, and with |z| < 2^62
//   |Hi| = |sum z mh| < 3 2^124 < 2^126,   |Lo| = |sum z ml| < 3 2^125 < 2^127:
// both sums fit in int128; det = Hi 2^63 + Lo (< 2^189) is assembled in 3 limbs.
inline Wide<3> det3(int64_t pz, int64_t qz, int64_t rz, i128 mqr, i128 mpr, i128 mpq)
{
  constexpr i128 kLow63 = (i128(1) << 63) - 1;
  const i128 hi = i128(pz) * static_cast<int64_t>(mqr >> 63) - i128(qz) * static_cast<int64_t>(mpr >> 63) +
    i128(rz) * static_cast<int64_t>(mpq >> 63);
  const i128 lo = i128(pz) * static_cast<int64_t>(mqr & kLow63) - i128(qz) * static_cast<int64_t>(mpr & kLow63) +
    i128(rz) * static_cast<int64_t>(mpq & kLow63);
  const Wide<3> h = fromI128<3>(hi);
  Wide<3> s;
  s.v[0] = h.v[0] << 63;
  s.v[1] = (h.v[1] << 63) | (h.v[0] >> 1);
  s.v[2] = (h.v[2] << 63) | (h.v[1] >> 1);
  accumulate(s, fromI128<3>(lo), false);
  return s;
}
} // namespace

// The last five points insphere converted, per thread: the SoS tie-break (toFixed) follows an exactly
// cospherical insphere on the same points, and reuses the conversion when the coordinates are equal.
struct LastConversion
{
  double x[5][3];
  int64_t X[5][3];
  bool valid = false;
};
thread_local LastConversion lastConversion;

bool toFixed(const double* const* pts, int n, int64_t (*out)[3])
{
  if (n != 5)
  {
    return n < 5 && toIntegers(pts, n, out);
  }
  LastConversion& c = lastConversion;
  if (c.valid)
  {
    bool same = true;
    for (int i = 0; i < 5; ++i)
    {
      same = same & (pts[i][0] == c.x[i][0]) & (pts[i][1] == c.x[i][1]) & (pts[i][2] == c.x[i][2]);
    }
    // == on doubles: equal values (+0 and -0 both convert to 0, no NaN was ever cached), same integers.
    if (same)
    {
      std::memcpy(out, c.X, sizeof c.X);
      return true;
    }
  }
  return toIntegers(pts, 5, out);
}

int orient3dFixed(const int64_t* a, const int64_t* b, const int64_t* c, const int64_t* d)
{
  const int64_t* q[3] = { b, c, d };
  int64_t u[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      u[r][k] = q[r][k] - a[k];
    }
  }
  const i128 m01 = minor2(u[0][0], u[0][1], u[1][0], u[1][1]);
  const i128 m02 = minor2(u[0][0], u[0][1], u[2][0], u[2][1]);
  const i128 m12 = minor2(u[1][0], u[1][1], u[2][0], u[2][1]);
  return signOf(det3(u[0][2], u[1][2], u[2][2], m12, m02, m01));
}

bool orient3d(const double* a, const double* b, const double* c, const double* d, int* sign)
{
  const double* in[4] = { a, b, c, d };
  int64_t p[4][3];
  if (!toIntegers(in, 4, p))
  {
    return false;
  }
  *sign = orient3dFixed(p[0], p[1], p[2], p[3]);
  return true;
}

bool insphere(const double* a, const double* b, const double* c, const double* d, const double* e, int* sign)
{
  const double* in[5] = { a, b, c, d, e };
  int64_t p[5][3];
  if (!toIntegers(in, 5, p))
  {
    return false;
  }
  LastConversion& last = lastConversion;
  for (int i = 0; i < 5; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      last.x[i][k] = in[i][k];
    }
  }
  std::memcpy(last.X, p, sizeof p);
  last.valid = true;
  int64_t q[4][3];
  u128 w[4];
  for (int r = 0; r < 4; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      q[r][k] = p[r][k] - p[4][k];
    }
    w[r] = static_cast<u128>((i128(q[r][0]) * q[r][0] + i128(q[r][1]) * q[r][1]) + i128(q[r][2]) * q[r][2]);
  }
  i128 m[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      m[i][j] = minor2(q[i][0], q[i][1], q[j][0], q[j][1]);
    }
  }
  // M_i = det3 of the other three rows in increasing order; D = -w0 M0 + w1 M1 - w2 M2 + w3 M3.
  const Wide<3> M0 = det3(q[1][2], q[2][2], q[3][2], m[2][3], m[1][3], m[1][2]);
  const Wide<3> M1 = det3(q[0][2], q[2][2], q[3][2], m[2][3], m[0][3], m[0][2]);
  const Wide<3> M2 = det3(q[0][2], q[1][2], q[3][2], m[1][3], m[0][3], m[0][1]);
  const Wide<3> M3 = det3(q[0][2], q[1][2], q[2][2], m[1][2], m[0][2], m[0][1]);
  Wide<5> D = mul128x192(w[1], M1);
  accumulate(D, mul128x192(w[0], M0), true);
  accumulate(D, mul128x192(w[3], M3), false);
  accumulate(D, mul128x192(w[2], M2), true);
  *sign = -signOf(D);
  return true;
}

#else
// Without a 128-bit integer type the expansion path decides everything.
bool toFixed(const double* const*, int, int64_t (*)[3])
{
  return false;
}

int orient3dFixed(const int64_t*, const int64_t*, const int64_t*, const int64_t*)
{
  return 0; // never called: toFixed fails
}

bool orient3d(const double*, const double*, const double*, const double*, int*)
{
  return false;
}

bool insphere(const double*, const double*, const double*, const double*, const double*, int*)
{
  return false;
}
#endif
} // namespace fixedpoint
} // namespace predicates
} // namespace volgrid
