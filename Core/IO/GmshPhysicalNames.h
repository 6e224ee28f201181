// The $PhysicalNames section of a gmsh file (2.2 and 4.1), read by the surface and the volume mesh
// readers alike: the count, then one "dim tag \"name\"" line per group (the quotes removed).
#pragma once

#include "Status.h"
#include "SurfaceReaderSupport.h"

#include <cstdint>
#include <functional>
#include <string>

namespace volgrid::detail
{
// Calls `add(dim, tag, name)` for every line; stops at the first bad one. The caller reads the
// closing $EndPhysicalNames.
Status readGmshPhysicalNames(Scanner& sc, const std::function<void(int64_t dim, int64_t tag, std::string name)>& add);
} // namespace volgrid::detail
