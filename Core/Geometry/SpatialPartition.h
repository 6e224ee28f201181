// Cuts a set of points (e.g. tet centroids) into spatially compact parts of near-equal size, to hand a mesh
// made on one process out to several: recursive coordinate bisection along the longest extent.
#pragma once

#include <cstdint>
#include <vector>

namespace volgrid
{

// part[i] in [0, parts) for each of the n points xyz[3i..3i+2]. Part sizes differ by at most one per
// bisection level; the result depends only on the points and `parts` (deterministic). parts < 1 is taken
// as 1.
std::vector<int32_t> bisectionPartition(const double* xyz, int64_t n, int parts);

} // namespace volgrid
