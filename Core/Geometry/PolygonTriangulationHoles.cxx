// Polygons with holes: every hole is cut open and joined to the outer boundary by a bridge edge (the
// hole's loop is spliced into the outer loop there, so the bridge's two ends appear twice), and the
// joined loop, one weakly simple polygon, is ear-clipped. Holes are bridged right to left (largest u
// first, as in Eberly's "Triangulation by Ear Clipping"), so the nearest boundary visible from a hole's
// rightmost corner is already part of the joined loop. Every bridge candidate is checked with exact
// orientation tests: it must leave both of its corners into the region and cross or touch no edge.
#include "PolygonTriangulation.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace volgrid
{

namespace
{
class HoleBridger
{
public:
  HoleBridger(const std::vector<double>& points, const ProjectionFrame& frame)
    : Points(points)
    , Frame(frame)
  {
  }

  const double* P(int32_t id) const { return Points.data() + 3 * size_t(id); }

  // True when the direction from loop corner i towards point q leaves the corner strictly into the
  // region left of the loop (counter-clockwise region; a hole loop is given clockwise).
  bool insideCorner(const std::vector<int32_t>& loop, size_t i, int32_t q) const
  {
    const size_t n = loop.size();
    const double* a = P(loop[(i + n - 1) % n]);
    const double* b = P(loop[i]);
    const double* c = P(loop[(i + 1) % n]);
    const int left1 = Frame.orient(a, b, P(q));
    const int left2 = Frame.orient(b, c, P(q));
    if (Frame.orient(a, b, c) > 0)
    {
      return left1 > 0 && left2 > 0; // convex corner: inside both edges
    }
    return left1 > 0 || left2 > 0; // reflex (or straight) corner: inside either edge
  }

  // True when the closed segments pq and cd share a point.
  bool segmentsMeet(int32_t p, int32_t q, int32_t c, int32_t d) const
  {
    const int o1 = Frame.orient(P(p), P(q), P(c));
    const int o2 = Frame.orient(P(p), P(q), P(d));
    const int o3 = Frame.orient(P(c), P(d), P(p));
    const int o4 = Frame.orient(P(c), P(d), P(q));
    if (o1 == 0 && o2 == 0)
    {
      // Collinear: they meet when their (u, v)-sorted extents overlap.
      auto lo = [&](int32_t x, int32_t y) { return Frame.lessUV(P(x), P(y)) ? x : y; };
      auto hi = [&](int32_t x, int32_t y) { return Frame.lessUV(P(x), P(y)) ? y : x; };
      return !Frame.lessUV(P(hi(p, q)), P(lo(c, d))) && !Frame.lessUV(P(hi(c, d)), P(lo(p, q)));
    }
    return o1 * o2 <= 0 && o3 * o4 <= 0;
  }

  // True when segment pq crosses or touches an edge of `loop` (edges at p or q are not tested here:
  // the corner tests decide about them).
  bool hitsLoop(int32_t p, int32_t q, const std::vector<int32_t>& loop) const
  {
    const size_t n = loop.size();
    for (size_t i = 0; i < n; ++i)
    {
      const int32_t c = loop[i], d = loop[(i + 1) % n];
      if (c == p || c == q || d == p || d == q)
      {
        continue;
      }
      if (segmentsMeet(p, q, c, d))
      {
        return true;
      }
    }
    return false;
  }

  double distance2(int32_t p, int32_t q) const
  {
    double s = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double d = P(p)[k] - P(q)[k];
      s += d * d;
    }
    return s;
  }

  // Joins `hole` (clockwise) into `joined` (counter-clockwise); `pending` are the holes not joined yet.
  bool bridge(std::vector<int32_t>& joined, const std::vector<int32_t>& hole,
              const std::vector<std::vector<int32_t>>& pending) const
  {
    const size_t m = hole.size();
    // Hole corners by decreasing u: the rightmost one sees the joined loop (Eberly); the others are
    // tried only for inputs where it does not (touching or slightly non-planar loops).
    std::vector<size_t> order(m);
    for (size_t i = 0; i < m; ++i)
    {
      order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return Frame.lessUV(P(hole[b]), P(hole[a])); });
    std::vector<std::pair<double, size_t>> candidates;
    for (size_t hi : order)
    {
      const int32_t h = hole[hi];
      // Nearest joined corners first: the first valid one is the bridge (usually one of the first few).
      candidates.clear();
      for (size_t j = 0; j < joined.size(); ++j)
      {
        candidates.emplace_back(distance2(h, joined[j]), j);
      }
      std::sort(candidates.begin(), candidates.end());
      size_t best = joined.size();
      for (const auto& [d2, j] : candidates)
      {
        const int32_t o = joined[j];
        if (o == h)
        {
          // The hole touches the boundary at this corner: splice with a bridge of length zero.
          best = j;
          break;
        }
        if (!insideCorner(joined, j, h) || !insideCorner(hole, hi, o) || hitsLoop(o, h, joined) || hitsLoop(o, h, hole))
        {
          continue;
        }
        bool clear = true;
        for (const auto& other : pending)
        {
          if (hitsLoop(o, h, other))
          {
            clear = false;
            break;
          }
        }
        if (clear)
        {
          best = j;
          break;
        }
      }
      if (best == joined.size())
      {
        continue;
      }
      // joined[..best], hole from hi around back to hi, joined[best..]: o, h, ..., h, o.
      std::vector<int32_t> spliced;
      spliced.reserve(joined.size() + m + 2);
      spliced.insert(spliced.end(), joined.begin(), joined.begin() + static_cast<std::ptrdiff_t>(best) + 1);
      const bool touching = joined[best] == h;
      for (size_t k = touching ? 1 : 0; k <= m; ++k)
      {
        spliced.push_back(hole[(hi + k) % m]);
      }
      if (!touching)
      {
        spliced.push_back(joined[best]);
      }
      spliced.insert(spliced.end(), joined.begin() + static_cast<std::ptrdiff_t>(best) + 1, joined.end());
      joined.swap(spliced);
      return true;
    }
    return false;
  }

private:
  const std::vector<double>& Points;
  const ProjectionFrame& Frame;
};
} // namespace

bool triangulatePolygonWithHoles(const std::vector<double>& points, const std::vector<int32_t>& outer,
                                 const std::vector<std::vector<int32_t>>& holes, const ProjectionFrame& frame,
                                 std::vector<int32_t>& out)
{
  const int outerSign = loopOrientation(points, outer, frame);
  if (outerSign == 0)
  {
    earClipPolygon(points, outer, frame, 1, out);
    return false;
  }
  // Work counter-clockwise with clockwise holes; the triangles are flipped back at the end if needed.
  std::vector<int32_t> joined = outer;
  if (outerSign < 0)
  {
    std::reverse(joined.begin(), joined.end());
  }
  std::vector<std::vector<int32_t>> pending;
  for (const auto& hole : holes)
  {
    if (hole.size() < 3)
    {
      continue;
    }
    pending.push_back(hole);
    if (loopOrientation(points, hole, frame) > 0)
    {
      std::reverse(pending.back().begin(), pending.back().end());
    }
  }
  auto rightmost = [&](const std::vector<int32_t>& loop)
  {
    const double* best = points.data() + 3 * size_t(loop[0]);
    for (int32_t id : loop)
    {
      if (frame.lessUV(best, points.data() + 3 * size_t(id)))
      {
        best = points.data() + 3 * size_t(id);
      }
    }
    return best;
  };
  std::sort(pending.begin(), pending.end(),
            [&](const std::vector<int32_t>& a, const std::vector<int32_t>& b)
            { return frame.lessUV(rightmost(b), rightmost(a)); });
  bool ok = true;
  HoleBridger bridger(points, frame);
  while (!pending.empty())
  {
    const std::vector<int32_t> hole = std::move(pending.front());
    pending.erase(pending.begin());
    if (!bridger.bridge(joined, hole, pending))
    {
      ok = false; // no bridge: the hole is left out rather than producing crossing triangles
    }
  }
  const size_t first = out.size();
  if (!earClipPolygon(points, joined, frame, 1, out))
  {
    ok = false;
  }
  if (outerSign < 0)
  {
    for (size_t t = first; t + 2 < out.size(); t += 3)
    {
      std::swap(out[t + 1], out[t + 2]);
    }
  }
  return ok;
}

} // namespace volgrid
