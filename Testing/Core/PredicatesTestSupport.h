// Shared helpers of the predicate tests (TestPredicates*.cxx): rational reference signs and small point
// helpers, in one place so that every test file checks against the same references.
// The reference for "exact" is rational arithmetic (GMP mpq_class): every double is a rational, so the
// references below are the true signs, computed from independent geometric definitions where possible
// (circumcentres rather than lifted determinants).
#pragma once

#include "Predicates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace predicates_test
{
namespace P = volgrid::predicates;
using Pt = std::array<double, 3>;
using Q = mpq_class;
using QPt = std::array<Q, 3>;

inline QPt toQ(const Pt& p)
{
  return { Q(p[0]), Q(p[1]), Q(p[2]) };
}
inline QPt sub(const QPt& a, const QPt& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Q dot(const QPt& a, const QPt& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline QPt cross(const QPt& a, const QPt& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

// ---- Exact references --------------------------------------------------------------------------
inline int refOrient3d(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  const QPt qa = toQ(a);
  return sgn(dot(sub(toQ(b), qa), cross(sub(toQ(c), qa), sub(toQ(d), qa))));
}

// Circumcentre of the tetrahedron by Cramer's rule; inside <=> |e - o| < |a - o|.
inline int refInsphere(const Pt& a, const Pt& b, const Pt& c, const Pt& d, const Pt& e)
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
inline int refIncircle3d(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
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

inline int refOrient2dProjected(const Pt& a, const Pt& b, const Pt& c, int k)
{
  const QPt qa = toQ(a);
  return sgn(cross(sub(toQ(b), qa), sub(toQ(c), qa))[k]);
}

// ---- Helpers ---------------------------------------------------------------------------------------
inline int orient(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  return P::orient3d(a.data(), b.data(), c.data(), d.data());
}
inline int insph(const Pt& a, const Pt& b, const Pt& c, const Pt& d, const Pt& e)
{
  return P::insphere(a.data(), b.data(), c.data(), d.data(), e.data());
}
inline int incirc(const Pt& a, const Pt& b, const Pt& c, const Pt& d)
{
  return P::incircle3d(a.data(), b.data(), c.data(), d.data());
}
inline Pt affine(const Pt& p, double scale, double shift)
{
  return { p[0] * scale + shift, p[1] * scale + shift, p[2] * scale + shift };
}
inline Pt nudge(Pt p, int axis, int ulps)
{
  for (int i = 0; i < std::abs(ulps); ++i)
  {
    p[axis] = std::nextafter(p[axis], ulps > 0 ? HUGE_VAL : -HUGE_VAL);
  }
  return p;
}

inline const std::vector<Pt>& cube()
{
  static const std::vector<Pt> c = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 },
                                     { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };
  return c;
}

// Integer points on the sphere x^2 + y^2 + z^2 = 9: permutations and signs of (1,2,2) and (3,0,0).
inline std::vector<Pt> sphere9()
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

inline int permutationParity(const std::array<int, 5>& p, int n)
{
  int inv = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      inv += p[i] > p[j];
  return (inv & 1) ? -1 : 1;
}

} // namespace predicates_test
