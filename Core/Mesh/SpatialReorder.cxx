#include "SpatialReorder.h"

#include "ParallelFor.h"
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

constexpr int64_t kMinPerThread = 1 << 16;

// New tet slots: the live tets by the new number of their highest vertex (ties by old slot), free slots
// -1. The vertices from firstVertex on are in Hilbert order and every tet but those spanned by earlier
// vertices has its highest vertex among them, so the tets follow the curve too. The keys are vertex
// numbers: a counting sort (tets per key, then the slots in order) gives the order of the sorted
// (key, slot) pairs in linear time, at 4 bytes per slot and per vertex of scratch.
std::vector<int32_t> tetOrder(const TetMesh& mesh, const std::vector<int32_t>& vertexOldToNew, int threads)
{
  const int64_t slots = mesh.tetCapacity();
  std::vector<int32_t> oldToNew(static_cast<size_t>(slots), -1); // the key first, then the new slot
  parallelFor(threads, slots, kMinPerThread,
              [&](int, int64_t begin, int64_t end)
              {
                for (int64_t t = begin; t < end; ++t)
                {
                  if (mesh.isFree(static_cast<int32_t>(t)))
                    continue;
                  const int32_t* v = mesh.vertices(static_cast<int32_t>(t));
                  oldToNew[static_cast<size_t>(t)] = std::max(std::max(vertexOldToNew[v[0]], vertexOldToNew[v[1]]),
                                                              std::max(vertexOldToNew[v[2]], vertexOldToNew[v[3]]));
                }
              });
  std::vector<int32_t> next(vertexOldToNew.size() + 1, 0); // per key: the first new slot of its tets
  for (const int32_t key : oldToNew)
    if (key >= 0)
      ++next[static_cast<size_t>(key) + 1];
  std::partial_sum(next.begin(), next.end(), next.begin());
  for (int32_t& n : oldToNew)
    if (n >= 0)
      n = next[static_cast<size_t>(n)]++;
  return oldToNew;
}

// The new vertex numbers, applied one array at a time (the extra memory is one array, not a second mesh),
// each on the threads: the points move and the tets take the new numbers in place. The mesh is valid
// afterwards (the same tets in the same slots, its vertices renumbered).
void renumberVertices(TetMesh& mesh, const SpatialRenumbering& r, int threads)
{
  std::vector<double> points(mesh.points.size());
  parallelFor(threads, static_cast<int64_t>(r.vertexOldToNew.size()), kMinPerThread,
              [&](int, int64_t begin, int64_t end)
              {
                for (int64_t v = begin; v < end; ++v)
                  std::copy_n(mesh.points.data() + 3 * v, 3,
                              points.data() + 3 * static_cast<size_t>(r.vertexOldToNew[static_cast<size_t>(v)]));
              });
  mesh.points.swap(points);
  std::vector<double>().swap(points);
  parallelFor(threads, mesh.tetCapacity(), kMinPerThread,
              [&](int, int64_t begin, int64_t end)
              {
                for (int64_t t = begin; t < end; ++t)
                  if (r.tetOldToNew[static_cast<size_t>(t)] >= 0)
                    for (int i = 0; i < 4; ++i)
                    {
                      int32_t& v = mesh.tetVertices[4 * static_cast<size_t>(t) + i];
                      v = r.vertexOldToNew[static_cast<size_t>(v)];
                    }
              });
}

// The new tet slots, one array at a time as above: every live slot's entries go to its own new place.
void moveTets(TetMesh& mesh, const SpatialRenumbering& r, int threads)
{
  const size_t live = static_cast<size_t>(mesh.numTets());
  const int64_t slots = mesh.tetCapacity();
  // body(t, n) for each live slot t and its new slot n = tetOldToNew[t] (a template: no call through a
  // std::function per slot).
  auto overLiveSlots = [&](const auto& body)
  {
    parallelFor(threads, slots, kMinPerThread,
                [&](int, int64_t begin, int64_t end)
                {
                  for (int64_t t = begin; t < end; ++t)
                    if (r.tetOldToNew[static_cast<size_t>(t)] >= 0)
                      body(static_cast<size_t>(t), static_cast<size_t>(r.tetOldToNew[static_cast<size_t>(t)]));
                });
  };
  std::vector<int32_t> words(4 * live);
  overLiveSlots([&](size_t t, size_t n) { std::copy_n(mesh.tetVertices.data() + 4 * t, 4, words.data() + 4 * n); });
  mesh.tetVertices.swap(words);
  words.assign(4 * live, TetMesh::kNoNeighbor);
  overLiveSlots(
    [&](size_t t, size_t n)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int32_t c = mesh.tetNeighbors[4 * t + i];
        if (c >= 0)
          words[4 * n + i] = TetMesh::encode(r.tetOldToNew[static_cast<size_t>(c >> 2)], c & 3);
      }
    });
  mesh.tetNeighbors.swap(words);
  std::vector<uint8_t> flags(live);
  overLiveSlots([&](size_t t, size_t n) { flags[n] = mesh.tetFlags[t]; });
  mesh.tetFlags.swap(flags);
}
} // namespace

SpatialRenumbering reorderSpatially(TetMesh& mesh, int32_t firstVertex, int threads, Progress* progress)
{
  SpatialRenumbering r;
  if (mesh.numGhostTets() > 0 || mesh.numTets() == 0)
    return r;
  auto stop = [&] { return progress && progress->cancelled(); };
  r.vertexOldToNew = vertexOrder(mesh, firstVertex);
  if (stop())
    return SpatialRenumbering();
  r.tetOldToNew = tetOrder(mesh, r.vertexOldToNew, threads);
  if (stop())
    return SpatialRenumbering();
  renumberVertices(mesh, r, threads);
  if (stop()) // valid, with its vertices renumbered: the caller, asking again, stops too
    return SpatialRenumbering();
  moveTets(mesh, r, threads);
  mesh.restoreBookkeeping({ -1, 0, 0 }); // compact: no free slot, no ghost
  return r;
}

} // namespace volgrid
