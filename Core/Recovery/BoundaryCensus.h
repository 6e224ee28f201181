// BoundaryCensus: which boundary subfaces and subface edges of a BoundaryConstraints are faces and edges
// of the mesh, found by ONE pass over the tets instead of a vertex-star search per item
// (MeshEditor::findEdge/findFace cost a breadth-first search each; a census of a 75k-triangle surface
// made 300k of them).
//
// The constraint edges and subfaces are indexed by their smallest vertex: vertex x owns one row holding
// the other ends of its edges and the other two vertices of its subfaces, so each tet matches the rows of
// its smaller vertices against its larger ones (short contiguous scans, no hashing). Answers are exact and equal
// to findEdge(a,b) >= 0 / findFace(a,b,c) >= 0 on a mesh whose vertex stars are face-connected (boundary
// recovery's mesh: the whole far box). A census is a snapshot: take() again after the mesh or the
// constraints changed (upToDate() tells).
#pragma once

#include "BoundaryRecovery.h"
#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

class BoundaryCensus
{
public:
  // Index the live subfaces of bc and sweep the live tets of the editor's mesh. Without edges only the
  // faces are looked for (edgePresent() is then false for all).
  void take(const MeshEditor& editor, const BoundaryConstraints& bc, bool withEdges = true);
  // The same for a plain list of `count` triangles (3 vertex ids each; triangle t plays subface t), e.g.
  // the input triangles once recovery is over. Never upToDate().
  void take(const TetMesh& mesh, const int32_t* triangles, int32_t count, bool withEdges = true);
  // True when neither the mesh (MeshEditor::edits, tet counts) nor the constraints changed since a
  // take() with edges.
  bool upToDate(const MeshEditor& editor, const BoundaryConstraints& bc) const;

  // Id of edge ab of a live subface, in [0, edgeIdLimit()); -1 when ab is no such edge. Subfaces with a
  // repeated vertex are not indexed (they are never faces of a tet, nor is an edge aa).
  int32_t edgeId(int32_t a, int32_t b) const;
  int32_t edgeIdLimit() const { return static_cast<int32_t>(data_.size()); }
  // Edge `id` is an edge of some live tet.
  bool edgePresent(int32_t id) const { return data_[static_cast<size_t>(id)] < 0; }
  // (tet << 2) | face of a live tet having subface f (live at take()) as its face, -1 when f is not a
  // face of the mesh.
  int32_t faceCode(int32_t f) const
  {
    if (f < 0 || static_cast<size_t>(f) >= facePos_.size())
      return -1;
    const int32_t at = facePos_[static_cast<size_t>(f)];
    return at < 0 ? -1 : data_[static_cast<size_t>(at) + 3];
  }

  // Calls fn(f, a, b, id, first) for each edge ab of each live subface f of bc, in subface order, with
  // the edge's id (edgeId) and whether this is its first visit (an edge of two subfaces comes twice; an
  // edge without id, never present, is always a first visit).
  template<class Fn>
  void forEachSubfaceEdge(const BoundaryConstraints& bc, Fn&& fn) const
  {
    std::vector<uint8_t> seen(data_.size(), 0);
    for (int32_t f = 0; f < bc.capacity(); ++f)
    {
      if (!bc.alive(f))
        continue;
      const int32_t* s = bc.subface(f);
      for (int i = 0; i < 3; ++i)
      {
        const int32_t a = s[i], b = s[(i + 1) % 3];
        const int32_t id = edgeId(a, b);
        const bool first = id < 0 || !seen[static_cast<size_t>(id)];
        if (id >= 0)
          seen[static_cast<size_t>(id)] = 1;
        fn(f, a, b, id, first);
      }
    }
  }

private:
  // Subfaces 0..count-1 with vertices verts[3f..3f+2]; dead where parent[f] < 0 (parent may be null).
  void index(const int32_t* verts, int32_t count, const int32_t* parent, int32_t numVertices);
  void sweep(const TetMesh& mesh, bool withEdges);

  // Row of vertex x: data_[rows_[x].begin .. rows_[x].faces) are the other ends b > x of its edges
  // (sorted; the sign bit set once the edge is found in a tet), then data_[rows_[x].faces ..
  // rows_[x].end) holds its subfaces {x < y < z} as quadruples (y, z, subface id, faceCode).
  struct Row
  {
    int32_t begin, faces, end;
  };
  std::vector<Row> rows_;
  std::vector<int32_t> data_;
  std::vector<int32_t> facePos_; // per subface: index of its quadruple in data_, -1 if degenerate/dead
  // Snapshot identity for upToDate().
  const TetMesh* mesh_ = nullptr;
  const BoundaryConstraints* bc_ = nullptr;
  uint64_t edits_ = 0;
  bool edgesSwept_ = false;
  int32_t tetCapacity_ = -1, numTets_ = -1, bcCapacity_ = -1, bcAlive_ = -1;
};

} // namespace volgrid
