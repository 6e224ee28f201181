// Piecewise facet recovery (FacetRecovery.h recoverFacetByPieces): the pieces of an input triangle
// split by rounded segment Steiner points are not coplanar, so the whole-triangle cavity cannot be used;
// each piece is recovered as its own triangle instead, after choosing pieces whose edges the mesh
// already has where possible.
#include "FacetPieces.h"

#include "IntervalTriangulation.h"
#include "Predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace volgrid
{

namespace
{

// Polygons longer than this keep their subfaces (the dynamic programme is cubic).
constexpr size_t kMaxPolygon = 200;

// Smallest-angle proxy of triangle abc: twice its area over its longest squared edge (scale free).
double shapeOf(const double* a, const double* b, const double* c)
{
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = c[k] - b[k];
  }
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
  const double area2 = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double l = std::max({ u[0] * u[0] + u[1] * u[1] + u[2] * u[2], v[0] * v[0] + v[1] * v[1] + v[2] * v[2],
                              w[0] * w[0] + w[1] * w[1] + w[2] * w[2] });
  return l > 0 ? area2 / l : 0;
}

// The border of the region covered by `subfaces` as one cycle starting at corner `a`, in the parent's
// orientation. False when the border is not a single simple cycle through a or a vertex is inner.
bool borderCycle(const BoundaryConstraints& bc, const std::vector<int32_t>& subfaces, int32_t a,
                 std::vector<int32_t>& cycle)
{
  std::unordered_map<uint64_t, int> uses;
  for (int32_t f : subfaces)
    for (int i = 0; i < 3; ++i)
      ++uses[edgeKey(bc.subface(f)[i], bc.subface(f)[(i + 1) % 3])];
  std::unordered_map<int32_t, int32_t> next;
  std::unordered_set<int32_t> all;
  size_t borderEdges = 0;
  for (int32_t f : subfaces)
    for (int i = 0; i < 3; ++i)
    {
      const int32_t x = bc.subface(f)[i], y = bc.subface(f)[(i + 1) % 3];
      all.insert(x);
      if (uses[edgeKey(x, y)] != 1)
        continue;
      ++borderEdges;
      if (!next.emplace(x, y).second)
        return false; // pinched border
    }
  cycle.clear();
  int32_t v = a;
  do
  {
    cycle.push_back(v);
    auto it = next.find(v);
    if (it == next.end() || cycle.size() > borderEdges)
      return false;
    v = it->second;
  } while (v != a);
  return cycle.size() == borderEdges && cycle.size() == all.size();
}

// Triangulation of the polygon `poly` (parent orientation) that uses as many present mesh edges as
// diagonals as possible, then the best shapes. Triangles must turn like the parent in its dominant
// projection and may not have their three corners on one side of the parent (`sides`: bit mask per
// vertex). False when no such triangulation exists.
bool chooseTriangulation(MeshEditor& ed, const std::vector<int32_t>& poly, const std::vector<int>& sides, int axis,
                         int o, std::vector<std::array<int32_t, 3>>& out)
{
  const TetMesh& m = ed.mesh;
  const int n = static_cast<int>(poly.size());
  // Mesh edges among the polygon's vertices, from their stars.
  std::unordered_map<int32_t, int> index;
  for (int i = 0; i < n; ++i)
    index[poly[i]] = i;
  std::vector<char> present(static_cast<size_t>(n * n), 0);
  std::vector<int32_t> star;
  for (int i = 0; i < n; ++i)
  {
    ed.star(poly[i], star);
    for (int32_t t : star)
      for (int k = 0; k < 4; ++k)
      {
        auto it = index.find(m.vertex(t, k));
        if (it != index.end())
          present[static_cast<size_t>(i * n + it->second)] = 1;
      }
  }
  auto miss = [&](int i, int j)
  {
    if (j == i + 1 || (i == 0 && j == n - 1))
      return 0;
    return present[static_cast<size_t>(i * n + j)] ? 0 : 1;
  };
  const int kInf = std::numeric_limits<int>::max() / 4;
  std::vector<int> cost(static_cast<size_t>(n * n), kInf), choice(static_cast<size_t>(n * n), -1);
  std::vector<double> shape(static_cast<size_t>(n * n), 0);
  for (int i = 0; i + 1 < n; ++i)
  {
    cost[static_cast<size_t>(i * n + i + 1)] = 0;
    shape[static_cast<size_t>(i * n + i + 1)] = std::numeric_limits<double>::infinity();
  }
  for (int len = 2; len < n; ++len)
    for (int i = 0; i + len < n; ++i)
    {
      const int j = i + len;
      int bc = kInf;
      double bq = -1;
      int bk = -1;
      for (int k = i + 1; k < j; ++k)
      {
        const int c1 = cost[static_cast<size_t>(i * n + k)], c2 = cost[static_cast<size_t>(k * n + j)];
        if (c1 >= kInf || c2 >= kInf || (sides[i] & sides[k] & sides[j]) != 0)
          continue;
        const int c = c1 + c2 + miss(i, k) + miss(k, j);
        if (c > bc)
          continue;
        const double *A = m.point(poly[i]), *B = m.point(poly[k]), *C = m.point(poly[j]);
        if (predicates::orient2dProjected(A, B, C, axis) != o)
          continue;
        const double q =
          std::min({ shape[static_cast<size_t>(i * n + k)], shape[static_cast<size_t>(k * n + j)], shapeOf(A, B, C) });
        if (c < bc || q > bq)
        {
          bc = c;
          bq = q;
          bk = k;
        }
      }
      cost[static_cast<size_t>(i * n + j)] = bc;
      shape[static_cast<size_t>(i * n + j)] = bq;
      choice[static_cast<size_t>(i * n + j)] = bk;
    }
  if (cost[static_cast<size_t>(n - 1)] >= kInf)
    return false;
  out.clear();
  forEachChosenTriangle(choice, n, [&](int i, int k, int j) { out.push_back({ { poly[i], poly[k], poly[j] } }); });
  return true;
}

} // namespace

bool recoverFacetByPieces(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                          FacetCavityStats* stats)
{
  if (subfaces.empty())
    return false;
  const TetMesh& m = ed.mesh;
  const int32_t* abc = bc.verts.data() + 3 * static_cast<size_t>(parent);
  std::vector<int32_t> poly;
  std::vector<std::array<int32_t, 3>> tri;
  if (borderCycle(bc, subfaces, abc[0], poly) && poly.size() <= kMaxPolygon)
  {
    // Which sides of the parent each border vertex lies on (corners: two).
    std::vector<int> sides(poly.size(), 0);
    int side = 0;
    for (size_t i = 0; i < poly.size(); ++i)
    {
      if (poly[i] == abc[0])
        sides[i] = 1 << 2 | 1 << 0;
      else if (poly[i] == abc[1])
        sides[i] = 1 << 0 | 1 << 1, side = 1;
      else if (poly[i] == abc[2])
        sides[i] = 1 << 1 | 1 << 2, side = 2;
      else
        sides[i] = 1 << side;
    }
    const double *A = m.point(abc[0]), *B = m.point(abc[1]), *C = m.point(abc[2]);
    double u[3], v[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = B[k] - A[k];
      v[k] = C[k] - A[k];
    }
    const double nrm[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(nrm[k]) > std::fabs(nrm[axis]))
        axis = k;
    const int o = predicates::orient2dProjected(A, B, C, axis);
    if (o == 0 || !chooseTriangulation(ed, poly, sides, axis, o, tri))
      tri.clear();
  }
  if (!tri.empty())
  {
    // Replace the subfaces by the chosen triangulation (when it differs).
    std::unordered_set<TriKey, TriKeyHash> now;
    for (int32_t f : subfaces)
      now.insert(TriKey(bc.subface(f)[0], bc.subface(f)[1], bc.subface(f)[2]));
    bool same = now.size() == tri.size();
    for (auto& t : tri)
      same = same && now.count(TriKey(t[0], t[1], t[2])) != 0;
    if (!same)
    {
      for (int32_t f : subfaces)
        bc.removeSubface(f);
      subfaces.clear();
      for (auto& t : tri)
        subfaces.push_back(bc.addSubface(t[0], t[1], t[2], parent));
    }
  }
  bool all = true;
  for (int32_t f : subfaces)
  {
    const int32_t* s = bc.subface(f);
    if (ed.findFace(s[0], s[1], s[2]) >= 0)
      continue;
    if (ed.findEdge(s[0], s[1]) < 0 || ed.findEdge(s[1], s[2]) < 0 || ed.findEdge(s[2], s[0]) < 0)
      all = false;
    else if (!recoverSubfaceByCavity(ed, bc, f, stats))
      all = false;
  }
  return all;
}

} // namespace volgrid
