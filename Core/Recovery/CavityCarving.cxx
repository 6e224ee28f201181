#include "CavityCarving.h"

#include "BoundaryRecovery.h"
#include "Predicates.h"
#include "Quality.h"

#include <algorithm>
#include <unordered_set>

namespace volgrid
{

namespace
{

using Face = std::array<int32_t, 3>;
using Tet = std::array<int32_t, 4>;

bool sameCycle(const Face& f, const Face& g)
{
  for (int r = 0; r < 3; ++r)
    if (f[0] == g[r] && f[1] == g[(r + 1) % 3] && f[2] == g[(r + 2) % 3])
      return true;
  return false;
}

class Carver
{
public:
  Carver(const TetMesh& m, const std::function<bool(int32_t, int32_t)>& edgeAllowed, int64_t maxSteps)
    : m_(m)
    , edgeAllowed_(edgeAllowed)
    , stepsLeft_(maxSteps)
  {
  }

  bool run(const std::vector<Face>& faces, std::vector<Tet>& tets)
  {
    for (auto& f : faces)
    {
      verts_.insert(verts_.end(), f.begin(), f.end());
      for (int i = 0; i < 3; ++i)
        boundaryEdges_.insert(edgeKey(f[i], f[(i + 1) % 3]));
    }
    std::sort(verts_.begin(), verts_.end());
    verts_.erase(std::unique(verts_.begin(), verts_.end()), verts_.end());
    std::vector<Face> front = faces;
    tets_.clear();
    if (!search(front))
      return false;
    tets = tets_;
    return true;
  }

private:
  // Index of the front face with f's vertices, -1 if none.
  static int findSet(const std::vector<Face>& front, const Face& f)
  {
    // Faces have three distinct vertices: same set = each of f's vertices is in front[i] (no sorting:
    // this is the search's innermost loop).
    for (size_t i = 0; i < front.size(); ++i)
    {
      const Face& g = front[i];
      if ((g[0] == f[0] || g[1] == f[0] || g[2] == f[0]) && (g[0] == f[1] || g[1] == f[1] || g[2] == f[1]) &&
          (g[0] == f[2] || g[1] == f[2] || g[2] == f[2]))
        return static_cast<int>(i);
    }
    return -1;
  }

  // Apex v on front face f: strictly positive, no disallowed new edge, no new face already in the front
  // with the same orientation (the tet would overlap what is filled).
  bool valid(const std::vector<Face>& front, const Face& f, int32_t v) const
  {
    if (v == f[0] || v == f[1] || v == f[2])
      return false;
    if (predicates::orient3d(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), m_.point(v)) <= 0)
      return false;
    for (int i = 0; i < 3; ++i)
      if (!boundaryEdges_.count(edgeKey(f[i], v)) && !edgeAllowed_(f[i], v))
        return false;
    for (int i = 0; i < 3; ++i)
    {
      const Face g = { { f[i], f[(i + 1) % 3], v } };
      const int k = findSet(front, g);
      if (k >= 0 && sameCycle(front[static_cast<size_t>(k)], g))
        return false;
    }
    return true;
  }

  bool search(std::vector<Face>& front)
  {
    if (front.empty())
      return true;
    if (--stepsLeft_ < 0)
      return false;
    // The front face with the fewest valid apexes (fail fast), candidates best shape first.
    size_t bestFace = 0;
    std::vector<std::pair<double, int32_t>> bestCands;
    bool have = false;
    for (size_t i = 0; i < front.size(); ++i)
    {
      std::vector<std::pair<double, int32_t>> cands;
      for (int32_t v : verts_)
        if (valid(front, front[i], v))
        {
          const Face& f = front[i];
          cands.push_back(
            { -quality::tetShapeMeasure(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), m_.point(v)), v });
        }
      if (!have || cands.size() < bestCands.size())
      {
        have = true;
        bestFace = i;
        bestCands = cands;
        if (cands.size() <= 1)
          break;
      }
    }
    if (bestCands.empty())
      return false;
    std::sort(bestCands.begin(), bestCands.end());
    const Face f = front[bestFace];
    for (auto& [q, v] : bestCands)
    {
      std::vector<Face> next = front;
      next.erase(next.begin() + static_cast<std::ptrdiff_t>(bestFace));
      for (int i = 0; i < 3; ++i)
      {
        const Face g = { { f[i], f[(i + 1) % 3], v } };
        const int k = findSet(next, g);
        if (k >= 0)
          next.erase(next.begin() + k); // the opposite orientation (valid() excluded the same)
        else
          next.push_back(g);
      }
      tets_.push_back({ { f[0], f[1], f[2], v } });
      if (search(next))
        return true;
      tets_.pop_back();
      if (stepsLeft_ < 0)
        return false;
    }
    return false;
  }

  const TetMesh& m_;
  const std::function<bool(int32_t, int32_t)>& edgeAllowed_;
  int64_t stepsLeft_;
  std::vector<int32_t> verts_;
  std::unordered_set<uint64_t> boundaryEdges_;
  std::vector<Tet> tets_;
};

} // namespace

bool carveCavity(const TetMesh& mesh, const std::vector<std::array<int32_t, 3>>& faces,
                 const std::function<bool(int32_t, int32_t)>& edgeAllowed, int64_t maxSteps,
                 std::vector<std::array<int32_t, 4>>& tets)
{
  if (faces.size() < 4)
    return false;
  Carver c(mesh, edgeAllowed, maxSteps);
  return c.run(faces, tets);
}

} // namespace volgrid
