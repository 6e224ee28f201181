// OctreeSizing: the most oversized cell split first, children appended as groups of eight siblings.
#include "OctreeSizing.h"

#include <algorithm>
#include <array>
#include <queue>
#include <utility>

namespace volgrid
{

struct OctreeSizing::Building
{
  std::vector<std::array<double, 3>> origin;
  std::vector<int> depth;
  std::vector<double> centreSize;
  // (size over the smallest size at its corners and centre, -cell): the most oversized first, ties by cell.
  std::priority_queue<std::pair<double, int32_t>> queue;
  double rootSize = 1;
  int maxDepth = 0;

  double cellSize(size_t c) const { return rootSize / static_cast<double>(1u << depth[c]); }
};

void OctreeSizing::build(const SizingField& field, const double lo[3], double size, int maxDepth, size_t maxCells,
                         const OccupancyPyramid* where, Progress* progress)
{
  cancelled_ = false;
  std::copy(lo, lo + 3, lo_);
  size_ = size;
  cells_.assign(1, Cell());
  for (int k = 0; k < 8; ++k)
  {
    const double p[3] = { lo[0] + ((k & 1) ? size : 0), lo[1] + ((k & 2) ? size : 0), lo[2] + ((k & 4) ? size : 0) };
    cells_[0].h[k] = static_cast<float>(field.evaluate(p));
  }
  Building b;
  b.origin = { { lo[0], lo[1], lo[2] } };
  b.depth = { 0 };
  b.rootSize = size;
  b.maxDepth = maxDepth;
  const auto queueIfOversized = [&](size_t c)
  {
    const double cs = b.cellSize(c);
    const double centre[3] = { b.origin[c][0] + cs / 2, b.origin[c][1] + cs / 2, b.origin[c][2] + cs / 2 };
    b.centreSize.resize(cells_.size());
    b.centreSize[c] = field.evaluate(centre);
    double hmin = b.centreSize[c];
    for (int k = 0; k < 8; ++k)
      hmin = std::min(hmin, static_cast<double>(cells_[c].h[k]));
    const double hi[3] = { b.origin[c][0] + cs, b.origin[c][1] + cs, b.origin[c][2] + cs };
    if (b.depth[c] < maxDepth && cs > 1.5 * hmin && (!where || where->mayOverlap(b.origin[c].data(), hi)))
      b.queue.push({ cs / hmin, -static_cast<int32_t>(c) });
  };
  queueIfOversized(0);
  for (size_t splits = 0; !b.queue.empty() && cells_.size() + 8 <= maxCells; ++splits)
  {
    if ((splits & 1023) == 1023 && progress && progress->cancelled())
    {
      cancelled_ = true;
      return;
    }
    const size_t c = static_cast<size_t>(-b.queue.top().second);
    b.queue.pop();
    split(c, b, field);
    for (int k = 0; k < 8; ++k)
      queueIfOversized(static_cast<size_t>(cells_[c].child + k));
  }
  capped_ = !b.queue.empty();
}

// Appends the eight children of `cell`, their corner sizes from the 3x3x3 lattice of their corners (the
// parent's corners and centre are known).
void OctreeSizing::split(size_t cell, Building& b, const SizingField& field)
{
  const double cs = b.cellSize(cell);
  const std::array<double, 3> o = b.origin[cell];
  float grid[27];
  for (int l = 0; l < 27; ++l)
  {
    const int i = l % 3, j = (l / 3) % 3, m = l / 9;
    if (i != 1 && j != 1 && m != 1)
      grid[l] = cells_[cell].h[(i / 2) | ((j / 2) << 1) | ((m / 2) << 2)];
    else if (i == 1 && j == 1 && m == 1)
      grid[l] = static_cast<float>(b.centreSize[cell]);
    else
    {
      const double p[3] = { o[0] + i * cs / 2, o[1] + j * cs / 2, o[2] + m * cs / 2 };
      grid[l] = static_cast<float>(field.evaluate(p));
    }
  }
  cells_[cell].child = static_cast<int32_t>(cells_.size());
  for (int k = 0; k < 8; ++k)
  {
    const int bx = k & 1, by = (k >> 1) & 1, bz = (k >> 2) & 1;
    Cell child;
    for (int n = 0; n < 8; ++n)
      child.h[n] = grid[(bx + (n & 1)) + 3 * (by + ((n >> 1) & 1)) + 9 * (bz + ((n >> 2) & 1))];
    cells_.push_back(child);
    b.origin.push_back({ o[0] + bx * cs / 2, o[1] + by * cs / 2, o[2] + bz * cs / 2 });
    b.depth.push_back(b.depth[cell] + 1);
  }
}

double OctreeSizing::evaluate(const double* p) const
{
  double u[3];
  for (int k = 0; k < 3; ++k)
    u[k] = std::clamp((p[k] - lo_[k]) / size_, 0.0, 1.0);
  int32_t c = 0;
  while (cells_[c].child >= 0)
  {
    int k = 0;
    for (int a = 0; a < 3; ++a)
    {
      u[a] *= 2;
      if (u[a] >= 1)
      {
        k |= 1 << a;
        u[a] -= 1;
      }
    }
    c = cells_[c].child + k;
  }
  const float* h = cells_[c].h;
  double r = 0;
  for (int k = 0; k < 8; ++k)
    r += h[k] * ((k & 1) ? u[0] : 1 - u[0]) * ((k & 2) ? u[1] : 1 - u[1]) * ((k & 4) ? u[2] : 1 - u[2]);
  return r;
}

} // namespace volgrid
