// The demo's domain for the quality stage's tests: the bundled wing (Testing/Data/straight_wing.stl) in a
// sphere 5x its size, meshed with the caller's options into a ghost-free TetMesh.
#pragma once

#include "Enclosures.h"
#include "MeshImprovement.h"
#include "Mesher.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <string>

namespace volgrid
{

// numBoundary (optional): the input points, the first vertices of the mesh (the boundary vertices).
inline void meshWingInSphere(const MesherOptions& options, TetMesh& mesh, int32_t* numBoundary = nullptr)
{
  SurfaceMesh wing;
  ASSERT_TRUE(readSurface(std::string(VOLGRID_TEST_DATA_DIR) + "/straight_wing.stl", wing).ok());
  mergeCoincidentPoints(wing);
  SurfaceMesh sphere;
  ASSERT_TRUE(makeEnclosure(enclosureAround(boundingBox(wing, true), EnclosureShape::Sphere, 5.0), sphere).ok());
  wing.append(sphere);
  MesherResult r;
  ASSERT_TRUE(meshSurface(wing, options, r).ok());
  if (numBoundary)
    *numBoundary = r.numInputPoints;
  ASSERT_TRUE(tetMeshFromTets(r.points, r.tets, mesh).ok());
}

} // namespace volgrid
