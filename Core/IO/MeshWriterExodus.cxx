// Exodus II writer (Debian's libexoIIv2c over netCDF): the tets in one TETRA element block per region
// (block id = region label, named after the region), and one side set per patch (id = patch label, named
// after it) listing each boundary triangle as (owning tet, Exodus side). Tets are numbered block by block,
// as Exodus numbers elements. Point fields (SolverMesh::pointData) become nodal variables at time 0.
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
  for (int32_t p : distinctLabels(mesh.trianglePatch))
    longest = std::max(longest, labelName(mesh.patchNames, p, "patch").size());
  for (int32_t r : distinctLabels(mesh.tetRegion))
    longest = std::max(longest, labelName(mesh.regionNames, r, "region").size());
  for (const auto& field : mesh.pointData)
    longest = std::max(longest, field.first.size());
  return longest;
}

// The tets block by block (ascending region label); elementNumber[t] is tet t's 1-based Exodus number.
bool writeBlocks(int file, const SolverMesh& mesh, const std::vector<int32_t>& regions,
                 std::vector<int64_t>& elementNumber)
{
  elementNumber.assign(static_cast<size_t>(mesh.numberOfTets()), 0);
  int64_t next = 1;
  for (int32_t region : regions)
  {
    std::vector<int> connectivity;
    for (int64_t t = 0; t < mesh.numberOfTets(); ++t)
    {
      if (mesh.tetRegion[t] != region)
        continue;
      elementNumber[t] = next++;
      for (int k = 0; k < 4; ++k)
        connectivity.push_back(mesh.tets[4 * t + k] + 1);
    }
    if (ex_put_elem_block(file, region, "TETRA", static_cast<int>(connectivity.size() / 4), 4, 0) < 0 ||
        ex_put_elem_conn(file, region, connectivity.data()) < 0)
      return false;
  }
  return putNames(file, EX_ELEM_BLOCK, regions, mesh.regionNames, "region") >= 0;
}

bool writeSideSets(int file, const SolverMesh& mesh, const std::vector<int32_t>& patches,
                   const std::vector<FaceOwner>& owners, const std::vector<int64_t>& elementNumber)
{
  for (int32_t patch : patches)
  {
    std::vector<int> elements, sides;
    for (int64_t t = 0; t < mesh.numberOfTriangles(); ++t)
    {
      if (mesh.trianglePatch[t] != patch)
        continue;
      elements.push_back(static_cast<int>(elementNumber[owners[t].tet]));
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

bool writeFile(int file, const SolverMesh& mesh, const std::vector<FaceOwner>& owners)
{
  const std::vector<int32_t> regions = distinctLabels(mesh.tetRegion);
  const std::vector<int32_t> patches = distinctLabels(mesh.trianglePatch);
  const size_t longest = longestName(mesh);
  if (longest > 32 && ex_set_max_name_length(file, static_cast<int>(longest)) < 0)
    return false;
  if (ex_put_init(file, "VolGrid tetrahedral mesh", 3, static_cast<int>(mesh.numberOfPoints()),
                  static_cast<int>(mesh.numberOfTets()), static_cast<int>(regions.size()), 0,
                  static_cast<int>(patches.size())) < 0)
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
  if (mesh.numberOfPoints() > 2147483647LL || mesh.numberOfTets() > 2147483647LL)
    return Status::failure(ErrorKind::InvalidOption,
                           "cannot write Exodus II file '" + path + "': more than 2^31 points or tets");
  std::vector<FaceOwner> owners;
  Status s = findBoundaryFaceOwners(mesh, owners);
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
