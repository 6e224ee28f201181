// Facet recovery by cavity retetrahedralization (Si & Gaertner 2005; TetGen's formcavity /
// delaunizecavity / fillcavity), used by BoundaryRecovery.h once the segments are present.
//
// The region R is one input triangle (corners A, B, C) whose sides may carry segment Steiner points;
// every subsegment of its sides must be a mesh edge and no mesh vertex may lie in R's interior. Then:
//   1. Cavity: the tets whose interior meets the open triangle R, plus the tets having a face inside R
//      (so that the whole of R is re-triangulated). Because R's boundary consists of mesh edges, each
//      such tet meets the plane of R inside R, and every outer face of the cavity lies in one closed
//      half-space of that plane: the faces split into an upper and a lower cavity boundary, whose
//      vertices are strictly above (below) the plane or on R's boundary.
//   2. Each side is tetrahedralized by the Delaunay tetrahedralization of its vertices; the tets inside
//      are found by a flood fill from the boundary faces that never crosses a boundary face nor a face
//      lying in R. A boundary face missing from the Delaunay tetrahedralization makes the cavity grow
//      by the tet outside that face (never across a constraint subface), and the side is redone.
//   3. Both sides must produce the same triangulation T of R, whose border must be exactly R's
//      subsegments; the two fills then replace the cavity (MeshEditor::replace checks the gluing) and
//      T becomes the subfaces of the input triangle.
// Every decision is an exact predicate; on any failure the mesh and the constraints are untouched.
#pragma once

#include "BoundaryRecovery.h"
#include "CavityDelaunay.h" // fillCavityDelaunay, used with the facet cavities

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

struct FacetCavityStats
{
  uint64_t attempts = 0, successes = 0, enlargements = 0;
};

// Recover input triangle `parent` (its live subfaces listed in `subfaces`) by cavity
// retetrahedralization. On success the listed subfaces are replaced in `bc` by the new triangulation
// (their ids are written back to `subfaces`) and true is returned.
bool recoverFacetByCavity(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                          FacetCavityStats* stats = nullptr);

// Recover one subface (its three edges present) as its own triangle R = the subface: the same cavity
// method, independent of whether its sibling subfaces are coplanar with it (segment Steiner points are
// rounded, so the pieces of a split input triangle generally are not). Every other constraint is kept.
bool recoverSubfaceByCavity(MeshEditor& ed, BoundaryConstraints& bc, int32_t subface,
                            FacetCavityStats* stats = nullptr);

// Recover input triangle `parent` whose split polygon is not planar (rounded segment Steiner points) when
// neither the whole-triangle cavity nor the pieces work: the cavity method with R's border vertices counted
// as on R. Each side then triangulates R on its own; the thin slab between the two triangulations (all its
// vertices on R's border) is filled by fillCavityDelaunay and the upper triangulation becomes the subfaces.
// A side that is reflex at a rounded point (its Delaunay tetrahedralization lacks a boundary face) is
// repaired by flips of that local tetrahedralization, or filled as the cone of its faces and R's current
// subfaces from a vertex that sees them all, before its cavity is grown.
bool recoverFacetBySlab(MeshEditor& ed, BoundaryConstraints& bc, int32_t parent, std::vector<int32_t>& subfaces,
                        FacetCavityStats* stats = nullptr);

} // namespace volgrid
