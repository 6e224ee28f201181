// The boundary a tetrahedral mesh must keep (the input triangles, split into subfaces while boundary
// Steiner points exist) and what each mesh vertex is. Built by the mesher, kept by recovery (its
// flips and insertions never destroy a subface), Steiner removal, exterior removal and improvement.
#pragma once

#include "FlatHashMap.h"
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
  Unused = 0,     // not (yet) in the mesh, or an input point no triangle references
  Boundary,       // an input point used by the boundary triangles
  Box,            // a corner of the auxiliary far box (only in exterior tets, removed with them)
  SteinerSegment, // added on an input edge (boundary: must be removed)
  SteinerFacet,   // added inside an input triangle (boundary: must be removed)
  SteinerInterior // added strictly inside a region (allowed, counted)
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
  FlatHashMap<TriKey, int32_t, TriKeyHash> faces_;
  FlatHashMap<uint64_t, std::array<int32_t, 2>, EdgeKeyHash> edges_;
  std::unordered_map<int32_t, uint64_t> segmentOf_; // segment Steiner point -> its input segment
  std::unordered_set<uint64_t> splitSegments_;
  int32_t numAlive_ = 0;
  int32_t numInput_ = 0;
  int64_t nonManifold_ = 0;
};

} // namespace volgrid
