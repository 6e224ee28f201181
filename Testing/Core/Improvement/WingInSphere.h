// The demo's domain for the quality stage's tests: the bundled wing (Testing/Data/straight_wing.stl) in a
// sphere 5x its size, meshed with the caller's options into a ghost-free TetMesh.
#pragma once

#include "Enclosures.h"
#include "MeshImprovement.h"
#include "MeshChecker.h"
#include "Mesher.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <string>

namespace volgrid
{

// The mesher's result for the domain.
inline void meshWingInSphere(const MesherOptions& options, MesherResult& r)
{
  SurfaceMesh wing;
  ASSERT_TRUE(readSurface(std::string(VOLGRID_TEST_DATA_DIR) + "/straight_wing.stl", wing).ok());
  mergeCoincidentPoints(wing);
  SurfaceMesh sphere;
  ASSERT_TRUE(makeEnclosure(enclosureAround(boundingBox(wing, true), EnclosureShape::Sphere, 5.0), sphere).ok());
  wing.append(sphere);
  ASSERT_TRUE(meshSurface(wing, options, r).ok());
}

// numBoundary (optional): the input points, the first vertices of the mesh (the boundary vertices).
inline void meshWingInSphere(const MesherOptions& options, TetMesh& mesh, int32_t* numBoundary = nullptr)
{
  MesherResult r;
  meshWingInSphere(options, r);
  ASSERT_FALSE(r.tets.empty());
  if (numBoundary)
    *numBoundary = r.numInputPoints;
  ASSERT_TRUE(tetMeshFromTets(r.points, r.tets, mesh).ok());
}

// Every tet positive and the adjacency consistent (MeshChecker.h; its hull checks are for a ball, this
// domain has two boundary surfaces).
inline void expectValidMesh(const TetMesh& mesh)
{
  MeshCheckOptions checkOptions;
  checkOptions.delaunay = false;
  const MeshCheckReport check = checkMesh(mesh, checkOptions);
  EXPECT_EQ(check.invertedTets, 0) << check.summary();
  EXPECT_EQ(check.badVertices + check.badNeighbors + check.asymmetricNeighbors + check.faceMismatches, 0)
    << check.summary();
}

// A test suite on the wing's mesh as the quality rounds leave it (default options without the
// orthogonality moves and the interior polish after them), built once for the suite (seconds); each test
// works on a copy in `mesh` (numBoundary: the boundary vertices, the first ones). Suite: the test class
// (one mesh per suite).
template<class Suite>
class WingSuite : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    wing_ = new TetMesh;
    MesherOptions options;
    options.improvement.orthogonalitySmoothing = false;
    options.improvement.interiorPolish = false;
    meshWingInSphere(options, *wing_, &numBoundary_);
  }
  static void TearDownTestSuite()
  {
    delete wing_;
    wing_ = nullptr;
  }
  void SetUp() override
  {
    ASSERT_GT(wing_->numTets(), 0) << "the wing did not mesh";
    mesh = *wing_;
    numBoundary = numBoundary_;
  }

  TetMesh mesh;
  int32_t numBoundary = 0;

private:
  static inline TetMesh* wing_ = nullptr;
  static inline int32_t numBoundary_ = 0;
};

} // namespace volgrid
