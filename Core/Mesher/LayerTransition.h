// How the cell size changes where the tets meet the last layer. The tets over the layers' outer surface
// are as large as its triangles (the conforming mesher sizes them by the surface's spacing, and a tet much
// flatter than its base triangle would be a sliver), so the last layer's thickness decides the jump: layers
// far thinner than the wall's triangles leave a step that the solver sees as a sudden change of cell
// size. Measured per interface triangle as the tet's height over it (3 V / area) over the height of the
// layer cell under it; reported with a warning when the median is far from 1, so that the user can choose
// more layers, a larger growth or a total thickness near the wall's spacing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct LayeredMeshResult;

struct LayerTransition
{
  int64_t faces = 0; // interface triangles with a tet above and a full layer cell below
  double medianRatio = 0, p90Ratio = 0, maxRatio = 0, minRatio = 0;
};

// Over the interface triangles of `result` (prisms, or split prisms, of the last layer below; columns that
// collapsed there have no layer cell under the interface and are left out).
LayerTransition measureLayerTransition(const LayeredMeshResult& result, int layers);

// A warning when the median ratio is above `limit` or under 1 / limit; else empty.
std::string layerTransitionWarning(const LayerTransition& transition, double limit = 4.0);

} // namespace volgrid
