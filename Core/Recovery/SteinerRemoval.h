// Removal of the Steiner points that boundary recovery put on the boundary (paper 7.5, TetGen's -Y).
//
// A boundary Steiner point p lies on an input edge (between two input triangles) or inside an input
// triangle; the triangles around it are subfaces of those input triangles. To remove p:
//   1. the subfaces around p are replaced by a triangulation, without p, of the polygon they cover in
//      each input triangle (ear clipping with exact 2D orientation tests in the triangle's dominant
//      projection); when p was the last Steiner point of an input triangle that polygon is the input
//      triangle itself, so the final boundary is exactly the input;
//   2. the tets around p, split by the boundary into one side (after exterior removal) or two (an
//      interface kept on both sides), are replaced on each side by the cone from a relocated point p'
//      strictly inside that side's cavity (every cavity face sees p' strictly positively, checked with the
//      exact orient3d). Candidates: p pushed along the mean normal of the new boundary triangles, points
//      towards the cavity's centroid, and the Chebyshev centre of the cavity's kernel (a small linear
//      programme: the point deepest inside every face plane) with points between it and p. When the
//      kernel is empty (p in a reflex or flat corner), the cavity is enlarged by up to three layers of
//      outer tets (never across a constraint, never swallowing a vertex) and the search repeated.
//      Relocated points are new interior Steiner points (allowed, counted). When no point sees a layer's
//      cavity but one of its vertices sees every face not through it (p's star flat, between two
//      triangulations of a planar part of the boundary), the cone from that vertex fills it. Otherwise
//      the cavity is tetrahedralized without a point (FacetRecovery.h fillCavityDelaunay:
//      Delaunay tetrahedralization of its vertices, grown across the faces it lacks, never across a
//      constraint nor swallowing a vertex).
// Points that cannot be removed stay and are reported (the caller turns them into RecoveryFailed).
#pragma once

#include "BoundaryRecovery.h"
#include "Progress.h"
#include "Status.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

struct SteinerRemovalReport
{
  int64_t boundaryBefore = 0;          // boundary Steiner points present before
  int64_t removed = 0;                 // removed from the boundary (relocated inside)
  int64_t remaining = 0;               // could not be removed
  int64_t addedInterior = 0;           // extra interior points for the second side of a two-sided interface
  std::vector<int32_t> firstRemaining; // vertex ids
};

// tetRegion: per tet slot labels (kept in step with the new tets; may be null).
Status removeBoundarySteinerPoints(MeshEditor& editor, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
                                   std::vector<int32_t>* tetRegion, Progress* progress, SteinerRemovalReport* report);

} // namespace volgrid
