// Inline fast paths of the exact predicates, for hot loops (the Delaunay kernel).
//
// orient3dInline, insphereInline, insphereSoSInline and orient2dProjectedInline return exactly what
// orient3d, insphere, insphereSoS and orient2dProjected (Predicates.h) return: the functions there are
// these. Including this header lets the compiler inline the filtered double evaluation (~60 flops for
// insphere, branch-free up to one well-predicted test) into the caller; only the rare uncertain cases
// call out of line into the exact code of PredicatesAdaptive.cxx (detail::*Exact).
//
// The error bounds are derived in Predicates.cxx. They stay sound if the caller's translation unit
// contracts a*b+c into fused multiply-adds (a fused operation only removes a rounding), but Core is
// compiled with -ffp-contract=off anyway.
#pragma once

#include "Predicates.h"

#include <cmath>
#include <cstdint>

namespace volgrid
{
namespace predicates
{
namespace detail
{
constexpr double kEps = 0x1p-53; // unit roundoff of binary64
// c in |det - fl(det)| <= c * permanent (+ an underflow term), with slack; see Predicates.cxx.
constexpr double kOrient3dBound = (8.0 + 256.0 * kEps) * kEps;
constexpr double kInsphereBound = (16.0 + 1024.0 * kEps) * kEps;
constexpr double kOrient2dBound = (3.0 + 64.0 * kEps) * kEps;

inline int signOf(double x)
{
  return (x > 0.0) - (x < 0.0);
}

// The lifted insphere determinant D = det[p - e, |p - e|^2] of the rows a, b, c, d in the arithmetic of
// Real, with what its error bounds need: D = (w1 d023 - w0 d123) + (w3 d012 - w2 d013) (insphere =
// -sign(D)), the lifted values w_i = |p_i - e|^2 and the permanents q_i of the other three rows' absolute
// coordinates (q[0] = q123, q[1] = q023, q[2] = q013, q[3] = q012). One expression tree for the double
// filter below, the extended-precision stage (PredicatesAdaptive.cxx) and the Delaunay kernel's filter
// (DelaunayInserterImpl.h); what a caller does not use is optimised away.
template<typename Real>
struct InsphereTerms
{
  Real det;
  Real w[4];
  Real q[4];
  Real permanent() const { return (w[1] * q[1] + w[0] * q[0]) + (w[3] * q[3] + w[2] * q[2]); }
};

template<typename Real>
inline InsphereTerms<Real> insphereTerms(const double* a, const double* b, const double* c, const double* d,
                                         const double* e)
{
  const Real x0 = Real(a[0]) - e[0], y0 = Real(a[1]) - e[1], z0 = Real(a[2]) - e[2];
  const Real x1 = Real(b[0]) - e[0], y1 = Real(b[1]) - e[1], z1 = Real(b[2]) - e[2];
  const Real x2 = Real(c[0]) - e[0], y2 = Real(c[1]) - e[1], z2 = Real(c[2]) - e[2];
  const Real x3 = Real(d[0]) - e[0], y3 = Real(d[1]) - e[1], z3 = Real(d[2]) - e[2];
  const Real x0y1 = x0 * y1, x1y0 = x1 * y0, x0y2 = x0 * y2, x2y0 = x2 * y0;
  const Real x0y3 = x0 * y3, x3y0 = x3 * y0, x1y2 = x1 * y2, x2y1 = x2 * y1;
  const Real x1y3 = x1 * y3, x3y1 = x3 * y1, x2y3 = x2 * y3, x3y2 = x3 * y2;
  const Real m01 = x0y1 - x1y0, m02 = x0y2 - x2y0, m03 = x0y3 - x3y0;
  const Real m12 = x1y2 - x2y1, m13 = x1y3 - x3y1, m23 = x2y3 - x3y2;
  const Real d123 = (z1 * m23 - z2 * m13) + z3 * m12;
  const Real d023 = (z0 * m23 - z2 * m03) + z3 * m02;
  const Real d013 = (z0 * m13 - z1 * m03) + z3 * m01;
  const Real d012 = (z0 * m12 - z1 * m02) + z2 * m01;
  InsphereTerms<Real> t;
  t.w[0] = (x0 * x0 + y0 * y0) + z0 * z0;
  t.w[1] = (x1 * x1 + y1 * y1) + z1 * z1;
  t.w[2] = (x2 * x2 + y2 * y2) + z2 * z2;
  t.w[3] = (x3 * x3 + y3 * y3) + z3 * z3;
  t.det = (t.w[1] * d023 - t.w[0] * d123) + (t.w[3] * d012 - t.w[2] * d013);
  const Real p01 = std::fabs(x0y1) + std::fabs(x1y0), p02 = std::fabs(x0y2) + std::fabs(x2y0);
  const Real p03 = std::fabs(x0y3) + std::fabs(x3y0), p12 = std::fabs(x1y2) + std::fabs(x2y1);
  const Real p13 = std::fabs(x1y3) + std::fabs(x3y1), p23 = std::fabs(x2y3) + std::fabs(x3y2);
  const Real az0 = std::fabs(z0), az1 = std::fabs(z1), az2 = std::fabs(z2), az3 = std::fabs(z3);
  t.q[0] = (az1 * p23 + az2 * p13) + az3 * p12;
  t.q[1] = (az0 * p23 + az2 * p03) + az3 * p02;
  t.q[2] = (az0 * p13 + az1 * p03) + az3 * p01;
  t.q[3] = (az0 * p12 + az1 * p02) + az2 * p01;
  return t;
}

// Exact evaluations (Predicates.cxx), called when the filter cannot decide.
int orient3dExact(const double* a, const double* b, const double* c, const double* d);
int insphereExact(const double* a, const double* b, const double* c, const double* d, const double* e);
int orient2dExact(const double* a, const double* b, const double* c, int i, int j);
// The same as orient3dExact / insphereExact, reporting which stage decided in *stage (tests, tuning):
// 1 = long double filter, 2 = exact coordinate differences, 3 = stage B (rounded differences, exactly),
// 4 = stage C (first-order tail correction), 5 = full evaluation over the raw coordinates, 6 = big
// integers (extreme exponents), 7 = fixed-point integers (narrow exponent range, PredicatesFixed.h).
// extended = false skips stage 1, fixedPoint = false skips stage 7 (to exercise the others). The
// production path (orient3dExact / insphereExact) tries stage 7 first, then 1, then 2..6.
int orient3dExactStaged(const double* a, const double* b, const double* c, const double* d, bool extended, int* stage,
                        bool fixedPoint = false);
int insphereExactStaged(const double* a, const double* b, const double* c, const double* d, const double* e,
                        bool extended, int* stage, bool fixedPoint = false);
// insphereSoS when insphere(a,b,c,d,e) == 0: the first nonzero cofactor in decreasing id order.
int insphereSoSTie(const double* a, const double* b, const double* c, const double* d, const double* e, int64_t ida,
                   int64_t idb, int64_t idc, int64_t idd, int64_t ide);
} // namespace detail

inline int orient3dInline(const double* a, const double* b, const double* c, const double* d)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double vywz = vy * wz, vzwy = vz * wy;
  const double vzwx = vz * wx, vxwz = vx * wz;
  const double vxwy = vx * wy, vywx = vy * wx;
  const double det = (ux * (vywz - vzwy) + uy * (vzwx - vxwz)) + uz * (vxwy - vywx);
  const double aux = std::fabs(ux), auy = std::fabs(uy), auz = std::fabs(uz);
  const double perm = (aux * (std::fabs(vywz) + std::fabs(vzwy)) + auy * (std::fabs(vzwx) + std::fabs(vxwz))) +
    auz * (std::fabs(vxwy) + std::fabs(vywx));
  // Underflow term U / c, a normal number (see Predicates.cxx).
  const double under = 0x1p-1020 * (((aux + auy) + auz) + 1.0);
  const double bound = detail::kOrient3dBound * (perm + under);
  if (std::fabs(det) > bound)
  {
    return detail::signOf(det);
  }
  return detail::orient3dExact(a, b, c, d);
}

inline int insphereInline(const double* a, const double* b, const double* c, const double* d, const double* e)
{
  const detail::InsphereTerms<double> t = detail::insphereTerms<double>(a, b, c, d, e);
  const double* w = t.w;
  const double* q = t.q;
  const double wsum = ((w[0] + w[1]) + (w[2] + w[3])) + 4.0;
  const double under = 0x1p-1020 * (wsum * wsum + ((q[0] + q[1]) + (q[2] + q[3])));
  const double bound = detail::kInsphereBound * (t.permanent() + under);
  if (std::fabs(t.det) > bound)
  {
    return -detail::signOf(t.det);
  }
  return detail::insphereExact(a, b, c, d, e);
}

inline int insphereSoSInline(const double* a, const double* b, const double* c, const double* d, const double* e,
                             int64_t ida, int64_t idb, int64_t idc, int64_t idd, int64_t ide)
{
  const int s = insphereInline(a, b, c, d, e);
  if (s != 0)
  {
    return s;
  }
  return detail::insphereSoSTie(a, b, c, d, e, ida, idb, idc, idd, ide);
}

inline int orient2dProjectedInline(const double* a, const double* b, const double* c, int dropAxis)
{
  // Cyclic frame: (i, j) = ((k+1)%3, (k+2)%3), so the result is the sign of ((b-a)x(c-a))[k].
  const int i = dropAxis == 2 ? 0 : dropAxis + 1;
  const int j = dropAxis == 0 ? 2 : dropAxis - 1;
  const double ui = b[i] - a[i], uj = b[j] - a[j];
  const double vi = c[i] - a[i], vj = c[j] - a[j];
  const double l = ui * vj, r = uj * vi;
  const double det = l - r;
  const double bound = detail::kOrient2dBound * ((std::fabs(l) + std::fabs(r)) + 0x1p-1021);
  if (std::fabs(det) > bound)
  {
    return detail::signOf(det);
  }
  return detail::orient2dExact(a, b, c, i, j);
}

} // namespace predicates
} // namespace volgrid
