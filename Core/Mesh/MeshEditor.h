// MeshEditor: local topological edits (flips, edge removal, vertex insertion) on a TetMesh without ghost
// tets, keeping the BoundaryConstraints.
#pragma once

#include "BoundaryConstraints.h"
#include "ConflictCavity.h"
#include "MeshNavigator.h"
#include "TetMesh.h"
#include "VertexKeys.h"

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

// Local topological edits on a TetMesh without ghost tets, with a vertex -> incident tet map.
// Every edit goes through replace(): old tets out, new (positively oriented) tets in, adjacency rebuilt
// from the old tets' outer faces. Used by recovery, Steiner insertion and Steiner removal.
// The vertex map, star, findEdge/findFace and stamps are MeshNavigator's (shared with TetEditor; a stale map
// entry is repaired by a rescan).
class MeshEditor : public MeshNavigator
{
public:
  explicit MeshEditor(TetMesh& mesh);
  // The ring around edge xy given a tet t containing it: ring vertices r_i and tets {x,y,r_i,r_i+1}
  // with orient3d(x,y,r_i,r_i+1) > 0. False when the ring is open (edge on the hull).
  bool edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets);

  // Replace oldTets by newTets (vertex quadruples, which must be positively oriented and fill the same
  // region): MeshNavigator::replaceTets. Returns false and leaves the mesh untouched when the faces do not match up.
  // With allowOpen, the region may change where it has no neighbour: unmatched new faces get no neighbour and outer
  // tets whose old face is gone lose that neighbour (used when the boundary moves, SteinerRemoval).
  bool replace(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
               std::vector<int32_t>* created = nullptr, bool allowOpen = false);

  // Flips. Each checks validity exactly and returns false (mesh untouched) when invalid or when it
  // would remove a constraint (a boundary subface / subface edge).
  bool flip23(int32_t t, int face, const BoundaryConstraints* bc, std::vector<int32_t>* created = nullptr);
  // Removes edge xy (contained in tet t): n-to-(2n-4) with the best valid ring triangulation.
  // chord: two ring vertices the ring triangulation must join (no other chord crosses theirs), or -1s.
  bool removeEdge(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc,
                  std::vector<int32_t>* created = nullptr, std::array<int32_t, 2> chord = { -1, -1 });

  // Inserts a new vertex v (coordinates already in mesh.points) with a Bowyer-Watson cavity grown from
  // the tets whose closure contains it, not crossing constraint faces (nor hull faces), made star-shaped
  // from v. start: a tet near v. Returns false (mesh untouched) when no valid cavity exists.
  bool insertVertex(int32_t v, int32_t start, const BoundaryConstraints* bc);

  // Locates a tet whose closure contains p by a visibility walk from `start`; -1 if it leaves the mesh.
  int32_t locate(const double* p, int32_t start);

  uint64_t flips23 = 0, flips32 = 0, flipsEdgeRemoval = 0;
  // Successful replace() calls: changes whenever the mesh does (BoundaryCensus::upToDate).
  uint64_t edits = 0;
  // Edge removals attempted (successful or not): the unit of recovery work.
  uint64_t removalAttempts = 0;
  // Edge removal that first tries to shrink the edge's ring by removing the edges joining its ends to
  // the ring vertices (recursively, `depth` levels) when the edge cannot be removed directly.
  bool removeEdgeDeep(int32_t t, int32_t x, int32_t y, const BoundaryConstraints* bc, std::vector<int32_t>* created,
                      int depth, std::array<int32_t, 2> chord = { -1, -1 });

  // The tets the last successful flip removed (for undo: replace(created, lastRemoved)) and their ids
  // before the flip.
  std::vector<std::array<int32_t, 4>> lastRemoved;
  std::vector<int32_t> lastRemovedIds;

private:
  std::vector<int32_t> tmpRing_, roots_;
  // insertVertex()'s steps and cavity.
  bool insertionRoots(int32_t v, int32_t t0, const BoundaryConstraints* bc, std::vector<int32_t>& roots);
  bool cavityKillsBoundaryEdge(const BoundaryConstraints& bc);
  ConflictCavity cavity_{ *this };
  std::vector<std::array<int32_t, 4>> tmpNew_;
  Cone cone_; // insertVertex()
};

} // namespace volgrid
