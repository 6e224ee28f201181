// Icospheres and boxes with named patches for the boundary-layer tests (header-only, test code).
#pragma once

#include "SurfaceMesh.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace volgrid
{
namespace layertest
{

// Icosphere of `subdivisions` levels, radius r, centre c, outward, every triangle on `patch`.
inline void addIcosphere(SurfaceMesh& s, const double c[3], double r, int subdivisions, int32_t patch)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
                                           { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t },
                                           { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 },  { 0, 1, 7 },   { 0, 7, 10 }, { 0, 10, 11 },
                                        { 1, 5, 9 },  { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                                        { 3, 9, 4 },  { 3, 4, 2 },  { 3, 2, 6 },   { 3, 6, 8 },  { 3, 8, 9 },
                                        { 4, 9, 5 },  { 2, 4, 11 }, { 6, 2, 10 },  { 8, 6, 7 },  { 9, 8, 1 } };
  for (auto& q : p)
  {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    for (double& x : q)
      x /= n;
  }
  for (int level = 0; level < subdivisions; ++level)
  {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b)
    {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      std::array<double, 3> m;
      for (int i = 0; i < 3; ++i)
        m[i] = p[a][i] + p[b][i];
      const double n = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      for (double& x : m)
        x /= n;
      p.push_back(m);
      return mid[key] = static_cast<int>(p.size() - 1);
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tri : f)
    {
      const int a = middle(tri[0], tri[1]), b = middle(tri[1], tri[2]), d = middle(tri[2], tri[0]);
      next.push_back({ tri[0], a, d });
      next.push_back({ tri[1], b, a });
      next.push_back({ tri[2], d, b });
      next.push_back({ a, b, d });
    }
    f.swap(next);
  }
  const int32_t base = s.numberOfPoints();
  for (const auto& q : p)
    s.addPoint(c[0] + r * q[0], c[1] + r * q[1], c[2] + r * q[2]);
  for (const auto& tri : f)
    s.addTriangle(base + tri[0], base + tri[1], base + tri[2], patch);
}

// A unit body sphere (patch 1 "wall") inside a far-field sphere of radius 10 (patch 2 "farfield").
inline SurfaceMesh sphereInSphere(int bodySubdivisions = 3)
{
  SurfaceMesh s;
  const double o[3] = { 0, 0, 0 };
  addIcosphere(s, o, 1.0, bodySubdivisions, 1);
  addIcosphere(s, o, 10.0, 1, 2);
  s.patchNames[1] = "wall";
  s.patchNames[2] = "farfield";
  return s;
}

} // namespace layertest
} // namespace volgrid
