#include "ShellNesting.h"

#include "Predicates.h"
#include "TriangleIntersection.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{

using detail::coplanarSegmentTriangle;
using detail::pointInTriangle2;
using detail::projectionAxis;
using predicates::orient2dProjected;
using predicates::orient3d;

int pointInClosedSurface(const SurfaceMesh& mesh, const std::vector<int32_t>& triangleIds, const double* x)
{
  BoundingBox box;
  for (int32_t t : triangleIds)
  {
    for (int k = 0; k < 3; ++k)
    {
      box.add(mesh.point(mesh.triangle(t)[k]));
    }
  }
  if (!box.valid)
  {
    return -1;
  }
  for (int k = 0; k < 3; ++k)
  {
    if (x[k] < box.min[k] || x[k] > box.max[k])
    {
      return -1;
    }
  }
  double reach = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    reach += std::fabs(box.max[k] - box.min[k]) + std::fabs(x[k]) + std::fabs(box.min[k]) + std::fabs(box.max[k]);
  }
  reach *= 2.0;
  uint64_t rng = 0x9E3779B97F4A7C15ull;
  for (int attempt = 0; attempt < 64; ++attempt)
  {
    // Axis directions first (cheap box rejection), then pseudo-random directions.
    double dir[3] = { 0, 0, 0 };
    int axis = -1;
    if (attempt < 6)
    {
      axis = attempt % 3;
      dir[axis] = attempt < 3 ? 1.0 : -1.0;
    }
    else
    {
      for (int k = 0; k < 3; ++k)
      {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        dir[k] = static_cast<double>(rng >> 11) / 9007199254740992.0 - 0.5;
      }
    }
    double r[3];
    for (int k = 0; k < 3; ++k)
    {
      r[k] = x[k] + reach * dir[k];
    }
    if (axis >= 0)
    {
      r[(axis + 1) % 3] = x[(axis + 1) % 3]; // keep the ray exactly axis-parallel
      r[(axis + 2) % 3] = x[(axis + 2) % 3];
    }
    int crossings = 0;
    bool degenerate = false;
    for (int32_t t : triangleIds)
    {
      const int32_t* v = mesh.triangle(t);
      const double* a = mesh.point(v[0]);
      const double* b = mesh.point(v[1]);
      const double* c = mesh.point(v[2]);
      if (axis >= 0)
      {
        bool miss = false;
        for (int m = 1; m <= 2 && !miss; ++m)
        {
          const int k = (axis + m) % 3;
          miss = x[k] < std::min({ a[k], b[k], c[k] }) || x[k] > std::max({ a[k], b[k], c[k] });
        }
        const double lo = std::min(x[axis], r[axis]), hi = std::max(x[axis], r[axis]);
        miss = miss || std::max({ a[axis], b[axis], c[axis] }) < lo || std::min({ a[axis], b[axis], c[axis] }) > hi;
        if (miss)
        {
          continue;
        }
      }
      const int o1 = orient3d(a, b, c, x);
      const int o2 = orient3d(a, b, c, r);
      if (o1 == 0)
      {
        const int ax = projectionAxis(a, b, c);
        if (ax >= 0 && pointInTriangle2(x, a, b, c, ax, orient2dProjected(a, b, c, ax)))
        {
          return 0;
        }
      }
      if (o1 == o2 && o1 != 0)
      {
        continue;
      }
      if (o1 == 0 || o2 == 0)
      {
        // The ray touches the plane at an end point, or lies in it: a hit there is a degenerate case.
        if (o1 == 0 && o2 == 0)
        {
          if (coplanarSegmentTriangle(x, r, a, b, c))
          {
            degenerate = true;
            break;
          }
        }
        else if (o2 == 0)
        {
          const int ax = projectionAxis(a, b, c);
          if (ax >= 0 && pointInTriangle2(r, a, b, c, ax, orient2dProjected(a, b, c, ax)))
          {
            degenerate = true;
            break;
          }
        }
        continue; // o1 == 0 with x outside the triangle: the segment meets the plane only at x
      }
      const int s1 = orient3d(x, r, a, b);
      const int s2 = orient3d(x, r, b, c);
      const int s3 = orient3d(x, r, c, a);
      const bool pos = s1 > 0 || s2 > 0 || s3 > 0;
      const bool neg = s1 < 0 || s2 < 0 || s3 < 0;
      if (pos && neg)
      {
        continue;
      }
      if (s1 == 0 || s2 == 0 || s3 == 0)
      {
        degenerate = true; // through an edge or a vertex
        break;
      }
      ++crossings;
    }
    if (!degenerate)
    {
      return (crossings % 2) ? 1 : -1;
    }
  }
  return -1; // unreachable in practice: 64 directions all degenerate
}

void detail::nestShells(const SurfaceMesh& mesh, const std::vector<std::vector<int32_t>>& shellTris,
                        SurfaceCheckReport& r)
{
  const size_t ns = r.shells.size();
  std::vector<std::vector<int32_t>> containers(ns);
  for (size_t b = 0; b < ns; ++b)
  {
    if (!r.shells[b].closed)
    {
      continue;
    }
    for (size_t a = 0; a < ns; ++a)
    {
      if (a == b || !r.shells[a].closed)
      {
        continue;
      }
      const double* ba = r.shells[a].bounds;
      const double* bb = r.shells[b].bounds;
      bool inside = true;
      for (int k = 0; k < 3; ++k)
      {
        inside = inside && ba[2 * k] <= bb[2 * k] && bb[2 * k + 1] <= ba[2 * k + 1];
      }
      if (!inside)
      {
        continue;
      }
      // A vertex of b that is not on a decides.
      int where = 0;
      for (int32_t t : shellTris[b])
      {
        for (int k = 0; k < 3 && where == 0; ++k)
        {
          where = pointInClosedSurface(mesh, shellTris[a], mesh.point(mesh.triangle(t)[k]));
        }
        if (where != 0)
        {
          break;
        }
      }
      if (where > 0)
      {
        containers[b].push_back(static_cast<int32_t>(a));
      }
    }
    r.shells[b].depth = static_cast<int>(containers[b].size());
  }
  for (size_t b = 0; b < ns; ++b)
  {
    int best = -1;
    for (int32_t a : containers[b])
    {
      if (best < 0 || r.shells[a].depth > best)
      {
        best = r.shells[a].depth;
        r.shells[b].parent = a;
      }
    }
  }
}

} // namespace volgrid
