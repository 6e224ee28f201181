// The mesh size from which the stages work in memory order rather than in priority or slot order: the
// quality stage renumbers the mesh in space (SpatialReorder.h), field point passes visit tets along the
// Hilbert curve, optimisation passes visit bad tets by slot and smooth in colour classes on all threads,
// and the quality stage is not run a second time from a copy (one run, with vertex collapses from the
// start). About 7 MB of tet arrays, past the caches of a typical core. Below it, meshes are made exactly
// as they were before these orders existed (on small meshes another order gives a different mesh, not a
// better or a faster one).
#pragma once

#include <cstdint>

namespace volgrid
{

inline constexpr int64_t kLargeMeshTets = 200000;

} // namespace volgrid
