// OFF reader: OFF/COFF/NOFF/CNOFF/STOFF (ASCII; normals, colours and texture coordinates ignored),
// polygons triangulated by ear clipping, faces with fewer than 3 corners skipped.
#include "OffReader.h"
#include "SurfaceReaderSupport.h"

#include <string>
#include <string_view>
#include <vector>

namespace volgrid
{

using namespace detail;

namespace
{
// The header keyword [ST][C][N]OFF in toks[0] (normals, colours, texture coordinates are skipped with
// the rest of each line); names the format in `info`. Binary and 4D/nD OFF are refused.
Status readOffKeyword(const Scanner& sc, const std::vector<std::string_view>& toks, SurfaceReadInfo& info)
{
  const std::string_view key = toks[0];
  if (key.size() >= 3 && key.substr(key.size() - 3) == "OFF")
  {
    std::string_view prefix = key.substr(0, key.size() - 3);
    if (prefix.size() >= 2 && prefix.substr(0, 2) == "ST")
    {
      prefix.remove_prefix(2);
    }
    if (!prefix.empty() && prefix[0] == 'C')
    {
      prefix.remove_prefix(1);
    }
    if (!prefix.empty() && prefix[0] == 'N')
    {
      prefix.remove_prefix(1);
    }
    if (!prefix.empty())
    {
      return sc.error("unsupported OFF variant '" + std::string(key) + "' (4D or n-dimensional OFF)");
    }
    info.format = std::string(key);
    return Status::success();
  }
  if (key == "OFF_BINARY" || (toks.size() > 1 && toks[1] == "BINARY"))
  {
    return sc.error("binary OFF is not supported");
  }
  return sc.error("not an OFF file: the first line must be the header 'OFF' (or COFF, NOFF, STOFF ...), got '" +
                  std::string(key.substr(0, 40)) + "'");
}

// The counts "nv nf [ne]" after the keyword (toks[1..]) or on the following line(s); bounded by `limit`.
Status readOffCounts(Scanner& sc, std::vector<std::string_view>& toks, int64_t limit, int64_t& nv, int64_t& nf)
{
  std::vector<int64_t> counts;
  size_t first = 1;
  while (counts.size() < 2)
  {
    if (first == 0 && !sc.nextLine(toks))
    {
      return sc.error("unexpected end of file in the OFF header");
    }
    for (size_t i = first; i < toks.size() && counts.size() < 3; ++i)
    {
      int64_t v = 0;
      if (!parseInt(toks[i], v))
      {
        return sc.error("expected vertex/face/edge counts, got '" + std::string(toks[i]) + "'");
      }
      counts.push_back(v);
    }
    first = 0;
  }
  nv = counts[0];
  nf = counts[1];
  if (nv < 0 || nf < 0 || nv > limit || nf > limit)
  {
    return sc.error("invalid counts in the OFF header");
  }
  return Status::success();
}

// nv vertex lines "x y z [anything]" into the mesh.
Status readOffVertices(Scanner& sc, int64_t nv, SurfaceMesh& mesh)
{
  std::vector<std::string_view> toks;
  mesh.points.reserve(3 * size_t(nv));
  for (int64_t i = 0; i < nv; ++i)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    }
    if (toks.size() < 3)
    {
      return sc.error("vertex " + std::to_string(i) + " has fewer than 3 coordinates");
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(toks[k], xyz[k]))
      {
        return sc.error("vertex " + std::to_string(i) + ": bad coordinate '" + std::string(toks[k]) + "'");
      }
    }
    mesh.addPoint(xyz[0], xyz[1], xyz[2]);
  }
  return Status::success();
}

// nf face lines "n id1 .. idn [colour]": polygons triangulated, faces of fewer than 3 corners counted
// as skipped.
Status readOffFaces(Scanner& sc, int64_t nv, int64_t nf, SurfaceMesh& mesh, SurfaceReadInfo& info)
{
  std::vector<std::string_view> toks;
  std::vector<int32_t> loop, scratch;
  mesh.triangles.reserve(3 * size_t(nf));
  for (int64_t f = 0; f < nf; ++f)
  {
    if (!sc.nextLine(toks))
    {
      return sc.error("unexpected end of file: read " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    }
    int64_t nc = 0;
    if (!parseInt(toks[0], nc) || nc < 0)
    {
      return sc.error("face " + std::to_string(f) + ": bad corner count '" + std::string(toks[0]) + "'");
    }
    if (nc >= static_cast<int64_t>(toks.size())) // not toks.size() < nc + 1: nc may be INT64_MAX
    {
      return sc.error("face " + std::to_string(f) + ": expected " + std::to_string(nc) + " vertex ids");
    }
    loop.clear();
    for (int64_t k = 0; k < nc; ++k)
    {
      int64_t id = 0;
      if (!parseInt(toks[1 + k], id) || id < 0 || id >= nv)
      {
        return sc.error("face " + std::to_string(f) + ": vertex id '" + std::string(toks[1 + k]) +
                        "' out of range [0," + std::to_string(nv) + ")");
      }
      loop.push_back(static_cast<int32_t>(id));
    }
    ++info.fileFaces;
    if (nc < 3)
    {
      info.skippedElements++;
      continue;
    }
    addPolygon(mesh, loop, -1, info, scratch);
  }
  return Status::success();
}
} // namespace

Status readOFF(const std::string& path, SurfaceMesh& mesh, SurfaceReadInfo* infoOut, const SurfaceReadOptions& options)
{
  ReadStart start(path, mesh, infoOut, "OFF");
  if (!start.loaded.ok())
    return start.loaded;
  SurfaceReadInfo& info = start.info;
  Scanner sc(start.text, path, true);
  std::vector<std::string_view> toks;
  if (!sc.nextLine(toks))
  {
    return Status::failure(ErrorKind::EmptyInput, path + ": empty file");
  }
  int64_t nv = 0, nf = 0;
  Status s = readOffKeyword(sc, toks, info);
  if (s.ok())
    s = readOffCounts(sc, toks, countLimit(start.text), nv, nf);
  if (s.ok())
    s = readOffVertices(sc, nv, mesh);
  if (!s.ok())
    return s;
  info.filePoints = nv;
  s = readOffFaces(sc, nv, nf, mesh, info);
  if (!s.ok())
    return s;
  if (info.skippedElements > 0)
  {
    info.warnings.push_back(std::to_string(info.skippedElements) + " face(s) with fewer than 3 vertices skipped");
  }
  fanFallbackWarning(info);
  return finish(path, mesh, &info, options.mergeCoincidentPoints);
}

} // namespace volgrid
