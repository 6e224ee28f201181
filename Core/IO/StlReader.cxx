// STL reader, ASCII and binary (one patch id per solid). Lenient ASCII: several solids, facets after
// 'endsolid', text after the last 'endsolid'. Points are always merged (STL has no connectivity).
#include "StlReader.h"
#include "SurfaceReaderSupport.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
// The rest of a facet after its 'facet' keyword: [normal nx ny nz] outer loop (vertex x y z)* endloop
// endfacet; the loop's vertices (added to mesh) into `loop`.
Status readFacet(Scanner& sc, SurfaceMesh& mesh, std::vector<int32_t>& loop)
{
  std::string_view tok;
  // facet normal nx ny nz
  if (!sc.next(tok))
  {
    return sc.error("unexpected end of file in a facet");
  }
  if (tok == "normal")
  {
    double nrm;
    for (int k = 0; k < 3; ++k)
    {
      const Status s = sc.readDouble(nrm, "a normal component");
      if (!s.ok())
      {
        return s;
      }
    }
    if (!sc.next(tok))
    {
      return sc.error("unexpected end of file in a facet");
    }
  }
  if (tok != "outer")
  {
    return sc.error("expected 'outer loop', got '" + std::string(tok.substr(0, 40)) + "'");
  }
  if (!sc.next(tok) || tok != "loop")
  {
    return sc.error("expected 'loop' after 'outer'");
  }
  loop.clear();
  while (true)
  {
    if (!sc.next(tok))
    {
      return sc.error("unexpected end of file in a facet loop");
    }
    if (tok == "endloop")
    {
      break;
    }
    if (tok != "vertex")
    {
      return sc.error("expected 'vertex' or 'endloop', got '" + std::string(tok.substr(0, 40)) + "'");
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k)
    {
      const Status s = sc.readDouble(xyz[k], "a vertex coordinate");
      if (!s.ok())
      {
        return s;
      }
    }
    loop.push_back(mesh.addPoint(xyz[0], xyz[1], xyz[2]));
  }
  if (!sc.next(tok) || tok != "endfacet")
  {
    return sc.error("expected 'endfacet'");
  }
  return Status::success();
}

// ASCII STL: every solid (its name the rest of its 'solid' line) one patch; facets after 'endsolid'
// join the last solid, text after the last 'endsolid' is ignored (with a warning).
Status readAsciiSTL(const std::string& text, const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  info.format = "STL ascii";
  Scanner sc(text, path, false);
  std::string_view tok;
  std::vector<int32_t> loop, scratch;
  int32_t solid = -1;
  int64_t strayFacets = 0;
  bool inSolid = false;
  while (sc.next(tok))
  {
    if (!inSolid)
    {
      if (tok == "solid")
      {
        ++solid;
        inSolid = true;
        std::string name; // the solid's name: the rest of the line
        while (sc.nextOnLine(tok))
          name += (name.empty() ? "" : " ") + std::string(tok);
        if (!name.empty())
          mesh.patchNames[solid] = name;
        continue;
      }
      if (tok == "facet" && solid >= 0)
      {
        // Facets after 'endsolid' without a new 'solid' (gmsh's multi_solid.stl): keep reading them
        // as part of the last solid.
        ++strayFacets;
        inSolid = true;
      }
      else
      {
        // Text after the last endsolid (gmsh appends its .geo commands): ignore, but say so.
        info.warnings.push_back("text after 'endsolid' at line " + std::to_string(sc.line()) + " ignored");
        break;
      }
    }
    if (tok == "endsolid")
    {
      inSolid = false;
      sc.skipLine();
      continue;
    }
    if (tok != "facet")
    {
      return sc.error("expected 'facet' or 'endsolid', got '" + std::string(tok.substr(0, 40)) + "'");
    }
    const Status facet = readFacet(sc, mesh, loop);
    if (!facet.ok())
      return facet;
    ++info.fileFaces;
    if (loop.size() < 3)
    {
      ++info.skippedElements;
      continue;
    }
    addPolygon(mesh, loop, solid, info, scratch);
  }
  if (strayFacets > 0)
  {
    info.warnings.push_back(std::to_string(strayFacets) + " time(s) facets followed 'endsolid' without a new 'solid'");
  }
  if (inSolid)
  {
    info.warnings.push_back("missing 'endsolid' at the end of the file");
  }
  info.solids = solid + 1;
  return Status::success();
}

// Binary STL: `count` triangles of 50 bytes after the 84-byte header, one patch.
void readBinarySTL(const std::string& text, uint32_t count, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  info.format = "STL binary";
  info.solids = 1;
  mesh.points.reserve(9 * size_t(count));
  mesh.triangles.reserve(3 * size_t(count));
  const char* p = text.data() + 84;
  for (uint32_t t = 0; t < count; ++t, p += 50)
  {
    float v[12];
    std::memcpy(v, p, 48);
    const int32_t a = mesh.addPoint(v[3], v[4], v[5]);
    const int32_t b = mesh.addPoint(v[6], v[7], v[8]);
    const int32_t c = mesh.addPoint(v[9], v[10], v[11]);
    mesh.addTriangle(a, b, c, 0);
  }
  info.fileFaces = count;
}
} // namespace

Status readSTL(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions&)
{
  ReadStart start(path, mesh, infoOut, "");
  if (!start.loaded.ok())
    return start.loaded;
  Status s;
  SurfaceReadInfo& info = start.info;
  const std::string& text = start.text;
  if (text.empty())
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  bool binary = false;
  uint32_t count = 0;
  if (text.size() >= 84)
  {
    std::memcpy(&count, text.data() + 80, 4); // little-endian hosts only (x86, ARM)
    binary = 84 + 50 * uint64_t(count) == text.size();
  }
  size_t firstNonSpace = text.find_first_not_of(" \t\r\n");
  const bool startsWithSolid = firstNonSpace != std::string::npos && text.compare(firstNonSpace, 5, "solid") == 0;
  if (binary && startsWithSolid)
  {
    // Some binary writers start the header with "solid"; an ASCII file whose size happens to match
    // is recognised by its 'facet' keyword right after the first line.
    const size_t eol = text.find('\n');
    const size_t facet = eol == std::string::npos ? std::string::npos : text.find_first_not_of(" \t\r\n", eol);
    binary = !(facet != std::string::npos &&
               (text.compare(facet, 5, "facet") == 0 || text.compare(facet, 8, "endsolid") == 0));
  }
  if (binary)
  {
    readBinarySTL(text, count, mesh, info);
  }
  else if (startsWithSolid && text.find('\0') != std::string::npos && text.size() >= 84)
  {
    // "solid" header but binary content (NUL bytes): a binary file whose size does not match.
    return readError(path, 0,
                     "binary STL header announces " + std::to_string(count) + " triangles (" +
                       std::to_string(84 + 50 * uint64_t(count)) + " bytes) but the file has " +
                       std::to_string(text.size()) + " bytes");
  }
  else if (startsWithSolid)
  {
    s = readAsciiSTL(text, path, mesh, info);
    if (!s.ok())
      return s;
  }
  else
  {
    if (text.size() < 84)
    {
      return readError(path, 0, "neither ASCII STL (no 'solid' keyword) nor binary STL (shorter than 84 bytes)");
    }
    return readError(path, 0,
                     "binary STL header announces " + std::to_string(count) + " triangles (" +
                       std::to_string(84 + 50 * uint64_t(count)) + " bytes) but the file has " +
                       std::to_string(text.size()) + " bytes, and it is not ASCII STL either");
  }
  info.filePoints = mesh.numberOfPoints();
  fanFallbackWarning(info);
  return finish(path, mesh, &info, true);
}

} // namespace volgrid
