// OctreeSizing: a level at a time on the threads, or the most oversized cell first under a cap; children
// appended as groups of eight siblings.
#include "OctreeSizing.h"

#include "ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <queue>
#include <unordered_map>
#include <utility>

namespace volgrid
{

namespace
{
constexpr size_t kCellsPerChunk = 64; // a level's cells are split in chunks of this many, one thread each
constexpr size_t kBatch = 1024;       // at most this many cells split at once in the most-oversized order
} // namespace

struct OctreeSizing::Building
{
  double rootSize = 1;
  int maxDepth = 0;
  size_t maxCells = 0;
  const OccupancyPyramid* where = nullptr;

  double cellSize(int depth) const { return rootSize / static_cast<double>(1u << depth); }
};

void OctreeSizing::build(const SizingField& field, const double lo[3], double size, int maxDepth, size_t maxCells,
                         const OccupancyPyramid* where, Progress* progress, int threads)
{
  cancelled_ = false;
  capped_ = false;
  std::copy(lo, lo + 3, lo_);
  size_ = size;
  cells_.assign(1, Cell());
  SizingField::Walk walk;
  for (int k = 0; k < 8; ++k)
  {
    const double p[3] = { lo[0] + ((k & 1) ? size : 0), lo[1] + ((k & 2) ? size : 0), lo[2] + ((k & 4) ? size : 0) };
    cells_[0].h[k] = static_cast<float>(field.evaluate(p, walk));
  }
  Building b;
  b.rootSize = size;
  b.maxDepth = maxDepth;
  b.maxCells = maxCells;
  b.where = where;
  const Unsplit root = sampleCentre({ lo[0], lo[1], lo[2] }, 0, field, walk, b);
  std::vector<Unsplit> states; // per cell of the level build
  if (field.evaluatesWithWalks() && buildByLevels(field, b, root, progress, threads, states))
    return;
  // Past the cap: the splits the levels made are taken again where the order wants them.
  const SplitCache made{ std::move(cells_), std::move(states) };
  cells_.assign(1, made.cells.empty() ? Cell() : made.cells[0]);
  cells_[0].child = -1;
  buildByPriority(field, b, root, progress, threads, made);
}

double OctreeSizing::splitPriority(const Cell& cell, const Unsplit& u, const Building& b) const
{
  const double cs = b.cellSize(u.depth);
  double hmin = u.centreSize;
  for (int k = 0; k < 8; ++k)
    hmin = std::min(hmin, static_cast<double>(cell.h[k]));
  const double hi[3] = { u.origin[0] + cs, u.origin[1] + cs, u.origin[2] + cs };
  if (u.depth < b.maxDepth && cs > 1.5 * hmin && (!b.where || b.where->mayOverlap(u.origin.data(), hi)))
    return cs / hmin;
  return 0;
}

OctreeSizing::Unsplit OctreeSizing::sampleCentre(const std::array<double, 3>& origin, int depth,
                                                 const SizingField& field, SizingField::Walk& walk, const Building& b)
{
  const double cs = b.cellSize(depth);
  const double centre[3] = { origin[0] + cs / 2, origin[1] + cs / 2, origin[2] + cs / 2 };
  Unsplit u;
  u.origin = origin;
  u.depth = depth;
  u.centreSize = field.evaluate(centre, walk);
  u.walk = walk;
  return u;
}

void OctreeSizing::splitInto(const Cell& cell, const Unsplit& u, const SizingField& field, const Building& b,
                             Cell* children, Unsplit* states)
{
  const double cs = b.cellSize(u.depth);
  const std::array<double, 3>& o = u.origin;
  SizingField::Walk walk = u.walk;
  float grid[27];
  for (int l = 0; l < 27; ++l)
  {
    const int i = l % 3, j = (l / 3) % 3, m = l / 9;
    if (i != 1 && j != 1 && m != 1)
      grid[l] = cell.h[(i / 2) | ((j / 2) << 1) | ((m / 2) << 2)];
    else if (i == 1 && j == 1 && m == 1)
      grid[l] = static_cast<float>(u.centreSize);
    else
    {
      const double p[3] = { o[0] + i * cs / 2, o[1] + j * cs / 2, o[2] + m * cs / 2 };
      grid[l] = static_cast<float>(field.evaluate(p, walk));
    }
  }
  for (int k = 0; k < 8; ++k)
  {
    const int bx = k & 1, by = (k >> 1) & 1, bz = (k >> 2) & 1;
    Cell& child = children[k];
    child = Cell();
    for (int n = 0; n < 8; ++n)
      child.h[n] = grid[(bx + (n & 1)) + 3 * (by + ((n >> 1) & 1)) + 9 * (bz + ((n >> 2) & 1))];
    states[k] =
      sampleCentre({ o[0] + bx * cs / 2, o[1] + by * cs / 2, o[2] + bz * cs / 2 }, u.depth + 1, field, walk, b);
  }
}

// The cells of a level are split on the threads, each into its own eight slots after the level's first
// (cells in level order), so the tree does not depend on which thread split which cell.
bool OctreeSizing::buildByLevels(const SizingField& field, const Building& b, const Unsplit& root, Progress* progress,
                                 int threads, std::vector<Unsplit>& states)
{
  states.assign(1, root);
  std::vector<int32_t> level;
  if (splitPriority(cells_[0], root, b) > 0)
    level.push_back(0);
  std::atomic<bool> stop{ false };
  size_t splitsAsked = 0; // the cells of the chunks worker 0 took: it asks as each 1024 more begin
  while (!level.empty())
  {
    if (cells_.size() + 8 * level.size() > b.maxCells)
      return false;
    const size_t base = cells_.size(), n = level.size();
    cells_.resize(base + 8 * n);
    states.resize(base + 8 * n);
    std::vector<uint8_t> splitNext(8 * n, 0);
    // Chunks of cells handed out in turn (the cost of a cell's walks varies over the domain); worker 0 runs
    // on the calling thread and asks progress.
    std::atomic<size_t> nextChunk{ 0 };
    const size_t chunks = (n + kCellsPerChunk - 1) / kCellsPerChunk;
    const int workers = static_cast<int>(std::min<size_t>(static_cast<size_t>(resolveThreads(threads)), chunks));
    parallelRun(workers,
                [&](int worker)
                {
                  for (size_t chunk = nextChunk++; chunk < chunks && !stop.load(std::memory_order_relaxed);
                       chunk = nextChunk++)
                  {
                    const size_t begin = chunk * kCellsPerChunk, end = std::min(n, begin + kCellsPerChunk);
                    if (worker == 0 && progress)
                    {
                      const size_t before = splitsAsked;
                      splitsAsked += end - begin;
                      if (before / 1024 != splitsAsked / 1024 && progress->cancelled())
                      {
                        stop = true;
                        break;
                      }
                    }
                    for (size_t i = begin; i < end; ++i)
                    {
                      const size_t first = base + 8 * i;
                      splitInto(cells_[level[i]], states[level[i]], field, b, &cells_[first], &states[first]);
                      for (int k = 0; k < 8; ++k)
                        splitNext[8 * i + k] = splitPriority(cells_[first + k], states[first + k], b) > 0;
                      cells_[level[i]].child = static_cast<int32_t>(first);
                    }
                  }
                });
    if (stop)
    {
      // The tree keeps the cells made until then: the level's slots end after its last split cell.
      size_t end = base;
      for (const int32_t c : level)
        if (cells_[c].child >= 0)
          end = std::max(end, static_cast<size_t>(cells_[c].child) + 8);
      cells_.resize(end);
      cancelled_ = true;
      return true;
    }
    level.clear();
    for (size_t c = 0; c < 8 * n; ++c)
      if (splitNext[c])
        level.push_back(static_cast<int32_t>(base + c));
  }
  return true;
}

// The cells next in the order are split as a batch on the threads (a split depends on its cell alone), then
// taken in the order one after the other, until a child of one taken outranks the next: the rest wait for
// the next batch, their splits kept. The tree is the one the one-at-a-time order gives. A cell that the
// level build split (`made`) takes its children from there.
void OctreeSizing::buildByPriority(const SizingField& field, const Building& b, const Unsplit& root, Progress* progress,
                                   int threads, const SplitCache& made)
{
  std::vector<Unsplit> state{ root }; // per cell
  std::vector<int32_t> madeAs{ 0 };   // per cell, the same cell in `made` (-1: none)
  // (how oversized, -cell): the most oversized first, ties by cell.
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry> queue;
  const auto queueIfOversized = [&](size_t c)
  {
    const double priority = splitPriority(cells_[c], state[c], b);
    if (priority > 0)
      queue.push({ priority, -static_cast<int32_t>(c) });
  };
  queueIfOversized(0);
  std::vector<Entry> batch;
  std::vector<Split> splits, waiting;            // the batch's; those made but not taken
  std::unordered_map<int32_t, size_t> waitingAt; // cell -> its split in waiting
  const int workers = field.evaluatesWithWalks() ? resolveThreads(threads) : 1;
  for (size_t done = 0; !queue.empty() && cells_.size() + 8 <= b.maxCells;)
  {
    // About an eighth of the queue (its most oversized cells seldom wait for a child of another); one cell
    // on one thread.
    const size_t room = (b.maxCells - cells_.size()) / 8;
    const size_t size =
      workers > 1 ? std::min({ std::max<size_t>(queue.size() / 8, 1), kBatch, room, queue.size() }) : 1;
    batch.clear();
    splits.assign(size, Split());
    for (size_t i = 0; i < size; ++i)
    {
      batch.push_back(queue.top());
      queue.pop();
      Split& split = splits[i];
      split.cell = -batch[i].second;
      const auto w = waitingAt.find(split.cell);
      const int32_t m = madeAs[split.cell];
      if (w != waitingAt.end())
        split = std::move(waiting[w->second]);
      else if (m >= 0 && made.cells[m].child >= 0)
      {
        split.madeFirst = made.cells[m].child;
        std::copy_n(&made.cells[split.madeFirst], 8, split.children);
        std::copy_n(&made.states[split.madeFirst], 8, split.states);
        split.made = true;
      }
    }
    std::atomic<size_t> next{ 0 };
    parallelRun(static_cast<int>(std::min<size_t>(static_cast<size_t>(workers), (size + 63) / 64)),
                [&](int)
                {
                  for (size_t i = next++; i < size; i = next++)
                    if (!splits[i].made)
                    {
                      splitInto(cells_[splits[i].cell], state[splits[i].cell], field, b, splits[i].children,
                                splits[i].states);
                      splits[i].made = true;
                    }
                });
    size_t taken = 0;
    for (; taken < size; ++taken)
    {
      if ((taken > 0 && !queue.empty() && queue.top() > batch[taken]) || cells_.size() + 8 > b.maxCells)
        break;
      if ((done & 1023) == 1023 && progress && progress->cancelled())
      {
        cancelled_ = true;
        return;
      }
      const Split& split = splits[taken];
      const size_t first = cells_.size();
      cells_.insert(cells_.end(), split.children, split.children + 8);
      for (int k = 0; k < 8; ++k)
      {
        cells_[first + static_cast<size_t>(k)].child = -1;
        state.push_back(split.states[k]);
        madeAs.push_back(split.madeFirst >= 0 ? split.madeFirst + k : -1);
      }
      cells_[split.cell].child = static_cast<int32_t>(first);
      for (int k = 0; k < 8; ++k)
        queueIfOversized(first + static_cast<size_t>(k));
      ++done;
    }
    waiting.clear();
    waitingAt.clear();
    for (size_t i = taken; i < size; ++i)
    {
      queue.push(batch[i]);
      waitingAt[splits[i].cell] = waiting.size();
      waiting.push_back(std::move(splits[i]));
    }
  }
  capped_ = !queue.empty();
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
