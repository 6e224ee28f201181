#include "SizeRatio.h"

#include "ParallelFor.h"
#include "TetMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace volgrid
{

namespace
{
// Below these a range is not worth a thread.
constexpr int64_t kMinTetsPerThread = 50000;
constexpr int64_t kMinVerticesPerThread = 8192; // about 25 tets around each

double meanEdge(const double* points, const int32_t* t)
{
  double sum = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
    {
      const double* a = points + 3 * static_cast<size_t>(t[i]);
      const double* b = points + 3 * static_cast<size_t>(t[j]);
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
  return sum / 6;
}

double ratioOf(double a, double b)
{
  return std::max(a, b) / std::max(std::min(a, b), 1e-300);
}

// One face of one tet: the sorted vertex ids and the tet.
struct Face
{
  std::array<int32_t, 3> v;
  int32_t tet;
  bool operator<(const Face& o) const { return v != o.v ? v < o.v : tet < o.tet; }
};

double percentile(std::vector<float>& r, double q)
{
  const size_t k = std::min(r.size() - 1, static_cast<size_t>(q * static_cast<double>(r.size())));
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(k), r.end());
  return r[k];
}

// Fills s from the ratios (reordered).
void summarize(std::vector<float>& ratios, SizeRatioSummary& s)
{
  s.faces = static_cast<int64_t>(ratios.size());
  if (ratios.empty())
    return;
  s.max = *std::max_element(ratios.begin(), ratios.end());
  s.p99 = percentile(ratios, 0.99);
  s.median = percentile(ratios, 0.5);
}
// The ratios of the faces whose smallest vertex is in [first, last), appended to `ratios`; `above` counts
// those above threshold (when > 0).
void matchFacesAround(const int32_t* tets, const std::vector<int64_t>& start, const std::vector<int32_t>& around,
                      const std::vector<double>& size, int32_t first, int32_t last, double threshold,
                      std::vector<float>& ratios, int64_t& above)
{
  std::vector<Face> local;
  for (int32_t v = first; v < last; ++v)
  {
    local.clear();
    for (int64_t k = start[static_cast<size_t>(v)]; k < start[static_cast<size_t>(v) + 1]; ++k)
    {
      const int32_t t = around[static_cast<size_t>(k)];
      const int32_t* q = tets + 4 * static_cast<size_t>(t);
      for (int i = 0; i < 4; ++i)
      {
        Face f{ { q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4] }, t };
        std::sort(f.v.begin(), f.v.end());
        if (f.v[0] == v)
          local.push_back(f);
      }
    }
    std::sort(local.begin(), local.end());
    for (size_t k = 0; k + 1 < local.size(); ++k)
    {
      if (local[k].v != local[k + 1].v)
        continue;
      const double r = ratioOf(size[static_cast<size_t>(local[k].tet)], size[static_cast<size_t>(local[k + 1].tet)]);
      ratios.push_back(static_cast<float>(r));
      above += threshold > 0 && r > threshold;
      ++k; // a face is shared by at most two tets in a valid mesh
    }
  }
}
} // namespace

SizeRatioSummary summarizeSizeRatios(const double* points, const int32_t* tets, size_t numTets, double threshold,
                                     int threads)
{
  SizeRatioSummary s;
  const int64_t nt = static_cast<int64_t>(numTets);
  std::vector<double> size(numTets);
  std::vector<int32_t> largestId(static_cast<size_t>(parallelRanges(threads, nt, kMinTetsPerThread)), -1);
  parallelFor(threads, nt, kMinTetsPerThread,
              [&](int r, int64_t begin, int64_t end)
              {
                for (int64_t t = begin; t < end; ++t)
                {
                  size[static_cast<size_t>(t)] = meanEdge(points, tets + 4 * t);
                  for (int i = 0; i < 4; ++i)
                    largestId[static_cast<size_t>(r)] = std::max(largestId[static_cast<size_t>(r)], tets[4 * t + i]);
                }
              });
  const int32_t numPoints = 1 + *std::max_element(largestId.begin(), largestId.end());
  // The tets around each vertex (compressed rows): 16 bytes per tet, where a list of all 4 n faces took 64.
  std::vector<int64_t> start(static_cast<size_t>(numPoints) + 1, 0);
  for (size_t k = 0; k < 4 * numTets; ++k)
    ++start[static_cast<size_t>(tets[k]) + 1];
  for (size_t v = 0; v < static_cast<size_t>(numPoints); ++v)
    start[v + 1] += start[v];
  std::vector<int32_t> around(4 * numTets);
  {
    std::vector<int64_t> next(start.begin(), start.end() - 1);
    for (size_t k = 0; k < 4 * numTets; ++k)
      around[static_cast<size_t>(next[static_cast<size_t>(tets[k])]++)] = static_cast<int32_t>(k / 4);
  }
  // Each face is matched around its smallest vertex, a range of vertices per thread; the ratios of the
  // ranges, joined in order, are the same for any thread count.
  const int ranges = parallelRanges(threads, numPoints, kMinVerticesPerThread);
  std::vector<std::vector<float>> part(static_cast<size_t>(ranges));
  std::vector<int64_t> above(static_cast<size_t>(ranges), 0);
  parallelFor(threads, numPoints, kMinVerticesPerThread,
              [&](int r, int64_t begin, int64_t end)
              {
                matchFacesAround(tets, start, around, size, static_cast<int32_t>(begin), static_cast<int32_t>(end),
                                 threshold, part[static_cast<size_t>(r)], above[static_cast<size_t>(r)]);
              });
  // The join needs no more memory than the matching did: its arrays go first, the first range is kept.
  std::vector<int32_t>().swap(around);
  std::vector<int64_t>().swap(start);
  std::vector<double>().swap(size);
  size_t total = 0;
  for (const std::vector<float>& ratiosOfRange : part)
    total += ratiosOfRange.size();
  std::vector<float> ratios = std::move(part[0]);
  ratios.reserve(total);
  s.aboveThreshold += above[0];
  for (int r = 1; r < ranges; ++r)
  {
    ratios.insert(ratios.end(), part[static_cast<size_t>(r)].begin(), part[static_cast<size_t>(r)].end());
    std::vector<float>().swap(part[static_cast<size_t>(r)]);
    s.aboveThreshold += above[static_cast<size_t>(r)];
  }
  summarize(ratios, s);
  return s;
}

SizeRatioSummary summarizeSizeRatios(const double* points, const int32_t* tets, size_t numTets,
                                     const std::vector<std::pair<int32_t, int32_t>>& sharedFaces, double threshold,
                                     int threads)
{
  SizeRatioSummary s;
  const int64_t nt = static_cast<int64_t>(numTets);
  std::vector<double> size(numTets);
  parallelFor(threads, nt, kMinTetsPerThread,
              [&](int, int64_t begin, int64_t end)
              {
                for (int64_t t = begin; t < end; ++t)
                  size[static_cast<size_t>(t)] = meanEdge(points, tets + 4 * t);
              });
  const int64_t nf = static_cast<int64_t>(sharedFaces.size());
  std::vector<float> ratios(sharedFaces.size());
  const int ranges = parallelRanges(threads, nf, kMinTetsPerThread);
  std::vector<int64_t> above(static_cast<size_t>(ranges), 0);
  parallelFor(threads, nf, kMinTetsPerThread,
              [&](int r, int64_t begin, int64_t end)
              {
                for (int64_t k = begin; k < end; ++k)
                {
                  const auto& f = sharedFaces[static_cast<size_t>(k)];
                  const double ratio = ratioOf(size[static_cast<size_t>(f.first)], size[static_cast<size_t>(f.second)]);
                  ratios[static_cast<size_t>(k)] = static_cast<float>(ratio);
                  above[static_cast<size_t>(r)] += threshold > 0 && ratio > threshold;
                }
              });
  std::vector<double>().swap(size);
  for (int64_t a : above)
    s.aboveThreshold += a;
  summarize(ratios, s);
  return s;
}

SizeRatioSummary summarizeSizeRatios(const TetMesh& mesh, double threshold)
{
  SizeRatioSummary s;
  std::vector<double> size(static_cast<size_t>(mesh.tetCapacity()), 0);
  mesh.forEachTet(
    [&](int32_t t)
    {
      if (!mesh.isGhost(t))
        size[t] = meanEdge(mesh.points.data(), mesh.vertices(t));
    });
  std::vector<float> ratios;
  ratios.reserve(2 * static_cast<size_t>(mesh.numTets()));
  mesh.forEachTet(
    [&](int32_t t)
    {
      if (mesh.isGhost(t))
        return;
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = mesh.neighbor(t, i);
        if (u < t || mesh.isGhost(u)) // no neighbour (< 0), or the face is counted from its lower tet
          continue;
        const double r = ratioOf(size[t], size[u]);
        ratios.push_back(static_cast<float>(r));
        s.aboveThreshold += threshold > 0 && r > threshold;
      }
    });
  summarize(ratios, s);
  return s;
}

} // namespace volgrid
