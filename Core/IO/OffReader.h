// Object File Format (.off and its variants), polygons triangulated.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

Status readOFF(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
               const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
