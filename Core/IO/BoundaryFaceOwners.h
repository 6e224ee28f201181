// For each boundary triangle of a SolverMesh, the tet that owns it and which of the tet's faces it is:
// what formats that store boundary faces as (element, side) pairs need (Exodus II side sets).
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

} // namespace volgrid
