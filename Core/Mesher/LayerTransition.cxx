// The size step between the last layer and the tets (LayerTransition.h).
#include "LayerTransition.h"

#include "LayeredMesher.h"
#include "VertexKeys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace volgrid
{
namespace
{
struct Plane
{
  double normal[3]; // unit
  double offset;
  bool valid;
};

Plane planeOf(const std::vector<double>& p, int32_t a, int32_t b, int32_t c, double* area)
{
  const double* pa = p.data() + 3 * size_t(a);
  const double* pb = p.data() + 3 * size_t(b);
  const double* pc = p.data() + 3 * size_t(c);
  const double u[3] = { pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2] };
  const double v[3] = { pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2] };
  double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  *area = 0.5 * length;
  Plane plane{ { 0, 0, 0 }, 0, length > 0 };
  if (plane.valid)
    for (int k = 0; k < 3; ++k)
      plane.normal[k] = n[k] / length;
  plane.offset = plane.normal[0] * pa[0] + plane.normal[1] * pa[1] + plane.normal[2] * pa[2];
  return plane;
}

// The distance of point v from the plane of triangle (a, b, c).
double heightOver(const std::vector<double>& p, int32_t a, int32_t b, int32_t c, int32_t v)
{
  double area = 0;
  const Plane plane = planeOf(p, a, b, c, &area);
  if (!plane.valid)
    return 0;
  const double* pv = p.data() + 3 * size_t(v);
  return std::abs(plane.normal[0] * pv[0] + plane.normal[1] * pv[1] + plane.normal[2] * pv[2] - plane.offset);
}

// The interface triangles by their sorted corners.
std::unordered_map<TriKey, int64_t, TriKeyHash> interfaceIndex(const LayeredMeshResult& r)
{
  std::unordered_map<TriKey, int64_t, TriKeyHash> index;
  index.reserve(r.interfaceTriangles.size() / 3);
  for (size_t i = 0; i < r.interfaceTriangles.size() / 3; ++i)
    index.emplace(TriKey(r.interfaceTriangles[3 * i], r.interfaceTriangles[3 * i + 1], r.interfaceTriangles[3 * i + 2]),
                  int64_t(i));
  return index;
}

double quantile(const std::vector<double>& sorted, double q)
{
  if (sorted.empty())
    return 0;
  const size_t k = std::min(sorted.size() - 1, size_t(q * double(sorted.size() - 1) + 0.5));
  return sorted[k];
}
} // namespace

LayerTransition measureLayerTransition(const LayeredMeshResult& r, int layers)
{
  const auto index = interfaceIndex(r);
  const size_t n = r.interfaceTriangles.size() / 3;
  std::vector<double> tetHeight(n, 0), layerHeight(n, 0);
  // A tet's face on the interface: its height over it, on the tet side (tet region) or the layer side
  // (the last layer's split prisms).
  for (size_t t = 0; t < r.tets.size() / 4; ++t)
  {
    const int32_t* v = r.tets.data() + 4 * t;
    const bool inLayer = r.tetLayer[t] >= 0;
    if (inLayer && (r.tetLayer[t] != layers - 1 || r.tetReason[t] == uint8_t(ThinnedReason::Collapsed)))
      continue; // not the last layer, or a collapsed column's cell (no layer under the interface there)
    for (int i = 0; i < 4; ++i)
    {
      const int32_t a = v[(i + 1) % 4], b = v[(i + 2) % 4], c = v[(i + 3) % 4];
      const auto it = index.find(TriKey(a, b, c));
      if (it != index.end())
        (inLayer ? layerHeight : tetHeight)[size_t(it->second)] = heightOver(r.points, a, b, c, v[i]);
    }
  }
  // A prism of the last layer under the interface: the mean height of its base corners under its top.
  for (size_t w = 0; w < r.wedges.size() / 6; ++w)
  {
    if (r.wedgeLayer[w] != layers - 1)
      continue;
    const int32_t* v = r.wedges.data() + 6 * w;
    const auto it = index.find(TriKey(v[3], v[4], v[5]));
    if (it == index.end())
      continue;
    layerHeight[size_t(it->second)] =
      (heightOver(r.points, v[3], v[4], v[5], v[0]) + heightOver(r.points, v[3], v[4], v[5], v[1]) +
       heightOver(r.points, v[3], v[4], v[5], v[2])) /
      3;
  }
  std::vector<double> ratios;
  for (size_t i = 0; i < n; ++i)
    if (tetHeight[i] > 0 && layerHeight[i] > 0)
      ratios.push_back(tetHeight[i] / layerHeight[i]);
  std::sort(ratios.begin(), ratios.end());
  LayerTransition result;
  result.faces = int64_t(ratios.size());
  if (ratios.empty())
    return result;
  result.minRatio = ratios.front();
  result.maxRatio = ratios.back();
  result.medianRatio = quantile(ratios, 0.5);
  result.p90Ratio = quantile(ratios, 0.9);
  return result;
}

std::string layerTransitionWarning(const LayerTransition& t, double limit)
{
  if (t.faces == 0 || (t.medianRatio <= limit && t.medianRatio >= 1 / limit))
    return std::string();
  char text[600];
  if (t.medianRatio > limit)
    std::snprintf(text, sizeof text,
                  "the tets over the last layer are %.3g times as tall as it (median over %lld faces; 90%% under "
                  "%.3g, at most %.3g): the cell size jumps there; more layers, a larger growth or a total "
                  "thickness closer to the wall's triangle size give a smoother transition",
                  t.medianRatio, (long long)t.faces, t.p90Ratio, t.maxRatio);
  else
    std::snprintf(text, sizeof text,
                  "the tets over the last layer are %.3g times as tall as it (median over %lld faces): the layers "
                  "are thicker than the wall's triangles, and the cell size drops there; fewer layers, a smaller "
                  "growth or a thinner total thickness give a smoother transition",
                  t.medianRatio, (long long)t.faces);
  return text;
}

} // namespace volgrid
