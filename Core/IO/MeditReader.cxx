// Medit .mesh reader (ASCII): Vertices, Triangles and Quadrilaterals (their references become patch
// ids); every other known section is skipped.
#include "MeditReader.h"
#include "SurfaceReaderSupport.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
// Entries per record of the sections we skip.
const std::pair<const char*, int> kSkipped[] = { { "Edges", 3 },
                                                 { "Tetrahedra", 5 },
                                                 { "Prisms", 7 },
                                                 { "Pentahedra", 7 },
                                                 { "Hexahedra", 9 },
                                                 { "Corners", 1 },
                                                 { "Ridges", 1 },
                                                 { "RequiredVertices", 1 },
                                                 { "RequiredEdges", 1 },
                                                 { "RequiredTriangles", 1 },
                                                 { "RequiredQuadrilaterals", 1 },
                                                 { "Normals", 3 },
                                                 { "Tangents", 3 },
                                                 { "NormalAtVertices", 2 },
                                                 { "NormalAtTriangleVertices", 3 },
                                                 { "NormalAtQuadrilateralVertices", 3 },
                                                 { "TangentAtVertices", 2 },
                                                 { "TangentAtEdgeVertices", 3 },
                                                 { "Crack", 2 },
                                                 { "Edges", 3 } };

// The Vertices section after its keyword: a count, then "x y z ref" records (the refs are ignored).
Status readMeditVertices(Scanner& sc, int64_t limit, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  int64_t nv;
  Status s = sc.readCount(nv, "vertex count", limit);
  if (!s.ok())
  {
    return s;
  }
  mesh.points.reserve(3 * size_t(nv));
  for (int64_t i = 0; i < nv; ++i)
  {
    double xyz[3];
    int64_t ref;
    for (int k = 0; k < 3 && s.ok(); ++k)
    {
      s = sc.readDouble(xyz[k], "a vertex coordinate");
    }
    if (s.ok())
    {
      s = sc.readInt(ref, "a vertex reference");
    }
    if (!s.ok())
    {
      return s;
    }
    mesh.addPoint(xyz[0], xyz[1], xyz[2]);
  }
  info.filePoints += nv;
  return Status::success();
}

// A Triangles (nc 3) or Quadrilaterals (nc 4) section after its keyword: a count, then records of nc
// 1-based vertex ids and a reference, which becomes the face's patch id.
Status readMeditElements(Scanner& sc, int nc, int64_t limit, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  int64_t ne;
  Status s = sc.readCount(ne, "element count", limit);
  if (!s.ok())
  {
    return s;
  }
  const int64_t nv = mesh.numberOfPoints();
  std::vector<int32_t> loop, scratch;
  for (int64_t e = 0; e < ne; ++e)
  {
    loop.clear();
    for (int k = 0; k < nc; ++k)
    {
      int64_t id;
      s = sc.readInt(id, "a vertex id");
      if (!s.ok())
      {
        return s;
      }
      if (id < 1 || id > nv)
      {
        return sc.error("element " + std::to_string(e + 1) + ": vertex id " + std::to_string(id) + " out of range [1," +
                        std::to_string(nv) + "]");
      }
      loop.push_back(static_cast<int32_t>(id - 1));
    }
    int64_t ref;
    s = sc.readInt(ref, "an element reference");
    if (!s.ok())
    {
      return s;
    }
    ++info.fileFaces;
    addPolygon(mesh, loop, static_cast<int32_t>(ref), info, scratch);
  }
  return Status::success();
}

// A known section we do not use (kSkipped), after its keyword: its count and records are skipped and
// counted; an unknown keyword is an error.
Status skipMeditSection(Scanner& sc, std::string_view keyword, int64_t limit, SurfaceReadInfo& info)
{
  int per = -1;
  for (const auto& sk : kSkipped)
  {
    if (keyword == sk.first)
    {
      per = sk.second;
    }
  }
  if (per < 0)
  {
    return sc.error("unknown Medit keyword '" + std::string(keyword.substr(0, 40)) + "'");
  }
  int64_t ne;
  const Status s = sc.readCount(ne, "entry count", limit);
  if (!s.ok())
  {
    return s;
  }
  std::string_view tok;
  for (int64_t e = 0; e < ne * per; ++e)
  {
    if (!sc.next(tok))
    {
      return sc.error("unexpected end of file in a skipped section");
    }
  }
  info.skippedElements += ne;
  return Status::success();
}

// The section or header keyword `tok` and what follows it; haveVertices tracks the Vertices section.
Status readMeditKeyword(Scanner& sc, std::string_view tok, int64_t limit, SurfaceMesh& mesh, SurfaceReadInfo& info,
                        bool& haveVertices)
{
  if (tok == "MeshVersionFormatted")
  {
    int64_t v;
    return sc.readInt(v, "version number");
  }
  if (tok == "Dimension")
  {
    int64_t dim = 3;
    const Status s = sc.readInt(dim, "dimension");
    if (s.ok() && dim != 3)
    {
      return sc.error("only 3D Medit meshes are supported (Dimension " + std::to_string(dim) + ")");
    }
    return s;
  }
  if (tok == "Vertices")
  {
    haveVertices = true;
    return readMeditVertices(sc, limit, mesh, info);
  }
  if (tok == "Triangles" || tok == "Quadrilaterals")
  {
    if (!haveVertices)
    {
      return sc.error("element section before the Vertices section");
    }
    return readMeditElements(sc, tok == "Triangles" ? 3 : 4, limit, mesh, info);
  }
  return skipMeditSection(sc, tok, limit, info);
}
} // namespace

Status readMedit(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
                 const SurfaceReadOptions& options)
{
  ReadStart start(path, mesh, infoOut, "Medit");
  if (!start.loaded.ok())
    return start.loaded;
  SurfaceReadInfo& info = start.info;
  const std::string& text = start.text;
  if (lowerExtension(path) == "meshb" || text.find('\0') != std::string::npos)
  {
    return readError(path, 0, "binary Medit (.meshb) is not supported");
  }
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  bool haveVertices = false;
  std::string_view tok;
  while (sc.next(tok) && tok != "End")
  {
    const Status s = readMeditKeyword(sc, tok, limit, mesh, info, haveVertices);
    if (!s.ok())
    {
      return s;
    }
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

} // namespace volgrid
