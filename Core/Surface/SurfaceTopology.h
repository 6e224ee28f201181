// Edge topology of a triangle surface, from its point ids: each edge's valence and orientation
// (boundary, non-manifold, inconsistently oriented), boundary loops, non-manifold vertices, and shells
// (edge-connected triangle sets) with their closedness, consistency, signed volume and bounds. A step
// of checkSurface (SurfaceChecks.h). Internal to Core.
#pragma once

#include "SurfaceChecks.h"

#include <cstdint>
#include <vector>

namespace volgrid::detail
{

// Appends id to a list of a report's first ids while the list holds fewer than maxIds.
inline void keepFirstId(std::vector<int32_t>& ids, int32_t id, int maxIds)
{
  if (static_cast<int>(ids.size()) < maxIds)
  {
    ids.push_back(id);
  }
}

// Fills the edge arrays, boundary edges and loops, non-manifold edges and vertices, inconsistent edges,
// shells and triangleShell of `r`, with the matching triangle flags and first ids. Triangles with
// valid[t] == 0 (point ids out of range) and triangles that repeat a point id have no edges and belong
// to no shell. Returns the triangles of each shell, in increasing order.
std::vector<std::vector<int32_t>> checkEdgeTopology(const SurfaceMesh& mesh, const std::vector<char>& valid, int maxIds,
                                                    SurfaceCheckReport& r);

} // namespace volgrid::detail
