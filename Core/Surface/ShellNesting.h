// Which closed shell contains which: a vertex of each closed shell is located against every other
// closed shell whose box contains it, with the exact ray-parity test pointInClosedSurface (declared in
// SurfaceChecks.h, defined in ShellNesting.cxx). Internal to Core.
#pragma once

#include "SurfaceChecks.h"

#include <cstdint>
#include <vector>

namespace volgrid::detail
{

// Sets depth (number of closed shells containing the shell) and parent (the innermost one) of every
// shell of `report`; shellTriangles lists each shell's triangles. Open shells contain nothing and
// are located in nothing.
void nestShells(const SurfaceMesh& mesh, const std::vector<std::vector<int32_t>>& shellTriangles,
                SurfaceCheckReport& report);

} // namespace volgrid::detail
