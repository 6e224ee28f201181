// MeshNavigator: what both mesh editors stand on (MeshEditor for recovery, TetEditor for refinement and
// improvement): the vertex -> incident tet map, the tet stamps, the star of a vertex and the tets holding
// an edge or a face, and the one replace() every edit of both ends in (old tets out, new tets in, adjacency
// glued, map kept up to date). The editors add their edits (flips, edge removal, insertion) on top.
#pragma once

#include "EditJournal.h"
#include "FlatHashMap.h"
#include "Progress.h"
#include "TetMesh.h"
#include "TetSlotPool.h"
#include "TetStamps.h"
#include "VertexKeys.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
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
  // Whether the navigator keeps the vertex -> tet map (star, findEdge, findFace need it). An editor that only
  // inserts points (a thread of FieldPointRegions.h) goes without: no whole-mesh scan to build it.
  enum class VertexMap
  {
    Kept,
    None
  };
  MeshNavigator(TetMesh& mesh, StaleEntries rule, VertexMap map = VertexMap::Kept);
  TetMesh& mesh;

  // Vertex -> one incident live tet, rebuilt from scratch: the highest live slot holding it.
  void rebuildVertexMap();
  // What rebuildVertexMap() would give, without its sweep of the mesh: only the vertices whose entry an
  // edit wrote or forgot since the last rebuild or refresh can differ from it (no other vertex had a tet
  // made or removed), and each of them gets the highest slot of its star, started from its entry when that
  // tet still holds it, else from a live tet of `hint` that holds it (after an undo: the slots it restored),
  // else none (a vertex left in no tet). Costs the stars of those vertices. progress (optional) is asked
  // between blocks of stars (after the first quality pass at 5M tets the refresh takes 0.3 s on 2 cores);
  // when it says stop, false: every entry holds its vertex, the ones not yet refreshed stay listed for the
  // next refresh.
  bool refreshVertexMap(const std::vector<int32_t>& hint, Progress* progress = nullptr);
  // The threads refreshVertexMap() uses for the stars (the rule of ParallelFor.h; the map is the same for
  // any count).
  int refreshThreads = 1;
  // The map's entry for v: -1 for a vertex in no tet or beyond the map.
  int32_t mappedTet(int32_t v) const
  {
    return v >= 0 && static_cast<size_t>(v) < vertTet_.size() ? vertTet_[static_cast<size_t>(v)] : -1;
  }
  // A live tet incident to v, or -1 (v in no tet), under the StaleEntries rule.
  int32_t tetOf(int32_t v);
  // The tets `made` were created by another editor (a thread's, without a map): the live ones become their
  // vertices' entries (every vertex whose entry such edits destroyed is in one of them; refreshVertexMap()
  // then makes the entries canonical).
  void mapTetsMadeElsewhere(const std::vector<int32_t>& made)
  {
    for (int32_t t : made)
      if (!mesh.isFree(t))
        for (int i = 0; i < 4; ++i)
          mapVertex(mesh.vertex(t, i), t);
  }
  // After an edit that leaves v in no tet (a vertex removal): tetOf(v) = -1 from then on.
  void forgetVertex(int32_t v)
  {
    if (v >= 0 && static_cast<size_t>(v) < vertTet_.size())
    {
      vertTet_[static_cast<size_t>(v)] = -1;
      markWritten(v);
    }
  }

  // All live tets incident to v (breadth first over the faces containing v, from tetOf(v)).
  void star(int32_t v, std::vector<int32_t>& out);
  // A tet containing edge ab (-1 if none).
  int32_t findEdge(int32_t a, int32_t b);
  // A tet having abc as a face (face index in *face), -1 if none.
  int32_t findFace(int32_t a, int32_t b, int32_t c, int* face = nullptr);
  // The ring around edge xy given a live tet t containing it: ring vertices r_i and tets {x,y,r_i,r_i+1}
  // with orient3d(x,y,r_i,r_i+1) > 0. False when a face around the edge is blocked (blocked(tet, face):
  // the hull for recovery, every constrained face for the improvement stages), when the ring has more
  // than maxTets tets, or when the adjacency around the edge is inconsistent.
  template<class Blocked>
  bool walkEdgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring, std::vector<int32_t>& tets,
                    int maxTets, Blocked&& blocked) const;

  // How a walk picks the first face it tries in each tet. It decides which tet a point on a shared face
  // or edge lands in (and so the mesh), so each editor keeps its own.
  enum class WalkOrder
  {
    Rotating, // faces 0, 1, 2, 3 first in turn; at most 4 n + 100 steps (recovery: MeshEditor)
    Random    // a pseudo-random face seeded by the start tet; at most 4 n + 64 steps (TetEditor)
  };
  // Visibility walk from `start` to a tet whose closure contains p (exact orient3d); -1 if the walk leaves
  // the mesh (p outside, or behind a boundary concavity) or does not converge.
  int32_t walk(const double* p, int32_t start, WalkOrder order) const;

  // Per tet slot marks: newStamp() gives a value no slot holds yet (resized on demand).
  uint32_t newStamp();
  void ensureStamp();
  TetStamps tetStamp;

  // Optional undo log: when set, every tet slot is saved in it before an edit writes it (EditJournal.h).
  // Points are the caller's to save before it moves them.
  EditJournal* journal = nullptr;
  // Optional per-tet-slot labels (region tags): new tets take the first old tet's, resized as tets are made.
  std::vector<int32_t>* labels = nullptr;
  // Optional slots of this editor's own (TetSlotPool.h): point insertions (replaceByCone) and replacements take
  // their new slots from it and give the freed ones back, instead of the mesh's free list. The caller sizes `labels` to
  // the mesh's capacity first, so that no thread grows it. Not with a journal (pooled slots are not saved).
  TetSlotPool* slotPool = nullptr;

protected:
  // Replaces oldTets by newTets (vertex quadruples, positively oriented, filling the same region): old
  // tets freed, new ones created in order (inheriting the first old tet's user flag bits and label),
  // adjacency glued through the old tets' outer faces, the vertex map and the journal kept. Returns false
  // and leaves the mesh untouched when the faces do not match: every face must be shared by two new tets
  // or by a new tet and an old outer face. With allowOpen the region may change where it has no
  // neighbour: a new face matching nothing gets no neighbour, an outer tet whose face is gone loses it.
  bool replaceTets(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets,
                   std::vector<int32_t>* created, bool allowOpen);
  // The cone of a vertex insertion, built by the editor from its cavity: tets[k] has the new vertex at
  // position apexAt[k], and its face apexAt[k] is a cavity boundary face whose outer neighbour code
  // (kNoNeighbor on the boundary) is outerCode[k].
  struct Cone
  {
    std::vector<std::array<int32_t, 4>> tets;
    std::vector<int32_t> outerCode, apexAt;
    void clear()
    {
      tets.clear();
      outerCode.clear();
      apexAt.clear();
    }
    void add(const std::array<int32_t, 4>& q, int32_t code, int32_t at)
    {
      tets.push_back(q);
      outerCode.push_back(code);
      apexAt.push_back(at);
    }
  };
  // Replaces the cavity's tets by the cone, as replaceTets() would but without its face matching: the
  // cone's side faces meet pairwise at the cavity's boundary edges. The caller guarantees a cavity that is
  // strictly star-shaped from the new vertex (so its boundary is a sphere) with no vertex inside.
  void replaceByCone(const std::vector<int32_t>& cavity, const Cone& cone, std::vector<int32_t>* created);
  void journalTet(int32_t t)
  {
    if (journal && t >= 0)
      journal->saveTet(mesh, labels, t);
  }
  // What the tets that replace t inherit from it: its user flag bits and its label (-1 without labels).
  uint8_t userBitsOf(int32_t t) const
  {
    return mesh.tetFlags[t] & static_cast<uint8_t>(~(TetMesh::kFree | TetMesh::kMarkA | TetMesh::kMarkB));
  }
  int32_t labelOf(int32_t t) const
  {
    return labels && static_cast<size_t>(t) < labels->size() ? (*labels)[static_cast<size_t>(t)] : -1;
  }
  // Gives the new tets `ids` the label (no-op without labels; the labels grow to the mesh's capacity).
  void labelTets(const std::vector<int32_t>& ids, int32_t label);

  // Records t as the tet of vertex v (the edits call it for every vertex of a new tet).
  void mapVertex(int32_t v, int32_t t)
  {
    if (map_ == VertexMap::None)
      return;
    if (static_cast<size_t>(v) >= vertTet_.size())
      vertTet_.resize(std::max(static_cast<size_t>(v) + 1, static_cast<size_t>(mesh.numVertices())), -1);
    vertTet_[static_cast<size_t>(v)] = t;
    markWritten(v);
  }

private:
  static constexpr int64_t kMinRefreshesPerThread = 4096;
  static constexpr size_t kRefreshesPerQuestion = size_t{ 1 } << 17; // about 0.07 s on 2 cores
  // The highest slot of v's star, walked from t0 (a live tet holding v) with starTets as scratch.
  // The entries written_[begin, end) from their stars (refreshVertexMap()).
  void refreshStars(size_t begin, size_t end);
  int32_t highestSlotOfStar(int32_t v, int32_t t0, std::vector<int32_t>& starTets) const;
  // Notes v among the entries written since the last rebuild or refresh (refreshVertexMap()).
  void markWritten(int32_t v)
  {
    if (static_cast<size_t>(v) >= writtenFlag_.size())
      writtenFlag_.resize(std::max(static_cast<size_t>(v) + 1, vertTet_.size()), 0);
    if (!writtenFlag_[static_cast<size_t>(v)])
    {
      writtenFlag_[static_cast<size_t>(v)] = 1;
      written_.push_back(v);
    }
  }
  // A new slot holding tet q (no neighbours yet): from slotPool when there is one, else the mesh's (journaled).
  int32_t placeNewTet(const std::array<int32_t, 4>& q);
  // replaceTets() once its faces matched: the mesh edit itself.
  void commitReplacement(const std::vector<int32_t>& oldTets, const std::vector<std::array<int32_t, 4>>& newTets);
  // replaceTets() scratch: a face by its sorted vertex triple; owner -1 for an old outer face (code: its
  // outer neighbour code), else the index of its new tet.
  struct FaceEntry
  {
    int32_t key[3];
    int32_t code;
    int32_t owner;
    int face;
  };
  std::vector<FaceEntry> replaceFaces_;
  std::vector<int32_t> replaceIds_;
  // replaceByCone(): side faces of the cone waiting for their partner, by edge key (empty between calls).
  FlatHashMap<uint64_t, int32_t, EdgeKeyHash> openSideFaces_;
  std::vector<int32_t> vertTet_;
  std::vector<int32_t> written_;     // vertices whose entry changed since the last rebuild or refresh
  std::vector<uint8_t> writtenFlag_; // 1 for those, per vertex
  std::vector<int32_t> findScratch_;
  StaleEntries stale_;
  VertexMap map_;
};

template<class Blocked>
bool MeshNavigator::walkEdgeRing(int32_t t, int32_t x, int32_t y, std::vector<int32_t>& ring,
                                 std::vector<int32_t>& tets, int maxTets, Blocked&& blocked) const
{
  ring.clear();
  tets.clear();
  const int ix = mesh.localIndex(t, x), iy = mesh.localIndex(t, y);
  if (ix < 0 || iy < 0)
    return false;
  int ia = -1, ib = -1;
  for (int i = 0; i < 4; ++i)
    if (i != ix && i != iy)
      (ia < 0 ? ia : ib) = i;
  // Parity of the permutation (ix, iy, ia, ib) of (0,1,2,3): an odd one flips the orientation.
  const int perm[4] = { ix, iy, ia, ib };
  int inv = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      inv += perm[i] > perm[j];
  if (inv & 1)
    std::swap(ia, ib);
  const int32_t* v = mesh.vertices(t);
  ring.push_back(v[ia]);
  ring.push_back(v[ib]);
  tets.push_back(t);
  int32_t cur = t;
  int32_t prevR = v[ia]; // the ring vertex whose opposite face leads on
  while (true)
  {
    // Across the face of cur opposite prevR (it contains x, y and the last ring vertex).
    const int f = mesh.localIndex(cur, prevR);
    if (blocked(cur, f))
      return false;
    const int32_t next = mesh.neighbor(cur, f);
    const int32_t last = ring.back();
    if (next == t)
      break;
    if (next < 0 || mesh.localIndex(next, x) < 0 || mesh.localIndex(next, y) < 0)
      return false;
    const int32_t* w = mesh.vertices(next);
    int32_t r = -1;
    for (int i = 0; i < 4; ++i)
      if (w[i] != x && w[i] != y && w[i] != last)
        r = w[i];
    if (r < 0 || static_cast<int>(tets.size()) >= maxTets)
      return false;
    tets.push_back(next);
    if (r != ring.front()) // the closing tet (x, y, r_n-1, r_0) adds no vertex
      ring.push_back(r);
    prevR = last;
    cur = next;
  }
  return ring.size() == tets.size() && ring.size() >= 3;
}

} // namespace volgrid
