// How deep a domain is at its boundary points: from a boundary vertex of a ghost-free tet mesh of the
// domain, the distance along its inward direction (against the area-weighted normals of its boundary faces)
// to where that ray leaves the domain. A measurement for size decisions (CoarseBoundaryFloor.h: how far
// a coarse boundary's spacing may reach in), not topology: plain floating point, and 0 wherever the walk
// cannot say (the caller then assumes the least room).
#pragma once

#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

// One value per vertex v < count (0 for a vertex in no tet). mesh: ghost-free; the walk crosses faces
// with a neighbour and stops at the first face without one.
std::vector<double> inwardThickness(const TetMesh& mesh, int32_t count);

} // namespace volgrid
