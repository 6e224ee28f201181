// Surface repair: welding a triangle soup, removing zero-area/duplicate triangles, stitching,
// filling holes with a refined patch, and orienting shells (consistency, then away from the domain).
#include "../../Common/CorpusSkip.h"
#include "Enclosures.h"
#include "SurfaceChecks.h"
#include "SurfaceReader.h"
#include "SurfaceRepair.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace volgrid;

SurfaceMesh sphere(double r, double h)
{
  EnclosureOptions o;
  o.shape = EnclosureShape::Sphere;
  o.dimensions[0] = r;
  o.targetEdgeLength = h;
  SurfaceMesh m;
  makeEnclosure(o, m);
  return m;
}

SurfaceMesh box(double x0, double x1, double h)
{
  EnclosureOptions o;
  o.shape = EnclosureShape::Box;
  for (int k = 0; k < 3; ++k)
  {
    o.center[k] = 0.5 * (x0 + x1);
    o.dimensions[k] = x1 - x0;
  }
  o.targetEdgeLength = h;
  SurfaceMesh m;
  makeEnclosure(o, m);
  return m;
}
} // namespace

TEST(SurfaceRepair, WeldTriangleSoup)
{
  // Every triangle with its own three points, jittered by 1e-9: an STL-like soup.
  const SurfaceMesh clean = sphere(1.0, 0.3);
  SurfaceMesh soup;
  uint32_t x = 1;
  for (int32_t t = 0; t < clean.numberOfTriangles(); ++t)
  {
    int32_t ids[3];
    for (int k = 0; k < 3; ++k)
    {
      const double* p = clean.point(clean.triangle(t)[k]);
      x = x * 1664525u + 1013904223u;
      const double j = 1e-9 * (static_cast<double>(x >> 8) / 16777216.0 - 0.5);
      ids[k] = soup.addPoint(p[0] + j, p[1] - j, p[2] + j);
    }
    soup.addTriangle(ids[0], ids[1], ids[2]);
  }
  EXPECT_FALSE(checkSurface(soup).watertight());
  SurfaceMesh exactOnly = soup;
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(exactOnly, SurfaceRepairOptions(), &r).ok());
  EXPECT_FALSE(checkSurface(exactOnly).watertight()); // exact-only mode does not weld jittered points

  SurfaceRepairOptions o;
  o.weldTolerance = 1e-7;
  ASSERT_TRUE(repairSurface(soup, o, &r).ok());
  EXPECT_EQ(soup.numberOfPoints(), clean.numberOfPoints());
  EXPECT_EQ(r.weldedPoints, 3 * clean.numberOfTriangles() - clean.numberOfPoints());
  const SurfaceCheckReport c = checkSurface(soup);
  EXPECT_TRUE(c.meshable()) << formatSurfaceReport(c);
  EXPECT_NEAR(signedVolume(soup), signedVolume(clean), 1e-6);
}

TEST(SurfaceRepair, RemoveDegenerateAndDuplicate)
{
  SurfaceMesh m = box(0, 1, 1.0);
  const int32_t n = m.numberOfTriangles();
  const int32_t a = m.addPoint(0.25, 0, 0), b = m.addPoint(0.75, 0, 0);
  const int32_t corner = 0;
  m.addTriangle(corner, a, b);                                         // collinear on the box edge
  m.addTriangle(m.triangle(3)[2], m.triangle(3)[0], m.triangle(3)[1]); // duplicate of triangle 3
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(m, SurfaceRepairOptions(), &r).ok());
  EXPECT_EQ(r.removedDegenerate, 1);
  EXPECT_EQ(r.removedDuplicates, 1);
  EXPECT_EQ(r.unreferencedPointsRemoved, 2);
  EXPECT_EQ(m.numberOfTriangles(), n);
  EXPECT_TRUE(checkSurface(m).meshable());
}

TEST(SurfaceRepair, StitchSeparatedPatches)
{
  // The box's six faces as separate parts (duplicated seam points), like a CAD patch export.
  const SurfaceMesh b = box(0, 1, 0.25);
  SurfaceMesh parts;
  for (int32_t t = 0; t < b.numberOfTriangles(); ++t)
  {
    const int32_t base = parts.numberOfPoints();
    for (int k = 0; k < 3; ++k)
    {
      const double* p = b.point(b.triangle(t)[k]);
      const double jitter = 1e-10 * static_cast<double>((t * 3 + k) % 7); // seams do not coincide exactly
      parts.addPoint(p[0] + jitter, p[1], p[2] - jitter);
    }
    parts.addTriangle(base, base + 1, base + 2, t / 32);
  }
  SurfaceRepairOptions o;
  o.stitchTolerance = 1e-8; // relative to the bounding-box diagonal; only boundary points move
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(parts, o, &r).ok());
  EXPECT_GT(r.stitchedPoints, 0);
  EXPECT_TRUE(checkSurface(parts).meshable());
  EXPECT_EQ(parts.patchIds.size(), static_cast<size_t>(parts.numberOfTriangles()));
}

TEST(SurfaceRepair, FillHolesWithRefinedPatch)
{
  SurfaceMesh m = sphere(1.0, 0.12);
  const double fullVolume = signedVolume(m);
  // Cut two caps: a big one (z > 0.8) and a small one (x > 0.95).
  std::vector<int32_t> kept;
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    double c[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      for (int d = 0; d < 3; ++d)
      {
        c[d] += m.point(m.triangle(t)[k])[d] / 3.0;
      }
    }
    if (!(c[2] > 0.8 || c[0] > 0.95))
    {
      kept.insert(kept.end(), m.triangle(t), m.triangle(t) + 3);
    }
  }
  m.triangles = kept;
  SurfaceCheckReport before = checkSurface(m);
  ASSERT_EQ(before.boundaryLoops, 2);
  const int64_t bigLoop = before.boundaryEdges;

  // A size limit smaller than the big loop fills only the small one.
  SurfaceMesh limited = m;
  SurfaceRepairOptions o;
  o.maxHoleEdges = 20;
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(limited, o, &r).ok());
  EXPECT_EQ(r.loopsFilled, 1);
  EXPECT_EQ(r.loopsLeftOpen, 1);

  o.maxHoleEdges = static_cast<int>(bigLoop);
  ASSERT_TRUE(repairSurface(m, o, &r).ok());
  EXPECT_EQ(r.loopsFilled, 2);
  EXPECT_EQ(r.loopsLeftOpen, 0);
  EXPECT_GT(r.pointsAdded, 0); // refined, not a fan of the loop
  const SurfaceCheckReport after = checkSurface(m);
  EXPECT_TRUE(after.meshable()) << formatSurfaceReport(after);
  EXPECT_TRUE(after.consistentlyOriented());
  EXPECT_GT(signedVolume(m), 0.0);
  EXPECT_LT(signedVolume(m), fullVolume);
  EXPECT_GT(signedVolume(m), 0.9 * fullVolume);
  // Patch edges are comparable with the surrounding ones (no long fan spokes).
  double maxEdge = 0;
  for (int32_t t = 0; t < m.numberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double* p = m.point(m.triangle(t)[k]);
      const double* q = m.point(m.triangle(t)[(k + 1) % 3]);
      maxEdge = std::max(
        maxEdge,
        std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2])));
    }
  }
  EXPECT_LT(maxEdge, 0.4);
}

TEST(SurfaceRepair, OrientConsistentlyThenForDomain)
{
  // Far field, body (given outward), a cavity body inside it; some triangles flipped at random.
  SurfaceMesh m = box(-10, 10, 5.0);
  m.append(box(-2, 2, 1.0));
  m.append(box(-1, 1, 1.0));
  for (int32_t t = 0; t < m.numberOfTriangles(); t += 3)
  {
    std::swap(m.triangles[3 * size_t(t) + 1], m.triangles[3 * size_t(t) + 2]);
  }
  EXPECT_FALSE(checkSurface(m).consistentlyOriented());
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(m, SurfaceRepairOptions(), &r).ok());
  EXPECT_GT(r.trianglesFlipped, 0);
  const SurfaceCheckReport c = checkSurface(m);
  EXPECT_TRUE(c.consistentlyOriented());
  ASSERT_EQ(c.shells.size(), 3u);
  EXPECT_GT(c.shells[0].signedVolume, 0); // far field outward
  EXPECT_LT(c.shells[1].signedVolume, 0); // body inward: normals point away from the domain
  EXPECT_GT(c.shells[2].signedVolume, 0); // body in the body's cavity: outward again
}

TEST(SurfaceRepair, CorpusCastingAndFalcon)
{
  // casting.off: closed, consistent, INWARD -> flipped outward.
  VOLGRID_SKIP_WITHOUT_CORPUS_FILE("/tetgen-tests/meshlab/casting.off");
  VOLGRID_SKIP_WITHOUT_CORPUS_FILE("/aero-gmsh/InitialMeshFalcon.msh");
  SurfaceMesh casting;
  ASSERT_TRUE(readSurface(volgrid_testing::corpusPath("/tetgen-tests/meshlab/casting.off"), casting).ok());
  EXPECT_EQ(checkSurface(casting).inwardShells(), 1);
  SurfaceRepairReport r;
  ASSERT_TRUE(repairSurface(casting, SurfaceRepairOptions(), &r).ok());
  EXPECT_EQ(r.shellsFlipped, 1);
  const SurfaceCheckReport c = checkSurface(casting);
  EXPECT_EQ(c.inwardShells(), 0);
  EXPECT_TRUE(c.meshable());

  // InitialMeshFalcon.msh: 16 CAD patches not stitched (duplicated seam points). Stitching joins the
  // seams that coincide exactly; it stays open at the symmetry plane.
  SurfaceMesh falcon;
  SurfaceReadOptions keep;
  keep.mergeCoincidentPoints = false;
  ASSERT_TRUE(
    readSurface(std::string(VOLGRID_SHARED_DATA_DIR) + "/aero-gmsh/InitialMeshFalcon.msh", falcon, nullptr, keep).ok());
  const SurfaceCheckReport before = checkSurface(falcon);
  EXPECT_EQ(before.boundaryEdges, 1781);
  EXPECT_EQ(before.shells.size(), 8u);
  ASSERT_TRUE(repairSurface(falcon, SurfaceRepairOptions(), &r).ok());
  EXPECT_GT(r.weldedPoints + r.stitchedPoints, 0); // exact-only mode: the weld step joins the seams
  const SurfaceCheckReport after = checkSurface(falcon);
  EXPECT_LT(after.boundaryEdges, before.boundaryEdges);
  EXPECT_LT(after.shells.size(), before.shells.size());
  EXPECT_EQ(after.nonManifoldEdges, 0);
  EXPECT_EQ(after.selfIntersectingPairs, 0);
}
