#include "SizeRatio.h"

#include "TetMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace volgrid
{

namespace
{
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
} // namespace

SizeRatioSummary summarizeSizeRatios(const double* points, const int32_t* tets, size_t numTets, double threshold)
{
  SizeRatioSummary s;
  std::vector<double> size(numTets);
  int32_t numPoints = 0;
  for (size_t t = 0; t < numTets; ++t)
  {
    size[t] = meanEdge(points, tets + 4 * t);
    for (int i = 0; i < 4; ++i)
      numPoints = std::max(numPoints, tets[4 * t + i] + 1);
  }
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
  // Each face is matched around its smallest vertex: the faces there, sorted, give the equal pairs.
  std::vector<float> ratios;
  ratios.reserve(2 * numTets);
  std::vector<Face> local;
  for (int32_t v = 0; v < numPoints; ++v)
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
      const double r = ratioOf(size[local[k].tet], size[local[k + 1].tet]);
      ratios.push_back(static_cast<float>(r));
      s.aboveThreshold += threshold > 0 && r > threshold;
      ++k; // a face is shared by at most two tets in a valid mesh
    }
  }
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
