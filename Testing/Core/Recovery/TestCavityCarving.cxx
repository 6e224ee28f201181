// Tetrahedralization of a cavity without new points by bounded search (Core/Recovery/CavityCarving.h).
#include "BoundaryRecovery.h"
#include "CavityCarving.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace volgrid;

namespace
{

// Unit cube: 8 points, 12 boundary triangles seen positively from inside.
void cube(TetMesh& m, std::vector<std::array<int32_t, 3>>& faces)
{
  for (int i = 0; i < 8; ++i)
  {
    const double p[3] = { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) };
    m.addPoint(p);
  }
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                            { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  faces.clear();
  for (auto& q : quads)
  {
    faces.push_back({ { q[0], q[1], q[2] } });
    faces.push_back({ { q[0], q[2], q[3] } });
  }
  // Orient each face so that the cube's centre is on its positive side.
  const double c[3] = { 0.5, 0.5, 0.5 };
  for (auto& f : faces)
    if (predicates::orient3d(m.point(f[0]), m.point(f[1]), m.point(f[2]), c) < 0)
      std::swap(f[1], f[2]);
}

double volume(const TetMesh& m, const std::array<int32_t, 4>& t)
{
  const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]), *d = m.point(t[3]);
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = d[k] - a[k];
  }
  return std::fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                   u[2] * (v[0] * w[1] - v[1] * w[0])) /
    6.0;
}

} // namespace

TEST(CavityCarving, CubeFilledExactly)
{
  TetMesh m;
  std::vector<std::array<int32_t, 3>> faces;
  cube(m, faces);
  std::vector<std::array<int32_t, 4>> tets;
  ASSERT_TRUE(carveCavity(
    m, faces, [](int32_t, int32_t) { return true; }, 1000, tets));
  double vol = 0;
  std::map<TriKey, int> count;
  for (auto& t : tets)
  {
    EXPECT_GT(predicates::orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])), 0);
    vol += volume(m, t);
    const int fv[4][3] = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } };
    for (auto& f : fv)
      ++count[TriKey(t[f[0]], t[f[1]], t[f[2]])];
  }
  EXPECT_NEAR(vol, 1.0, 1e-12);
  // Cube faces once, inner faces twice.
  for (auto& f : faces)
    EXPECT_EQ(count[TriKey(f[0], f[1], f[2])], 1);
  int once = 0;
  for (auto& [k, n] : count)
  {
    EXPECT_LE(n, 2);
    once += n == 1;
  }
  EXPECT_EQ(once, 12);
}

TEST(CavityCarving, InsideOutOrNoBudgetFails)
{
  TetMesh m;
  std::vector<std::array<int32_t, 3>> faces;
  cube(m, faces);
  std::vector<std::array<int32_t, 4>> tets;
  // No step allowed: no fill.
  EXPECT_FALSE(carveCavity(
    m, faces, [](int32_t, int32_t) { return true; }, 0, tets));
  for (auto& f : faces)
    std::swap(f[1], f[2]); // the outside of the cube: not a bounded cavity
  EXPECT_FALSE(carveCavity(
    m, faces, [](int32_t, int32_t) { return true; }, 1000, tets));
}
