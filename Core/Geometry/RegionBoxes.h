// Boxes of space holding about equal shares of a set of points (tet centroids), for threads that edit one
// box of a mesh each (FieldPointRegions.h, RegionFlips.h): a k-d tree of `regions` leaves (a power of two).
// Each cut halves a node's points at their median across the longest side of their bounding box. The
// boxes depend on the points alone (never on a thread count).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

class RegionBoxes
{
public:
  // xyz: 3 coordinates per point. regions: a power of two from 1 to 256.
  RegionBoxes(const std::vector<double>& xyz, int regions);
  // The box holding p, in [0, regions).
  uint8_t regionOf(const double* p) const
  {
    size_t node = 0;
    while (node < split_.size())
      node = 2 * node + (p[split_[node].axis] < split_[node].at ? 1 : 2);
    return static_cast<uint8_t>(node - split_.size());
  }

private:
  struct Split
  {
    int axis = 0;
    double at = 0;
  };
  using Iter = std::vector<int32_t>::iterator;
  void build(const std::vector<double>& xyz, Iter begin, Iter end, size_t node);
  std::vector<Split> split_;
};

} // namespace volgrid
