// For each boundary triangle (and quad) of a SolverMesh, the cell that owns it and which of the cell's
// faces it is: what formats that store boundary faces as (element, side) pairs need (Exodus II side sets),
// and what VTK grids carry as the cell array BoundaryFacePatch.
#pragma once

#include "SolverMesh.h"
#include "Status.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

// Side f + 1 of an Exodus II tet: the local vertices of that face, outward for a positive tet.
extern const int kExodusTetSide[4][3];

struct FaceOwner
{
  int64_t tet = -1; // index into mesh.tets
  int side = -1;    // 0..3, a row of kExodusTetSide
};

// One owner per triangle of `triangles` (3 ids each) among `tets` (4 ids each). Fails naming the first
// triangles that are not a face of any tet (their owner stays tet -1).
Status findBoundaryFaceOwners(const std::vector<int32_t>& tets, const std::vector<int32_t>& triangles,
                              std::vector<FaceOwner>& owners);
Status findBoundaryFaceOwners(const SolverMesh& mesh, std::vector<FaceOwner>& owners);

// Side f + 1 of an Exodus II wedge in SolverMesh's order, outward (a triangle's fourth entry is -1).
extern const int kExodusWedgeSide[5][4];
// And of an Exodus II pyramid (quad 1-4 turning towards the apex 5).
extern const int kExodusPyramidSide[5][4];

// A boundary face's owner among all the cells: tets first, then prisms, then pyramids (prism w is cell
// numberOfTets + w), and its 0-based Exodus side (a row of kExodusTetSide, kExodusWedgeSide or
// kExodusPyramidSide).
struct CellSide
{
  int64_t cell = -1;
  int side = -1;
};

// One owner per boundary triangle, then one per quad (after them): tet faces by findBoundaryFaceOwners,
// the rest among the prisms' and pyramids' faces. Fails naming the first face that is none of these.
Status findBoundaryCellSides(const SolverMesh& mesh, std::vector<CellSide>& owners);

} // namespace volgrid
