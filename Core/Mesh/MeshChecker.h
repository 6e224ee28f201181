// Validity checker for TetMesh, used by the tests and the CLI. Exact: it uses the same predicates as the
// mesher. Works with or without ghost tets (see TetMesh.h).
//
// Checked:
//  - vertices: ids in range, four distinct ids per tet, at most one kGhostVertex (ghost tets);
//  - orientation: every finite tet has orient3d > 0;
//  - adjacency: neighbour codes in range and pointing to live tets, symmetric (the neighbour points back
//    with the same face), and the shared face has the same three vertices in opposite orientation;
//  - hull: with ghosts, every ghost has its hull face against a finite tet and no face lacks a
//    neighbour; without ghosts, the faces without neighbour form a closed, consistently oriented
//    2-manifold (every directed edge once, its reverse once). The hull surface has Euler characteristic 2;
//  - Delaunay (optional): for every face between two finite tets, the opposite vertex of one is not in
//    conflict with the other (insphereSoS < 0: the same SoS rule as the mesher, so local Delaunay, which
//    implies the global empty-circumsphere property). With ghosts, hull edges must be convex (no hull
//    vertex strictly outside another hull face's plane; coplanar hull faces use the mesher's rule);
//  - Euler (optional): V - E + F - T == 1 for the finite tets (a triangulated ball). Costs a sort of 6
//    edges per tet.
#pragma once

#include "TetMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct MeshCheckOptions
{
  bool delaunay = true;
  bool euler = true;
  size_t maxReported = 10; // how many offending tets to list
};

struct MeshCheckReport
{
  bool valid = true;
  // Violation counts.
  int64_t badVertices = 0;  // id out of range, repeated in a tet, two ghost vertices
  int64_t invertedTets = 0; // finite tets with orient3d <= 0
  int64_t badNeighbors = 0; // out of range or pointing at a free slot
  int64_t asymmetricNeighbors = 0;
  int64_t faceMismatches = 0; // neighbours whose shared face differs or has the same orientation
  int64_t openFaces = 0;      // faces without neighbour while ghosts are present
  int64_t hullErrors = 0;     // ghost hull faces not on finite tets, non-manifold/open hull edges
  int64_t nonDelaunayFaces = 0;
  int64_t nonConvexHullEdges = 0;
  bool eulerOk = true;
  // Sizes.
  int64_t finiteTets = 0, ghostTets = 0, hullFaces = 0, vertices = 0, edges = 0;
  std::vector<int32_t> firstBadTets; // first offending tets (any kind)

  std::string summary() const; // one line
};

MeshCheckReport checkMesh(const TetMesh& mesh, const MeshCheckOptions& options = MeshCheckOptions());

} // namespace volgrid
