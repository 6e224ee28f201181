// Readers of Core/SurfaceReader: each format on a small hand-written file, polygon facets, and clear
// errors (file and line) on malformed input.
#include "SurfaceChecks.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace
{
using namespace volgrid;

std::string writeFile(const std::string& name, const std::string& content)
{
  const std::string path = ::testing::TempDir() + "volgrid_surface_" + name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path;
}

double triangleArea(const SurfaceMesh& m, int32_t t, double n[3])
{
  const double* a = m.point(m.triangle(t)[0]);
  const double* b = m.point(m.triangle(t)[1]);
  const double* c = m.point(m.triangle(t)[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

const char* kTetOff = "OFF\n# a tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
} // namespace

TEST(SurfaceReader, OffTetrahedron)
{
  SurfaceMesh m;
  SurfaceReadInfo info;
  ASSERT_TRUE(readSurface(writeFile("tet.off", kTetOff), m, &info).ok());
  EXPECT_EQ(m.numberOfPoints(), 4);
  EXPECT_EQ(m.numberOfTriangles(), 4);
  EXPECT_NEAR(signedVolume(m), 1.0 / 6.0, 1e-15);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_TRUE(r.meshable());
}

TEST(SurfaceReader, OffNonConvexPolygonIsEarClipped)
{
  // An L-shaped hexagon in the plane z = 1 (non-convex: a fan from vertex 0 would leave the polygon).
  const std::string off = "OFF\n6 1 0\n"
                          "2 2 1\n0 2 1\n0 0 1\n1 0 1\n1 1 1\n2 1 1\n"
                          "6 0 1 2 3 4 5\n";
  SurfaceMesh m;
  SurfaceReadInfo info;
  ASSERT_TRUE(readSurface(writeFile("L.off", off), m, &info).ok());
  EXPECT_EQ(info.polygonFaces, 1);
  EXPECT_EQ(info.fanFallbacks, 0);
  ASSERT_EQ(m.numberOfTriangles(), 4);
  double total = 0;
  for (int32_t t = 0; t < 4; ++t)
  {
    double n[3];
    total += triangleArea(m, t, n);
    EXPECT_GT(n[2], 0.0) << "triangle " << t << " lost the polygon's orientation";
  }
  EXPECT_NEAR(total, 3.0, 1e-12);
  const SurfaceCheckReport r = checkSurface(m);
  EXPECT_EQ(r.selfIntersectingPairs, 0);
  EXPECT_EQ(r.degenerateTriangles, 0);
}

TEST(SurfaceReader, OffVariantsAndCountsOnNextLine)
{
  const std::string coff = "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
                           "0 0 1 9 9 9 255\n3 0 2 1 1 1 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  SurfaceMesh m;
  ASSERT_TRUE(readSurface(writeFile("c.off", coff), m).ok());
  EXPECT_EQ(m.numberOfTriangles(), 4);
  const std::string split =
    "OFF\n\n# counts on their own line\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  ASSERT_TRUE(readSurface(writeFile("split.off", split), m).ok());
  EXPECT_EQ(m.numberOfTriangles(), 4);
}

TEST(SurfaceReader, OffErrorsNameFileAndLine)
{
  SurfaceMesh m;
  const std::string badId = writeFile("badid.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  Status s = readSurface(badId, m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find(badId + ":6:"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("out of range"), std::string::npos) << s.message;

  s = readSurface(writeFile("short.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("end of file"), std::string::npos) << s.message;

  s = readSurface(writeFile("text.off", "OFF\n3 1 0\n0 0 zero\n1 0 0\n0 1 0\n3 0 1 2\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find(":3:"), std::string::npos) << s.message;

  s = readSurface(writeFile("nan.off", "OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind, ErrorKind::NonFinitePoint);

  s = readSurface(::testing::TempDir() + "does_not_exist.off", m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("cannot open"), std::string::npos);

  s = readSurface(writeFile("x.xyz", "1 2 3"), m);
  EXPECT_FALSE(s.ok());
}

TEST(SurfaceReader, GarbageNeverCrashes)
{
  std::string garbage;
  uint32_t x = 12345;
  for (int i = 0; i < 4000; ++i)
  {
    x = x * 1103515245u + 12345u;
    garbage.push_back(static_cast<char>(x >> 24));
  }
  for (const char* ext : { "off", "mesh", "poly", "smesh", "msh", "stl" })
  {
    SurfaceMesh m;
    const Status s = readSurface(writeFile(std::string("garbage.") + ext, garbage), m);
    EXPECT_FALSE(s.ok()) << ext;
    // Truncations of valid files fail cleanly too.
    const Status e = readSurface(writeFile(std::string("empty.") + ext, ""), m);
    EXPECT_FALSE(e.ok()) << ext;
  }
  const std::string full = kTetOff;
  for (size_t cut = 0; cut + 2 < full.size(); cut += 3)
  {
    SurfaceMesh m;
    const Status s = readSurface(writeFile("cut.off", full.substr(0, cut)), m);
    EXPECT_FALSE(s.ok()) << cut;
  }
}

TEST(SurfaceReader, StlAsciiSeveralSolidsAndTrailingText)
{
  std::string stl;
  auto facet = [&](const char* a, const char* b, const char* c)
  {
    stl += std::string("  facet normal 0 0 0\n    outer loop\n      vertex ") + a + "\n      vertex " + b +
      "\n      vertex " + c + "\n    endloop\n  endfacet\n";
  };
  stl += "solid first\n";
  facet("0 0 0", "0 1 0", "1 0 0");
  facet("0 0 0", "1 0 0", "0 0 1");
  stl += "endsolid first\nsolid second\n";
  facet("0 0 0", "0 0 1", "0 1 0");
  facet("1 0 0", "0 1 0", "0 0 1");
  stl += "endsolid second\nSurface Loop(2) = {1};\nVolume(3) = {2};\n"; // gmsh appends its .geo text
  SurfaceMesh m;
  SurfaceReadInfo info;
  const Status s = readSurface(writeFile("two.stl", stl), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(info.solids, 2);
  EXPECT_EQ(m.numberOfPoints(), 4); // exactly coincident vertices merged
  EXPECT_EQ(info.mergedPoints, 8);
  ASSERT_EQ(m.patchIds.size(), 4u);
  EXPECT_EQ(m.patchIds[0], 0);
  EXPECT_EQ(m.patchIds[3], 1);
  EXPECT_FALSE(info.warnings.empty());
  EXPECT_TRUE(checkSurface(m).meshable());

  const Status bad = readSurface(writeFile("bad.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0\n"), m);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message.find(":4:"), std::string::npos) << bad.message;
}

TEST(SurfaceReader, StlBinary)
{
  const float v[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const int tris[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  std::string data(80, ' ');
  data.replace(0, 5, "solid"); // binary files that start with "solid" exist
  const uint32_t n = 4;
  data.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris)
  {
    float rec[12] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      std::memcpy(rec + 3 + 3 * k, v[t[k]], sizeof(v[0]));
    }
    data.append(reinterpret_cast<const char*>(rec), 48);
    data.append(2, '\0');
  }
  SurfaceMesh m;
  SurfaceReadInfo info;
  ASSERT_TRUE(readSurface(writeFile("tet.stl", data), m, &info).ok());
  EXPECT_EQ(info.format, "STL binary");
  EXPECT_EQ(m.numberOfPoints(), 4);
  EXPECT_NEAR(signedVolume(m), 1.0 / 6.0, 1e-7);
  // Truncated binary: a clear size message.
  const Status s = readSurface(writeFile("trunc.stl", data.substr(0, data.size() - 10)), m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("bytes"), std::string::npos) << s.message;
}

TEST(SurfaceReader, MeditTrianglesQuadsAndSkippedTets)
{
  const std::string mesh = "MeshVersionFormatted 2\nDimension\n3\n# comment\nVertices\n5\n"
                           "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n0.5 0.5 1 2\n"
                           "Quadrilaterals\n1\n1 4 3 2 7\n"
                           "Triangles\n4\n1 2 5 3\n2 3 5 3\n3 4 5 3\n4 1 5 3\n"
                           "Tetrahedra\n1\n1 2 3 5 0\nEnd\n";
  SurfaceMesh m;
  SurfaceReadInfo info;
  const Status s = readSurface(writeFile("pyr.mesh", mesh), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 6);
  EXPECT_EQ(info.skippedElements, 1);
  ASSERT_TRUE(m.hasPatchIds());
  EXPECT_EQ(m.patchIds[0], 7);
  EXPECT_EQ(m.patchIds[5], 3);
  EXPECT_NEAR(signedVolume(m), 1.0 / 3.0, 1e-12);
  EXPECT_TRUE(checkSurface(m).meshable());
  const Status bad =
    readSurface(writeFile("bad.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\nBogus 3\n"), m);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message.find("Bogus"), std::string::npos);
  EXPECT_NE(bad.message.find(":6:"), std::string::npos) << bad.message;
}

TEST(SurfaceReader, TetGenSmeshAndPoly)
{
  // A unit cube with quad facets, 1-based node numbering, boundary markers.
  const std::string nodes = "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n";
  const std::string smesh = "# cube\n" + nodes +
    "6 1\n4 1 4 3 2 10\n4 5 6 7 8 11\n4 1 2 6 5 12\n4 2 3 7 6 13\n4 3 4 8 7 14\n4 4 1 5 8 15\n0\n0\n";
  SurfaceMesh m;
  SurfaceReadInfo info;
  Status s = readSurface(writeFile("cube.smesh", smesh), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 12);
  EXPECT_EQ(info.polygonFaces, 6);
  EXPECT_EQ(m.patchIds[0], 10);
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-12);
  EXPECT_TRUE(checkSurface(m).meshable());

  const std::string poly = nodes +
    "6 1\n1 0 10\n4 1 4 3 2\n1 0 11\n4 5 6 7 8\n1 0 12\n4 1 2 6 5\n"
    "1 0 13\n4 2 3 7 6\n1 0 14\n4 3 4 8 7\n1\n4 4 1 5 8\n0\n0\n";
  s = readSurface(writeFile("cube.poly", poly), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 12);
  EXPECT_NEAR(signedVolume(m), 1.0, 1e-12);

  // Nodes in a sibling .node file when the node list is empty.
  writeFile("sib.node", nodes);
  s = readSurface(writeFile("sib.smesh", "0 3 0 0\n" + smesh.substr(smesh.find("6 1\n"))), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 12);

  const Status bad = readSurface(writeFile("bad.smesh", nodes + "1 0\n3 1 2 99\n"), m);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message.find(":11:"), std::string::npos) << bad.message;

  // Found by fuzz.reader_poly: a node numbered INT64_MAX made the index range overflow (UBSan).
  const Status huge = readSurface(writeFile("huge.poly", "1\n9223372036854775807 1 2 3\n1 0\n1\n3 1 1 1\n0\n0\n"), m);
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.message.find("numbered 9223372036854775807"), std::string::npos) << huge.message;
  EXPECT_NE(huge.message.find(":2:"), std::string::npos) << huge.message;
}

TEST(SurfaceReader, GmshV2AndV4)
{
  const std::string v2 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n10 0 0 0\n20 1 0 0\n30 0 1 0\n40 0 0 1\n$EndNodes\n"
    "$Elements\n6\n1 15 2 0 1 10\n2 1 2 0 1 10 20\n3 2 2 5 1 10 30 20\n4 2 2 5 1 10 20 40\n"
    "5 2 2 0 2 10 40 30\n6 2 2 0 3 20 30 40\n$EndElements\n";
  SurfaceMesh m;
  SurfaceReadInfo info;
  Status s = readSurface(writeFile("tet2.msh", v2), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 4);
  EXPECT_EQ(info.skippedElements, 2);
  EXPECT_EQ(m.patchIds[0], 5); // physical tag
  EXPECT_EQ(m.patchIds[2], 2); // elementary tag when no physical group
  EXPECT_NEAR(signedVolume(m), 1.0 / 6.0, 1e-15);

  const std::string v4 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1 0 0 0 1 1 1 0 0\n$EndEntities\n"
    "$Nodes\n2 4 1 4\n0 1 0 1\n1\n0 0 0\n2 1 0 3\n2\n3\n4\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
    "$Elements\n2 5 1 5\n0 1 15 1\n1 1\n2 1 2 4\n2 1 3 2\n3 1 2 4\n4 1 4 3\n5 2 3 4\n$EndElements\n";
  s = readSurface(writeFile("tet4.msh", v4), m, &info);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(m.numberOfTriangles(), 4);
  EXPECT_EQ(info.format, "gmsh 4.1");
  EXPECT_NEAR(signedVolume(m), 1.0 / 6.0, 1e-15);
  EXPECT_TRUE(checkSurface(m).meshable());

  const Status bin = readSurface(writeFile("bin.msh", "$MeshFormat\n4.1 1 8\n"), m);
  ASSERT_FALSE(bin.ok());
  EXPECT_NE(bin.message.find("binary"), std::string::npos);
  const Status unknownNode =
    readSurface(writeFile("un.msh",
                          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
                          "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n"),
                m);
  ASSERT_FALSE(unknownNode.ok());
  EXPECT_NE(unknownNode.message.find("unknown node"), std::string::npos) << unknownNode.message;
}

TEST(SurfaceReader, MergeKeepsFirstOccurrenceOrder)
{
  SurfaceMesh m;
  m.addPoint(0, 0, 0);
  m.addPoint(1, 0, 0);
  m.addPoint(-0.0, 0, 0); // equal to point 0
  m.addPoint(0, 1, 0);
  m.addPoint(1, 0, 0); // equal to point 1
  m.addTriangle(2, 4, 3);
  const MergeResult r = mergeCoincidentPoints(m);
  EXPECT_EQ(r.mergedPoints, 2);
  EXPECT_EQ(m.numberOfPoints(), 3);
  EXPECT_EQ(r.oldToNew, (std::vector<int32_t>{ 0, 1, 0, 2, 1 }));
  EXPECT_EQ(std::vector<int32_t>(m.triangles.begin(), m.triangles.end()), (std::vector<int32_t>{ 0, 1, 2 }));
}
