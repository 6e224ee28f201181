// TetMesh: the tetrahedral mesh every Core stage works on (Delaunay insertion, boundary recovery,
// exterior removal, refinement, smoothing, flips). Flat arrays only, no per-element allocation.
//
// CONVENTIONS (every stage relies on them)
//
// Vertices. Vertex v has coordinates points[3v..3v+2]. Vertices are never renumbered by the mesher,
//   except the field points once, in space (SpatialReorder.h): buildDelaunay() makes vertex i = input
//   point i (exact duplicates stay in `points` but are used by no tet). Steiner/field points are appended
//   with addPoint(). kGhostVertex (-1) is the "vertex at
//   infinity" of ghost tets (see below); it has no coordinates.
//
// Tets. Tet t has vertices tetVertices[4t..4t+3] = (v0,v1,v2,v3). A finite tet is POSITIVELY oriented:
//   predicates::orient3d(p(v0),p(v1),p(v2),p(v3)) > 0, i.e. v3 lies on the side of the right-hand normal
//   (p1-p0)x(p2-p0) of triangle (v0,v1,v2).
//
// Faces. Face i of a tet is the triangle opposite vertex i. Its vertices, in the order returned by
//   faceVertices(t,i) (table kFaceVertex[i]), are oriented so that the opposite vertex vi sees the face
//   positively: orient3d(f0,f1,f2,vi) > 0. Equivalently orient3d(f0,f1,f2,x) has the sign of the tet
//   obtained by replacing vi with x. Replacing vi by a point on the same side keeps the orientation.
//     face 0 = (v1,v3,v2)   face 1 = (v0,v2,v3)   face 2 = (v0,v3,v1)   face 3 = (v0,v1,v2)
//   Two tets sharing a face list it with opposite orientations (the same three vertices, reversed
//   cyclic order).
//
// Neighbours. tetNeighbors[4t+i] describes the tet across face i: the value (u<<2)|j means "tet u, and
//   this face is u's face j" so that moving to the neighbour and back is O(1):
//     neighbor(neighbor(t,i), mirrorFace(t,i)) == t. kNoNeighbor (-1) marks a face without a neighbour
//   (a hull face once ghosts are removed, or a boundary after exterior removal).
//
// Ghost tets (unbounded domain). While ghosts are present, every convex-hull face (a,b,c) is also face
//   k of a ghost tet that has kGhostVertex at position k. The ghost tet follows the same orientation
//   rule with the vertex at infinity standing for a point far outside: orient3d(faceVertices(g,k), x) > 0
//   means x is strictly outside the hull beyond that face. Finite tets + ghost tets then triangulate the
//   whole space (topologically a 3-sphere): every face has exactly one neighbour, no kNoNeighbor. The
//   other three faces of a ghost contain kGhostVertex and link ghosts around the hull edges.
//   removeGhostTets() frees them and sets the hull faces' neighbours to kNoNeighbor.
//
// Flags. One byte per tet: kFree (slot on the free list, contents meaningless), two transient bits
//   reserved for algorithms (kMarkA/kMarkB: must be zero between operations), and user bits
//   kUser0..kUser4 for later stages (e.g. exterior/region tagging). (Delaunay insertion marks its
//   cavity in the sign bit of tetNeighbors words instead, and clears it before returning.)
//
// Free list. Deleted tets are recycled: freeTet() pushes the slot (linked through tetNeighbors[4t]),
//   newTet() pops one or appends. tetCapacity() counts all slots (including free ones); iterate with
//   `for (t = 0; t < tetCapacity(); ++t) if (!isFree(t)) ...` or forEachTet / forEachFiniteTet.
//   compact() removes free slots (renumbers tets, keeps their relative order and adjacency).
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class TetMesh
{
public:
  static constexpr int32_t kGhostVertex = -1;
  static constexpr int32_t kNoNeighbor = -1;

  // Flag bits (tetFlags).
  static constexpr uint8_t kFree = 1u << 0;
  static constexpr uint8_t kMarkA = 1u << 1; // transient, algorithm-private
  static constexpr uint8_t kMarkB = 1u << 2; // transient, algorithm-private
  static constexpr uint8_t kUser0 = 1u << 3;
  static constexpr uint8_t kUser1 = 1u << 4;
  static constexpr uint8_t kUser2 = 1u << 5;
  static constexpr uint8_t kUser3 = 1u << 6;
  static constexpr uint8_t kUser4 = 1u << 7;

  // kFaceVertex[i] = local indices of face i's vertices, oriented so that vertex i sees them positively.
  static constexpr int kFaceVertex[4][3] = { { 1, 3, 2 }, { 0, 2, 3 }, { 0, 3, 1 }, { 0, 1, 2 } };
  // The three faces other than i are faces containing vertex i (every face j != i contains vertex i).

  // ---- data (public: hot loops of Core stages index the flat arrays directly) ----
  std::vector<double> points;        // 3 per vertex
  std::vector<int32_t> tetVertices;  // 4 per tet slot
  std::vector<int32_t> tetNeighbors; // 4 per tet slot, (tet<<2)|face or kNoNeighbor
  std::vector<uint8_t> tetFlags;     // 1 per tet slot

  // ---- sizes ----
  int32_t numVertices() const { return static_cast<int32_t>(points.size() / 3); }
  int32_t tetCapacity() const { return static_cast<int32_t>(tetFlags.size()); } // slots, free included
  int32_t numTets() const { return tetCapacity() - numFree_; }                  // live tets, ghosts included
  int32_t numFreeTets() const { return numFree_; }
  int32_t numGhostTets() const { return numGhost_; }
  int32_t numFiniteTets() const { return numTets() - numGhost_; }

  // Reserve room for about `tets` tet slots and `vertices` vertices (no-op when smaller than now).
  void reserve(size_t vertices, size_t tets);
  // Remove everything (keeps capacity).
  void clear();

  // ---- vertices ----
  // Loops over scattered tets start the loads of a tet some iterations ahead: its flags and vertex
  // numbers first (prefetchTet), its points once those have arrived (prefetchPoints).
  void prefetchTet(int32_t t) const
  {
    __builtin_prefetch(&tetFlags[static_cast<size_t>(t)]);
    __builtin_prefetch(&tetVertices[4 * static_cast<size_t>(t)]);
  }
  void prefetchPoints(int32_t t) const
  {
    for (int i = 0; i < 4; ++i)
    {
      const int32_t v = tetVertices[4 * static_cast<size_t>(t) + i];
      if (v >= 0 && v < numVertices()) // a free slot or a ghost holds others
        __builtin_prefetch(points.data() + 3 * static_cast<size_t>(v));
    }
  }
  const double* point(int32_t v) const
  {
    assert(v >= 0 && v < numVertices());
    return points.data() + 3 * static_cast<size_t>(v);
  }
  int32_t addPoint(const double* xyz);

  // ---- tets ----
  bool isFree(int32_t t) const
  {
    assert(t >= 0 && t < tetCapacity());
    return (tetFlags[t] & kFree) != 0;
  }
  int32_t vertex(int32_t t, int i) const
  {
    assert(t >= 0 && t < tetCapacity() && i >= 0 && i < 4);
    return tetVertices[4 * static_cast<size_t>(t) + i];
  }
  const int32_t* vertices(int32_t t) const
  {
    assert(t >= 0 && t < tetCapacity());
    return tetVertices.data() + 4 * static_cast<size_t>(t);
  }
  bool isGhost(int32_t t) const
  {
    const int32_t* v = vertices(t);
    return (v[0] | v[1] | v[2] | v[3]) < 0 && !isFree(t);
  }
  // Local index (0..3) of vertex v in tet t, or -1.
  int localIndex(int32_t t, int32_t v) const
  {
    const int32_t* w = vertices(t);
    return w[0] == v ? 0 : w[1] == v ? 1 : w[2] == v ? 2 : w[3] == v ? 3 : -1;
  }
  // Position of kGhostVertex in a ghost tet (-1 for a finite tet).
  int ghostIndex(int32_t t) const { return localIndex(t, kGhostVertex); }

  // The three vertices of face i, oriented so that vertex i of t sees them positively.
  void faceVertices(int32_t t, int i, int32_t out[3]) const
  {
    const int32_t* v = vertices(t);
    assert(i >= 0 && i < 4);
    out[0] = v[kFaceVertex[i][0]];
    out[1] = v[kFaceVertex[i][1]];
    out[2] = v[kFaceVertex[i][2]];
  }

  // ---- adjacency ----
  int32_t neighborCode(int32_t t, int i) const // (u<<2)|j or kNoNeighbor
  {
    assert(t >= 0 && t < tetCapacity() && i >= 0 && i < 4);
    return tetNeighbors[4 * static_cast<size_t>(t) + i];
  }
  int32_t neighbor(int32_t t, int i) const // tet across face i or kNoNeighbor
  {
    const int32_t c = neighborCode(t, i);
    return c < 0 ? kNoNeighbor : (c >> 2);
  }
  int mirrorFace(int32_t t, int i) const // index of the same face in neighbor(t,i); -1 if none
  {
    const int32_t c = neighborCode(t, i);
    return c < 0 ? -1 : (c & 3);
  }
  static int32_t encode(int32_t t, int face) { return (t << 2) | face; }
  // Set both directions: face i of t <-> face j of u.
  void link(int32_t t, int i, int32_t u, int j)
  {
    assert(t >= 0 && t < tetCapacity() && u >= 0 && u < tetCapacity());
    tetNeighbors[4 * static_cast<size_t>(t) + i] = encode(u, j);
    tetNeighbors[4 * static_cast<size_t>(u) + j] = encode(t, i);
  }
  void unlink(int32_t t, int i) { tetNeighbors[4 * static_cast<size_t>(t) + i] = kNoNeighbor; }

  // ---- creation / deletion ----
  // A new tet slot (recycled from the free list or appended) with the given vertices, no neighbours,
  // flags 0. The caller guarantees the orientation convention.
  int32_t newTet(int32_t v0, int32_t v1, int32_t v2, int32_t v3);
  // Append `count` new slots at the end (the free list is not used) and return the first one. Their
  // vertices and neighbours are uninitialized and their flags 0: the caller fills them (fast path for
  // insertion algorithms that write whole tets).
  int32_t appendTets(int32_t count);
  // Drop the slots from `capacity` on (they must be referenced by nothing and not be on the free list;
  // used after appendTets reserved more slots than a parallel stage needed).
  void truncate(int32_t capacity);
  // Take every free slot out of circulation (for TetSlotPools), in ascending order: the free list is then
  // empty; the slots keep their kFree flags and are given back with returnSlot().
  std::vector<int32_t> takeFreeSlots();
  // Put a slot that a TetSlotPool kept out of circulation (appended, or freed by a pooled edit) on the
  // free list: flags kFree, counted free. Its contents are meaningless and nothing references it.
  void returnSlot(int32_t t);
  // Overwrite the vertices of a live tet (adjusts the ghost count).
  void setTetVertices(int32_t t, int32_t v0, int32_t v1, int32_t v2, int32_t v3);
  // Put t on the free list. Neighbours pointing at t are NOT updated (the caller relinks them).
  void freeTet(int32_t t);

  // Free all ghost tets; hull faces get kNoNeighbor. Returns how many were removed.
  int32_t removeGhostTets();
  // Renumber live tets to 0..numTets()-1 (order kept), drop free slots, shrink the arrays.
  // If oldToNew is given it receives the map (-1 for removed slots).
  void compact(std::vector<int32_t>* oldToNew = nullptr);

  // Bytes held by the tet arrays and the points (capacity, not size).
  size_t memoryBytes() const;

  template<class F>
  void forEachTet(F&& f) const
  {
    const int32_t n = tetCapacity();
    for (int32_t t = 0; t < n; ++t)
      if (!(tetFlags[t] & kFree))
        f(t);
  }
  template<class F>
  void forEachFiniteTet(F&& f) const
  {
    const int32_t n = tetCapacity();
    for (int32_t t = 0; t < n; ++t)
    {
      if (tetFlags[t] & kFree)
        continue;
      const int32_t* v = tetVertices.data() + 4 * static_cast<size_t>(t);
      if ((v[0] | v[1] | v[2] | v[3]) >= 0)
        f(t);
    }
  }

  // Internal bookkeeping exposed for fast paths (Delaunay reuses slots in place): callers that change
  // the number of ghosts by writing tetVertices directly must report it here.
  void adjustGhostCount(int32_t delta) { numGhost_ += delta; }
  int32_t freeListHead() const { return freeHead_; }
  // The free list's head and the counters as one value, for an undo log of local edits (EditJournal.h)
  // that restores the slots themselves.
  struct Bookkeeping
  {
    int32_t freeHead, numFree, numGhost;
  };
  Bookkeeping bookkeeping() const { return { freeHead_, numFree_, numGhost_ }; }
  void restoreBookkeeping(const Bookkeeping& b)
  {
    freeHead_ = b.freeHead;
    numFree_ = b.numFree;
    numGhost_ = b.numGhost;
  }

private:
  int32_t freeHead_ = -1;
  int32_t numFree_ = 0;
  int32_t numGhost_ = 0;
};

} // namespace volgrid
