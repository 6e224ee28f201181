#include "SurfaceRepair.h"

#include "SurfaceChecks.h"
#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace volgrid
{

namespace
{
inline uint64_t edgeKey(int32_t a, int32_t b)
{
  const uint32_t lo = static_cast<uint32_t>(std::min(a, b)), hi = static_cast<uint32_t>(std::max(a, b));
  return (uint64_t(lo) << 32) | hi;
}

void keepTriangles(SurfaceMesh& m, const std::vector<char>& keep)
{
  size_t w = 0;
  const bool patches = m.hasPatchIds();
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    if (!keep[t])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      m.triangles[3 * w + k] = m.triangles[3 * size_t(t) + k];
    }
    if (patches)
    {
      m.patchIds[w] = m.patchIds[t];
    }
    ++w;
  }
  m.triangles.resize(3 * w);
  if (patches)
  {
    m.patchIds.resize(w);
  }
}

// Undirected edge -> number of triangles using it.
std::unordered_map<uint64_t, int> edgeValences(const SurfaceMesh& m)
{
  std::unordered_map<uint64_t, int> count;
  count.reserve(m.triangles.size());
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    const int32_t* v = m.triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      if (v[k] != v[(k + 1) % 3])
      {
        ++count[edgeKey(v[k], v[(k + 1) % 3])];
      }
    }
  }
  return count;
}

struct Vec
{
  double x, y, z;
};
inline Vec P(const SurfaceMesh& m, int32_t i)
{
  const double* p = m.point(i);
  return { p[0], p[1], p[2] };
}
inline Vec sub(Vec a, Vec b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
inline Vec cross(Vec a, Vec b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double dot(Vec a, Vec b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double norm(Vec a)
{
  return std::sqrt(dot(a, a));
}
inline double angleAt(Vec apex, Vec a, Vec b)
{
  const Vec u = sub(a, apex), v = sub(b, apex);
  return std::atan2(norm(cross(u, v)), dot(u, v));
}
} // namespace

int64_t weldPoints(SurfaceMesh& mesh, double tol, bool boundaryOnly)
{
  const int32_t n = mesh.numberOfPoints();
  std::vector<char> candidate(n, boundaryOnly ? 0 : 1);
  if (boundaryOnly)
  {
    for (const auto& e : edgeValences(mesh))
    {
      if (e.second == 1)
      {
        candidate[static_cast<int32_t>(e.first >> 32)] = 1;
        candidate[static_cast<int32_t>(e.first & 0xffffffffu)] = 1;
      }
    }
  }
  UnionFind<int32_t> sets(static_cast<size_t>(n)); // the smallest id of a welded group is its root
  if (!(tol > 0))
  {
    std::vector<int32_t> canon;
    exactCoincidenceMap(mesh.points, canon);
    std::vector<int32_t> firstOf(n, -1);
    for (int32_t i = 0; i < n; ++i)
    {
      if (!candidate[i])
      {
        continue;
      }
      if (firstOf[canon[i]] < 0)
      {
        firstOf[canon[i]] = i;
      }
      else
      {
        sets.unite(firstOf[canon[i]], i);
      }
    }
  }
  else
  {
    auto cell = [&](double v) { return static_cast<int64_t>(std::floor(v / tol)); };
    auto hash = [](int64_t a, int64_t b, int64_t c)
    { return (uint64_t(a) * 73856093ull) ^ (uint64_t(b) * 19349663ull) ^ (uint64_t(c) * 83492791ull); };
    std::unordered_map<uint64_t, std::vector<int32_t>> grid;
    for (int32_t i = 0; i < n; ++i)
    {
      if (candidate[i])
      {
        const double* p = mesh.point(i);
        grid[hash(cell(p[0]), cell(p[1]), cell(p[2]))].push_back(i);
      }
    }
    const double tol2 = tol * tol;
    for (int32_t i = 0; i < n; ++i)
    {
      if (!candidate[i])
      {
        continue;
      }
      const double* p = mesh.point(i);
      const int64_t c0 = cell(p[0]), c1 = cell(p[1]), c2 = cell(p[2]);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
          {
            auto it = grid.find(hash(c0 + dx, c1 + dy, c2 + dz));
            if (it == grid.end())
            {
              continue;
            }
            for (int32_t j : it->second)
            {
              if (j <= i)
              {
                continue;
              }
              const double* q = mesh.point(j);
              const double d2 =
                (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
              if (d2 <= tol2)
              {
                sets.unite(i, j);
              }
            }
          }
    }
  }
  std::vector<int32_t> oldToNew(n, -1);
  int32_t next = 0;
  for (int32_t i = 0; i < n; ++i)
  {
    const int32_t r = sets.find(i);
    oldToNew[i] = r == i ? next++ : oldToNew[r];
  }
  if (next != n)
  {
    remapPoints(mesh, oldToNew, next);
  }
  return n - next;
}

int64_t removeDegenerateTriangles(SurfaceMesh& mesh)
{
  std::vector<char> keep(mesh.numberOfTriangles(), 1);
  int64_t removed = 0;
  for (int32_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    const int32_t* v = mesh.triangle(t);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        triangleIsDegenerate(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])))
    {
      keep[t] = 0;
      ++removed;
    }
  }
  if (removed)
  {
    keepTriangles(mesh, keep);
  }
  return removed;
}

int64_t removeDuplicateTriangles(SurfaceMesh& mesh)
{
  const int32_t nt = mesh.numberOfTriangles();
  std::vector<std::array<int32_t, 4>> keys(nt);
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t* v = mesh.triangle(t);
    keys[t] = { v[0], v[1], v[2], t };
    std::sort(keys[t].begin(), keys[t].begin() + 3);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> keep(nt, 1);
  int64_t removed = 0;
  for (int32_t i = 1; i < nt; ++i)
  {
    if (std::equal(keys[i].begin(), keys[i].begin() + 3, keys[i - 1].begin()))
    {
      keep[keys[i][3]] = 0;
      ++removed;
    }
  }
  if (removed)
  {
    keepTriangles(mesh, keep);
  }
  return removed;
}

int64_t orientShellsConsistently(SurfaceMesh& mesh, int64_t* nonOrientable)
{
  const int32_t nt = mesh.numberOfTriangles();
  // Adjacency across manifold edges: (neighbour, same direction?).
  std::unordered_map<uint64_t, std::vector<std::pair<int32_t, int8_t>>> edges;
  edges.reserve(3 * size_t(nt));
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t* v = mesh.triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      const int32_t a = v[k], b = v[(k + 1) % 3];
      if (a != b)
      {
        edges[edgeKey(a, b)].push_back({ t, static_cast<int8_t>(a < b) });
      }
    }
  }
  std::vector<std::vector<std::pair<int32_t, int8_t>>> adj(nt);
  for (const auto& e : edges)
  {
    if (e.second.size() == 2 && e.second[0].first != e.second[1].first)
    {
      const int8_t same = e.second[0].second == e.second[1].second;
      adj[e.second[0].first].push_back({ e.second[1].first, same });
      adj[e.second[1].first].push_back({ e.second[0].first, same });
    }
  }
  std::vector<int8_t> flip(nt, -1);
  int64_t flipped = 0, bad = 0;
  std::vector<int32_t> component;
  for (int32_t s = 0; s < nt; ++s)
  {
    if (flip[s] >= 0)
    {
      continue;
    }
    component.clear();
    std::deque<int32_t> queue{ s };
    flip[s] = 0;
    bool conflict = false;
    while (!queue.empty())
    {
      const int32_t t = queue.front();
      queue.pop_front();
      component.push_back(t);
      for (const auto& nb : adj[t])
      {
        const int8_t want = static_cast<int8_t>(flip[t] ^ nb.second);
        if (flip[nb.first] < 0)
        {
          flip[nb.first] = want;
          queue.push_back(nb.first);
        }
        else if (flip[nb.first] != want)
        {
          conflict = true;
        }
      }
    }
    bad += conflict ? 1 : 0;
    int64_t count = 0;
    for (int32_t t : component)
    {
      count += flip[t];
    }
    const bool invert = 2 * count > static_cast<int64_t>(component.size()); // flip the fewest
    for (int32_t t : component)
    {
      if ((flip[t] != 0) != invert)
      {
        std::swap(mesh.triangles[3 * size_t(t) + 1], mesh.triangles[3 * size_t(t) + 2]);
        ++flipped;
      }
    }
  }
  if (nonOrientable)
  {
    *nonOrientable = bad;
  }
  return flipped;
}

int64_t orientShellsForDomain(SurfaceMesh& mesh)
{
  SurfaceCheckOptions o;
  o.selfIntersections = false;
  o.nesting = true;
  const SurfaceCheckReport r = checkSurface(mesh, o);
  std::vector<char> flipShell(r.shells.size(), 0);
  int64_t flipped = 0;
  for (size_t s = 0; s < r.shells.size(); ++s)
  {
    const SurfaceShell& sh = r.shells[s];
    if (!sh.closed || !sh.consistent || sh.signedVolume == 0.0)
    {
      continue;
    }
    const bool wantOutward = (sh.depth % 2) == 0;
    if ((sh.signedVolume > 0) != wantOutward)
    {
      flipShell[s] = 1;
      ++flipped;
    }
  }
  for (int32_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    const int32_t s = r.triangleShell[t];
    if (s >= 0 && flipShell[s])
    {
      std::swap(mesh.triangles[3 * size_t(t) + 1], mesh.triangles[3 * size_t(t) + 2]);
    }
  }
  return flipped;
}

// ---------------------------------------------------------------------------------------------------
// Hole filling: minimum-angle ear clipping, centroid refinement with edge relaxation, then fairing.

namespace
{
using Patch = std::vector<std::array<int32_t, 3>>;

// The loop's normal (Newell); the hole lies to the left of the loop around it.
Vec loopNormal(const SurfaceMesh& m, const std::vector<int32_t>& loop)
{
  const size_t n = loop.size();
  Vec nrm{ 0, 0, 0 };
  for (size_t i = 0; i < n; ++i)
  {
    const Vec a = P(m, loop[i]), b = P(m, loop[(i + 1) % n]);
    nrm.x += (a.y - b.y) * (a.z + b.z);
    nrm.y += (a.z - b.z) * (a.x + b.x);
    nrm.z += (a.x - b.x) * (a.y + b.y);
  }
  return nrm;
}

// Triangulates the loop by clipping the ear of smallest interior angle first (about the normal nrm);
// the new diagonals go into edgeSet.
void clipEars(const SurfaceMesh& m, const std::vector<int32_t>& loop, const Vec& nrm,
              std::unordered_set<uint64_t>& edgeSet, Patch& tris)
{
  std::vector<int32_t> poly = loop;
  auto interior = [&](size_t i)
  {
    const size_t k = poly.size();
    const Vec c = P(m, poly[i]);
    const Vec e1 = sub(P(m, poly[(i + k - 1) % k]), c), e2 = sub(P(m, poly[(i + 1) % k]), c);
    double a = std::atan2(dot(nrm, cross(e2, e1)) / std::max(norm(nrm), 1e-300), dot(e1, e2));
    if (a < 0)
    {
      a += 2.0 * 3.14159265358979323846;
    }
    // An ear whose diagonal already exists would create a non-manifold edge: last resort only.
    if (edgeSet.count(edgeKey(poly[(i + k - 1) % k], poly[(i + 1) % k])))
    {
      a += 10.0;
    }
    return a;
  };
  while (poly.size() > 3)
  {
    size_t best = 0;
    double bestAngle = 1e300;
    for (size_t i = 0; i < poly.size(); ++i)
    {
      const double a = interior(i);
      if (a < bestAngle)
      {
        bestAngle = a;
        best = i;
      }
    }
    const size_t k = poly.size();
    const int32_t a = poly[(best + k - 1) % k], b = poly[best], c = poly[(best + 1) % k];
    tris.push_back({ a, b, c });
    edgeSet.insert(edgeKey(a, c));
    poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(best));
  }
  tris.push_back({ poly[0], poly[1], poly[2] });
}

// Flips patch-interior edges whose opposite angles sum above pi, up to 8 sweeps; edgeSet follows.
void relaxPatch(const SurfaceMesh& m, std::unordered_set<uint64_t>& edgeSet, Patch& tris)
{
  for (int sweep = 0; sweep < 8; ++sweep)
  {
    std::unordered_map<uint64_t, std::vector<std::pair<size_t, int>>> own;
    for (size_t t = 0; t < tris.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        own[edgeKey(tris[t][k], tris[t][(k + 1) % 3])].push_back({ t, k });
      }
    }
    bool flippedAny = false;
    std::vector<char> touched(tris.size(), 0);
    for (const auto& e : own)
    {
      if (e.second.size() != 2)
      {
        continue;
      }
      const size_t t1 = e.second[0].first, t2 = e.second[1].first;
      if (touched[t1] || touched[t2])
      {
        continue;
      }
      const int k1 = e.second[0].second, k2 = e.second[1].second;
      const int32_t a = tris[t1][k1], b = tris[t1][(k1 + 1) % 3], c = tris[t1][(k1 + 2) % 3];
      const int32_t d = tris[t2][(k2 + 2) % 3];
      if (tris[t2][k2] != b || c == d || edgeSet.count(edgeKey(c, d)))
      {
        continue;
      }
      if (angleAt(P(m, c), P(m, a), P(m, b)) + angleAt(P(m, d), P(m, a), P(m, b)) <= 3.14159265358979323846 + 1e-9)
      {
        continue;
      }
      tris[t1] = { c, a, d };
      tris[t2] = { d, b, c };
      edgeSet.erase(edgeKey(a, b));
      edgeSet.insert(edgeKey(c, d));
      touched[t1] = touched[t2] = 1;
      flippedAny = true;
    }
    if (!flippedAny)
    {
      break;
    }
  }
}

// Splits the patch's triangles at their centroids while they are large against the loop's spacing
// (sigma, carried to the new points), relaxing after each pass (at most 12 passes); adds the points to m.
void refinePatch(SurfaceMesh& m, const std::vector<int32_t>& loop, std::unordered_set<uint64_t>& edgeSet, Patch& tris)
{
  const size_t n = loop.size();
  std::unordered_map<int32_t, double> sigma;
  for (size_t i = 0; i < n; ++i)
  {
    const Vec c = P(m, loop[i]);
    sigma[loop[i]] = 0.5 * (norm(sub(P(m, loop[(i + n - 1) % n]), c)) + norm(sub(P(m, loop[(i + 1) % n]), c)));
  }
  for (int pass = 0; pass < 12; ++pass)
  {
    bool split = false;
    const size_t count = tris.size();
    for (size_t t = 0; t < count; ++t)
    {
      const auto tri = tris[t];
      const Vec a = P(m, tri[0]), b = P(m, tri[1]), c = P(m, tri[2]);
      const Vec g{ (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3 };
      const double sg = (sigma[tri[0]] + sigma[tri[1]] + sigma[tri[2]]) / 3.0;
      bool big = true;
      for (int k = 0; k < 3 && big; ++k)
      {
        const double d = std::sqrt(2.0) * norm(sub(g, P(m, tri[k])));
        big = d > sg && d > sigma[tri[k]];
      }
      if (!big)
      {
        continue;
      }
      const int32_t v = m.addPoint(g.x, g.y, g.z);
      sigma[v] = sg;
      tris[t] = { tri[0], tri[1], v };
      tris.push_back({ tri[1], tri[2], v });
      tris.push_back({ tri[2], tri[0], v });
      for (int k = 0; k < 3; ++k)
      {
        edgeSet.insert(edgeKey(tri[k], v));
      }
      split = true;
    }
    relaxPatch(m, edgeSet, tris);
    if (!split)
    {
      break;
    }
  }
}

// Umbrella smoothing of the points from firstNew on (the inserted ones) with the loop fixed: a membrane
// spanning the loop.
void fairPatch(SurfaceMesh& m, const Patch& tris, int32_t firstNew, int fairing)
{
  const int32_t added = m.numberOfPoints() - firstNew;
  std::vector<std::vector<int32_t>> nb(added);
  for (const auto& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (t[k] >= firstNew)
      {
        nb[t[k] - firstNew].push_back(t[(k + 1) % 3]);
        nb[t[k] - firstNew].push_back(t[(k + 2) % 3]);
      }
    }
  }
  for (int it = 0; it < fairing; ++it)
  {
    for (int32_t i = 0; i < added; ++i)
    {
      double s[3] = { 0, 0, 0 };
      for (int32_t j : nb[i])
      {
        for (int k = 0; k < 3; ++k)
        {
          s[k] += m.point(j)[k];
        }
      }
      if (!nb[i].empty())
      {
        for (int k = 0; k < 3; ++k)
        {
          m.points[3 * size_t(firstNew + i) + k] = s[k] / static_cast<double>(nb[i].size());
        }
      }
    }
  }
}

// Fills one hole loop: ear clipping, then (refine) centroid refinement, then (fairing) smoothing of the new
// points; the triangles get `patch` when the mesh has patch ids.
void fillLoop(SurfaceMesh& m, const std::vector<int32_t>& loop, std::unordered_set<uint64_t>& edgeSet, bool refine,
              int fairing, int32_t patch, int64_t& pointsAdded, int64_t& trianglesAdded)
{
  Patch tris;
  clipEars(m, loop, loopNormal(m, loop), edgeSet, tris);
  const int32_t firstNew = m.numberOfPoints();
  if (refine)
  {
    refinePatch(m, loop, edgeSet, tris);
  }
  const int32_t added = m.numberOfPoints() - firstNew;
  if (added > 0 && fairing > 0)
  {
    fairPatch(m, tris, firstNew, fairing);
  }
  for (const auto& t : tris)
  {
    m.addTriangle(t[0], t[1], t[2], m.hasPatchIds() ? patch : -1);
  }
  pointsAdded += added;
  trianglesAdded += static_cast<int64_t>(tris.size());
}
} // namespace

int64_t fillHoles(SurfaceMesh& mesh, int maxEdges, bool refine, int fairingIterations, int64_t* loopsLeftOpen,
                  int64_t* pointsAdded, int64_t* trianglesAdded)
{
  int64_t filled = 0, open = 0, pts = 0, tris = 0;
  const auto valence = edgeValences(mesh);
  // Hole edges run opposite to their triangle's boundary edge: b -> a for a triangle edge a -> b.
  std::unordered_map<int32_t, std::vector<std::pair<int32_t, int32_t>>> out; // from -> (to, triangle)
  std::unordered_set<uint64_t> edgeSet;
  for (const auto& e : valence)
  {
    edgeSet.insert(e.first);
  }
  for (int32_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    const int32_t* v = mesh.triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      const int32_t a = v[k], b = v[(k + 1) % 3];
      if (a != b && valence.at(edgeKey(a, b)) == 1)
      {
        out[b].push_back({ a, t });
      }
    }
  }
  std::vector<int32_t> starts;
  for (const auto& o : out)
  {
    starts.push_back(o.first);
  }
  std::sort(starts.begin(), starts.end());
  for (int32_t s : starts)
  {
    while (!out[s].empty())
    {
      std::vector<int32_t> loop{ s };
      int32_t cur = s;
      const int32_t patch = mesh.hasPatchIds() ? mesh.patchIds[out[s].back().second] : -1;
      bool closed = false;
      while (true)
      {
        auto& o = out[cur];
        if (o.empty())
        {
          break;
        }
        const int32_t next = o.back().first;
        o.pop_back();
        if (next == s)
        {
          closed = true;
          break;
        }
        loop.push_back(next);
        cur = next;
        if (loop.size() > valence.size())
        {
          break;
        }
      }
      if (!closed || loop.size() < 3 || (maxEdges > 0 && static_cast<int>(loop.size()) > maxEdges) || maxEdges <= 0)
      {
        ++open;
        continue;
      }
      fillLoop(mesh, loop, edgeSet, refine, fairingIterations, patch, pts, tris);
      ++filled;
    }
  }
  if (loopsLeftOpen)
  {
    *loopsLeftOpen = open;
  }
  if (pointsAdded)
  {
    *pointsAdded = pts;
  }
  if (trianglesAdded)
  {
    *trianglesAdded = tris;
  }
  return filled;
}

// ---------------------------------------------------------------------------------------------------

Status repairSurface(SurfaceMesh& mesh, const SurfaceRepairOptions& o, SurfaceRepairReport* reportOut)
{
  SurfaceRepairReport local;
  SurfaceRepairReport& r = reportOut ? *reportOut : local;
  r = SurfaceRepairReport();
  SilentProgress silent;
  Progress* progress = o.progress ? o.progress : &silent;
  if (mesh.numberOfTriangles() == 0)
  {
    return Status::failure(ErrorKind::EmptyInput, "The surface has no triangles.");
  }
  int32_t bad = -1;
  if (!allPointsFinite(mesh, &bad))
  {
    return Status::failure(ErrorKind::NonFinitePoint,
                           "Point " + std::to_string(bad) + " has a NaN or infinite coordinate.", { bad });
  }
  for (int32_t v : mesh.triangles)
  {
    if (v < 0 || v >= mesh.numberOfPoints())
    {
      return Status::failure(ErrorKind::InvalidOption, "A triangle refers to a point id that does not exist.");
    }
  }
  if (o.weldTolerance < 0 || o.stitchTolerance < 0 || !std::isfinite(o.weldTolerance) ||
      !std::isfinite(o.stitchTolerance))
  {
    return Status::failure(ErrorKind::InvalidOption, "Weld and stitch tolerances must be finite and non-negative.");
  }
  const double diag = boundingBox(mesh, true).diagonal();
  progress->report(0.0, "Repairing surface");
  // Only points on open edges are welded: copies of one vertex (a triangle soup, a seam) leave the edges
  // around them open, while two points of a closed part are two vertices however close they are (a prepared
  // domain prepared again, whose far field has grown the bounding box and so the tolerance, lost a wing's
  // thin trailing edge to the weld when every point was a candidate).
  r.weldedPoints = weldPoints(mesh, o.weldTolerance * diag, true);
  if (o.removeDegenerate)
  {
    r.removedDegenerate = removeDegenerateTriangles(mesh);
  }
  if (o.removeDuplicates)
  {
    r.removedDuplicates = removeDuplicateTriangles(mesh);
  }
  if (o.stitch)
  {
    r.stitchedPoints = weldPoints(mesh, o.stitchTolerance * diag, true);
    if (r.stitchedPoints > 0)
    {
      // Stitching can collapse or duplicate triangles along the seam.
      if (o.removeDegenerate)
      {
        r.removedDegenerate += removeDegenerateTriangles(mesh);
      }
      if (o.removeDuplicates)
      {
        r.removedDuplicates += removeDuplicateTriangles(mesh);
      }
    }
  }
  progress->report(0.3, "Repairing surface");
  if (progress->cancelled())
  {
    return Status::failure(ErrorKind::Cancelled, "Surface repair cancelled.");
  }
  if (o.orientConsistently)
  {
    // Before filling, so that the loops' directions agree with their neighbourhoods.
    r.trianglesFlipped = orientShellsConsistently(mesh, &r.nonOrientableShells);
  }
  if (o.maxHoleEdges > 0)
  {
    r.loopsFilled = fillHoles(mesh, o.maxHoleEdges, o.refineFilledHoles, o.fairingIterations, &r.loopsLeftOpen,
                              &r.pointsAdded, &r.trianglesAdded);
  }
  else
  {
    fillHoles(mesh, 0, false, 0, &r.loopsLeftOpen);
  }
  progress->report(0.6, "Repairing surface");
  if (o.orientConsistently && r.loopsFilled > 0)
  {
    r.trianglesFlipped += orientShellsConsistently(mesh, &r.nonOrientableShells);
  }
  if (o.orientForDomain)
  {
    r.shellsFlipped = orientShellsForDomain(mesh);
  }
  r.unreferencedPointsRemoved = removeUnreferencedPoints(mesh);
  if (r.nonOrientableShells > 0)
  {
    r.notes.push_back(std::to_string(r.nonOrientableShells) +
                      " shell(s) cannot be oriented consistently (non-orientable or non-manifold)");
  }
  progress->report(1.0, "Repairing surface");
  return mesh.numberOfTriangles() > 0 ? Status::success()
                                      : Status::failure(ErrorKind::EmptyInput, "Repair removed every triangle.");
}

std::string SurfaceRepairReport::summary() const
{
  std::ostringstream os;
  os << "welded points " << weldedPoints << ", degenerate triangles removed " << removedDegenerate
     << ", duplicate triangles removed " << removedDuplicates << ", stitched points " << stitchedPoints
     << ", loops filled " << loopsFilled << " (" << trianglesAdded << " triangles, " << pointsAdded
     << " points), loops left open " << loopsLeftOpen << ", triangles flipped " << trianglesFlipped
     << ", shells flipped " << shellsFlipped;
  for (const auto& n : notes)
  {
    os << "; " << n;
  }
  return os.str();
}

} // namespace volgrid
