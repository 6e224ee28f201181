// Test fixture shared by the Recovery tests: the Delaunay tetrahedralization of a surface's points plus
// the corners of a far cube (as the mesher does), no ghosts, with the surface's constraints.
#pragma once

#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "SurfaceMesh.h"

#include <gtest/gtest.h>

#include <vector>

namespace volgrid
{
struct RecoverySetup
{
  TetMesh mesh;
  BoundaryConstraints bc;
  std::vector<VertexKind> kinds;
  // The far cube is [-far, far]^3.
  explicit RecoverySetup(const SurfaceMesh& s, double far = 10)
  {
    std::vector<double> xyz = s.points;
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 3; ++k)
        xyz.push_back(((c >> k) & 1) ? far : -far);
    DelaunayOptions o;
    o.keepGhosts = false;
    std::vector<int32_t> map;
    EXPECT_TRUE(buildDelaunay(xyz.data(), xyz.size() / 3, o, mesh, map).ok());
    bc.init(s.triangles.data(), s.numberOfTriangles());
    kinds.assign(xyz.size() / 3, VertexKind::Boundary);
  }
};
} // namespace volgrid
