// volgrid mesh --layers: boundary-layer prisms on the wall patches plus tets (Core/Mesher/LayeredMesher.h),
// written as one mixed mesh (VTK_WEDGE, VTK_PYRAMID where a column collapsed, VTK_TETRA; cell arrays
// LayerIndex, ThinnedReason, Region).
#pragma once

#include "BoundaryLayers.h"
#include "MeshExport.h"
#include "Mesher.h"
#include "SurfaceMesh.h"

#include <string>

namespace volgrid
{
namespace cli
{
// Parses one layer option at argv[i] (advancing i past its value); returns 1 when taken, 0 when argv[i]
// is not a layer option, -1 on a bad value (message printed).
int parseLayerOption(int argc, char** argv, int& i, LayerOptions& options);

extern const std::string kLayerUsage; // usage text, numbers from OptionTable.h

// Meshes with layers and writes OUT (.vtu/.vtk; solver formats need splitPrisms). Returns the exit code.
int runLayeredMesh(const SurfaceMesh& surface, const std::string& surfaceName, const std::string& out,
                   MeshFormat format, bool vtkOutput, const ExportRequest& request, const MesherOptions& options,
                   const LayerOptions& layers, bool json);
} // namespace cli
} // namespace volgrid
