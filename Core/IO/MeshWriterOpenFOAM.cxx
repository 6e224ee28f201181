// OpenFOAM polyMesh writer: CASE/constant/polyMesh/{points,faces,owner,neighbour,boundary}, ASCII.
// Every prism (first, as in the .vtu), pyramid (where a layer column collapsed) and tet is a cell; faces
// are triangles or quads (prism sides, pyramid bases). Faces are oriented out of their owner; internal
// faces come first, in upper triangular order (owner < neighbour, sorted by owner then neighbour), then
// the boundary faces grouped by patch in label order. A boundary face takes the patch of the boundary triangle (or
// quad: prism sides on a symmetry plane) with the same points; a boundary face without one fails (the mesh and its
// patches disagree). Triangles between two cells (an interface between regions) are internal faces.
// No face list is built: the cell across each cell face (CellFaces.h, 4 bytes per cell face) and the
// boundary faces are all it keeps; every file is written by walking the cells again.
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
// The polyMesh's faces without a list of them: the cell across each cell face, and the boundary faces.
struct PolyFaces
{
  std::vector<int32_t> neighbour; // per cell face (MixedCellFaces numbering): the cell across, or -1
  int64_t internalFaces = 0;
  struct Boundary
  {
    int32_t patch;
    std::array<int32_t, 4> key;
    int32_t cell;
    int face;
    bool operator<(const Boundary& o) const { return patch < o.patch || (patch == o.patch && key < o.key); }
  };
  std::vector<Boundary> boundary;             // by patch, then by point ids
  std::vector<int32_t> patchStart, patchSize; // per patch in label order
};

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

Status buildPolyFaces(const SolverMesh& mesh, const MixedCellFaces& cells, const std::vector<int32_t>& patches,
                      PolyFaces& poly)
{
  Status s = faceNeighbours(cells, mesh.numberOfPoints(), poly.neighbour);
  if (!s.ok())
    return s;
  const std::vector<std::pair<std::array<int32_t, 4>, int32_t>> keys = boundaryKeys(mesh);
  for (int64_t c = 0; c < cells.numberOfCells(); ++c)
    for (int f = 0; f < cells.numberOfFaces(c); ++f)
    {
      const int32_t across = poly.neighbour[cells.firstFace(c) + f];
      if (across == c)
        return Status::failure(ErrorKind::InvalidOption, "cell " + std::to_string(c) + " has the face " +
                                                           cellFaceText(cells.key(c, f)) + " twice");
      if (across >= 0)
      {
        poly.internalFaces += across > c;
        continue;
      }
      const std::array<int32_t, 4> key = cells.key(c, f);
      const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, INT32_MIN));
      if (it == keys.end() || it->first != key)
        return Status::failure(ErrorKind::InvalidOption,
                               "boundary face " + cellFaceText(key) + " of cell " + std::to_string(c) + " is in no patch");
      poly.boundary.push_back({ it->second, key, static_cast<int32_t>(c), f });
    }
  std::sort(poly.boundary.begin(), poly.boundary.end());
  size_t b = 0;
  for (int32_t p : patches)
  {
    poly.patchStart.push_back(static_cast<int32_t>(poly.internalFaces + static_cast<int64_t>(b)));
    const size_t first = b;
    while (b < poly.boundary.size() && poly.boundary[b].patch == p)
      ++b;
    poly.patchSize.push_back(static_cast<int32_t>(b - first));
  }
  return Status::success();
}

// Visits the internal faces in upper triangular order: by owner (the smaller cell), then by neighbour.
template <class Visit>
void forEachInternalFace(const MixedCellFaces& cells, const PolyFaces& poly, Visit visit)
{
  for (int64_t c = 0; c < cells.numberOfCells(); ++c)
  {
    std::pair<int32_t, int> upper[5];
    int n = 0;
    for (int f = 0; f < cells.numberOfFaces(c); ++f)
    {
      const int32_t across = poly.neighbour[cells.firstFace(c) + f];
      if (across > c)
        upper[n++] = { across, f };
    }
    for (int k = 1; k < n; ++k) // insertion sort of at most 5
      for (int j = k; j > 0 && upper[j] < upper[j - 1]; --j)
        std::swap(upper[j], upper[j - 1]);
    for (int k = 0; k < n; ++k)
      visit(static_cast<int32_t>(c), upper[k].second, upper[k].first);
  }
}

void foamHeader(std::FILE* f, const char* cls, const char* object, const std::string& note)
{
  std::fprintf(f, "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       %s;\n", cls);
  if (!note.empty())
    std::fprintf(f, "    note        \"%s\";\n", note.c_str());
  std::fprintf(f, "    location    \"constant/polyMesh\";\n    object      %s;\n}\n\n", object);
}

// A labelList of `count` labels, which `emit` prints one per line.
template <class Emit>
Status writeLabels(const std::string& path, const char* object, int64_t count, const std::string& note, Emit emit)
{
  OutputFile out;
  Status s = out.open(path);
  if (!s.ok())
    return s;
  foamHeader(out.stream(), "labelList", object, note);
  std::fprintf(out.stream(), "%" PRId64 "\n(\n", count);
  emit(out.stream());
  std::fprintf(out.stream(), ")\n");
  return out.commit();
}

// A face's loop from its smallest point id: independent of the cell's vertex order.
void printFace(std::FILE* out, const std::array<int32_t, 4>& f)
{
  const int n = f[3] < 0 ? 3 : 4;
  const int k = static_cast<int>(std::min_element(f.begin(), f.begin() + n) - f.begin());
  std::fprintf(out, "%d(%d", n, f[k]);
  for (int j = 1; j < n; ++j)
    std::fprintf(out, " %d", f[(k + j) % n]);
  std::fprintf(out, ")\n");
}

Status writeFiles(const std::string& dir, const SolverMesh& mesh, const MixedCellFaces& cells, const PolyFaces& poly,
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
  const int64_t numFaces = poly.internalFaces + static_cast<int64_t>(poly.boundary.size());
  foamHeader(faces.stream(), "faceList", "faces", "");
  std::fprintf(faces.stream(), "%" PRId64 "\n(\n", numFaces);
  std::FILE* out = faces.stream();
  forEachInternalFace(cells, poly, [&](int32_t owner, int f, int32_t) { printFace(out, cells.loop(owner, f)); });
  for (const PolyFaces::Boundary& b : poly.boundary)
    printFace(out, cells.loop(b.cell, b.face));
  std::fprintf(out, ")\n");
  if (!(s = faces.commit()).ok())
    return s;
  const std::string note = "nPoints:" + std::to_string(mesh.numberOfPoints()) +
    "  nCells:" + std::to_string(cells.numberOfCells()) + "  nFaces:" + std::to_string(numFaces) +
    "  nInternalFaces:" + std::to_string(poly.internalFaces);
  const auto owners = [&](std::FILE* f)
  {
    forEachInternalFace(cells, poly, [&](int32_t owner, int, int32_t) { std::fprintf(f, "%d\n", owner); });
    for (const PolyFaces::Boundary& b : poly.boundary)
      std::fprintf(f, "%d\n", b.cell);
  };
  const auto neighbours = [&](std::FILE* f)
  { forEachInternalFace(cells, poly, [&](int32_t, int, int32_t across) { std::fprintf(f, "%d\n", across); }); };
  if (!(s = writeLabels(dir + "/owner", "owner", numFaces, note, owners)).ok() ||
      !(s = writeLabels(dir + "/neighbour", "neighbour", poly.internalFaces, note, neighbours)).ok() ||
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
  const MixedCellFaces cells(mesh.points, mesh.tets, mesh.prisms, mesh.pyramids);
  PolyFaces poly;
  Status s = buildPolyFaces(mesh, cells, patches, poly);
  if (!s.ok())
    return s;
  const std::string temp = caseDir + ".volgrid-tmp-" + std::to_string(static_cast<long>(getpid()));
  fs::create_directories(temp + "/constant/polyMesh", ec);
  if (ec)
    return Status::failure(ErrorKind::InvalidOption, "cannot create '" + temp + "': " + ec.message());
  s = writeFiles(temp + "/constant/polyMesh", mesh, cells, poly, patches, options);
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
