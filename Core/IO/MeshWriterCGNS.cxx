// CGNS writer (Debian's libcgns, HDF5): one base, one unstructured zone; the tets in one TETRA_4 section
// per region (named after the region), the boundary-layer prisms in one PENTA_6 section per region
// ("<region>_prisms"; SolverMesh's order is CGNS's: face (1 3 2) points out), the pyramids of collapsed
// layer columns in one PYRA_5 section per region ("<region>_pyramids"; SolverMesh's order is CGNS's too:
// face (1 4 3 2) points out), then per patch its boundary
// triangles (TRI_3 section) and prism side quads (QUAD_4 section "<patch>_quads", right after), and one
// boundary condition per patch, named after it, over the element range of its sections (face-centred). Each
// condition is FamilySpecified, its family (same name) holding the type (wall, symmetry, far field ...):
// the usual CGNS practice, and the form ParaView's reader takes for every type.
#include "LibraryOutput.h"
#include "MeshWriter.h"

#include <algorithm>
#include <cctype>
#include <cgnslib.h>

namespace volgrid
{
namespace
{
bool nameHas(const std::string& name, const char* word)
{
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower.find(word) != std::string::npos;
}

// The same choice by name as OpenFOAM's patch types (defaultOpenFoamPatchType).
CGNS_ENUMT(BCType_t) bcTypeFor(const std::string& name)
{
  if (nameHas(name, "symmetry"))
    return CGNS_ENUMV(BCSymmetryPlane);
  if (nameHas(name, "farfield"))
    return CGNS_ENUMV(BCFarfield);
  if (nameHas(name, "inlet"))
    return CGNS_ENUMV(BCInflow);
  if (nameHas(name, "outlet"))
    return CGNS_ENUMV(BCOutflow);
  return CGNS_ENUMV(BCWall);
}

// CGNS names are at most 32 characters (checked by longNameError before anything is written).
std::string cgnsName(const std::string& name)
{
  return name.substr(0, 32);
}

// The first patch or region name CGNS cannot hold whole, as an error message ("" when all fit).
std::string longNameError(const SolverMesh& mesh)
{
  std::vector<int32_t> faces = mesh.trianglePatch, cells = mesh.tetRegion;
  faces.insert(faces.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  cells.insert(cells.end(), mesh.prismRegion.begin(), mesh.prismRegion.end());
  cells.insert(cells.end(), mesh.pyramidRegion.begin(), mesh.pyramidRegion.end());
  for (int32_t p : distinctLabels(faces))
    if (labelName(mesh.patchNames, p, "patch").size() > 32)
      return "patch name '" + labelName(mesh.patchNames, p, "patch") + "' is longer than CGNS's 32 characters";
  for (int32_t r : distinctLabels(cells))
    if (labelName(mesh.regionNames, r, "region").size() > 32)
      return "region name '" + labelName(mesh.regionNames, r, "region") + "' is longer than CGNS's 32 characters";
  return "";
}

// Writes the element sections of one label kind: cells of `type` with `perCell` vertices, one section per
// label of `only` that has cells (named after the label, plus `suffix`), numbered from `next`. Returns
// each label's first and last element number (next, next - 1 when it has none).
bool writeSections(int file, int base, int zone, CGNS_ENUMT(ElementType_t) type, int perCell,
                   const std::vector<int32_t>& cells, const std::vector<int32_t>& labels, const NameTable& names,
                   const char* prefix, const char* suffix, const std::vector<int32_t>& only, cgsize_t& next,
                   std::vector<std::pair<cgsize_t, cgsize_t>>& ranges)
{
  for (int32_t label : only)
  {
    std::vector<cgsize_t> connectivity;
    for (size_t c = 0; c < labels.size(); ++c)
      if (labels[c] == label)
        for (int k = 0; k < perCell; ++k)
          connectivity.push_back(static_cast<cgsize_t>(cells[perCell * c + k]) + 1);
    const cgsize_t count = static_cast<cgsize_t>(connectivity.size() / perCell);
    ranges.emplace_back(next, next + count - 1);
    if (count == 0)
      continue;
    const std::string name = cgnsName(labelName(names, label, prefix)).substr(0, 32 - std::string(suffix).size());
    int section = 0;
    if (cg_section_write(file, base, zone, (name + suffix).c_str(), type, next, next + count - 1, 0,
                         connectivity.data(), &section) != CG_OK)
      return false;
    next += count;
  }
  return true;
}

bool writeBoundaryConditions(int file, int base, int zone, const SolverMesh& mesh, const std::vector<int32_t>& patches,
                             const std::vector<std::pair<cgsize_t, cgsize_t>>& ranges)
{
  for (size_t k = 0; k < patches.size(); ++k)
  {
    const std::string name = cgnsName(labelName(mesh.patchNames, patches[k], "patch"));
    int family = 0, familyBC = 0, bc = 0;
    cgsize_t range[2] = { ranges[k].first, ranges[k].second };
    if (cg_family_write(file, base, name.c_str(), &family) != CG_OK ||
        cg_fambc_write(file, base, family, name.c_str(), bcTypeFor(name), &familyBC) != CG_OK ||
        cg_boco_write(file, base, zone, name.c_str(), CGNS_ENUMV(FamilySpecified), CGNS_ENUMV(PointRange), 2, range,
                      &bc) != CG_OK ||
        cg_boco_gridlocation_write(file, base, zone, bc, CGNS_ENUMV(FaceCenter)) != CG_OK ||
        cg_goto(file, base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", bc, "end") != CG_OK ||
        cg_famname_write(name.c_str()) != CG_OK)
      return false;
  }
  return true;
}

bool writeZone(int file, const SolverMesh& mesh)
{
  int base = 0, zone = 0, coordinate = 0;
  const cgsize_t cells = static_cast<cgsize_t>(mesh.numberOfTets() + static_cast<int64_t>(mesh.prisms.size() / 6) +
                                               static_cast<int64_t>(mesh.pyramids.size() / 5));
  cgsize_t size[3] = { static_cast<cgsize_t>(mesh.numberOfPoints()), cells, 0 };
  if (cg_base_write(file, "Base", 3, 3, &base) != CG_OK ||
      cg_zone_write(file, base, "Zone", size, CGNS_ENUMV(Unstructured), &zone) != CG_OK ||
      cg_goto(file, base, "end") != CG_OK || cg_dataclass_write(CGNS_ENUMV(NormalizedByUnknownDimensional)) != CG_OK)
    return false; // the data class: the coordinates are in the input's (unknown) units
  static const char* const axes[3] = { "CoordinateX", "CoordinateY", "CoordinateZ" };
  std::vector<double> values(static_cast<size_t>(mesh.numberOfPoints()));
  for (int axis = 0; axis < 3; ++axis)
  {
    for (size_t i = 0; i < values.size(); ++i)
      values[i] = mesh.points[3 * i + axis];
    // Coordinates are lengths: exponent 1 of length (mass, length, time, temperature, angle).
    const float lengthExponents[5] = { 0, 1, 0, 0, 0 };
    if (cg_coord_write(file, base, zone, CGNS_ENUMV(RealDouble), axes[axis], values.data(), &coordinate) != CG_OK ||
        cg_goto(file, base, "Zone_t", zone, "GridCoordinates_t", 1, "DataArray_t", coordinate, "end") != CG_OK ||
        cg_exponents_write(CGNS_ENUMV(RealSingle), lengthExponents) != CG_OK)
      return false;
  }
  cgsize_t next = 1;
  std::vector<std::pair<cgsize_t, cgsize_t>> cellRanges, patchRanges;
  if (!writeSections(file, base, zone, CGNS_ENUMV(TETRA_4), 4, mesh.tets, mesh.tetRegion, mesh.regionNames, "region",
                     "", distinctLabels(mesh.tetRegion), next, cellRanges) ||
      !writeSections(file, base, zone, CGNS_ENUMV(PENTA_6), 6, mesh.prisms, mesh.prismRegion, mesh.regionNames,
                     "region", "_prisms", distinctLabels(mesh.prismRegion), next, cellRanges) ||
      !writeSections(file, base, zone, CGNS_ENUMV(PYRA_5), 5, mesh.pyramids, mesh.pyramidRegion, mesh.regionNames,
                     "region", "_pyramids", distinctLabels(mesh.pyramidRegion), next, cellRanges))
    return false;
  // A patch's triangles and quads are consecutive: one element range for its boundary condition.
  std::vector<int32_t> faces = mesh.trianglePatch;
  faces.insert(faces.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  const std::vector<int32_t> patches = distinctLabels(faces);
  for (int32_t p : patches)
  {
    std::vector<std::pair<cgsize_t, cgsize_t>> r;
    if (!writeSections(file, base, zone, CGNS_ENUMV(TRI_3), 3, mesh.triangles, mesh.trianglePatch, mesh.patchNames,
                       "patch", "", { p }, next, r) ||
        !writeSections(file, base, zone, CGNS_ENUMV(QUAD_4), 4, mesh.quads, mesh.quadPatch, mesh.patchNames, "patch",
                       "_quads", { p }, next, r))
      return false;
    patchRanges.emplace_back(r[0].first, r[1].second);
  }
  return writeBoundaryConditions(file, base, zone, mesh, patches, patchRanges);
}
} // namespace

Status writeCGNS(const std::string& path, const SolverMesh& mesh)
{
  if (mesh.numberOfPoints() > 2147483647LL ||
      mesh.numberOfTets() + mesh.numberOfTriangles() +
          static_cast<int64_t>(mesh.prismRegion.size() + mesh.pyramidRegion.size() + mesh.quadPatch.size()) >
        2147483647LL)
    return Status::failure(ErrorKind::InvalidOption,
                           "cannot write CGNS file '" + path +
                             "': more than 2^31 points or elements (Debian's libcgns is 32-bit)");
  const std::string tooLong = longNameError(mesh);
  if (!tooLong.empty())
    return Status::failure(ErrorKind::InvalidOption,
                           "cannot write CGNS file '" + path + "': " + tooLong + " (rename it with --patch NAME=ID)");
  LibraryOutput out;
  Status s = out.open(path, "CGNS");
  if (!s.ok())
    return s;
  int file = 0;
  if (cg_open(out.temporaryPath().c_str(), CG_MODE_WRITE, &file) != CG_OK)
    return out.failure(cg_get_error());
  const bool written = writeZone(file, mesh);
  const std::string error = written ? "" : cg_get_error();
  if (cg_close(file) != CG_OK && written)
    return out.failure(cg_get_error());
  if (!written)
    return out.failure(error);
  return out.commit();
}

} // namespace volgrid
