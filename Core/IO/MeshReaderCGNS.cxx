// CGNS reader (Debian's libcgns): the first unstructured zone of the first base. TETRA_4 sections are the
// tets, one region per section (named after it); PENTA_6 and PYRA_5 sections the boundary-layer prisms and
// pyramids (CGNS's node orders are SolverMesh's, as MeshWriterCGNS.cxx writes them), in the region of the
// section's name without "_prisms" / "_pyramids" (a new region when no section had that name); TRI_3 and
// QUAD_4 sections the boundary triangles and quads. Patches are the boundary conditions (named after them)
// over element ranges or lists, or over vertex lists (a face whose vertices are all listed); faces no
// condition covers keep one patch per section (a "<patch>_quads" section joins patch <patch>).
#include "MeshReader.h"

#include <algorithm>
#include <cgnslib.h>
#include <iterator>
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

// A boundary face by its element number: a triangle or a quad, and its index among those.
struct FaceRef
{
  bool quad = false;
  int64_t index = 0;
};
using FaceOfElement = std::map<cgsize_t, FaceRef>;

int32_t newLabel(NameTable& names, const std::string& name)
{
  const int32_t label = names.empty() ? 1 : names.rbegin()->first + 1;
  names[label] = name;
  return label;
}

// The label of a section VolGrid's writer named "<label's name><suffix>" (the name cut to fit CGNS's 32
// characters with the suffix): the first label of that name, else a new label named without the suffix.
int32_t labelNamed(NameTable& names, const std::string& section, const std::string& suffix)
{
  const bool suffixed =
    section.size() > suffix.size() && section.compare(section.size() - suffix.size(), suffix.size(), suffix) == 0;
  const std::string base = suffixed ? section.substr(0, section.size() - suffix.size()) : section;
  const bool cut = suffixed && section.size() == 32;
  for (const auto& entry : names)
    if (entry.second == base || (cut && entry.second.compare(0, base.size(), base) == 0))
      return entry.first;
  return newLabel(names, base);
}

// The sections: cells and boundary faces appended to `mesh`, each face's element number in `faceOf`.
Status readSections(const std::string& path, int file, int zone, cgsize_t numPoints, SolverMesh& mesh,
                    FaceOfElement& faceOf)
{
  int numSections = 0;
  if (cg_nsections(file, 1, zone, &numSections) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  // The element types read, their vertices (CGNS's orders are SolverMesh's), where they go, and the suffix
  // the writer gives a layer section's or quad section's name (none: each section is a new label).
  const struct
  {
    CGNS_ENUMT(ElementType_t) type;
    int vertices;
    std::vector<int32_t>* cells;
    std::vector<int32_t>* labels;
    NameTable* names;
    const char* suffix;
  } kinds[] = { { CGNS_ENUMV(TETRA_4), 4, &mesh.tets, &mesh.tetRegion, &mesh.regionNames, nullptr },
                { CGNS_ENUMV(PENTA_6), 6, &mesh.prisms, &mesh.prismRegion, &mesh.regionNames, "_prisms" },
                { CGNS_ENUMV(PYRA_5), 5, &mesh.pyramids, &mesh.pyramidRegion, &mesh.regionNames, "_pyramids" },
                { CGNS_ENUMV(TRI_3), 3, &mesh.triangles, &mesh.trianglePatch, &mesh.patchNames, nullptr },
                { CGNS_ENUMV(QUAD_4), 4, &mesh.quads, &mesh.quadPatch, &mesh.patchNames, "_quads" } };
  for (int section = 1; section <= numSections; ++section)
  {
    char name[33] = {};
    CGNS_ENUMT(ElementType_t) type;
    cgsize_t start = 0, end = 0, dataSize = 0;
    int boundary = 0, parents = 0;
    if (cg_section_read(file, 1, zone, section, name, &type, &start, &end, &boundary, &parents) != CG_OK ||
        cg_ElementDataSize(file, 1, zone, section, &dataSize) != CG_OK)
      return cgnsFailure(path, cg_get_error());
    const auto* kind = std::find_if(std::begin(kinds), std::end(kinds), [&](const auto& k) { return k.type == type; });
    if (kind == std::end(kinds))
      return cgnsFailure(path,
                         "section '" + std::string(name) + "' holds " + cg_ElementTypeName(type) +
                           " elements (only TETRA_4, PENTA_6, PYRA_5, TRI_3 and QUAD_4 are read)");
    if (end < start || dataSize != (end - start + 1) * kind->vertices || dataSize > countLimit(path))
      return cgnsFailure(path, "section '" + std::string(name) + "' has an inconsistent size");
    std::vector<cgsize_t> connectivity(static_cast<size_t>(dataSize));
    if (cg_elements_read(file, 1, zone, section, connectivity.data(), nullptr) != CG_OK)
      return cgnsFailure(path, cg_get_error());
    for (cgsize_t v : connectivity)
      if (v < 1 || v > numPoints)
        return cgnsFailure(path,
                           "section '" + std::string(name) + "' names point " + std::to_string(v) + " of " +
                             std::to_string(numPoints));
    for (cgsize_t v : connectivity)
      kind->cells->push_back(static_cast<int32_t>(v - 1));
    const int64_t first = static_cast<int64_t>(kind->labels->size());
    const int32_t label = kind->suffix ? labelNamed(*kind->names, name, kind->suffix) : newLabel(*kind->names, name);
    kind->labels->insert(kind->labels->end(), static_cast<size_t>(end - start + 1), label);
    if (kind->names == &mesh.patchNames)
      for (cgsize_t e = start; e <= end; ++e)
        faceOf[e] = { kind->cells == &mesh.quads, first + static_cast<int64_t>(e - start) };
  }
  return Status::success();
}

// The faces one boundary condition covers.
Status conditionFaces(const std::string& path, int file, int zone, int bc, const SolverMesh& mesh,
                      const FaceOfElement& faceOf, std::string& name, std::vector<FaceRef>& covered)
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
    const auto allListed = [&](const std::vector<int32_t>& faces, int n, int64_t f)
    {
      for (int k = 0; k < n; ++k)
        if (!listed[static_cast<size_t>(faces[static_cast<size_t>(n * f + k)])])
          return false;
      return true;
    };
    for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
      if (allListed(mesh.triangles, 3, t))
        covered.push_back({ false, t });
    for (int64_t q = 0; q < static_cast<int64_t>(mesh.quads.size() / 4); ++q)
      if (allListed(mesh.quads, 4, q))
        covered.push_back({ true, q });
    return Status::success();
  }
  auto add = [&](cgsize_t element)
  {
    const auto it = faceOf.find(element);
    if (it != faceOf.end())
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

// Relabels the faces by boundary condition: condition k is patch k; faces no condition covers keep their
// section's patch, after the conditions.
Status readBoundaryConditions(const std::string& path, int file, int zone, SolverMesh& mesh,
                              const FaceOfElement& faceOf)
{
  int numConditions = 0;
  if (cg_nbocos(file, 1, zone, &numConditions) != CG_OK)
    return cgnsFailure(path, cg_get_error());
  if (numConditions == 0)
    return Status::success();
  std::vector<int32_t> patch[2] = { std::vector<int32_t>(mesh.trianglePatch.size(), 0),
                                    std::vector<int32_t>(mesh.quadPatch.size(), 0) };
  NameTable names;
  for (int bc = 1; bc <= numConditions; ++bc)
  {
    std::string name;
    std::vector<FaceRef> covered;
    Status s = conditionFaces(path, file, zone, bc, mesh, faceOf, name, covered);
    if (!s.ok())
      return s;
    names[bc] = name;
    for (const FaceRef& f : covered)
      patch[f.quad][static_cast<size_t>(f.index)] = bc;
  }
  std::vector<int32_t>* sectionPatch[2] = { &mesh.trianglePatch, &mesh.quadPatch };
  for (int kind = 0; kind < 2; ++kind)
  {
    for (size_t f = 0; f < patch[kind].size(); ++f)
      if (patch[kind][f] == 0)
      {
        patch[kind][f] = numConditions + (*sectionPatch[kind])[f];
        names[patch[kind][f]] = mesh.patchNames[(*sectionPatch[kind])[f]];
      }
    *sectionPatch[kind] = patch[kind];
  }
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
  FaceOfElement faceOf;
  Status s = readCoordinates(path, file.id, 1, size[0], mesh);
  if (s.ok())
    s = readSections(path, file.id, 1, size[0], mesh, faceOf);
  if (s.ok())
    s = readBoundaryConditions(path, file.id, 1, mesh, faceOf);
  if (s.ok() && !finishReadCells(mesh))
    s = cgnsFailure(path, "no TETRA_4, PENTA_6 or PYRA_5 elements");
  if (!s.ok())
    mesh = SolverMesh();
  return s;
}

} // namespace volgrid
