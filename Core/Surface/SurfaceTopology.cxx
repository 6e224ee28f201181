#include "SurfaceTopology.h"

#include "UnionFind.h"

#include <algorithm>
#include <numeric>

namespace volgrid::detail
{

namespace
{

using UnionFind = volgrid::UnionFind<int32_t>;

struct HalfEdge
{
  uint64_t key; // (min << 32) | max
  int32_t tri;
  int8_t local;   // edge k goes from corner k to corner k+1
  int8_t forward; // 1 when it runs min -> max
};

// Boundary loops: connected groups of boundary edges.
void countBoundaryLoops(UnionFind& loopUF, int32_t np, SurfaceCheckReport& r)
{
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
void markNonManifoldVertices(const SurfaceMesh& mesh, const std::vector<char>& valid, UnionFind& cornerUF,
                             const std::vector<char>& onNonManifoldEdge, int maxIds, SurfaceCheckReport& r)
{
  const int32_t np = mesh.numberOfPoints();
  const int32_t nt = mesh.numberOfTriangles();
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
      keepFirstId(r.firstNonManifoldVertices, i, maxIds);
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
std::vector<std::vector<int32_t>> buildShells(const SurfaceMesh& mesh, const std::vector<char>& valid,
                                              UnionFind& shellUF, SurfaceCheckReport& r)
{
  const int32_t nt = mesh.numberOfTriangles();
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
  return shellTris;
}

} // namespace

std::vector<std::vector<int32_t>> checkEdgeTopology(const SurfaceMesh& mesh, const std::vector<char>& valid, int maxIds,
                                                    SurfaceCheckReport& r)
{
  const int32_t np = mesh.numberOfPoints();
  const int32_t nt = mesh.numberOfTriangles();
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
  std::sort(half.begin(), half.end(),
            [](const HalfEdge& a, const HalfEdge& b) { return a.key < b.key || (a.key == b.key && a.tri < b.tri); });
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
      keepFirstId(r.firstBoundaryEdgeTriangles, half[s].tri, maxIds);
      keepFirstId(r.firstBoundaryEdges, edgeId, maxIds);
      loopUF.unite(a, b);
    }
    else if (valence > 2)
    {
      flags |= EdgeNonManifold;
      ++r.nonManifoldEdges;
      keepFirstId(r.firstNonManifoldEdges, edgeId, maxIds);
      keepFirstId(r.firstNonManifoldEdgeTriangles, half[s].tri, maxIds);
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
        keepFirstId(r.firstInconsistentTriangles, h0.tri, maxIds);
      }
      // Join the corners at a and at b across this manifold edge.
      auto corner = [&](const HalfEdge& h, int32_t v)
      {
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
  countBoundaryLoops(loopUF, np, r);
  markNonManifoldVertices(mesh, valid, cornerUF, onNonManifoldEdge, maxIds, r);
  return buildShells(mesh, valid, shellUF, r);
}

} // namespace volgrid::detail
