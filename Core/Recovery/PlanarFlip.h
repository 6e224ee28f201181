// A 2D edge flip inside a flat part of the boundary, done in 3D (PlanarFlip.cxx); boundary recovery's
// way past an edge that crosses a missing segment in a common plane.
#pragma once

#include "MeshEditor.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

// Replaces edge xy (in tet t) by pq, where p and q are ring vertices coplanar with x and y (a 2D flip
// inside a flat face); each side of the plane is re-filled on its own (PlanarFlip.cxx). With `kinds`,
// a side no cone or Delaunay fill can do gets an interior Steiner point (appended to kinds).
bool flipInPlane(MeshEditor& editor, int32_t t, int32_t x, int32_t y, int32_t p, int32_t q,
                 const BoundaryConstraints* bc, std::vector<int32_t>* created = nullptr,
                 std::vector<VertexKind>* kinds = nullptr);

} // namespace volgrid
