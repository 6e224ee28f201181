#include "StarFlips.h"

#include <algorithm>
#include <array>

namespace volgrid
{

void starFlipCandidates(MeshEditor& ed, const BoundaryConstraints& bc, int32_t p,
                        std::vector<std::pair<int32_t, int32_t>>& out)
{
  out.clear();
  std::vector<int32_t> star;
  ed.star(p, star);
  std::vector<int32_t> layer;
  for (int32_t t : star)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t u = ed.mesh.neighbor(t, i);
      if (u >= 0 && std::find(star.begin(), star.end(), u) == star.end() &&
          std::find(layer.begin(), layer.end(), u) == layer.end())
        layer.push_back(u);
    }
  std::vector<uint64_t> seen;
  auto add = [&](int32_t x, int32_t y, int pass)
  {
    const bool throughP = x == p || y == p;
    if ((pass == 0) != throughP || bc.isEdge(x, y))
      return;
    const uint64_t k = edgeKey(x, y);
    if (std::find(seen.begin(), seen.end(), k) != seen.end())
      return;
    seen.push_back(k);
    out.push_back({ x, y });
  };
  static const int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
  for (int pass = 0; pass < 2; ++pass)
    for (int32_t t : star)
      for (auto& e : kEdge)
        add(ed.mesh.vertex(t, e[0]), ed.mesh.vertex(t, e[1]), pass);
  for (int32_t t : layer)
    for (auto& e : kEdge)
      add(ed.mesh.vertex(t, e[0]), ed.mesh.vertex(t, e[1]), 1);
}

bool removeEdgeKeepingRegion(MeshEditor& ed, const BoundaryConstraints& bc, int32_t x, int32_t y,
                             std::vector<int32_t>* tetRegion)
{
  const int32_t t = ed.findEdge(x, y);
  if (t < 0)
    return false;
  const int32_t region =
    tetRegion && static_cast<size_t>(t) < tetRegion->size() ? (*tetRegion)[static_cast<size_t>(t)] : -1;
  std::vector<int32_t> created;
  if (!ed.removeEdge(t, x, y, &bc, &created))
    return false;
  if (tetRegion)
  {
    if (tetRegion->size() < static_cast<size_t>(ed.mesh.tetCapacity()))
      tetRegion->resize(static_cast<size_t>(ed.mesh.tetCapacity()), -1);
    for (int32_t id : ed.lastRemovedIds)
      if (ed.mesh.isFree(id))
        (*tetRegion)[static_cast<size_t>(id)] = -1;
    for (int32_t c : created)
      (*tetRegion)[static_cast<size_t>(c)] = region;
  }
  return true;
}

} // namespace volgrid
