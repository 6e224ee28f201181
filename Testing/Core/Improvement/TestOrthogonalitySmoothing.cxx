// Orthogonality smoothing (OrthogonalitySmoothing.h) on the bundled wing's mesh, where the quality stage
// leaves thousands of severely non-orthogonal faces: it removes some, counts them as an independent
// recount does, keeps the mesh valid and its boundary exactly, and makes no tet worse than its floor.
#include "OrthogonalitySmoothing.h"
#include "TetEditor.h"
#include "WingInSphere.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace volgrid;

namespace
{
// checkMesh's count, written again here: interior faces whose normal makes more than 70 degrees with the
// line between the centroids of their two tets.
int64_t countSevereFaces(const TetMesh& m)
{
  auto centroid = [&](int32_t t, double c[3])
  {
    for (int k = 0; k < 3; ++k)
      c[k] = (m.point(m.vertex(t, 0))[k] + m.point(m.vertex(t, 1))[k] + m.point(m.vertex(t, 2))[k] +
              m.point(m.vertex(t, 3))[k]) /
        4;
  };
  int64_t n = 0;
  m.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = m.neighbor(t, i);
        if (u < t)
          continue; // no neighbour, or counted from u
        int32_t f[3];
        m.faceVertices(t, i, f);
        double a[3], b[3], nrm[3], d[3];
        for (int k = 0; k < 3; ++k)
        {
          a[k] = m.point(f[1])[k] - m.point(f[0])[k];
          b[k] = m.point(f[2])[k] - m.point(f[0])[k];
        }
        nrm[0] = a[1] * b[2] - a[2] * b[1];
        nrm[1] = a[2] * b[0] - a[0] * b[2];
        nrm[2] = a[0] * b[1] - a[1] * b[0];
        double ct[3], cu[3];
        centroid(t, ct);
        centroid(u, cu);
        for (int k = 0; k < 3; ++k)
          d[k] = cu[k] - ct[k];
        const double dot = std::abs(nrm[0] * d[0] + nrm[1] * d[1] + nrm[2] * d[2]);
        const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]) *
          std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        n += std::acos(std::min(1.0, dot / len)) > 70 * 3.14159265358979323846 / 180;
      }
    });
  return n;
}

std::vector<std::array<int32_t, 4>> tetList(const TetMesh& m)
{
  std::vector<std::array<int32_t, 4>> out;
  m.forEachTet([&](int32_t t) { out.push_back({ m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2), m.vertex(t, 3) }); });
  return out;
}

class OrthogonalitySmoothing : public WingSuite<OrthogonalitySmoothing>
{
};
} // namespace

TEST_F(OrthogonalitySmoothing, RemovesSevereFacesAndMakesNoTetWorseThanItsFloor)
{
  const std::vector<double> pointsBefore = mesh.points;
  const auto tetsBefore = tetList(mesh);
  std::vector<double> qualityBefore;
  for (const auto& q : tetsBefore)
    qualityBefore.push_back(tetSineQuality(mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]), mesh.point(q[3])));
  const int64_t severeBefore = countSevereFaces(mesh);

  OrthogonalitySmoothingReport report;
  ASSERT_TRUE(smoothNonOrthogonalFaces(mesh, nullptr, nullptr, OrthogonalitySmoothingOptions(), nullptr, &report).ok());
  std::printf("severe faces %lld -> %lld, %lld moves\n", static_cast<long long>(report.severeBefore),
              static_cast<long long>(report.severeAfter), static_cast<long long>(report.moves));

  // What it says is what a recount finds; it removed some (the wing's mesh has thousands).
  EXPECT_EQ(report.severeBefore, severeBefore);
  EXPECT_GT(severeBefore, 1000);
  EXPECT_EQ(report.severeAfter, countSevereFaces(mesh));
  EXPECT_LT(report.severeAfter, report.severeBefore);
  EXPECT_GT(report.moves, 0);

  // Valid (every tet positive, adjacency consistent; the hull checks are for a ball, this domain has two
  // boundary surfaces); the same tets; boundary vertices where they were; no tet below min(its quality
  // before, 10 deg).
  expectValidMesh(mesh);
  EXPECT_EQ(tetList(mesh), tetsBefore);
  for (size_t k = 0; k < 3 * static_cast<size_t>(numBoundary); ++k)
    ASSERT_EQ(mesh.points[k], pointsBefore[k]) << "boundary coordinate " << k;
  const double q10 = std::sin(10 * 3.14159265358979323846 / 180);
  for (size_t i = 0; i < tetsBefore.size(); ++i)
  {
    const auto& q = tetsBefore[i];
    const double after = tetSineQuality(mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]), mesh.point(q[3]));
    ASSERT_GE(after, std::min(qualityBefore[i], q10)) << "tet " << i;
  }
}

TEST_F(OrthogonalitySmoothing, LockedVerticesStay)
{
  const std::vector<double> pointsBefore = mesh.points;
  const std::vector<uint8_t> all(static_cast<size_t>(mesh.numVertices()), 1);
  OrthogonalitySmoothingReport report;
  ASSERT_TRUE(smoothNonOrthogonalFaces(mesh, nullptr, &all, OrthogonalitySmoothingOptions(), nullptr, &report).ok());
  EXPECT_EQ(report.moves, 0);
  EXPECT_EQ(report.severeAfter, report.severeBefore);
  EXPECT_EQ(mesh.points, pointsBefore);
}
