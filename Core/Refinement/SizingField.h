// Sizing field: the target edge length h(p) everywhere in space (paper sections 2 and 7.2).
//
//   1. Point distribution function (paper eq. 3): at every boundary point, the mean length of the
//      distinct surface edges incident to it (pointDistributionFunction()).
//   2. Sized nodes: the boundary points with their PDF, plus optional user nodes with a target size
//      (clustering points with a size: they densify their neighbourhood).
//   3. Optional user sizes: a callback h_user(p) and/or a background point cloud with one size per point
//      (e.g. a VTK data set's point-data array: a coarse background mesh, a CFD solution's error estimate),
//      interpolated linearly over the cloud's Delaunay tetrahedralization. Each node's size becomes
//      min(own size, user sizes at the node).
//   4. Gradation (Dijkstra-like limiting over the edges of the Delaunay tetrahedralization of the nodes):
//      h(v) <= h(u) + (G - 1) |uv| for every background edge, G = SizingOptions::gradation. Two neighbours
//      one size apart thus differ by at most the factor G. The limited value is the largest one that
//      satisfies all the bounds: h(v) = min_u (h0(u) + (G-1) d(u, v)), d the shortest path along edges.
//   5. Query: h(p) = barycentric interpolation over the background tet containing p (outside the nodes'
//      hull: linear interpolation at the point of the hull nearest p), then
//      min(h, callback(p), cloud(p), maxEdgeLength), max(h, minEdgeLength).
// The user sizes are not graded between nodes (only at the nodes): a user field is taken as given.
//
// evaluate(p) walks the background mesh from the last query (spatially coherent queries are cheap); it is
// therefore not thread-safe. evaluate(p, walk) walks from the caller's own Walk instead, so threads with a
// Walk each may query at once when evaluatesWithWalks() (no user function, or a thread-safe one; the
// sampling octree, OctreeSizing.h, does so). Without any walk, evaluatesConcurrently() tells: a uniform
// field whose only user input is a function declared thread-safe (e.g. an OctreeSizing lookup,
// DomainSizing.h).
#pragma once

#include "OptionTable.h"
#include "Progress.h"
#include "Status.h"
#include "TetMesh.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace volgrid
{

class CoarseBoundaryFloor;

struct SizingOptions
{
  // Size growth bound between neighbours: h(v) <= h(u) + (gradation - 1) |uv|. Values <= 1 disable it.
  double gradation = option::gradation.defaultValue;
  // Global bounds on the target edge length (0 = none).
  double maxEdgeLength = 0;
  double minEdgeLength = 0;
  // Multiplies the boundary PDF (< 1 gives a finer volume grid than the surface suggests).
  double scale = option::sizeScale.defaultValue;
};

// Piecewise-linear interpolation of scattered values over the Delaunay tetrahedralization of their points.
// Fewer than four affinely independent points: the nearest point's value.
class LinearInterpolant
{
public:
  LinearInterpolant();
  ~LinearInterpolant();
  LinearInterpolant(LinearInterpolant&&) noexcept;
  LinearInterpolant& operator=(LinearInterpolant&&) noexcept;

  // n points (xyz), one finite value each. Identical points keep the smallest value.
  Status build(const double* xyz, size_t n, const double* values, Progress* progress = nullptr);
  bool empty() const { return values_.empty(); }
  // The value at p, walking from the tet of the last query.
  double evaluate(const double* p) const;
  // The same, walking from `hint` (a tet of an earlier query, or -1), which is set to the tet p lies in:
  // callers with hints of their own may query at once. The value depends on the start only where p lies on
  // a face of the background mesh, or outside it where its nearest point is on several hull faces (then
  // either face's or tet's weights, equal up to rounding).
  double evaluate(const double* p, int32_t& hint) const;

  // The background mesh (with ghosts) and the value per mesh vertex, for the gradation and the tests.
  TetMesh& mesh() { return mesh_; }
  const TetMesh& mesh() const { return mesh_; }
  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  bool degenerate() const { return degenerate_; }

private:
  double outsideHull(const double* p, int32_t ghost, int32_t& hint) const;
  TetMesh mesh_;
  std::vector<double> values_;
  bool degenerate_ = false;
  struct Locator;
  std::unique_ptr<Locator> locator_;
};

// Paper eq. 3: per point, the mean length of the distinct triangle edges incident to it. Points used by no
// triangle get 0.
std::vector<double> pointDistributionFunction(const double* points, int32_t numPoints, const int32_t* triangles,
                                              int32_t numTriangles);

class SizingField
{
public:
  using Function = std::function<double(const double* xyz)>;

  // Optional user inputs; set them before build().
  // threadSafe: f may be called from several threads at once (see evaluatesConcurrently()).
  void setUserFunction(Function f, bool threadSafe = false)
  {
    user_ = std::move(f);
    userThreadSafe_ = threadSafe;
  }
  // Background cloud of sizes (copied). Non-finite or non-positive sizes are ignored.
  void setBackgroundCloud(const double* xyz, const double* sizes, size_t n);
  // Extra sized nodes (clustering points with a target size). Non-finite or non-positive sizes ignored.
  void addSizedPoints(const double* xyz, const double* sizes, size_t n);
  // A floor under the size cap (CoarseBoundaryFloor.h): the cap at p becomes max(maxEdgeLength, floor(p)).
  // A cap that varies in space also caps the nodes before the gradation (a constant one needs not: the
  // graded field capped afterwards is the same).
  void setCapFloor(std::shared_ptr<const CoarseBoundaryFloor> floor) { capFloor_ = std::move(floor); }

  // Build from the boundary surface (points and triangles; points used by no triangle are ignored).
  // Errors: EmptyInput (no triangle and no sized point), InvalidOption (bad option values).
  Status build(const double* points, int32_t numPoints, const int32_t* triangles, int32_t numTriangles,
               const SizingOptions& options, Progress* progress = nullptr);

  // A uniform field (no surface): h = size everywhere, with the same caps and user inputs.
  Status buildUniform(double size, const SizingOptions& options);

  // Where a caller's last queries ended in each background mesh (-1: not yet).
  struct Walk
  {
    int32_t graded = -1, cloud = -1, floor = -1;
  };
  double evaluate(const double* p) const { return evaluate(p, walk_); }
  double evaluate(const double* p, Walk& walk) const;
  double operator()(const double* p) const { return evaluate(p); }
  // Whether evaluate(p, walk) may be called from several threads at once, each with its own Walk.
  bool evaluatesWithWalks() const { return !user_ || userThreadSafe_; }
  // Whether evaluate() may be called from several threads at once: no interpolant walks (no graded
  // nodes, no background cloud) and no user function other than a thread-safe one.
  bool evaluatesConcurrently() const
  {
    return graded_.empty() && cloud_.empty() && !capFloor_ && (!user_ || userThreadSafe_);
  }

  // The graded interpolant (nodes = boundary points + sized points) and the options used.
  const LinearInterpolant& nodes() const { return graded_; }
  const SizingOptions& options() const { return options_; }
  // Smallest and largest node size.
  double minNodeSize() const { return minNode_; }
  double maxNodeSize() const { return maxNode_; }

private:
  double userSize(const double* p, Walk& walk) const;
  double capAt(const double* p, Walk& walk) const; // the cap, raised by the floor (infinite: none)
  SizingOptions options_;
  Function user_;
  bool userThreadSafe_ = false;
  std::shared_ptr<const CoarseBoundaryFloor> capFloor_;
  mutable Walk walk_; // evaluate(p)'s
  std::vector<double> cloudXYZ_, cloudSize_;
  std::vector<double> extraXYZ_, extraSize_;
  LinearInterpolant cloud_;
  LinearInterpolant graded_;
  double uniform_ = 0;
  double minNode_ = 0, maxNode_ = 0;
};

// Gradation limiting on a tet mesh's edges (the finite tets): sizes[v] <= sizes[u] + slope * |uv| for every
// edge, by Dijkstra from the smallest sizes. Vertices with a non-finite or non-positive size are left out.
void limitGradation(const TetMesh& mesh, double slope, std::vector<double>& sizes);

} // namespace volgrid
