// Defect checks of Core/SurfaceChecks on hand-made cases: one case per defect class, the exact
// triangle-triangle test on touching/overlapping configurations, nesting and the mesher's Status.
#include "SurfaceChecks.h"

#include <gtest/gtest.h>

namespace
{
using namespace volgrid;

// Closed outward tetrahedron, optionally scaled and shifted.
void addTet(SurfaceMesh& m, double s = 1.0, double ox = 0, double oy = 0, double oz = 0)
{
  const int32_t b = m.numberOfPoints();
  m.addPoint(ox, oy, oz);
  m.addPoint(ox + s, oy, oz);
  m.addPoint(ox, oy + s, oz);
  m.addPoint(ox, oy, oz + s);
  m.addTriangle(b + 0, b + 2, b + 1);
  m.addTriangle(b + 0, b + 1, b + 3);
  m.addTriangle(b + 0, b + 3, b + 2);
  m.addTriangle(b + 1, b + 2, b + 3);
}

// Closed outward axis-aligned box made of 12 triangles.
void addBox(SurfaceMesh& m, double x0, double y0, double z0, double x1, double y1, double z1, bool inward = false)
{
  const int32_t b = m.numberOfPoints();
  for (int i = 0; i < 8; ++i)
  {
    m.addPoint(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  }
  const int q[6][4] = {
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
  };
  for (const auto& f : q)
  {
    if (inward)
    {
      m.addTriangle(b + f[0], b + f[2], b + f[1]);
      m.addTriangle(b + f[0], b + f[3], b + f[2]);
    }
    else
    {
      m.addTriangle(b + f[0], b + f[1], b + f[2]);
      m.addTriangle(b + f[0], b + f[2], b + f[3]);
    }
  }
}

bool intersect(const double* a, const double* b, const double* c, const int32_t ia[3], const double* d, const double* e,
               const double* f, const int32_t ib[3])
{
  const double* p[3] = { a, b, c };
  const double* q[3] = { d, e, f };
  return trianglesIntersect(p, ia, q, ib);
}
} // namespace

TEST(SurfaceChecks, CleanClosedShells)
{
  SurfaceMesh m;
  addTet(m);
  addBox(m, 3, 0, 0, 4, 1, 1);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_TRUE(r.consistentlyOriented());
  EXPECT_TRUE(r.meshable());
  ASSERT_EQ(r.shells.size(), 2u);
  EXPECT_NEAR(r.shells[0].signedVolume, 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(r.shells[1].signedVolume, 1.0, 1e-14);
  EXPECT_EQ(r.inwardShells(), 0);
  EXPECT_EQ(r.edges, 6 + 18);
  EXPECT_TRUE(surfaceStatus(r).ok());
}

TEST(SurfaceChecks, OpenSurfaceAndBoundaryLoops)
{
  SurfaceMesh m;
  addBox(m, 0, 0, 0, 1, 1, 1);
  // Remove the two triangles of the top face and one of the bottom face: two holes.
  m.triangles.erase(m.triangles.begin() + 3 * 2, m.triangles.begin() + 3 * 4);
  m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 3);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_FALSE(r.watertight());
  EXPECT_EQ(r.boundaryEdges, 4 + 3);
  EXPECT_EQ(r.boundaryLoops, 2);
  EXPECT_FALSE(r.shells[0].closed);
  const Status s = surfaceStatus(r);
  EXPECT_EQ(s.kind, ErrorKind::OpenSurface);
  EXPECT_NE(s.message.find("7 boundary edge"), std::string::npos) << s.message;
  EXPECT_FALSE(s.firstIds.empty());
  int flagged = 0;
  for (uint8_t f : r.edgeFlags)
  {
    flagged += (f & EdgeBoundary) ? 1 : 0;
  }
  EXPECT_EQ(flagged, 7);
}

TEST(SurfaceChecks, NonManifoldEdgeAndVertex)
{
  // Four triangles around the edge 0-1 (wildmeshing's edge_with_four_triangles).
  SurfaceMesh m;
  m.addPoint(0, 0, 0);
  m.addPoint(0, 0, 1);
  m.addPoint(1, 0, 0);
  m.addPoint(0, 1, 0);
  m.addPoint(-1, 0, 0);
  m.addPoint(0, -1, 0);
  for (int32_t k = 2; k < 6; ++k)
  {
    m.addTriangle(0, 1, k);
  }
  SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.nonManifoldEdges, 1);
  EXPECT_EQ(r.boundaryEdges, 8);
  EXPECT_EQ(r.nonManifoldVertices, 2);
  EXPECT_EQ(surfaceStatus(r).kind, ErrorKind::NonManifoldEdge);

  // Two closed tetrahedra sharing one vertex: a non-manifold vertex, still meshable.
  SurfaceMesh h;
  addTet(h);
  addTet(h, -1.0);
  mergeCoincidentPoints(h);
  r = checkSurface(h);
  EXPECT_EQ(r.nonManifoldVertices, 1);
  EXPECT_EQ(r.nonManifoldEdges, 0);
  EXPECT_EQ(r.shells.size(), 2u);
  EXPECT_EQ(r.selfIntersectingPairs + r.shellIntersectingPairs, 0);
  EXPECT_TRUE(surfaceStatus(r).ok());
}

TEST(SurfaceChecks, DegenerateAndDuplicateTriangles)
{
  SurfaceMesh m;
  addTet(m);
  const int32_t a = m.addPoint(0, 0, 0.25);
  const int32_t b = m.addPoint(0, 0, 0.75);
  m.addTriangle(0, a, b); // collinear: zero area
  m.addTriangle(1, 1, 2); // repeated point id
  m.addTriangle(3, 1, 0); // same point set as triangle 1, opposite order
  SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.degenerateTriangles, 2);
  EXPECT_EQ(r.firstDegenerateTriangles, (std::vector<int32_t>{ 4, 5 }));
  EXPECT_EQ(r.duplicateTriangles, 1);
  EXPECT_EQ(r.firstDuplicateTriangles, (std::vector<int32_t>{ 6 }));
  EXPECT_TRUE(r.triangleFlags[6] & TriangleDuplicate);
  const Status s = surfaceStatus(r);
  EXPECT_EQ(s.kind, ErrorKind::DegenerateTriangle);
  EXPECT_NE(s.message.find("2 degenerate"), std::string::npos) << s.message;
  EXPECT_EQ(s.firstIds, (std::vector<int64_t>{ 4, 5 }));
  m.triangles.resize(3 * 4);
  m.addTriangle(3, 1, 0);
  EXPECT_EQ(surfaceStatus(checkSurface(m)).kind, ErrorKind::DuplicateTriangle);
}

TEST(SurfaceChecks, InconsistentOrientation)
{
  SurfaceMesh m;
  addTet(m);
  std::swap(m.triangles[0], m.triangles[1]); // flip triangle 0
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_EQ(r.inconsistentEdges, 3);
  EXPECT_FALSE(r.consistentlyOriented());
  EXPECT_FALSE(r.shells[0].consistent);
  EXPECT_TRUE(surfaceStatus(r).ok()); // the mesher's even-odd rule does not need orientation
}

TEST(SurfaceChecks, TriangleTriangleExactCases)
{
  const double o[3] = { 0, 0, 0 }, x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
  const double h[3] = { 0.5, 0.5, 0 }, ny[3] = { 0, -1, 0 }, mid[3] = { 0.5, 0, 0 };
  const double up[3] = { 0.25, 0.25, 1 }, down[3] = { 0.25, 0.25, -1 }, far[3] = { 5, 5, 5 };
  const int32_t i012[3] = { 0, 1, 2 };
  // Shared edge 0-1, coplanar, same side: overlap.
  const int32_t i013[3] = { 0, 1, 3 };
  EXPECT_TRUE(intersect(o, x, y, i012, o, x, h, i013));
  // Shared edge, coplanar, opposite sides: only the edge.
  EXPECT_FALSE(intersect(o, x, y, i012, o, x, ny, i013));
  // Shared edge, not coplanar: only the edge.
  EXPECT_FALSE(intersect(o, x, y, i012, o, x, up, i013));
  // Shared vertex 0, the other triangle pierces through: intersection beyond the vertex.
  const int32_t i034[3] = { 0, 3, 4 };
  EXPECT_TRUE(intersect(o, x, y, i012, o, up, down, i034));
  // Shared vertex, other triangle on one side: only the vertex.
  EXPECT_FALSE(intersect(o, x, y, i012, o, up, far, i034));
  // Shared vertex, coplanar, collinear edges overlapping (0->mid along 0->x).
  EXPECT_TRUE(intersect(o, x, y, i012, o, mid, ny, i034));
  // No shared vertex: a vertex touching the interior of the other (T-junction) counts.
  const int32_t i345[3] = { 3, 4, 5 };
  const double top[3] = { 0.2, 0.2, 0 }, t1[3] = { 0.2, 0.2, 1 }, t2[3] = { 1, 1, 1 };
  EXPECT_TRUE(intersect(o, x, y, i012, top, t1, t2, i345));
  // Same triangle with distinct ids (coincident, not merged) overlaps.
  EXPECT_TRUE(intersect(o, x, y, i012, o, x, y, i345));
  // Disjoint parallel triangles.
  const double o2[3] = { 0, 0, 1e-300 }, x2[3] = { 1, 0, 1e-300 }, y2[3] = { 0, 1, 1e-300 };
  EXPECT_FALSE(intersect(o, x, y, i012, o2, x2, y2, i345));
  // Coplanar, disjoint, no shared vertex.
  const double a2[3] = { 1, 1, 0 }, b2[3] = { 2, 1, 0 }, c2[3] = { 1, 2, 0 };
  EXPECT_FALSE(intersect(o, x, y, i012, a2, b2, c2, i345));
  // Coplanar, edges crossing.
  const double d2[3] = { 0.3, -0.5, 0 }, e2[3] = { 0.3, 2, 0 }, f2[3] = { 2, 0.7, 0 };
  EXPECT_TRUE(intersect(o, x, y, i012, d2, e2, f2, i345));
}

TEST(SurfaceChecks, SelfIntersectingShell)
{
  // A box whose top corner (0,0,1) is pulled down through the bottom face: the top face's triangles
  // cross the bottom face's, all in one shell.
  SurfaceMesh m;
  addBox(m, 0, 0, 0, 1, 1, 1);
  m.points[3 * 4 + 0] = 0.5;
  m.points[3 * 4 + 1] = 0.5;
  m.points[3 * 4 + 2] = -1.0;
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_TRUE(r.watertight());
  EXPECT_GT(r.selfIntersectingPairs, 0);
  EXPECT_EQ(r.shellIntersectingPairs, 0);
  const Status s = surfaceStatus(r);
  EXPECT_EQ(s.kind, ErrorKind::SelfIntersection);
  EXPECT_GE(s.firstIds.size(), 2u);
}

TEST(SurfaceChecks, IntersectingShells)
{
  SurfaceMesh m;
  addBox(m, 0, 0, 0, 2, 2, 2);
  addBox(m, 1, 1, 1, 3, 3, 3);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
  EXPECT_GT(r.shellIntersectingPairs, 0);
  EXPECT_TRUE(r.shells[0].intersectsOtherShell);
  EXPECT_EQ(surfaceStatus(r).kind, ErrorKind::IntersectingShells);
  // Boxes touching along a face without sharing points: coplanar overlap counts too.
  SurfaceMesh t;
  addBox(t, 0, 0, 0, 1, 1, 1);
  addBox(t, 1, 0, 0, 2, 1, 1);
  EXPECT_EQ(surfaceStatus(checkSurface(t)).kind, ErrorKind::IntersectingShells);
}

TEST(SurfaceChecks, NestingAndOrientation)
{
  // Far field box, a body inside (inward-oriented, as the paper wants), a body inside a cavity of it.
  SurfaceMesh m;
  addBox(m, -10, -10, -10, 10, 10, 10);
  addBox(m, -2, -2, -2, 2, 2, 2, true);
  addBox(m, -1, -1, -1, 1, 1, 1);
  addBox(m, 5, 5, 5, 6, 6, 6);
  const SurfaceCheckReport r = checkSurface(m);
  ASSERT_EQ(r.shells.size(), 4u);
  EXPECT_TRUE(r.meshable());
  EXPECT_EQ(r.shells[0].depth, 0);
  EXPECT_EQ(r.shells[0].parent, -1);
  EXPECT_EQ(r.shells[1].depth, 1);
  EXPECT_EQ(r.shells[1].parent, 0);
  EXPECT_EQ(r.shells[2].depth, 2);
  EXPECT_EQ(r.shells[2].parent, 1);
  EXPECT_EQ(r.shells[3].depth, 1);
  EXPECT_EQ(r.shells[3].parent, 0);
  EXPECT_LT(r.shells[1].signedVolume, 0);
  EXPECT_EQ(r.inwardShells(), 1);
}

TEST(SurfaceChecks, PointInClosedSurfaceDegenerateRays)
{
  // Axis-parallel rays from these points run exactly along edges and through vertices of the box.
  SurfaceMesh m;
  addBox(m, 0, 0, 0, 1, 1, 1);
  std::vector<int32_t> all(m.numberOfTriangles());
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    all[t] = t;
  }
  const double center[3] = { 0.5, 0.5, 0.5 }, diag[3] = { 0.5, 0.5, 0.25 };
  const double outside[3] = { -1, 0, 0 }, onFace[3] = { 0.5, 0.5, 1 }, onEdge[3] = { 1, 1, 0.3 };
  const double outsideAligned[3] = { 2, 1, 1 }, corner[3] = { 0, 0, 0 };
  EXPECT_EQ(pointInClosedSurface(m, all, center), 1);
  EXPECT_EQ(pointInClosedSurface(m, all, diag), 1);
  EXPECT_EQ(pointInClosedSurface(m, all, outside), -1);
  EXPECT_EQ(pointInClosedSurface(m, all, outsideAligned), -1);
  EXPECT_EQ(pointInClosedSurface(m, all, onFace), 0);
  EXPECT_EQ(pointInClosedSurface(m, all, onEdge), 0);
  EXPECT_EQ(pointInClosedSurface(m, all, corner), 0);
}

TEST(SurfaceChecks, InvalidIdsAndEmpty)
{
  SurfaceMesh m;
  EXPECT_EQ(surfaceStatus(checkSurface(m)).kind, ErrorKind::EmptyInput);
  addTet(m);
  m.addTriangle(0, 1, 99);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.invalidTriangles, 1);
  EXPECT_FALSE(surfaceStatus(r).ok());
  EXPECT_NE(formatSurfaceReport(r).find("invalid triangles"), std::string::npos);
}
