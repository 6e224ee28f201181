// Sizing field: the paper's point distribution function, its interpolation into the volume, the gradation
// bound, the global caps and the user inputs (callback, background cloud, sized points).
#include "Enclosures.h"
#include "SizingField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace volgrid;

namespace
{
double dist(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

SurfaceMesh sphere(double r, double edge, double cx = 0)
{
  SurfaceMesh s;
  EnclosureOptions o;
  o.shape = EnclosureShape::Sphere;
  o.dimensions[0] = r;
  o.center[0] = cx;
  o.targetEdgeLength = edge;
  EXPECT_TRUE(makeEnclosure(o, s).ok());
  return s;
}

// Largest violation of h(v) <= h(u) + slope |uv| over the finite background edges (<= 0 when it holds).
double worstGradation(const LinearInterpolant& f, double slope)
{
  const TetMesh& m = f.mesh();
  double worst = -1e300;
  m.forEachFiniteTet(
    [&](int32_t t)
    {
      const int32_t* v = m.vertices(t);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (i != j)
          {
            const double excess = f.values()[v[j]] - f.values()[v[i]] - slope * dist(m.point(v[i]), m.point(v[j]));
            worst = std::max(worst, excess / f.values()[v[i]]);
          }
    });
  return worst;
}
} // namespace

TEST(SizingField, PointDistributionFunctionIsMeanEdgeLength)
{
  // A tetrahedron surface with unequal edges, plus an unused point.
  const std::vector<double> p = { 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 3, 5, 5, 5 };
  const std::vector<int32_t> tris = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
  const std::vector<double> pdf = pointDistributionFunction(p.data(), 5, tris.data(), 4);
  ASSERT_EQ(pdf.size(), 5u);
  auto d = [&](int a, int b) { return dist(&p[3 * a], &p[3 * b]); };
  EXPECT_NEAR(pdf[0], (d(0, 1) + d(0, 2) + d(0, 3)) / 3, 1e-15);
  EXPECT_NEAR(pdf[1], (d(1, 0) + d(1, 2) + d(1, 3)) / 3, 1e-15);
  EXPECT_NEAR(pdf[3], (d(3, 0) + d(3, 1) + d(3, 2)) / 3, 1e-15);
  EXPECT_EQ(pdf[4], 0.0);
}

TEST(SizingField, InterpolatesBoundarySizesIntoTheVolume)
{
  // Fine inner sphere (r = 1, edge ~0.1) inside a coarse outer sphere (r = 4, edge ~0.8): between them
  // the size must lie between the two and grow outwards.
  SurfaceMesh s = sphere(1, 0.1);
  s.append(sphere(4, 0.8));
  SizingField f;
  SizingOptions o;
  o.gradation = 0; // plain interpolation
  ASSERT_TRUE(f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  double prev = 0;
  for (double r = 1.2; r < 3.9; r += 0.5)
  {
    const double p[3] = { r * 0.6, r * 0.0, r * 0.8 };
    const double h = f.evaluate(p);
    EXPECT_GT(h, 0.8 * f.minNodeSize());
    EXPECT_LT(h, 1.2 * f.maxNodeSize());
    EXPECT_GT(h, prev) << "r=" << r;
    prev = h;
  }
  // At a boundary point the size is its PDF.
  const std::vector<double> pdf =
    pointDistributionFunction(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles());
  for (int32_t i = 0; i < s.numberOfPoints(); i += 97)
    EXPECT_NEAR(f.evaluate(s.point(i)), pdf[i], 1e-9 * pdf[i]);
}

namespace
{
// The gradation limit on surface s: it lowers sizes only, until every background edge holds the bound,
// and no further (a lowered node's size is reached from a neighbour along one edge).
void expectGradedAlongEdges(const SurfaceMesh& s)
{
  for (double g : { 1.2, 1.5, 1.8 })
  {
    SizingField raw, graded;
    SizingOptions o;
    o.gradation = 0;
    ASSERT_TRUE(raw.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
    EXPECT_GT(worstGradation(raw.nodes(), g - 1), 0.01) << "the test case must need grading";
    o.gradation = g;
    ASSERT_TRUE(graded.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
    EXPECT_LE(worstGradation(graded.nodes(), g - 1), 1e-12) << "gradation " << g;
    const std::vector<double>& hRaw = raw.nodes().values();
    const std::vector<double>& h = graded.nodes().values();
    for (size_t i = 0; i < hRaw.size(); ++i)
      EXPECT_LE(h[i], hRaw[i] * (1 + 1e-15));
    const TetMesh& m = graded.nodes().mesh();
    std::vector<uint8_t> tight(h.size(), 0);
    m.forEachFiniteTet(
      [&](int32_t t)
      {
        const int32_t* v = m.vertices(t);
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            if (i != j && std::abs(h[v[i]] + (g - 1) * dist(m.point(v[i]), m.point(v[j])) - h[v[j]]) <= 1e-12 * h[v[j]])
              tight[v[j]] = 1;
      });
    int64_t loose = 0;
    for (size_t i = 0; i < h.size(); ++i)
      loose += h[i] < hRaw[i] * (1 - 1e-12) && !tight[i];
    EXPECT_EQ(loose, 0) << "gradation " << g;
  }
}
} // namespace

TEST(SizingField, GradationBoundHoldsBetweenNeighbours)
{
  // A very fine small sphere close inside a coarse sphere: the raw sizes jump, the graded ones not. Both
  // orders of the spheres' points: the grading runs along the edges both ways.
  SurfaceMesh fineFirst = sphere(0.4, 0.02, 0.0), coarseFirst = sphere(1, 1.0);
  fineFirst.append(sphere(1, 1.0));
  coarseFirst.append(sphere(0.4, 0.02, 0.0));
  expectGradedAlongEdges(fineFirst);
  expectGradedAlongEdges(coarseFirst);
}

TEST(SizingField, CapsAndUserFunction)
{
  SurfaceMesh s = sphere(1, 0.2);
  SizingOptions o;
  o.maxEdgeLength = 0.15;
  SizingField f;
  f.setUserFunction([](const double* p) { return p[0] > 0.5 ? 0.05 : 1e9; });
  ASSERT_TRUE(f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  const double a[3] = { 0, 0, 0 }, b[3] = { 0.7, 0, 0 };
  EXPECT_LE(f.evaluate(a), 0.15);
  EXPECT_GT(f.evaluate(a), 0.05);
  EXPECT_NEAR(f.evaluate(b), 0.05, 1e-15);
  o.minEdgeLength = 0.1;
  ASSERT_TRUE(f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  EXPECT_NEAR(f.evaluate(b), 0.1, 1e-15);
  o.minEdgeLength = 1;
  EXPECT_EQ(f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).kind,
            ErrorKind::InvalidOption);
}

TEST(SizingField, BackgroundCloudIsInterpolatedLinearly)
{
  // Sizes linear in x on a jittered grid: the interpolant reproduces a linear function.
  std::vector<double> xyz, h;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      for (int k = 0; k <= 6; ++k)
      {
        const double p[3] = { -1.5 + 0.5 * i + 0.01 * ((j * 7 + k) % 5), -1.5 + 0.5 * j, -1.5 + 0.5 * k + 0.003 * i };
        xyz.insert(xyz.end(), p, p + 3);
        h.push_back(0.2 + 0.05 * p[0]);
      }
  SurfaceMesh s = sphere(1, 0.3);
  SizingField f;
  f.setBackgroundCloud(xyz.data(), h.data(), h.size());
  SizingOptions o;
  ASSERT_TRUE(f.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  for (double x = -0.8; x <= 0.8; x += 0.2)
  {
    const double p[3] = { x, 0.1, -0.2 };
    EXPECT_NEAR(f.evaluate(p), 0.2 + 0.05 * x, 1e-9) << x;
  }
}

TEST(SizingField, SizedPointsDensifyTheirNeighbourhood)
{
  SurfaceMesh s = sphere(1, 0.2);
  const double c[3] = { 0.2, 0.1, 0 };
  const double hc = 0.02;
  SizingField plain, sized;
  SizingOptions o;
  o.gradation = 1.5;
  ASSERT_TRUE(plain.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  sized.addSizedPoints(c, &hc, 1);
  ASSERT_TRUE(sized.build(s.points.data(), s.numberOfPoints(), s.triangles.data(), s.numberOfTriangles(), o).ok());
  EXPECT_NEAR(sized.evaluate(c), hc, 1e-12);
  const double near[3] = { 0.25, 0.1, 0 };
  EXPECT_LT(sized.evaluate(near), 0.5 * plain.evaluate(near));
  // Far away (on the boundary) the size is unchanged.
  EXPECT_NEAR(sized.evaluate(s.point(0)), plain.evaluate(s.point(0)), 1e-12);
}

// Outside the nodes' hull the value is the one at the hull point nearest the query, whatever tet the walk
// starts from. Below a flat hull (the nodes of a symmetry plane) every hull face is on the query's side,
// so the face the walk happens to cross says nothing: a far start gave the value of a far face.
TEST(LinearInterpolant, OutsideTheHullTheValueIsAtTheNearestHullPoint)
{
  std::vector<double> xyz, values;
  const auto f = [](double x, double y, double z) { return 1 + 2 * x - 3 * y + 0.5 * z; }; // linear: exact
  uint32_t seed = 12345;
  const auto jitter = [&]()
  {
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 0.02;
  };
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
    {
      const double x = i / 10.0 + (i % 10 ? jitter() : 0), y = j / 10.0 + (j % 10 ? jitter() : 0);
      xyz.insert(xyz.end(), { x, y, 0.0 });
      values.push_back(f(x, y, 0));
    }
  for (int k = 0; k < 40; ++k)
  {
    const double x = 0.5 + 20 * jitter(), y = 0.5 + 20 * jitter(), z = 0.3 + 30 * jitter();
    xyz.insert(xyz.end(), { x, y, z });
    values.push_back(f(x, y, z));
  }
  LinearInterpolant interpolant;
  ASSERT_TRUE(interpolant.build(xyz.data(), values.size(), values.data()).ok());
  ASSERT_FALSE(interpolant.degenerate());
  // Start tets: every tet the walks to these points end in.
  std::vector<int32_t> starts = { -1 };
  for (const double* s : { &xyz[0], &xyz[3 * 120], &xyz[3 * 130], &xyz[3 * 10] })
  {
    const double above[3] = { s[0] * 0.98 + 0.01, s[1] * 0.98 + 0.01, 0.05 };
    int32_t hint = -1;
    interpolant.evaluate(above, hint);
    starts.push_back(hint);
  }
  for (double x = 0.05; x < 1; x += 0.1)
    for (double y = 0.07; y < 1; y += 0.1)
    {
      const double below[3] = { x, y, -0.3 }; // nearest hull point (x, y, 0)
      int32_t firstHint = starts[0];
      const double first = interpolant.evaluate(below, firstHint);
      EXPECT_NEAR(first, f(x, y, 0), 1e-12) << x << " " << y;
      for (int32_t start : starts)
      {
        int32_t hint = start;
        EXPECT_EQ(interpolant.evaluate(below, hint), first) << x << " " << y << " from tet " << start;
      }
    }
  // Beyond the square's edge x = 1 and below it: the nearest hull point is on the edge.
  const double beyond[3] = { 1.4, 0.55, -0.2 };
  int32_t hint = -1;
  EXPECT_NEAR(interpolant.evaluate(beyond, hint), f(1, 0.55, 0), 1e-12);
}
