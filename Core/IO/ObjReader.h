// Wavefront OBJ, `g` groups as named patches.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

// Wavefront OBJ (ObjReader.cxx): strict numbers, every bad face reference counted and the first named.
Status readOBJ(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
               const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
