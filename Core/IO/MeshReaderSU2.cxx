// SU2 native mesh reader (.su2, ASCII, 3D): tets (type 10), points, and markers of triangles (type 5).
// Each marker becomes a patch, labelled 1, 2, ... in file order and named by its MARKER_TAG; SU2 has no
// regions (all tets get region 1). Other element types are refused with their type number.
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <string_view>

namespace volgrid
{

using namespace detail;

namespace
{
// "KEYWORD= value" may come as one token ("NDIME=3") or two ("NDIME=", "3"): returns the value text.
bool keywordValue(Scanner& sc, std::string_view tok, std::string_view key, std::string_view& value)
{
  if (tok.substr(0, key.size()) != key)
    return false;
  value = tok.substr(key.size());
  if (value.empty())
    sc.nextOnLine(value);
  return true;
}

Status readCount(Scanner& sc, std::string_view text, int64_t limit, int64_t& count)
{
  if (!parseInt(text, count) || count < 0 || count > limit)
    return sc.error("bad count '" + std::string(text) + "'");
  return Status::success();
}

Status readIds(Scanner& sc, int n, int64_t numPoints, std::vector<int32_t>& out)
{
  for (int k = 0; k < n; ++k)
  {
    int64_t v = 0;
    Status s = sc.readInt(v, "a point id");
    if (!s.ok())
      return s;
    if (v < 0 || (numPoints >= 0 && v >= numPoints))
      return sc.error("point id " + std::to_string(v) + " out of range");
    out.push_back(static_cast<int32_t>(v));
  }
  return Status::success();
}
} // namespace

Status readSU2(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
    return s;
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  std::string_view tok, value;
  int64_t count = 0;
  int32_t marker = 0;
  while (s.ok() && sc.next(tok))
  {
    if (keywordValue(sc, tok, "NDIME=", value))
    {
      if (value != "3")
        return sc.error("only 3D SU2 meshes are read (NDIME= " + std::string(value) + ")");
    }
    else if (keywordValue(sc, tok, "NELEM=", value) && (s = readCount(sc, value, limit, count)).ok())
    {
      for (int64_t e = 0; e < count && s.ok(); ++e)
      {
        int64_t type = 0, index = 0;
        s = sc.readInt(type, "an element type");
        if (s.ok() && type != 10)
          return sc.error("SU2 element type " + std::to_string(type) + " is not supported (tets, type 10, only)");
        if (s.ok())
          s = readIds(sc, 4, -1, mesh.tets);
        if (s.ok() && sc.nextOnLine(tok) && !parseInt(tok, index))
          return sc.error("bad element index");
      }
      mesh.tetRegion.assign(mesh.tets.size() / 4, 1);
    }
    else if (keywordValue(sc, tok, "NPOIN=", value) && (s = readCount(sc, value, limit, count)).ok())
    {
      for (int64_t i = 0; i < count && s.ok(); ++i)
      {
        for (int k = 0; k < 3 && s.ok(); ++k)
        {
          double x = 0;
          s = sc.readDouble(x, "a point coordinate");
          mesh.points.push_back(x);
        }
        while (s.ok() && sc.nextOnLine(tok))
        {
        } // the optional point index
      }
    }
    else if (keywordValue(sc, tok, "NMARK=", value))
    {
    }
    else if (keywordValue(sc, tok, "MARKER_TAG=", value))
      mesh.patchNames[++marker] = std::string(value);
    else if (keywordValue(sc, tok, "MARKER_ELEMS=", value) && (s = readCount(sc, value, limit, count)).ok())
    {
      for (int64_t e = 0; e < count && s.ok(); ++e)
      {
        int64_t type = 0;
        s = sc.readInt(type, "a marker element type");
        if (s.ok() && type != 5)
          return sc.error("SU2 marker element type " + std::to_string(type) + " is not supported (triangles only)");
        if (s.ok())
          s = readIds(sc, 3, mesh.numberOfPoints(), mesh.triangles);
        mesh.trianglePatch.push_back(marker);
      }
    }
    else if (s.ok())
      return sc.error("unexpected '" + std::string(tok.substr(0, 40)) + "'");
  }
  if (!s.ok())
    return s;
  for (int32_t v : mesh.tets)
    if (v >= mesh.numberOfPoints())
      return readError(path, 0, "tet point id " + std::to_string(v) + " out of range");
  if (mesh.tets.empty())
    return readError(path, 0, "no tetrahedra: not a volume mesh");
  return Status::success();
}

} // namespace volgrid
