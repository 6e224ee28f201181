// MeshNavigator: what both mesh editors stand on (MeshEditor for recovery, TetEditor for refinement and
// improvement): the vertex -> incident tet map, the tet stamps, the star of a vertex and the tets holding
// an edge or a face. The editors add their edits (replace, flips, insertion) on top and keep the map up to
// date through mapVertex().
#pragma once

#include "TetMesh.h"
#include "TetStamps.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace volgrid
{

class MeshNavigator
{
public:
  // What tetOf() does with a map entry that does not hold its vertex. Each editor keeps its own rule:
  // a rescan rebuilds every entry, which changes the tets stars start from, and so the output mesh.
  enum class StaleEntries
  {
    Rescan, // rebuild the map (recovery: MeshEditor)
    Trust   // return the entry (the improvement stages: TetEditor, whose edits and forgetVertex keep it exact)
  };
  MeshNavigator(TetMesh& mesh, StaleEntries rule);
  TetMesh& mesh;

  // Vertex -> one incident live tet, rebuilt from scratch.
  void rebuildVertexMap();
  // The map's entry for v: -1 for a vertex in no tet or beyond the map.
  int32_t mappedTet(int32_t v) const
  {
    return v >= 0 && static_cast<size_t>(v) < vertTet_.size() ? vertTet_[static_cast<size_t>(v)] : -1;
  }
  // A live tet incident to v, or -1 (v in no tet), under the StaleEntries rule.
  int32_t tetOf(int32_t v);
  // After an edit that leaves v in no tet (a vertex removal): tetOf(v) = -1 from then on.
  void forgetVertex(int32_t v)
  {
    if (v >= 0 && static_cast<size_t>(v) < vertTet_.size())
      vertTet_[static_cast<size_t>(v)] = -1;
  }

  // All live tets incident to v (breadth first over the faces containing v, from tetOf(v)).
  void star(int32_t v, std::vector<int32_t>& out);
  // A tet containing edge ab (-1 if none).
  int32_t findEdge(int32_t a, int32_t b);
  // A tet having abc as a face (face index in *face), -1 if none.
  int32_t findFace(int32_t a, int32_t b, int32_t c, int* face = nullptr);

  // Per tet slot marks: newStamp() gives a value no slot holds yet (resized on demand).
  uint32_t newStamp();
  void ensureStamp();
  TetStamps tetStamp;

protected:
  // Records t as the tet of vertex v (the edits call it for every vertex of a new tet).
  void mapVertex(int32_t v, int32_t t)
  {
    if (static_cast<size_t>(v) >= vertTet_.size())
      vertTet_.resize(std::max(static_cast<size_t>(v) + 1, static_cast<size_t>(mesh.numVertices())), -1);
    vertTet_[static_cast<size_t>(v)] = t;
  }

private:
  std::vector<int32_t> vertTet_;
  std::vector<int32_t> findScratch_;
  StaleEntries stale_;
};

} // namespace volgrid
