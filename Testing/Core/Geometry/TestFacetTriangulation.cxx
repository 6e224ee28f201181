// Planar facets with holes (Core/Geometry/PolygonTriangulation.h): TetGen .poly facets made of several polygons
// and hole points are triangulated as regions with holes, on hand-made facets and on TetGen's own
// example.poly from the shared corpus.
#include "PolygonTriangulation.h"
#include "SurfaceChecks.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace volgrid;

std::string writeFile(const std::string& name, const std::string& content)
{
  const std::string path = ::testing::TempDir() + "volgrid_facet_" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Signed area of triangle t projected on the z = const plane (positive counter-clockwise).
double signedAreaZ(const std::vector<double>& p, const int32_t* t)
{
  const double* a = &p[3 * size_t(t[0])];
  const double* b = &p[3 * size_t(t[1])];
  const double* c = &p[3 * size_t(t[2])];
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

std::set<std::pair<int32_t, int32_t>> undirectedEdges(const std::vector<int32_t>& tris)
{
  std::set<std::pair<int32_t, int32_t>> edges;
  for (size_t t = 0; t + 2 < tris.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int32_t a = tris[t + k], b = tris[t + (k + 1) % 3];
      edges.insert({ std::min(a, b), std::max(a, b) });
    }
  }
  return edges;
}

void expectLoopEdges(const std::vector<int32_t>& tris, const std::vector<int32_t>& loop)
{
  const auto edges = undirectedEdges(tris);
  for (size_t i = 0; i < loop.size(); ++i)
  {
    const int32_t a = loop[i], b = loop[(i + 1) % loop.size()];
    EXPECT_TRUE(edges.count({ std::min(a, b), std::max(a, b) })) << "loop edge " << a << "-" << b << " missing";
  }
}

// Square [0,4]^2 (ids 0-3, counter-clockwise), square hole [1,3]^2 (ids 4-7, also counter-clockwise as
// TetGen files often list it), both in z = 0.
const std::vector<double> kSquareWithHole = { 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 1, 1, 0, 3, 1, 0, 3, 3, 0, 1, 3, 0 };
const std::vector<int32_t> kOuter = { 0, 1, 2, 3 };
const std::vector<int32_t> kInner = { 4, 5, 6, 7 };
} // namespace

TEST(FacetTriangulation, SquareWithSquareHole)
{
  std::vector<int32_t> tris;
  FacetTriangulationInfo info;
  const std::vector<double> holePoint = { 2, 2, 0 };
  ASSERT_TRUE(triangulateFacet(kSquareWithHole, { kOuter, kInner }, holePoint, tris, &info));
  EXPECT_EQ(info.regions, 1);
  EXPECT_EQ(info.holeRegions, 1);
  // 8 corners, 1 hole: 8 + 2*1 - 2 = 8 triangles covering 16 - 4 = 12.
  ASSERT_EQ(tris.size(), 8u * 3);
  double area = 0;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    const double a = signedAreaZ(kSquareWithHole, &tris[t]);
    EXPECT_GT(a, 0.0) << "triangle " << t / 3 << " not oriented like the outer loop";
    area += a;
    // No triangle inside the hole: its centroid is outside the open square (1,3)^2.
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; ++k)
    {
      cx += kSquareWithHole[3 * size_t(tris[t + k])] / 3;
      cy += kSquareWithHole[3 * size_t(tris[t + k]) + 1] / 3;
    }
    EXPECT_FALSE(cx > 1 && cx < 3 && cy > 1 && cy < 3) << "triangle " << t / 3 << " lies in the hole";
  }
  EXPECT_DOUBLE_EQ(area, 12.0);
  expectLoopEdges(tris, kOuter);
  expectLoopEdges(tris, kInner);

  // The outer loop listed clockwise: same region, triangles clockwise too.
  std::vector<int32_t> reversed(kOuter.rbegin(), kOuter.rend());
  tris.clear();
  ASSERT_TRUE(triangulateFacet(kSquareWithHole, { kInner, reversed }, holePoint, tris, &info));
  ASSERT_EQ(tris.size(), 8u * 3);
  area = 0;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    area += signedAreaZ(kSquareWithHole, &tris[t]);
  }
  EXPECT_DOUBLE_EQ(area, -12.0);
}

TEST(FacetTriangulation, InnerLoopWithoutHolePointKeepsBothRegions)
{
  // TetGen semantics: without a hole point the inner square is a constraint, not a hole: both the ring
  // and the inner square are meshed, each once (total area 16, no overlap), sharing the inner edges.
  std::vector<int32_t> tris;
  FacetTriangulationInfo info;
  ASSERT_TRUE(triangulateFacet(kSquareWithHole, { kOuter, kInner }, {}, tris, &info));
  EXPECT_EQ(info.regions, 2);
  EXPECT_EQ(info.holeRegions, 0);
  ASSERT_EQ(tris.size(), (8u + 2u) * 3);
  double area = 0;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    const double a = signedAreaZ(kSquareWithHole, &tris[t]);
    EXPECT_GT(a, 0.0);
    area += a;
  }
  EXPECT_DOUBLE_EQ(area, 16.0);

  // A hole point outside every polygon changes nothing and is counted.
  tris.clear();
  ASSERT_TRUE(triangulateFacet(kSquareWithHole, { kOuter, kInner }, { 9, 9, 0 }, tris, &info));
  EXPECT_EQ(info.unusedHolePoints, 1);
  EXPECT_EQ(tris.size(), (8u + 2u) * 3);
}

TEST(FacetTriangulation, SeveralNonConvexHolesAndAnIsland)
{
  // Outer 10x10 square; two L-shaped holes; inside the second hole an island square (its own region).
  std::vector<double> p = { 0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 0 };
  auto add = [&](double x, double y)
  {
    p.insert(p.end(), { x, y, 0 });
    return static_cast<int32_t>(p.size() / 3 - 1);
  };
  std::vector<int32_t> l1, l2, island;
  for (auto [x, y] : { std::pair<double, double>{ 1, 1 }, { 4, 1 }, { 4, 2 }, { 2, 2 }, { 2, 4 }, { 1, 4 } })
    l1.push_back(add(x, y));
  for (auto [x, y] : { std::pair<double, double>{ 5, 5 }, { 9, 5 }, { 9, 9 }, { 8, 9 }, { 8, 6 }, { 5, 6 } })
    l2.push_back(add(x, y));
  // Island inside l2's wide part? l2 is an L of width 1: put the island in its corner square [8,9]x[5,6].
  for (auto [x, y] : { std::pair<double, double>{ 8.25, 5.25 }, { 8.75, 5.25 }, { 8.75, 5.75 }, { 8.25, 5.75 } })
    island.push_back(add(x, y));
  const std::vector<double> holes = { 1.5, 3, 0, 6, 5.5, 0 };
  std::vector<int32_t> tris;
  FacetTriangulationInfo info;
  ASSERT_TRUE(triangulateFacet(p, { l1, island, kOuter, l2 }, holes, tris, &info));
  EXPECT_EQ(info.holeRegions, 2);
  EXPECT_EQ(info.regions, 2); // the square minus the Ls, and the island
  const double lArea = 3 + 2, l2Area = 4 + 3, islandArea = 0.25;
  double area = 0;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    const double a = signedAreaZ(p, &tris[t]);
    EXPECT_GT(a, 0.0);
    area += a;
  }
  EXPECT_NEAR(area, 100 - lArea - l2Area + islandArea, 1e-12);
  // Counts: square region 4 + 6 + 6 corners, 2 holes: 16 + 4 - 2 = 18 triangles; island 2.
  EXPECT_EQ(tris.size(), (18u + 2u) * 3);
  for (const auto& loop : { kOuter, l1, l2, island })
  {
    expectLoopEdges(tris, loop);
  }
  // The triangles do not overlap: the exact intersection test of the surface checks finds no pair.
  SurfaceMesh m;
  m.points = p;
  for (size_t t = 0; t < tris.size(); t += 3)
  {
    m.addTriangle(tris[t], tris[t + 1], tris[t + 2], 0);
  }
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.selfIntersectingPairs + r.shellIntersectingPairs, 0);
  EXPECT_EQ(r.degenerateTriangles, 0);
  EXPECT_EQ(r.nonManifoldEdges, 0);
}

TEST(FacetTriangulation, AlignedGridOfHolesInATiltedPlane)
{
  // 3x3 square holes on a grid inside a square: many corners share a u or v coordinate, so bridge
  // candidates pass exactly through other corners (rejected exactly). Then the same facet tilted out
  // of the coordinate planes (rounded coordinates, so only nearly planar).
  for (int tilted = 0; tilted < 2; ++tilted)
  {
    SCOPED_TRACE(tilted ? "tilted" : "z = 0");
    std::vector<double> p;
    auto add = [&](double x, double y)
    {
      if (tilted)
      {
        // Rodrigues rotation of (x, y, 0) by 0.7 rad about the unit axis k = (1,1,1)/sqrt(3), then an
        // offset: v cos + (k x v) sin + k (k.v)(1 - cos).
        const double c = std::cos(0.7), s = std::sin(0.7), k = 1.0 / std::sqrt(3.0);
        const double v[3] = { x, y, 0 };
        const double kxv[3] = { k * (v[2] - v[1]), k * (v[0] - v[2]), k * (v[1] - v[0]) };
        const double kv = k * (v[0] + v[1] + v[2]);
        for (int i = 0; i < 3; ++i)
        {
          p.push_back(v[i] * c + kxv[i] * s + k * kv * (1 - c) + 0.1 * (i + 1));
        }
      }
      else
      {
        p.insert(p.end(), { x, y, 0 });
      }
      return static_cast<int32_t>(p.size() / 3 - 1);
    };
    std::vector<std::vector<int32_t>> polygons(1);
    for (auto [x, y] : { std::pair<double, double>{ 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } })
      polygons[0].push_back(add(x, y));
    std::vector<double> holes;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        const double x0 = 1 + 3 * i, y0 = 1 + 3 * j;
        polygons.emplace_back();
        for (auto [x, y] : { std::pair<double, double>{ x0, y0 }, { x0 + 2, y0 }, { x0 + 2, y0 + 2 }, { x0, y0 + 2 } })
          polygons.back().push_back(add(x, y));
        const size_t before = p.size();
        add(x0 + 1, y0 + 1); // the hole point, mapped like the corners
        holes.insert(holes.end(), p.begin() + static_cast<std::ptrdiff_t>(before), p.end());
        p.resize(before);
      }
    }
    std::vector<int32_t> tris;
    FacetTriangulationInfo info;
    ASSERT_TRUE(triangulateFacet(p, polygons, holes, tris, &info));
    EXPECT_EQ(info.holeRegions, 9);
    // 40 corners, 9 holes: 40 + 18 - 2 triangles.
    EXPECT_EQ(tris.size(), 56u * 3);
    for (const auto& loop : polygons)
    {
      expectLoopEdges(tris, loop);
    }
    SurfaceMesh m;
    m.points = p;
    double area = 0;
    for (size_t t = 0; t < tris.size(); t += 3)
    {
      m.addTriangle(tris[t], tris[t + 1], tris[t + 2], 0);
      double n[3];
      const double* a = m.point(tris[t]);
      const double* b = m.point(tris[t + 1]);
      const double* c = m.point(tris[t + 2]);
      n[0] = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
      n[1] = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
      n[2] = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    EXPECT_NEAR(area, 100 - 9 * 4, 1e-9);
    const SurfaceCheckReport r = checkSurface(m);
    EXPECT_EQ(r.selfIntersectingPairs + r.shellIntersectingPairs, 0);
    EXPECT_EQ(r.degenerateTriangles, 0);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.inconsistentEdges, 0);
  }
}

TEST(FacetTriangulation, PolyReaderSquareFacetWithSquareHole)
{
  // The square with a hole as one .poly facet in the plane x = 0 (the projection drops x).
  std::string poly = "8 3 0 0\n";
  for (int i = 0; i < 8; ++i)
  {
    poly += std::to_string(i + 1) + " 0 " + std::to_string(kSquareWithHole[3 * i]) + " " +
      std::to_string(kSquareWithHole[3 * i + 1]) + "\n";
  }
  poly += "1 1\n2 1 7\n4 1 2 3 4\n4 5 6 7 8\n1 0 2 2\n0\n";
  SurfaceMesh m;
  SurfaceReadInfo info;
  const Status s = readSurface(writeFile("square_hole.poly", poly), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(info.holeRegions, 1);
  EXPECT_TRUE(info.warnings.empty());
  ASSERT_EQ(m.numberOfTriangles(), 8);
  EXPECT_EQ(m.patchIds[0], 7);
  double area = 0;
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    const double* a = m.point(m.triangle(t)[0]);
    const double* b = m.point(m.triangle(t)[1]);
    const double* c = m.point(m.triangle(t)[2]);
    area += 0.5 * ((b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]));
  }
  EXPECT_DOUBLE_EQ(area, 12.0);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.boundaryEdges, 8); // the two loops, each edge once
  EXPECT_EQ(r.boundaryLoops, 2);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
}

TEST(FacetTriangulation, CorpusTetGenExamplePoly)
{
  const std::string path = std::string(VOLGRID_SHARED_DATA_DIR) + "/tetgen-tests/tetgen/example.poly";
  if (!std::ifstream(path))
  {
    GTEST_SKIP() << "shared corpus not available";
  }
  SurfaceMesh m;
  SurfaceReadInfo info;
  const Status s = readSurface(path, m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(info.fileFaces, 23);
  EXPECT_EQ(info.holeRegions, 1);
  EXPECT_TRUE(info.warnings.empty());
  // 22 quadrilateral facets give 2 triangles each; facet 3, the 2x4 wall y = 0 with the 1.5x0.5 window
  // where the inner box (nodes 21-28) touches it, has 8 corners and 1 hole: 8 + 2 - 2 = 8 triangles.
  EXPECT_EQ(m.numberOfTriangles(), 22 * 2 + 8);

  // Facet 3 (marker 3, in y = 0, z <= 4; facet 8 continues the wall above z = 4): area 8 - 0.75, no
  // triangle in the window, both loops' edges present.
  std::vector<int32_t> wall;
  double wallArea = 0;
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    const int32_t* tri = m.triangle(t);
    bool inWall = m.patchIds[t] == 3;
    for (int k = 0; k < 3; ++k)
    {
      inWall = inWall && m.point(tri[k])[1] == 0 && m.point(tri[k])[2] <= 4;
    }
    if (!inWall)
    {
      continue;
    }
    wall.insert(wall.end(), tri, tri + 3);
    const double* a = m.point(tri[0]);
    const double* b = m.point(tri[1]);
    const double* c = m.point(tri[2]);
    wallArea += 0.5 * std::fabs((b[0] - a[0]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[0] - a[0]));
    const double cx = (a[0] + b[0] + c[0]) / 3, cz = (a[2] + b[2] + c[2]) / 3;
    EXPECT_FALSE(cx > 0.25 && cx < 1.75 && cz > 2 && cz < 2.5) << "triangle " << t << " lies in the window";
  }
  EXPECT_EQ(wall.size(), 8u * 3);
  EXPECT_DOUBLE_EQ(wallArea, 8.0 - 0.75);
  // Node n of the file (1-based) is point n - 1.
  expectLoopEdges(wall, { 0, 1, 5, 4 });
  expectLoopEdges(wall, { 20, 21, 25, 24 });

  // What is really there: a PLC with an internal facet and a box glued into the window. Non-manifold
  // edges: the 4 edges of internal facet 2 (nodes 5-8), each shared with the lower and upper walls,
  // and the 4 window edges, each shared by the wall, the box's face in the window (facet 20) and one
  // side of the box. Their 8 end points are the non-manifold vertices. Nothing intersects, nothing is
  // duplicated, nothing is open.
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.nonManifoldEdges, 8);
  EXPECT_EQ(r.nonManifoldVertices, 8);
  EXPECT_EQ(r.boundaryEdges, 0);
  EXPECT_EQ(r.duplicateTriangles, 0);
  EXPECT_EQ(r.degenerateTriangles, 0);
  EXPECT_TRUE(r.intersectionsChecked);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
  EXPECT_EQ(r.shellIntersectingPairs, 0);
}
