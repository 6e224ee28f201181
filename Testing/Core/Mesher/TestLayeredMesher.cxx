// Boundary layers plus the conforming mesher (Core/Mesher/LayeredMesher.h): one conformal mixed mesh.
#include "LayeredMesher.h"

#include "../Layers/LayerTestShapes.h"
#include "MeshWriter.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <map>

using namespace volgrid;

namespace
{
LayerOptions tenLayers()
{
  LayerOptions o;
  o.layers = 10;
  o.firstHeight = 1e-3;
  o.growth = 1.2;
  return o;
}

double tetVolume(const std::vector<double>& p, const int32_t* v)
{
  const double* a = p.data() + 3 * size_t(v[0]);
  double u[3], w[3], z[3];
  for (int i = 0; i < 3; ++i)
    u[i] = p[3 * size_t(v[1]) + i] - a[i], w[i] = p[3 * size_t(v[2]) + i] - a[i], z[i] = p[3 * size_t(v[3]) + i] - a[i];
  return (u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) +
          u[2] * (w[0] * z[1] - w[1] * z[0])) /
    6;
}
} // namespace

TEST(LayeredMesher, SphereInSphereIsConformalWithPrismsAndTets)
{
  const SurfaceMesh s = layertest::sphereInSphere(3);
  LayeredMeshResult r;
  MesherOptions mo;
  mo.verify = true;
  const Status st = meshSurfaceWithLayers(s, mo, tenLayers(), r);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(r.wedges.size() / 6, size_t(12800));
  EXPECT_DOUBLE_EQ(r.layerStats.coverage(), 1.0);
  // The tet region's boundary is exactly the last layer's outer surface (and the far field).
  EXPECT_EQ(r.interfaceOnTets, 1280);
  EXPECT_EQ(r.tetBoundaryOnInterface, 1280);
  for (size_t t = 0; t < r.tets.size(); t += 4)
  {
    const double* p = r.points.data();
    ASSERT_GT(predicates::orient3d(p + 3 * size_t(r.tets[t]), p + 3 * size_t(r.tets[t + 1]),
                                   p + 3 * size_t(r.tets[t + 2]), p + 3 * size_t(r.tets[t + 3])),
              0);
  }
  for (size_t w = 0; w < r.wedges.size(); w += 6)
  {
    const auto at = [&](int i) { return r.points.data() + 3 * size_t(r.wedges[w + i]); };
    ASSERT_TRUE(prismIsValid(at(0), at(1), at(2), at(3), at(4), at(5))) << "wedge " << w / 6;
  }
  EXPECT_EQ(r.boundaryTriangles.size() / 3, size_t(1280 + 80)); // wall + far field
}

TEST(LayeredMesher, TheSizeStepToTheTetsIsMeasuredAndWarnedAbout)
{
  // Ten layers of 1e-3 (the last 5.2e-3 tall) under tets as large as the sphere's triangles: a step of
  // more than 4, with a warning. Thicker layers (growth 2: the last 0.51) bring the step down, whether
  // the prisms are kept or split.
  const SurfaceMesh s = layertest::sphereInSphere(3);
  LayeredMeshResult thin, thick, thickSplit;
  ASSERT_TRUE(meshSurfaceWithLayers(s, MesherOptions(), tenLayers(), thin).ok());
  EXPECT_EQ(thin.transition.faces, 1280);
  EXPECT_GT(thin.transition.medianRatio, 4);
  EXPECT_LE(thin.transition.minRatio, thin.transition.medianRatio);
  EXPECT_LE(thin.transition.medianRatio, thin.transition.p90Ratio);
  EXPECT_LE(thin.transition.p90Ratio, thin.transition.maxRatio);
  EXPECT_TRUE(std::any_of(thin.warnings.begin(), thin.warnings.end(),
                          [](const std::string& w) { return w.find("times as tall as it") != std::string::npos; }));
  LayerOptions o = tenLayers();
  o.growth = 2;
  ASSERT_TRUE(meshSurfaceWithLayers(s, MesherOptions(), o, thick).ok());
  o.splitPrisms = true;
  ASSERT_TRUE(meshSurfaceWithLayers(s, MesherOptions(), o, thickSplit).ok());
  EXPECT_EQ(thick.transition.faces, 1280);
  EXPECT_EQ(thickSplit.transition.faces, 1280);
  EXPECT_LT(thick.transition.medianRatio, thin.transition.medianRatio / 20);
  EXPECT_LT(thickSplit.transition.medianRatio, thin.transition.medianRatio / 20);
}

TEST(LayeredMesher, SplitPrismsGiveAConformalTetMesh)
{
  const SurfaceMesh s = layertest::sphereInSphere(2);
  LayerOptions o = tenLayers();
  o.splitPrisms = true;
  LayeredMeshResult r;
  ASSERT_TRUE(meshSurfaceWithLayers(s, MesherOptions(), o, r).ok());
  EXPECT_TRUE(r.wedges.empty());
  // Every face is shared by two tets, or is one of the boundary triangles: conformal, no hanging face.
  std::map<std::array<int32_t, 3>, int> faces;
  double volume = 0;
  int64_t layerTets = 0;
  for (size_t t = 0; t < r.tets.size() / 4; ++t)
  {
    const int32_t* v = r.tets.data() + 4 * t;
    ASSERT_GT(tetVolume(r.points, v), 0) << "tet " << t;
    volume += tetVolume(r.points, v);
    layerTets += r.tetLayer[t] >= 0 ? 1 : 0;
    for (int f = 0; f < 4; ++f)
    {
      std::array<int32_t, 3> key = { v[(f + 1) % 4], v[(f + 2) % 4], v[(f + 3) % 4] };
      std::sort(key.begin(), key.end());
      ++faces[key];
    }
  }
  EXPECT_EQ(layerTets, 3 * 10 * 320);
  int64_t single = 0;
  for (const auto& f : faces)
  {
    ASSERT_LE(f.second, 2);
    single += f.second == 1 ? 1 : 0;
  }
  EXPECT_EQ(single, static_cast<int64_t>(r.boundaryTriangles.size() / 3));
  // Volume between the spheres' polyhedra: the same as the surface encloses.
  std::vector<int32_t> body, far;
  for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
    (s.patchIds[t] == 1 ? body : far).push_back(t);
  EXPECT_NEAR(volume / (signedVolume(s, far) - signedVolume(s, body)), 1.0, 1e-9);
}

TEST(LayeredMesher, GmshWritesPrismsAndQuadsTetGenRefusesThem)
{
  // One prism (region 0) on a triangle (patch 3), its side quad on patch 5, its top on patch 4.
  SolverMesh mesh;
  mesh.points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1 };
  mesh.prisms = { 0, 1, 2, 3, 4, 5 };
  mesh.prismRegion = { 0 };
  mesh.triangles = { 0, 2, 1, 3, 4, 5 };
  mesh.trianglePatch = { 3, 4 };
  mesh.quads = { 0, 1, 4, 3 };
  mesh.quadPatch = { 5 };
  const std::string dir = ::testing::TempDir();
  for (const MeshFormat format : { MeshFormat::Gmsh22, MeshFormat::Gmsh41 })
  {
    const std::string path = dir + "/layers_prism.msh";
    ASSERT_TRUE(writeSolverMesh(path, mesh, format).ok());
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string elements = text.substr(text.find("$Elements"));
    if (format == MeshFormat::Gmsh22) // number, type, 2 tags (physical = entity = the normalized label), nodes
    {
      EXPECT_NE(elements.find("\n4 6 2 1 1 1 2 3 4 5 6\n"), std::string::npos) << elements;
      EXPECT_NE(elements.find("\n3 3 2 3 3 1 2 5 4\n"), std::string::npos) << elements;
    }
    else // blocks: 2 triangle blocks, 1 quad block, 1 prism block
    {
      EXPECT_NE(elements.find("\n4 4 1 4\n"), std::string::npos) << elements;
      EXPECT_NE(elements.find("\n2 3 3 1\n"), std::string::npos) << elements;
      EXPECT_NE(elements.find("\n3 1 6 1\n4 1 2 3 4 5 6\n"), std::string::npos) << elements;
    }
  }
  // SU2, Medit, CGNS, Exodus and OpenFOAM take prisms too (TestSolverMesh.cxx); TetGen refuses them.
  const Status refused = writeSolverMesh(dir + "/layers_prism.node", mesh, MeshFormat::TetGen);
  EXPECT_EQ(refused.kind, ErrorKind::InvalidOption);
  EXPECT_NE(refused.message.find("prisms are not written to TetGen"), std::string::npos) << refused.message;
}
