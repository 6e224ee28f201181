// OpenFOAM polyMesh writer: CASE/constant/polyMesh/{points,faces,owner,neighbour,boundary}, ASCII.
// Every tet is a cell. Faces are oriented out of their owner; internal faces come first, in upper
// triangular order (owner < neighbour, sorted by owner then neighbour), then the boundary faces grouped
// by patch in label order. Boundary faces take the patch of the boundary triangle with the same three
// points; a boundary face without one fails (the mesh and its patches disagree). Triangles between two
// tets (an interface between regions) are internal faces.
#include "MeshWriter.h"
#include "OutputFile.h"
#include "TetFaces.h"

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
  std::vector<std::array<int32_t, 3>> faces;
  std::vector<int32_t> owner, neighbour;      // neighbour: internal faces only
  std::vector<int32_t> patchStart, patchSize; // per patch in label order
};

Status buildPolyMesh(const SolverMesh& mesh, const std::vector<int32_t>& patches, PolyMesh& poly)
{
  const std::vector<TetFace> faces = sortedTetFaces(mesh.points, mesh.tets);
  struct Internal
  {
    int32_t owner, neighbour;
    std::array<int32_t, 3> loop;
  };
  std::vector<Internal> internal;
  std::vector<std::pair<int32_t, const TetFace*>> boundary; // (patch, face)
  std::vector<std::pair<std::array<int32_t, 3>, int32_t>> triangleKeys;
  for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
  {
    std::array<int32_t, 3> k = { mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2] };
    std::sort(k.begin(), k.end());
    triangleKeys.emplace_back(k, mesh.trianglePatch[t]);
  }
  std::sort(triangleKeys.begin(), triangleKeys.end());
  for (size_t i = 0; i < faces.size();)
  {
    if (i + 1 < faces.size() && faces[i + 1].key == faces[i].key)
    {
      const TetFace& a = faces[i]; // sorted: the smaller tet first
      const TetFace& b = faces[i + 1];
      internal.push_back({ a.tet, b.tet, a.loop });
      i += 2;
      continue;
    }
    const auto it = std::lower_bound(triangleKeys.begin(), triangleKeys.end(), std::make_pair(faces[i].key, INT32_MIN));
    if (it == triangleKeys.end() || it->first != faces[i].key)
      return Status::failure(ErrorKind::InvalidOption,
                             "boundary face (" + std::to_string(faces[i].key[0]) + " " +
                               std::to_string(faces[i].key[1]) + " " + std::to_string(faces[i].key[2]) + ") of tet " +
                               std::to_string(faces[i].tet) + " is in no patch");
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
      poly.owner.push_back(boundary[b].second->tet);
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
  for (const auto& f : poly.faces) // each loop from its smallest point id: independent of the tet's vertex order
  {
    const int k = f[0] < f[1] ? (f[0] < f[2] ? 0 : 2) : (f[1] < f[2] ? 1 : 2);
    std::fprintf(faces.stream(), "3(%d %d %d)\n", f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
  }
  std::fprintf(faces.stream(), ")\n");
  if (!(s = faces.commit()).ok())
    return s;
  const std::string note = "nPoints:" + std::to_string(mesh.numberOfPoints()) +
    "  nCells:" + std::to_string(mesh.numberOfTets()) + "  nFaces:" + std::to_string(poly.faces.size()) +
    "  nInternalFaces:" + std::to_string(poly.neighbour.size());
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
  const std::vector<int32_t> patches = distinctLabels(mesh.trianglePatch);
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
