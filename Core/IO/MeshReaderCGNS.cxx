// CGNS reader (Debian's libcgns): the first unstructured zone of the first base. TETRA_4 sections are the
// tets, one region per section (named after it); TRI_3 sections the boundary triangles. Patches are the
// boundary conditions (named after them) over element ranges or lists, or over vertex lists (a triangle
// whose three vertices are listed); triangles no condition covers keep one patch per section.
#include "MeshReader.h"

#include <algorithm>
#include <cgnslib.h>
#include <map>
#include <sys/stat.h>

namespace volgrid
{
namespace
{
struct CgnsFile
{
  int id = -1;
  ~CgnsFile()
  {
    if (id >= 0)
      cg_close(id);
  }
};

Status cgnsFailure(const std::string& path, const std::string& reason)
{
  return Status::failure(ErrorKind::InvalidOption, "cannot read CGNS file '" + path + "': " + reason);
}

// A damaged file must not make the reader allocate more than the file could hold: every stored value
// takes at least one byte (CGNS does not compress).
cgsize_t countLimit(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0 ? static_cast<cgsize_t>(std::min<long long>(info.st_size, 2147483647LL)) : 0;
}

Status readCoordinates(const std::string& path, int file, int zone, cgsize_t numPoints, SolverMesh& mesh)
{
  static const char* const axes[3] = { "CoordinateX", "CoordinateY", "CoordinateZ" };
  std::vector<double> values(static_cast<size_t>(numPoints));
  mesh.points.assign(3 * values.size(), 0.0);
  cgsize_t first = 1, last = numPoints;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (cg_coord_read(file, 1, zone, axes[axis], CGNS_ENUMV(RealDouble), &first, &last, values.data()) != CG_OK)
      return cgnsFailure(path, std::string(axes[axis]) + ": " + cg_get_error());
    for (size_t i = 0; i < values.size(); ++i)
      mesh.points[3 * i + axis] = values[i];
  }
  return Status::success();
}

// The sections: tets and triangles appended to `mesh`, each triangle's element number in `triangleOf`.
Status readSections(const std::string& path, int file, int zone, cgsize_t numPoints, SolverMesh& mesh,
                    std::map<cgsize_t, int64_t>& triangleOf)
{
  int numSections = 0;
  if (cg_nsections(file, 1, zone, &numSections) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  int32_t region = 0, sectionPatch = 0;
  for (int section = 1; section <= numSections; ++section)
  {
    char name[33] = {};
    CGNS_ENUMT(ElementType_t) type;
    cgsize_t start = 0, end = 0, dataSize = 0;
    int boundary = 0, parents = 0;
    if (cg_section_read(file, 1, zone, section, name, &type, &start, &end, &boundary, &parents) != CG_OK ||
        cg_ElementDataSize(file, 1, zone, section, &dataSize) != CG_OK)
      return cgnsFailure(path, cg_get_error());
    const int perCell = type == CGNS_ENUMV(TETRA_4) ? 4 : type == CGNS_ENUMV(TRI_3) ? 3 : 0;
    if (perCell == 0)
      return cgnsFailure(path,
                         "section '" + std::string(name) + "' holds " + cg_ElementTypeName(type) +
                           " elements (only TETRA_4 and TRI_3 are read)");
    if (end < start || dataSize != (end - start + 1) * perCell || dataSize > countLimit(path))
      return cgnsFailure(path, "section '" + std::string(name) + "' has an inconsistent size");
    std::vector<cgsize_t> connectivity(static_cast<size_t>(dataSize));
    if (cg_elements_read(file, 1, zone, section, connectivity.data(), nullptr) != CG_OK)
      return cgnsFailure(path, cg_get_error());
    for (cgsize_t v : connectivity)
      if (v < 1 || v > numPoints)
        return cgnsFailure(path,
                           "section '" + std::string(name) + "' names point " + std::to_string(v) + " of " +
                             std::to_string(numPoints));
    std::vector<int32_t>& cells = perCell == 4 ? mesh.tets : mesh.triangles;
    for (cgsize_t v : connectivity)
      cells.push_back(static_cast<int32_t>(v - 1));
    if (perCell == 4)
    {
      mesh.regionNames[++region] = name;
      mesh.tetRegion.insert(mesh.tetRegion.end(), static_cast<size_t>(end - start + 1), region);
      continue;
    }
    mesh.patchNames[++sectionPatch] = name;
    for (cgsize_t e = start; e <= end; ++e)
    {
      triangleOf[e] = static_cast<int64_t>(mesh.trianglePatch.size());
      mesh.trianglePatch.push_back(sectionPatch);
    }
  }
  return Status::success();
}

// The triangles one boundary condition covers.
Status conditionTriangles(const std::string& path, int file, int zone, int bc, const SolverMesh& mesh,
                          const std::map<cgsize_t, int64_t>& triangleOf, std::string& name,
                          std::vector<int64_t>& covered)
{
  char text[33] = {};
  CGNS_ENUMT(BCType_t) type;
  CGNS_ENUMT(PointSetType_t) setType;
  CGNS_ENUMT(GridLocation_t) location;
  CGNS_ENUMT(DataType_t) normalType;
  cgsize_t numSetPoints = 0, normalSize = 0;
  int normalIndex[3] = {}, numData = 0;
  if (cg_boco_info(file, 1, zone, bc, text, &type, &setType, &numSetPoints, normalIndex, &normalSize, &normalType,
                   &numData) != CG_OK ||
      cg_boco_gridlocation_read(file, 1, zone, bc, &location) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  name = text;
  if (numSetPoints < 0 || numSetPoints > countLimit(path))
    return cgnsFailure(path, "boundary condition '" + name + "' claims " + std::to_string(numSetPoints) + " entries");
  std::vector<cgsize_t> set(static_cast<size_t>(numSetPoints));
  if (cg_boco_read(file, 1, zone, bc, set.data(), nullptr) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  const bool range = setType == CGNS_ENUMV(PointRange) || setType == CGNS_ENUMV(ElementRange);
  if (range && set.size() != 2)
    return cgnsFailure(path, "boundary condition '" + name + "' has a range without two ends");
  if (location == CGNS_ENUMV(Vertex) && setType != CGNS_ENUMV(ElementRange) && setType != CGNS_ENUMV(ElementList))
  {
    const cgsize_t numPoints = static_cast<cgsize_t>(mesh.numberOfPoints());
    std::vector<char> listed(static_cast<size_t>(numPoints), 0);
    for (cgsize_t v = range ? set[0] : 0; range ? v <= set[1] : v < static_cast<cgsize_t>(set.size()); ++v)
    {
      const cgsize_t p = range ? v : set[static_cast<size_t>(v)];
      if (p >= 1 && p <= numPoints)
        listed[static_cast<size_t>(p - 1)] = 1;
    }
    for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
      if (listed[mesh.triangles[3 * t]] && listed[mesh.triangles[3 * t + 1]] && listed[mesh.triangles[3 * t + 2]])
        covered.push_back(t);
    return Status::success();
  }
  auto add = [&](cgsize_t element)
  {
    const auto it = triangleOf.find(element);
    if (it != triangleOf.end())
      covered.push_back(it->second);
  };
  if (range)
    for (cgsize_t e = set[0]; e <= set[1]; ++e)
      add(e);
  else
    for (cgsize_t e : set)
      add(e);
  return Status::success();
}

// Relabels the triangles by boundary condition: condition k is patch k; triangles no condition covers
// keep their section's patch, after the conditions.
Status readBoundaryConditions(const std::string& path, int file, int zone, SolverMesh& mesh,
                              const std::map<cgsize_t, int64_t>& triangleOf)
{
  int numConditions = 0;
  if (cg_nbocos(file, 1, zone, &numConditions) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  if (numConditions == 0)
    return Status::success();
  std::vector<int32_t> patch(mesh.trianglePatch.size(), 0);
  NameTable names;
  for (int bc = 1; bc <= numConditions; ++bc)
  {
    std::string name;
    std::vector<int64_t> covered;
    Status s = conditionTriangles(path, file, zone, bc, mesh, triangleOf, name, covered);
    if (!s.ok())
      return s;
    names[bc] = name;
    for (int64_t t : covered)
      patch[static_cast<size_t>(t)] = bc;
  }
  for (size_t t = 0; t < patch.size(); ++t)
    if (patch[t] == 0)
    {
      patch[t] = numConditions + mesh.trianglePatch[t];
      names[patch[t]] = mesh.patchNames[mesh.trianglePatch[t]];
    }
  mesh.trianglePatch = patch;
  mesh.patchNames = names;
  return Status::success();
}
} // namespace

Status readCGNS(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  CgnsFile file;
  if (cg_open(path.c_str(), CG_MODE_READ, &file.id) != CG_OK)
  {
    file.id = -1;
    return cgnsFailure(path, cg_get_error());
  }
  int numBases = 0, numZones = 0;
  if (cg_nbases(file.id, &numBases) != CG_OK || numBases < 1 || cg_nzones(file.id, 1, &numZones) != CG_OK ||
      numZones < 1)
    return cgnsFailure(path, "no base with a zone");
  CGNS_ENUMT(ZoneType_t) zoneType;
  char zoneName[33] = {};
  cgsize_t size[3] = {};
  if (cg_zone_type(file.id, 1, 1, &zoneType) != CG_OK || cg_zone_read(file.id, 1, 1, zoneName, size) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  if (zoneType != CGNS_ENUMV(Unstructured))
    return cgnsFailure(path, "zone '" + std::string(zoneName) + "' is structured (a tet mesh is unstructured)");
  if (size[0] < 4 || size[0] > countLimit(path) / 3)
    return cgnsFailure(path,
                       "zone '" + std::string(zoneName) + "' claims " + std::to_string(size[0]) +
                         " points, impossible in a file of this size");
  std::map<cgsize_t, int64_t> triangleOf;
  Status s = readCoordinates(path, file.id, 1, size[0], mesh);
  if (s.ok())
    s = readSections(path, file.id, 1, size[0], mesh, triangleOf);
  if (s.ok())
    s = readBoundaryConditions(path, file.id, 1, mesh, triangleOf);
  if (s.ok() && mesh.numberOfTets() == 0)
    s = cgnsFailure(path, "no TETRA_4 elements");
  if (!s.ok())
    mesh = SolverMesh();
  return s;
}

} // namespace volgrid
