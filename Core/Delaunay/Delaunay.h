// Exact 3D Delaunay tetrahedralization by Bowyer-Watson insertion.
//
// Unbounded domain: ghost tets, not a super-box. The VolGrid paper starts from a "super-hexahedron"
// (bounding box split into five tets) and inserts the points into it. That box has to be "far enough",
// and however far it is, its corners still change which tets are Delaunay near the convex hull (the
// hull faces are wrong unless the box is infinitely far). Instead we use a vertex at infinity
// (TetMesh::kGhostVertex) and one ghost tet per convex-hull face (see TetMesh.h): finite + ghost tets
// triangulate all of space, so every point, inside or outside the current hull, is inserted by the same
// cavity algorithm, and the result is exactly the Delaunay triangulation of the input points, with no
// extra vertices to remove afterwards.
//
// Exactness: all decisions use predicates::orient3d and predicates::insphereSoS (Simulation of
// Simplicity with the vertex ids), so the result is the unique SoS-Delaunay triangulation of the points:
// it does not depend on the insertion order, also for cospherical inputs such as regular grids.
//   A finite tet is in conflict with p when insphereSoS(tet, p) > 0. A ghost tet (hull face abc, seen
//   positively from infinity) is in conflict when orient3d(a,b,c,p) > 0 (p strictly outside that face)
//   or, when p is coplanar with abc, when p is in conflict with the finite tet across abc (for a point
//   on the plane of abc that test only depends on a,b,c,p, so it is a consistent 2D rule).
// The cavity (tets in conflict, grown by adjacency from the tet containing p) is star-shaped from p and
// is replaced by the tets joining p to its boundary faces, reusing the freed slots.
//
// Speed: points are inserted in BRIO rounds along a Hilbert curve (SpatialSort.h) and stored in that
// order during the construction (vertex ids are restored at the end; SoS uses the input ids); point
// location is a visibility walk from the new tet closest to the next point; the cavity is found
// breadth-first with prefetching, marked in the neighbour words, and the new tets reuse its slots and
// are glued by a small matrix of boundary edges. The hot predicates are inline filters falling back to
// Core/Geometry/Predicates.h; lattice inputs (grids) evaluate exactly in doubles. Large inputs use all
// threads asked for (DelaunayParallel.cxx; the result does not depend on their number).
//
// Duplicates: points with exactly equal coordinates are merged into the first occurrence (lowest
// input index) and reported. Mesh vertex i is input point i; merged duplicates stay in mesh.points but
// no tet uses them.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "TetMesh.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace volgrid
{

enum class PointLocation
{
  Walk,      // visibility walk from the last created tet (best with spatially sorted insertion)
  BucketGrid // the paper's octree idea: a bucket grid of inserted vertices gives a nearby start vertex
};

struct DelaunayOptions
{
  bool spatialSort = true; // BRIO + Hilbert order; false = input order
  PointLocation location = PointLocation::Walk;
  uint64_t seed = 0x766f6c67726964ull; // BRIO rounds and walk randomization
  bool keepGhosts = true;              // false: removeGhostTets() at the end (hull faces -> no neighbour)
  // Threads for large inputs (>= 200k distinct points, spatialSort, Walk): 1 = sequential, n = n
  // threads (more than the cores is allowed; at most 255 are used), 0 = all cores (ParallelFor.h).
  int threads = 0;
  // Tet numbering. The same input and options give the same mesh arrays, whatever the thread count and
  // from run to run: inputs large enough for the parallel construction (the conditions above, whatever
  // `threads` says) are renumbered canonically (DelaunayCanonical.cxx: earliest inserted vertex first in
  // each tet by an even rotation, tets grouped by their last inserted vertex, then by vertex list, no
  // free slots); smaller ones are always built sequentially and keep the construction's numbering.
  // true: canonical numbering for every input. Cost of the renumbering: ~5-10% of the construction,
  // and the peak stays within 60 bytes per tet (1M random points: ~56 one thread, ~58 two or eight threads).
  bool canonicalNumbering = false;
};

struct DelaunayReport
{
  size_t numInput = 0;
  size_t numVertices = 0;               // distinct points inserted
  size_t numDuplicates = 0;             // input points merged into an earlier identical point
  std::vector<int64_t> firstDuplicates; // first few duplicate input ids
  // Work counters (for tuning/benchmarks).
  uint64_t walkSteps = 0;
  uint64_t cavityTets = 0;
  uint64_t deferred = 0; // parallel construction: insertions that met another worker, redone after their round
};

// Build the Delaunay tetrahedralization of n points (xyz: 3 doubles per point).
// On success: mesh holds vertices 0..n-1 (= input points) and the tets (with ghosts unless
// !options.keepGhosts); inputToVertex[i] is the mesh vertex of input point i (i itself, or the first
// identical point). Errors: EmptyInput, NonFinitePoint, DegenerateInput (all points coplanar),
// InvalidOption (too many points), Cancelled.
Status buildDelaunay(const double* xyz, size_t n, const DelaunayOptions& options, TetMesh& mesh,
                     std::vector<int32_t>& inputToVertex, Progress* progress = nullptr,
                     DelaunayReport* report = nullptr);

// Incremental insertion into an existing Delaunay mesh WITH ghost tets (as built by buildDelaunay with
// keepGhosts). Keeps reusable buffers, so create one per stage and insert many points with it.
class DelaunayInserter
{
public:
  explicit DelaunayInserter(TetMesh& mesh, uint64_t seed = 1);
  ~DelaunayInserter();
  DelaunayInserter(const DelaunayInserter&) = delete;
  DelaunayInserter& operator=(const DelaunayInserter&) = delete;

  // A tet whose closure contains p (finite tet), or a ghost tet whose hull face sees p strictly
  // (p outside the hull). hint: a live tet to start from, or -1 for the last tet created.
  int32_t locate(const double* p, int32_t hint = -1);

  struct Result
  {
    int32_t tet = -1;         // a tet incident to the inserted vertex (or to the duplicate)
    int32_t duplicateOf = -1; // >= 0: the point equals this existing vertex, nothing was inserted
    bool aborted = false;     // internal (parallel construction): not inserted, retry later
  };
  // Insert mesh vertex v (its coordinates already in mesh.points, e.g. from mesh.addPoint) and restore
  // the Delaunay property. v must not be used by any tet yet. `next` (optional): where the next point
  // to insert is, so that lastTet() becomes the new tet closest to it (shorter next walk).
  Result insert(int32_t v, int32_t hint = -1, const double* next = nullptr);

  // Optional bucket-grid point location (PointLocation::BucketGrid): box of all points to come and the
  // expected number of vertices. Inserted vertices are registered automatically.
  void enableBucketGrid(const double lo[3], const double hi[3], size_t expectedVertices);
  // Register an existing mesh vertex in the bucket grid (only needed for vertices not inserted by this
  // inserter) with a tet incident to it.
  void registerVertex(int32_t v, int32_t tet);

  // Simulation of Simplicity ids of the vertices (ids[v] for vertex v; must outlive the inserter).
  // Default (nullptr): the vertex ids themselves. Lets a caller store vertices in another order than the
  // ids that define the unique triangulation.
  void setSoSIds(const int32_t* ids);

  int32_t lastTet() const;
  uint64_t walkSteps() const;
  uint64_t cavityTets() const;

private:
  friend Status buildDelaunay(const double*, size_t, const DelaunayOptions&, TetMesh&, std::vector<int32_t>&, Progress*,
                              DelaunayReport*);
  friend Status insertParallel(TetMesh&, DelaunayInserter&, const std::vector<int32_t>&, const std::vector<size_t>&,
                               size_t, const int32_t*, std::vector<int32_t>&, std::vector<int32_t>&, DelaunayReport&,
                               Progress*, uint64_t, int);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Build the first tet (a,b,c,d must be affinely independent, any orientation) and its four ghosts in an
// empty mesh whose points are already set. Returns the finite tet.
int32_t initDelaunayTet(TetMesh& mesh, int32_t a, int32_t b, int32_t c, int32_t d);

} // namespace volgrid
