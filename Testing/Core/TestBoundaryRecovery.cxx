// Boundary recovery on its own: flips (2-3, 3-2, edge removal), Steiner fallback, constraints kept.
#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "MeshChecker.h"
#include "MesherTestShapes.h"
#include "Predicates.h"

#include <gtest/gtest.h>

using namespace volgrid;

namespace
{

// Delaunay of the surface points plus a far box (as the mesher does), no ghosts.
struct RecoverySetup
{
  TetMesh mesh;
  BoundaryConstraints bc;
  std::vector<VertexKind> kinds;
  explicit RecoverySetup(const SurfaceMesh& s)
  {
    std::vector<double> xyz = s.points;
    const double lo = -10, hi = 10;
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 3; ++k)
        xyz.push_back(((c >> k) & 1) ? hi : lo);
    DelaunayOptions o;
    o.keepGhosts = false;
    std::vector<int32_t> map;
    EXPECT_TRUE(buildDelaunay(xyz.data(), xyz.size() / 3, o, mesh, map).ok());
    bc.init(s.triangles.data(), s.numberOfTriangles());
    kinds.assign(xyz.size() / 3, VertexKind::Boundary);
  }
};

bool allPresent(MeshEditor& ed, const BoundaryConstraints& bc)
{
  for (int32_t f = 0; f < bc.capacity(); ++f)
    if (bc.alive(f) && ed.findFace(bc.subface(f)[0], bc.subface(f)[1], bc.subface(f)[2]) < 0)
      return false;
  return true;
}

MeshCheckOptions structural()
{
  MeshCheckOptions o;
  o.delaunay = false;
  o.euler = false;
  return o;
}

} // namespace

TEST(BoundaryRecovery, CubeByFlipsOnly)
{
  SurfaceMesh s;
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  testshapes::addBox(s, lo, hi);
  RecoverySetup su(s);
  MeshEditor ed(su.mesh);
  RecoveryOptions ro;
  ro.allowSteiner = false;
  RecoveryReport rep;
  Status st = recoverBoundary(ed, su.bc, su.kinds, ro, nullptr, &rep);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_TRUE(allPresent(ed, su.bc));
  EXPECT_GT(rep.missingEdgesInitially, 0); // cospherical corners: the Delaunay picks other diagonals
  EXPECT_EQ(rep.steinerSegment + rep.steinerFacet, 0);
  MeshCheckReport mc = checkMesh(su.mesh, structural());
  EXPECT_TRUE(mc.valid) << mc.summary();
}

TEST(BoundaryRecovery, SchoenhardtNeedsSteiner)
{
  SurfaceMesh s = testshapes::schoenhardt(30);
  {
    RecoverySetup su(s);
    MeshEditor ed(su.mesh);
    RecoveryOptions ro;
    ro.allowSteiner = false;
    Status st = recoverBoundary(ed, su.bc, su.kinds, ro, nullptr, nullptr);
    EXPECT_EQ(st.kind, ErrorKind::RecoveryFailed);
    EXPECT_TRUE(checkMesh(su.mesh, structural()).valid);
  }
  RecoverySetup su(s);
  MeshEditor ed(su.mesh);
  RecoveryReport rep;
  Status st = recoverBoundary(ed, su.bc, su.kinds, RecoveryOptions(), nullptr, &rep);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_GT(rep.steinerSegment + rep.steinerFacet, 0);
  EXPECT_TRUE(allPresent(ed, su.bc));
  EXPECT_TRUE(checkMesh(su.mesh, structural()).valid);
}

TEST(BoundaryRecovery, Flip23And32AreInverse)
{
  // Two tets sharing face (0,1,2), apexes 3 (above) and 4 (below).
  TetMesh m;
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, 1 }, { 0.3, 0.3, -1 } };
  for (auto& q : p)
    m.addPoint(q);
  const int32_t a = m.newTet(0, 1, 2, 3), b = m.newTet(0, 2, 1, 4);
  ASSERT_GT(predicates::orient3d(p[0], p[1], p[2], p[3]), 0);
  m.link(a, 3, b, 3);
  MeshEditor ed(m);
  ASSERT_TRUE(ed.flip23(a, 3, nullptr));
  EXPECT_EQ(m.numTets(), 3);
  EXPECT_TRUE(checkMesh(m, structural()).valid);
  const int32_t t = ed.findEdge(3, 4);
  ASSERT_GE(t, 0);
  ASSERT_TRUE(ed.removeEdge(t, 3, 4, nullptr));
  EXPECT_EQ(m.numTets(), 2);
  EXPECT_GE(ed.findFace(0, 1, 2), 0);
  EXPECT_TRUE(checkMesh(m, structural()).valid);
}

TEST(BoundaryRecovery, FlipsNeverRemoveConstraints)
{
  TetMesh m;
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, 1 }, { 0.3, 0.3, -1 } };
  for (auto& q : p)
    m.addPoint(q);
  const int32_t a = m.newTet(0, 1, 2, 3), b = m.newTet(0, 2, 1, 4);
  m.link(a, 3, b, 3);
  MeshEditor ed(m);
  BoundaryConstraints bc;
  const int32_t tri[3] = { 0, 1, 2 };
  bc.init(tri, 1);
  EXPECT_FALSE(ed.flip23(a, 3, &bc));
  EXPECT_EQ(m.numTets(), 2);
}

TEST(BoundaryRecovery, SkinnyStripsRecovered)
{
  SurfaceMesh s = testshapes::stripBox(20, 1.0, 8.0, 0.25);
  RecoverySetup su(s);
  MeshEditor ed(su.mesh);
  RecoveryReport rep;
  Status st = recoverBoundary(ed, su.bc, su.kinds, RecoveryOptions(), nullptr, &rep);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_GT(rep.missingEdgesInitially, 0);
  EXPECT_TRUE(allPresent(ed, su.bc));
  EXPECT_TRUE(checkMesh(su.mesh, structural()).valid);
}
