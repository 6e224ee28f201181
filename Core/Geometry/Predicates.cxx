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
//      See "Adaptive stages" in PredicatesAdaptive.cxx for the bounds.
//      Before all of these, inputs whose coordinates span at most 61 bits (from the highest to the lowest
//      set bit over the call: the usual case, e.g. structured grids x0 + i h with non-dyadic h, whose
//      exactly cospherical cells defeat every filter) are evaluated exactly on fixed-point integers
//      with 64/128/192/320-bit arithmetic (PredicatesFixed.h, bit bounds in PredicatesFixed.cxx):
//      ~10x cheaper than the full expansion evaluation, and it certifies exact zeros.
//   3. Inputs whose bits span more than the scaling window (e.g. 1e-300 and 1e+300 in one call) are
//      evaluated with exact big integers instead (BigInt, PredicatesWide.cxx), so any finite doubles
//      are handled.
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
//
// This file: the overview above, the exact orient2d and incircle3d, the SoS tie-break and the public
// entry points. The exact stages of orient3d / insphere are in PredicatesAdaptive.cxx, the big-integer
// fallback in PredicatesWide.cxx, the helpers they share in PredicatesInternal.h.
#include "Predicates.h"
#include "PredicatesInline.h"

#include "ExpansionArithmetic.h"
#include "PredicatesFixed.h"
#include "PredicatesInternal.h"

#include <cmath>
#include <utility>

namespace volgrid
{
namespace predicates
{
namespace
{
using namespace expansion;
using namespace internal;

using detail::kEps;
using detail::signOf;
constexpr double kIncircleBound = (12.0 + 512.0 * kEps) * kEps;

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
  auto minor = [&](int r, int s, double* out)
  {
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
int orient2dExact(const double* a, const double* b, const double* c, int i, int j)
{
  return orient2dExactImpl(a, b, c, i, j);
}

int insphereSoSTie(const double* a, const double* b, const double* c, const double* d, const double* e, int64_t ida,
                   int64_t idb, int64_t idc, int64_t idd, int64_t ide)
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

int insphereSoS(const double* a, const double* b, const double* c, const double* d, const double* e, int64_t ida,
                int64_t idb, int64_t idc, int64_t idd, int64_t ide)
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
  const double n[3] = { std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz), std::fabs(ux * vy - uy * vx) };
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
