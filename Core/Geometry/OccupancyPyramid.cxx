// OccupancyPyramid: boxes marked coarsely enough to cost at most 8 flags each.
#include "OccupancyPyramid.h"

#include <algorithm>
#include <cmath>

namespace volgrid
{

void OccupancyPyramid::reset(const double lo[3], double size, int finestLevel)
{
  std::copy(lo, lo + 3, lo_);
  size_ = size;
  levels_.assign(static_cast<size_t>(std::clamp(finestLevel, 0, 10)) + 1, {});
  for (size_t l = 0; l < levels_.size(); ++l)
    levels_[l].assign(size_t(1) << (3 * l), 0);
}

size_t OccupancyPyramid::index(int level, int64_t i, int64_t j, int64_t k) const
{
  return static_cast<size_t>(i + (j << level) + (k << (2 * level)));
}

void OccupancyPyramid::markBelow(int level, int64_t i, int64_t j, int64_t k)
{
  for (int l = level - 1; l >= 0; --l)
  {
    i >>= 1, j >>= 1, k >>= 1;
    uint8_t& flags = levels_[l][index(l, i, j, k)];
    if (flags & kBelow)
      return; // its ancestors know already
    flags |= kBelow;
  }
}

int OccupancyPyramid::cellsOf(const double lo[3], const double hi[3], int64_t first[3], int64_t last[3]) const
{
  const int finest = static_cast<int>(levels_.size()) - 1;
  // A margin of a millionth of the cube keeps a box on a cell's face from being missed by rounding.
  const double margin = 1e-6 * size_;
  double extent = 0;
  for (int a = 0; a < 3; ++a)
    extent = std::max(extent, hi[a] - lo[a] + 2 * margin);
  const int level = std::clamp(static_cast<int>(std::floor(std::log2(size_ / extent))), 0, finest);
  const int64_t n = int64_t(1) << level;
  const double cell = size_ / static_cast<double>(n);
  for (int a = 0; a < 3; ++a)
  {
    first[a] = std::clamp(static_cast<int64_t>(std::floor((lo[a] - margin - lo_[a]) / cell)), int64_t(0), n - 1);
    last[a] = std::clamp(static_cast<int64_t>(std::floor((hi[a] + margin - lo_[a]) / cell)), int64_t(0), n - 1);
  }
  return level;
}

void OccupancyPyramid::addBox(const double lo[3], const double hi[3])
{
  int64_t first[3], last[3];
  const int level = cellsOf(lo, hi, first, last);
  for (int64_t k = first[2]; k <= last[2]; ++k)
    for (int64_t j = first[1]; j <= last[1]; ++j)
      for (int64_t i = first[0]; i <= last[0]; ++i)
      {
        levels_[level][index(level, i, j, k)] |= kMarked;
        markBelow(level, i, j, k);
      }
}

bool OccupancyPyramid::occupied(int level, int64_t i, int64_t j, int64_t k) const
{
  if (levels_[level][index(level, i, j, k)] != 0)
    return true;
  for (int l = level - 1; l >= 0; --l)
  {
    i >>= 1, j >>= 1, k >>= 1;
    if (levels_[l][index(l, i, j, k)] & kMarked)
      return true;
  }
  return false;
}

bool OccupancyPyramid::mayOverlap(const double lo[3], const double hi[3]) const
{
  for (int a = 0; a < 3; ++a)
    if (hi[a] < lo_[a] || lo[a] > lo_[a] + size_)
      return false; // outside the cube, where nothing was marked
  int64_t first[3], last[3];
  const int level = cellsOf(lo, hi, first, last);
  for (int64_t k = first[2]; k <= last[2]; ++k)
    for (int64_t j = first[1]; j <= last[1]; ++j)
      for (int64_t i = first[0]; i <= last[0]; ++i)
        if (occupied(level, i, j, k))
          return true;
  return false;
}

} // namespace volgrid
