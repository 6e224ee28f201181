#include "RegionBoxes.h"

#include <algorithm>

namespace volgrid
{

RegionBoxes::RegionBoxes(const std::vector<double>& xyz, int regions)
  : split_(static_cast<size_t>(std::max(1, regions) - 1))
{
  std::vector<int32_t> ids(xyz.size() / 3);
  for (size_t i = 0; i < ids.size(); ++i)
    ids[i] = static_cast<int32_t>(i);
  build(xyz, ids.begin(), ids.end(), 0);
}

// Node i's children are 2i+1 and 2i+2.
void RegionBoxes::build(const std::vector<double>& xyz, Iter begin, Iter end, size_t node)
{
  if (node >= split_.size())
    return;
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (Iter i = begin; i != end; ++i)
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], xyz[3 * static_cast<size_t>(*i) + k]);
      hi[k] = std::max(hi[k], xyz[3 * static_cast<size_t>(*i) + k]);
    }
  Split& s = split_[node];
  s.axis = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[s.axis] - lo[s.axis])
      s.axis = k;
  auto coordinate = [&](int32_t i) { return xyz[3 * static_cast<size_t>(i) + s.axis]; };
  Iter mid = begin + (end - begin) / 2;
  if (begin != end)
  {
    std::nth_element(begin, mid, end, [&](int32_t a, int32_t b) { return coordinate(a) < coordinate(b); });
    s.at = coordinate(*mid);
  }
  // The children get the points as regionOf() sends them.
  mid = std::partition(begin, end, [&](int32_t i) { return coordinate(i) < s.at; });
  build(xyz, begin, mid, 2 * node + 1);
  build(xyz, mid, end, 2 * node + 2);
}

} // namespace volgrid
