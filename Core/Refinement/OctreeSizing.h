// A sizing field sampled on an adaptive octree over a box, with trilinear interpolation in the leaves: what
// the field points query (DomainSizing.h). They ask for the size at tet centroids in an order that jumps
// around the domain, and each query of the background interpolant (SizingField) walks its mesh from the
// previous one; the octree answers in O(depth) wherever the query is.
//
// A cell is split while it is larger than 1.5 times the smallest size at its corners and centre, so that
// leaves are about the local size and the interpolation follows the field closely. Under a cap on the cell
// count, cells are split most-oversized first (size over that smallest size): the cells left unsplit are
// then the least oversized ones, wherever they are. (Breadth first, a size cap that fills a large far field
// with cells used up the cap before the boundary's small sizes were reached, and the sizes near a wall
// were interpolated from far away.) Without the cap, every order splits the same cells.
//
// Only cells where the domain is are split (`where`, the boxes of the domain's tets): the cube around a
// body is mostly outside it, and the surface's small sizes, interpolated there, would otherwise ask for
// cells that no query reaches (a dinosaur of 20k tets filled the cap of a million cells; now it needs 0.6
// million).
#pragma once

#include "OccupancyPyramid.h"
#include "Progress.h"
#include "SizingField.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class OctreeSizing
{
public:
  // Samples `field` over the cube [lo, lo + size]^3, at most maxDepth levels deep and maxCells cells,
  // splitting only cells that `where` may overlap (every cell when null). progress (optional) is asked every
  // 1024 splits whether to stop (then cancelled() is true and the tree is unfinished).
  void build(const SizingField& field, const double lo[3], double size, int maxDepth, size_t maxCells,
             const OccupancyPyramid* where = nullptr, Progress* progress = nullptr);
  bool cancelled() const { return cancelled_; }
  // The interpolated size at p (clamped to the cube).
  double evaluate(const double* p) const;
  size_t cells() const { return cells_.size(); }
  // Whether cells that asked to be split were left for the cap.
  bool capped() const { return capped_; }

private:
  struct Cell
  {
    float h[8]; // the size at its corners, x fastest
    int32_t child = -1;
  };
  struct Building; // the per-cell state of build()

  void split(size_t cell, Building& b, const SizingField& field);

  std::vector<Cell> cells_;
  double lo_[3] = { 0, 0, 0 };
  double size_ = 1;
  bool capped_ = false;
  bool cancelled_ = false;
};

} // namespace volgrid
