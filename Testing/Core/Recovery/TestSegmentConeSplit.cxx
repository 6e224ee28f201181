// Segment cones (Core/Recovery/SegmentConeSplit.h): a missing segment split by points on it whose pieces are
// edges at once, and the mesher's last-resort retry that uses them (gmsh-benchmarks/prt2.stl).
#include "BoundaryRecovery.h"
#include "Delaunay.h"
#include "MeshChecker.h"
#include "MesherTestCorpusModel.h"
#include "Quality.h"
#include "SegmentConeSplit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace volgrid;

namespace
{

double meshVolume(const TetMesh& m)
{
  double v = 0;
  m.forEachTet(
    [&](int32_t t)
    {
      v += quality::tetVolume(m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2)),
                              m.point(m.vertex(t, 3)));
    });
  return v;
}

// Distance from P to the line AB, relative to |AB|.
double offLine(const double* A, const double* B, const double* P)
{
  double d[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    d[k] = B[k] - A[k];
    w[k] = P[k] - A[k];
  }
  const double c[3] = { d[1] * w[2] - d[2] * w[1], d[2] * w[0] - d[0] * w[2], d[0] * w[1] - d[1] * w[0] };
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / dd;
}

} // namespace

// Long segments through a random Delaunay mesh: each is made an edge chain (its pieces between the new
// points) by cone steps alone, the mesh stays valid with the same volume, and the points lie on it.
TEST(SegmentConeSplit, PiecesAreEdgesAndTheMeshStaysValid)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < 3000; ++i)
    for (int k = 0; k < 3; ++k)
      xyz.push_back(u(rng));
  TetMesh m;
  DelaunayOptions o;
  o.keepGhosts = false;
  std::vector<int32_t> map;
  ASSERT_TRUE(buildDelaunay(xyz.data(), xyz.size() / 3, o, m, map).ok());
  MeshEditor ed(m);
  BoundaryConstraints bc;
  bc.init(nullptr, 0);
  const double v0 = meshVolume(m);
  MeshCheckOptions co;
  co.delaunay = false;
  co.euler = false;

  int recovered = 0, withPoints = 0, points = 0;
  for (int s = 0; s < 40; ++s)
  {
    // Far apart interior points: tens of tets between them.
    const int32_t a = 2 * s, b = 2999 - 2 * s;
    const double A[3] = { m.point(a)[0], m.point(a)[1], m.point(a)[2] };
    const double B[3] = { m.point(b)[0], m.point(b)[1], m.point(b)[2] };
    if (std::hypot(A[0] - B[0], A[1] - B[1], A[2] - B[2]) < 0.5 || ed.findEdge(a, b) >= 0)
      continue;
    std::vector<int32_t> added;
    auto onLine = [&](int32_t w)
    { return w == a || w == b || std::find(added.begin(), added.end(), w) != added.end(); };
    int32_t from = a;
    ConeStep step = ConeStep::Advanced;
    for (int n = 0; n < 200 && step == ConeStep::Advanced; ++n)
    {
      int32_t v = -1;
      step = coneStepAlongSegment(ed, bc, from, b, onLine, &v);
      if (step == ConeStep::Advanced)
      {
        EXPECT_GE(ed.findEdge(from, v), 0) << "segment " << s;
        EXPECT_LT(offLine(A, B, m.point(v)), 1e-12) << "segment " << s;
        added.push_back(v);
        from = v;
      }
    }
    ASSERT_NE(step, ConeStep::Failed) << "segment " << s << " after " << added.size() << " points";
    EXPECT_GE(ed.findEdge(from, b), 0) << "segment " << s;
    // Every piece is still there after the later steps.
    int32_t p = a;
    for (int32_t v : added)
    {
      EXPECT_GE(ed.findEdge(p, v), 0) << "segment " << s;
      p = v;
    }
    ++recovered;
    withPoints += !added.empty();
    points += static_cast<int>(added.size());
  }
  EXPECT_GE(recovered, 20);
  EXPECT_GT(withPoints, 0); // the stepping path was exercised, not only single cones
  EXPECT_TRUE(checkMesh(m, co).valid);
  EXPECT_NEAR(meshVolume(m), v0, 1e-12 * v0);
  std::printf("segment cones: %d segments recovered, %d needed points, %d points\n", recovered, withPoints, points);
}

// prt2.stl (gmsh benchmarks): a slanted prism whose curved faces are strips of needle triangles 75 units
// long and a fraction of a unit wide. Flips leave about 260 of its segments; midpoint splits do not make
// their pieces recoverable (the missing edges grow, before and after the presplit retry), segment cones
// do. The mesh then has the input boundary exactly.
TEST(SegmentConeSplit, NeedleStripsOfPrt2MeshedByTheConeRetry)
{
  MesherResult r;
  if (!testshapes::meshCorpusModelAndCheck("gmsh-benchmarks/prt2.stl", r))
    GTEST_SKIP() << "corpus file gmsh-benchmarks/prt2.stl not found";
  EXPECT_EQ(r.stats.recoveryAttempts, 3);
}
