// gmsh .msh reader (ASCII, versions 2.x and 4.x): triangles and quadrangles (physical or entity tags
// become patch ids); other element types are skipped.
#include "GmshReader.h"
#include "GmshPhysicalNames.h"
#include "SurfaceReaderSupport.h"

#include <algorithm>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
Status skipSection(Scanner& sc, std::string_view name)
{
  const std::string endTag = "$End" + std::string(name.substr(1));
  std::string_view tok;
  while (sc.next(tok))
  {
    if (tok == endTag)
    {
      return Status::success();
    }
  }
  return sc.error("section " + std::string(name) + " is not closed by " + endTag);
}

// $PhysicalNames: "dim tag \"name\"" lines; the names of 2D groups become patch names (the reader uses
// the physical tag as the patch id, and VolGrid's writer gives each entity its physical group's tag).
Status readPhysicalNames(Scanner& sc, SurfaceMesh& mesh)
{
  Status s = readGmshPhysicalNames(sc,
                                   [&](int64_t dim, int64_t tag, std::string name)
                                   {
                                     if (dim == 2)
                                       mesh.patchNames[static_cast<int32_t>(tag)] = std::move(name);
                                   });
  if (!s.ok())
  {
    return s;
  }
  std::string_view end;
  if (!sc.next(end) || end != "$EndPhysicalNames")
  {
    return sc.error("$PhysicalNames is not closed by $EndPhysicalNames");
  }
  return Status::success();
}
// The sections of one .msh file, read into `mesh` (nodes by tag, elements as polygons).
struct GmshSurfaceReader
{
  Scanner& sc;
  SurfaceMesh& mesh;
  SurfaceReadInfo& info;
  const int64_t limit;
  double version = 0;
  bool haveFormat = false;
  std::unordered_map<int64_t, int32_t> nodeIndex;
  std::vector<int32_t> loop, scratch;
  std::vector<std::string_view> toks;

  GmshSurfaceReader(Scanner& scanner, SurfaceMesh& out, SurfaceReadInfo& readInfo, int64_t countLimit)
    : sc(scanner)
    , mesh(out)
    , info(readInfo)
    , limit(countLimit)
  {
  }

  Status node(int64_t tag, int32_t& index)
  {
    auto it = nodeIndex.find(tag);
    if (it == nodeIndex.end())
    {
      return sc.error("element refers to unknown node " + std::to_string(tag));
    }
    index = it->second;
    return Status::success();
  }
  void addElement(int64_t, int32_t patch) // nodes already in loop
  {
    ++info.fileFaces;
    addPolygon(mesh, loop, patch, info, scratch);
  }

  // $MeshFormat: version, ASCII only.
  Status meshFormat()
  {
    Status s;
    int64_t fileType = 0, dataSize = 0;
    s = sc.readDouble(version, "the format version");
    if (s.ok())
    {
      s = sc.readInt(fileType, "the file type");
    }
    if (s.ok())
    {
      s = sc.readInt(dataSize, "the data size");
    }
    if (!s.ok())
    {
      return s;
    }
    if (fileType != 0)
    {
      return sc.error("binary .msh files are not supported (write ASCII with gmsh -format msh2 or msh4)");
    }
    if (version < 2.0 || version >= 5.0)
    {
      return sc.error("unsupported .msh version " + std::to_string(version) + " (2.x and 4.x are supported)");
    }
    if (version >= 3.0 && version < 4.0)
    {
      return sc.error("unsupported .msh version 3 (2.x and 4.x are supported)");
    }
    info.format = "gmsh " + std::string(version >= 4.0 ? (version >= 4.05 ? "4.1" : "4.0") : "2");
    haveFormat = true;
    return Status::success();
  }

  // $Nodes of a version 2 file: "tag x y z" lines.
  Status nodes2()
  {
    Status s;
    int64_t n;
    s = sc.readCount(n, "node count", limit);
    if (!s.ok())
    {
      return s;
    }
    nodeIndex.reserve(size_t(n));
    for (int64_t i = 0; i < n; ++i)
    {
      int64_t tag;
      double xyz[3];
      s = sc.readInt(tag, "a node tag");
      for (int k = 0; k < 3 && s.ok(); ++k)
      {
        s = sc.readDouble(xyz[k], "a node coordinate");
      }
      if (!s.ok())
      {
        return s;
      }
      nodeIndex[tag] = mesh.addPoint(xyz[0], xyz[1], xyz[2]);
    }
    return Status::success();
  }

  // $Nodes of a version 4 file: entity blocks (4.1: tags first, then coordinates).
  Status nodes4()
  {
    Status s;
    const bool v41 = version >= 4.05;
    int64_t nblocks, n, dummy;
    s = sc.readCount(nblocks, "entity block count", limit);
    if (s.ok())
    {
      s = sc.readCount(n, "node count", limit);
    }
    if (s.ok() && v41)
    {
      s = sc.readInt(dummy, "the minimum node tag");
      if (s.ok())
      {
        s = sc.readInt(dummy, "the maximum node tag");
      }
    }
    if (!s.ok())
    {
      return s;
    }
    nodeIndex.reserve(size_t(n));
    std::vector<int64_t> tags;
    for (int64_t b = 0; b < nblocks; ++b)
    {
      int64_t h[4];
      for (int k = 0; k < 4 && s.ok(); ++k)
      {
        s = sc.readInt(h[k], "a node block header value");
      }
      if (!s.ok())
      {
        return s;
      }
      const int64_t entityDim = v41 ? h[0] : h[1];
      const int64_t parametric = h[2];
      const int64_t count = h[3];
      if (count < 0 || count > limit)
      {
        return sc.error("bad node block size " + std::to_string(count));
      }
      const int64_t nparam = parametric ? std::max<int64_t>(entityDim, 0) : 0;
      if (v41)
      {
        tags.resize(size_t(count));
        for (int64_t i = 0; i < count && s.ok(); ++i)
        {
          s = sc.readInt(tags[i], "a node tag");
        }
      }
      for (int64_t i = 0; i < count && s.ok(); ++i)
      {
        int64_t tag = 0;
        if (!v41)
        {
          s = sc.readInt(tag, "a node tag");
        }
        else
        {
          tag = tags[i];
        }
        double xyz[3], uvw;
        for (int k = 0; k < 3 && s.ok(); ++k)
        {
          s = sc.readDouble(xyz[k], "a node coordinate");
        }
        for (int64_t k = 0; k < nparam && s.ok(); ++k)
        {
          s = sc.readDouble(uvw, "a parametric coordinate");
        }
        if (s.ok())
        {
          nodeIndex[tag] = mesh.addPoint(xyz[0], xyz[1], xyz[2]);
        }
      }
      if (!s.ok())
      {
        return s;
      }
    }
    return Status::success();
  }

  // $Elements of a version 2 file: "id type ntags tags... nodes..." lines.
  Status elements2()
  {
    Status s;
    int64_t n;
    s = sc.readCount(n, "element count", limit);
    if (!s.ok())
    {
      return s;
    }
    sc.skipLine();
    for (int64_t e = 0; e < n; ++e)
    {
      if (!sc.nextLine(toks))
      {
        return sc.error("unexpected end of file: read " + std::to_string(e) + " of " + std::to_string(n) + " elements");
      }
      int64_t id, type, ntags;
      if (toks.size() < 3 || !parseInt(toks[0], id) || !parseInt(toks[1], type) || !parseInt(toks[2], ntags) ||
          ntags < 0 || static_cast<int64_t>(toks.size()) < 3 + ntags)
      {
        return sc.error("malformed element line");
      }
      if (type != 2 && type != 3)
      {
        ++info.skippedElements;
        continue;
      }
      const int nc = type == 2 ? 3 : 4;
      if (static_cast<int64_t>(toks.size()) < 3 + ntags + nc)
      {
        return sc.error("element " + std::to_string(id) + ": too few node tags");
      }
      int64_t physical = 0, elementary = 0;
      if (ntags > 0)
      {
        parseInt(toks[3], physical);
      }
      if (ntags > 1)
      {
        parseInt(toks[4], elementary);
      }
      loop.clear();
      for (int k = 0; k < nc; ++k)
      {
        int64_t tag;
        int32_t index;
        if (!parseInt(toks[3 + ntags + k], tag))
        {
          return sc.error("element " + std::to_string(id) + ": bad node tag");
        }
        s = node(tag, index);
        if (!s.ok())
        {
          return s;
        }
        loop.push_back(index);
      }
      addElement(type, static_cast<int32_t>(physical != 0 ? physical : elementary));
    }
    return Status::success();
  }

  // $Elements of a version 4 file: entity blocks of "tag nodes..." lines.
  Status elements4()
  {
    Status s;
    const bool v41 = version >= 4.05;
    int64_t nblocks, n, dummy;
    s = sc.readCount(nblocks, "element block count", limit);
    if (s.ok())
    {
      s = sc.readCount(n, "element count", limit);
    }
    if (s.ok() && v41)
    {
      s = sc.readInt(dummy, "the minimum element tag");
      if (s.ok())
      {
        s = sc.readInt(dummy, "the maximum element tag");
      }
    }
    if (!s.ok())
    {
      return s;
    }
    for (int64_t b = 0; b < nblocks; ++b)
    {
      int64_t h[4];
      for (int k = 0; k < 4 && s.ok(); ++k)
      {
        s = sc.readInt(h[k], "an element block header value");
      }
      if (!s.ok())
      {
        return s;
      }
      const int64_t entityTag = v41 ? h[1] : h[0];
      const int64_t type = h[2];
      const int64_t count = h[3];
      if (count < 0 || count > limit)
      {
        return sc.error("bad element block size " + std::to_string(count));
      }
      sc.skipLine();
      for (int64_t e = 0; e < count; ++e)
      {
        if (!sc.nextLine(toks))
        {
          return sc.error("unexpected end of file in an element block");
        }
        if (type != 2 && type != 3)
        {
          ++info.skippedElements;
          continue;
        }
        const size_t nc = type == 2 ? 3 : 4;
        if (toks.size() < nc + 1)
        {
          return sc.error("element with too few node tags");
        }
        loop.clear();
        for (size_t k = 0; k < nc; ++k)
        {
          int64_t tag;
          int32_t index;
          if (!parseInt(toks[1 + k], tag))
          {
            return sc.error("bad node tag '" + std::string(toks[1 + k]) + "'");
          }
          s = node(tag, index);
          if (!s.ok())
          {
            return s;
          }
          loop.push_back(index);
        }
        addElement(type, static_cast<int32_t>(entityTag));
      }
    }
    return Status::success();
  }
};

} // namespace

Status readGmsh(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions& options)
{
  ReadStart start(path, mesh, infoOut, "gmsh");
  if (!start.loaded.ok())
    return start.loaded;
  Status s;
  Scanner sc(start.text, path, false);
  GmshSurfaceReader r(sc, mesh, start.info, countLimit(start.text));
  std::string_view tok;
  while (sc.next(tok))
  {
    if (tok.empty() || tok[0] != '$')
    {
      return sc.error("expected a section tag such as $Nodes, got '" + std::string(tok.substr(0, 40)) + "'");
    }
    if (tok == "$MeshFormat")
      s = r.meshFormat();
    else if (tok == "$PhysicalNames")
    {
      s = readPhysicalNames(sc, mesh);
      if (!s.ok())
        return s;
      continue; // readPhysicalNames reads the end tag
    }
    else if (tok == "$Nodes" || tok == "$Elements")
    {
      if (!r.haveFormat)
        return sc.error(std::string(tok) + " before $MeshFormat");
      if (tok == "$Nodes")
        s = r.version < 3.0 ? r.nodes2() : r.nodes4();
      else
        s = r.version < 3.0 ? r.elements2() : r.elements4();
    }
    if (!s.ok())
      return s;
    s = skipSection(sc, tok);
    if (!s.ok())
      return s;
  }
  start.info.filePoints = mesh.numberOfPoints();
  fanFallbackWarning(start.info);
  return finish(path, mesh, &start.info, options.mergeCoincidentPoints);
}

} // namespace volgrid
