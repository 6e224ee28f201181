// gmsh .msh surfaces (ASCII, versions 2.x and 4.x), $PhysicalNames as patch names.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

Status readGmsh(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
                const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
