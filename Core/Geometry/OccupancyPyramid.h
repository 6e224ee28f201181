// Which parts of a cube a set of boxes may overlap, answered for any box in O(levels). Conservative: a box
// that some added box overlaps is never reported empty; a box near one may be reported occupied.
//
// A pyramid of flag grids, level l with 2^l cells per axis. A box is marked on the finest level where it
// spans at most two cells per axis (at most 8 cells, however large the box), and every ancestor of a marked
// cell notes that something below it is marked. A box is asked about the same way: on the finest level
// where it spans at most two cells per axis, those cells are occupied when they or a descendant are
// marked, or when an ancestor is (a large box marked coarsely).
//
// The sizing octree uses it to split only the cells that the domain's tets can query (OctreeSizing.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class OccupancyPyramid
{
public:
  // The cube [lo, lo + size]^3 with levels 0..finestLevel (at most 10), nothing marked.
  void reset(const double lo[3], double size, int finestLevel);
  // Marks the box [lo, hi] (clipped to the cube).
  void addBox(const double lo[3], const double hi[3]);
  // Whether some added box may overlap the box [lo, hi].
  bool mayOverlap(const double lo[3], const double hi[3]) const;

private:
  enum : uint8_t
  {
    kMarked = 1, // a box was marked on this cell
    kBelow = 2,  // a box was marked on a descendant
  };
  size_t index(int level, int64_t i, int64_t j, int64_t k) const;
  // The finest level where [lo, hi] spans at most two cells per axis, and the range of those cells.
  int cellsOf(const double lo[3], const double hi[3], int64_t first[3], int64_t last[3]) const;
  bool occupied(int level, int64_t i, int64_t j, int64_t k) const;
  void markBelow(int level, int64_t i, int64_t j, int64_t k);

  std::vector<std::vector<uint8_t>> levels_;
  double lo_[3] = { 0, 0, 0 };
  double size_ = 1;
};

} // namespace volgrid
