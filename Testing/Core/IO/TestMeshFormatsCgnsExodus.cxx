// Core's CGNS and Exodus II writers and readers: names, labels and counts survive a round trip, the
// second write equals the first, and bad files and paths get a clear error instead of a crash.
#include "MeshReader.h"
#include "MeshWriter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

namespace
{
using namespace volgrid;

// Two positive tets sharing the face (1 2 3); the six outer faces in two named patches, outward.
SolverMesh twoTets()
{
  SolverMesh m;
  m.points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 };
  m.tets = { 0, 1, 2, 3, 1, 2, 3, 4 };
  m.tetRegion = { 1, 2 };
  m.regionNames = { { 1, "fluid" }, { 2, "solid" } };
  m.triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 4, 3, 2, 3, 4, 1, 2, 4 };
  m.trianglePatch = { 1, 1, 1, 2, 2, 2 };
  m.patchNames = { { 1, "wall" }, { 2, "farfield" } };
  return m;
}

std::string temp(const std::string& name)
{
  return ::testing::TempDir() + "volgrid_formats_" + name;
}

std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void expectSameLabelsAndNames(const SolverMesh& a, const SolverMesh& b)
{
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.tetRegion, b.tetRegion);
  EXPECT_EQ(a.regionNames, b.regionNames);
  EXPECT_EQ(a.trianglePatch, b.trianglePatch);
  EXPECT_EQ(a.patchNames, b.patchNames);
  EXPECT_EQ(a.triangles.size(), b.triangles.size());
}
} // namespace

TEST(MeshFormatsCgnsExodus, CgnsRoundTripKeepsEverything)
{
  const SolverMesh mesh = twoTets();
  const std::string path = temp("two.cgns");
  ASSERT_TRUE(writeSolverMesh(path, mesh, meshFormatFromPath(path)).ok());
  SolverMesh back;
  const Status s = readSolverMesh(path, back);
  ASSERT_TRUE(s.ok()) << s.message;
  expectSameLabelsAndNames(mesh, back);
  EXPECT_EQ(back.triangles, mesh.triangles); // CGNS keeps each triangle's vertex order
}

TEST(MeshFormatsCgnsExodus, ExodusRoundTripKeepsLabelsNamesAndBytes)
{
  const SolverMesh mesh = twoTets();
  const std::string path = temp("two.exo"), again = temp("again.exo");
  ASSERT_TRUE(writeSolverMesh(path, mesh, meshFormatFromPath(path)).ok());
  SolverMesh back;
  const Status s = readSolverMesh(path, back);
  ASSERT_TRUE(s.ok()) << s.message;
  expectSameLabelsAndNames(mesh, back);
  ASSERT_TRUE(writeSolverMesh(again, back, MeshFormat::Exodus).ok());
  EXPECT_EQ(contents(path), contents(again));
}

TEST(MeshFormatsCgnsExodus, ExodusRefusesATriangleThatIsNoTetFace)
{
  SolverMesh mesh = twoTets();
  mesh.triangles[0] = 4; // (4 3 0): no tet has both 0 and 4
  mesh.triangles[1] = 3;
  mesh.triangles[2] = 0;
  const std::string path = temp("orphan.exo");
  const Status s = writeSolverMesh(path, mesh, MeshFormat::Exodus);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("not a face of any tet"), std::string::npos) << s.message;
  EXPECT_TRUE(contents(path).empty());
}

TEST(MeshFormatsCgnsExodus, GarbageFilesGetAClearError)
{
  for (const char* name : { "garbage.cgns", "garbage.exo" })
  {
    const std::string path = temp(name);
    std::ofstream(path, std::ios::binary) << "this is not a mesh\n";
    SolverMesh mesh;
    const Status s = readSolverMesh(path, mesh);
    EXPECT_FALSE(s.ok()) << name;
    EXPECT_NE(s.message.find(path), std::string::npos) << s.message;
    EXPECT_EQ(mesh.numberOfTets(), 0);
  }
}

TEST(MeshFormatsCgnsExodus, UnwritablePathLeavesNoFile)
{
  for (const char* name : { "missing-dir/out.cgns", "missing-dir/out.exo" })
  {
    const std::string path = temp(name);
    const Status s = writeSolverMesh(path, twoTets(), meshFormatFromPath(path));
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message.find("missing-dir"), std::string::npos) << s.message;
    EXPECT_TRUE(contents(path).empty());
  }
}

TEST(MeshFormatsCgnsExodus, CgnsRefusesANameLongerThan32Characters)
{
  SolverMesh mesh = twoTets();
  mesh.patchNames[2] = "a_far_field_name_that_is_longer_than_32";
  const std::string path = temp("long.cgns");
  const Status s = writeSolverMesh(path, mesh, MeshFormat::CGNS);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("longer than CGNS's 32 characters"), std::string::npos) << s.message;
  EXPECT_TRUE(contents(path).empty());
}
