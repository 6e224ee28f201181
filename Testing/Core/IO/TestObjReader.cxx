// The Core OBJ reader: strict numbers, named bad references, polygons and negative references.
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace
{
using namespace volgrid;

std::string writeObj(const std::string& name, const std::string& content)
{
  const std::string path = ::testing::TempDir() + "volgrid_obj_" + name + ".obj";
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

const char* kTet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
} // namespace

TEST(ObjReader, TetrahedronWithTextureAndNormalReferences)
{
  SurfaceMesh m;
  const Status s = readSurface(
    writeObj("tet",
             std::string("# c\no tet\n") + kTet + "vt 0 0\nvn 0 0 1\nf 1/1 3/1/1 2//1\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"),
    m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfPoints(), 4);
  EXPECT_EQ(m.numberOfTriangles(), 4);
}

TEST(ObjReader, NegativeReferencesAndQuads)
{
  SurfaceMesh m;
  SurfaceReadInfo info;
  const Status s = readSurface(writeObj("quad", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n"), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 2);
  EXPECT_EQ(info.polygonFaces, 1);
}

TEST(ObjReader, RefusesNonNumbersWithTheLine)
{
  for (const char* bad : { "nan", "inf", "abc", "1x", "-infinity" })
  {
    SurfaceMesh m;
    const std::string path = writeObj(std::string("bad_") + (bad[0] == '-' ? "minf" : bad),
                                      std::string("v 0 0 0\nv ") + bad + " 0 0\nv 0 1 0\nf 1 2 3\n");
    const Status s = readSurface(path, m);
    ASSERT_FALSE(s.ok()) << bad;
    EXPECT_NE(s.message.find(path + ":2:"), std::string::npos) << s.message;
    EXPECT_NE(s.message.find(bad), std::string::npos) << s.message;
  }
}

TEST(ObjReader, OutOfRangeReferencesAreCountedAndTheFirstNamed)
{
  SurfaceMesh m;
  const Status s = readSurface(writeObj("range", std::string(kTet) + "f 1 2 3\nf 1 2 9\nf 1 -7 3\nf 2 3 4\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("2 face reference(s)"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("face 2 (line 6) refers to vertex 9"), std::string::npos) << s.message;
  EXPECT_EQ(s.message.find("open"), std::string::npos) << s.message;
}

TEST(ObjReader, ZeroAndGarbageReferencesAreErrors)
{
  SurfaceMesh m;
  EXPECT_FALSE(readSurface(writeObj("zero", std::string(kTet) + "f 0 1 2\n"), m).ok());
  EXPECT_FALSE(readSurface(writeObj("garbage", std::string(kTet) + "f 1 x 2\n"), m).ok());
  EXPECT_FALSE(readSurface(writeObj("two", std::string(kTet) + "f 1 2\n"), m).ok());
  EXPECT_FALSE(readSurface(writeObj("empty", ""), m).ok());
}

// `o` objects name patches like `g` groups: the latest of the two names the faces that follow.
TEST(ObjReader, ObjectsAndGroupsAreNamedPatches)
{
  SurfaceMesh m;
  const Status s = readSurface(
    writeObj("objects", std::string(kTet) + "o Wing\nf 1 3 2\nf 1 2 4\no Tip\nf 1 4 3\ng Tip_cap\nf 2 3 4\n"), m);
  ASSERT_TRUE(s.ok()) << s.message;
  ASSERT_EQ(m.patchIds.size(), 4u);
  std::vector<std::string> names;
  for (int32_t id : m.patchIds)
    names.push_back(m.patchNames.at(id));
  EXPECT_EQ(names, (std::vector<std::string>{ "Wing", "Wing", "Tip", "Tip_cap" }));
}
