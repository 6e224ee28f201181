// Boundary recovery on its own: flips (2-3, 3-2, edge removal), Steiner fallback, constraints kept.
#include "../../Common/CorpusSkip.h"
#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "FacetPieces.h"
#include "FacetRecovery.h"
#include "MeshChecker.h"
#include "MesherTestShapes.h"
#include "PlanarFlip.h"
#include "Predicates.h"
#include "Quality.h"
#include "RecoveryTestSetup.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>

using namespace volgrid;

namespace
{

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

// The Delaunay cavity fill used when no single point sees a cavity: a closed cube (8 cospherical
// corners, so Simulation of Simplicity picks the diagonals) given by the 12 triangles of the
// tetrahedralization's own hull, and a face set the Delaunay tetrahedralization cannot contain.
TEST(BoundaryRecovery, DelaunayCavityFill)
{
  TetMesh m;
  for (int c = 0; c < 8; ++c)
  {
    const double p[3] = { double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1) };
    m.addPoint(p);
  }
  // Hull triangles of the cube as the Delaunay tetrahedralization splits them.
  TetMesh dt;
  std::vector<int32_t> map;
  DelaunayOptions o;
  o.keepGhosts = false;
  ASSERT_TRUE(buildDelaunay(m.points.data(), 8, o, dt, map).ok());
  std::vector<std::array<int32_t, 3>> faces;
  int32_t f[3];
  for (int32_t t = 0; t < dt.tetCapacity(); ++t)
    if (!dt.isFree(t))
      for (int i = 0; i < 4; ++i)
        if (dt.neighbor(t, i) < 0)
        {
          dt.faceVertices(t, i, f);
          faces.push_back({ { f[0], f[1], f[2] } });
        }
  ASSERT_EQ(faces.size(), 12u);
  std::vector<std::array<int32_t, 4>> tets;
  std::vector<std::array<int32_t, 3>> missing;
  ASSERT_TRUE(fillCavityDelaunay(m, faces, tets, &missing));
  EXPECT_TRUE(missing.empty());
  double vol = 0;
  for (auto& t : tets)
  {
    const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]), *d = m.point(t[3]);
    EXPECT_GT(predicates::orient3d(a, b, c, d), 0);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] },
                 w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
    vol +=
      (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) /
      6;
  }
  EXPECT_NEAR(vol, 1.0, 1e-12);
  // Flip the diagonal of one square: that cavity boundary is not in the Delaunay tetrahedralization.
  std::vector<std::array<int32_t, 3>> other;
  std::array<int32_t, 3> first{}, second{};
  int found = 0;
  for (auto& a : faces)
    for (auto& b : faces)
    {
      if (&a >= &b || found)
        continue;
      int shared = 0;
      for (int x : a)
        for (int y : b)
          shared += x == y;
      const bool coplanar = predicates::orient3d(m.point(a[0]), m.point(a[1]), m.point(a[2]), m.point(b[0])) == 0 &&
        predicates::orient3d(m.point(a[0]), m.point(a[1]), m.point(a[2]), m.point(b[1])) == 0 &&
        predicates::orient3d(m.point(a[0]), m.point(a[1]), m.point(a[2]), m.point(b[2])) == 0;
      if (shared == 2 && coplanar)
      {
        first = a;
        second = b;
        found = 1;
      }
    }
  ASSERT_TRUE(found);
  // The square's corners in cyclic order, then the other diagonal.
  int32_t apexB = -1;
  for (int y : second)
    if (y != first[0] && y != first[1] && y != first[2])
      apexB = y;
  int r = 0;
  while (std::find(second.begin(), second.end(), first[r]) != second.end())
    ++r; // first[r] is first's apex (not on the shared diagonal)
  const int32_t q0 = first[r], q1 = first[(r + 1) % 3], q3 = first[(r + 2) % 3];
  for (auto& a : faces)
    if (a != first && a != second)
      other.push_back(a);
  other.push_back({ { q0, q1, apexB } });
  other.push_back({ { q0, apexB, q3 } });
  EXPECT_FALSE(fillCavityDelaunay(m, other, tets, &missing));
  EXPECT_EQ(missing.size(), 2u);
}

// An input triangle ABC split by a segment Steiner point M that rounding put just off its plane: the
// pieces AMC and MBC are not coplanar, so the whole-triangle cavity does not apply, but each piece is a
// triangle of its own (recoverFacetByPieces / recoverSubfaceByCavity). AMC is crossed by edge PQ; MBC
// is already a face (the two bipyramids are joined along MC by tets PMCR and QMCS).
TEST(BoundaryRecovery, NonCoplanarPiecesRecovered)
{
  const double pts[8][3] = { { 0, 0, 0 },     { 2, 0, 0 },      { 1, 2, 0 },     { 1, 0, 1e-17 },
                             { 0.7, 0.5, 1 }, { 0.7, 0.5, -1 }, { 1.4, 0.6, 1 }, { 1.4, 0.6, -1 } };
  enum
  {
    A,
    B,
    C,
    M,
    P,
    Q,
    R,
    S
  };
  auto build = [&](TetMesh& m)
  {
    for (auto& p : pts)
      m.addPoint(p);
    std::vector<std::array<int32_t, 4>> tets = { { P, Q, A, M }, { P, Q, M, C }, { P, Q, C, A }, { M, B, C, R },
                                                 { M, B, C, S }, { P, M, C, R }, { Q, M, C, S } };
    for (auto& t : tets)
      if (predicates::orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
        std::swap(t[0], t[1]);
    MeshEditor ed(m);
    EXPECT_TRUE(ed.replace({}, tets, nullptr, true));
  };
  ASSERT_NE(predicates::orient3d(pts[A], pts[B], pts[C], pts[M]), 0);
  auto constraints = [](BoundaryConstraints& bc, std::vector<int32_t>& subs)
  {
    const int32_t tri[3] = { A, B, C };
    bc.init(tri, 1);
    bc.removeSubface(0);
    subs = { bc.addSubface(A, M, C, 0), bc.addSubface(M, B, C, 0) };
  };
  {
    TetMesh m;
    build(m);
    MeshEditor ed(m);
    BoundaryConstraints bc;
    std::vector<int32_t> subs;
    constraints(bc, subs);
    EXPECT_FALSE(recoverFacetByCavity(ed, bc, 0, subs)); // the plane of ABC does not split the cavity
  }
  TetMesh m;
  build(m);
  MeshEditor ed(m);
  BoundaryConstraints bc;
  std::vector<int32_t> subs;
  constraints(bc, subs);
  ASSERT_TRUE(recoverFacetByPieces(ed, bc, 0, subs));
  EXPECT_GE(ed.findFace(A, M, C), 0);
  EXPECT_GE(ed.findFace(M, B, C), 0);
  EXPECT_LT(ed.findEdge(P, Q), 0);
  EXPECT_TRUE(allPresent(ed, bc));
}

// Once input edge AB is split by a segment Steiner point M (rounded, so just off AB), no flip may
// create edge AB again: it would run alongside the pieces AM, MB and fold the boundary into flat tets
// that Steiner removal cannot undo. A 2-3 flip whose new edge is AB is refused; the constraints' pieces
// and other edges stay allowed.
TEST(BoundaryRecovery, NoEdgeAlongSplitSegment)
{
  // Face xyz with apexes A above and B below: the 2-3 flip of xyz creates edge AB.
  const double pts[7][3] = { { 0, 0, 1 },   { 0, 0, -1 },    { 1, 0, 0 }, { -1, 1, 0 },
                             { -1, -1, 0 }, { 0, 1e-17, 0 }, { 3, 3, 3 } };
  enum
  {
    A,
    B,
    X,
    Y,
    Z,
    M,
    W
  };
  auto run = [&](bool split)
  {
    TetMesh m;
    for (auto& p : pts)
      m.addPoint(p);
    std::vector<std::array<int32_t, 4>> tets = { { X, Y, Z, A }, { X, Z, Y, B } };
    for (auto& t : tets)
      if (predicates::orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
        std::swap(t[0], t[1]);
    MeshEditor ed(m);
    EXPECT_TRUE(ed.replace({}, tets, nullptr, true));
    BoundaryConstraints bc;
    const int32_t tri[3] = { A, B, W };
    bc.init(tri, 1);
    if (split)
    {
      bc.removeSubface(0);
      bc.addSubface(A, M, W, 0);
      bc.addSubface(M, B, W, 0);
      bc.addSegmentPoint(M, A, B);
      EXPECT_TRUE(bc.forbiddenEdge(A, B));
      EXPECT_FALSE(bc.forbiddenEdge(A, M)); // a piece of the segment
      EXPECT_FALSE(bc.forbiddenEdge(A, X));
    }
    int face = -1;
    const int32_t t = ed.findFace(X, Y, Z, &face);
    EXPECT_GE(t, 0);
    return ed.flip23(t, face, &bc);
  };
  EXPECT_TRUE(run(false)); // the flip itself is valid
  EXPECT_FALSE(run(true));
}

// Input triangle ABC split by a rounded segment Steiner point M (just above AB), pierced by edge PQ:
// the piece diagonal MC is not a mesh edge and no flip of the pieces makes it, and the whole-triangle
// cavity fails because M is off ABC's plane. The slab method counts M as on the triangle: each side of
// the cavity is re-tetrahedralized, the thin slab between their two triangulations is filled, and the
// pieces become mesh faces with the rest of the mesh valid.
TEST(BoundaryRecovery, NonPlanarSplitTriangleBySlab)
{
  const double pts[6][3] = {
    { 0, 0, 0 }, { 2, 0, 0 }, { 1, 2, 0 }, { 1, 0, 1e-17 }, { 1, 0.6, 0.1 }, { 1, 0.6, -0.1 }
  };
  enum
  {
    A,
    B,
    C,
    M,
    P,
    Q
  };
  SurfaceMesh s;
  for (auto& p : pts)
    s.points.insert(s.points.end(), p, p + 3);
  auto setup = [&](RecoverySetup& r, std::vector<int32_t>& subs)
  {
    const int32_t tri[3] = { A, B, C };
    r.bc.init(tri, 1);
    r.bc.removeSubface(0);
    subs = { r.bc.addSubface(A, M, C, 0), r.bc.addSubface(M, B, C, 0) };
    r.bc.addSegmentPoint(M, A, B);
  };
  ASSERT_GT(predicates::orient3d(pts[A], pts[B], pts[C], pts[M]), 0);
  {
    RecoverySetup r(s);
    MeshEditor ed(r.mesh);
    std::vector<int32_t> subs;
    setup(r, subs);
    ASSERT_GE(ed.findEdge(P, Q), 0);
    ASSERT_LT(ed.findEdge(M, C), 0);
    ASSERT_GE(ed.findEdge(A, M), 0);
    ASSERT_GE(ed.findEdge(M, B), 0);
    EXPECT_FALSE(recoverFacetByCavity(ed, r.bc, 0, subs));
    EXPECT_FALSE(recoverFacetByPieces(ed, r.bc, 0, subs));
  }
  RecoverySetup r(s);
  MeshEditor ed(r.mesh);
  std::vector<int32_t> subs;
  setup(r, subs);
  ASSERT_TRUE(recoverFacetBySlab(ed, r.bc, 0, subs));
  EXPECT_TRUE(allPresent(ed, r.bc));
  EXPECT_LT(ed.findEdge(P, Q), 0);
  EXPECT_TRUE(checkMesh(r.mesh, structural()).valid);
}

// The presplit stage (RecoveryOptions::presplitSegments) on a box whose sides are fans of long thin
// strips (segments missing from the Delaunay tetrahedralization): with every input segment listed, their
// pieces are all mesh edges before the first flip, and the rest of recovery then only has facets to do.
// A needle-thin CAD part (part.off) needs more points than the stage allows: it says so instead.
TEST(BoundaryRecovery, PresplitSegmentsArePresentBeforeAnyFlip)
{
  auto allSegments = [](const SurfaceMesh& s)
  {
    std::unordered_set<uint64_t> all;
    for (int32_t t = 0; t < s.numberOfTriangles(); ++t)
      for (int i = 0; i < 3; ++i)
        all.insert(edgeKey(s.triangle(t)[i], s.triangle(t)[(i + 1) % 3]));
    return all;
  };
  SurfaceMesh s = testshapes::stripBox(20, 1.0, 8.0, 0.25);
  const std::unordered_set<uint64_t> all = allSegments(s);
  {
    RecoverySetup su(s);
    MeshEditor ed(su.mesh);
    RecoveryReport rep;
    recoverBoundary(ed, su.bc, su.kinds, RecoveryOptions(), nullptr, &rep);
    EXPECT_GT(rep.missingEdgesInitially, 0); // without the presplit stage
  }
  RecoverySetup su(s);
  MeshEditor ed(su.mesh);
  RecoveryOptions ro;
  ro.presplitSegments = &all;
  RecoveryReport rep;
  Status st = recoverBoundary(ed, su.bc, su.kinds, ro, nullptr, &rep);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_GT(rep.presplitPoints, 0);
  EXPECT_EQ(rep.missingEdgesInitially, 0);
  EXPECT_FALSE(rep.splitSegments.empty());
  EXPECT_TRUE(allPresent(ed, su.bc));
  EXPECT_TRUE(checkMesh(su.mesh, structural()).valid);

  VOLGRID_SKIP_WITHOUT_CORPUS_FILE("/tetgen-tests/cgal/part.off");
  SurfaceMesh part;
  ASSERT_TRUE(readSurface(volgrid_testing::corpusPath("/tetgen-tests/cgal/part.off"), part).ok());
  const std::unordered_set<uint64_t> partSegments = allSegments(part);
  RecoverySetup sp(part);
  MeshEditor ep(sp.mesh);
  ro.presplitSegments = &partSegments;
  st = recoverBoundary(ep, sp.bc, sp.kinds, ro, nullptr, &rep);
  EXPECT_EQ(st.kind, ErrorKind::RecoveryFailed);
  EXPECT_NE(st.message.find("did not make them edges"), std::string::npos) << st.message;
  EXPECT_LE(rep.presplitPoints, part.numberOfTriangles());
}

// flipInPlane: edge xy in the plane z = 0 with ring p, u1, [u2] (above), q, w (below), p and q in the
// plane. Replacing xy by pq keeps the region (same volume, valid adjacency); when the quad x-p-y-q is not
// convex the flip is refused and the mesh left as it was (the two floor triangles would overlap).
TEST(BoundaryRecovery, PlanarFlipReplacesTheDiagonalOfAFlatQuad)
{
  auto run = [](double px, bool twoAbove)
  {
    const double pts[7][3] = { { -1, 0, 0 },     { 1, 0, 0 },      { px, -1, 0 }, { px, 1, 0 },
                               { 0.3, -0.5, 1 }, { -0.3, 0.5, 1 }, { 0, 0, -1 } };
    enum
    {
      X,
      Y,
      P,
      Q,
      U1,
      U2,
      W
    };
    TetMesh m;
    for (auto& p : pts)
      m.addPoint(p);
    const std::vector<int32_t> ring =
      twoAbove ? std::vector<int32_t>{ P, U1, U2, Q, W } : std::vector<int32_t>{ P, U1, Q, W };
    const size_t n = ring.size();
    std::vector<std::array<int32_t, 4>> tets;
    for (size_t i = 0; i < n; ++i)
    {
      std::array<int32_t, 4> t = { { X, Y, ring[i], ring[(i + 1) % n] } };
      if (predicates::orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
        std::swap(t[0], t[1]);
      tets.push_back(t);
    }
    MeshEditor ed(m);
    EXPECT_TRUE(ed.replace({}, tets, nullptr, true));
    auto volume = [&]()
    {
      double v = 0;
      m.forEachTet(
        [&](int32_t t)
        {
          v += quality::tetVolume(m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2)),
                                  m.point(m.vertex(t, 3)));
        });
      return v;
    };
    const double v0 = volume();
    const int32_t t0 = m.numTets();
    std::vector<VertexKind> kinds(7, VertexKind::Boundary);
    const bool flipped = flipInPlane(ed, ed.findEdge(X, Y), X, Y, P, Q, nullptr, nullptr, &kinds);
    EXPECT_TRUE(checkMesh(m, structural()).valid);
    EXPECT_NEAR(volume(), v0, 1e-12);
    if (flipped)
    {
      EXPECT_LT(ed.findEdge(X, Y), 0);
      EXPECT_GE(ed.findEdge(P, Q), 0);
    }
    else
    {
      EXPECT_GE(ed.findEdge(X, Y), 0);
      EXPECT_EQ(m.numTets(), t0);
    }
    return flipped;
  };
  EXPECT_TRUE(run(0.0, true));
  EXPECT_TRUE(run(0.0, false));
  EXPECT_FALSE(run(-2.0, true));
  EXPECT_FALSE(run(-2.0, false)); // each side's cone alone would be valid here
}

// Flat faces made of needle fans (testshapes::fanBox): their missing segments cross only edges lying in
// the face's own plane, many of them, and each flip may leave the crossing count unchanged. Sloan's 2D
// flips (recoverEdgeInPlane) recover all of them without a Steiner point on the boundary.
TEST(BoundaryRecovery, FlatNeedleFansRecoveredByPlanarFlips)
{
  for (int n : { 12, 40, 100, 200 })
  {
    SurfaceMesh s = testshapes::fanBox(n, 10.0, 1.0, 1.0);
    RecoverySetup su(s);
    MeshEditor ed(su.mesh);
    RecoveryReport rep;
    const Status st = recoverBoundary(ed, su.bc, su.kinds, RecoveryOptions(), nullptr, &rep);
    ASSERT_TRUE(st.ok()) << "n = " << n << ": " << st.message;
    EXPECT_GT(rep.missingEdgesInitially, n / 2) << "n = " << n;
    EXPECT_EQ(rep.steinerSegment + rep.steinerFacet, 0) << "n = " << n;
    EXPECT_TRUE(allPresent(ed, su.bc)) << "n = " << n;
    EXPECT_TRUE(checkMesh(su.mesh, structural()).valid) << "n = " << n;
  }
}
