// STL, ASCII (one patch per solid) or binary.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

Status readSTL(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
               const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
