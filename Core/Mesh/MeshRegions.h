// What threads that edit a mesh one region of space each share (FieldPointRegions.h, RegionFlips.h): the
// boxes (RegionBoxes.h) cut from the centroids of the tets to work on, each vertex's box, each tet's
// region (the box of all four of its vertices, else none), and the tet slots each region may fill.
//
// Why regions may run at once: a region's thread removes only tets whose four vertices are the region's
// (TetEditor::RegionLimit), and two such tets of different regions never share a face (it would have three
// vertices in both). So each cavity's outer neighbours are its region's tets or tets no thread removes, and
// what a region does depends on nothing another one does: any thread count gives the same mesh.
#pragma once

#include "RegionBoxes.h"
#include "TetMesh.h"
#include "TetSlotPool.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

constexpr uint8_t kSpansRegions = 255; // a tet whose vertices lie in two or more boxes

// How many regions a job of `tets` tets is cut into: the largest power of two up to maxRegions that leaves
// each region at least perRegion tets, or 1. It depends on the job alone, never on the thread count.
int regionCountFor(int64_t tets, int64_t perRegion, int maxRegions);
// The centroid of tet t into c[0..2].
void tetCentroid(const TetMesh& mesh, int32_t t, double* c);
// The boxes of `regions` (a power of two), from the centroids of (a sample of at most about 65,536 of) tets.
RegionBoxes boxesOfTets(const TetMesh& mesh, const std::vector<int32_t>& tets, int regions);
// The box of each vertex of the mesh, on `threads` (ParallelFor.h's rule).
std::vector<uint8_t> vertexRegions(const TetMesh& mesh, const RegionBoxes& boxes, int threads);
// Tet t's region: its vertices' common box, or kSpansRegions.
inline uint8_t tetRegionOf(const TetMesh& mesh, const std::vector<uint8_t>& vertexRegion, int32_t t)
{
  const int32_t* v = mesh.vertices(t);
  const uint8_t r = vertexRegion[static_cast<size_t>(v[0])];
  for (int i = 1; i < 4; ++i)
    if (vertexRegion[static_cast<size_t>(v[i])] != r)
      return kSpansRegions;
  return r;
}
// pools[i] gets wants[i] slots before the threads start: the mesh's free slots first, in slot order (so
// that each region writes its own stretch of the arrays), then appended ones. The free slots no pool takes
// go back to the mesh's free list, the lowest first in line. After the threads, each pool's returnAll().
void fillSlotPools(TetMesh& mesh, const std::vector<TetSlotPool*>& pools, const std::vector<size_t>& wants);

} // namespace volgrid
