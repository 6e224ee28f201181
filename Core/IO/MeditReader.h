// Medit .mesh surfaces (ASCII): triangles and quadrilaterals, references as patch ids.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

Status readMedit(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
                 const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
