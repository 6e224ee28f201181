// Gzip-compressed surfaces (Core/GzipFile): name.ext.gz is read by the .ext reader, corrupt and
// truncated data give clear errors, and the corpus's falcon1.stl.gz reads exactly as falcon1.stl.
#include "GzipFile.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <iterator>
#include <string>

namespace
{
using namespace volgrid;

std::string tempPath(const std::string& name)
{
  return ::testing::TempDir() + "volgrid_gzip_" + name;
}

// Compressed with zlib's own gzip writer (independent of the reader under test).
std::string writeGz(const std::string& name, const std::string& content)
{
  const std::string path = tempPath(name);
  gzFile f = gzopen(path.c_str(), "wb9");
  EXPECT_NE(f, nullptr);
  EXPECT_EQ(gzwrite(f, content.data(), static_cast<unsigned>(content.size())), static_cast<int>(content.size()));
  EXPECT_EQ(gzclose(f), Z_OK);
  return path;
}

std::string readBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string writeBytes(const std::string& name, const std::string& bytes)
{
  const std::string path = tempPath(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

void expectSameMesh(const SurfaceMesh& a, const SurfaceMesh& b)
{
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.patchIds, b.patchIds);
}

const char* kTetOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* kTetStl =
  "solid tet\n"
  "facet normal 0 0 -1\n outer loop\n vertex 0 0 0\n vertex 0 1 0\n vertex 1 0 0\n endloop\nendfacet\n"
  "facet normal 0 -1 0\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 0 1\n endloop\nendfacet\n"
  "facet normal -1 0 0\n outer loop\n vertex 0 0 0\n vertex 0 0 1\n vertex 0 1 0\n endloop\nendfacet\n"
  "facet normal 1 1 1\n outer loop\n vertex 1 0 0\n vertex 0 1 0\n vertex 0 0 1\n endloop\nendfacet\n"
  "endsolid tet\n";
} // namespace

TEST(GzipReading, SuffixHandling)
{
  EXPECT_TRUE(isGzipPath("a/wing.stl.gz"));
  EXPECT_TRUE(isGzipPath("WING.STL.GZ"));
  EXPECT_FALSE(isGzipPath("wing.stl"));
  EXPECT_FALSE(isGzipPath("gz"));
  EXPECT_EQ(stripGzipSuffix("dir/wing.stl.gz"), "dir/wing.stl");
  EXPECT_EQ(stripGzipSuffix("dir/wing.stl"), "dir/wing.stl");
  EXPECT_TRUE(surfaceReaderSupports("wing.STL.gz"));
  EXPECT_TRUE(surfaceReaderSupports("part.off.gz"));
  EXPECT_FALSE(surfaceReaderSupports("notes.txt.gz"));
}

TEST(GzipReading, RoundTripOffAndStl)
{
  for (const auto& [name, text] : { std::pair<std::string, std::string>("tet.off", kTetOff), { "tet.stl", kTetStl } })
  {
    SurfaceMesh plain, packed;
    SurfaceReadInfo plainInfo, packedInfo;
    const Status p = readSurface(writeBytes(name, text), plain, &plainInfo);
    ASSERT_TRUE(p.ok()) << p.message;
    const Status g = readSurface(writeGz(name + ".gz", text), packed, &packedInfo);
    ASSERT_TRUE(g.ok()) << g.message;
    EXPECT_EQ(packed.numberOfTriangles(), 4) << name;
    EXPECT_EQ(packedInfo.format, plainInfo.format);
    expectSameMesh(plain, packed);
  }
}

TEST(GzipReading, ConcatenatedMembersAreJoined)
{
  // `cat a.gz b.gz > c.gz` is valid gzip (gunzip outputs both parts): split the OFF file in two members.
  const std::string text = kTetOff;
  const std::string half = text.substr(0, text.size() / 2), rest = text.substr(text.size() / 2);
  const std::string joined = readBytes(writeGz("h1.gz", half)) + readBytes(writeGz("h2.gz", rest));
  SurfaceMesh m;
  const Status s = readSurface(writeBytes("joined.off.gz", joined), m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 4);
}

TEST(GzipReading, TruncatedCorruptAndNonGzipDataAreErrors)
{
  const std::string gz = readBytes(writeGz("whole.stl.gz", kTetStl));
  ASSERT_GT(gz.size(), 40u);
  SurfaceMesh m;

  const std::string truncatedPath = writeBytes("truncated.stl.gz", gz.substr(0, gz.size() / 2));
  Status s = readSurface(truncatedPath, m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("truncated"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find(truncatedPath), std::string::npos) << s.message;

  // Only the 8-byte trailer (CRC-32 and length) missing: still truncated, not silently accepted.
  s = readSurface(writeBytes("notrailer.stl.gz", gz.substr(0, gz.size() - 8)), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("truncated"), std::string::npos) << s.message;

  // A flipped bit in the CRC-32 of the trailer.
  std::string badCrc = gz;
  badCrc[gz.size() - 8] = static_cast<char>(badCrc[gz.size() - 8] ^ 0x01);
  s = readSurface(writeBytes("badcrc.stl.gz", badCrc), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("corrupt"), std::string::npos) << s.message;

  s = readSurface(writeBytes("plain.stl.gz", kTetStl), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("not gzip"), std::string::npos) << s.message;

  s = readSurface(writeBytes("empty.stl.gz", ""), m);
  ASSERT_FALSE(s.ok());

  s = readSurface(writeBytes("garbage.stl.gz", gz + "garbage"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("after the end"), std::string::npos) << s.message;
}

TEST(GzipReading, CorpusFalconGzEqualsItsDecompressedTwin)
{
  // SOURCES.md: falcon1.stl is the decompressed falcon1.stl.gz (identical content).
  const std::string dir = std::string(VOLGRID_SHARED_DATA_DIR) + "/aero-gmsh/";
  if (!std::ifstream(dir + "falcon1.stl.gz") || !std::ifstream(dir + "falcon1.stl"))
  {
    GTEST_SKIP() << "shared corpus not available";
  }
  std::string unpacked;
  ASSERT_TRUE(readGzipFile(dir + "falcon1.stl.gz", unpacked).ok());
  EXPECT_EQ(unpacked, readBytes(dir + "falcon1.stl"));

  SurfaceMesh plain, packed;
  ASSERT_TRUE(readSurface(dir + "falcon1.stl", plain).ok());
  const Status s = readSurface(dir + "falcon1.stl.gz", packed);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(packed.numberOfTriangles(), 200);
  expectSameMesh(plain, packed);
}
