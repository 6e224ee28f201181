// Conforming midpoint refinement of the wall around its skewed edges (see WallRefinement.h).
#include "WallRefinement.h"

#include "WallFaceQuality.h"

#include <algorithm>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

namespace volgrid
{
namespace
{
uint64_t edgeKey(int32_t a, int32_t b)
{
  return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
}

double squaredLength(const SurfaceMesh& s, int32_t a, int32_t b)
{
  double sum = 0;
  for (int k = 0; k < 3; ++k)
    sum += (s.point(a)[k] - s.point(b)[k]) * (s.point(a)[k] - s.point(b)[k]);
  return sum;
}

// The longest edge of both wall triangles of every skewed edge (ties: the smaller key, so the same
// surface always gives the same edges).
std::unordered_set<uint64_t> edgesToBisect(const SurfaceMesh& s, const std::vector<uint8_t>& isWall,
                                           const std::vector<int32_t>& skewed)
{
  std::unordered_set<uint64_t> skewedKeys, marked;
  for (size_t e = 0; e < skewed.size(); e += 2)
    skewedKeys.insert(edgeKey(skewed[e], skewed[e + 1]));
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
  {
    const int32_t* v = s.triangle(t);
    bool touches = false;
    for (int i = 0; i < 3 && isWall[t]; ++i)
      touches = touches || skewedKeys.count(edgeKey(v[i], v[(i + 1) % 3]));
    if (!touches)
      continue;
    int longest = 0;
    for (int i = 1; i < 3; ++i)
    {
      const double li = squaredLength(s, v[i], v[(i + 1) % 3]);
      const double ll = squaredLength(s, v[longest], v[(longest + 1) % 3]);
      if (li > ll || (li == ll && edgeKey(v[i], v[(i + 1) % 3]) < edgeKey(v[longest], v[(longest + 1) % 3])))
        longest = i;
    }
    marked.insert(edgeKey(v[longest], v[(longest + 1) % 3]));
  }
  return marked;
}

// Splits triangle t, whose edges i (v[i], v[i+1]) have midpoints m[i] (-1: not bisected), into parts with
// its orientation; the first part replaces it, the others are appended with its patch and wall flag.
void splitTriangle(SurfaceMesh& s, std::vector<uint8_t>& isWall, int32_t t, const int32_t m[3])
{
  const int32_t v[3] = { s.triangle(t)[0], s.triangle(t)[1], s.triangle(t)[2] };
  const int32_t patch = s.hasPatchIds() ? s.patchIds[t] : -1;
  std::vector<int32_t> parts;
  const int count = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
  if (count == 3)
    parts = { v[0], m[0], m[2], m[0], v[1], m[1], m[2], m[1], v[2], m[0], m[1], m[2] };
  else if (count == 1)
  {
    const int i = m[0] >= 0 ? 0 : (m[1] >= 0 ? 1 : 2);
    parts = { v[i], m[i], v[(i + 2) % 3], m[i], v[(i + 1) % 3], v[(i + 2) % 3] };
  }
  else
  {
    // Edge k is whole: a corner triangle at the opposite point, the quad left cut by its shorter diagonal.
    const int k = m[0] < 0 ? 0 : (m[1] < 0 ? 1 : 2);
    const int32_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3], mbc = m[(k + 1) % 3], mca = m[(k + 2) % 3];
    parts = { mbc, c, mca };
    if (squaredLength(s, a, mbc) <= squaredLength(s, b, mca))
      parts.insert(parts.end(), { a, b, mbc, a, mbc, mca });
    else
      parts.insert(parts.end(), { a, b, mca, b, mbc, mca });
  }
  std::copy(parts.begin(), parts.begin() + 3, s.triangles.begin() + 3 * size_t(t));
  for (size_t p = 3; p < parts.size(); p += 3)
  {
    s.addTriangle(parts[p], parts[p + 1], parts[p + 2], patch);
    isWall.push_back(isWall[t]);
  }
}

// Bisects the marked edges of every triangle (wall or not: the surface stays conforming).
void bisect(SurfaceMesh& s, std::vector<uint8_t>& isWall, const std::unordered_set<uint64_t>& marked,
            WallRefinement& stats)
{
  std::unordered_map<uint64_t, int32_t> midpoint;
  const int32_t n = s.numberOfTriangles();
  for (int32_t t = 0; t < n; ++t)
  {
    int32_t m[3] = { -1, -1, -1 };
    for (int i = 0; i < 3; ++i)
    {
      const int32_t a = s.triangle(t)[i], b = s.triangle(t)[(i + 1) % 3];
      const uint64_t key = edgeKey(a, b);
      if (!marked.count(key))
        continue;
      auto found = midpoint.find(key);
      if (found == midpoint.end())
      {
        const double* p = s.point(a);
        const double* q = s.point(b);
        found = midpoint.emplace(key, s.addPoint(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]))).first;
        ++stats.splitEdges;
      }
      m[i] = found->second;
    }
    if (m[0] >= 0 || m[1] >= 0 || m[2] >= 0)
    {
      const int32_t before = s.numberOfTriangles();
      splitTriangle(s, isWall, t, m);
      stats.addedTriangles += s.numberOfTriangles() - before;
    }
  }
}
} // namespace

std::vector<int32_t> wallTriangles(const SurfaceMesh& s, const std::vector<uint8_t>& isWall)
{
  std::vector<int32_t> wall;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    if (isWall[t])
      wall.insert(wall.end(), s.triangle(t), s.triangle(t) + 3);
  return wall;
}

WallRefinement refineSkewedWall(SurfaceMesh& surface, std::vector<uint8_t>& isWall, double skewnessLimit,
                                int maxRounds)
{
  WallRefinement stats;
  std::vector<int32_t> skewed = skewedWallEdges(surface.points, wallTriangles(surface, isWall), skewnessLimit);
  stats.skewedEdgesBefore = static_cast<int64_t>(skewed.size() / 2);
  for (; !skewed.empty() && stats.rounds < maxRounds; ++stats.rounds)
  {
    bisect(surface, isWall, edgesToBisect(surface, isWall, skewed), stats);
    skewed = skewedWallEdges(surface.points, wallTriangles(surface, isWall), skewnessLimit);
  }
  stats.skewedEdgesAfter = static_cast<int64_t>(skewed.size() / 2);
  return stats;
}

std::string wallRefinementNote(const WallRefinement& r)
{
  if (r.splitEdges == 0)
    return std::string();
  char text[500];
  std::snprintf(text, sizeof text,
                "the wall's triangles were split at %lld edge midpoints (%lld more triangles, %d rounds) around %lld "
                "wall edge(s) whose prism side faces OpenFOAM's checkMesh would find highly skewed; the wall keeps "
                "its shape, its triangulation differs from the input there (keepWallTriangles keeps it)%s",
                (long long)r.splitEdges, (long long)r.addedTriangles, r.rounds, (long long)r.skewedEdgesBefore,
                r.skewedEdgesAfter ? "; some are still over the limit" : "");
  return text;
}

} // namespace volgrid
