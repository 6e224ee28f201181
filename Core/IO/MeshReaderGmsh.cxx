// gmsh .msh volume reader (ASCII 2.2 and 4.1): nodes, triangles (type 2) and tets (type 4); other
// elements are skipped. Labels: a 2.2 element's physical tag (its elementary tag when 0); in 4.1 the first
// physical tag of the element's entity (from $Entities), else the entity tag. $PhysicalNames names the
// patches (dim 2) and regions (dim 3).
#include "GmshPhysicalNames.h"
#include "MeshReader.h"
#include "SurfaceReaderSupport.h"

#include <map>
#include <string_view>
#include <unordered_map>

namespace volgrid
{

using namespace detail;

namespace
{
struct GmshState
{
  double version = 0;
  std::map<std::pair<int64_t, int64_t>, int64_t> entityPhysical; // (dim, entity) -> first physical tag
  std::unordered_map<int64_t, int32_t> nodeIndex;
};

Status readInts(Scanner& sc, int64_t* v, int n, const char* what)
{
  Status s = Status::success();
  for (int k = 0; k < n && s.ok(); ++k)
    s = sc.readInt(v[k], what);
  return s;
}

Status readPhysicalNames(Scanner& sc, SolverMesh& mesh)
{
  return readGmshPhysicalNames(sc,
                               [&](int64_t dim, int64_t tag, std::string name) {
                                 (dim == 2 ? mesh.patchNames : mesh.regionNames)[static_cast<int32_t>(tag)] =
                                   std::move(name);
                               });
}

// 4.1 $Entities: the first physical tag of each surface and volume.
Status readEntities(Scanner& sc, GmshState& st)
{
  int64_t counts[4];
  Status s = readInts(sc, counts, 4, "an entity count");
  for (int dim = 0; dim < 4 && s.ok(); ++dim)
    for (int64_t e = 0; e < counts[dim] && s.ok(); ++e)
    {
      int64_t tag = 0, nphys = 0;
      double box[6];
      s = sc.readInt(tag, "an entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6) && s.ok(); ++k)
        s = sc.readDouble(box[k], "an entity bounding box");
      if (s.ok())
        s = sc.readCount(nphys, "a physical tag count", 1 << 20);
      for (int64_t p = 0; p < nphys && s.ok(); ++p)
      {
        int64_t phys = 0;
        s = sc.readInt(phys, "a physical tag");
        if (s.ok() && p == 0)
          st.entityPhysical[{ dim, tag }] = phys < 0 ? -phys : phys;
      }
      int64_t nbound = 0;
      if (s.ok() && dim > 0)
        s = sc.readCount(nbound, "a bounding entity count", 1 << 24);
      for (int64_t b = 0; b < nbound && s.ok(); ++b)
        s = sc.readInt(tag, "a bounding entity tag");
    }
  return s;
}

Status addNode(Scanner& sc, SolverMesh& mesh, GmshState& st, int64_t tag)
{
  double xyz[3];
  Status s = Status::success();
  for (int k = 0; k < 3 && s.ok(); ++k)
    s = sc.readDouble(xyz[k], "a node coordinate");
  if (!s.ok())
    return s;
  st.nodeIndex[tag] = static_cast<int32_t>(mesh.numberOfPoints());
  mesh.points.insert(mesh.points.end(), xyz, xyz + 3);
  return s;
}

Status readNodes(Scanner& sc, SolverMesh& mesh, GmshState& st, int64_t limit)
{
  int64_t h[4] = { 1, 0, 0, 0 };
  Status s = st.version < 4 ? sc.readCount(h[1], "the node count", limit) : readInts(sc, h, 4, "the node header");
  if (st.version < 4)
  {
    for (int64_t i = 0; i < h[1] && s.ok(); ++i)
    {
      int64_t tag = 0;
      s = sc.readInt(tag, "a node tag");
      if (s.ok())
        s = addNode(sc, mesh, st, tag);
    }
    return s;
  }
  for (int64_t b = 0; b < h[0] && s.ok(); ++b)
  {
    int64_t bh[4];
    s = readInts(sc, bh, 4, "a node block header");
    if (s.ok() && bh[2] != 0)
      return sc.error("parametric nodes are not supported");
    std::vector<int64_t> tags(static_cast<size_t>(s.ok() ? std::max<int64_t>(0, std::min(bh[3], limit)) : 0));
    for (int64_t& t : tags)
      if (s.ok())
        s = sc.readInt(t, "a node tag");
    for (int64_t t : tags)
      if (s.ok())
        s = addNode(sc, mesh, st, t);
  }
  return s;
}

// One element of `type` with label `label`: its node tags follow in the scanner.
Status addElement(Scanner& sc, SolverMesh& mesh, GmshState& st, int64_t type, int32_t label, int64_t nodes)
{
  int32_t ids[6];
  for (int64_t k = 0; k < nodes; ++k)
  {
    int64_t tag = 0;
    Status s = sc.readInt(tag, "an element node tag");
    if (!s.ok())
      return s;
    const auto it = st.nodeIndex.find(tag);
    if (it == st.nodeIndex.end())
      return sc.error("element refers to unknown node " + std::to_string(tag));
    if (k < 6)
      ids[k] = it->second;
  }
  if (type == 2)
  {
    mesh.triangles.insert(mesh.triangles.end(), ids, ids + 3);
    mesh.trianglePatch.push_back(label);
  }
  else if (type == 4)
  {
    mesh.tets.insert(mesh.tets.end(), ids, ids + 4);
    mesh.tetRegion.push_back(label);
  }
  else if (type == 3) // boundary quads, prisms and pyramids: SolverMesh's order is gmsh's
  {
    mesh.quads.insert(mesh.quads.end(), ids, ids + 4);
    mesh.quadPatch.push_back(label);
  }
  else if (type == 6)
  {
    mesh.prisms.insert(mesh.prisms.end(), ids, ids + 6);
    mesh.prismRegion.push_back(label);
  }
  else if (type == 7)
  {
    mesh.pyramids.insert(mesh.pyramids.end(), ids, ids + 5);
    mesh.pyramidRegion.push_back(label);
  }
  return Status::success();
}

// Nodes per element type for the types VolGrid may meet (others are refused with their number).
int64_t nodesOf(int64_t type)
{
  switch (type)
  {
    case 1:
      return 2;
    case 2:
      return 3;
    case 3:
      return 4;
    case 4:
      return 4;
    case 6:
      return 6;
    case 7:
      return 5;
    case 15:
      return 1;
    default:
      return -1;
  }
}

Status readElements(Scanner& sc, SolverMesh& mesh, GmshState& st, int64_t limit)
{
  int64_t h[4] = { 0, 0, 0, 0 };
  Status s = st.version < 4 ? sc.readCount(h[0], "the element count", limit) : readInts(sc, h, 4, "the element header");
  for (int64_t b = 0; b < h[0] && s.ok(); ++b)
  {
    int64_t eh[4] = { 0, 0, 0, 1 }; // 4.1 block: dim, entity, type, count; 2.2: one element per "block"
    if (st.version < 4)
    {
      // "id type ntags tag... node...": physical tag first, then the elementary one.
      int64_t id = 0, ntags = 0, tags[2] = { 0, 0 };
      s = sc.readInt(id, "an element id");
      if (s.ok())
        s = sc.readInt(eh[2], "an element type");
      if (s.ok())
        s = sc.readCount(ntags, "an element tag count", 64);
      for (int64_t k = 0; k < ntags && s.ok(); ++k)
      {
        int64_t v = 0;
        s = sc.readInt(v, "an element tag");
        if (k < 2)
          tags[k] = v;
      }
      eh[0] = eh[2] == 4 || eh[2] == 6 || eh[2] == 7 ? 3 : 2;
      eh[1] = tags[0] != 0 ? tags[0] : tags[1];
    }
    else
      s = readInts(sc, eh, 4, "an element block header");
    const int64_t nodes = nodesOf(eh[2]);
    if (s.ok() && nodes < 0)
      return sc.error("element type " + std::to_string(eh[2]) +
                      " is not supported (triangles, quads, tets, prisms and pyramids only)");
    const auto phys = st.entityPhysical.find({ eh[0], eh[1] });
    const int32_t label = static_cast<int32_t>(phys != st.entityPhysical.end() ? phys->second : eh[1]);
    for (int64_t e = 0; e < eh[3] && s.ok(); ++e)
    {
      int64_t tag = 0;
      if (st.version >= 4)
        s = sc.readInt(tag, "an element tag");
      if (s.ok())
        s = addElement(sc, mesh, st, eh[2], label, nodes);
    }
  }
  return s;
}
} // namespace

Status readGmshVolume(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  std::string text;
  Status s = loadFile(path, text);
  if (!s.ok())
    return s;
  Scanner sc(text, path, false);
  const int64_t limit = countLimit(text);
  GmshState st;
  std::string_view tok;
  while (s.ok() && sc.next(tok))
  {
    if (tok == "$MeshFormat")
    {
      int64_t fileType = 0, dataSize = 0;
      s = sc.readDouble(st.version, "the format version");
      if (s.ok())
        s = sc.readInt(fileType, "the file type");
      if (s.ok())
        s = sc.readInt(dataSize, "the data size");
      if (s.ok() && (fileType != 0 || !((st.version >= 2 && st.version < 3) || (st.version >= 4.1 && st.version < 5))))
        return sc.error("only ASCII gmsh 2.2 and 4.1 volume meshes are read");
    }
    else if (tok == "$PhysicalNames")
      s = readPhysicalNames(sc, mesh);
    else if (tok == "$Entities")
      s = readEntities(sc, st);
    else if (tok == "$Nodes")
      s = readNodes(sc, mesh, st, limit);
    else if (tok == "$Elements")
      s = readElements(sc, mesh, st, limit);
    else if (tok.substr(0, 4) != "$End")
    {
      // Unknown section: skip to its end tag.
      const std::string end = "$End" + std::string(tok.substr(1));
      while (sc.next(tok) && tok != end)
      {
      }
    }
  }
  if (!s.ok())
    return s;
  if (!finishReadCells(mesh))
    return readError(path, 0, "no tetrahedra, prisms or pyramids: not a volume mesh");
  return Status::success();
}

} // namespace volgrid
