// Named patches and the solver writers: --patch parsing and relabelling, OpenFOAM words, label
// normalisation, the all-or-nothing output file, the OpenFOAM face order and orientation, the Medit
// round trip with names, STL solid names and gmsh $PhysicalNames.
#include "MeshReader.h"
#include "MeshWriter.h"
#include "OutputFile.h"
#include "PatchNames.h"
#include "SolverMesh.h"
#include "SurfaceReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

using namespace volgrid;

namespace
{
// Per process: two builds' tests running at once (ASan beside Release) must not share files.
std::string tempPath(const std::string& name)
{
  return ::testing::TempDir() + "volgrid_solver_" + std::to_string(getpid()) + "_" + name;
}

std::string readText(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Two positive tets sharing the face (1 2 3): patch 1 on the three faces of tet 0 other than the shared
// one, patch 2 on those of tet 1.
SolverMesh twoTets()
{
  SolverMesh m;
  m.points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1 };
  m.tets = { 0, 1, 2, 3, 1, 2, 3, 4 };
  m.tetRegion = { 1, 1 };
  m.triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 4, 2, 1, 3, 4, 2, 4, 3 };
  m.trianglePatch = { 1, 1, 1, 2, 2, 2 };
  m.patchNames = { { 1, "wall_a" }, { 2, "farfield" } };
  return m;
}

// A boundary-layer prism (base 0 1 2 at z = 0, its normal towards the top 3 4 5 at z = 1) under a tet
// (3 4 5 6): the wall under the prism, its three sides on a symmetry patch, the tet's other faces far field.
SolverMesh prismUnderTet()
{
  SolverMesh m;
  m.points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 0.3, 0.3, 2 };
  m.prisms = { 0, 1, 2, 3, 4, 5 };
  m.prismRegion = { 1 };
  m.tets = { 3, 4, 5, 6 };
  m.tetRegion = { 1 };
  m.triangles = { 0, 2, 1, 3, 4, 6, 4, 5, 6, 5, 3, 6 };
  m.trianglePatch = { 1, 3, 3, 3 };
  m.quads = { 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5 };
  m.quadPatch = { 2, 2, 2 };
  m.patchNames = { { 1, "wall" }, { 2, "symmetry" }, { 3, "farfield" } };
  return m;
}

// A pyramid (unit square base turning towards the apex 4) and a tet on its side (0 1 4); the base is a
// boundary quad.
SolverMesh pyramidBesideTet()
{
  SolverMesh m;
  m.points = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1, 0.5, -1, 0.5 };
  m.pyramids = { 0, 1, 2, 3, 4 };
  m.pyramidRegion = { 1 };
  m.tets = { 0, 1, 4, 5 };
  m.tetRegion = { 1 };
  m.triangles = { 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 5, 1, 1, 5, 4, 4, 5, 0 };
  m.trianglePatch = { 2, 2, 2, 2, 2, 2 };
  m.quads = { 0, 3, 2, 1 };
  m.quadPatch = { 1 };
  m.patchNames = { { 1, "wall" }, { 2, "farfield" } };
  return m;
}

// The text a writer gives `mesh` as file `name` ("" when it fails).
std::string writtenText(const std::string& name, const SolverMesh& mesh, MeshFormat format)
{
  const std::string path = tempPath(name);
  std::filesystem::remove(path);
  const Status s = writeSolverMesh(path, mesh, format);
  EXPECT_TRUE(s.ok()) << s.message;
  return s.ok() ? readText(path) : "";
}

// A fresh OpenFOAM case of `mesh` named `name`; its directory.
std::string writtenFoamCase(const std::string& name, const SolverMesh& mesh)
{
  const std::string dir = tempPath(name);
  std::filesystem::remove_all(dir);
  const Status s = writeSolverMesh(dir, mesh, MeshFormat::OpenFOAM);
  EXPECT_TRUE(s.ok()) << s.message;
  return dir;
}

// A refusal whose message holds `fragment`.
void expectRefused(const Status& s, const std::string& fragment)
{
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find(fragment), std::string::npos) << s.message;
}
} // namespace

TEST(PatchNames, ParsesGroupsAndBareIds)
{
  PatchAssignment a;
  ASSERT_TRUE(parsePatchAssignment("farfield=1,symmetry=2,wing=3,4,5", a).ok());
  ASSERT_EQ(a.names, (std::vector<std::string>{ "farfield", "symmetry", "wing" }));
  EXPECT_EQ(a.ids[2], (std::vector<int32_t>{ 3, 4, 5 }));
  ASSERT_TRUE(parsePatchAssignment("inlet=7", a).ok()); // appends
  EXPECT_EQ(a.names.size(), 4u);
  PatchAssignment b;
  EXPECT_FALSE(parsePatchAssignment("1,2", b).ok());
  EXPECT_FALSE(parsePatchAssignment("=1", b).ok());
  EXPECT_FALSE(parsePatchAssignment("wing=x", b).ok());
  EXPECT_FALSE(parsePatchAssignment("wing=1,", b).ok());
}

TEST(PatchNames, RelabelsInOrderAndKeepsTheOthers)
{
  PatchAssignment a;
  ASSERT_TRUE(parsePatchAssignment("wing=3,4,farfield=1", a).ok());
  std::vector<int32_t> labels = { 1, 3, 4, 7, 3 };
  NameTable names = { { 7, "outlet" } };
  ASSERT_TRUE(applyPatchAssignment(a, labels, names).ok());
  EXPECT_EQ(labels, (std::vector<int32_t>{ 2, 1, 1, 3, 1 }));
  EXPECT_EQ(names, (NameTable{ { 1, "wing" }, { 2, "farfield" }, { 3, "outlet" } }));
  PatchAssignment twice, missing;
  ASSERT_TRUE(parsePatchAssignment("a=1,b=1", twice).ok());
  ASSERT_TRUE(parsePatchAssignment("a=9", missing).ok());
  std::vector<int32_t> before = labels;
  EXPECT_FALSE(applyPatchAssignment(twice, labels, names).ok());
  EXPECT_FALSE(applyPatchAssignment(missing, labels, names).ok());
  EXPECT_EQ(labels, before);
}

TEST(PatchNames, OpenFoamWordsAndPatchTypes)
{
  EXPECT_TRUE(isOpenFoamWord("wing_upper-1"));
  for (const char* bad : { "", "bad name", "a;b", "a/b", "a{b", "a(b", "a\"b", "a#b", "a$b" })
    EXPECT_FALSE(isOpenFoamWord(bad)) << bad;
  EXPECT_EQ(defaultOpenFoamPatchType("Symmetry_y0"), "symmetryPlane");
  EXPECT_EQ(defaultOpenFoamPatchType("farfield"), "patch");
  EXPECT_EQ(defaultOpenFoamPatchType("outlet2"), "patch");
  EXPECT_EQ(defaultOpenFoamPatchType("wing"), "wall");
}

TEST(SolverMesh, NormalizeLabelsIsDenseAndNamed)
{
  SolverMesh m = twoTets();
  m.trianglePatch = { 0, 0, 5, 5, 9, 9 };
  m.patchNames = { { 5, "wing" } };
  m.tetRegion = { 0, 0 };
  normalizeLabels(m);
  EXPECT_EQ(m.trianglePatch, (std::vector<int32_t>{ 1, 1, 2, 2, 3, 3 }));
  EXPECT_EQ(m.patchNames, (NameTable{ { 1, "patch0" }, { 2, "wing" }, { 3, "patch9" } }));
  EXPECT_EQ(m.regionNames, (NameTable{ { 1, "region0" } }));
}

TEST(OutputFile, NoPartialFile)
{
  const std::string path = tempPath("partial.txt");
  std::filesystem::remove(path);
  {
    OutputFile f;
    ASSERT_TRUE(f.open(path).ok());
    std::fputs("half", f.stream());
  } // abandoned: nothing appears
  EXPECT_FALSE(std::filesystem::exists(path));
  OutputFile g;
  ASSERT_TRUE(g.open(path).ok());
  std::fputs("whole", g.stream());
  ASSERT_TRUE(g.commit().ok());
  EXPECT_EQ(readText(path), "whole");
  OutputFile h;
  const Status s = h.open(tempPath("no-such-dir/x.msh"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message.find("no-such-dir/x.msh"), std::string::npos);
  EXPECT_NE(s.message.find("No such file"), std::string::npos);
}

TEST(MeshWriterOpenFOAM, UpperTriangularOrderOutwardFacesPatchesByName)
{
  const std::string dir = tempPath("foam");
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(writeSolverMesh(dir, twoTets(), MeshFormat::OpenFOAM).ok());
  const std::string owner = readText(dir + "/constant/polyMesh/owner");
  EXPECT_NE(owner.find("nPoints:5  nCells:2  nFaces:7  nInternalFaces:1"), std::string::npos);
  EXPECT_NE(owner.find("7\n(\n0\n0\n0\n0\n1\n1\n1\n)"), std::string::npos) << owner;
  EXPECT_NE(readText(dir + "/constant/polyMesh/neighbour").find("1\n(\n1\n)"), std::string::npos);
  // The internal face (1 2 3) points from tet 0 to tet 1, i.e. towards point 4 = (1 1 1).
  const std::string faces = readText(dir + "/constant/polyMesh/faces");
  EXPECT_NE(faces.find("7\n(\n3(1 2 3)\n"), std::string::npos) << faces;
  const std::string boundary = readText(dir + "/constant/polyMesh/boundary");
  EXPECT_NE(boundary.find("wall_a\n    {\n        type            wall;"), std::string::npos) << boundary;
  EXPECT_NE(boundary.find("farfield\n    {\n        type            patch;"), std::string::npos);
  EXPECT_NE(boundary.find("nFaces          3;\n        startFace       4;"), std::string::npos);
  // Read back: the same tets (from the faces) and the patches by name, in the boundary file's order.
  SolverMesh r;
  ASSERT_TRUE(readSolverMesh(dir, r).ok());
  EXPECT_EQ(r.numberOfTets(), 2);
  EXPECT_EQ(r.points, twoTets().points);
  EXPECT_EQ(r.patchNames, (NameTable{ { 1, "wall_a" }, { 2, "farfield" } }));
  EXPECT_EQ(r.trianglePatch, (std::vector<int32_t>{ 1, 1, 1, 2, 2, 2 }));
  const std::string again = tempPath("foam-again");
  std::filesystem::remove_all(again);
  ASSERT_TRUE(writeSolverMesh(again, r, MeshFormat::OpenFOAM).ok());
  for (const char* f : { "points", "faces", "owner", "neighbour", "boundary" })
    EXPECT_EQ(readText(dir + "/constant/polyMesh/" + f), readText(again + "/constant/polyMesh/" + f)) << f;
  // An existing directory is refused; a bad word is refused before anything is written.
  EXPECT_FALSE(writeSolverMesh(dir, twoTets(), MeshFormat::OpenFOAM).ok());
  SolverMesh bad = twoTets();
  bad.patchNames[1] = "a b";
  const std::string dir2 = tempPath("foam-bad");
  std::filesystem::remove_all(dir2);
  EXPECT_FALSE(writeSolverMesh(dir2, bad, MeshFormat::OpenFOAM).ok());
  EXPECT_FALSE(std::filesystem::exists(dir2));
}

TEST(MeshWriterOpenFOAM, PrismsAreCellsWithQuadSidesInTheirPatch)
{
  const std::string dir = writtenFoamCase("foam-prism", prismUnderTet());
  const std::string owner = readText(dir + "/constant/polyMesh/owner");
  // The prism is cell 0, the tet cell 1; the shared top (3 4 5) is the internal face, out of the prism.
  EXPECT_NE(owner.find("nPoints:7  nCells:2  nFaces:8  nInternalFaces:1"), std::string::npos) << owner;
  EXPECT_NE(owner.find("8\n(\n0\n0\n0\n0\n0\n1\n1\n1\n)"), std::string::npos) << owner;
  EXPECT_NE(readText(dir + "/constant/polyMesh/neighbour").find("1\n(\n1\n)"), std::string::npos);
  const std::string faces = readText(dir + "/constant/polyMesh/faces");
  EXPECT_NE(faces.find("8\n(\n3(3 4 5)\n3(0 2 1)\n4(0 1 4 3)\n4(0 3 5 2)\n4(1 2 5 4)\n"), std::string::npos) << faces;
  const std::string boundary = readText(dir + "/constant/polyMesh/boundary");
  EXPECT_NE(boundary.find("symmetry\n    {\n        type            symmetryPlane;\n        inGroups        "
                          "List<word> 1(symmetryPlane);\n        nFaces          3;\n        startFace       2;"),
            std::string::npos)
    << boundary;
  // A side quad in no patch is a mesh that disagrees with its patches: refused, nothing written.
  SolverMesh open = prismUnderTet();
  open.quads.resize(8);
  open.quadPatch.resize(2);
  const std::string dir2 = tempPath("foam-prism-open");
  std::filesystem::remove_all(dir2);
  const Status s = writeSolverMesh(dir2, open, MeshFormat::OpenFOAM);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("boundary face (0 2 3 5) of cell 0 is in no patch"), std::string::npos) << s.message;
  EXPECT_FALSE(std::filesystem::exists(dir2));
}

// The faces are matched by their point ids: a third tet on the face (1 2 3) makes a mesh no solver can
// take, so it is refused, naming the face and its cells, before anything is written; so is a face twice in a cell.
TEST(MeshWriterOpenFOAM, AFaceOfThreeCellsOrTwiceInACellIsRefused)
{
  SolverMesh three = twoTets();
  three.points.insert(three.points.end(), { 2, 2, 2 });
  three.tets.insert(three.tets.end(), { 3, 2, 1, 5 });
  three.tetRegion.push_back(1);
  const std::string dir = tempPath("foam-three");
  std::filesystem::remove_all(dir);
  const Status s = writeSolverMesh(dir, three, MeshFormat::OpenFOAM);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("face (1 2 3) is shared by more than two cells (0, 1, 2)"), std::string::npos) << s.message;
  EXPECT_FALSE(std::filesystem::exists(dir));
  // A tet with a repeated point has a face twice: refused too, not written as a face between a cell and itself.
  SolverMesh flat = twoTets();
  flat.tets[3] = flat.tets[2]; // (0 1 2 2)
  const Status f = writeSolverMesh(dir, flat, MeshFormat::OpenFOAM);
  EXPECT_FALSE(f.ok());
  EXPECT_NE(f.message.find("cell 0 has the face (0 1 2) twice"), std::string::npos) << f.message;
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(MeshWriterSU2, PrismsInVtkOrderAndSideQuadsInTheirMarker)
{
  const std::string text = writtenText("prism.su2", prismUnderTet(), MeshFormat::SU2);
  EXPECT_NE(text.find("NELEM= 2\n10 3 4 5 6 0\n13 0 2 1 3 5 4 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("MARKER_TAG= symmetry\nMARKER_ELEMS= 3\n9 0 1 4 3\n9 1 2 5 4\n9 2 0 3 5\n"), std::string::npos)
    << text;
  // TetGen has no prisms: refused by name, nothing written.
  const std::string out = tempPath("prism-refused.x");
  expectRefused(writeSolverMesh(out, prismUnderTet(), MeshFormat::TetGen), "prisms are not written to TetGen");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(MeshWriterMedit, PrismsAndSideQuadsInTheirSections)
{
  const std::string text = writtenText("prism.mesh", prismUnderTet(), MeshFormat::Medit);
  EXPECT_NE(text.find("Quadrilaterals\n3\n1 2 5 4 2\n2 3 6 5 2\n3 1 4 6 2\nTetrahedra\n1\n4 5 6 7 1\n"
                      "Prisms\n1\n1 2 3 4 5 6 1\nEnd\n"),
            std::string::npos)
    << text;
  EXPECT_NE(text.find("# VolGrid patch 2 symmetry\n"), std::string::npos) << text;
}

// Medit, gmsh and SU2 files with layers read back into the mesh that was written: prisms, pyramids, the
// side quads and their labels (SU2 has no regions: every cell comes back in region 1).
TEST(MeshReaders, PrismsPyramidsAndQuadsReadBack)
{
  const std::pair<MeshFormat, const char*> formats[] = { { MeshFormat::Medit, "mesh" },
                                                         { MeshFormat::Gmsh22, "msh" },
                                                         { MeshFormat::Gmsh41, "msh" },
                                                         { MeshFormat::SU2, "su2" } };
  for (const SolverMesh& mesh : { prismUnderTet(), pyramidBesideTet() })
    for (const auto& [format, ext] : formats)
    {
      const std::string path = tempPath(std::string("layers-back.") + ext);
      std::filesystem::remove(path);
      ASSERT_TRUE(writeSolverMesh(path, mesh, format).ok());
      SolverMesh back;
      const Status s = readSolverMesh(path, back);
      ASSERT_TRUE(s.ok()) << ext << ": " << s.message;
      const bool su2 = format == MeshFormat::SU2;
      EXPECT_EQ(back.points, mesh.points) << ext;
      EXPECT_EQ(back.tets, mesh.tets) << ext;
      EXPECT_EQ(back.prisms, mesh.prisms) << ext;
      EXPECT_EQ(back.pyramids, mesh.pyramids) << ext;
      EXPECT_EQ(back.quads, mesh.quads) << ext;
      EXPECT_EQ(back.triangles, mesh.triangles) << ext;
      EXPECT_EQ(back.prismRegion, su2 ? std::vector<int32_t>(mesh.prismRegion.size(), 1) : mesh.prismRegion) << ext;
      EXPECT_EQ(back.pyramidRegion, su2 ? std::vector<int32_t>(mesh.pyramidRegion.size(), 1) : mesh.pyramidRegion)
        << ext;
      if (!su2) // SU2 numbers its markers in file order
      {
        EXPECT_EQ(back.quadPatch, mesh.quadPatch) << ext;
        EXPECT_EQ(back.trianglePatch, mesh.trianglePatch) << ext;
      }
      EXPECT_EQ(back.quadPatch.size(), mesh.quadPatch.size()) << ext;
    }
}

// Quads are faces of prisms and pyramids only: a tet mesh's file with quads reads as the tet mesh.
TEST(MeshReaders, QuadsWithoutLayerCellsAreDropped)
{
  SolverMesh m = twoTets();
  m.quads = { 0, 1, 2, 3 };
  m.quadPatch = { 1 };
  const std::string path = tempPath("tets-with-quads.mesh");
  std::filesystem::remove(path);
  ASSERT_TRUE(writeSolverMesh(path, m, MeshFormat::Medit).ok());
  SolverMesh back;
  ASSERT_TRUE(readSolverMesh(path, back).ok());
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_TRUE(back.quads.empty() && back.quadPatch.empty());
}

TEST(MeshWriters, PyramidsInEveryFormatWithPrisms)
{
  const std::string dir = writtenFoamCase("foam-pyramid", pyramidBesideTet());
  // The pyramid is cell 0, the tet cell 1; their face (0 1 4) is internal, out of the pyramid; the base
  // is written out of it too.
  const std::string owner = readText(dir + "/constant/polyMesh/owner");
  EXPECT_NE(owner.find("nPoints:6  nCells:2  nFaces:8  nInternalFaces:1"), std::string::npos) << owner;
  const std::string faces = readText(dir + "/constant/polyMesh/faces");
  EXPECT_NE(faces.find("8\n(\n3(0 1 4)\n"), std::string::npos) << faces;
  EXPECT_NE(faces.find("\n4(0 3 2 1)\n"), std::string::npos) << faces;
  const std::string su2 = writtenText("pyramid.su2", pyramidBesideTet(), MeshFormat::SU2);
  EXPECT_NE(su2.find("NELEM= 2\n10 0 1 4 5 0\n14 0 1 2 3 4 1\n"), std::string::npos) << su2;
  const std::string medit = writtenText("pyramid.mesh", pyramidBesideTet(), MeshFormat::Medit);
  EXPECT_NE(medit.find("Quadrilaterals\n1\n1 4 3 2 1\nTetrahedra\n1\n1 2 5 6 1\nPyramids\n1\n1 2 3 4 5 1\n"),
            std::string::npos)
    << medit;
  // CGNS (a PYRA_5 section) and Exodus II (a PYRAMID block, the base its side 5) take them, and VolGrid's
  // readers read them back (TestLayeredReaders.cxx has more); TetGen refuses them with a message,
  // nothing written.
  for (MeshFormat f : { MeshFormat::CGNS, MeshFormat::Exodus })
  {
    const std::string path = tempPath(std::string("pyramid.") + (f == MeshFormat::CGNS ? "cgns" : "exo"));
    std::filesystem::remove(path);
    ASSERT_TRUE(writeSolverMesh(path, pyramidBesideTet(), f).ok());
    SolverMesh back;
    const Status s = readSolverMesh(path, back);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(back.pyramids, pyramidBesideTet().pyramids);
    EXPECT_EQ(back.tets, pyramidBesideTet().tets);
    EXPECT_EQ(back.quads, pyramidBesideTet().quads);
    EXPECT_EQ(back.quadPatch, pyramidBesideTet().quadPatch);
  }
  const std::string node = tempPath("pyramid-refused.node");
  std::filesystem::remove(node);
  expectRefused(writeSolverMesh(node, pyramidBesideTet(), MeshFormat::TetGen), "prisms are not written to TetGen");
  EXPECT_FALSE(std::filesystem::exists(node));
}

TEST(MeshWriterExodus, PrismSidesFoundOrRefusedByName)
{
  const std::string path = tempPath("prism.exo");
  std::filesystem::remove(path);
  ASSERT_TRUE(writeSolverMesh(path, prismUnderTet(), MeshFormat::Exodus).ok());
  EXPECT_TRUE(std::filesystem::exists(path));
  // A quad of the prism's points across it, (2 0 4 5), is no face of any cell: refused, nothing written.
  SolverMesh bad = prismUnderTet();
  bad.quads[10] = 4;
  const std::string badPath = tempPath("prism-bad.exo");
  std::filesystem::remove(badPath);
  const Status s = writeSolverMesh(badPath, bad, MeshFormat::Exodus);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("boundary quad 2 is not a face of any tet, prism or pyramid"), std::string::npos)
    << s.message;
  EXPECT_FALSE(std::filesystem::exists(badPath));
}

TEST(MeshWriterMedit, RoundTripKeepsLabelsAndNames)
{
  const std::string path = tempPath("two.mesh"), again = tempPath("two-again.mesh");
  const SolverMesh m = twoTets();
  ASSERT_TRUE(writeSolverMesh(path, m, MeshFormat::Medit).ok());
  SolverMesh r;
  ASSERT_TRUE(readSolverMesh(path, r).ok());
  EXPECT_EQ(r.points, m.points);
  EXPECT_EQ(r.tets, m.tets);
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.trianglePatch, m.trianglePatch);
  EXPECT_EQ(r.patchNames, m.patchNames);
  ASSERT_TRUE(writeSolverMesh(again, r, MeshFormat::Medit).ok());
  EXPECT_EQ(readText(path), readText(again));
  EXPECT_FALSE(readSolverMesh(tempPath("missing.mesh"), r).ok());
}

TEST(SurfaceReaderNames, StlSolidNamesAndGmshPhysicalNames)
{
  const std::string stl = tempPath("named.stl");
  std::ofstream(stl) << "solid upper wing\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                        "vertex 0 1 0\nendloop\nendfacet\nendsolid\nsolid tip\nfacet normal 0 0 1\nouter loop\n"
                        "vertex 0 0 1\nvertex 1 0 1\nvertex 0 1 1\nendloop\nendfacet\nendsolid tip\n";
  SurfaceMesh s;
  ASSERT_TRUE(readSurface(stl, s).ok());
  EXPECT_EQ(s.patchNames, (NameTable{ { 0, "upper wing" }, { 1, "tip" } }));
  for (MeshFormat f : { MeshFormat::Gmsh22, MeshFormat::Gmsh41 })
  {
    const std::string msh = tempPath(f == MeshFormat::Gmsh22 ? "two22.msh" : "two41.msh");
    ASSERT_TRUE(writeSolverMesh(msh, twoTets(), f).ok());
    SurfaceMesh g;
    ASSERT_TRUE(readSurface(msh, g).ok());
    EXPECT_EQ(g.numberOfTriangles(), 6);
    EXPECT_EQ(g.patchIds, (std::vector<int32_t>{ 1, 1, 1, 2, 2, 2 }));
    EXPECT_EQ(g.patchNames, (NameTable{ { 1, "wall_a" }, { 2, "farfield" } }));
  }
}

TEST(MeshReaderTetGen, RoundTripAndZeroBasedFilesWithoutFaces)
{
  const std::string stem = tempPath("two-tetgen");
  ASSERT_TRUE(writeSolverMesh(stem + ".node", twoTets(), MeshFormat::TetGen).ok());
  SolverMesh r;
  ASSERT_TRUE(readSolverMesh(stem + ".ele", r).ok());
  const SolverMesh m = twoTets();
  EXPECT_EQ(r.points, m.points);
  EXPECT_EQ(r.tets, m.tets);
  EXPECT_EQ(r.tetRegion, m.tetRegion);
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.trianglePatch, m.trianglePatch);
  // TetGen's own numbering may start at 0; without .face there are no boundary triangles.
  const std::string zero = tempPath("zero");
  std::ofstream(zero + ".node") << "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
  std::ofstream(zero + ".ele") << "1 4 0\n0 0 1 2 3\n";
  std::filesystem::remove(zero + ".face");
  ASSERT_TRUE(readSolverMesh(zero + ".node", r).ok());
  EXPECT_EQ(r.tets, (std::vector<int32_t>{ 0, 1, 2, 3 }));
  EXPECT_EQ(r.tetRegion, (std::vector<int32_t>{ 1 }));
  EXPECT_TRUE(r.triangles.empty());
  std::ofstream(zero + ".ele") << "1 4 0\n0 0 1 2 9\n";
  EXPECT_FALSE(readSolverMesh(zero + ".node", r).ok()); // node id out of range
}
