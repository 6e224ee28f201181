// A sizing field sampled on an adaptive octree over a box, with trilinear interpolation in the leaves: what
// the field points query (DomainSizing.h). They ask for the size at tet centroids in an order that jumps
// around the domain, and each query of the background interpolant (SizingField) walks its mesh from the
// previous one; the octree answers in O(depth) wherever the query is.
//
// A cell is split while it is larger than 1.5 times the smallest size at its corners and centre, so that
// leaves are about the local size and the interpolation follows the field closely. Without a cap on the
// cell count, every order splits the same cells, so the tree is built a level at a time, the cells of a
// level on all threads (each cell's samples walk the field from where its parent's centre did:
// SizingField::Walk), and it is the same for any thread count. Under a cap, cells are split
// most-oversized first (size over that smallest size), one after the other: the cells left unsplit are
// then the least oversized ones, wherever they are. (Breadth first, a size cap that fills a large far field
// with cells used up the cap before the boundary's small sizes were reached, and the sizes near a wall
// were interpolated from far away.) A level that would pass the cap starts the build again in that order,
// with the splits the levels made (the cells next in the order are split in batches on the threads, and
// taken one after the other: the same tree as one at a time); a field that only one thread may query (a
// user function not declared thread-safe) is built in that order from the start.
//
// Only cells where the domain is are split (`where`, the boxes of the domain's tets): the cube around a
// body is mostly outside it, and the surface's small sizes, interpolated there, would otherwise ask for
// cells that no query reaches (a dinosaur of 20k tets filled the cap of a million cells; now it needs 0.6
// million).
#pragma once

#include "OccupancyPyramid.h"
#include "Progress.h"
#include "SizingField.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class OctreeSizing
{
public:
  // Samples `field` over the cube [lo, lo + size]^3, at most maxDepth levels deep and maxCells cells,
  // splitting only cells that `where` may overlap (every cell when null), on `threads` threads (the rule of
  // ParallelFor.h). progress (optional) is asked about every 1024 splits whether to stop (then cancelled()
  // is true and the tree is unfinished).
  void build(const SizingField& field, const double lo[3], double size, int maxDepth, size_t maxCells,
             const OccupancyPyramid* where = nullptr, Progress* progress = nullptr, int threads = 1);
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
  // A cell's state while the tree is built: where it is, how deep, the size at its centre, and where the
  // walk that sampled its centre ended.
  struct Unsplit
  {
    std::array<double, 3> origin;
    int depth = 0;
    double centreSize = 0;
    SizingField::Walk walk;
  };
  struct Building;

  // How oversized a cell is (its size over the smallest size at its corners and centre) when the rule above
  // splits it, else 0.
  double splitPriority(const Cell& cell, const Unsplit& u, const Building& b) const;
  // The state of the cell at (origin, depth), its centre sampled with `walk`.
  static Unsplit sampleCentre(const std::array<double, 3>& origin, int depth, const SizingField& field,
                              SizingField::Walk& walk, const Building& b);
  // Writes the eight children of cell (state u) to children[0..7] and their states to states[0..7], their
  // corner sizes from the 3x3x3 lattice of their corners (the parent's corners and centre are known). The
  // samples walk on from the parent's centre, so they depend on the cell alone, not on the order of splits.
  static void splitInto(const Cell& cell, const Unsplit& u, const SizingField& field, const Building& b, Cell* children,
                        Unsplit* states);
  // A split made before it was taken: the children and their states (madeFirst: where the level build
  // put them, -1 when made here).
  struct Split
  {
    int32_t cell = -1;
    bool made = false;
    int32_t madeFirst = -1;
    Cell children[8];
    Unsplit states[8];
  };
  // The cells and states of a level build that stopped at the cap.
  struct SplitCache
  {
    std::vector<Cell> cells;
    std::vector<Unsplit> states;
  };
  // The level-at-a-time build (states: per cell); false when a level would pass the cap (the cells and
  // states made until then stay, for the other order to take).
  bool buildByLevels(const SizingField& field, const Building& b, const Unsplit& root, Progress* progress, int threads,
                     std::vector<Unsplit>& states);
  void buildByPriority(const SizingField& field, const Building& b, const Unsplit& root, Progress* progress,
                       int threads, const SplitCache& made);

  std::vector<Cell> cells_;
  double lo_[3] = { 0, 0, 0 };
  double size_ = 1;
  bool capped_ = false;
  bool cancelled_ = false;
};

} // namespace volgrid
