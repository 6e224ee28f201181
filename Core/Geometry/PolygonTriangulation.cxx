// Polygon triangulation by ear clipping in the polygon's plane (triangulatePolygon is declared in
// SurfaceReader.h; the readers split every polygon face with it), and the projection frame shared with
// the hole and facet triangulations (PolygonTriangulation.h).
#include "PolygonTriangulation.h"

#include "Predicates.h"

#include <cmath>
#include <vector>

namespace volgrid
{

namespace
{
double triangleQuality(const double* a, const double* b, const double* c)
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    e[0][k] = b[k] - a[k];
    e[1][k] = c[k] - b[k];
    e[2][k] = a[k] - c[k];
  }
  const double nx = e[0][1] * e[2][2] - e[0][2] * e[2][1];
  const double ny = e[0][2] * e[2][0] - e[0][0] * e[2][2];
  const double nz = e[0][0] * e[2][1] - e[0][1] * e[2][0];
  const double area2 = std::sqrt(nx * nx + ny * ny + nz * nz);
  double l2 = 0;
  for (int i = 0; i < 3; ++i)
  {
    l2 += e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
  }
  return l2 > 0 ? 2.0 * std::sqrt(3.0) * area2 / l2 : 0.0; // 1 for equilateral
}
} // namespace

bool ProjectionFrame::chooseFrom(const double normal[3])
{
  drop = 2;
  for (int k = 0; k < 3; ++k)
  {
    if (std::fabs(normal[k]) > std::fabs(normal[drop]))
    {
      drop = k;
    }
  }
  return normal[drop] != 0.0 && std::isfinite(normal[drop]);
}

int ProjectionFrame::orient(const double* a, const double* b, const double* c) const
{
  // orient2dProjected is the sign of the drop-th component of (b-a)x(c-a): counter-clockwise in (u, v).
  return predicates::orient2dProjected(a, b, c, drop);
}

bool ProjectionFrame::lessUV(const double* a, const double* b) const
{
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  return a[u] < b[u] || (a[u] == b[u] && a[v] < b[v]);
}

void addNewellNormal(const std::vector<double>& points, const std::vector<int32_t>& loop, double nrm[3])
{
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = points.data() + 3 * size_t(loop[i]);
    const double* b = points.data() + 3 * size_t(loop[(i + 1) % n]);
    nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
    nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
    nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
}

int loopOrientation(const std::vector<double>& points, const std::vector<int32_t>& loop, const ProjectionFrame& frame)
{
  const size_t n = loop.size();
  if (n < 3)
  {
    return 0;
  }
  auto P = [&](size_t i) { return points.data() + 3 * size_t(loop[i % n]); };
  size_t low = 0;
  for (size_t i = 1; i < n; ++i)
  {
    if (frame.lessUV(P(i), P(low)))
    {
      low = i;
    }
  }
  return frame.orient(P(low + n - 1), P(low), P(low + 1));
}

bool triangulatePolygon(const std::vector<double>& points, const std::vector<int32_t>& loop, std::vector<int32_t>& out)
{
  if (loop.size() < 3)
  {
    return false;
  }
  // Newell normal: its largest component picks the projection, its sign the loop orientation there.
  double nrm[3] = { 0, 0, 0 };
  addNewellNormal(points, loop, nrm);
  ProjectionFrame frame;
  const bool planar = frame.chooseFrom(nrm);
  if (!planar && loop.size() > 3)
  {
    for (size_t i = 1; i + 1 < loop.size(); ++i)
    {
      out.push_back(loop[0]);
      out.push_back(loop[i]);
      out.push_back(loop[i + 1]);
    }
    return false;
  }
  return earClipPolygon(points, loop, frame, nrm[frame.drop] > 0 ? 1 : -1, out);
}

bool earClipPolygon(const std::vector<double>& points, const std::vector<int32_t>& loop, const ProjectionFrame& frame,
                    int sign, std::vector<int32_t>& out)
{
  const size_t n = loop.size();
  if (n < 3)
  {
    return false;
  }
  if (n == 3)
  {
    out.insert(out.end(), loop.begin(), loop.end());
    return true;
  }
  auto P = [&](int32_t id) { return points.data() + 3 * size_t(id); };
  auto fan = [&](const std::vector<int32_t>& rest)
  {
    for (size_t i = 1; i + 1 < rest.size(); ++i)
    {
      out.push_back(rest[0]);
      out.push_back(rest[i]);
      out.push_back(rest[i + 1]);
    }
  };
  auto orient = [&](int32_t a, int32_t b, int32_t c) { return frame.orient(P(a), P(b), P(c)) * sign; };

  std::vector<int32_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i)
  {
    prev[i] = static_cast<int32_t>((i + n - 1) % n);
    next[i] = static_cast<int32_t>((i + 1) % n);
  }
  std::vector<char> alive(n, 1);
  std::vector<double> quality(n, -1.0); // < 0: not an ear
  auto evaluate = [&](int32_t i)
  {
    const int32_t ia = prev[i], ic = next[i];
    const int32_t a = loop[ia], b = loop[i], c = loop[ic];
    quality[i] = -1.0;
    if (orient(a, b, c) <= 0)
    {
      return;
    }
    for (int32_t j = next[ic]; j != ia; j = next[j])
    {
      const int32_t p = loop[j];
      if (p == a || p == b || p == c)
      {
        continue;
      }
      if (orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0)
      {
        return; // p inside or on the ear: cutting it would cross or touch the boundary
      }
    }
    quality[i] = triangleQuality(P(a), P(b), P(c));
  };
  for (size_t i = 0; i < n; ++i)
  {
    evaluate(static_cast<int32_t>(i));
  }
  size_t remaining = n;
  int32_t start = 0;
  bool refreshed = false;
  while (remaining > 3)
  {
    int32_t best = -1;
    int32_t i = start;
    do
    {
      if (quality[i] >= 0 && (best < 0 || quality[i] > quality[best]))
      {
        best = i;
      }
      i = next[i];
    } while (i != start);
    if (best < 0)
    {
      if (!refreshed)
      {
        // Removing a vertex can unblock ears elsewhere; re-evaluate everything once before giving up.
        i = start;
        do
        {
          evaluate(i);
          i = next[i];
        } while (i != start);
        refreshed = true;
        continue;
      }
      std::vector<int32_t> rest;
      i = start;
      do
      {
        rest.push_back(loop[i]);
        i = next[i];
      } while (i != start);
      fan(rest);
      return false;
    }
    refreshed = false;
    const int32_t ia = prev[best], ic = next[best];
    out.push_back(loop[ia]);
    out.push_back(loop[best]);
    out.push_back(loop[ic]);
    alive[best] = 0;
    next[ia] = ic;
    prev[ic] = ia;
    --remaining;
    start = ia;
    if (remaining > 3)
    {
      evaluate(ia);
      evaluate(ic);
    }
  }
  out.push_back(loop[prev[start]]);
  out.push_back(loop[start]);
  out.push_back(loop[next[start]]);
  return true;
}

} // namespace volgrid
