// TetGen-style planar facets: several polygons plus hole points. The polygons are nested (a polygon
// inside another is an inner boundary of the outer one's region); a region holding a hole point is cut
// away, every other region is triangulated with its directly nested polygons as holes, so the nested
// polygons' edges appear on both sides and each region is covered exactly once. Nesting and hole
// location use exact point-in-polygon tests (crossing parity decided by orient2d in the projection).
#include "PolygonTriangulation.h"

#include <algorithm>
#include <vector>

namespace volgrid
{

namespace
{
enum class Where
{
  Outside,
  Inside,
  Boundary
};

// Exact point-in-polygon in the frame: parity of the edges crossed by the ray from q towards +u.
Where locate(const std::vector<double>& points, const std::vector<int32_t>& loop, const double* q,
             const ProjectionFrame& frame)
{
  const int v = (frame.drop + 2) % 3;
  bool inside = false;
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = points.data() + 3 * size_t(loop[i]);
    const double* b = points.data() + 3 * size_t(loop[(i + 1) % n]);
    if (!frame.lessUV(a, q) && !frame.lessUV(q, a))
    {
      return Where::Boundary; // q is this corner
    }
    const bool aAbove = a[v] > q[v], bAbove = b[v] > q[v];
    if (aAbove != bAbove)
    {
      // The edge spans q's v (half-open, so a corner on the ray counts once): q left of the upward edge
      // (right of the downward one) means the edge crosses the ray.
      const int o = frame.orient(a, b, q);
      if (o == 0)
      {
        return Where::Boundary;
      }
      if ((o > 0) == bAbove)
      {
        inside = !inside;
      }
    }
    else if (a[v] == q[v] && b[v] == q[v] && frame.orient(a, b, q) == 0)
    {
      // Horizontal edge on q's line: q on it?
      if (!frame.lessUV(q, std::min(a, b, [&](const double* x, const double* y) { return frame.lessUV(x, y); })) &&
          !frame.lessUV(std::max(a, b, [&](const double* x, const double* y) { return frame.lessUV(x, y); }), q))
      {
        return Where::Boundary;
      }
    }
  }
  return inside ? Where::Inside : Where::Outside;
}

// Polygon `inner` lies inside polygon `outer`: decided at its first corner that is not on `outer`.
bool nestedIn(const std::vector<double>& points, const std::vector<int32_t>& inner, const std::vector<int32_t>& outer,
              const ProjectionFrame& frame)
{
  for (int32_t id : inner)
  {
    const Where w = locate(points, outer, points.data() + 3 * size_t(id), frame);
    if (w != Where::Boundary)
    {
      return w == Where::Inside;
    }
  }
  return false; // every corner on the other polygon: the same polygon, not nested
}
} // namespace

bool triangulateFacet(const std::vector<double>& points, const std::vector<std::vector<int32_t>>& polygons,
                      const std::vector<double>& holePoints, std::vector<int32_t>& out, FacetTriangulationInfo* infoOut)
{
  FacetTriangulationInfo localInfo;
  FacetTriangulationInfo& info = infoOut ? *infoOut : localInfo;
  info = FacetTriangulationInfo();
  std::vector<const std::vector<int32_t>*> loops;
  for (const auto& p : polygons)
  {
    if (p.size() >= 3)
    {
      loops.push_back(&p);
    }
  }
  const size_t n = loops.size();
  if (n == 0)
  {
    return true;
  }
  // The projection of the facet: that of its largest polygon (the Newell normals of nested polygons of
  // opposite orientations would cancel in a sum).
  double normal[3] = { 0, 0, 0 };
  double largest = -1;
  for (const auto* loop : loops)
  {
    double nrm[3] = { 0, 0, 0 };
    addNewellNormal(points, *loop, nrm);
    const double size = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
    if (size > largest)
    {
      largest = size;
      std::copy(nrm, nrm + 3, normal);
    }
  }
  ProjectionFrame frame;
  if (!frame.chooseFrom(normal))
  {
    // No plane: every polygon on its own, as a single polygon would be.
    for (const auto* loop : loops)
    {
      ++info.regions;
      if (!triangulatePolygon(points, *loop, out))
      {
        ++info.failures;
      }
    }
    return info.failures == 0;
  }
  // Nesting: depth = number of polygons containing a polygon; its parent is the containing polygon of
  // depth one less (the innermost one).
  std::vector<std::vector<char>> inside(n, std::vector<char>(n, 0)); // inside[i][j]: i nested in j
  std::vector<int> depth(n, 0);
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = 0; j < n; ++j)
    {
      if (i != j && nestedIn(points, *loops[i], *loops[j], frame))
      {
        inside[i][j] = 1;
        ++depth[i];
      }
    }
  }
  std::vector<int> parent(n, -1);
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = 0; j < n; ++j)
    {
      if (inside[i][j] && depth[j] == depth[i] - 1)
      {
        parent[i] = static_cast<int>(j);
      }
    }
  }
  // A hole point removes the region of the innermost polygon containing it.
  std::vector<char> removed(n, 0);
  for (size_t h = 0; 3 * h + 2 < holePoints.size(); ++h)
  {
    const double* q = holePoints.data() + 3 * h;
    int innermost = -1;
    for (size_t j = 0; j < n; ++j)
    {
      if (locate(points, *loops[j], q, frame) == Where::Inside && (innermost < 0 || depth[j] > depth[innermost]))
      {
        innermost = static_cast<int>(j);
      }
    }
    if (innermost < 0)
    {
      ++info.unusedHolePoints;
    }
    else if (!removed[innermost])
    {
      removed[innermost] = 1;
      ++info.holeRegions;
    }
  }
  std::vector<std::vector<int32_t>> children;
  for (size_t i = 0; i < n; ++i)
  {
    if (removed[i])
    {
      continue;
    }
    children.clear();
    for (size_t j = 0; j < n; ++j)
    {
      if (parent[j] == static_cast<int>(i))
      {
        children.push_back(*loops[j]);
      }
    }
    ++info.regions;
    const bool ok = children.empty() ? triangulatePolygon(points, *loops[i], out)
                                     : triangulatePolygonWithHoles(points, *loops[i], children, frame, out);
    if (!ok)
    {
      ++info.failures;
    }
  }
  return info.failures == 0;
}

} // namespace volgrid
