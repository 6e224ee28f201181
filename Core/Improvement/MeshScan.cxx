#include "MeshScan.h"

#include "ParallelFor.h"
#include "TetEditor.h"

#include <algorithm>

namespace volgrid
{

namespace
{
constexpr int64_t kMinPerThread = 25000; // tet slots: below this a range is not worth a thread

double quality(const TetMesh& m, int32_t t)
{
  const int32_t* v = m.vertices(t);
  return tetSineQuality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

// f(t) for every live tet of [begin, end).
template<class F>
void forLive(const TetMesh& m, int64_t begin, int64_t end, F&& f)
{
  for (int64_t t = begin; t < end; ++t)
    if (!m.isFree(static_cast<int32_t>(t)))
      f(static_cast<int32_t>(t));
}
} // namespace

double minSineQuality(const TetMesh& mesh, int threads)
{
  const int64_t n = mesh.tetCapacity();
  std::vector<double> part(static_cast<size_t>(parallelRanges(threads, n, kMinPerThread)), 2.0);
  parallelFor(threads, n, kMinPerThread,
              [&](int k, int64_t begin, int64_t end)
              {
                double q = 2.0;
                forLive(mesh, begin, end, [&](int32_t t) { q = std::min(q, quality(mesh, t)); });
                part[static_cast<size_t>(k)] = q;
              });
  return *std::min_element(part.begin(), part.end());
}

int64_t countSineBelow(const TetMesh& mesh, double q, int threads)
{
  const int64_t n = mesh.tetCapacity();
  std::vector<int64_t> part(static_cast<size_t>(parallelRanges(threads, n, kMinPerThread)), 0);
  parallelFor(threads, n, kMinPerThread,
              [&](int k, int64_t begin, int64_t end)
              {
                int64_t c = 0;
                forLive(mesh, begin, end, [&](int32_t t) { c += quality(mesh, t) < q; });
                part[static_cast<size_t>(k)] = c;
              });
  int64_t total = 0;
  for (int64_t c : part)
    total += c;
  return total;
}

bool collectSineBelow(const TetMesh& mesh, double q, int threads, std::vector<std::pair<double, int32_t>>& out,
                      Progress* progress)
{
  out.clear();
  const int64_t n = mesh.tetCapacity();
  const int64_t block = progress ? kSlotsPerQuestion : std::max<int64_t>(n, 1);
  std::vector<std::vector<std::pair<double, int32_t>>> part;
  for (int64_t first = 0; first < n; first += block)
  {
    if (first > 0 && progress->cancelled())
      return false;
    const int64_t count = std::min(block, n - first);
    part.assign(static_cast<size_t>(parallelRanges(threads, count, kMinPerThread)), {});
    parallelFor(threads, count, kMinPerThread,
                [&](int r, int64_t begin, int64_t end)
                {
                  auto& mine = part.size() == 1 ? out : part[static_cast<size_t>(r)];
                  forLive(mesh, first + begin, first + end,
                          [&](int32_t t)
                          {
                            const double qt = quality(mesh, t);
                            if (qt < q)
                              mine.emplace_back(qt, t);
                          });
                });
    if (part.size() > 1)
      for (const auto& p : part) // in slot order: the same for any split
        out.insert(out.end(), p.begin(), p.end());
  }
  return true;
}

void collectSineBelowAmong(const TetMesh& mesh, double q, std::vector<int32_t>& candidates,
                           std::vector<std::pair<double, int32_t>>& out)
{
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  out.clear();
  for (int32_t t : candidates)
    if (t >= 0 && t < mesh.tetCapacity() && !mesh.isFree(t))
    {
      const double qt = quality(mesh, t);
      if (qt < q)
        out.emplace_back(qt, t);
    }
  std::sort(out.begin(), out.end());
}

} // namespace volgrid
