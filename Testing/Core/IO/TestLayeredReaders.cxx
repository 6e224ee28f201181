// Boundary layers through CGNS, Exodus II and OpenFOAM: a hand-made mesh of a tet, a prism, two pyramids
// and boundary triangles and quads in three patches, written by VolGrid's writers and read back by its
// readers, has the same cells (vertex tuples in the same order; OpenFOAM: the same cells in the same
// orientation, from any first point), regions and patches (faces in the same orientation), and every cell
// read back has a positive volume (exact orient3d of each tet of its split).
#include "MeshReader.h"
#include "MeshWriter.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace volgrid;

// The prism (0 1 2 | 3 4 5) stands on the wall z = 0, the tet (3 4 5 6) on its top; pyramid A's quad
// (0 1 4 3) is the prism's side y = 0, its apex 7 beyond; pyramid B (8 9 10 11 | 12), alone in region
// "solid", has its quad on the symmetry plane z = 0. The faces are given in various rotations.
SolverMesh layeredMesh()
{
  SolverMesh m;
  m.points = { 0, 0,   0,    1,   0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1,   1,   0.3, 0.3,
               2, 0.5, -0.5, 0.5, 3, 0, 0, 4, 0, 0, 4, 1, 0, 3, 1, 0, 3.5, 0.5, 1 };
  m.tets = { 3, 4, 5, 6 };
  m.tetRegion = { 1 };
  m.prisms = { 0, 1, 2, 3, 4, 5 };
  m.prismRegion = { 1 };
  m.pyramids = { 0, 1, 4, 3, 7, 8, 9, 10, 11, 12 };
  m.pyramidRegion = { 1, 2 };
  m.regionNames = { { 1, "fluid" }, { 2, "solid" } };
  m.triangles = { 2, 1, 0,  0, 1,  7,                                 // wall: the prism's base, a pyramid A side
                  7, 1, 4,                                            // symmetry
                  3, 4, 6,  4, 5,  6,  3,  6,  5,  4,  3, 7, 3, 0, 7, // farfield: the tet's and pyramid A's
                  8, 9, 12, 9, 10, 12, 10, 11, 12, 11, 8, 12 };       // and pyramid B's sides
  m.trianglePatch = { 1, 1, 2, 3, 3, 3, 3, 3, 3, 3, 3, 3 };
  m.quads = { 2, 5, 4, 1, 0, 3, 5, 2, 8, 11, 10, 9 }; // the prism's two free sides, pyramid B's base
  m.quadPatch = { 2, 2, 2 };
  m.patchNames = { { 1, "wall" }, { 2, "symmetry" }, { 3, "farfield" } };
  return m;
}

std::string temp(const std::string& name)
{
  return ::testing::TempDir() + "volgrid_layered_" + name;
}

std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

using Labelled = std::vector<std::pair<std::vector<int32_t>, int32_t>>;

// The cells of `n` vertices with their labels, sorted; faces rotated to start at their smallest vertex
// (the same face in the same orientation), cells as they are.
Labelled labelled(const std::vector<int32_t>& cells, size_t n, const std::vector<int32_t>& labels, bool face)
{
  Labelled out;
  for (size_t c = 0; c < labels.size(); ++c)
  {
    std::vector<int32_t> v(cells.begin() + static_cast<std::ptrdiff_t>(n * c),
                           cells.begin() + static_cast<std::ptrdiff_t>(n * c + n));
    if (face)
      std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.emplace_back(v, labels[c]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expectSameMesh(const SolverMesh& a, const SolverMesh& b)
{
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(labelled(a.tets, 4, a.tetRegion, false), labelled(b.tets, 4, b.tetRegion, false));
  EXPECT_EQ(labelled(a.prisms, 6, a.prismRegion, false), labelled(b.prisms, 6, b.prismRegion, false));
  EXPECT_EQ(labelled(a.pyramids, 5, a.pyramidRegion, false), labelled(b.pyramids, 5, b.pyramidRegion, false));
  EXPECT_EQ(labelled(a.triangles, 3, a.trianglePatch, true), labelled(b.triangles, 3, b.trianglePatch, true));
  EXPECT_EQ(labelled(a.quads, 4, a.quadPatch, true), labelled(b.quads, 4, b.quadPatch, true));
  EXPECT_EQ(a.regionNames, b.regionNames);
  EXPECT_EQ(a.patchNames, b.patchNames);
}

// Every cell split into tets (prism a b c a' b' c': a b c a', b c a' b', c a' b' c'; pyramid q0..q3 apex:
// q0 q1 q2 apex, q0 q2 q3 apex), each of positive exact orientation.
void expectPositiveVolumes(const SolverMesh& m)
{
  const auto p = [&](int32_t v) { return m.points.data() + 3 * v; };
  const auto positive = [&](const int32_t* c, const int(*split)[4], int tets, const char* what)
  {
    for (int t = 0; t < tets; ++t)
      EXPECT_GT(predicates::orient3d(p(c[split[t][0]]), p(c[split[t][1]]), p(c[split[t][2]]), p(c[split[t][3]])), 0)
        << what << " (" << c[0] << " " << c[1] << " " << c[2] << " ...), part " << t;
  };
  static const int tet[1][4] = { { 0, 1, 2, 3 } };
  static const int prism[3][4] = { { 0, 1, 2, 3 }, { 1, 2, 3, 4 }, { 2, 3, 4, 5 } };
  static const int pyramid[2][4] = { { 0, 1, 2, 4 }, { 0, 2, 3, 4 } };
  for (size_t c = 0; c < m.tets.size() / 4; ++c)
    positive(m.tets.data() + 4 * c, tet, 1, "tet");
  for (size_t c = 0; c < m.prisms.size() / 6; ++c)
    positive(m.prisms.data() + 6 * c, prism, 3, "prism");
  for (size_t c = 0; c < m.pyramids.size() / 5; ++c)
    positive(m.pyramids.data() + 5 * c, pyramid, 2, "pyramid");
}

// A cell of `n` points in a form that only its points and orientation decide: tets sorted (the last two
// swapped after an odd permutation), prisms and pyramids the least of their equal forms (prism: a base
// rotation, or top and base swapped and reversed; pyramid: a rotation of the quad).
std::vector<int32_t> canonicalCell(std::vector<int32_t> v)
{
  if (v.size() == 4)
  {
    bool odd = false;
    for (size_t i = 0; i < 4; ++i)
      for (size_t j = 0; j + 1 < 4 - i; ++j)
        if (v[j] > v[j + 1])
          std::swap(v[j], v[j + 1]), odd = !odd;
    if (odd)
      std::swap(v[2], v[3]);
    return v;
  }
  std::vector<std::vector<int32_t>> forms;
  if (v.size() == 6)
    for (const std::vector<int32_t>& p : { v, std::vector<int32_t>{ v[3], v[5], v[4], v[0], v[2], v[1] } })
      for (int r = 0; r < 3; ++r)
        forms.push_back({ p[r], p[(r + 1) % 3], p[(r + 2) % 3], p[3 + r], p[3 + (r + 1) % 3], p[3 + (r + 2) % 3] });
  else
    for (int r = 0; r < 4; ++r)
      forms.push_back({ v[r], v[(r + 1) % 4], v[(r + 2) % 4], v[(r + 3) % 4], v[4] });
  return *std::min_element(forms.begin(), forms.end());
}

std::vector<std::vector<int32_t>> canonicalCells(const std::vector<int32_t>& cells, size_t n)
{
  std::vector<std::vector<int32_t>> out;
  for (size_t c = 0; c < cells.size() / n; ++c)
    out.push_back(canonicalCell(std::vector<int32_t>(cells.begin() + static_cast<std::ptrdiff_t>(n * c),
                                                     cells.begin() + static_cast<std::ptrdiff_t>(n * c + n))));
  std::sort(out.begin(), out.end());
  return out;
}

// Written, read back: the same mesh, positive cells.
SolverMesh roundTrip(const SolverMesh& mesh, const std::string& path)
{
  SolverMesh back;
  const Status w = writeSolverMesh(path, mesh, meshFormatFromPath(path));
  EXPECT_TRUE(w.ok()) << w.message;
  const Status r = readSolverMesh(path, back);
  EXPECT_TRUE(r.ok()) << r.message;
  return back;
}
} // namespace

TEST(LayeredReaders, TheTestMeshIsPositive)
{
  expectPositiveVolumes(layeredMesh());
}

TEST(LayeredReaders, CgnsRoundTripKeepsPrismsPyramidsAndQuads)
{
  const SolverMesh mesh = layeredMesh();
  const SolverMesh back = roundTrip(mesh, temp("mesh.cgns"));
  ASSERT_EQ(back.prisms.size(), 6u);
  ASSERT_EQ(back.pyramids.size(), 10u);
  EXPECT_EQ(back.quads.size(), 12u);
  expectSameMesh(mesh, back);
  expectPositiveVolumes(back);
  EXPECT_EQ(back.triangles.size(), mesh.triangles.size());
  // Written again from what was read: read back the same.
  expectSameMesh(back, roundTrip(back, temp("again.cgns")));
}

TEST(LayeredReaders, ExodusRoundTripKeepsPrismsPyramidsQuadsAndBytes)
{
  const SolverMesh mesh = layeredMesh();
  const std::string path = temp("mesh.exo"), again = temp("again.exo");
  const SolverMesh back = roundTrip(mesh, path);
  ASSERT_EQ(back.prisms.size(), 6u);
  ASSERT_EQ(back.pyramids.size(), 10u);
  EXPECT_EQ(back.quads.size(), 12u);
  expectSameMesh(mesh, back);
  expectPositiveVolumes(back);
  ASSERT_TRUE(writeSolverMesh(again, back, MeshFormat::Exodus).ok());
  EXPECT_EQ(contents(path), contents(again));
}

// A region with prisms but no tets, and a patch of quads only: both come back under their names.
TEST(LayeredReaders, LayerOnlyRegionsAndQuadOnlyPatchesKeepTheirNames)
{
  SolverMesh mesh = layeredMesh();
  mesh.prismRegion = { 2 };
  mesh.pyramidRegion = { 2, 2 };
  mesh.trianglePatch[2] = 3; // the symmetry patch keeps its quads only
  for (const char* name : { "only.cgns", "only.exo" })
  {
    const SolverMesh back = roundTrip(mesh, temp(name));
    expectSameMesh(mesh, back);
  }
}

// OpenFOAM keeps cells as faces: the cells come back in the same orientation (any first point; the prism
// may stand on its top), all in region 1; faces with their patches by name; written again, the same files.
TEST(LayeredReaders, OpenFoamRoundTripKeepsPrismsPyramidsQuadsAndFiles)
{
  const SolverMesh mesh = layeredMesh();
  const std::string dir = temp("foam"), again = temp("foam-again");
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(again);
  ASSERT_TRUE(writeSolverMesh(dir, mesh, MeshFormat::OpenFOAM).ok());
  SolverMesh back;
  const Status s = readSolverMesh(dir, back);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(back.points, mesh.points);
  EXPECT_EQ(canonicalCells(back.tets, 4), canonicalCells(mesh.tets, 4));
  EXPECT_EQ(canonicalCells(back.prisms, 6), canonicalCells(mesh.prisms, 6));
  EXPECT_EQ(canonicalCells(back.pyramids, 5), canonicalCells(mesh.pyramids, 5));
  ASSERT_EQ(back.prisms.size(), 6u);
  ASSERT_EQ(back.pyramids.size(), 10u);
  for (const std::vector<int32_t>* regions : { &back.tetRegion, &back.prismRegion, &back.pyramidRegion })
    EXPECT_EQ(*regions, std::vector<int32_t>(regions->size(), 1));
  EXPECT_EQ(labelled(back.triangles, 3, back.trianglePatch, true),
            labelled(mesh.triangles, 3, mesh.trianglePatch, true));
  EXPECT_EQ(labelled(back.quads, 4, back.quadPatch, true), labelled(mesh.quads, 4, mesh.quadPatch, true));
  EXPECT_EQ(back.patchNames, mesh.patchNames);
  expectPositiveVolumes(back);
  ASSERT_TRUE(writeSolverMesh(again, back, MeshFormat::OpenFOAM).ok());
  for (const char* f : { "points", "faces", "owner", "neighbour", "boundary" })
    EXPECT_EQ(contents(dir + "/constant/polyMesh/" + f), contents(again + "/constant/polyMesh/" + f)) << f;
}

// A cell of other faces (here a hexahedron's six quads) is refused by number, with its faces counted.
TEST(LayeredReaders, OpenFoamRefusesOtherCellsByNumber)
{
  const std::string dir = temp("foam-hex");
  std::filesystem::remove_all(dir);
  const std::string mesh = dir + "/constant/polyMesh/";
  std::filesystem::create_directories(mesh);
  const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";
  std::ofstream(mesh + "points") << header
                                 << "8\n(\n(0 0 0)\n(1 0 0)\n(1 1 0)\n(0 1 0)\n(0 0 1)\n(1 0 1)\n"
                                    "(1 1 1)\n(0 1 1)\n)\n";
  std::ofstream(mesh + "faces") << header
                                << "6\n(\n4(0 3 2 1)\n4(4 5 6 7)\n4(0 1 5 4)\n4(1 2 6 5)\n4(2 3 7 6)\n4(3 0 4 7)\n)\n";
  std::ofstream(mesh + "owner") << header << "6\n(\n0\n0\n0\n0\n0\n0\n)\n";
  std::ofstream(mesh + "neighbour") << header << "0\n(\n)\n";
  std::ofstream(mesh + "boundary") << header << "1\n(\nwalls\n{\ntype wall;\nnFaces 6;\nstartFace 0;\n}\n)\n";
  SolverMesh back;
  const Status s = readSolverMesh(dir, back);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("cell 0 is not a tetrahedron, prism or pyramid (6 faces: 0 triangles, 6 quads)"),
            std::string::npos)
    << s.message;
  EXPECT_EQ(back.numberOfPoints(), 0);
}
