// PLY surfaces, ASCII or binary, faces and triangle strips.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

// PLY, ASCII or binary, with faces and triangle strips (PlyReader.cxx).
Status readPLY(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
               const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
