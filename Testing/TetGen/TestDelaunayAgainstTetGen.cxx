// VolGrid's Delaunay kernel against TetGen on inputs in general position, where the Delaunay
// tetrahedralization is unique: the tet counts must agree exactly.
#include "TetGenRunner.h"

#include "Delaunay.h"
#include "MeshChecker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
std::vector<double> uniformPoints(size_t n, uint64_t seed)
{
  std::mt19937_64 generator(seed);
  std::vector<double> xyz(3 * n);
  for (double& c : xyz)
    c = static_cast<double>(generator() >> 11) * 0x1.0p-53;
  return xyz;
}

// Points on two concentric spheres, radius 1 and 10: the far-field situation.
std::vector<double> sphericalShells(size_t n, uint64_t seed)
{
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  std::vector<double> xyz;
  for (size_t i = 0; i < n; ++i)
  {
    double p[3] = { normal(generator), normal(generator), normal(generator) };
    const double scale = (i % 2 ? 10.0 : 1.0) / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double c : p)
      xyz.push_back(c * scale);
  }
  return xyz;
}

void expectSameAsTetGen(const std::vector<double>& xyz)
{
  volgrid::TetMesh mesh;
  std::vector<int32_t> inputToVertex;
  const volgrid::Status status =
    volgrid::buildDelaunay(xyz.data(), xyz.size() / 3, volgrid::DelaunayOptions(), mesh, inputToVertex);
  ASSERT_TRUE(status.ok()) << status.message;
  const volgrid::MeshCheckReport check = volgrid::checkMesh(mesh);
  EXPECT_TRUE(check.valid) << check.summary();
  const volgrid_tetgen::TetGenResult tetgen = volgrid_tetgen::delaunay(xyz);
  ASSERT_TRUE(tetgen.ok) << tetgen.error;
  EXPECT_EQ(mesh.numFiniteTets(), tetgen.tets);
}
} // namespace

TEST(DelaunayVsTetGen, UniformRandom10k)
{
  expectSameAsTetGen(uniformPoints(10000, 1));
}
TEST(DelaunayVsTetGen, UniformRandom100k)
{
  expectSameAsTetGen(uniformPoints(100000, 2));
}
TEST(DelaunayVsTetGen, ConcentricSpheres20k)
{
  expectSameAsTetGen(sphericalShells(20000, 3));
}
TEST(DelaunayVsTetGen, Offset1e9Random10k)
{
  std::vector<double> xyz = uniformPoints(10000, 4);
  for (double& c : xyz)
    c += 1e9;
  expectSameAsTetGen(xyz);
}
