// Medit .mesh volume reader (see MeshReader.h) and the solver reader dispatch by extension.
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <string_view>

namespace volgrid
{

using namespace detail;

namespace
{
// "# VolGrid patch LABEL NAME" and "# VolGrid region LABEL NAME" lines (MeshWriterMedit.cxx).
void readNameComments(const std::string& text, SolverMesh& mesh)
{
  const std::string tag = "# VolGrid ";
  for (size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1))
  {
    if (at > 0 && text[at - 1] != '\n')
      continue;
    const size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at + tag.size(), end - at - tag.size());
    char kind[16] = { 0 };
    int label = 0, used = 0;
    if (std::sscanf(line.c_str(), "%15s %d %n", kind, &label, &used) < 2 || used <= 0)
      continue;
    std::string name = line.substr(static_cast<size_t>(used));
    while (!name.empty() && (name.back() == '\r' || name.back() == ' '))
      name.pop_back();
    if (std::strcmp(kind, "patch") == 0)
      mesh.patchNames[label] = name;
    else if (std::strcmp(kind, "region") == 0)
      mesh.regionNames[label] = name;
  }
}

// Reads `count` records of `nv` 1-based vertex ids and a reference.
Status readCells(Scanner& sc, int64_t count, int nv, int64_t numPoints, std::vector<int32_t>& cells,
                 std::vector<int32_t>& refs)
{
  for (int64_t e = 0; e < count; ++e)
  {
    for (int k = 0; k <= nv; ++k)
    {
      int64_t v = 0;
      Status s = sc.readInt(v, k < nv ? "a vertex id" : "a reference");
      if (!s.ok())
        return s;
      if (k < nv && (v < 1 || v > numPoints))
        return sc.error("vertex id " + std::to_string(v) + " out of range 1.." + std::to_string(numPoints));
      (k < nv ? cells : refs).push_back(static_cast<int32_t>(k < nv ? v - 1 : v));
    }
  }
  return Status::success();
}
} // namespace

bool solverMeshReaderSupports(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  return ext == "mesh" || ext == "msh" || ext == "su2" || ext == "node" || ext == "ele" || ext == "face" ||
    ext == "cgns" || ext == "exo" || ext == "e" || ext == "ex2" || isOpenFoamCase(path);
}

Status readSolverMesh(const std::string& path, SolverMesh& mesh)
{
  if (isOpenFoamCase(path))
    return readOpenFOAM(path, mesh);
  if (lowerExtension(path) == "mesh")
    return readMeditVolume(path, mesh);
  if (lowerExtension(path) == "msh")
    return readGmshVolume(path, mesh);
  if (lowerExtension(path) == "su2")
    return readSU2(path, mesh);
  if (lowerExtension(path) == "cgns")
    return readCGNS(path, mesh);
  const std::string ext = lowerExtension(path);
  if (ext == "exo" || ext == "e" || ext == "ex2")
    return readExodus(path, mesh);
  if (solverMeshReaderSupports(path))
    return readTetGenVolume(path, mesh);
  return Status::failure(ErrorKind::InvalidOption,
                         "cannot read a volume mesh from '" + path +
                           "': unknown extension (.mesh .msh .su2 .node .cgns .exo)");
}

Status readMeditVolume(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
    return s;
  readNameComments(text, mesh);
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  static const std::pair<const char*, int> skipped[] = {
    { "Edges", 3 },         { "Hexahedra", 9 },        { "Corners", 1 }, { "Ridges", 1 }, { "RequiredVertices", 1 },
    { "RequiredEdges", 1 }, { "RequiredTriangles", 1 }
  };
  // Cell sections: vertices per cell, and where the cells and their references go (SolverMesh's order is
  // Medit's for every kind, MeshWriterMedit.cxx).
  const struct
  {
    const char* name;
    int vertices;
    std::vector<int32_t>* cells;
    std::vector<int32_t>* refs;
  } sections[] = { { "Tetrahedra", 4, &mesh.tets, &mesh.tetRegion },
                   { "Triangles", 3, &mesh.triangles, &mesh.trianglePatch },
                   { "Quadrilaterals", 4, &mesh.quads, &mesh.quadPatch },
                   { "Prisms", 6, &mesh.prisms, &mesh.prismRegion },
                   { "Pyramids", 5, &mesh.pyramids, &mesh.pyramidRegion } };
  std::string_view tok;
  int64_t value = 0;
  while (s.ok() && sc.next(tok) && tok != "End")
  {
    if (tok == "MeshVersionFormatted" || tok == "Dimension")
    {
      s = sc.readInt(value, tok == "Dimension" ? "the dimension" : "the version");
      if (s.ok() && tok == "Dimension" && value != 3)
        return sc.error("only 3D Medit meshes are supported");
      continue;
    }
    const bool verts = tok == "Vertices";
    const auto* section =
      std::find_if(std::begin(sections), std::end(sections), [&](const auto& c) { return tok == c.name; });
    int64_t count = 0;
    s = sc.readCount(count, "an entry count", limit);
    if (!s.ok())
      return s;
    if (verts)
    {
      for (int64_t i = 0; i < 4 * count && s.ok(); ++i)
      {
        double x = 0;
        s = sc.readDouble(x, "a vertex coordinate or reference");
        if (i % 4 != 3)
          mesh.points.push_back(x);
      }
    }
    else if (section != std::end(sections))
      s = readCells(sc, count, section->vertices, mesh.numberOfPoints(), *section->cells, *section->refs);
    else
    {
      int per = 0;
      for (const auto& sk : skipped)
        per = tok == sk.first ? sk.second : per;
      if (per == 0)
        return sc.error("unknown Medit section '" + std::string(tok.substr(0, 40)) + "'");
      double ignored = 0;
      for (int64_t i = 0; i < per * count && s.ok(); ++i)
        s = sc.readDouble(ignored, "an entry");
    }
  }
  if (!s.ok())
    return s;
  if (!finishReadCells(mesh))
    return readError(path, 0, "no Tetrahedra, Prisms or Pyramids section: not a volume mesh");
  return Status::success();
}

} // namespace volgrid
