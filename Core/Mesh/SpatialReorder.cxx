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

// New tet slots: the live tets in Hilbert order of their centroids (ties by old slot), free slots -1.
std::vector<int32_t> tetOrder(const TetMesh& mesh)
{
  std::vector<double> centroids;
  std::vector<int32_t> live, ids;
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      for (int k = 0; k < 3; ++k)
        centroids.push_back((mesh.point(v[0])[k] + mesh.point(v[1])[k] + mesh.point(v[2])[k] + mesh.point(v[3])[k]) /
                            4);
      ids.push_back(static_cast<int32_t>(live.size()));
      live.push_back(t);
    });
  hilbertSort(centroids.data(), ids); // stable: ties keep the old order
  std::vector<int32_t> oldToNew(static_cast<size_t>(mesh.tetCapacity()), -1);
  for (size_t k = 0; k < ids.size(); ++k)
    oldToNew[static_cast<size_t>(live[static_cast<size_t>(ids[k])])] = static_cast<int32_t>(k);
  return oldToNew;
}
} // namespace

SpatialRenumbering reorderSpatially(TetMesh& mesh, int32_t firstVertex)
{
  SpatialRenumbering r;
  if (mesh.numGhostTets() > 0 || mesh.numTets() == 0)
    return r;
  r.vertexOldToNew = vertexOrder(mesh, firstVertex);
  r.tetOldToNew = tetOrder(mesh);
  std::vector<double> points(mesh.points.size());
  for (size_t v = 0; v < r.vertexOldToNew.size(); ++v)
    std::copy_n(mesh.points.data() + 3 * v, 3, points.data() + 3 * static_cast<size_t>(r.vertexOldToNew[v]));
  TetMesh out;
  out.points.swap(points);
  const int32_t live = mesh.numTets();
  out.appendTets(live);
  for (int32_t t = 0; t < mesh.tetCapacity(); ++t)
  {
    const int32_t n = r.tetOldToNew[static_cast<size_t>(t)];
    if (n < 0)
      continue;
    const int32_t* v = mesh.vertices(t);
    out.setTetVertices(n, r.vertexOldToNew[v[0]], r.vertexOldToNew[v[1]], r.vertexOldToNew[v[2]],
                       r.vertexOldToNew[v[3]]);
    for (int i = 0; i < 4; ++i)
    {
      const int32_t c = mesh.neighborCode(t, i);
      out.tetNeighbors[4 * static_cast<size_t>(n) + i] =
        c < 0 ? TetMesh::kNoNeighbor : TetMesh::encode(r.tetOldToNew[static_cast<size_t>(c >> 2)], c & 3);
    }
    out.tetFlags[static_cast<size_t>(n)] = mesh.tetFlags[static_cast<size_t>(t)];
  }
  mesh = std::move(out);
  return r;
}

} // namespace volgrid
