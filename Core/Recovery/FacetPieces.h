// Facet recovery piece by piece (FacetPieces.cxx): boundary recovery's second way to make an input
// triangle a union of mesh faces, when its cavity retetrahedralization (FacetRecovery.h) fails.
#pragma once

#include "FacetRecovery.h"

namespace volgrid
{

// Recover input triangle `parent` piece by piece (FacetPieces.cxx), when recoverFacetByCavity fails: its
// region (the polygon bounded by its subsegments) is re-triangulated, preferring diagonals that are
// already mesh edges (dynamic programming over the polygon; no triangle spans three points of one side),
// the listed subfaces are replaced by that triangulation in `bc`, and each missing piece whose edges
// are present is recovered by recoverSubfaceByCavity. Regions with inner vertices keep their subfaces.
// True when every piece is a mesh face; the new subfaces are written back to `subfaces` in any case.
bool recoverFacetByPieces(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                          FacetCavityStats* stats = nullptr);

} // namespace volgrid
