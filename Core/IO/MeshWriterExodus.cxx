// Exodus II writer (Debian's libexoIIv2c over netCDF): the tets in one TETRA element block per region
// (block id = region label, named after the region), boundary-layer prisms in one WEDGE block per region
// after them (id = region label + the largest tet region label, named "<region>_prisms"; SolverMesh's
// order is Exodus's: side 4 (1 3 2) points out), the pyramids of collapsed layer columns in one PYRAMID
// block per region after those (id = region label + the largest prism block id, "<region>_pyramids";
// SolverMesh's order is Exodus's too: side 5 (1 4 3 2) points out), and one side set per patch (id = patch
// label, named after it) listing each boundary triangle and quad as (owning element, Exodus side).
// Elements are numbered block by block, as Exodus numbers them. Point fields (SolverMesh::pointData)
// become nodal variables at time 0.
#include "BoundaryFaceOwners.h"
#include "LibraryOutput.h"
#include "MeshWriter.h"

#include <algorithm>
#include <exodusII.h>

namespace volgrid
{
namespace
{
std::string exodusError()
{
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  return message && *message ? message : "the Exodus library reported error " + std::to_string(code);
}

// ex_put_names wants mutable char*s.
int putNames(int file, ex_entity_type kind, const std::vector<int32_t>& labels, const NameTable& names,
             const char* prefix)
{
  std::vector<std::string> texts;
  for (int32_t label : labels)
    texts.push_back(labelName(names, label, prefix));
  std::vector<char*> pointers;
  for (std::string& t : texts)
    pointers.push_back(&t[0]);
  return ex_put_names(file, kind, pointers.data());
}

size_t longestName(const SolverMesh& mesh)
{
  size_t longest = 0;
  for (int32_t r : distinctLabels(mesh.prismRegion))
    longest = std::max(longest, labelName(mesh.regionNames, r, "region").size() + 7);
  for (int32_t r : distinctLabels(mesh.pyramidRegion))
    longest = std::max(longest, labelName(mesh.regionNames, r, "region").size() + 9);
  for (int32_t p : distinctLabels(mesh.trianglePatch))
    longest = std::max(longest, labelName(mesh.patchNames, p, "patch").size());
  for (int32_t r : distinctLabels(mesh.tetRegion))
    longest = std::max(longest, labelName(mesh.regionNames, r, "region").size());
  for (const auto& field : mesh.pointData)
    longest = std::max(longest, field.first.size());
  return longest;
}

// The cells of one kind block by block (ascending label), numbered from `next`; elementNumber[first + c]
// is cell c's 1-based Exodus number.
bool writeKindBlocks(int file, const char* type, int nv, const std::vector<int32_t>& cells,
                     const std::vector<int32_t>& labels, int32_t idOffset, size_t first, int64_t& next,
                     std::vector<int64_t>& elementNumber)
{
  for (int32_t label : distinctLabels(labels))
  {
    std::vector<int> connectivity;
    for (size_t c = 0; c < labels.size(); ++c)
    {
      if (labels[c] != label)
        continue;
      elementNumber[first + c] = next++;
      for (int k = 0; k < nv; ++k)
        connectivity.push_back(cells[nv * c + k] + 1);
    }
    if (ex_put_elem_block(file, label + idOffset, type, static_cast<int>(connectivity.size() / nv), nv, 0) < 0 ||
        ex_put_elem_conn(file, label + idOffset, connectivity.data()) < 0)
      return false;
  }
  return true;
}

// The tet blocks, then the prism blocks, then the pyramid blocks; their names.
bool writeBlocks(int file, const SolverMesh& mesh, const std::vector<int32_t>& regions,
                 std::vector<int64_t>& elementNumber)
{
  const std::vector<int32_t> prismRegions = distinctLabels(mesh.prismRegion);
  const std::vector<int32_t> pyramidRegions = distinctLabels(mesh.pyramidRegion);
  const int32_t offset = regions.empty() ? 0 : regions.back();
  const int32_t pyramidOffset = offset + (prismRegions.empty() ? 0 : prismRegions.back());
  elementNumber.assign(mesh.tetRegion.size() + mesh.prismRegion.size() + mesh.pyramidRegion.size(), 0);
  int64_t next = 1;
  if (!writeKindBlocks(file, "TETRA", 4, mesh.tets, mesh.tetRegion, 0, 0, next, elementNumber) ||
      !writeKindBlocks(file, "WEDGE", 6, mesh.prisms, mesh.prismRegion, offset, mesh.tetRegion.size(), next,
                       elementNumber) ||
      !writeKindBlocks(file, "PYRAMID", 5, mesh.pyramids, mesh.pyramidRegion, pyramidOffset,
                       mesh.tetRegion.size() + mesh.prismRegion.size(), next, elementNumber))
    return false;
  std::vector<std::string> texts;
  for (int32_t r : regions)
    texts.push_back(labelName(mesh.regionNames, r, "region"));
  for (int32_t r : prismRegions)
    texts.push_back(labelName(mesh.regionNames, r, "region") + "_prisms");
  for (int32_t r : pyramidRegions)
    texts.push_back(labelName(mesh.regionNames, r, "region") + "_pyramids");
  std::vector<char*> pointers;
  for (std::string& t : texts)
    pointers.push_back(&t[0]);
  return ex_put_names(file, EX_ELEM_BLOCK, pointers.data()) >= 0;
}

bool writeSideSets(int file, const SolverMesh& mesh, const std::vector<int32_t>& patches,
                   const std::vector<CellSide>& owners, const std::vector<int64_t>& elementNumber)
{
  std::vector<int32_t> facePatch = mesh.trianglePatch; // triangles, then quads, as the owners
  facePatch.insert(facePatch.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  for (int32_t patch : patches)
  {
    std::vector<int> elements, sides;
    for (size_t t = 0; t < facePatch.size(); ++t)
    {
      if (facePatch[t] != patch)
        continue;
      elements.push_back(static_cast<int>(elementNumber[owners[t].cell]));
      sides.push_back(owners[t].side + 1);
    }
    if (ex_put_side_set_param(file, patch, static_cast<int>(elements.size()), 0) < 0 ||
        ex_put_side_set(file, patch, elements.data(), sides.data()) < 0)
      return false;
  }
  return putNames(file, EX_SIDE_SET, patches, mesh.patchNames, "patch") >= 0;
}

// The point fields as nodal variables of one time step (time 0).
bool writePointData(int file, const SolverMesh& mesh)
{
  if (mesh.pointData.empty())
    return true;
  std::vector<std::string> names;
  for (const auto& field : mesh.pointData)
    names.push_back(field.first);
  std::vector<char*> pointers;
  for (std::string& n : names)
    pointers.push_back(&n[0]);
  const double time = 0.0;
  if (ex_put_variable_param(file, EX_NODAL, static_cast<int>(names.size())) < 0 ||
      ex_put_variable_names(file, EX_NODAL, static_cast<int>(names.size()), pointers.data()) < 0 ||
      ex_put_time(file, 1, &time) < 0)
    return false;
  int index = 1;
  for (const auto& field : mesh.pointData)
    if (field.second.size() != static_cast<size_t>(mesh.numberOfPoints()) ||
        ex_put_var(file, 1, EX_NODAL, index++, 1, mesh.numberOfPoints(), field.second.data()) < 0)
      return false;
  return true;
}

bool writeFile(int file, const SolverMesh& mesh, const std::vector<CellSide>& owners)
{
  const std::vector<int32_t> regions = distinctLabels(mesh.tetRegion);
  std::vector<int32_t> faces = mesh.trianglePatch;
  faces.insert(faces.end(), mesh.quadPatch.begin(), mesh.quadPatch.end());
  const std::vector<int32_t> patches = distinctLabels(faces);
  const size_t blocks =
    regions.size() + distinctLabels(mesh.prismRegion).size() + distinctLabels(mesh.pyramidRegion).size();
  const int64_t elements =
    mesh.numberOfTets() + static_cast<int64_t>(mesh.prismRegion.size() + mesh.pyramidRegion.size());
  const size_t longest = longestName(mesh);
  if (longest > 32 && ex_set_max_name_length(file, static_cast<int>(longest)) < 0)
    return false;
  if (ex_put_init(file, "VolGrid tetrahedral mesh", 3, static_cast<int>(mesh.numberOfPoints()),
                  static_cast<int>(elements), static_cast<int>(blocks), 0, static_cast<int>(patches.size())) < 0)
    return false;
  std::vector<double> xyz[3];
  for (int axis = 0; axis < 3; ++axis)
    for (int64_t i = 0; i < mesh.numberOfPoints(); ++i)
      xyz[axis].push_back(mesh.points[3 * i + axis]);
  char x[] = "x", y[] = "y", z[] = "z";
  char* axisNames[3] = { x, y, z };
  std::vector<int64_t> elementNumber;
  return ex_put_coord(file, xyz[0].data(), xyz[1].data(), xyz[2].data()) >= 0 &&
    ex_put_coord_names(file, axisNames) >= 0 && writeBlocks(file, mesh, regions, elementNumber) &&
    writeSideSets(file, mesh, patches, owners, elementNumber) && writePointData(file, mesh);
}
} // namespace

Status writeExodus(const std::string& path, const SolverMesh& mesh)
{
  if (mesh.numberOfPoints() > 2147483647LL ||
      mesh.numberOfTets() + static_cast<int64_t>(mesh.prismRegion.size() + mesh.pyramidRegion.size()) > 2147483647LL)
    return Status::failure(ErrorKind::InvalidOption,
                           "cannot write Exodus II file '" + path + "': more than 2^31 points or cells");
  std::vector<CellSide> owners;
  Status s = findBoundaryCellSides(mesh, owners);
  if (!s.ok())
    return Status::failure(ErrorKind::InvalidOption, "cannot write Exodus II file '" + path + "': " + s.message);
  LibraryOutput out;
  s = out.open(path, "Exodus II");
  if (!s.ok())
    return s;
  int wordSize = 8, ioWordSize = 8;
  const int file = ex_create(out.temporaryPath().c_str(), EX_CLOBBER, &wordSize, &ioWordSize);
  if (file < 0)
    return out.failure(exodusError());
  const bool written = writeFile(file, mesh, owners);
  const std::string error = written ? "" : exodusError();
  if (ex_close(file) < 0 && written)
    return out.failure(exodusError());
  if (!written)
    return out.failure(error);
  return out.commit();
}

} // namespace volgrid
