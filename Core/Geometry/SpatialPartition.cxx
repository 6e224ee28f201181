#include "SpatialPartition.h"

#include <algorithm>
#include <numeric>

namespace volgrid
{
namespace
{
struct Bisector
{
  const double* xyz;
  std::vector<int32_t>& part;

  // The axis along which the points ids[begin, end) spread the most.
  int longestAxis(const std::vector<int64_t>& ids, int64_t begin, int64_t end) const
  {
    double lo[3] = { xyz[3 * ids[begin]], xyz[3 * ids[begin] + 1], xyz[3 * ids[begin] + 2] };
    double hi[3] = { lo[0], lo[1], lo[2] };
    for (int64_t k = begin; k < end; ++k)
    {
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], xyz[3 * ids[k] + a]);
        hi[a] = std::max(hi[a], xyz[3 * ids[k] + a]);
      }
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      axis = hi[a] - lo[a] > hi[axis] - lo[axis] ? a : axis;
    return axis;
  }

  // Parts [firstPart, firstPart + parts) for the points ids[begin, end).
  void split(std::vector<int64_t>& ids, int64_t begin, int64_t end, int firstPart, int parts)
  {
    if (parts <= 1 || end - begin <= 1)
    {
      for (int64_t k = begin; k < end; ++k)
        part[ids[k]] = firstPart;
      return;
    }
    const int lowParts = parts / 2;
    const int64_t mid = begin + (end - begin) * lowParts / parts;
    const int axis = this->longestAxis(ids, begin, end);
    // Ties on the coordinate are broken by the id, so that the cut is unique.
    std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end,
                     [&](int64_t a, int64_t b)
                     {
                       const double ca = xyz[3 * a + axis], cb = xyz[3 * b + axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    this->split(ids, begin, mid, firstPart, lowParts);
    this->split(ids, mid, end, firstPart + lowParts, parts - lowParts);
  }
};
} // namespace

std::vector<int32_t> bisectionPartition(const double* xyz, int64_t n, int parts)
{
  std::vector<int32_t> part(static_cast<size_t>(std::max<int64_t>(n, 0)), 0);
  if (n <= 0 || parts <= 1)
    return part;
  std::vector<int64_t> ids(static_cast<size_t>(n));
  std::iota(ids.begin(), ids.end(), int64_t(0));
  Bisector bisector{ xyz, part };
  bisector.split(ids, 0, n, 0, parts);
  return part;
}

} // namespace volgrid
