// OpenFOAM polyMesh writer: CASE/constant/polyMesh/{points,faces,owner,neighbour,boundary}, ASCII.
// Every prism (first, as in the .vtu), pyramid (where a layer column collapsed) and tet is a cell; faces
// are triangles or quads (prism sides, pyramid bases). Faces are oriented out of their owner; internal
// faces come first, in upper triangular order (owner < neighbour, sorted by owner then neighbour), then
// the boundary faces grouped by patch in label order. A boundary face takes the patch of the boundary triangle (or
// quad: prism sides on a symmetry plane) with the same points; a boundary face without one fails (the mesh and its
// patches disagree). Triangles between two cells (an interface between regions) are internal faces.
#include "CellFaces.h"
#include "MeshWriter.h"
#include "OutputFile.h"

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <tuple>
#include <unistd.h>

namespace volgrid
{
namespace
{
struct PolyMesh
{
  std::vector<std::array<int32_t, 4>> faces;  // a triangle's fourth point is -1
  std::vector<int32_t> owner, neighbour;      // neighbour: internal faces only
  std::vector<int32_t> patchStart, patchSize; // per patch in label order
};

std::string faceText(const std::array<int32_t, 4>& key)
{
  std::string text = "(" + std::to_string(key[0]);
  for (int k = 1; k < 4 && key[k] >= 0; ++k)
    text += " " + std::to_string(key[k]);
  return text + ")";
}

// The boundary triangles and quads by sorted key, with their patch.
std::vector<std::pair<std::array<int32_t, 4>, int32_t>> boundaryKeys(const SolverMesh& mesh)
{
  std::vector<std::pair<std::array<int32_t, 4>, int32_t>> keys;
  for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
    keys.emplace_back(cellFaceKey(mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]),
                      mesh.trianglePatch[t]);
  for (size_t q = 0; q < mesh.quadPatch.size(); ++q)
    keys.emplace_back(
      cellFaceKey(mesh.quads[4 * q], mesh.quads[4 * q + 1], mesh.quads[4 * q + 2], mesh.quads[4 * q + 3]),
      mesh.quadPatch[q]);
  std::sort(keys.begin(), keys.end());
  return keys;
}

Status buildPolyMesh(const SolverMesh& mesh, const std::vector<int32_t>& patches, PolyMesh& poly)
{
  const std::vector<CellFace> faces = sortedCellFaces(mesh.points, mesh.tets, mesh.prisms, mesh.pyramids);
  struct Internal
  {
    int32_t owner, neighbour;
    std::array<int32_t, 4> loop;
  };
  std::vector<Internal> internal;
  std::vector<std::pair<int32_t, const CellFace*>> boundary; // (patch, face)
  const std::vector<std::pair<std::array<int32_t, 4>, int32_t>> keys = boundaryKeys(mesh);
  for (size_t i = 0; i < faces.size();)
  {
    if (i + 1 < faces.size() && faces[i + 1].key == faces[i].key)
    {
      if (i + 2 < faces.size() && faces[i + 2].key == faces[i].key)
        return Status::failure(ErrorKind::InvalidOption,
                               "face " + faceText(faces[i].key) + " is shared by more than two cells (" +
                                 std::to_string(faces[i].cell) + ", " + std::to_string(faces[i + 1].cell) + ", " +
                                 std::to_string(faces[i + 2].cell) + ")");
      const CellFace& a = faces[i]; // sorted: the smaller cell first
      const CellFace& b = faces[i + 1];
      internal.push_back({ a.cell, b.cell, a.loop });
      i += 2;
      continue;
    }
    const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(faces[i].key, INT32_MIN));
    if (it == keys.end() || it->first != faces[i].key)
      return Status::failure(ErrorKind::InvalidOption,
                             "boundary face " + faceText(faces[i].key) + " of cell " + std::to_string(faces[i].cell) +
                               " is in no patch");
    boundary.emplace_back(it->second, &faces[i]);
    ++i;
  }
  std::sort(internal.begin(), internal.end(),
            [](const Internal& x, const Internal& y)
            { return std::tie(x.owner, x.neighbour) < std::tie(y.owner, y.neighbour); });
  std::stable_sort(boundary.begin(), boundary.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const Internal& f : internal)
  {
    poly.faces.push_back(f.loop);
    poly.owner.push_back(f.owner);
    poly.neighbour.push_back(f.neighbour);
  }
  size_t b = 0;
  for (int32_t p : patches)
  {
    poly.patchStart.push_back(static_cast<int32_t>(poly.faces.size()));
    for (; b < boundary.size() && boundary[b].first == p; ++b)
    {
      poly.faces.push_back(boundary[b].second->loop);
      poly.owner.push_back(boundary[b].second->cell);
    }
    poly.patchSize.push_back(static_cast<int32_t>(poly.faces.size()) - poly.patchStart.back());
  }
  return Status::success();
}

void foamHeader(std::FILE* f, const char* cls, const char* object, const std::string& note)
{
  std::fprintf(f, "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       %s;\n", cls);
  if (!note.empty())
    std::fprintf(f, "    note        \"%s\";\n", note.c_str());
  std::fprintf(f, "    location    \"constant/polyMesh\";\n    object      %s;\n}\n\n", object);
}

Status writeLabels(const std::string& path, const char* object, const std::vector<int32_t>& labels,
                   const std::string& note)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  foamHeader(out.stream(), "labelList", object, note);
  std::fprintf(out.stream(), "%zu\n(\n", labels.size());
  for (int32_t l : labels)
    std::fprintf(out.stream(), "%d\n", l);
  std::fprintf(out.stream(), ")\n");
  return out.commit();
}

Status writeFiles(const std::string& dir, const SolverMesh& mesh, const PolyMesh& poly,
                  const std::vector<int32_t>& patches, const MeshWriteOptions& options)
{
  OutputFile points, faces, boundary;
  Status s = points.open(dir + "/points");
  if (!s.ok())
    return s;
  foamHeader(points.stream(), "vectorField", "points", "");
  std::fprintf(points.stream(), "%" PRId64 "\n(\n", mesh.numberOfPoints());
  for (int64_t i = 0; i < mesh.numberOfPoints(); ++i)
    std::fprintf(points.stream(), "(%.17g %.17g %.17g)\n", mesh.points[3 * i], mesh.points[3 * i + 1],
                 mesh.points[3 * i + 2]);
  std::fprintf(points.stream(), ")\n");
  if (!(s = points.commit()).ok() || !(s = faces.open(dir + "/faces")).ok())
    return s;
  foamHeader(faces.stream(), "faceList", "faces", "");
  std::fprintf(faces.stream(), "%zu\n(\n", poly.faces.size());
  for (const auto& f : poly.faces) // each loop from its smallest point id: independent of the cell's vertex order
  {
    const int n = f[3] < 0 ? 3 : 4;
    const int k = static_cast<int>(std::min_element(f.begin(), f.begin() + n) - f.begin());
    std::fprintf(faces.stream(), "%d(%d", n, f[k]);
    for (int j = 1; j < n; ++j)
      std::fprintf(faces.stream(), " %d", f[(k + j) % n]);
    std::fprintf(faces.stream(), ")\n");
  }
  std::fprintf(faces.stream(), ")\n");
  if (!(s = faces.commit()).ok())
    return s;
  const std::string note = "nPoints:" + std::to_string(mesh.numberOfPoints()) + "  nCells:" +
    std::to_string(mesh.numberOfTets() + static_cast<int64_t>(mesh.prisms.size() / 6) +
                   static_cast<int64_t>(mesh.pyramids.size() / 5)) +
    "  nFaces:" + std::to_string(poly.faces.size()) + "  nInternalFaces:" + std::to_string(poly.neighbour.size());
  if (!(s = writeLabels(dir + "/owner", "owner", poly.owner, note)).ok() ||
      !(s = writeLabels(dir + "/neighbour", "neighbour", poly.neighbour, note)).ok() ||
      !(s = boundary.open(dir + "/boundary")).ok())
    return s;
  foamHeader(boundary.stream(), "polyBoundaryMesh", "boundary", "");
  std::fprintf(boundary.stream(), "%zu\n(\n", patches.size());
  for (size_t k = 0; k < patches.size(); ++k)
  {
    const std::string name = labelName(mesh.patchNames, patches[k], "patch");
    const auto it = options.openFoamPatchTypes.find(name);
    const std::string type = it != options.openFoamPatchTypes.end() ? it->second : defaultOpenFoamPatchType(name);
    std::fprintf(boundary.stream(),
                 "    %s\n    {\n        type            %s;\n        inGroups        List<word> 1(%s);\n"
                 "        nFaces          %d;\n        startFace       %d;\n    }\n",
                 name.c_str(), type.c_str(), type.c_str(), poly.patchSize[k], poly.patchStart[k]);
  }
  std::fprintf(boundary.stream(), ")\n");
  return boundary.commit();
}
} // namespace

Status writeOpenFOAM(const std::string& caseDir, const SolverMesh& mesh, const MeshWriteOptions& options)
{
  namespace fs = std::filesystem;
  std::vector<int32_t> allPatches = mesh.trianglePatch;
  allPatches.insert(allPatches.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  const std::vector<int32_t> patches = distinctLabels(allPatches);
  for (int32_t p : patches)
  {
    const std::string name = labelName(mesh.patchNames, p, "patch");
    if (!isOpenFoamWord(name))
      return Status::failure(ErrorKind::InvalidOption,
                             "patch name '" + name +
                               "' is not a valid OpenFOAM word (no spaces, quotes, slashes, ;{}()[]#$)");
  }
  std::error_code ec;
  if (fs::exists(caseDir, ec))
    return Status::failure(ErrorKind::InvalidOption,
                           "cannot write the OpenFOAM case '" + caseDir +
                             "': it already exists (remove it or choose another name)");
  PolyMesh poly;
  Status s = buildPolyMesh(mesh, patches, poly);
  if (!s.ok())
    return s;
  const std::string temp = caseDir + ".volgrid-tmp-" + std::to_string(static_cast<long>(getpid()));
  fs::create_directories(temp + "/constant/polyMesh", ec);
  if (ec)
    return Status::failure(ErrorKind::InvalidOption, "cannot create '" + temp + "': " + ec.message());
  s = writeFiles(temp + "/constant/polyMesh", mesh, poly, patches, options);
  if (s.ok())
  {
    fs::rename(temp, caseDir, ec);
    if (ec)
      s =
        Status::failure(ErrorKind::InvalidOption, "cannot rename '" + temp + "' to '" + caseDir + "': " + ec.message());
  }
  if (!s.ok())
    fs::remove_all(temp, ec);
  return s;
}

} // namespace volgrid
