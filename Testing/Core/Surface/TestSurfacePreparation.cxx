// Surface preparation (the sequence behind Surface Prep and `volgrid prep`): a box with a hole and a
// flipped triangle comes out closed, consistently oriented and meshable inside a far-field sphere, and
// the summary rows report the defects before and after and the repairs made.
#include "../MesherTestShapes.h"
#include "SurfacePreparation.h"

#include <gtest/gtest.h>

#include <string>

using namespace volgrid;

namespace
{
// A unit box missing its last triangle, with its first triangle reversed.
SurfaceMesh damagedBox()
{
  SurfaceMesh box;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(box, lo, hi);
  box.triangles.resize(box.triangles.size() - 3);
  std::swap(box.triangles[1], box.triangles[2]);
  return box;
}

const SurfacePreparationRow& row(const std::vector<SurfacePreparationRow>& rows, const std::string& key)
{
  for (const SurfacePreparationRow& r : rows)
    if (key == r.key)
      return r;
  ADD_FAILURE() << "no row " << key;
  return rows.front();
}
} // namespace

TEST(SurfacePreparation, RepairsEnclosesAndReports)
{
  SurfaceMesh mesh = damagedBox();
  SurfacePreparationOptions options;
  options.enclosure = true;
  options.shape = EnclosureShape::Sphere;
  SurfacePreparationReport report;
  ASSERT_TRUE(prepareSurface(mesh, 1, options, report).ok());
  EXPECT_TRUE(report.haveInput);
  EXPECT_TRUE(report.meshable);
  EXPECT_EQ(report.enclosurePatchId, 1);
  EXPECT_EQ(report.output.shells.size(), 2u);
  EXPECT_EQ(misorientedShells(report.output), 0);

  const std::vector<SurfacePreparationRow> rows = surfacePreparationRows(report, 1);
  EXPECT_EQ(row(rows, "BoundaryEdges").input, 3);
  EXPECT_EQ(row(rows, "BoundaryEdges").output, 0);
  EXPECT_GT(row(rows, "InconsistentEdges").input, 0);
  EXPECT_EQ(row(rows, "LoopsFilled").output, 1);
  EXPECT_EQ(row(rows, "SelfIntersectingPairs").output, 0);
  EXPECT_EQ(row(rows, "Parts").output, 1);
  EXPECT_EQ(surfacePreparationWarning(report, rows, mesh.numberOfTriangles()), "");
}

// Preparing a prepared domain again changes nothing, even where two sheets of the body are closer than the
// weld tolerance of the larger box the far field makes (here a slab 2e-6 thick in a sphere 10 times its size:
// 1e-6 x the diagonal is about 1.7e-5). Before, the second preparation welded the slab's top to its bottom
// and called the result open and non-manifold (found on a swept wing's trailing edge).
TEST(SurfacePreparation, PreparingAPreparedDomainAgainChangesNothing)
{
  SurfaceMesh mesh;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 2e-6 };
  testshapes::addBox(mesh, lo, hi);
  SurfacePreparationOptions options;
  options.enclosure = true;
  SurfacePreparationReport first;
  ASSERT_TRUE(prepareSurface(mesh, 1, options, first).ok());
  ASSERT_TRUE(first.meshable);
  const SurfaceMesh prepared = mesh;
  SurfacePreparationOptions again; // no new enclosure: the domain already has one
  SurfacePreparationReport second;
  ASSERT_TRUE(prepareSurface(mesh, 2, again, second).ok());
  EXPECT_TRUE(second.meshable);
  EXPECT_EQ(second.repair.weldedPoints, 0);
  EXPECT_EQ(second.repair.removedDegenerate, 0);
  EXPECT_EQ(mesh.points, prepared.points);
  EXPECT_EQ(mesh.triangles, prepared.triangles);
}

TEST(SurfacePreparation, LeftDefectsAreWarnedAndUnmeasuredCountsSaySo)
{
  SurfaceMesh mesh = damagedBox();
  SurfacePreparationOptions options;
  options.maxHoleEdges = 0; // leave the hole open
  options.checkIntersections = false;
  SurfacePreparationReport report;
  ASSERT_TRUE(prepareSurface(mesh, 1, options, report).ok());
  EXPECT_FALSE(report.meshable);
  const std::vector<SurfacePreparationRow> rows = surfacePreparationRows(report, 1);
  EXPECT_EQ(row(rows, "BoundaryEdges").output, 3);
  EXPECT_EQ(row(rows, "SelfIntersectingPairs").output, -1);
  const std::string warning = surfacePreparationWarning(report, rows, mesh.numberOfTriangles());
  EXPECT_NE(warning.find("not meshable"), std::string::npos) << warning;
  EXPECT_NE(warning.find("Open edges: 3"), std::string::npos) << warning;
}

TEST(SurfacePreparation, EnclosureAloneAndBadEnclosure)
{
  SurfaceMesh mesh;
  SurfacePreparationOptions options;
  options.enclosure = true;
  options.explicitEnclosure.shape = EnclosureShape::Box;
  options.explicitEnclosure.dimensions[0] = 2;
  SurfacePreparationReport report;
  ASSERT_TRUE(prepareSurface(mesh, 0, options, report).ok());
  EXPECT_FALSE(report.haveInput);
  EXPECT_TRUE(report.meshable);
  EXPECT_EQ(surfacePreparationRows(report, 0)[0].input, -1); // no input: not measured

  SurfaceMesh none;
  options.explicitEnclosure.dimensions[0] = -1;
  const Status status = prepareSurface(none, 0, options, report);
  EXPECT_EQ(status.kind, ErrorKind::InvalidOption);
  EXPECT_EQ(status.message.rfind("Enclosure: ", 0), 0u) << status.message;
}
