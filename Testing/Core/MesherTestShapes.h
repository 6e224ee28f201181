// Hand-made closed surfaces for the mesher tests (header-only, test code).
#pragma once

#include "SurfaceMesh.h"

#include <cmath>
#include <map>
#include <utility>

namespace volgrid
{
namespace testshapes
{

// Axis-aligned box, 12 triangles, outward. flipDiagonals: use the other diagonal on faces with odd index.
inline void addBox(SurfaceMesh& s, const double lo[3], const double hi[3], bool flipDiagonals = false, bool inward = false)
{
  const int32_t b = s.numberOfPoints();
  for (int c = 0; c < 8; ++c)
    s.addPoint((c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]);
  // quads, outward (counter-clockwise seen from outside)
  const int q[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (int f = 0; f < 6; ++f)
  {
    int a = q[f][0], bb = q[f][1], c = q[f][2], d = q[f][3];
    int t[2][3];
    if (flipDiagonals && (f % 2))
    {
      t[0][0] = a; t[0][1] = bb; t[0][2] = d;
      t[1][0] = bb; t[1][1] = c; t[1][2] = d;
    }
    else
    {
      t[0][0] = a; t[0][1] = bb; t[0][2] = c;
      t[1][0] = a; t[1][1] = c; t[1][2] = d;
    }
    for (auto& tr : t)
      if (inward)
        s.addTriangle(b + tr[0], b + tr[2], b + tr[1]);
      else
        s.addTriangle(b + tr[0], b + tr[1], b + tr[2]);
  }
}

// Schönhardt's twisted prism: not tetrahedralizable without a Steiner point.
inline SurfaceMesh schoenhardt(double twistDegrees = 30)
{
  SurfaceMesh s;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 3; ++i)
  {
    const double a = 2 * pi * i / 3;
    s.addPoint(std::cos(a), std::sin(a), 0);
  }
  for (int i = 0; i < 3; ++i)
  {
    const double a = 2 * pi * i / 3 + twistDegrees * pi / 180;
    s.addPoint(std::cos(a), std::sin(a), 1);
  }
  s.addTriangle(0, 2, 1);
  s.addTriangle(3, 4, 5);
  for (int i = 0; i < 3; ++i)
  {
    const int a0 = i, a1 = (i + 1) % 3, b0 = 3 + i, b1 = 3 + (i + 1) % 3;
    s.addTriangle(a0, a1, b1);
    s.addTriangle(a0, b1, b0);
  }
  return s;
}

// Box whose faces are split into long skinny strips (the surface triangles are far from Delaunay).
inline SurfaceMesh stripBox(int n, double lx, double ly, double lz, double shift = 0.37)
{
  SurfaceMesh s;
  std::map<std::pair<int, int>, int32_t> dummy;
  (void)dummy;
  // Points: on the four long edges parallel to y (x in {0,lx}, z in {0,lz}), n+1 each, plus nothing else.
  auto id = [&](int xi, int zi, int k) { return (xi * 2 + zi) * (n + 1) + k; };
  for (int xi = 0; xi < 2; ++xi)
    for (int zi = 0; zi < 2; ++zi)
      for (int k = 0; k <= n; ++k)
      {
        double y = ly * k / n;
        // shift interior points of two edges so the strips are sheared
        if ((xi ^ zi) && k > 0 && k < n)
          y = ly * (k + shift) / n;
        s.addPoint(xi * lx, y, zi * lz);
      }
  // Four long faces as strips between two edges: (e0 = edge A, e1 = edge B), outward orientation chosen
  // per face below.
  auto strip = [&](int xa, int za, int xb, int zb, bool flip) {
    for (int k = 0; k < n; ++k)
    {
      int a0 = id(xa, za, k), a1 = id(xa, za, k + 1), b0 = id(xb, zb, k), b1 = id(xb, zb, k + 1);
      if (!flip)
      {
        s.addTriangle(a0, b0, b1);
        s.addTriangle(a0, b1, a1);
      }
      else
      {
        s.addTriangle(a0, b1, b0);
        s.addTriangle(a0, a1, b1);
      }
    }
  };
  strip(0, 0, 1, 0, true);  // bottom z=0
  strip(0, 1, 1, 1, false); // top z=lz
  strip(0, 0, 0, 1, false); // x=0
  strip(1, 0, 1, 1, true);  // x=lx
  // End caps y=0 and y=ly: quads (0,0),(1,0),(1,1),(0,1).
  s.addTriangle(id(0, 0, 0), id(1, 0, 0), id(1, 1, 0));
  s.addTriangle(id(0, 0, 0), id(1, 1, 0), id(0, 1, 0));
  s.addTriangle(id(0, 0, n), id(1, 1, n), id(1, 0, n));
  s.addTriangle(id(0, 0, n), id(0, 1, n), id(1, 1, n));
  return s;
}

// Icosphere (subdivided icosahedron), outward.
inline void addSphere(SurfaceMesh& s, const double c[3], double r, int levels, bool inward = false)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t },
    { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> mid;
    auto m = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      p.push_back({ (p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2 });
      return mid[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (auto& tr : f)
    {
      int a = m(tr[0], tr[1]), b = m(tr[1], tr[2]), cc = m(tr[2], tr[0]);
      g.push_back({ tr[0], a, cc });
      g.push_back({ tr[1], b, a });
      g.push_back({ tr[2], cc, b });
      g.push_back({ a, b, cc });
    }
    f = g;
  }
  const int32_t base = s.numberOfPoints();
  for (auto& q : p)
  {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    s.addPoint(c[0] + r * q[0] / n, c[1] + r * q[1] / n, c[2] + r * q[2] / n);
  }
  for (auto& tr : f)
    if (inward)
      s.addTriangle(base + tr[0], base + tr[2], base + tr[1]);
    else
      s.addTriangle(base + tr[0], base + tr[1], base + tr[2]);
}

} // namespace testshapes
} // namespace volgrid
