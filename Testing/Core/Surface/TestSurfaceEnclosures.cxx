// Enclosures: every primitive is closed, manifold, outward, free of intersections, well shaped, and
// its volume is within 1% of the exact primitive volume.
#include "Enclosures.h"
#include "SurfaceChecks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace volgrid;

double minQuality(const SurfaceMesh& m, double& maxEdge)
{
  double q = 1.0;
  maxEdge = 0.0;
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    const double* p[3] = { m.point(m.triangle(t)[0]), m.point(m.triangle(t)[1]), m.point(m.triangle(t)[2]) };
    double l2 = 0, e[3][3];
    for (int i = 0; i < 3; ++i)
    {
      double s = 0;
      for (int k = 0; k < 3; ++k)
      {
        e[i][k] = p[(i + 1) % 3][k] - p[i][k];
        s += e[i][k] * e[i][k];
      }
      l2 += s;
      maxEdge = std::max(maxEdge, std::sqrt(s));
    }
    const double n[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                          e[0][0] * e[1][1] - e[0][1] * e[1][0] };
    q = std::min(q, 2.0 * std::sqrt(3.0) * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / l2);
  }
  return q;
}

void expectGoodEnclosure(const EnclosureOptions& o, double minQ)
{
  SurfaceMesh m;
  const Status s = makeEnclosure(o, m);
  ASSERT_TRUE(s.ok()) << s.message;
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_TRUE(r.meshable()) << formatSurfaceReport(r);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.consistentlyOriented());
  EXPECT_EQ(r.nonManifoldVertices, 0);
  ASSERT_EQ(r.shells.size(), 1u);
  EXPECT_GT(r.shells[0].signedVolume, 0.0) << "not outward";
  const double exact = enclosureExactVolume(o);
  EXPECT_NEAR(signedVolume(m), exact, 0.01 * exact);
  double maxEdge = 0;
  EXPECT_GT(minQuality(m, maxEdge), minQ);
  if (o.targetEdgeLength > 0)
  {
    EXPECT_LT(maxEdge, 2.0 * o.targetEdgeLength);
  }
}
} // namespace

TEST(SurfaceEnclosures, Box)
{
  EnclosureOptions o;
  o.shape = EnclosureShape::Box;
  o.center[0] = 1;
  o.dimensions[0] = 3;
  o.dimensions[1] = 2;
  o.dimensions[2] = 0.5;
  o.targetEdgeLength = 0.2;
  expectGoodEnclosure(o, 0.6);
}

TEST(SurfaceEnclosures, SphereIsAnIcosphere)
{
  EnclosureOptions o;
  o.shape = EnclosureShape::Sphere;
  o.dimensions[0] = 10;
  o.targetEdgeLength = 1.0;
  expectGoodEnclosure(o, 0.75);
  SurfaceMesh m;
  ASSERT_TRUE(makeEnclosure(o, m).ok());
  EXPECT_EQ(m.numberOfTriangles() % 20, 0); // 20 n^2 triangles
  EXPECT_EQ(m.numberOfPoints(), m.numberOfTriangles() / 2 + 2);
}

TEST(SurfaceEnclosures, CylinderHemisphereEllipsoid)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    SCOPED_TRACE(axis);
    EnclosureOptions c;
    c.shape = EnclosureShape::Cylinder;
    c.axis = axis;
    c.dimensions[0] = 2;
    c.dimensions[1] = 5;
    c.targetEdgeLength = 0.25;
    expectGoodEnclosure(c, 0.3);
    EnclosureOptions h;
    h.shape = EnclosureShape::Hemisphere;
    h.axis = axis;
    h.dimensions[0] = 3;
    h.targetEdgeLength = 0.25;
    expectGoodEnclosure(h, 0.3);
    h.domeNegative = true;
    expectGoodEnclosure(h, 0.3);
  }
  EnclosureOptions e;
  e.shape = EnclosureShape::Ellipsoid;
  e.dimensions[0] = 4;
  e.dimensions[1] = 2;
  e.dimensions[2] = 1.5;
  e.targetEdgeLength = 0.2;
  expectGoodEnclosure(e, 0.25);
}

TEST(SurfaceEnclosures, AroundABodyNestsIt)
{
  // A body (a small box) inside each enclosure sized by factor 3 of its bounding box: two shells,
  // no intersection, the body at depth 1.
  EnclosureOptions bodyOptions;
  bodyOptions.shape = EnclosureShape::Box;
  bodyOptions.center[0] = 5;
  bodyOptions.dimensions[0] = 4;
  bodyOptions.dimensions[1] = 1;
  bodyOptions.dimensions[2] = 0.3;
  SurfaceMesh body;
  ASSERT_TRUE(makeEnclosure(bodyOptions, body).ok());
  const BoundingBox box = boundingBox(body);
  for (EnclosureShape shape : { EnclosureShape::Box, EnclosureShape::Sphere, EnclosureShape::Cylinder,
                                EnclosureShape::Hemisphere, EnclosureShape::Ellipsoid })
  {
    SCOPED_TRACE(static_cast<int>(shape));
    EnclosureOptions o = enclosureAround(box, shape, 3.0, 0);
    if (shape == EnclosureShape::Hemisphere)
    {
      o.center[0] -= 1.0; // keep the body off the disk for this test
    }
    SurfaceMesh m;
    ASSERT_TRUE(makeEnclosure(o, m).ok());
    m.append(body);
    const SurfaceCheckReport r = checkSurface(m);
    EXPECT_TRUE(r.meshable()) << formatSurfaceReport(r);
    ASSERT_EQ(r.shells.size(), 2u);
    EXPECT_EQ(r.shells[1].depth, 1);
    EXPECT_EQ(r.shells[1].parent, 0);
  }
  EnclosureOptions bad;
  bad.dimensions[0] = -1;
  SurfaceMesh m;
  EXPECT_EQ(makeEnclosure(bad, m).kind, ErrorKind::InvalidOption);
  bad.dimensions[0] = 1;
  bad.targetEdgeLength = 1e-9;
  EXPECT_EQ(makeEnclosure(bad, m).kind, ErrorKind::InvalidOption);
}
