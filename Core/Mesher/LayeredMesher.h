// Boundary layers plus tets: prisms grown from the wall patches (Layers/BoundaryLayers.h), and the
// conforming mesher (Mesher.h) on the region between the last layer's surface and the other patches.
// The mesher keeps that surface exactly, so prisms and tets share their faces and points exactly.
#pragma once

#include "BoundaryLayers.h"
#include "LayerTransition.h"
#include "Mesher.h"
#include "PatchNames.h"
#include "SolverMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct LayeredMeshResult
{
  std::vector<double> points;     // the merged input surface's points first, then the layers', then the tets'
  std::vector<int32_t> tets;      // 4 per tet, positively oriented (split prisms included)
  std::vector<int32_t> tetRegion; // region label (split prisms: 0)
  std::vector<int32_t> tetLayer;  // -1 for the tet region, the layer index for a layer tet or split prism
  std::vector<uint8_t> tetReason; // ThinnedReason of a split prism's column, 0 for the tet region
  std::vector<int32_t> wedges;    // 6 per prism: base a,b,c (normal towards the top), top a',b',c'
  std::vector<int32_t> wedgeLayer;
  std::vector<uint8_t> wedgeReason;
  std::vector<int32_t> pyramids; // 5 per pyramid over collapsed columns: quad, apex (orient3d(q0,q1,q2,apex) > 0)
  std::vector<int32_t> pyramidLayer;
  std::vector<uint8_t> pyramidReason;
  std::vector<int32_t> wallTriangles; // the layered input triangles, 3 each (also in boundaryTriangles)
  // The domain's boundary: walls, the other patches, and with split prisms the prisms' side quads on
  // symmetry planes (each as two triangles cut through its smallest id, as the split prisms' faces are).
  std::vector<int32_t> boundaryTriangles;
  std::vector<int32_t> boundaryPatch;
  std::vector<int32_t> sideQuads; // the prisms' side faces on symmetry planes, 4 each (boundary faces)
  std::vector<int32_t> sidePatch;
  NameTable patchNames;
  std::vector<int32_t> interfaceTriangles; // the last layer's outer surface, 3 each
  int64_t interfaceOnTets = 0;             // of those, how many are faces of the tet region's boundary
  int64_t tetBoundaryOnInterface = 0;      // tet-region boundary triangles of the interface patch
  LayerTransition transition;              // the size step from the last layer to the tets (LayerTransition.h)
  LayerStatistics layerStats;
  MesherStatistics mesherStats;
  std::vector<std::string> warnings;
  double seconds = 0;
};

// The result as the solver formats take it: tets, prisms and pyramids (the layers' region 0), the boundary
// triangles and, unless the prisms were split, the prisms' side quads on symmetry planes.
SolverMesh layeredSolverMesh(const LayeredMeshResult& result);

// Grows the layers and meshes the rest. Without layers (options.layers == 0) this is an error: call
// meshSurface. On failure the result is empty and the Status says which stage failed and why.
Status meshSurfaceWithLayers(const SurfaceMesh& surface, const MesherOptions& mesherOptions,
                             const LayerOptions& layerOptions, LayeredMeshResult& result, Progress* progress = nullptr);

} // namespace volgrid
