// Recoverer: the edits of boundary recovery on one segment or facet (BoundaryRecovery.h describes the
// algorithm): tracing what a segment or facet crosses, recovering it by flips, and splitting it with
// Steiner points. recoverBoundary() (BoundaryRecovery.cxx) drives it over the missing segments and facets.
#pragma once

#include "BoundaryConstraints.h"
#include "MeshEditor.h"
#include "TetMesh.h"
#include "VertexKeys.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace volgrid
{

// A face (a: face index) or an edge (a, b: its endpoints) of tet `tet` that a segment or facet crosses.
struct Crossing
{
  int32_t tet;
  int32_t a, b; // edge endpoints (edges) or face index in a (faces)
};

class Recoverer
{
public:
  Recoverer(MeshEditor& ed, BoundaryConstraints& bc, std::vector<VertexKind>& kinds)
    : ed_(ed)
    , m_(ed.mesh)
    , bc_(bc)
    , kinds_(kinds)
  {
  }

  // Crossings of the open segment ab. Returns false when a vertex lies on it.
  bool traceSegment(int32_t a, int32_t b, std::vector<Crossing>& faces, std::vector<Crossing>& edges);

  // Edges crossing the interior of triangle abc (its edges present). False when a vertex lies in it.
  bool traceFacet(int32_t a, int32_t b, int32_t c, std::vector<Crossing>& edges, std::vector<int32_t>* visited);

  void undo(const std::vector<int32_t>& created);

  // For edge c crossing segment ab in a common plane: the two vertices of c's ring in that plane (the
  // diagonal a 2D flip would create), or {-1, -1}.
  std::array<int32_t, 2> inPlaneChord(int32_t a, int32_t b, const Crossing& c);

  // Segment ab lies in a flat part of the mesh where it crosses only edges of that plane, each with the
  // two in-plane ring vertices of a 2D triangulation (a flat CAD face): Sloan's 2D algorithm. Crossing
  // edges wait in a queue; one whose quad is convex is flipped in the plane (flipInPlane refuses the
  // others, which go back to the queue), and the new diagonal joins the queue if it still crosses ab.
  // In 2D a convex one always exists, so this ends; the crossing count never grows but may stay the
  // same for many flips, which the greedy search below does not allow.
  bool recoverEdgeInPlane(int32_t a, int32_t b, const std::vector<Crossing>& edges);

  bool recoverEdgeByFlips(int32_t a, int32_t b);

  // The 2-3 flip of a face the segment crosses is invalid when one of the face's edges is reflex; then
  // that edge has to go first (TetGen's removefacebyflips does the same). Tries each edge of each crossing
  // face; keeps a removal that lowers the crossing count (or keeps it, a bounded number of times).
  bool removeCrossingFaceEdge(int32_t a, int32_t b, size_t m0, int& sideways);

  // After a flip: does segment ab cross fewer than m0 faces and edges? Like Sloan's 2D algorithm, a flip
  // that keeps the count may still be needed (coplanar crossings): up to 64 such sideways steps per
  // segment are accepted too.
  bool fewerCrossings(int32_t a, int32_t b, size_t m0, int& sideways);

  bool recoverFacetByFlips(int32_t a, int32_t b, int32_t c);

  // Where the presplit stage splits missing subsegment ab (the mesh is Delaunay, nothing flipped yet):
  // at the foot of the vertex that encroaches most on it (largest angle a-q-b among the vertices of the
  // faces it crosses), which then no longer encroaches on either piece; when that foot is near an end,
  // at a power-of-two distance from the piece's input end point (concentric shells: pieces of segments
  // meeting at a small angle do not keep encroaching on each other), else at the midpoint.
  void presplitPoint(int32_t a, int32_t b, double* p);

  // Steiner point on subsegment ab: at its midpoint, or (presplit stage) at presplitPoint() inserted
  // by plain Delaunay insertion.
  bool splitEdge(int32_t a, int32_t b, bool presplit = false);

  // Missing subsegment ab recovered at once by points on it (SegmentConeSplit.h); false when that does
  // not apply (the caller then splits it at its midpoint).
  bool splitEdgeByCones(int32_t a, int32_t b, size_t maxPoints);

  // Subsegment ab of the constraints becomes av + vb; the subfaces on it are split in two.
  void splitConstraintEdge(int32_t a, int32_t b, int32_t v, bool sameParent);

  bool splitFacet(int32_t fid);

  int64_t steinerSegment = 0, steinerFacet = 0;

private:
  // The breadth-first walks of traceSegment and traceFacet: seedQueue stamps the tets already in queue_
  // with a fresh stamp (returned); pushOnce appends tet t (-1: none) unless it carries that stamp.
  // Defined here so that the walks' inner loops inline them.
  uint32_t seedQueue()
  {
    const uint32_t s = ed_.newStamp();
    for (int32_t t : queue_)
      ed_.tetStamp[t] = s;
    return s;
  }
  void pushOnce(int32_t t, uint32_t stamp)
  {
    if (t >= 0 && ed_.tetStamp[t] != stamp)
    {
      ed_.tetStamp[t] = stamp;
      queue_.push_back(t);
    }
  }

  MeshEditor& ed_;
  TetMesh& m_;
  BoundaryConstraints& bc_;
  std::vector<VertexKind>& kinds_;
  std::vector<int32_t> queue_;
  std::unordered_set<TriKey, TriKeyHash> seenFaces_;
  std::unordered_set<uint64_t> seenEdges_;
  std::unordered_map<uint64_t, int> coneRounds_; // per input segment (edgeKey), splitEdgeByCones calls
};

} // namespace volgrid
