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
  // The faces bucketed by their smallest vertex (a counting sort), each bucket then sorted: the same
  // pairs of equal faces as one sort of all 4 n faces, at a fraction of its cost.
  auto faceOf = [&](size_t t, int i)
  {
    const int32_t* v = tets + 4 * t;
    Face f{ { v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4] }, static_cast<int32_t>(t) };
    std::sort(f.v.begin(), f.v.end());
    return f;
  };
  std::vector<int64_t> start(static_cast<size_t>(numPoints) + 1, 0);
  for (size_t t = 0; t < numTets; ++t)
    for (int i = 0; i < 4; ++i)
      ++start[static_cast<size_t>(faceOf(t, i).v[0]) + 1];
  for (size_t v = 0; v < static_cast<size_t>(numPoints); ++v)
    start[v + 1] += start[v];
  std::vector<Face> faces(4 * numTets);
  std::vector<int64_t> next(start.begin(), start.end() - 1);
  for (size_t t = 0; t < numTets; ++t)
    for (int i = 0; i < 4; ++i)
    {
      const Face f = faceOf(t, i);
      faces[static_cast<size_t>(next[static_cast<size_t>(f.v[0])]++)] = f;
    }
  for (size_t v = 0; v < static_cast<size_t>(numPoints); ++v)
    std::sort(faces.begin() + start[v], faces.begin() + start[v + 1]);
  std::vector<float> ratios;
  ratios.reserve(2 * numTets);
  for (size_t k = 0; k + 1 < faces.size(); ++k)
  {
    if (faces[k].v != faces[k + 1].v)
      continue;
    const double r = ratioOf(size[faces[k].tet], size[faces[k + 1].tet]);
    ratios.push_back(static_cast<float>(r));
    s.aboveThreshold += threshold > 0 && r > threshold;
    ++k; // a face is shared by at most two tets in a valid mesh
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
