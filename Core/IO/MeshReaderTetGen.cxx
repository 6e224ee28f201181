// TetGen mesh reader: STEM.node, STEM.ele and (when present) STEM.face, numbered from 0 or 1 as the
// first node says. A tet's first attribute (TetGen -A, or VolGrid's writer) is its region, else 1; a
// face's boundary marker is its patch, else 1. The format has no names.
#include "MeshReader.h"
#include "MeshWriter.h"
#include "SurfaceReaderSupport.h"

#include <filesystem>

namespace volgrid
{

using namespace detail;

namespace
{
// Reads `count` records "id v1 .. vn [extra...]" where the header gave `extras` values after the ids;
// ids are shifted by `first`. The first extra value (if any) goes to `labels` (default 1).
Status readRecords(Scanner& sc, int64_t count, int nv, int64_t extras, int64_t first, int64_t numPoints,
                   std::vector<int32_t>& cells, std::vector<int32_t>& labels)
{
  for (int64_t e = 0; e < count; ++e)
  {
    int64_t id = 0;
    Status s = sc.readInt(id, "a record id");
    for (int k = 0; k < nv && s.ok(); ++k)
    {
      int64_t v = 0;
      s = sc.readInt(v, "a node id");
      if (s.ok() && (v - first < 0 || v - first >= numPoints))
        return sc.error("node id " + std::to_string(v) + " out of range");
      cells.push_back(static_cast<int32_t>(v - first));
    }
    int32_t label = 1;
    for (int64_t k = 0; k < extras && s.ok(); ++k)
    {
      double x = 0;
      s = sc.readDouble(x, "an attribute or marker");
      if (k == 0)
        label = static_cast<int32_t>(x);
    }
    if (!s.ok())
      return s;
    labels.push_back(label);
  }
  return Status::success();
}
} // namespace

Status readTetGenVolume(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  const std::string stem = tetgenStem(path);
  std::string node, ele, face;
  Status s = loadFile(stem + ".node", node);
  if (s.ok())
    s = loadFile(stem + ".ele", ele);
  if (!s.ok())
    return s;
  Scanner ns(node, stem + ".node", true);
  int64_t h[4] = { 0, 0, 0, 0 }, first = 0;
  for (int k = 0; k < 4 && s.ok(); ++k)
    s = ns.readInt(h[k], "the .node header");
  if (s.ok() && (h[1] != 3 || h[0] < 0 || h[0] > countLimit(node)))
    return ns.error("expected '<points> 3 <attributes> <markers>'");
  for (int64_t i = 0; i < h[0] && s.ok(); ++i)
  {
    int64_t id = 0;
    s = ns.readInt(id, "a node id");
    if (i == 0)
      first = id;
    for (int64_t k = 0; k < 3 + h[2] + (h[3] ? 1 : 0) && s.ok(); ++k)
    {
      double x = 0;
      s = ns.readDouble(x, "a node value");
      if (k < 3)
        mesh.points.push_back(x);
    }
  }
  Scanner es(ele, stem + ".ele", true);
  int64_t eh[3] = { 0, 0, 0 };
  for (int k = 0; k < 3 && s.ok(); ++k)
    s = es.readInt(eh[k], "the .ele header");
  if (s.ok() && (eh[1] != 4 || eh[0] < 0 || eh[0] > countLimit(ele)))
    return es.error("expected '<tets> 4 <attributes>' (linear tets only)");
  if (s.ok())
    s = readRecords(es, eh[0], 4, eh[2], first, mesh.numberOfPoints(), mesh.tets, mesh.tetRegion);
  if (s.ok() && std::filesystem::exists(stem + ".face"))
  {
    s = loadFile(stem + ".face", face);
    Scanner fs(face, stem + ".face", true);
    int64_t fh[2] = { 0, 0 };
    for (int k = 0; k < 2 && s.ok(); ++k)
      s = fs.readInt(fh[k], "the .face header");
    if (s.ok() && (fh[0] < 0 || fh[0] > countLimit(face)))
      return fs.error("bad face count");
    if (s.ok())
      s = readRecords(fs, fh[0], 3, fh[1] ? 1 : 0, first, mesh.numberOfPoints(), mesh.triangles, mesh.trianglePatch);
  }
  if (s.ok() && mesh.tets.empty())
    return readError(path, 0, "no tetrahedra: not a volume mesh");
  return s;
}

} // namespace volgrid
