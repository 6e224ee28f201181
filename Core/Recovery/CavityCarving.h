// Tetrahedralization of a small cavity without new points by a bounded backtracking search.
//
// Used by Steiner removal (SteinerRemoval.h) when no point sees the cavity left by a boundary Steiner
// point, no cavity vertex does either (no cone), and the Delaunay tetrahedralization of the cavity's
// vertices does not conform to its faces (flat CAD parts, reflex corners).
//
// The front starts as the cavity's faces, each oriented with the part still to fill on its positive
// side. A step takes the front face with the fewest candidates and puts a tet on it whose apex is a
// cavity vertex strictly on its positive side (exact orient3d); each new face cancels its opposite in the
// front or joins it, and a face already in the front with the same orientation rejects the tet. When the
// front is empty the boundary of the tets equals the cavity's boundary as an oriented surface and every
// tet is positively oriented, so the tets cover each point of the cavity exactly once (the covering
// number equals the winding number of the boundary, 1 inside and 0 outside): a valid tetrahedralization,
// with no intersection test needed. The search stops after `maxSteps` tet placements.
#pragma once

#include "TetMesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace volgrid
{

// faces: the cavity's boundary, each seen positively from inside. edgeAllowed(u, v) is asked for every
// edge a tet would add that is not an edge of `faces`. True with `tets` (positively oriented) on success.
bool carveCavity(const TetMesh& mesh, const std::vector<std::array<int32_t, 3>>& faces,
                 const std::function<bool(int32_t, int32_t)>& edgeAllowed, int64_t maxSteps,
                 std::vector<std::array<int32_t, 4>>& tets);

} // namespace volgrid
