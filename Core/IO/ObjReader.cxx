// Wavefront OBJ reader: `v` lines (x y z, an optional w or colour ignored), `f` lines (polygons of
// v, v/t, v/t/n or v//n references; negative references count back from the last vertex), polygons
// triangulated by ear clipping; `g` groups and `o` objects become named patches (one per distinct name, in
// order of first appearance; the latest `g` or `o` statement names the faces that follow, so an object's
// groups split it and an object without groups is one patch; faces before the first are in "default");
// texture coordinates, normals, materials and lines are ignored.
// Strict: every coordinate is a whole finite number ("nan", "1x", "abc" are errors naming the line), and
// every face reference must name an existing vertex (all bad references are counted, the first named).
#include "ObjReader.h"
#include "SurfaceReaderSupport.h"

#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
struct ObjFaces
{
  std::vector<int64_t> refs;   // vertex references, 1-based after resolving negatives (0: unresolvable)
  std::vector<size_t> starts;  // first ref of each face, plus the end
  std::vector<int64_t> lines;  // line of each face
  std::vector<int32_t> groups; // group of each face (-1: before any `g` or `o` statement)
};

// `g` and `o` statements: the group of the faces that follow, by name.
struct ObjGroups
{
  std::map<std::string, int32_t> idOfName;
  int32_t current = -1;

  void start(const std::vector<std::string_view>& toks, SurfaceMesh& mesh)
  {
    std::string name;
    for (size_t k = 1; k < toks.size(); ++k)
      name += (k > 1 ? " " : "") + std::string(toks[k]);
    current = id(name.empty() ? "default" : name, mesh);
  }
  int32_t id(const std::string& name, SurfaceMesh& mesh)
  {
    const auto it = idOfName.emplace(name, static_cast<int32_t>(idOfName.size())).first;
    mesh.patchNames[it->second] = name;
    return it->second;
  }
};

// "12", "12/3", "12/3/4", "12//4" -> 12; false when the vertex part is not an integer.
bool vertexReference(std::string_view tok, int64_t& ref)
{
  const size_t slash = tok.find('/');
  return parseInt(slash == std::string_view::npos ? tok : tok.substr(0, slash), ref);
}

Status readVertex(Scanner& sc, const std::vector<std::string_view>& toks, SurfaceMesh& mesh)
{
  if (toks.size() < 4)
  {
    return sc.error("a vertex needs three coordinates, got " + std::to_string(toks.size() - 1));
  }
  double xyz[3];
  for (int k = 0; k < 3; ++k)
  {
    if (!parseDouble(toks[1 + k], xyz[k]) || !std::isfinite(xyz[k]))
    {
      return Status::failure(ErrorKind::NonFinitePoint,
                             sc.path() + ":" + std::to_string(sc.line()) + ": vertex " +
                               std::to_string(mesh.numberOfPoints() + 1) + ": coordinate '" +
                               std::string(toks[1 + k].substr(0, 40)) + "' is not a finite number");
    }
  }
  mesh.points.insert(mesh.points.end(), xyz, xyz + 3);
  return Status::success();
}

Status readFace(Scanner& sc, const std::vector<std::string_view>& toks, int64_t vertices, int32_t group,
                ObjFaces& faces)
{
  if (toks.size() < 4)
  {
    return sc.error("a face needs at least three vertices, got " + std::to_string(toks.size() - 1));
  }
  for (size_t k = 1; k < toks.size(); ++k)
  {
    int64_t ref = 0;
    if (!vertexReference(toks[k], ref) || ref == 0)
    {
      return sc.error("face " + std::to_string(faces.lines.size() + 1) + ": '" + std::string(toks[k].substr(0, 40)) +
                      "' is not a vertex reference");
    }
    faces.refs.push_back(ref < 0 ? vertices + 1 + ref : ref); // -1: the last vertex read so far
  }
  faces.starts.push_back(faces.refs.size());
  faces.lines.push_back(sc.line());
  faces.groups.push_back(group);
  return Status::success();
}

// All references checked before any triangle is built: the count and the first bad one are named.
Status checkReferences(const std::string& path, const ObjFaces& faces, int64_t vertices)
{
  int64_t bad = 0;
  std::string first;
  for (size_t f = 0; f + 1 < faces.starts.size(); ++f)
    for (size_t k = faces.starts[f]; k < faces.starts[f + 1]; ++k)
      if (faces.refs[k] < 1 || faces.refs[k] > vertices)
      {
        if (bad++ == 0)
          first = "face " + std::to_string(f + 1) + " (line " + std::to_string(faces.lines[f]) + ") refers to vertex " +
            std::to_string(faces.refs[k]);
      }
  if (bad == 0)
    return Status::success();
  return readError(path, 0,
                   std::to_string(bad) + " face reference(s) outside the " + std::to_string(vertices) +
                     " vertices; first: " + first);
}
} // namespace

Status readOBJ(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions& options)
{
  ReadStart start(path, mesh, infoOut, "OBJ");
  if (!start.loaded.ok())
    return start.loaded;
  Status s;
  SurfaceReadInfo& info = start.info;
  const std::string& text = start.text;
  Scanner sc(text, path, true);
  std::vector<std::string_view> toks;
  ObjFaces faces;
  ObjGroups groups;
  faces.starts.push_back(0);
  while (sc.nextLine(toks))
  {
    if (toks[0] == "v")
      s = readVertex(sc, toks, mesh);
    else if (toks[0] == "f" || toks[0] == "fo")
      s = readFace(sc, toks, mesh.numberOfPoints(), groups.current, faces);
    else if (toks[0] == "g" || toks[0] == "o")
      groups.start(toks, mesh);
    else if (toks[0] == "l" || toks[0] == "p")
      ++info.skippedElements;
    if (!s.ok())
      return s;
  }
  const int64_t vertices = mesh.numberOfPoints();
  info.filePoints = vertices;
  s = checkReferences(path, faces, vertices);
  if (!s.ok())
    return s;
  const bool grouped = !groups.idOfName.empty();
  std::vector<int32_t> loop, scratch;
  for (size_t f = 0; f + 1 < faces.starts.size(); ++f)
  {
    loop.clear();
    for (size_t k = faces.starts[f]; k < faces.starts[f + 1]; ++k)
      loop.push_back(static_cast<int32_t>(faces.refs[k] - 1));
    ++info.fileFaces;
    const int32_t patch = !grouped ? -1 : faces.groups[f] >= 0 ? faces.groups[f] : groups.id("default", mesh);
    addPolygon(mesh, loop, patch, info, scratch);
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

} // namespace volgrid
