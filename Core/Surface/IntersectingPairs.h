// The self-intersection search of checkSurface: a bounding volume hierarchy over the triangles' boxes
// yields the candidate pairs whose boxes overlap, and the exact test (trianglesIntersect) keeps those
// that really intersect. Candidates are tested on worker threads. Internal to Core.
#pragma once

#include "SurfaceMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid::detail
{

// All pairs (t, u), t < u, of `candidates` (triangles with valid ids and non-zero area) that intersect
// beyond the corners they share, sorted. canon gives every point the id of the first point with the same
// coordinates, so triangles that touch at a duplicated point share that corner. threads as in
// SurfaceCheckOptions (0 = up to 2).
std::vector<std::pair<int32_t, int32_t>> findIntersectingPairs(const SurfaceMesh& mesh,
                                                               const std::vector<int32_t>& candidates,
                                                               const std::vector<int32_t>& canon, int threads);

} // namespace volgrid::detail
