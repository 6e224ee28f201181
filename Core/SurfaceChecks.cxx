#include "SurfaceChecks.h"

#include "Predicates.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <thread>

namespace volgrid
{

using predicates::orient2dProjected;
using predicates::orient3d;

// ---------------------------------------------------------------------------------------------------
// Exact primitives

namespace
{

// Axis whose projection keeps triangle (a,b,c) non-degenerate, or -1 when it is collinear.
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

// Closed point-in-triangle test in the projection dropping `axis`; o = orient2dProjected(a,b,c,axis) != 0.
bool pointInTriangle2(const double* p, const double* a, const double* b, const double* c, int axis, int o)
{
  return orient2dProjected(a, b, p, axis) * o >= 0 && orient2dProjected(b, c, p, axis) * o >= 0 &&
    orient2dProjected(c, a, p, axis) * o >= 0;
}

// Closed segment-triangle test for a segment in the triangle's plane.
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

// Closed segment-triangle test; op/oq = orient3d(a,b,c,p) / orient3d(a,b,c,q).
bool segmentTriangle(const double* p, const double* q, const double* a, const double* b, const double* c, int op, int oq)
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

// ---------------------------------------------------------------------------------------------------
// Point in closed surface

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

// ---------------------------------------------------------------------------------------------------
// The report

int SurfaceCheckReport::inwardShells() const
{
  int n = 0;
  for (const auto& s : shells)
  {
    if (s.closed && s.consistent && s.signedVolume < 0)
    {
      ++n;
    }
  }
  return n;
}

bool SurfaceCheckReport::meshable() const
{
  return triangles > 0 && invalidTriangles == 0 && nonFinitePoints == 0 && degenerateTriangles == 0 &&
    duplicateTriangles == 0 && nonManifoldEdges == 0 && boundaryEdges == 0 && selfIntersectingPairs == 0 &&
    shellIntersectingPairs == 0;
}

namespace
{

struct UnionFind
{
  std::vector<int32_t> parent;
  explicit UnionFind(size_t n)
    : parent(n)
  {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int32_t find(int32_t x)
  {
    while (parent[x] != x)
    {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(int32_t a, int32_t b)
  {
    a = find(a);
    b = find(b);
    if (a != b)
    {
      if (a < b)
      {
        parent[b] = a;
      }
      else
      {
        parent[a] = b;
      }
    }
  }
};

struct HalfEdge
{
  uint64_t key;  // (min << 32) | max
  int32_t tri;
  int8_t local;  // edge k goes from corner k to corner k+1
  int8_t forward; // 1 when it runs min -> max
};

void keep(std::vector<int32_t>& ids, int32_t id, int maxIds)
{
  if (static_cast<int>(ids.size()) < maxIds)
  {
    ids.push_back(id);
  }
}

// Bounding volume hierarchy over triangle boxes, for candidate pairs.
struct BVH
{
  struct Node
  {
    double lo[3], hi[3];
    int32_t left = -1, right = -1; // children, or -1 for a leaf
    int32_t start = 0, count = 0;  // leaf range in `items`
  };
  std::vector<Node> nodes;
  std::vector<int32_t> items;
  const std::vector<double>* boxes = nullptr; // 6 per triangle: lo xyz, hi xyz

  void build(const std::vector<int32_t>& tris, const std::vector<double>& triBoxes)
  {
    boxes = &triBoxes;
    items = tris;
    nodes.clear();
    if (items.empty())
    {
      return;
    }
    nodes.reserve(2 * items.size() / 3 + 2);
    struct Job
    {
      int32_t node, start, end;
    };
    std::vector<Job> stack;
    nodes.emplace_back();
    stack.push_back({ 0, 0, static_cast<int32_t>(items.size()) });
    while (!stack.empty())
    {
      const Job job = stack.back();
      stack.pop_back();
      Node node;
      double clo[3] = { 1e308, 1e308, 1e308 }, chi[3] = { -1e308, -1e308, -1e308 };
      for (int k = 0; k < 3; ++k)
      {
        node.lo[k] = 1e308;
        node.hi[k] = -1e308;
      }
      for (int32_t i = job.start; i < job.end; ++i)
      {
        const double* b = triBoxes.data() + 6 * size_t(items[i]);
        for (int k = 0; k < 3; ++k)
        {
          node.lo[k] = std::min(node.lo[k], b[k]);
          node.hi[k] = std::max(node.hi[k], b[3 + k]);
          const double c = 0.5 * (b[k] + b[3 + k]);
          clo[k] = std::min(clo[k], c);
          chi[k] = std::max(chi[k], c);
        }
      }
      const int32_t count = job.end - job.start;
      if (count <= 4)
      {
        node.start = job.start;
        node.count = count;
        nodes[job.node] = node;
        continue;
      }
      int axis = 0;
      for (int k = 1; k < 3; ++k)
      {
        if (chi[k] - clo[k] > chi[axis] - clo[axis])
        {
          axis = k;
        }
      }
      const int32_t mid = job.start + count / 2;
      std::nth_element(items.begin() + job.start, items.begin() + mid, items.begin() + job.end,
        [&](int32_t a, int32_t b) {
          const double* ba = triBoxes.data() + 6 * size_t(a);
          const double* bb = triBoxes.data() + 6 * size_t(b);
          return ba[axis] + ba[3 + axis] < bb[axis] + bb[3 + axis];
        });
      node.left = static_cast<int32_t>(nodes.size());
      node.right = node.left + 1;
      nodes[job.node] = node;
      nodes.emplace_back();
      nodes.emplace_back();
      stack.push_back({ node.left, job.start, mid });
      stack.push_back({ node.right, mid, job.end });
    }
  }

  // Calls f(j) for every item whose closed box overlaps `b`.
  template <class F>
  void query(const double* b, std::vector<int32_t>& stack, F&& f) const
  {
    if (nodes.empty())
    {
      return;
    }
    stack.clear();
    stack.push_back(0);
    while (!stack.empty())
    {
      const Node& n = nodes[stack.back()];
      stack.pop_back();
      if (n.lo[0] > b[3] || n.hi[0] < b[0] || n.lo[1] > b[4] || n.hi[1] < b[1] || n.lo[2] > b[5] || n.hi[2] < b[2])
      {
        continue;
      }
      if (n.left < 0)
      {
        for (int32_t i = n.start; i < n.start + n.count; ++i)
        {
          const int32_t j = items[i];
          const double* c = boxes->data() + 6 * size_t(j);
          if (c[0] <= b[3] && c[3] >= b[0] && c[1] <= b[4] && c[4] >= b[1] && c[2] <= b[5] && c[5] >= b[2])
          {
            f(j);
          }
        }
      }
      else
      {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
  }
};

} // namespace

SurfaceCheckReport checkSurface(const SurfaceMesh& mesh, const SurfaceCheckOptions& options)
{
  SilentProgress silent;
  Progress* progress = options.progress ? options.progress : &silent;
  const int maxIds = std::max(0, options.maxReportedIds);
  SurfaceCheckReport r;
  const int32_t np = mesh.numberOfPoints();
  const int32_t nt = mesh.numberOfTriangles();
  r.points = np;
  r.triangles = nt;
  r.triangleFlags.assign(nt, 0);
  r.triangleShell.assign(nt, -1);
  r.pointNonManifold.assign(np, 0);
  progress->report(0.0, "Checking surface");

  // Valid triangles and referenced points.
  std::vector<char> valid(nt, 1);
  std::vector<char> referenced(np, 0);
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t* v = mesh.triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      if (v[k] < 0 || v[k] >= np)
      {
        valid[t] = 0;
      }
    }
    if (!valid[t])
    {
      ++r.invalidTriangles;
      keep(r.firstInvalidTriangles, t, maxIds);
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      referenced[v[k]] = 1;
    }
  }
  for (int32_t i = 0; i < np; ++i)
  {
    if (!referenced[i])
    {
      ++r.unreferencedPoints;
    }
    else
    {
      const double* p = mesh.point(i);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        ++r.nonFinitePoints;
      }
    }
  }
  if (r.nonFinitePoints > 0)
  {
    return r; // no geometry can be trusted
  }
  // Exactly coincident points: canonical ids for the geometric tests.
  std::vector<int32_t> canon;
  exactCoincidenceMap(mesh.points, canon);
  {
    std::vector<char> seen(np, 0);
    for (int32_t i = 0; i < np; ++i)
    {
      if (referenced[i])
      {
        if (seen[canon[i]])
        {
          ++r.coincidentPoints;
        }
        seen[canon[i]] = 1;
      }
    }
  }

  // Degenerate and duplicate triangles.
  std::vector<char> degenerate(nt, 0);
  for (int32_t t = 0; t < nt; ++t)
  {
    if (!valid[t])
    {
      continue;
    }
    const int32_t* v = mesh.triangle(t);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
      triangleIsDegenerate(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])))
    {
      degenerate[t] = 1;
      r.triangleFlags[t] |= TriangleDegenerate;
      ++r.degenerateTriangles;
      keep(r.firstDegenerateTriangles, t, maxIds);
    }
  }
  {
    struct Key
    {
      int32_t v[3];
      int32_t t;
    };
    std::vector<Key> keys;
    keys.reserve(nt);
    for (int32_t t = 0; t < nt; ++t)
    {
      if (valid[t])
      {
        Key k;
        std::copy(mesh.triangle(t), mesh.triangle(t) + 3, k.v);
        std::sort(k.v, k.v + 3);
        k.t = t;
        keys.push_back(k);
      }
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
      return std::lexicographical_compare(a.v, a.v + 3, b.v, b.v + 3) || (std::equal(a.v, a.v + 3, b.v) && a.t < b.t);
    });
    for (size_t i = 1; i < keys.size(); ++i)
    {
      if (std::equal(keys[i].v, keys[i].v + 3, keys[i - 1].v))
      {
        const int32_t t = keys[i].t;
        r.triangleFlags[t] |= TriangleDuplicate;
        ++r.duplicateTriangles;
        keep(r.firstDuplicateTriangles, t, maxIds);
      }
    }
    std::sort(r.firstDuplicateTriangles.begin(), r.firstDuplicateTriangles.end());
  }
  progress->report(0.1, "Checking surface");

  // Edges.
  std::vector<HalfEdge> half;
  half.reserve(3 * size_t(nt));
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t* v = mesh.triangle(t);
    // A triangle that repeats a point id is not a surface element: it gets no edges (it is reported
    // as degenerate). Collinear triangles with three distinct ids keep theirs.
    if (!valid[t] || v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int32_t a = v[k], b = v[(k + 1) % 3];
      const uint32_t lo = static_cast<uint32_t>(std::min(a, b)), hi = static_cast<uint32_t>(std::max(a, b));
      half.push_back({ (uint64_t(lo) << 32) | hi, t, static_cast<int8_t>(k), static_cast<int8_t>(a < b) });
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return a.key < b.key || (a.key == b.key && a.tri < b.tri);
  });
  UnionFind shellUF(nt);
  UnionFind cornerUF(3 * size_t(nt));
  UnionFind loopUF(np);
  std::vector<char> onNonManifoldEdge(np, 0);
  for (size_t s = 0; s < half.size();)
  {
    size_t e = s + 1;
    while (e < half.size() && half[e].key == half[s].key)
    {
      ++e;
    }
    const int32_t edgeId = static_cast<int32_t>(r.edgeValence.size());
    const int32_t a = static_cast<int32_t>(half[s].key >> 32), b = static_cast<int32_t>(half[s].key & 0xffffffffu);
    const int32_t valence = static_cast<int32_t>(e - s);
    r.edgePoints.push_back(a);
    r.edgePoints.push_back(b);
    r.edgeValence.push_back(valence);
    uint8_t flags = 0;
    for (size_t i = s + 1; i < e; ++i)
    {
      shellUF.unite(half[s].tri, half[i].tri);
    }
    if (valence == 1)
    {
      flags |= EdgeBoundary;
      ++r.boundaryEdges;
      r.triangleFlags[half[s].tri] |= TriangleBoundaryEdge;
      keep(r.firstBoundaryEdgeTriangles, half[s].tri, maxIds);
      keep(r.firstBoundaryEdges, edgeId, maxIds);
      loopUF.unite(a, b);
    }
    else if (valence > 2)
    {
      flags |= EdgeNonManifold;
      ++r.nonManifoldEdges;
      keep(r.firstNonManifoldEdges, edgeId, maxIds);
      keep(r.firstNonManifoldEdgeTriangles, half[s].tri, maxIds);
      for (size_t i = s; i < e; ++i)
      {
        r.triangleFlags[half[i].tri] |= TriangleNonManifoldEdge;
      }
      onNonManifoldEdge[a] = onNonManifoldEdge[b] = 1;
    }
    else
    {
      const HalfEdge& h0 = half[s];
      const HalfEdge& h1 = half[s + 1];
      if (h0.forward == h1.forward)
      {
        flags |= EdgeInconsistent;
        ++r.inconsistentEdges;
        r.triangleFlags[h0.tri] |= TriangleInconsistent;
        r.triangleFlags[h1.tri] |= TriangleInconsistent;
        keep(r.firstInconsistentTriangles, h0.tri, maxIds);
      }
      // Join the corners at a and at b across this manifold edge.
      auto corner = [&](const HalfEdge& h, int32_t v) {
        const int32_t* tv = mesh.triangle(h.tri);
        const int k = tv[h.local] == v ? h.local : (h.local + 1) % 3;
        return 3 * h.tri + k;
      };
      cornerUF.unite(corner(h0, a), corner(h1, a));
      cornerUF.unite(corner(h0, b), corner(h1, b));
    }
    r.edgeFlags.push_back(flags);
    s = e;
  }
  r.edges = static_cast<int64_t>(r.edgeValence.size());
  {
    // Boundary loops: connected groups of boundary edges.
    std::vector<char> isRoot(np, 0);
    for (int64_t ei = 0; ei < r.edges; ++ei)
    {
      if (r.edgeFlags[ei] & EdgeBoundary)
      {
        const int32_t root = loopUF.find(r.edgePoints[2 * ei]);
        if (!isRoot[root])
        {
          isRoot[root] = 1;
          ++r.boundaryLoops;
        }
      }
    }
  }
  // Non-manifold vertices: corners of one point that are not all in one edge-connected fan.
  {
    std::vector<int32_t> firstRoot(np, -1);
    for (int32_t t = 0; t < nt; ++t)
    {
      if (!valid[t])
      {
        continue;
      }
      const int32_t* v = mesh.triangle(t);
      for (int k = 0; k < 3; ++k)
      {
        const int32_t root = cornerUF.find(3 * t + k);
        if (firstRoot[v[k]] < 0)
        {
          firstRoot[v[k]] = root;
        }
        else if (firstRoot[v[k]] != root)
        {
          r.pointNonManifold[v[k]] = 1;
        }
      }
    }
    for (int32_t i = 0; i < np; ++i)
    {
      if (onNonManifoldEdge[i])
      {
        r.pointNonManifold[i] = 1;
      }
      if (r.pointNonManifold[i])
      {
        ++r.nonManifoldVertices;
        keep(r.firstNonManifoldVertices, i, maxIds);
      }
    }
    for (int32_t t = 0; t < nt; ++t)
    {
      if (valid[t])
      {
        const int32_t* v = mesh.triangle(t);
        if (r.pointNonManifold[v[0]] || r.pointNonManifold[v[1]] || r.pointNonManifold[v[2]])
        {
          r.triangleFlags[t] |= TriangleNonManifoldVertex;
        }
      }
    }
  }
  // Shells, numbered in order of their first triangle.
  {
    std::vector<int32_t> rootShell(nt, -1);
    for (int32_t t = 0; t < nt; ++t)
    {
      const int32_t* tv = mesh.triangle(t);
      if (!valid[t] || tv[0] == tv[1] || tv[1] == tv[2] || tv[0] == tv[2])
      {
        continue; // no edges, so in no shell
      }
      const int32_t root = shellUF.find(t);
      if (rootShell[root] < 0)
      {
        rootShell[root] = static_cast<int32_t>(r.shells.size());
        SurfaceShell sh;
        sh.firstTriangle = t;
        sh.closed = true;
        r.shells.push_back(sh);
      }
      const int32_t s = rootShell[root];
      r.triangleShell[t] = s;
      SurfaceShell& sh = r.shells[s];
      ++sh.triangles;
      if (r.triangleFlags[t] & (TriangleBoundaryEdge | TriangleNonManifoldEdge))
      {
        sh.closed = false;
      }
      if (r.triangleFlags[t] & TriangleInconsistent)
      {
        sh.consistent = false;
      }
    }
    std::vector<std::vector<int32_t>> shellTris(r.shells.size());
    for (int32_t t = 0; t < nt; ++t)
    {
      if (r.triangleShell[t] >= 0)
      {
        shellTris[r.triangleShell[t]].push_back(t);
      }
    }
    for (size_t s = 0; s < r.shells.size(); ++s)
    {
      SurfaceShell& sh = r.shells[s];
      sh.signedVolume = signedVolume(mesh, shellTris[s]);
      BoundingBox box;
      for (int32_t t : shellTris[s])
      {
        for (int k = 0; k < 3; ++k)
        {
          box.add(mesh.point(mesh.triangle(t)[k]));
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        sh.bounds[2 * k] = box.min[k];
        sh.bounds[2 * k + 1] = box.max[k];
      }
    }
    progress->report(0.2, "Checking surface");

    // Self-intersections.
    if (options.selfIntersections && !progress->cancelled())
    {
      r.intersectionsChecked = true;
      std::vector<double> boxes(6 * size_t(nt), 0.0);
      std::vector<int32_t> candidates;
      candidates.reserve(nt);
      for (int32_t t = 0; t < nt; ++t)
      {
        if (!valid[t] || degenerate[t])
        {
          continue;
        }
        candidates.push_back(t);
        const int32_t* v = mesh.triangle(t);
        double* b = boxes.data() + 6 * size_t(t);
        for (int k = 0; k < 3; ++k)
        {
          const double* p0 = mesh.point(v[0]);
          const double* p1 = mesh.point(v[1]);
          const double* p2 = mesh.point(v[2]);
          b[k] = std::min({ p0[k], p1[k], p2[k] });
          b[3 + k] = std::max({ p0[k], p1[k], p2[k] });
        }
      }
      BVH bvh;
      bvh.build(candidates, boxes);
      int nthreads = options.threads > 0 ? options.threads : 2;
      const unsigned hw = std::thread::hardware_concurrency();
      if (options.threads <= 0 && hw > 0)
      {
        nthreads = std::min<int>(nthreads, static_cast<int>(hw));
      }
      nthreads = std::max(1, std::min(nthreads, 16));
      std::vector<std::vector<std::pair<int32_t, int32_t>>> found(nthreads);
      auto work = [&](int w) {
        std::vector<int32_t> stack;
        for (size_t i = w; i < candidates.size(); i += nthreads)
        {
          const int32_t t = candidates[i];
          const int32_t* tv = mesh.triangle(t);
          const double* p[3] = { mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]) };
          const int32_t ip[3] = { canon[tv[0]], canon[tv[1]], canon[tv[2]] };
          bvh.query(boxes.data() + 6 * size_t(t), stack, [&](int32_t u) {
            if (u <= t)
            {
              return;
            }
            const int32_t* uv = mesh.triangle(u);
            const double* q[3] = { mesh.point(uv[0]), mesh.point(uv[1]), mesh.point(uv[2]) };
            const int32_t iq[3] = { canon[uv[0]], canon[uv[1]], canon[uv[2]] };
            if (trianglesIntersect(p, ip, q, iq))
            {
              found[w].emplace_back(t, u);
            }
          });
        }
      };
      if (nthreads == 1)
      {
        work(0);
      }
      else
      {
        std::vector<std::thread> pool;
        for (int w = 0; w < nthreads; ++w)
        {
          pool.emplace_back(work, w);
        }
        for (auto& th : pool)
        {
          th.join();
        }
      }
      std::vector<std::pair<int32_t, int32_t>> pairs;
      for (auto& f : found)
      {
        pairs.insert(pairs.end(), f.begin(), f.end());
      }
      std::sort(pairs.begin(), pairs.end());
      for (const auto& pr : pairs)
      {
        const int32_t sa = r.triangleShell[pr.first], sb = r.triangleShell[pr.second];
        if (sa == sb)
        {
          ++r.selfIntersectingPairs;
          r.triangleFlags[pr.first] |= TriangleSelfIntersecting;
          r.triangleFlags[pr.second] |= TriangleSelfIntersecting;
          if (static_cast<int>(r.firstSelfIntersectingPairs.size()) < 2 * maxIds)
          {
            r.firstSelfIntersectingPairs.push_back(pr.first);
            r.firstSelfIntersectingPairs.push_back(pr.second);
          }
        }
        else
        {
          ++r.shellIntersectingPairs;
          r.triangleFlags[pr.first] |= TriangleShellIntersecting;
          r.triangleFlags[pr.second] |= TriangleShellIntersecting;
          r.shells[sa].intersectsOtherShell = true;
          r.shells[sb].intersectsOtherShell = true;
          if (static_cast<int>(r.firstShellIntersectingPairs.size()) < 2 * maxIds)
          {
            r.firstShellIntersectingPairs.push_back(pr.first);
            r.firstShellIntersectingPairs.push_back(pr.second);
          }
        }
      }
    }
    progress->report(0.8, "Checking surface");

    // Nesting of closed shells.
    if (options.nesting && !progress->cancelled())
    {
      r.nestingChecked = true;
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
  }
  progress->report(1.0, "Checking surface");
  return r;
}

// ---------------------------------------------------------------------------------------------------

namespace
{
std::string idList(const std::vector<int32_t>& ids)
{
  std::ostringstream os;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    os << (i ? ", " : "") << ids[i];
  }
  return os.str();
}

std::string pairList(const std::vector<int32_t>& ids)
{
  std::ostringstream os;
  for (size_t i = 0; i + 1 < ids.size(); i += 2)
  {
    os << (i ? ", " : "") << "(" << ids[i] << "," << ids[i + 1] << ")";
  }
  return os.str();
}

std::string edgeList(const SurfaceCheckReport& r, const std::vector<int32_t>& edges)
{
  std::ostringstream os;
  for (size_t i = 0; i < edges.size(); ++i)
  {
    os << (i ? ", " : "") << r.edgePoints[2 * size_t(edges[i])] << "-" << r.edgePoints[2 * size_t(edges[i]) + 1];
  }
  return os.str();
}

std::vector<int64_t> toIds(const std::vector<int32_t>& v)
{
  return std::vector<int64_t>(v.begin(), v.end());
}
} // namespace

Status surfaceStatus(const SurfaceCheckReport& r)
{
  if (r.triangles == 0)
  {
    return Status::failure(ErrorKind::EmptyInput, "The surface has no triangles.");
  }
  if (r.invalidTriangles > 0)
  {
    return Status::failure(ErrorKind::InvalidOption,
      std::to_string(r.invalidTriangles) + " triangle(s) refer to point ids that do not exist; first triangles: " +
        idList(r.firstInvalidTriangles) + ".",
      toIds(r.firstInvalidTriangles));
  }
  if (r.nonFinitePoints > 0)
  {
    return Status::failure(ErrorKind::NonFinitePoint,
      std::to_string(r.nonFinitePoints) + " point(s) have NaN or infinite coordinates.");
  }
  if (r.degenerateTriangles > 0)
  {
    return Status::failure(ErrorKind::DegenerateTriangle,
      std::to_string(r.degenerateTriangles) + " degenerate (zero-area) triangle(s); first triangles: " +
        idList(r.firstDegenerateTriangles) + ".",
      toIds(r.firstDegenerateTriangles));
  }
  if (r.duplicateTriangles > 0)
  {
    return Status::failure(ErrorKind::DuplicateTriangle,
      std::to_string(r.duplicateTriangles) + " duplicate triangle(s) (same three points as an earlier triangle); first triangles: " +
        idList(r.firstDuplicateTriangles) + ".",
      toIds(r.firstDuplicateTriangles));
  }
  if (r.nonManifoldEdges > 0)
  {
    return Status::failure(ErrorKind::NonManifoldEdge,
      std::to_string(r.nonManifoldEdges) + " non-manifold edge(s) (used by more than two triangles); first edges (points): " +
        edgeList(r, r.firstNonManifoldEdges) + "; first triangles: " + idList(r.firstNonManifoldEdgeTriangles) + ".",
      toIds(r.firstNonManifoldEdgeTriangles));
  }
  if (r.boundaryEdges > 0)
  {
    return Status::failure(ErrorKind::OpenSurface,
      "The surface is open: " + std::to_string(r.boundaryEdges) + " boundary edge(s) in " +
        std::to_string(r.boundaryLoops) + " boundary loop(s); first edges (points): " + edgeList(r, r.firstBoundaryEdges) +
        "; first triangles: " + idList(r.firstBoundaryEdgeTriangles) + ".",
      toIds(r.firstBoundaryEdgeTriangles));
  }
  if (r.selfIntersectingPairs > 0)
  {
    return Status::failure(ErrorKind::SelfIntersection,
      std::to_string(r.selfIntersectingPairs) + " pair(s) of triangles intersect or overlap; first pairs: " +
        pairList(r.firstSelfIntersectingPairs) + ".",
      toIds(r.firstSelfIntersectingPairs));
  }
  if (r.shellIntersectingPairs > 0)
  {
    return Status::failure(ErrorKind::IntersectingShells,
      std::to_string(r.shellIntersectingPairs) + " pair(s) of triangles from different shells intersect; first pairs: " +
        pairList(r.firstShellIntersectingPairs) + ".",
      toIds(r.firstShellIntersectingPairs));
  }
  return Status::success();
}

std::string formatSurfaceReport(const SurfaceCheckReport& r)
{
  std::ostringstream os;
  os << "points                     " << r.points << "\n";
  os << "triangles                  " << r.triangles << "\n";
  os << "edges                      " << r.edges << "\n";
  os << "shells                     " << r.shells.size() << "\n";
  os << "watertight                 " << (r.watertight() ? "yes" : "no") << "\n";
  os << "consistently oriented      " << (r.consistentlyOriented() ? "yes" : "no") << "\n";
  os << "boundary edges             " << r.boundaryEdges << " in " << r.boundaryLoops << " loop(s)\n";
  os << "non-manifold edges         " << r.nonManifoldEdges << "\n";
  os << "inconsistent edges         " << r.inconsistentEdges << "\n";
  os << "non-manifold vertices      " << r.nonManifoldVertices << "\n";
  os << "degenerate triangles       " << r.degenerateTriangles << "\n";
  os << "duplicate triangles        " << r.duplicateTriangles << "\n";
  if (r.intersectionsChecked)
  {
    os << "self-intersecting pairs    " << r.selfIntersectingPairs << "\n";
    os << "shell-intersecting pairs   " << r.shellIntersectingPairs << "\n";
  }
  os << "coincident points          " << r.coincidentPoints << "\n";
  os << "unreferenced points        " << r.unreferencedPoints << "\n";
  if (r.invalidTriangles)
  {
    os << "invalid triangles          " << r.invalidTriangles << "\n";
  }
  for (size_t s = 0; s < r.shells.size() && s < 50; ++s)
  {
    const SurfaceShell& sh = r.shells[s];
    os << "shell " << s << ": " << sh.triangles << " triangles, " << (sh.closed ? "closed" : "open") << ", "
       << (sh.consistent ? "consistent" : "inconsistent");
    if (sh.closed && sh.consistent)
    {
      os << ", " << (sh.signedVolume >= 0 ? "outward" : "INWARD") << ", volume " << sh.signedVolume;
    }
    if (r.nestingChecked && sh.closed)
    {
      os << ", depth " << sh.depth;
      if (sh.parent >= 0)
      {
        os << " (inside shell " << sh.parent << ")";
      }
    }
    if (sh.intersectsOtherShell)
    {
      os << ", intersects another shell";
    }
    os << "\n";
  }
  if (r.shells.size() > 50)
  {
    os << "... " << (r.shells.size() - 50) << " more shells\n";
  }
  const Status st = surfaceStatus(r);
  os << "verdict                    " << (st.ok() ? "meshable" : st.message) << "\n";
  return os.str();
}

} // namespace volgrid
