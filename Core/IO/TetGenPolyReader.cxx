// TetGen .poly / .smesh reader: polygon facets triangulated by ear clipping in the facet plane (facet
// markers become patch ids); a .poly facet with several polygons or hole points is one planar region
// with inner boundaries and holes (triangulateFacet). The nodes come from the sibling .node file when
// the node list is empty.
#include "TetGenPolyReader.h"
#include "GzipFile.h"
#include "PolygonTriangulation.h"
#include "SurfaceReaderSupport.h"

#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
// Reads a node list (header line already tokenised in `header`). Returns the index base.
Status readTetGenNodes(Scanner& sc, const std::vector<std::string_view>& header, SurfaceMesh& mesh, int64_t limit,
                       int64_t& base)
{
  int64_t n = 0, dim = 3, nattr = 0, nbm = 0;
  if (!parseInt(header[0], n) || n < 0 || n > limit)
  {
    return sc.error("bad node count '" + std::string(header[0]) + "'");
  }
  if (header.size() > 1 && (!parseInt(header[1], dim) || dim != 3))
  {
    return sc.error("only 3D node lists are supported");
  }
  if (header.size() > 2 && (!parseInt(header[2], nattr) || nattr < 0))
  {
    return sc.error("bad attribute count");
  }
  if (header.size() > 3 && (!parseInt(header[3], nbm) || nbm < 0))
  {
    return sc.error("bad boundary-marker flag");
  }
  std::vector<std::string_view> toks;
  mesh.points.reserve(3 * size_t(n));
  for (int64_t i = 0; i < n; ++i)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(n) + " nodes");
    }
    int64_t id = 0;
    double xyz[3];
    if (toks.size() < 4 || !parseInt(toks[0], id))
    {
      return sc.error("node " + std::to_string(i) + ": expected 'index x y z'");
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(toks[1 + k], xyz[k]))
      {
        return sc.error("node " + std::to_string(id) + ": bad coordinate '" + std::string(toks[1 + k]) + "'");
      }
    }
    if (i == 0)
    {
      // TetGen numbers nodes from 0 or 1 (and base + count must not overflow).
      if (id != 0 && id != 1)
      {
        return sc.error("the first node is numbered " + std::to_string(id) + "; TetGen numbers nodes from 0 or 1");
      }
      base = id;
    }
    else if (id != base + i)
    {
      return sc.error("node indices must be consecutive: expected " + std::to_string(base + i) + ", got " +
                      std::to_string(id));
    }
    mesh.addPoint(xyz[0], xyz[1], xyz[2]);
  }
  return Status::success();
}

Status readPolygonLine(Scanner& sc, const std::vector<std::string_view>& toks, int64_t base, int64_t nv,
                       std::vector<int32_t>& loop, size_t& used)
{
  int64_t nc = 0;
  if (!parseInt(toks[0], nc) || nc < 0)
  {
    return sc.error("bad polygon corner count '" + std::string(toks[0]) + "'");
  }
  if (nc >= static_cast<int64_t>(toks.size())) // not toks.size() < nc + 1: nc may be INT64_MAX
  {
    return sc.error("polygon with " + std::to_string(nc) + " corners lists fewer ids");
  }
  loop.clear();
  for (int64_t k = 0; k < nc; ++k)
  {
    int64_t id = 0;
    if (!parseInt(toks[1 + k], id) || id < base || id >= base + nv)
    {
      return sc.error("polygon corner '" + std::string(toks[1 + k]) + "' is not a node index in [" +
                      std::to_string(base) + "," + std::to_string(base + nv - 1) + "]");
    }
    loop.push_back(static_cast<int32_t>(id - base));
  }
  used = static_cast<size_t>(nc + 1);
  return Status::success();
}

// The nodes from the sibling file name.node (or name.node.gz, the compressed one first when the .poly
// itself is compressed), for a .poly whose node list is empty. `line` is the .poly's line, for messages.
Status readSiblingNodes(const std::string& path, int64_t line, SurfaceMesh& mesh, int64_t& base)
{
  std::string nodeText;
  const std::string inner = stripGzipSuffix(path);
  const std::string plainNode = inner.substr(0, inner.find_last_of('.')) + ".node";
  const std::string nodeCandidates[2] = { isGzipPath(path) ? plainNode + ".gz" : plainNode,
                                          isGzipPath(path) ? plainNode : plainNode + ".gz" };
  std::string nodePath = nodeCandidates[0];
  if (!std::ifstream(nodePath) && std::ifstream(nodeCandidates[1]))
  {
    nodePath = nodeCandidates[1];
  }
  if (!loadFile(nodePath, nodeText).ok())
  {
    return readError(path, line, "the node list is empty and " + nodePath + " cannot be read");
  }
  Scanner nsc(nodeText, nodePath, true);
  std::vector<std::string_view> nh;
  if (!nsc.nextLine(nh))
  {
    return readError(nodePath, 0, "empty .node file");
  }
  return readTetGenNodes(nsc, nh, mesh, countLimit(nodeText), base);
}

// What the facet readers share: the scanner on the facet list, the nodes' index base and count.
struct FacetList
{
  Scanner& sc;
  SurfaceMesh& mesh;
  SurfaceReadInfo& info;
  int64_t base, nv, limit;
  bool hasMarkers;
  std::vector<int32_t> loop, scratch;
};

// One .smesh facet (its line in `toks`): a polygon and an optional marker (else the facet's number).
Status readSmeshFacet(FacetList& fl, const std::vector<std::string_view>& toks, int64_t f)
{
  size_t used = 0;
  const Status s = readPolygonLine(fl.sc, toks, fl.base, fl.nv, fl.loop, used);
  if (!s.ok())
  {
    return s;
  }
  int64_t marker = -1;
  if (fl.hasMarkers && toks.size() > used)
  {
    parseInt(toks[used], marker);
  }
  ++fl.info.fileFaces;
  if (fl.loop.size() < 3)
  {
    ++fl.info.skippedElements;
    return Status::success();
  }
  addPolygon(fl.mesh, fl.loop, static_cast<int32_t>(fl.hasMarkers ? marker : f), fl.info, fl.scratch);
  return Status::success();
}

// The polygons and hole points of .poly facet f after its header line; fails on a malformed line.
Status readPolyFacetBody(FacetList& fl, int64_t f, int64_t npoly, int64_t nholes,
                         std::vector<std::vector<int32_t>>& polygons, std::vector<double>& holes)
{
  std::vector<std::string_view> toks;
  for (int64_t p = 0; p < npoly; ++p)
  {
    if (!fl.sc.nextLine(toks))
    {
      return fl.sc.error("unexpected end of file in facet " + std::to_string(f));
    }
    size_t used = 0;
    const Status s = readPolygonLine(fl.sc, toks, fl.base, fl.nv, fl.loop, used);
    if (!s.ok())
    {
      return s;
    }
    polygons.push_back(fl.loop);
  }
  for (int64_t h = 0; h < nholes; ++h)
  {
    if (!fl.sc.nextLine(toks) || toks.size() < 4)
    {
      return fl.sc.error("facet " + std::to_string(f) + ": expected a hole point 'index x y z'");
    }
    for (int k = 1; k <= 3; ++k)
    {
      double v;
      if (!parseDouble(toks[k], v))
      {
        return fl.sc.error("facet " + std::to_string(f) + ": bad hole coordinate");
      }
      holes.push_back(v);
    }
  }
  return Status::success();
}

// Adds .poly facet f: a single polygon as one polygon face, several polygons or hole points as one
// planar region with inner boundaries and holes (triangulateFacet); segments and points are skipped.
void addPolyFacet(FacetList& fl, int64_t f, int64_t marker, const std::vector<std::vector<int32_t>>& polygons,
                  const std::vector<double>& holes)
{
  SurfaceReadInfo& info = fl.info;
  ++info.fileFaces;
  int64_t areaPolygons = 0;
  for (const auto& poly : polygons)
  {
    if (poly.size() < 3)
    {
      ++info.skippedElements; // segments and isolated points inside a facet
    }
    else
    {
      ++areaPolygons;
    }
  }
  if (areaPolygons == 1 && holes.empty())
  {
    for (const auto& poly : polygons)
    {
      if (poly.size() >= 3)
      {
        addPolygon(fl.mesh, poly, static_cast<int32_t>(marker), info, fl.scratch);
      }
    }
    return;
  }
  ++info.polygonFaces;
  fl.scratch.clear();
  FacetTriangulationInfo facet;
  if (!triangulateFacet(fl.mesh.points, polygons, holes, fl.scratch, &facet))
  {
    info.warnings.push_back("facet " + std::to_string(f) + ": " + std::to_string(facet.failures) +
                            " region(s) could not be triangulated exactly (a hole not bridged or a fan fallback)");
  }
  info.holeRegions += facet.holeRegions;
  if (facet.unusedHolePoints > 0)
  {
    info.warnings.push_back("facet " + std::to_string(f) + ": " + std::to_string(facet.unusedHolePoints) +
                            " hole point(s) outside all of its polygons ignored");
  }
  for (size_t i = 0; i + 2 < fl.scratch.size(); i += 3)
  {
    fl.mesh.addTriangle(fl.scratch[i], fl.scratch[i + 1], fl.scratch[i + 2], static_cast<int32_t>(marker));
  }
}

// One .poly facet (its header "npolygons [nholes] [marker]" in `toks`), its polygons and hole points.
Status readPolyFacet(FacetList& fl, const std::vector<std::string_view>& toks, int64_t f)
{
  int64_t npoly = 0, nholes = 0, marker = f;
  if (!parseInt(toks[0], npoly) || npoly < 0 || npoly > fl.limit)
  {
    return fl.sc.error("facet " + std::to_string(f) + ": bad polygon count '" + std::string(toks[0]) + "'");
  }
  if (toks.size() > 1 && (!parseInt(toks[1], nholes) || nholes < 0 || nholes > fl.limit))
  {
    return fl.sc.error("facet " + std::to_string(f) + ": bad hole count '" + std::string(toks[1]) + "'");
  }
  if (fl.hasMarkers && toks.size() > 2)
  {
    parseInt(toks[2], marker);
  }
  std::vector<std::vector<int32_t>> polygons;
  std::vector<double> holes;
  const Status s = readPolyFacetBody(fl, f, npoly, nholes, polygons, holes);
  if (s.ok())
  {
    addPolyFacet(fl, f, marker, polygons, holes);
  }
  return s;
}
} // namespace

Status readTetGen(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut,
                  const SurfaceReadOptions& options)
{
  const bool smesh = lowerExtension(path) == "smesh";
  ReadStart start(path, mesh, infoOut, smesh ? "TetGen smesh" : "TetGen poly");
  if (!start.loaded.ok())
    return start.loaded;
  SurfaceReadInfo& info = start.info;
  const std::string& text = start.text;
  Scanner sc(text, path, true);
  const int64_t limit = countLimit(text);
  std::vector<std::string_view> toks;
  if (!sc.nextLine(toks))
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  int64_t base = 0;
  int64_t nodeCount = 0;
  if (!parseInt(toks[0], nodeCount))
  {
    return sc.error("expected the node count, got '" + std::string(toks[0]) + "'");
  }
  Status s =
    nodeCount == 0 ? readSiblingNodes(path, sc.line(), mesh, base) : readTetGenNodes(sc, toks, mesh, limit, base);
  if (!s.ok())
  {
    return s;
  }
  const int64_t nv = mesh.numberOfPoints();
  info.filePoints = nv;
  if (!sc.nextLine(toks))
  {
    return sc.error("unexpected end of file: the facet list is missing");
  }
  int64_t nf = 0, hasMarkers = 0;
  if (!parseInt(toks[0], nf) || nf < 0 || nf > limit)
  {
    return sc.error("bad facet count '" + std::string(toks[0]) + "'");
  }
  if (toks.size() > 1 && !parseInt(toks[1], hasMarkers))
  {
    return sc.error("bad boundary-marker flag '" + std::string(toks[1]) + "'");
  }
  FacetList fl{ sc, mesh, info, base, nv, limit, hasMarkers != 0, {}, {} };
  for (int64_t f = 0; f < nf; ++f)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(f) + " of " + std::to_string(nf) + " facets");
    }
    s = smesh ? readSmeshFacet(fl, toks, f) : readPolyFacet(fl, toks, f);
    if (!s.ok())
    {
      return s;
    }
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

} // namespace volgrid
