// The whole pipeline on hand-made hard cases: boundary kept exactly, volume exact, valid tets.
#include "BoundaryCheck.h"
#include "Mesher.h"
#include "MesherTestShapes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace volgrid;

namespace
{

MesherResult meshAndCheck(const SurfaceMesh& s, MesherOptions opt = MesherOptions())
{
  MesherResult r;
  Status st = meshSurface(s, opt, r);
  EXPECT_TRUE(st.ok()) << st.message;
  if (!st.ok())
    return r;
  BoundaryCheckReport br =
    checkBoundaryConformity(r.points, r.numInputPoints, r.tets, s.triangles, r.stats.enclosedVolume);
  EXPECT_TRUE(br.meshValid()) << br.summary();
  if (opt.regionRule != RegionRule::KeepAll)
  {
    EXPECT_TRUE(br.boundaryEqualsInput()) << br.summary();
  }
  EXPECT_LT(br.relativeVolumeError, 1e-9) << br.summary();
  EXPECT_EQ(r.stats.steinerBoundary, 0);
  // Input points first, in order.
  for (int32_t i = 0; i < s.numberOfPoints() && i < r.numInputPoints; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(r.points[3 * i + k], s.points[3 * i + k]);
  return r;
}

} // namespace

TEST(Mesher, UnitCube)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  MesherResult r = meshAndCheck(s);
  EXPECT_NEAR(r.stats.tetVolume, 1.0, 1e-12);
  EXPECT_EQ(r.boundaryTriangles.size(), s.triangles.size());
}

TEST(Mesher, CubeWithTwistedFaceDiagonals)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 2, 1, 3 };
  testshapes::addBox(s, lo, hi, true);
  MesherResult r = meshAndCheck(s);
  EXPECT_NEAR(r.stats.tetVolume, 6.0, 1e-12);
}

TEST(Mesher, InwardCubeEvenOdd)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi, false, true);
  MesherResult r = meshAndCheck(s);
  EXPECT_NEAR(r.stats.tetVolume, 1.0, 1e-12);
}

TEST(Mesher, SchoenhardtPrismNeedsInteriorSteiner)
{
  SurfaceMesh s = testshapes::schoenhardt(30);
  MesherResult r = meshAndCheck(s);
  EXPECT_GE(r.stats.steinerInterior, 1);
  EXPECT_EQ(r.stats.steinerBoundary, 0);
}

TEST(Mesher, SchoenhardtFlipsOnlyIsReported)
{
  SurfaceMesh s = testshapes::schoenhardt(30);
  MesherOptions opt;
  opt.allowSteinerPoints = false;
  MesherResult r;
  Status st = meshSurface(s, opt, r);
  EXPECT_EQ(st.kind, ErrorKind::RecoveryFailed) << st.message;
}

TEST(Mesher, ThinSlab)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 10, 7, 0.001 };
  testshapes::addBox(s, lo, hi, true);
  meshAndCheck(s);
}

TEST(Mesher, NestedCubes)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 3, 3, 3 }, lo2[3] = { 1, 1, 1 }, hi2[3] = { 2, 2, 2 };
  testshapes::addBox(s, lo, hi);
  testshapes::addBox(s, lo2, hi2, true, true);
  MesherResult r = meshAndCheck(s);
  EXPECT_NEAR(r.stats.tetVolume, 26.0, 1e-9);
  // Keep-all: two regions, the whole outer cube.
  MesherOptions opt;
  opt.regionRule = RegionRule::KeepAll;
  MesherResult k = meshAndCheck(s, opt);
  EXPECT_EQ(k.stats.regions, 2);
  EXPECT_NEAR(k.stats.tetVolume, 27.0, 1e-9);
}

// Without the surface checks the shells come from edge connectivity alone: the same shells, numbered in
// the order of their first triangle, and the same mesh.
TEST(Mesher, ShellsWithoutSurfaceChecks)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 3, 3, 3 }, lo2[3] = { 1, 1, 1 }, hi2[3] = { 2, 2, 2 };
  testshapes::addBox(s, lo, hi);
  testshapes::addBox(s, lo2, hi2, true, true);
  const size_t outerTriangles = 12;
  MesherOptions opt;
  opt.checkSurface = false;
  MesherResult unchecked;
  // Not meshAndCheck: without the checks the nesting is unknown, so enclosedVolume is no reference.
  ASSERT_TRUE(meshSurface(s, opt, unchecked).ok());
  BoundaryCheckReport br = checkBoundaryConformity(unchecked.points, unchecked.numInputPoints, unchecked.tets,
                                                   s.triangles, unchecked.stats.enclosedVolume);
  EXPECT_TRUE(br.meshValid()) << br.summary();
  EXPECT_TRUE(br.boundaryEqualsInput()) << br.summary();
  ASSERT_EQ(unchecked.triangleShell.size(), s.triangles.size() / 3);
  for (size_t t = 0; t < unchecked.triangleShell.size(); ++t)
    EXPECT_EQ(unchecked.triangleShell[t], t < outerTriangles ? 0 : 1) << "triangle " << t;
  MesherResult checked = meshAndCheck(s);
  EXPECT_EQ(unchecked.tets, checked.tets);
  EXPECT_NEAR(unchecked.stats.tetVolume, 26.0, 1e-9);
}

TEST(Mesher, OrientationRule)
{
  // Sphere enclosure (normals pointing away from the domain = outward) around an inward cube.
  SurfaceMesh s;
  const double c[3] = { 0.5, 0.5, 0.5 };
  testshapes::addSphere(s, c, 3.0, 1);
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi, false, true);
  MesherOptions opt;
  opt.regionRule = RegionRule::Orientation;
  MesherResult r = meshAndCheck(s, opt);
  EXPECT_EQ(r.stats.regions, 1);
}

TEST(Mesher, SkinnyFacetsBox)
{
  SurfaceMesh s = testshapes::stripBox(25, 1.0, 10.0, 0.3);
  meshAndCheck(s);
}

TEST(Mesher, SphereInSphere)
{
  SurfaceMesh s;
  const double c[3] = { 0, 0, 0 };
  testshapes::addSphere(s, c, 10.0, 2);
  testshapes::addSphere(s, c, 1.0, 3);
  MesherResult r = meshAndCheck(s);
  EXPECT_GT(r.stats.tets, 0);
  // Patch ids: shell index.
  ASSERT_EQ(r.boundaryPatch.size() * 3, r.boundaryTriangles.size());
}

TEST(Mesher, RejectsOpenSurface)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  s.triangles.resize(s.triangles.size() - 3);
  MesherResult r;
  Status st = meshSurface(s, MesherOptions(), r);
  EXPECT_EQ(st.kind, ErrorKind::OpenSurface) << st.message;
  EXPECT_TRUE(r.tets.empty());
}

// The thread count (0 = all cores, 1, more threads than cores) does not change the mesh: the same points,
// bit for bit, and the same tets in the same order (README, "Threads").
TEST(Mesher, SameMeshForAnyThreadCount)
{
  SurfaceMesh s;
  const double c[3] = { 0, 0, 0 };
  testshapes::addSphere(s, c, 10.0, 2);
  testshapes::addSphere(s, c, 1.0, 3);
  MesherOptions opt;
  opt.threads = 8;
  const MesherResult first = meshAndCheck(s, opt);
  const MesherResult again = meshAndCheck(s, opt);
  opt.threads = 1;
  const MesherResult one = meshAndCheck(s, opt);
  opt.threads = 0;
  const MesherResult all = meshAndCheck(s, opt);
  ASSERT_GT(first.tets.size(), 0u);
  for (const MesherResult* r : { &again, &one, &all })
  {
    EXPECT_EQ(r->points, first.points);
    EXPECT_EQ(r->tets, first.tets);
    EXPECT_EQ(r->tetRegion, first.tetRegion);
    EXPECT_EQ(r->boundaryTriangles, first.boundaryTriangles);
  }
}

// Tets whose shape the input surface forces are marked per tet: four input (boundary) vertices and a
// dihedral angle under 10 or over 170 degrees; the count is in the statistics.
// A thin plate in a sphere: its edges leave tets under 5 deg after the first run of the quality stage, so the
// run with vertex collapses follows; on more than one thread both run at once (QualityRounds). The meshes
// must be those of one run after the other.
TEST(Mesher, CollapseRerunIsTheSameOnAnyThreadCount)
{
  const SurfaceMesh s = testshapes::plateInSphere();
  MesherOptions opt;
  opt.threads = 1;
  const MesherResult one = meshAndCheck(s, opt);
  ASSERT_GT(one.tets.size(), 0u);
  for (const int threads : { 2, 8 })
  {
    opt.threads = threads;
    const MesherResult r = meshAndCheck(s, opt);
    EXPECT_EQ(r.points, one.points) << threads << " threads";
    EXPECT_EQ(r.tets, one.tets) << threads << " threads";
    EXPECT_EQ(r.tetRegion, one.tetRegion) << threads << " threads";
  }
}

TEST(Mesher, ForcedTetsAreMarked)
{
  SurfaceMesh s = testshapes::stripBox(25, 1.0, 10.0, 0.3);
  const MesherResult r = meshAndCheck(s);
  ASSERT_EQ(r.tetForced.size() * 4, r.tets.size());
  int64_t marked = 0;
  const double q10 = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  for (size_t t = 0; t < r.tetForced.size(); ++t)
  {
    const int32_t* v = &r.tets[4 * t];
    const bool boundary =
      v[0] < r.numInputPoints && v[1] < r.numInputPoints && v[2] < r.numInputPoints && v[3] < r.numInputPoints;
    const bool bad =
      tetSineQuality(&r.points[3 * static_cast<size_t>(v[0])], &r.points[3 * static_cast<size_t>(v[1])],
                     &r.points[3 * static_cast<size_t>(v[2])], &r.points[3 * static_cast<size_t>(v[3])]) < q10;
    EXPECT_EQ(r.tetForced[t] != 0, boundary && bad) << t;
    marked += r.tetForced[t];
  }
  EXPECT_EQ(marked, r.stats.forcedTets);
}
