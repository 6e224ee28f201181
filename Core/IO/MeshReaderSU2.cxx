// SU2 native mesh reader (.su2, ASCII, 3D): tets (type 10), boundary-layer prisms (13, VTK's order) and
// pyramids (14), points, and markers of triangles (type 5) and quads (9). Each marker becomes a patch,
// labelled 1, 2, ... in file order and named by its MARKER_TAG; SU2 has no regions (every cell gets
// region 1). Other element types are refused with their type number.
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <string_view>
#include <utility>

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
        if (s.ok() && type != 10 && type != 13 && type != 14)
          return sc.error("SU2 element type " + std::to_string(type) +
                          " is not supported (tets 10, prisms 13 and pyramids 14 only)");
        if (s.ok())
          s = readIds(sc,
                      type == 10     ? 4
                        : type == 13 ? 6
                                     : 5,
                      -1,
                      type == 10     ? mesh.tets
                        : type == 13 ? mesh.prisms
                                     : mesh.pyramids);
        if (s.ok() && type == 13) // VTK's wedge order: both triangles the other way round from SolverMesh's
        {
          int32_t* v = mesh.prisms.data() + mesh.prisms.size() - 6;
          std::swap(v[1], v[2]);
          std::swap(v[4], v[5]);
        }
        if (s.ok() && sc.nextOnLine(tok) && !parseInt(tok, index))
          return sc.error("bad element index");
      }
      mesh.tetRegion.assign(mesh.tets.size() / 4, 1);
      mesh.prismRegion.assign(mesh.prisms.size() / 6, 1);
      mesh.pyramidRegion.assign(mesh.pyramids.size() / 5, 1);
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
        if (s.ok() && type != 5 && type != 9)
          return sc.error("SU2 marker element type " + std::to_string(type) +
                          " is not supported (triangles 5 and quads 9 only)");
        if (s.ok())
          s = readIds(sc, type == 5 ? 3 : 4, mesh.numberOfPoints(), type == 5 ? mesh.triangles : mesh.quads);
        (type == 5 ? mesh.trianglePatch : mesh.quadPatch).push_back(marker);
      }
    }
    else if (s.ok())
      return sc.error("unexpected '" + std::string(tok.substr(0, 40)) + "'");
  }
  if (!s.ok())
    return s;
  for (const std::vector<int32_t>* cells : { &mesh.tets, &mesh.prisms, &mesh.pyramids })
    for (int32_t v : *cells)
      if (v >= mesh.numberOfPoints())
        return readError(path, 0, "cell point id " + std::to_string(v) + " out of range");
  if (!finishReadCells(mesh))
    return readError(path, 0, "no tetrahedra, prisms or pyramids: not a volume mesh");
  return Status::success();
}

} // namespace volgrid
