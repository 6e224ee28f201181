// Renumbering of a tet mesh along the Hilbert curve, so that vertices and tets close in space are close
// in memory.
//
// Why: the quality stage runs after many thousands of point insertions, whose new vertices and recycled
// tet slots are scattered through the arrays. Every sweep and every local edit then reads points and
// tets from all over memory (at 1M tets a sweep took about 190 ns per tet, nearly all of it cache misses).
// One renumbering before the stage makes sweeps and stars read mostly consecutive memory.
//
// The vertices from `firstVertex` on are renumbered in Hilbert order of their points (those before keep
// their numbers: input points, boundary Steiner points, anything the caller refers to by number). The live
// tets are renumbered by their highest new vertex number, so they follow the curve too (free slots
// dropped, so the mesh is compact). The arrays are rewritten one at a time: the extra memory at the peak
// is one array, not a second mesh.
// The mesh is the same (same points, same tets with the same vertex order, same adjacency): only the
// numbers change. Deterministic (no randomness, ties by old number), the same for any thread count
// (`threads`: the rule of ParallelFor.h).
#pragma once

#include "Progress.h"
#include "TetMesh.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace volgrid
{

struct SpatialRenumbering
{
  std::vector<int32_t> vertexOldToNew; // per old vertex: its new number
  std::vector<int32_t> tetOldToNew;    // per old tet slot: its new slot, -1 for a free slot
};

// Renumbers mesh (see above); the returned maps let the caller carry per-vertex and per-tet arrays over.
// A mesh with ghost tets is left as it is (empty maps). progress (optional) is asked between the four
// steps (each about a tenth of a second at 5M tets); when it says stop, the maps are empty and the mesh is
// valid: as it was, or with its vertices renumbered after the third (the caller, asking again, stops
// without carrying arrays over).
SpatialRenumbering reorderSpatially(TetMesh& mesh, int32_t firstVertex, int threads = 1, Progress* progress = nullptr);

// Carries a per-tet-slot array over (entries of free slots dropped, the array sized to the new slots).
template<typename T>
void renumberTetArray(const SpatialRenumbering& r, std::vector<T>& perTet, const T& fill)
{
  int32_t slots = 0;
  for (int32_t n : r.tetOldToNew)
    slots += n >= 0;
  std::vector<T> out(static_cast<size_t>(slots), fill);
  for (size_t t = 0; t < r.tetOldToNew.size() && t < perTet.size(); ++t)
    if (r.tetOldToNew[t] >= 0)
      out[static_cast<size_t>(r.tetOldToNew[t])] = perTet[t];
  perTet.swap(out);
}

// Carries a per-vertex array over (sized to cover every vertex it had an entry for; new entries `fill`).
template<typename T>
void renumberVertexArray(const SpatialRenumbering& r, std::vector<T>& perVertex, const T& fill)
{
  if (perVertex.empty() || r.vertexOldToNew.empty())
    return;
  std::vector<T> out(std::max(perVertex.size(), r.vertexOldToNew.size()), fill);
  for (size_t v = 0; v < perVertex.size(); ++v)
    out[v < r.vertexOldToNew.size() ? static_cast<size_t>(r.vertexOldToNew[v]) : v] = perVertex[v];
  perVertex.swap(out);
}

} // namespace volgrid
