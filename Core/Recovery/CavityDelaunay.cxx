#include "CavityDelaunay.h"

#include "Delaunay.h"

#include <algorithm>

namespace volgrid
{

namespace cavity
{
OKey orientedKey(const int32_t* f)
{
  if (f[0] < f[1] && f[0] < f[2])
    return { { f[0], f[1], f[2] } };
  if (f[1] < f[0] && f[1] < f[2])
    return { { f[1], f[2], f[0] } };
  return { { f[2], f[0], f[1] } };
}

size_t OKeyHash::operator()(const OKey& k) const
{
  TriKey t;
  t.v[0] = k.v[0];
  t.v[1] = k.v[1];
  t.v[2] = k.v[2];
  return TriKeyHash()(t);
}

bool localDelaunay(const TetMesh& mesh, std::vector<int32_t>& verts, TetMesh& local)
{
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  if (verts.size() < 4)
    return false;
  std::vector<double> xyz(3 * verts.size());
  for (size_t i = 0; i < verts.size(); ++i)
    std::copy(mesh.point(verts[i]), mesh.point(verts[i]) + 3, xyz.begin() + 3 * i);
  DelaunayOptions opt;
  opt.spatialSort = false;
  opt.keepGhosts = false;
  std::vector<int32_t> map;
  if (!buildDelaunay(xyz.data(), verts.size(), opt, local, map).ok())
    return false;
  for (size_t i = 0; i < map.size(); ++i)
    if (map[i] != static_cast<int32_t>(i))
      return false;
  return true;
}

std::unordered_map<OKey, int32_t, OKeyHash> faceOwners(const TetMesh& local, const std::vector<int32_t>& verts)
{
  std::unordered_map<OKey, int32_t, OKeyHash> owners;
  int32_t f[3];
  for (int32_t t = 0; t < local.tetCapacity(); ++t)
  {
    if (local.isFree(t))
      continue;
    for (int i = 0; i < 4; ++i)
    {
      local.faceVertices(t, i, f);
      for (int32_t& x : f)
        x = verts[static_cast<size_t>(x)];
      owners.emplace(orientedKey(f), t);
    }
  }
  return owners;
}

bool floodFill(const TetMesh& local, const std::vector<int32_t>& verts, const std::vector<int32_t>& seeds,
               const std::function<FaceStep(int32_t tet, int face, const int32_t* f)>& step,
               std::vector<std::array<int32_t, 4>>& tets)
{
  auto global = [&](int32_t l) { return verts[static_cast<size_t>(l)]; };
  std::vector<int32_t> queue;
  std::vector<char> inFill(static_cast<size_t>(local.tetCapacity()), 0);
  for (int32_t t : seeds)
    if (!inFill[t])
    {
      inFill[t] = 1;
      queue.push_back(t);
    }
  int32_t f[3];
  for (size_t q = 0; q < queue.size(); ++q)
  {
    const int32_t t = queue[q];
    for (int i = 0; i < 4; ++i)
    {
      local.faceVertices(t, i, f);
      for (int32_t& x : f)
        x = global(x);
      const FaceStep next = step(t, i, f);
      if (next == FaceStep::Fail)
        return false;
      if (next == FaceStep::Stop)
        continue;
      const int32_t n = local.neighbor(t, i);
      if (n < 0)
        return false; // the fill leaks out of the cavity
      if (!inFill[n])
      {
        inFill[n] = 1;
        queue.push_back(n);
      }
    }
  }
  for (int32_t t : queue)
  {
    const int32_t* v = local.vertices(t);
    tets.push_back({ { global(v[0]), global(v[1]), global(v[2]), global(v[3]) } });
  }
  return true;
}
} // namespace cavity

using namespace cavity;

bool fillCavityDelaunay(const TetMesh& m, const std::vector<std::array<int32_t, 3>>& faces,
                        std::vector<std::array<int32_t, 4>>& tets, std::vector<std::array<int32_t, 3>>* missing)
{
  tets.clear();
  if (missing)
    missing->clear();
  if (faces.size() < 4)
    return false;
  std::vector<int32_t> verts;
  std::unordered_map<TriKey, OKey, TriKeyHash> fm;
  for (auto& f : faces)
  {
    verts.insert(verts.end(), f.begin(), f.end());
    if (!fm.emplace(TriKey(f[0], f[1], f[2]), orientedKey(f.data())).second)
      return false;
  }
  TetMesh lm;
  if (!localDelaunay(m, verts, lm))
    return false;
  const std::unordered_map<OKey, int32_t, OKeyHash> owners = faceOwners(lm, verts);
  std::vector<int32_t> seeds;
  for (auto& [k, ok] : fm)
  {
    auto it = owners.find(ok);
    if (it != owners.end())
      seeds.push_back(it->second);
    else if (missing)
      missing->push_back({ { ok.v[0], ok.v[1], ok.v[2] } });
  }
  if (missing && !missing->empty())
    return false;
  // A face of the cavity's boundary ends the fill, reached from the inside only.
  auto step = [&](int32_t, int, const int32_t* f)
  {
    auto bt = fm.find(TriKey(f[0], f[1], f[2]));
    if (bt == fm.end())
      return FaceStep::Cross;
    return bt->second == orientedKey(f) ? FaceStep::Stop : FaceStep::Fail;
  };
  return floodFill(lm, verts, seeds, step, tets);
}

} // namespace volgrid
