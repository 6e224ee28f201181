// Hand-made closed surfaces for the mesher tests (header-only, test code).
#pragma once

#include "SurfaceMesh.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace volgrid
{
namespace testshapes
{

// Axis-aligned box, 12 triangles, outward. flipDiagonals: use the other diagonal on faces with odd index.
inline void addBox(SurfaceMesh& s, const double lo[3], const double hi[3], bool flipDiagonals = false,
                   bool inward = false)
{
  const int32_t b = s.numberOfPoints();
  for (int c = 0; c < 8; ++c)
    s.addPoint((c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]);
  // quads, outward (counter-clockwise seen from outside)
  const int q[6][4] = {
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
  };
  for (int f = 0; f < 6; ++f)
  {
    int a = q[f][0], bb = q[f][1], c = q[f][2], d = q[f][3];
    int t[2][3];
    if (flipDiagonals && (f % 2))
    {
      t[0][0] = a;
      t[0][1] = bb;
      t[0][2] = d;
      t[1][0] = bb;
      t[1][1] = c;
      t[1][2] = d;
    }
    else
    {
      t[0][0] = a;
      t[0][1] = bb;
      t[0][2] = c;
      t[1][0] = a;
      t[1][1] = c;
      t[1][2] = d;
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
  auto strip = [&](int xa, int za, int xb, int zb, bool flip)
  {
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

// Flat box (x in [0, l], y in [0, w], z in [0, h]) whose top face z = h has n + 1 points along each long
// edge, a[k] at y = 0 and b[k] at y = w, triangulated by two fans of needles: from a[0] to every b[k],
// and from b[n] to every a[k]. The sides y = 0 and y = w are fans from a bottom corner. These are flat
// CAD faces: the 3D Delaunay mesh has the short zig-zag edges a[k]-b[k] in the top plane instead, and a
// fan segment crosses up to 2n of them, all in that plane.
inline SurfaceMesh fanBox(int n, double l, double w, double h)
{
  SurfaceMesh s;
  const int32_t c0 = s.addPoint(0, 0, 0), c1 = s.addPoint(l, 0, 0), c2 = s.addPoint(0, w, 0), c3 = s.addPoint(l, w, 0);
  std::vector<int32_t> a, b;
  for (int k = 0; k <= n; ++k)
  {
    a.push_back(s.addPoint(l * k / n, 0, h));
    b.push_back(s.addPoint(l * k / n, w, h));
  }
  // Each triangle turned to face away from the box's centre.
  auto add = [&](int32_t p, int32_t q, int32_t r)
  {
    const double *P = &s.points[3 * p], *Q = &s.points[3 * q], *R = &s.points[3 * r];
    double u[3], v[3], m[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = Q[k] - P[k];
      v[k] = R[k] - P[k];
      m[k] = (P[k] + Q[k] + R[k]) / 3 - (k == 0 ? l : k == 1 ? w : h) / 2;
    }
    const double nx = u[1] * v[2] - u[2] * v[1], ny = u[2] * v[0] - u[0] * v[2], nz = u[0] * v[1] - u[1] * v[0];
    if (nx * m[0] + ny * m[1] + nz * m[2] > 0)
      s.addTriangle(p, q, r);
    else
      s.addTriangle(p, r, q);
  };
  for (int k = 0; k < n; ++k)
  {
    add(a[0], b[k], b[k + 1]); // top, first fan
    add(b[n], a[k], a[k + 1]); // top, second fan
    add(c2, b[k], b[k + 1]);   // side y = w
    add(c1, a[k], a[k + 1]);   // side y = 0
  }
  add(c1, a[0], c0);
  add(c2, b[n], c3);
  add(a[0], b[0], c2), add(a[0], c2, c0); // side x = 0
  add(a[n], c1, c3), add(a[n], c3, b[n]); // side x = l
  add(c0, c2, c3), add(c0, c3, c1);       // bottom
  return s;
}

// Icosphere (subdivided icosahedron), outward.
inline void addSphere(SurfaceMesh& s, const double c[3], double r, int levels, bool inward = false)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
                                           { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t },
                                           { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> f = { { 0, 11, 5 }, { 0, 5, 1 },  { 0, 1, 7 },   { 0, 7, 10 }, { 0, 10, 11 },
                                        { 1, 5, 9 },  { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
                                        { 3, 9, 4 },  { 3, 4, 2 },  { 3, 2, 6 },   { 3, 6, 8 },  { 3, 8, 9 },
                                        { 4, 9, 5 },  { 2, 4, 11 }, { 6, 2, 10 },  { 8, 6, 7 },  { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> mid;
    auto m = [&](int a, int b)
    {
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

// A thin plate (6 x 4 x 0.04) inside a sphere (r = 10, icosphere level 2): the plate's edges force tets under
// 5 degrees after a first run of the quality stage, and severely non-orthogonal faces.
inline SurfaceMesh plateInSphere()
{
  SurfaceMesh s;
  const double c[3] = { 0, 0, 0 }, lo[3] = { -3, -2, -0.02 }, hi[3] = { 3, 2, 0.02 };
  addSphere(s, c, 10.0, 2);
  addBox(s, lo, hi, true, true);
  return s;
}

} // namespace testshapes
} // namespace volgrid
