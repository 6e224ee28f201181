#include "SizingField.h"

#include "CoarseBoundaryFloor.h"
#include "Delaunay.h"
#include "PredicatesInline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace volgrid
{

namespace
{
inline double dist(const double* a, const double* b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}
inline bool usable(double h)
{
  return std::isfinite(h) && h > 0;
}

// The point of triangle abc nearest p, as barycentric weights w (Ericson, Real-Time Collision Detection
// 5.1.5: the vertex, edge or face region p projects into); returns the squared distance.
double nearestOnTriangle(const double* p, const double* a, const double* b, const double* c, double w[3])
{
  const auto sub = [](const double* x, const double* y, double* r)
  {
    for (int k = 0; k < 3; ++k)
      r[k] = x[k] - y[k];
  };
  const auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  sub(p, b, bp);
  sub(p, c, cp);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp),
               d6 = dot(ac, cp);
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  if (d1 <= 0 && d2 <= 0)
    w[0] = 1, w[1] = 0, w[2] = 0;
  else if (d3 >= 0 && d4 <= d3)
    w[0] = 0, w[1] = 1, w[2] = 0;
  else if (d6 >= 0 && d5 <= d6)
    w[0] = 0, w[1] = 0, w[2] = 1;
  else if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double t = d1 / (d1 - d3);
    w[0] = 1 - t, w[1] = t, w[2] = 0;
  }
  else if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double t = d2 / (d2 - d6);
    w[0] = 1 - t, w[1] = 0, w[2] = t;
  }
  else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    w[0] = 0, w[1] = 1 - t, w[2] = t;
  }
  else
  {
    const double sum = va + vb + vc;
    w[0] = va / sum, w[1] = vb / sum, w[2] = vc / sum;
    if (!std::isfinite(w[0]) || !std::isfinite(w[1]) || !std::isfinite(w[2]))
      w[0] = 1, w[1] = 0, w[2] = 0; // a degenerate hull face: its first vertex
  }
  double q[3];
  for (int k = 0; k < 3; ++k)
    q[k] = w[0] * a[k] + w[1] * b[k] + w[2] * c[k] - p[k];
  return dot(q, q);
}
} // namespace

// ---------------------------------------------------------------------------------------------------------
struct LinearInterpolant::Locator
{
  int32_t hint = -1;
};

LinearInterpolant::LinearInterpolant()
  : locator_(new Locator)
{
}
LinearInterpolant::~LinearInterpolant() = default;
LinearInterpolant::LinearInterpolant(LinearInterpolant&&) noexcept = default;
LinearInterpolant& LinearInterpolant::operator=(LinearInterpolant&&) noexcept = default;

Status LinearInterpolant::build(const double* xyz, size_t n, const double* values, Progress* progress)
{
  mesh_.clear();
  values_.clear();
  degenerate_ = false;
  locator_->hint = -1;
  if (n == 0)
    return Status::failure(ErrorKind::EmptyInput, "The sizing interpolant has no point.");
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i]))
      return Status::failure(ErrorKind::InvalidOption,
                             "The sizing interpolant got a non-finite value at point " + std::to_string(i) + ".",
                             { int64_t(i) });
  std::vector<int32_t> inputToVertex;
  DelaunayOptions opt;
  Status st = n >= 4 ? buildDelaunay(xyz, n, opt, mesh_, inputToVertex, progress)
                     : Status::failure(ErrorKind::DegenerateInput, "fewer than four points");
  if (!st.ok() && st.kind != ErrorKind::DegenerateInput)
    return st;
  if (!st.ok())
  {
    // Coplanar or tiny input: nearest-point interpolation over the raw points.
    degenerate_ = true;
    mesh_.clear();
    mesh_.points.assign(xyz, xyz + 3 * n);
    values_.assign(values, values + n);
    return Status::success();
  }
  values_.assign(static_cast<size_t>(mesh_.numVertices()), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; ++i)
  {
    double& h = values_[inputToVertex[i]];
    h = std::min(h, values[i]);
  }
  for (size_t i = 0; i < values_.size(); ++i)
    if (!std::isfinite(values_[i]))
      values_[i] = 0; // merged duplicates: unused by tets
  return Status::success();
}

double LinearInterpolant::evaluate(const double* p) const
{
  return evaluate(p, locator_->hint);
}

double LinearInterpolant::evaluate(const double* p, int32_t& hint) const
{
  if (values_.empty())
    return std::numeric_limits<double>::quiet_NaN();
  if (degenerate_)
  {
    double best = std::numeric_limits<double>::infinity(), h = values_[0];
    for (size_t i = 0; i < values_.size(); ++i)
    {
      const double d = dist(p, mesh_.points.data() + 3 * i);
      if (d < best)
      {
        best = d;
        h = values_[i];
      }
    }
    return h;
  }
  // Visibility walk (randomised start face) from the hint's tet.
  int32_t t = hint;
  if (t < 0 || t >= mesh_.tetCapacity() || mesh_.isFree(t) || mesh_.isGhost(t))
  {
    t = -1;
    for (int32_t u = 0; u < mesh_.tetCapacity() && t < 0; ++u)
      if (!mesh_.isFree(u) && !mesh_.isGhost(u))
        t = u;
  }
  uint32_t rng = 0x2545F491u;
  const int64_t maxSteps = 4 * static_cast<int64_t>(mesh_.numTets()) + 64;
  for (int64_t step = 0; step < maxSteps; ++step)
  {
    const int32_t* v = mesh_.vertices(t);
    const int g = mesh_.ghostIndex(t);
    if (g >= 0)
      return outsideHull(p, t, hint);
    rng = rng * 1664525u + 1013904223u;
    const int first = static_cast<int>((rng >> 16) & 3);
    int exitFace = -1;
    for (int k = 0; k < 4 && exitFace < 0; ++k)
    {
      const int i = (first + k) & 3;
      int32_t f[3];
      mesh_.faceVertices(t, i, f);
      if (predicates::orient3dInline(mesh_.point(f[0]), mesh_.point(f[1]), mesh_.point(f[2]), p) < 0)
        exitFace = i;
    }
    if (exitFace < 0)
    {
      // Inside t: barycentric weights from sub-volumes.
      hint = t;
      const double* P[4] = { mesh_.point(v[0]), mesh_.point(v[1]), mesh_.point(v[2]), mesh_.point(v[3]) };
      double w[4], sw = 0;
      for (int i = 0; i < 4; ++i)
      {
        const double* Q[4] = { P[0], P[1], P[2], P[3] };
        Q[i] = p;
        const double u1[3] = { Q[1][0] - Q[0][0], Q[1][1] - Q[0][1], Q[1][2] - Q[0][2] };
        const double u2[3] = { Q[2][0] - Q[0][0], Q[2][1] - Q[0][1], Q[2][2] - Q[0][2] };
        const double u3[3] = { Q[3][0] - Q[0][0], Q[3][1] - Q[0][1], Q[3][2] - Q[0][2] };
        const double det = u1[0] * (u2[1] * u3[2] - u2[2] * u3[1]) - u1[1] * (u2[0] * u3[2] - u2[2] * u3[0]) +
          u1[2] * (u2[0] * u3[1] - u2[1] * u3[0]);
        w[i] = std::max(0.0, det);
        sw += w[i];
      }
      if (!(sw > 0))
        return (values_[v[0]] + values_[v[1]] + values_[v[2]] + values_[v[3]]) / 4;
      return (w[0] * values_[v[0]] + w[1] * values_[v[1]] + w[2] * values_[v[2]] + w[3] * values_[v[3]]) / sw;
    }
    t = mesh_.neighbor(t, exitFace);
  }
  // Did not converge (should not happen on a Delaunay mesh): nearest vertex of the last tet.
  const int32_t* v = mesh_.vertices(t);
  double best = std::numeric_limits<double>::infinity(), h = 0;
  for (int i = 0; i < 4; ++i)
    if (v[i] >= 0 && dist(p, mesh_.point(v[i])) < best)
    {
      best = dist(p, mesh_.point(v[i]));
      h = values_[v[i]];
    }
  return h;
}

// p is outside the hull, beyond the hull face of ghost tet t that the walk crossed. Every hull face on the
// side of p may be crossed (below a flat hull, such as a symmetry plane's, all of them), so the value is
// taken at the point of the hull nearest p, not on the face crossed: the walk goes on over the hull faces
// to a nearer one while there is one. A face whose nearest point is a vertex or an edge shares it with its
// neighbours there, so their ring is searched (faces as near as the best) before the walk stops. On a
// convex hull the distance has no other local minimum: the walk ends on a face through the nearest
// point whatever the start (only where several faces touch that point may the face depend on it).
double LinearInterpolant::outsideHull(const double* p, int32_t t, int32_t& hint) const
{
  const auto distance = [&](int32_t ghost, double w[3], int32_t f[3])
  {
    mesh_.faceVertices(ghost, mesh_.ghostIndex(ghost), f);
    return nearestOnTriangle(p, mesh_.point(f[0]), mesh_.point(f[1]), mesh_.point(f[2]), w);
  };
  double w[3];
  int32_t f[3];
  double best = distance(t, w, f);
  // Faces as near as the best, searched from (a few: a vertex's ring); the thread's own, kept between calls.
  thread_local std::vector<int32_t> plateau;
  plateau.assign(1, t);
  for (size_t next = 0; next < plateau.size();)
  {
    const int32_t cur = plateau[next++];
    const int g = mesh_.ghostIndex(cur);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = i == g ? -1 : mesh_.neighbor(cur, i);
      if (u < 0 || !mesh_.isGhost(u) || std::find(plateau.begin(), plateau.end(), u) != plateau.end())
        continue;
      double wu[3];
      int32_t fu[3];
      const double d = distance(u, wu, fu);
      if (d < best)
      {
        best = d;
        t = u;
        std::copy(wu, wu + 3, w);
        std::copy(fu, fu + 3, f);
        plateau.assign(1, u);
        next = 0;
        break;
      }
      if (d == best)
        plateau.push_back(u);
    }
  }
  hint = mesh_.neighbor(t, mesh_.ghostIndex(t));
  return w[0] * values_[f[0]] + w[1] * values_[f[1]] + w[2] * values_[f[2]];
}

// ---------------------------------------------------------------------------------------------------------
std::vector<double> pointDistributionFunction(const double* points, int32_t numPoints, const int32_t* triangles,
                                              int32_t numTriangles)
{
  std::vector<std::pair<int32_t, int32_t>> edges;
  edges.reserve(3 * static_cast<size_t>(numTriangles));
  for (int32_t t = 0; t < numTriangles; ++t)
    for (int k = 0; k < 3; ++k)
    {
      int32_t a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
      if (a == b || a < 0 || b < 0 || a >= numPoints || b >= numPoints)
        continue;
      if (a > b)
        std::swap(a, b);
      edges.emplace_back(a, b);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> sum(static_cast<size_t>(numPoints), 0.0);
  std::vector<int32_t> count(static_cast<size_t>(numPoints), 0);
  for (const auto& e : edges)
  {
    const double l = dist(points + 3 * static_cast<size_t>(e.first), points + 3 * static_cast<size_t>(e.second));
    sum[e.first] += l;
    sum[e.second] += l;
    ++count[e.first];
    ++count[e.second];
  }
  for (int32_t i = 0; i < numPoints; ++i)
    sum[i] = count[i] ? sum[i] / count[i] : 0.0;
  return sum;
}

namespace
{
// The vertex adjacency of the finite tets' edges, as CSR: the neighbours of v are adj[start[v], start[v + 1]),
// each once. Each tet's six edges are bucketed under their lower vertex (a counting pass, no global sort),
// each bucket made unique, then mirrored under the upper vertex.
void edgeAdjacency(const TetMesh& mesh, std::vector<int32_t>& start, std::vector<int32_t>& adj)
{
  const int32_t nv = mesh.numVertices();
  std::vector<int32_t> upStart(static_cast<size_t>(nv) + 1, 0);
  auto forEachEdge = [&](auto&& f)
  {
    mesh.forEachFiniteTet(
      [&](int32_t t)
      {
        const int32_t* v = mesh.vertices(t);
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j)
            f(std::min(v[i], v[j]), std::max(v[i], v[j]));
      });
  };
  forEachEdge([&](int32_t a, int32_t) { ++upStart[a + 1]; });
  for (int32_t v = 0; v < nv; ++v)
    upStart[v + 1] += upStart[v];
  std::vector<int32_t> up(static_cast<size_t>(upStart[nv])), fill(upStart.begin(), upStart.end() - 1);
  forEachEdge([&](int32_t a, int32_t b) { up[fill[a]++] = b; });
  // Unique upper neighbours of each vertex, compacted in place; then the degrees of both ends.
  start.assign(static_cast<size_t>(nv) + 1, 0);
  std::vector<int32_t> upEnd(static_cast<size_t>(nv));
  for (int32_t v = 0, kept = 0; v < nv; ++v)
  {
    const auto first = up.begin() + upStart[v], last = up.begin() + upStart[v + 1];
    std::sort(first, last);
    const auto uniqueEnd = std::unique(first, last);
    upStart[v] = kept; // bucket v now starts where the kept entries end
    for (auto it = first; it != uniqueEnd; ++it)
    {
      up[static_cast<size_t>(kept++)] = *it;
      ++start[v + 1];
      ++start[*it + 1];
    }
    upEnd[v] = kept;
  }
  for (int32_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  adj.assign(static_cast<size_t>(start[nv]), 0);
  std::vector<int32_t> pos(start.begin(), start.end() - 1);
  for (int32_t v = 0; v < nv; ++v)
    for (int32_t k = upStart[v]; k < upEnd[v]; ++k)
    {
      adj[static_cast<size_t>(pos[v]++)] = up[static_cast<size_t>(k)];
      adj[static_cast<size_t>(pos[up[static_cast<size_t>(k)]]++)] = v;
    }
}
} // namespace

void limitGradation(const TetMesh& mesh, double slope, std::vector<double>& sizes)
{
  const int32_t nv = mesh.numVertices();
  if (!(slope >= 0) || sizes.size() < static_cast<size_t>(nv))
    return;
  std::vector<int32_t> start, adj;
  edgeAdjacency(mesh, start, adj);
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (int32_t v = 0; v < nv; ++v)
    if (usable(sizes[v]))
      heap.emplace(sizes[v], v);
  while (!heap.empty())
  {
    const Item it = heap.top();
    heap.pop();
    const int32_t u = it.second;
    if (it.first > sizes[u])
      continue; // stale
    for (int32_t k = start[u]; k < start[u + 1]; ++k)
    {
      const int32_t w = adj[k];
      if (!usable(sizes[w]))
        continue;
      const double bound = sizes[u] + slope * dist(mesh.point(u), mesh.point(w));
      if (bound < sizes[w])
      {
        sizes[w] = bound;
        heap.emplace(bound, w);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
void SizingField::setBackgroundCloud(const double* xyz, const double* sizes, size_t n)
{
  cloudXYZ_.clear();
  cloudSize_.clear();
  for (size_t i = 0; i < n; ++i)
    if (usable(sizes[i]) && std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2]))
    {
      cloudXYZ_.insert(cloudXYZ_.end(), xyz + 3 * i, xyz + 3 * i + 3);
      cloudSize_.push_back(sizes[i]);
    }
}

void SizingField::addSizedPoints(const double* xyz, const double* sizes, size_t n)
{
  for (size_t i = 0; i < n; ++i)
    if (usable(sizes[i]) && std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2]))
    {
      extraXYZ_.insert(extraXYZ_.end(), xyz + 3 * i, xyz + 3 * i + 3);
      extraSize_.push_back(sizes[i]);
    }
}

double SizingField::userSize(const double* p, Walk& walk) const
{
  double h = std::numeric_limits<double>::infinity();
  if (user_)
  {
    const double u = user_(p);
    if (usable(u))
      h = u;
  }
  if (!cloud_.empty())
  {
    const double c = cloud_.evaluate(p, walk.cloud);
    if (usable(c))
      h = std::min(h, c);
  }
  return h;
}

double SizingField::capAt(const double* p, Walk& walk) const
{
  double cap = options_.maxEdgeLength > 0 ? options_.maxEdgeLength : std::numeric_limits<double>::infinity();
  if (capFloor_ && options_.maxEdgeLength > 0)
    cap = std::max(cap, capFloor_->evaluate(p, walk.floor));
  return cap;
}

static Status checkOptions(const SizingOptions& o)
{
  if (!std::isfinite(o.gradation) || !(o.maxEdgeLength >= 0) || !std::isfinite(o.maxEdgeLength) ||
      !(o.minEdgeLength >= 0) || !std::isfinite(o.minEdgeLength) || !(o.scale > 0) || !std::isfinite(o.scale) ||
      (o.maxEdgeLength > 0 && o.minEdgeLength > o.maxEdgeLength))
    return Status::failure(ErrorKind::InvalidOption,
                           "Sizing options must be finite, with scale > 0, edge-length bounds >= 0 and min <= max.");
  return Status::success();
}

Status SizingField::build(const double* points, int32_t numPoints, const int32_t* triangles, int32_t numTriangles,
                          const SizingOptions& options, Progress* progress)
{
  Status st = checkOptions(options);
  if (!st.ok())
    return st;
  options_ = options;
  uniform_ = 0;
  walk_ = Walk();
  if (!cloudXYZ_.empty())
  {
    st = cloud_.build(cloudXYZ_.data(), cloudSize_.size(), cloudSize_.data(), progress);
    if (!st.ok())
      return st;
  }
  const std::vector<double> pdf = pointDistributionFunction(points, numPoints, triangles, numTriangles);
  std::vector<double> xyz, h;
  for (int32_t i = 0; i < numPoints; ++i)
    if (pdf[i] > 0)
    {
      xyz.insert(xyz.end(), points + 3 * static_cast<size_t>(i), points + 3 * static_cast<size_t>(i) + 3);
      h.push_back(pdf[i] * options.scale);
    }
  xyz.insert(xyz.end(), extraXYZ_.begin(), extraXYZ_.end());
  h.insert(h.end(), extraSize_.begin(), extraSize_.end());
  if (h.empty())
    return Status::failure(ErrorKind::EmptyInput, "The sizing field has no boundary triangle and no sized point.");
  for (size_t i = 0; i < h.size(); ++i)
  {
    h[i] = std::min(h[i], userSize(xyz.data() + 3 * i, walk_));
    if (capFloor_)
      h[i] = std::min(h[i], capAt(xyz.data() + 3 * i, walk_));
  }
  st = graded_.build(xyz.data(), h.size(), h.data(), progress);
  if (!st.ok())
    return st;
  if (options.gradation > 1 && !graded_.degenerate())
    limitGradation(graded_.mesh(), options.gradation - 1, graded_.values());
  minNode_ = std::numeric_limits<double>::infinity();
  maxNode_ = 0;
  for (double v : graded_.values())
    if (v > 0)
    {
      minNode_ = std::min(minNode_, v);
      maxNode_ = std::max(maxNode_, v);
    }
  return Status::success();
}

Status SizingField::buildUniform(double size, const SizingOptions& options)
{
  Status st = checkOptions(options);
  if (!st.ok())
    return st;
  if (!usable(size))
    return Status::failure(ErrorKind::InvalidOption, "The uniform size must be finite and positive.");
  options_ = options;
  walk_ = Walk();
  if (!cloudXYZ_.empty())
  {
    st = cloud_.build(cloudXYZ_.data(), cloudSize_.size(), cloudSize_.data());
    if (!st.ok())
      return st;
  }
  uniform_ = size;
  minNode_ = maxNode_ = size;
  if (!extraXYZ_.empty())
  {
    std::vector<double> h(extraSize_);
    for (double& x : h)
      x = std::min(x, size);
    st = graded_.build(extraXYZ_.data(), h.size(), h.data());
    if (!st.ok())
      return st;
    if (options.gradation > 1 && !graded_.degenerate())
      limitGradation(graded_.mesh(), options.gradation - 1, graded_.values());
  }
  return Status::success();
}

double SizingField::evaluate(const double* p, Walk& walk) const
{
  double h = std::numeric_limits<double>::infinity();
  if (uniform_ > 0)
  {
    h = uniform_;
    // Sized points in a uniform field: cones of slope (gradation - 1) around each one.
    if (!extraXYZ_.empty())
    {
      const double slope = options_.gradation > 1 ? options_.gradation - 1 : 0;
      for (size_t i = 0; i < extraSize_.size(); ++i)
        if (slope > 0)
          h = std::min(h, extraSize_[i] + slope * dist(p, extraXYZ_.data() + 3 * i));
    }
  }
  else if (!graded_.empty())
    h = graded_.evaluate(p, walk.graded);
  h = std::min(h, userSize(p, walk));
  h = std::min(h, capAt(p, walk));
  if (options_.minEdgeLength > 0)
    h = std::max(h, options_.minEdgeLength);
  return h;
}

} // namespace volgrid
