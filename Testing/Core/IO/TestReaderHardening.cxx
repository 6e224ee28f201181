// Readers refuse what is not a surface file with a message in the user's terms: a directory, an OFF
// file without its header, PLY counts the file cannot hold, PLY numbers that are not whole tokens.
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <string>

namespace
{
using namespace volgrid;

std::string writeFile(const std::string& name, const std::string& content)
{
  const std::string path = ::testing::TempDir() + "volgrid_hardening_" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

std::string plyHeader(const char* vertices, const char* faces)
{
  return std::string("ply\nformat ascii 1.0\nelement vertex ") + vertices +
    "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
    "\nproperty list uchar int vertex_indices\nend_header\n";
}
} // namespace

TEST(ReaderHardening, DirectoryIsNamedAsSuch)
{
  for (const char* ext : { "stl", "off", "obj", "ply", "msh", "stl.gz" })
  {
    const std::string dir = ::testing::TempDir() + "volgrid_hardening_dir." + ext;
    ::mkdir(dir.c_str(), 0755);
    SurfaceMesh m;
    const Status s = readSurface(dir, m);
    ASSERT_FALSE(s.ok()) << ext;
    EXPECT_NE(s.message.find("directory"), std::string::npos) << s.message;
  }
}

TEST(ReaderHardening, OffWithoutHeaderIsRefused)
{
  SurfaceMesh m;
  const Status s = readSurface(writeFile("noheader.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("header 'OFF'"), std::string::npos) << s.message;
}

TEST(ReaderHardening, PlyCountsBeyondTheFileAreRefusedBeforeAllocating)
{
  SurfaceMesh m;
  const Status s = readSurface(writeFile("huge.ply", plyHeader("2000000000", "2000000000") + "0 0 0\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("claims 2000000000 entries"), std::string::npos) << s.message;
}

// An element without properties takes no bytes, so no file size bounds its count: a fuzzed header with
// 1.9e9 such faces kept the reader looping for minutes. Refused at once.
TEST(ReaderHardening, PlyElementsWithoutPropertiesAreRefused)
{
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1901144563\nend_header\n";
  SurfaceMesh m;
  const Status s = readSurface(writeFile("noproperties.ply", header + std::string(36, '\0')), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("element 'face' claims 1901144563 entries but has no properties"), std::string::npos)
    << s.message;
}

TEST(ReaderHardening, PlyNumbersMustBeWholeTokens)
{
  const std::string faces = "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n";
  SurfaceMesh m;
  Status s = readSurface(writeFile("x.ply", plyHeader("4", "4") + "0 0 0\n1x 0 0\n0 1 0\n0 0 1\n" + faces), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("'1x' is not a number"), std::string::npos) << s.message;
  s = readSurface(writeFile("nan.ply", plyHeader("4", "4") + "0 0 0\nnan 0 0\n0 1 0\n0 0 1\n" + faces), m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind, ErrorKind::NonFinitePoint);
  s = readSurface(
    writeFile("idx.ply", plyHeader("4", "4") + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2.5\n3 0 3 1\n3 1 3 2\n3 2 3 0\n"),
    m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("refers to vertex 2.5"), std::string::npos) << s.message;
}
