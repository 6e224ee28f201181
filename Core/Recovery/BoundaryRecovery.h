// Boundary recovery (paper 7.3): make every input triangle a face of the tetrahedral mesh.
//
// Starting point: the Delaunay tetrahedralization of the surface points (plus a far box, see Mesher.h),
// without ghost tets. Stages, all decided by the exact predicates (no epsilon):
//   1. Missing edges (segments) are recovered by flips: 2-3 flips of the faces the segment crosses, edge
//      removal (3-2, 4-4 and general n-to-(2n-4), best triangulation of the edge's ring found by
//      dynamic programming) of the edges it crosses and of the edges of the faces it crosses (the reflex
//      edge that blocks a 2-3 flip). An edge crossing the segment in a common plane (a flat CAD face) is
//      first removed as a 2D flip would: with the chord between its two in-plane ring vertices required,
//      then by flipInPlane (PlanarFlip.h: each side of the plane re-filled by a cone, a Delaunay fill or an
//      interior Steiner point). A flip is kept only when it reduces the number of faces/edges the segment
//      crosses (a bounded number of sideways steps aside), so the search always terminates.
//   2. Missing facets: once every segment (input edge, or piece of one between Steiner points) is
//      present, each input triangle with missing subfaces is re-triangulated as a whole by cavity
//      retetrahedralization (FacetRecovery.h): its inner subface edges need not be recovered first.
//      When its pieces are not coplanar (rounded segment Steiner points), it is re-triangulated with
//      diagonals the mesh has and each piece is recovered as its own triangle (recoverFacetByPieces).
//      When that fails for a triangle, its subface edges and subfaces are recovered one by one as before:
//      the edges crossing a subface are removed by edge removal or 2-3 flips.
//   3. What flips cannot recover gets a Steiner point (paper: "points at the intersection of the missing
//      edges/facets with the tets"): the midpoint of a missing (sub)segment or the centroid of a missing
//      (sub)facet, inserted by a Bowyer-Watson cavity that never crosses a recovered boundary face and is
//      made star-shaped exactly (with RecoveryOptions::segmentCones a segment is first split at crossing
//      points whose cones make every piece an edge at once, SegmentConeSplit.h). The boundary triangles
//      are then split into subfaces (BoundaryConstraints) and the pieces are recovered in turn.
//      SteinerRemoval.h later removes every such boundary point.
// Flips and insertions never destroy a recovered subface or subsegment (they are constraints), and
// never create an edge between two points of a split input segment other than its pieces
// (BoundaryConstraints::forbiddenEdge; the same holds for facet cavities and Steiner removal).
// With RecoveryOptions::presplitSegments (the mesher's retry after a failed first attempt) the listed
// segments are split by Delaunay insertion before any flip, until their pieces are edges.
// Whatever cannot be recovered is reported as ErrorKind::RecoveryFailed, with the counts, the first
// input triangles concerned and why recovery stopped: the Steiner budget, the missing-edge count growing
// for three rounds (Steiner points that do not converge); the flip work budget (edge-removal attempts,
// 1000 per initially missing edge + 100000) keeps hopeless cases to seconds: once spent, only Steiner
// points are added.
#pragma once

#include "BoundaryConstraints.h"
#include "MeshEditor.h"
#include "Progress.h"
#include "Status.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace volgrid
{

struct RecoveryOptions
{
  bool allowSteiner = true;      // false: flips only (what flips cannot do is reported)
  int64_t maxSteinerPoints = -1; // budget; -1 = automatic (4 x triangles + 1000)
  // Input segments (edgeKey of their end points) to split first, while the mesh is still Delaunay:
  // before any flip, their missing pieces are split by plain Delaunay insertion until every piece is an
  // edge. That converges (a piece short enough is a Delaunay edge), where splitting after flips may
  // not; the mesher retries a failed recovery with the segments the first attempt had to split.
  const std::unordered_set<uint64_t>* presplitSegments = nullptr;
  // Missing segments that flips leave are split by cones (SegmentConeSplit.h: their pieces are edges at
  // once) before the midpoint split is tried. The mesher's last resort: long needle segments that the
  // midpoint split does not make recoverable (prt2.stl) converge with few points, while segments meeting
  // at a small angle can be slower to recover that way than with midpoints.
  bool segmentCones = false;
};

struct RecoveryReport
{
  int64_t missingEdgesInitially = 0;
  int64_t missingFacetsInitially = 0; // facets missing after all edges were present
  int64_t steinerSegment = 0;         // Steiner points put on input edges
  int64_t steinerFacet = 0;           // Steiner points put inside input triangles
  uint64_t flips23 = 0, flips32 = 0, flipsEdgeRemoval = 0;
  int64_t facetCavities = 0;           // input triangles recovered by cavity retetrahedralization
  int64_t facetCavityEnlargements = 0; // tets added to those cavities for missing boundary faces
  int64_t unrecoveredEdges = 0, unrecoveredFacets = 0;
  int64_t presplitPoints = 0;                 // Steiner points of the presplit stage (part of steinerSegment)
  std::unordered_set<uint64_t> splitSegments; // input segments that received Steiner points
  double seconds = 0;
};

// Recover the boundary. `mesh` has no ghost tets; every vertex of the constraints is a mesh vertex;
// `kinds` gives one VertexKind per mesh vertex and is extended for the Steiner points added.
Status recoverBoundary(MeshEditor& editor, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
                       const RecoveryOptions& options, Progress* progress, RecoveryReport* report);

} // namespace volgrid
