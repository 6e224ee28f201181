// Boundary recovery (paper 7.3): make every input triangle a face of the tetrahedral mesh.
//
// Starting point: the Delaunay tetrahedralization of the surface points (plus a far box, see Mesher.h),
// without ghost tets. Stages, all decided by the exact predicates (no epsilon):
//   1. Missing edges (segments) are recovered by flips: 2-3 flips of the faces the segment crosses, edge
//      removal (3-2, 4-4 and general n-to-(2n-4), best triangulation of the edge's ring found by
//      dynamic programming) of the edges it crosses and of the edges of the faces it crosses (the reflex
//      edge that blocks a 2-3 flip). An edge crossing the segment in a common plane (a flat CAD face) is
//      first removed as a 2D flip would: with the chord between its two in-plane ring vertices required,
//      then by MeshEditor::flipInPlane (each side of the plane re-filled by a cone, a Delaunay fill or an
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

#include "FlatHashMap.h"
#include "Progress.h"
#include "Status.h"
#include "TetMesh.h"
#include "TetStamps.h"
#include "VertexKeys.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace volgrid
{

// What a mesh vertex is, for recovery and Steiner removal.
enum class VertexKind : uint8_t
{
  Unused = 0,      // not (yet) in the mesh, or an input point no triangle references
  Boundary,        // an input point used by the boundary triangles
  Box,             // a corner of the auxiliary far box (only in exterior tets, removed with them)
  SteinerSegment,  // added on an input edge (boundary: must be removed)
  SteinerFacet,    // added inside an input triangle (boundary: must be removed)
  SteinerInterior  // added strictly inside a region (allowed, counted)
};

// The boundary the mesh must contain: the input triangles, each possibly split into subfaces while
// boundary Steiner points exist. A subface keeps its parent triangle's orientation and id.
class BoundaryConstraints
{
public:
  void init(const int32_t* triangles, int32_t numTriangles);
  int32_t addSubface(int32_t a, int32_t b, int32_t c, int32_t parent);
  void removeSubface(int32_t f);
  int32_t findSubface(int32_t a, int32_t b, int32_t c) const; // -1 when not a (live) subface
  bool isEdge(int32_t a, int32_t b) const { return edges_.contains(edgeKey(a, b)); }
  // The (at most two) live subfaces using edge ab; -1 entries are empty. nullptr when not an edge.
  const std::array<int32_t, 2>* edgeFaces(int32_t a, int32_t b) const;

  int32_t capacity() const { return static_cast<int32_t>(parent.size()); }
  bool alive(int32_t f) const { return parent[f] >= 0; }
  const int32_t* subface(int32_t f) const { return verts.data() + 3 * static_cast<size_t>(f); }
  int32_t numAlive() const { return numAlive_; }
  int32_t numInputTriangles() const { return numInput_; }
  // Edges used by more than two subfaces seen by init() (the input was not manifold).
  int64_t nonManifoldEdges() const { return nonManifold_; }

  // Segment Steiner points: v was put on input edge (a, b) (segment `original`, split before or not).
  void addSegmentPoint(int32_t v, int32_t a, int32_t b);
  // An edge uv that must not be created: both ends on one split input segment without being one of its
  // pieces. Rounded segment points lie just off the segment, so such an edge would run alongside the
  // pieces and fold the boundary (flat tets that Steiner removal cannot undo).
  bool forbiddenEdge(int32_t u, int32_t v) const;
  // The input segment (edgeKey of its input end points) that subsegment ab lies on.
  uint64_t segmentOf(int32_t a, int32_t b) const;
  // Is w an end point of input segment seg, or a Steiner point put on it?
  bool onSegment(int32_t w, uint64_t seg) const;
  // Input segments that received Steiner points.
  const std::unordered_set<uint64_t>& splitSegments() const { return splitSegments_; }

  std::vector<int32_t> verts;  // 3 per subface
  std::vector<int32_t> parent; // input triangle id, -1 = removed

private:
  struct EdgeKeyHash
  {
    uint64_t operator()(uint64_t k) const { return k; } // FlatHashMap mixes the bits
  };
  FlatHashMap<TriKey, int32_t, TriKeyHash> faces_;
  FlatHashMap<uint64_t, std::array<int32_t, 2>, EdgeKeyHash> edges_;
  std::unordered_map<int32_t, uint64_t> segmentOf_; // segment Steiner point -> its input segment
  std::unordered_set<uint64_t> splitSegments_;
  int32_t numAlive_ = 0;
  int32_t numInput_ = 0;
  int64_t nonManifold_ = 0;
};

// Local topological edits on a TetMesh without ghost tets, with a vertex -> incident tet map.
// Every edit goes through replace(): old tets out, new (positively oriented) tets in, adjacency rebuilt
// from the old tets' outer faces. Used by recovery, Steiner insertion and Steiner removal.
class MeshEditor
{
public:
  explicit MeshEditor(TetMesh& mesh);
  TetMesh& mesh;

  void rebuildVertexMap();
  // A live tet incident to v, or -1 (v used by no tet).
  int32_t tetOf(int32_t v);
  // All live tets incident to v (BFS over faces containing v).
  void star(int32_t v, std::vector<int32_t>& out);
  // A tet containing edge ab (-1 if none).
  int32_t findEdge(int32_t a, int32_t b);
  // A tet having abc as a face (face index in *face), -1 if none.
  int32_t findFace(int32_t a, int32_t b, int32_t c, int* face = nullptr);
  // The ring around edge xy given a tet t containing it: ring vertices r_i and tets {x,y,r_i,r_i+1}
  // with orient3d(x,y,r_i,r_i+1) > 0. False when the ring is open (edge on the hull).
  bool edgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets);

  // Replace oldTets by newTets (vertex quadruples, which must be positively oriented and fill the same
  // region). Returns false and leaves the mesh untouched when the faces do not match up. With allowOpen,
  // the region may change where it has no neighbour: unmatched new faces get no neighbour and outer tets
  // whose old face is gone lose that neighbour (used when the boundary moves, SteinerRemoval).
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

  // Replaces edge xy (in tet t) by pq, where p and q are ring vertices coplanar with x and y (a 2D flip
  // inside a flat face); each side of the plane is re-filled on its own (PlanarFlip.cxx). With `kinds`,
  // a side no cone or Delaunay fill can do gets an interior Steiner point (appended to kinds).
  bool flipInPlane(int32_t t, int32_t x, int32_t y, int32_t p, int32_t q, const BoundaryConstraints* bc,
    std::vector<int32_t>* created = nullptr, std::vector<VertexKind>* kinds = nullptr);

  // The tets the last successful flip removed (for undo: replace(created, lastRemoved)) and their ids
  // before the flip.
  std::vector<std::array<int32_t, 4>> lastRemoved;
  std::vector<int32_t> lastRemovedIds;

  // Scratch helpers shared by the stages.
  uint32_t newStamp();
  TetStamps tetStamp; // per tet slot (resized on demand)
  void ensureStamp();

private:
  std::vector<int32_t> vertTet_;
  uint32_t stamp_ = 0;
  // replace() scratch
  struct BFace
  {
    TriKey key;
    int32_t code;
  };
  struct NFace
  {
    TriKey key;
    int32_t tet;
    int face;
  };
  std::vector<BFace> bfaces_;
  std::vector<NFace> nfaces_;
  std::vector<int32_t> tmpTets_, tmpRing_, cavity_, queue_;
  std::vector<std::array<int32_t, 4>> tmpNew_;
};

struct RecoveryOptions
{
  bool allowSteiner = true;   // false: flips only (what flips cannot do is reported)
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
  int64_t facetCavities = 0;          // input triangles recovered by cavity retetrahedralization
  int64_t facetCavityEnlargements = 0; // tets added to those cavities for missing boundary faces
  int64_t unrecoveredEdges = 0, unrecoveredFacets = 0;
  int64_t presplitPoints = 0;          // Steiner points of the presplit stage (part of steinerSegment)
  std::unordered_set<uint64_t> splitSegments; // input segments that received Steiner points
  double seconds = 0;
};

// Recover the boundary. `mesh` has no ghost tets; every vertex of the constraints is a mesh vertex;
// `kinds` gives one VertexKind per mesh vertex and is extended for the Steiner points added.
Status recoverBoundary(MeshEditor& editor, BoundaryConstraints& bc, std::vector<VertexKind>& kinds,
  const RecoveryOptions& options, Progress* progress, RecoveryReport* report);

} // namespace volgrid
