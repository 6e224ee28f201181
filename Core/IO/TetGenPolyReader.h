// TetGen .poly and .smesh piecewise linear complexes, facets with holes triangulated.
// Called by readSurface (SurfaceReader.h), which chooses the reader by extension.
#pragma once

#include "SurfaceReader.h"

namespace volgrid
{

// .poly and .smesh (chosen by extension).
Status readTetGen(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* info = nullptr,
                  const SurfaceReadOptions& options = SurfaceReadOptions());

} // namespace volgrid
