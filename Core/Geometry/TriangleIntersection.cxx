#include "TriangleIntersection.h"

#include "Predicates.h"

#include <algorithm>

namespace volgrid
{
using predicates::orient2dProjected;
using predicates::orient3d;
} // namespace volgrid

namespace volgrid::detail
{

namespace
{

inline bool between(const double* p, const double* q, const double* r)
{
  for (int k = 0; k < 3; ++k)
  {
    const double lo = std::min(p[k], q[k]), hi = std::max(p[k], q[k]);
    if (r[k] < lo || r[k] > hi)
    {
      return false;
    }
  }
  return true;
}

// Closed 2D segment-segment test in the projection dropping `axis` (all points coplanar).
bool segmentsIntersect2(const double* p, const double* q, const double* r, const double* s, int axis)
{
  const int d1 = orient2dProjected(p, q, r, axis);
  const int d2 = orient2dProjected(p, q, s, axis);
  const int d3 = orient2dProjected(r, s, p, axis);
  const int d4 = orient2dProjected(r, s, q, axis);
  if (d1 * d2 < 0 && d3 * d4 < 0)
  {
    return true;
  }
  // Collinear touching: for coplanar points, projected collinearity is collinearity in 3D, and then
  // lying within the bounding box means lying on the segment.
  return (d1 == 0 && between(p, q, r)) || (d2 == 0 && between(p, q, s)) || (d3 == 0 && between(r, s, p)) ||
    (d4 == 0 && between(r, s, q));
}

} // namespace

int projectionAxis(const double* a, const double* b, const double* c)
{
  for (int k = 0; k < 3; ++k)
  {
    if (orient2dProjected(a, b, c, k) != 0)
    {
      return k;
    }
  }
  return -1;
}

bool pointInTriangle2(const double* p, const double* a, const double* b, const double* c, int axis, int o)
{
  return orient2dProjected(a, b, p, axis) * o >= 0 && orient2dProjected(b, c, p, axis) * o >= 0 &&
    orient2dProjected(c, a, p, axis) * o >= 0;
}

bool coplanarSegmentTriangle(const double* p, const double* q, const double* a, const double* b, const double* c)
{
  const int axis = projectionAxis(a, b, c);
  if (axis < 0)
  {
    return false;
  }
  const int o = orient2dProjected(a, b, c, axis);
  return pointInTriangle2(p, a, b, c, axis, o) || pointInTriangle2(q, a, b, c, axis, o) ||
    segmentsIntersect2(p, q, a, b, axis) || segmentsIntersect2(p, q, b, c, axis) ||
    segmentsIntersect2(p, q, c, a, axis);
}

} // namespace volgrid::detail

namespace volgrid
{

using detail::coplanarSegmentTriangle;
using detail::projectionAxis;

namespace
{

// Closed segment-triangle test; op/oq = orient3d(a,b,c,p) / orient3d(a,b,c,q).
bool segmentTriangle(const double* p, const double* q, const double* a, const double* b, const double* c, int op,
                     int oq)
{
  if (op == oq && op != 0)
  {
    return false;
  }
  if (op == 0 && oq == 0)
  {
    return coplanarSegmentTriangle(p, q, a, b, c);
  }
  const int s1 = orient3d(p, q, a, b);
  const int s2 = orient3d(p, q, b, c);
  const int s3 = orient3d(p, q, c, a);
  const bool pos = s1 > 0 || s2 > 0 || s3 > 0;
  const bool neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(pos && neg);
}

bool sameStrictSign(int a, int b, int c)
{
  return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
}

} // namespace

bool triangleIsDegenerate(const double* a, const double* b, const double* c)
{
  return projectionAxis(a, b, c) < 0;
}

bool trianglesIntersect(const double* const p[3], const int32_t ip[3], const double* const q[3], const int32_t iq[3])
{
  // Shared corners: sp[i] = index in q of p[i]'s vertex, or -1.
  int sp[3] = { -1, -1, -1 };
  int shared = 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (ip[i] == iq[j])
      {
        sp[i] = j;
        ++shared;
        break;
      }
    }
  }
  if (shared >= 3)
  {
    return true; // the same triangle twice: they overlap entirely
  }
  if (shared == 2)
  {
    // p = (a,b,c), q = (a,b,d): they overlap beyond ab only when coplanar with c, d on the same side.
    int ic = 0;
    while (sp[ic] >= 0)
    {
      ++ic;
    }
    int jd = 0;
    while (jd == sp[0] || jd == sp[1] || jd == sp[2])
    {
      ++jd;
    }
    const double* a = p[(ic + 1) % 3];
    const double* b = p[(ic + 2) % 3];
    const double* c = p[ic];
    const double* d = q[jd];
    if (orient3d(a, b, c, d) != 0)
    {
      return false;
    }
    const int axis = projectionAxis(a, b, c);
    return axis >= 0 && orient2dProjected(a, b, c, axis) * orient2dProjected(a, b, d, axis) > 0;
  }
  if (shared == 1)
  {
    int ia = 0;
    while (sp[ia] < 0)
    {
      ++ia;
    }
    const int ja = sp[ia];
    const double* a = p[ia];
    const double* b = p[(ia + 1) % 3];
    const double* c = p[(ia + 2) % 3];
    const double* d = q[(ja + 1) % 3];
    const double* e = q[(ja + 2) % 3];
    const int od = orient3d(a, b, c, d), oe = orient3d(a, b, c, e);
    if (od == oe && od != 0)
    {
      return false; // q touches p's plane only at a
    }
    const int ob = orient3d(a, d, e, b), oc = orient3d(a, d, e, c);
    if (ob == oc && ob != 0)
    {
      return false;
    }
    // Beyond a, the two triangles meet iff the far edge of one meets the other: each triangle meets
    // the other's plane (or, coplanar, each ray from a inside both) in a segment starting at a, and the
    // shorter of the two segments ends on a far edge inside the other triangle.
    return segmentTriangle(b, c, a, d, e, ob, oc) || segmentTriangle(d, e, a, b, c, od, oe);
  }
  int oq[3], op[3];
  for (int i = 0; i < 3; ++i)
  {
    oq[i] = orient3d(p[0], p[1], p[2], q[i]);
  }
  if (sameStrictSign(oq[0], oq[1], oq[2]))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    op[i] = orient3d(q[0], q[1], q[2], p[i]);
  }
  if (sameStrictSign(op[0], op[1], op[2]))
  {
    return false;
  }
  // Two closed triangles intersect iff an edge of one meets the other.
  for (int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    if (segmentTriangle(p[i], p[j], q[0], q[1], q[2], op[i], op[j]))
    {
      return true;
    }
    if (segmentTriangle(q[i], q[j], p[0], p[1], p[2], oq[i], oq[j]))
    {
      return true;
    }
  }
  return false;
}

} // namespace volgrid
