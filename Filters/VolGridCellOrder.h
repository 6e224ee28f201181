// The point order of a boundary-layer prism in VTK and in Core, one conversion for every adapter.
// Core's prisms (Core/Mesh/SolverMesh.h) are in gmsh's order: base a,b,c whose normal points to the top
// a',b',c'. VTK_WEDGE lists each of its two triangles the other way round (its first triangle's normal points
// away from the second), so the conversion swaps points 1 and 2, and 4 and 5; the swap is its own inverse.
// Pyramids need none: Core's quad turns like a positive tet's base towards the apex, as VTK's pyramid base does.
#ifndef VolGridCellOrder_h
#define VolGridCellOrder_h

#include <array>

// Core's prism corner k is VTK's wedge corner kVolGridWedgeOrder[k], and the other way round.
constexpr int kVolGridWedgeOrder[6] = { 0, 2, 1, 3, 5, 4 };

// The six ids of a VTK_WEDGE (ids[0, 6)) in Core's prism order, as Out.
template<typename Out, typename In>
std::array<Out, 6> VolGridPrismFromWedge(const In* ids)
{
  std::array<Out, 6> prism;
  for (int k = 0; k < 6; ++k)
    prism[k] = static_cast<Out>(ids[kVolGridWedgeOrder[k]]);
  return prism;
}

// The six ids of a Core prism (ids[0, 6)) in VTK_WEDGE's order, as Out.
template<typename Out, typename In>
std::array<Out, 6> VolGridWedgeFromPrism(const In* ids)
{
  return VolGridPrismFromWedge<Out>(ids); // the same swap
}

#endif
