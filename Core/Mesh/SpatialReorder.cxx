#include "SpatialReorder.h"

#include "SpatialSort.h"

#include <algorithm>
#include <numeric>

namespace volgrid
{

namespace
{
// New vertex numbers: the identity below firstVertex, Hilbert order of the points from there on.
std::vector<int32_t> vertexOrder(const TetMesh& mesh, int32_t firstVertex)
{
  const int32_t nv = mesh.numVertices();
  std::vector<int32_t> oldToNew(static_cast<size_t>(nv));
  std::iota(oldToNew.begin(), oldToNew.end(), 0);
  std::vector<int32_t> ids;
  for (int32_t v = std::max(firstVertex, 0); v < nv; ++v)
    ids.push_back(v);
  hilbertSort(mesh.points.data(), ids);
  for (size_t k = 0; k < ids.size(); ++k)
    oldToNew[static_cast<size_t>(ids[k])] = std::max(firstVertex, 0) + static_cast<int32_t>(k);
  return oldToNew;
}

// New tet slots: the live tets by the new number of their highest vertex (ties by old slot), free slots
// -1. The vertices from firstVertex on are in Hilbert order and every tet but those spanned by earlier
// vertices has its highest vertex among them, so the tets follow the curve too, at 8 bytes per tet of
// scratch (centroids would cost 24).
std::vector<int32_t> tetOrder(const TetMesh& mesh, const std::vector<int32_t>& vertexOldToNew)
{
  std::vector<std::pair<int32_t, int32_t>> keyed; // (highest new vertex, old slot)
  keyed.reserve(static_cast<size_t>(mesh.numTets()));
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      keyed.emplace_back(std::max(std::max(vertexOldToNew[v[0]], vertexOldToNew[v[1]]),
                                  std::max(vertexOldToNew[v[2]], vertexOldToNew[v[3]])),
                         t);
    });
  std::sort(keyed.begin(), keyed.end());
  std::vector<int32_t> oldToNew(static_cast<size_t>(mesh.tetCapacity()), -1);
  for (size_t k = 0; k < keyed.size(); ++k)
    oldToNew[static_cast<size_t>(keyed[k].second)] = static_cast<int32_t>(k);
  return oldToNew;
}

// Applies the maps one array at a time (the extra memory is one array, not a second mesh).
void permute(TetMesh& mesh, const SpatialRenumbering& r)
{
  std::vector<double> points(mesh.points.size());
  for (size_t v = 0; v < r.vertexOldToNew.size(); ++v)
    std::copy_n(mesh.points.data() + 3 * v, 3, points.data() + 3 * static_cast<size_t>(r.vertexOldToNew[v]));
  mesh.points.swap(points);
  std::vector<double>().swap(points);
  const size_t live = static_cast<size_t>(mesh.numTets()), slots = static_cast<size_t>(mesh.tetCapacity());
  std::vector<int32_t> words(4 * live);
  for (size_t t = 0; t < slots; ++t)
    if (r.tetOldToNew[t] >= 0)
      for (int i = 0; i < 4; ++i)
        words[4 * static_cast<size_t>(r.tetOldToNew[t]) + i] = r.vertexOldToNew[mesh.tetVertices[4 * t + i]];
  mesh.tetVertices.swap(words);
  words.assign(4 * live, TetMesh::kNoNeighbor);
  for (size_t t = 0; t < slots; ++t)
    if (r.tetOldToNew[t] >= 0)
      for (int i = 0; i < 4; ++i)
      {
        const int32_t c = mesh.tetNeighbors[4 * t + i];
        if (c >= 0)
          words[4 * static_cast<size_t>(r.tetOldToNew[t]) + i] = TetMesh::encode(r.tetOldToNew[c >> 2], c & 3);
      }
  mesh.tetNeighbors.swap(words);
  std::vector<uint8_t> flags(live);
  for (size_t t = 0; t < slots; ++t)
    if (r.tetOldToNew[t] >= 0)
      flags[static_cast<size_t>(r.tetOldToNew[t])] = mesh.tetFlags[t];
  mesh.tetFlags.swap(flags);
}
} // namespace

SpatialRenumbering reorderSpatially(TetMesh& mesh, int32_t firstVertex)
{
  SpatialRenumbering r;
  if (mesh.numGhostTets() > 0 || mesh.numTets() == 0)
    return r;
  r.vertexOldToNew = vertexOrder(mesh, firstVertex);
  r.tetOldToNew = tetOrder(mesh, r.vertexOldToNew);
  permute(mesh, r);
  mesh.restoreBookkeeping({ -1, 0, 0 }); // compact: no free slot, no ghost
  return r;
}

} // namespace volgrid
