// Analytic values of the quality metrics (Core/Quality/Quality.h) and their statistics
// (Core/Quality/QualityStatistics.h).
#include "Quality.h"
#include "QualityStatistics.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace volgrid::quality;

namespace
{
const double kPi = 3.14159265358979323846;
const double kDeg = 180.0 / kPi;
using P = std::array<double, 3>;

TetMetrics measure(const P& a, const P& b, const P& c, const P& d)
{
  return tetMetrics(a.data(), b.data(), c.data(), d.data());
}

bool allFinite(const TetMetrics& m)
{
  return std::isfinite(m.aspectRatio) && std::isfinite(m.minDihedralAngle) && std::isfinite(m.maxDihedralAngle) &&
    std::isfinite(m.minSolidAngle) && std::isfinite(m.volume) && std::isfinite(m.radiusEdgeRatio) &&
    std::isfinite(m.radiusRatio);
}

// Regular tet with edge 2*sqrt(2), positively oriented.
const P R0 = { 1, 1, 1 }, R1 = { -1, 1, -1 }, R2 = { 1, -1, -1 }, R3 = { -1, -1, 1 };

// A closed surface as flat arrays.
struct Surface
{
  std::vector<double> points;
  std::vector<int64_t> tris;
  int64_t addPoint(double x, double y, double z)
  {
    points.insert(points.end(), { x, y, z });
    return static_cast<int64_t>(points.size() / 3 - 1);
  }
  void addTri(int64_t a, int64_t b, int64_t c) { tris.insert(tris.end(), { a, b, c }); }
  SurfaceSummary summary() const
  {
    return surfaceSummary(points.data(), static_cast<int64_t>(points.size() / 3), tris.data(),
                          static_cast<int64_t>(tris.size() / 3));
  }
};

// Unit cube [0,1]^3, outward triangles; without the top face (z = 1) if open.
Surface cube(bool open)
{
  Surface s;
  for (int i = 0; i < 8; ++i)
    s.addPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // quads as outward (counter-clockwise seen from outside) vertex loops
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                            { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (int q = 0; q < 6; ++q)
  {
    if (open && q == 1)
      continue;
    s.addTri(quads[q][0], quads[q][1], quads[q][2]);
    s.addTri(quads[q][0], quads[q][2], quads[q][3]);
  }
  return s;
}

// Octahedron of "radius" r at centre (cx, 0, 0), outward; volume 4 r^3 / 3.
void addOctahedron(Surface& s, double cx, double r)
{
  const int64_t px = s.addPoint(cx + r, 0, 0), nx = s.addPoint(cx - r, 0, 0), py = s.addPoint(cx, r, 0),
                ny = s.addPoint(cx, -r, 0), pz = s.addPoint(cx, 0, r), nz = s.addPoint(cx, 0, -r);
  s.addTri(px, py, pz);
  s.addTri(py, nx, pz);
  s.addTri(nx, ny, pz);
  s.addTri(ny, px, pz);
  s.addTri(py, px, nz);
  s.addTri(nx, py, nz);
  s.addTri(ny, nx, nz);
  s.addTri(px, ny, nz);
}
} // namespace

TEST(Quality, RegularTet)
{
  const TetMetrics m = measure(R0, R1, R2, R3);
  const double dihedral = std::acos(1.0 / 3.0) * kDeg; // 70.528779...
  EXPECT_NEAR(dihedral, 70.5288, 1e-4);
  EXPECT_NEAR(m.minDihedralAngle, dihedral, 1e-12);
  EXPECT_NEAR(m.maxDihedralAngle, dihedral, 1e-12);
  EXPECT_NEAR(m.aspectRatio, 1.0, 1e-15);
  EXPECT_NEAR(m.minSolidAngle, std::acos(23.0 / 27.0), 1e-14); // 0.5513 sr
  const double edge = 2.0 * std::sqrt(2.0);
  EXPECT_NEAR(m.volume, edge * edge * edge / (6.0 * std::sqrt(2.0)), 1e-14);
  EXPECT_GT(m.volume, 0.0);
  EXPECT_NEAR(m.radiusEdgeRatio, std::sqrt(6.0) / 4.0, 1e-15);
  EXPECT_NEAR(m.radiusRatio, 1.0, 1e-14);

  double angles[6], omega[4];
  tetDihedralAngles(R0.data(), R1.data(), R2.data(), R3.data(), angles);
  tetSolidAngles(R0.data(), R1.data(), R2.data(), R3.data(), omega);
  for (double a : angles)
    EXPECT_NEAR(a, dihedral, 1e-12);
  for (double o : omega)
    EXPECT_NEAR(o, std::acos(23.0 / 27.0), 1e-14);
}

TEST(Quality, CornerTet)
{
  // The corner of the unit cube: an octant (pi/2 sr) at the origin, right dihedral angles on the axes.
  const P o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, z = { 0, 0, 1 };
  double angles[6], omega[4];
  tetDihedralAngles(o.data(), x.data(), y.data(), z.data(), angles);
  tetSolidAngles(o.data(), x.data(), y.data(), z.data(), omega);
  EXPECT_NEAR(omega[0], kPi / 2.0, 1e-14);
  for (int e = 0; e < 3; ++e)
    EXPECT_NEAR(angles[e], 90.0, 1e-12);
  for (int e = 3; e < 6; ++e)
    EXPECT_NEAR(angles[e], std::acos(1.0 / std::sqrt(3.0)) * kDeg, 1e-12);
  const TetMetrics m = measure(o, x, y, z);
  EXPECT_NEAR(m.volume, 1.0 / 6.0, 1e-16);
  EXPECT_NEAR(m.aspectRatio, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(m.radiusEdgeRatio, std::sqrt(3.0) / 2.0, 1e-15); // R = sqrt(3)/2, shortest edge 1
  // The solid angles at the other three vertices are equal and sum with the octant to less than 4 pi.
  EXPECT_NEAR(omega[1], omega[2], 1e-15);
  EXPECT_NEAR(m.minSolidAngle, omega[1], 1e-15);
}

TEST(Quality, InvertedTet)
{
  const TetMetrics good = measure(R0, R1, R2, R3);
  const TetMetrics bad = measure(R1, R0, R2, R3);
  EXPECT_LT(bad.volume, 0.0);
  EXPECT_DOUBLE_EQ(bad.volume, -good.volume);
  // Shape metrics do not depend on the orientation.
  EXPECT_NEAR(bad.minDihedralAngle, good.minDihedralAngle, 1e-12);
  EXPECT_NEAR(bad.minSolidAngle, good.minSolidAngle, 1e-14);
  EXPECT_NEAR(bad.radiusRatio, good.radiusRatio, 1e-14);
}

TEST(Quality, Sliver)
{
  // Four well-spaced points almost on a plane: fine aspect ratio, nearly zero volume and angles.
  const double h = 0.01;
  const TetMetrics m = measure({ 1, 0, h }, { -1, 0, h }, { 0, 1, -h }, { 0, -1, -h });
  EXPECT_NEAR(m.aspectRatio, 2.0 / std::sqrt(2.0 + 4 * h * h), 1e-14);
  EXPECT_NEAR(m.volume, 4.0 * h / 3.0, 1e-15);
  EXPECT_NEAR(m.maxDihedralAngle, 180.0 - 2.0 * std::atan(2.0 * h) * kDeg, 1e-10);
  EXPECT_NEAR(m.minDihedralAngle, std::acos(1.0 / (1.0 + 4 * h * h)) * kDeg, 1e-8);
  EXPECT_LT(m.minSolidAngle, 0.02); // regular: 0.55
  EXPECT_GT(m.radiusRatio, 10.0);
}

TEST(Quality, Cap)
{
  // Apex just above the centre of an equilateral base (circumradius 1, inradius 1/2).
  const double h = 0.01;
  const P a = { 1, 0, 0 }, b = { -0.5, std::sqrt(3.0) / 2, 0 }, c = { -0.5, -std::sqrt(3.0) / 2, 0 };
  const P apex = { 0, 0, h };
  const TetMetrics m = measure(a, b, c, apex);
  EXPECT_NEAR(m.minDihedralAngle, std::atan(2.0 * h) * kDeg, 1e-10); // at the base edges
  EXPECT_GT(m.maxDihedralAngle, 175.0);                              // side faces nearly coplanar around the apex edges
  double omega[4];
  tetSolidAngles(a.data(), b.data(), c.data(), apex.data(), omega);
  EXPECT_GT(omega[3], 0.95 * 2 * kPi); // the apex sees almost a hemisphere
  EXPECT_LT(omega[3], 2 * kPi);
  EXPECT_NEAR(m.aspectRatio, std::sqrt(3.0) / std::sqrt(1.0 + h * h), 1e-14);
}

TEST(Quality, Needle)
{
  // A tiny equilateral base (side eps) and a far apex: the aspect ratio sees it, the dihedral angles
  // stay near 60 and 90 degrees.
  const double eps = 1e-3, r = eps / std::sqrt(3.0);
  const P a = { r, 0, 0 }, b = { -r / 2, eps / 2, 0 }, c = { -r / 2, -eps / 2, 0 }, apex = { 0, 0, 1 };
  const TetMetrics m = measure(a, b, c, apex);
  EXPECT_NEAR(m.aspectRatio, std::sqrt(1.0 + r * r) / eps, 1e-9);
  EXPECT_NEAR(m.minDihedralAngle, 60.0, 0.01);
  EXPECT_NEAR(m.maxDihedralAngle, 90.0, 0.05);
  EXPECT_NEAR(m.minSolidAngle, std::sqrt(3.0) / 4.0 * eps * eps, 1e-8); // base area seen from the apex
}

TEST(Quality, Wedge)
{
  // One short edge (eps) between p0 and p1: aspect ratio sqrt(2)/eps, a dihedral angle near 0 at the
  // opposite edge and 90 degrees at the short edge.
  const double eps = 1e-3;
  const P a = { -eps / 2, 0, 0 }, b = { eps / 2, 0, 0 }, c = { 0, 1, 0 }, d = { 0, 0, 1 };
  const TetMetrics m = measure(a, b, c, d);
  EXPECT_NEAR(m.aspectRatio, std::sqrt(2.0) / eps, 1e-9);
  double angles[6];
  tetDihedralAngles(a.data(), b.data(), c.data(), d.data(), angles);
  EXPECT_NEAR(angles[0], 90.0, 1e-12); // at the short edge (0,1)
  EXPECT_NEAR(m.minDihedralAngle, angles[5], 1e-15);
  EXPECT_LT(m.minDihedralAngle, 0.1);
  EXPECT_NEAR(m.volume, eps / 6.0, 1e-18);
}

TEST(Quality, DegenerateTetsAreFinite)
{
  const P o = { 0, 0, 0 }, x = { 1, 0, 0 }, y = { 0, 1, 0 }, xy = { 1, 1, 0 }, mid = { 0.5, 0, 0 };
  const TetMetrics coincident = measure(o, o, o, o);
  const TetMetrics twoSame = measure(o, o, y, { 0, 0, 1 });
  const TetMetrics flat = measure(o, x, y, xy);
  const TetMetrics collinearFace = measure(o, mid, x, y);
  for (const TetMetrics& m : { coincident, twoSame, flat, collinearFace })
  {
    EXPECT_TRUE(allFinite(m));
    EXPECT_EQ(m.volume, 0.0);
    EXPECT_EQ(m.minDihedralAngle, 0.0);
    EXPECT_EQ(m.maxDihedralAngle, 180.0);
    EXPECT_EQ(m.minSolidAngle, 0.0);
    EXPECT_EQ(m.radiusRatio, kMaxRatio);
    EXPECT_EQ(m.radiusEdgeRatio, kMaxRatio);
  }
  EXPECT_EQ(coincident.aspectRatio, kMaxRatio);
  EXPECT_EQ(twoSame.aspectRatio, kMaxRatio);
  EXPECT_NEAR(flat.aspectRatio, std::sqrt(2.0), 1e-15);
}

TEST(Quality, Triangles)
{
  const P a = { 0, 0, 0 }, b = { std::sqrt(3.0), 0, 0 }, c = { 0, 1, 0 };
  const TriangleMetrics t = triangleMetrics(a.data(), b.data(), c.data());
  EXPECT_NEAR(t.minAngle, 30.0, 1e-12);
  EXPECT_NEAR(t.maxAngle, 90.0, 1e-12);
  EXPECT_NEAR(t.area, std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_NEAR(t.aspectRatio, 2.0, 1e-15);

  const P e = { 1, 0, 0 }, f = { 0.5, std::sqrt(3.0) / 2, 0 };
  const TriangleMetrics eq = triangleMetrics(a.data(), e.data(), f.data());
  EXPECT_NEAR(eq.minAngle, 60.0, 1e-12);
  EXPECT_NEAR(eq.maxAngle, 60.0, 1e-12);
  EXPECT_NEAR(eq.aspectRatio, 1.0, 1e-15);

  // Obtuse isosceles: 120 degrees at the apex.
  const P g = { -std::sqrt(3.0) / 2, 0, 0 }, h = { std::sqrt(3.0) / 2, 0, 0 }, apex = { 0, 0.5, 0 };
  const TriangleMetrics obtuse = triangleMetrics(g.data(), h.data(), apex.data());
  EXPECT_NEAR(obtuse.maxAngle, 120.0, 1e-12);
  EXPECT_NEAR(obtuse.minAngle, 30.0, 1e-12);

  const TriangleMetrics point = triangleMetrics(a.data(), a.data(), a.data());
  EXPECT_EQ(point.minAngle, 0.0);
  EXPECT_EQ(point.maxAngle, 180.0);
  EXPECT_EQ(point.area, 0.0);
  EXPECT_EQ(point.aspectRatio, kMaxRatio);
  const P mid = { 0.5, 0, 0 };
  const TriangleMetrics line = triangleMetrics(a.data(), mid.data(), e.data());
  EXPECT_EQ(line.minAngle, 0.0);
  EXPECT_EQ(line.maxAngle, 180.0);
  EXPECT_NEAR(line.aspectRatio, 2.0, 1e-15);
}

TEST(Quality, CubeSurface)
{
  const SurfaceSummary s = cube(false).summary();
  EXPECT_EQ(s.elements, 12);
  EXPECT_NEAR(s.area, 6.0, 1e-14);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.consistentlyOriented);
  EXPECT_NEAR(s.enclosedVolume, 1.0, 1e-14);
  EXPECT_EQ(s.boundaryLoops, 0);
  EXPECT_EQ(s.boundaryEdges, 0);
  EXPECT_EQ(s.nonManifoldEdges, 0);
  EXPECT_EQ(s.shells, 1);
}

TEST(Quality, InsideOutCubeHasNegativeVolume)
{
  Surface c = cube(false);
  for (size_t t = 0; t < c.tris.size(); t += 3)
    std::swap(c.tris[t + 1], c.tris[t + 2]);
  EXPECT_NEAR(c.summary().enclosedVolume, -1.0, 1e-14);
}

TEST(Quality, OpenBox)
{
  const SurfaceSummary s = cube(true).summary();
  EXPECT_EQ(s.elements, 10);
  EXPECT_NEAR(s.area, 5.0, 1e-14);
  EXPECT_FALSE(s.closed);
  EXPECT_TRUE(std::isnan(s.enclosedVolume));
  EXPECT_EQ(s.boundaryEdges, 4);
  EXPECT_EQ(s.boundaryLoops, 1);
  EXPECT_EQ(s.shells, 1);
}

TEST(Quality, TwoDisjointSpheres)
{
  Surface s;
  addOctahedron(s, 0.0, 1.0);
  addOctahedron(s, 5.0, 2.0);
  const SurfaceSummary m = s.summary();
  EXPECT_EQ(m.shells, 2);
  EXPECT_EQ(m.boundaryLoops, 0);
  EXPECT_TRUE(m.closed);
  EXPECT_NEAR(m.enclosedVolume, 4.0 / 3.0 * (1.0 + 8.0), 1e-13);
  EXPECT_NEAR(m.area, 4.0 * std::sqrt(3.0) * (1.0 + 4.0), 1e-13);
}

TEST(Quality, NonManifoldEdge)
{
  Surface s;
  const int64_t a = s.addPoint(0, 0, 0), b = s.addPoint(1, 0, 0);
  const int64_t c = s.addPoint(0, 1, 0), d = s.addPoint(0, -1, 0), e = s.addPoint(0, 0, 1);
  s.addTri(a, b, c);
  s.addTri(b, a, d);
  s.addTri(a, b, e);
  const SurfaceSummary m = s.summary();
  EXPECT_EQ(m.nonManifoldEdges, 1);
  EXPECT_EQ(m.shells, 1);
  EXPECT_EQ(m.boundaryEdges, 6);
  EXPECT_EQ(m.boundaryLoops, 1); // the six boundary edges form one connected graph through a and b
  EXPECT_FALSE(m.closed);
}

TEST(Quality, VolumeGradient)
{
  // Tets 0 and 1 share face (0,1,2); tet 2 shares only an edge with tet 0; tet 3 is apart.
  const std::vector<double> pts = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -2,
                                    1, 1, 1, 5, 5, 5, 6, 5, 5, 5, 6, 5, 5, 5, 6 };
  const std::vector<long long> tets = { 0, 1, 2, 3, 0, 2, 1, 4, 0, 1, 5, 3, 6, 7, 8, 9 };
  std::vector<double> volume(4), gradient(4);
  TetMetricArrays out;
  out.volume = volume.data();
  measureTets(pts.data(), tets.data(), 0, 4, out);
  PointTets incidence;
  incidence.build(tets.data(), 4, 10);
  volumeGradient(tets.data(), volume.data(), incidence, 0, 4, gradient.data());
  EXPECT_NEAR(volume[0], 1.0 / 6.0, 1e-16);
  EXPECT_NEAR(volume[1], 2.0 / 6.0, 1e-16);
  // tet 0 touches tet 2 by face (0,1,3) as well: |1/6 - V2|
  const double g0 = std::max(std::fabs(volume[0] - volume[1]), std::fabs(volume[0] - volume[2]));
  EXPECT_DOUBLE_EQ(gradient[0], g0);
  EXPECT_DOUBLE_EQ(gradient[1], std::fabs(volume[1] - volume[0]));
  EXPECT_DOUBLE_EQ(gradient[3], 0.0);
}

TEST(Quality, StatisticsKnownValues)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> v = { 2, 4, nan, 4, 4, 5, 5, 7, 9 };
  const Statistics s = computeStatistics(v.data(), static_cast<int64_t>(v.size()), 7, Worst::Largest);
  EXPECT_EQ(s.count, 8);
  EXPECT_EQ(s.skipped, 1);
  EXPECT_EQ(s.min, 2.0);
  EXPECT_EQ(s.max, 9.0);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_DOUBLE_EQ(s.stddev, 2.0);
  EXPECT_EQ(s.worstIndex, 8);
  ASSERT_EQ(s.binEdges.size(), 8u);
  EXPECT_EQ(s.binEdges.front(), 2.0);
  EXPECT_EQ(s.binEdges.back(), 9.0);
  const std::vector<int64_t> expected = { 1, 0, 3, 2, 0, 1, 1 };
  EXPECT_EQ(s.binCounts, expected);
  const Statistics w = computeStatistics(v.data(), static_cast<int64_t>(v.size()), 7, Worst::Smallest);
  EXPECT_EQ(w.worstIndex, 0);
}

TEST(Quality, StatisticsConstantAndEmpty)
{
  const std::vector<double> same(10, 3.0);
  const Statistics s = computeStatistics(same.data(), 10, 4, Worst::Smallest);
  EXPECT_EQ(s.stddev, 0.0);
  EXPECT_EQ(s.binCounts[0] + s.binCounts[1] + s.binCounts[2] + s.binCounts[3], 10);
  EXPECT_LT(s.binEdges.front(), 3.0);
  EXPECT_GT(s.binEdges.back(), 3.0);
  const std::vector<double> none(3, std::numeric_limits<double>::quiet_NaN());
  const Statistics e = computeStatistics(none.data(), 3, 4, Worst::Smallest);
  EXPECT_EQ(e.count, 0);
  EXPECT_EQ(e.worstIndex, -1);
  EXPECT_TRUE(std::isnan(e.mean));
}

TEST(Quality, StatisticsChunkedEqualsSerial)
{
  // Many chunks: the partials merged in order equal the serial reference bit for bit, and histogram
  // counts sum to the number of measured values.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 180.0);
  std::vector<double> v(5 * kStatisticsChunk + 123);
  for (double& x : v)
    x = u(rng);
  const int64_t n = static_cast<int64_t>(v.size());
  const Statistics ref = computeStatistics(v.data(), n, 20, Worst::Smallest);
  std::vector<Partial> partials;
  std::vector<int64_t> counts(20, 0);
  for (int64_t b = 0; b < n; b += kStatisticsChunk)
    partials.push_back(accumulate(v.data(), b, std::min(n, b + kStatisticsChunk)));
  const Partial all = mergeInOrder(partials);
  const std::vector<double> edges = binEdges(all.min, all.max, 20);
  for (int64_t b = n; b > 0; b -= 1000) // a different split of the histogram
    histogram(v.data(), std::max<int64_t>(0, b - 1000), b, edges, counts.data());
  const Statistics s = finish(all, n, Worst::Smallest, edges, counts);
  EXPECT_EQ(s.mean, ref.mean);
  EXPECT_EQ(s.stddev, ref.stddev);
  EXPECT_EQ(s.worstIndex, ref.worstIndex);
  EXPECT_EQ(s.binCounts, ref.binCounts);
  int64_t sum = 0;
  for (int64_t c : s.binCounts)
    sum += c;
  EXPECT_EQ(sum, n);
  EXPECT_NEAR(s.mean, 90.0, 1.0);
  EXPECT_NEAR(s.stddev, 180.0 / std::sqrt(12.0), 1.0);
}
