// Exodus II reader (Debian's libexoIIv2c): the TETRA element blocks are the regions (in file order, named
// after the block), the side sets the patches (named after the set), each side a boundary triangle taken
// from its tet in the Exodus side order (kExodusTetSide), nodal variables at the last time step the point
// fields (a solver's target size, ...). Blocks of other element types are refused.
#include "BoundaryFaceOwners.h"
#include "MeshReader.h"

#include <algorithm>
#include <cctype>
#include <exodusII.h>
#include <sys/stat.h>

namespace volgrid
{
namespace
{
struct ExodusFile
{
  int id = -1;
  ~ExodusFile()
  {
    if (id >= 0)
      ex_close(id);
  }
};

Status exodusFailure(const std::string& path, const std::string& reason)
{
  return Status::failure(ErrorKind::InvalidOption, "cannot read Exodus II file '" + path + "': " + reason);
}

std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

// The names of `count` entities of `kind` (empty where the file has none).
std::vector<std::string> entityNames(int file, ex_entity_type kind, int count)
{
  const int length = std::max(32, static_cast<int>(ex_inquire_int(file, EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  ex_set_max_name_length(file, length);
  std::vector<std::vector<char>> buffers(static_cast<size_t>(count), std::vector<char>(length + 1, 0));
  std::vector<char*> pointers;
  for (auto& b : buffers)
    pointers.push_back(b.data());
  std::vector<std::string> names(static_cast<size_t>(count));
  if (count > 0 && ex_get_names(file, kind, pointers.data()) >= 0)
    for (int k = 0; k < count; ++k)
      names[k] = buffers[k].data();
  return names;
}

Status readBlocks(const std::string& path, int file, int numBlocks, int64_t numPoints, int numElements,
                  SolverMesh& mesh)
{
  std::vector<int> ids(static_cast<size_t>(numBlocks));
  if (numBlocks > 0 && ex_get_elem_blk_ids(file, ids.data()) < 0)
    return exodusFailure(path, "cannot read the element block ids");
  const std::vector<std::string> names = entityNames(file, EX_ELEM_BLOCK, numBlocks);
  for (int b = 0; b < numBlocks; ++b)
  {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, perElement = 0, attributes = 0;
    if (ex_get_elem_block(file, ids[b], type, &count, &perElement, &attributes) < 0)
      return exodusFailure(path, "cannot read element block " + std::to_string(ids[b]));
    const std::string kind = upper(type);
    if (count == 0)
      continue;
    if (count < 0 || count > numElements)
      return exodusFailure(path,
                           "element block " + std::to_string(ids[b]) + " claims " + std::to_string(count) +
                             " elements of " + std::to_string(numElements));
    if (kind.compare(0, 3, "TET") != 0 || perElement != 4)
      return exodusFailure(path,
                           "element block " + std::to_string(ids[b]) + " holds " + type + " elements with " +
                             std::to_string(perElement) + " nodes (only 4-node tets are read)");
    std::vector<int> connectivity(static_cast<size_t>(count) * 4);
    if (ex_get_elem_conn(file, ids[b], connectivity.data()) < 0)
      return exodusFailure(path, "cannot read the connectivity of block " + std::to_string(ids[b]));
    for (int v : connectivity)
    {
      if (v < 1 || v > numPoints)
        return exodusFailure(path,
                             "block " + std::to_string(ids[b]) + " names node " + std::to_string(v) + " of " +
                               std::to_string(numPoints));
      mesh.tets.push_back(v - 1);
    }
    const int32_t region = static_cast<int32_t>(mesh.regionNames.size() + 1);
    mesh.regionNames[region] = names[b].empty() ? "block" + std::to_string(ids[b]) : names[b];
    mesh.tetRegion.insert(mesh.tetRegion.end(), static_cast<size_t>(count), region);
  }
  return Status::success();
}

// The nodal variables at the last time step (a solver's latest result) as point fields.
Status readNodalVariables(const std::string& path, int file, int numPoints, SolverMesh& mesh)
{
  int numVariables = 0;
  const int numSteps = static_cast<int>(ex_inquire_int(file, EX_INQ_TIME));
  if (numSteps < 1 || ex_get_variable_param(file, EX_NODAL, &numVariables) < 0 || numVariables < 1)
    return Status::success();
  const int length = std::max(32, static_cast<int>(ex_inquire_int(file, EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  std::vector<std::vector<char>> buffers(static_cast<size_t>(numVariables), std::vector<char>(length + 1, 0));
  std::vector<char*> pointers;
  for (auto& b : buffers)
    pointers.push_back(b.data());
  if (ex_get_variable_names(file, EX_NODAL, numVariables, pointers.data()) < 0)
    return exodusFailure(path, "cannot read the nodal variable names");
  for (int k = 0; k < numVariables; ++k)
  {
    const std::string name = buffers[k].data();
    std::vector<double> values(static_cast<size_t>(numPoints));
    if (ex_get_var(file, numSteps, EX_NODAL, k + 1, 1, numPoints, values.data()) < 0)
      return exodusFailure(path, "cannot read nodal variable " + std::to_string(k + 1));
    mesh.pointData[name.empty() ? "variable" + std::to_string(k + 1) : name] = std::move(values);
  }
  return Status::success();
}

Status readSideSets(const std::string& path, int file, int numSets, SolverMesh& mesh)
{
  std::vector<int> ids(static_cast<size_t>(numSets));
  if (numSets > 0 && ex_get_side_set_ids(file, ids.data()) < 0)
    return exodusFailure(path, "cannot read the side set ids");
  const std::vector<std::string> names = entityNames(file, EX_SIDE_SET, numSets);
  for (int k = 0; k < numSets; ++k)
  {
    int numSides = 0, numFactors = 0;
    if (ex_get_side_set_param(file, ids[k], &numSides, &numFactors) < 0 || numSides < 0 ||
        numSides > 4 * mesh.numberOfTets())
      return exodusFailure(path,
                           "cannot read side set " + std::to_string(ids[k]) + " (or it has more sides than the tets)");
    std::vector<int> elements(static_cast<size_t>(numSides)), sides(static_cast<size_t>(numSides));
    if (numSides > 0 && ex_get_side_set(file, ids[k], elements.data(), sides.data()) < 0)
      return exodusFailure(path, "cannot read the sides of side set " + std::to_string(ids[k]));
    const int32_t patch = k + 1;
    mesh.patchNames[patch] = names[k].empty() ? "sideset" + std::to_string(ids[k]) : names[k];
    for (int s = 0; s < numSides; ++s)
    {
      if (elements[s] < 1 || elements[s] > mesh.numberOfTets() || sides[s] < 1 || sides[s] > 4)
        return exodusFailure(path,
                             "side set " + std::to_string(ids[k]) + " names side " + std::to_string(sides[s]) +
                               " of element " + std::to_string(elements[s]) + " (tets have sides 1-4)");
      const int32_t* tet = mesh.tets.data() + 4 * static_cast<int64_t>(elements[s] - 1);
      for (int corner : kExodusTetSide[sides[s] - 1])
        mesh.triangles.push_back(tet[corner]);
      mesh.trianglePatch.push_back(patch);
    }
  }
  return Status::success();
}
} // namespace

Status readExodus(const std::string& path, SolverMesh& mesh)
{
  mesh = SolverMesh();
  int wordSize = 8, ioWordSize = 0;
  float version = 0;
  ExodusFile file;
  file.id = ex_open(path.c_str(), EX_READ, &wordSize, &ioWordSize, &version);
  if (file.id < 0)
    return exodusFailure(path, "not an Exodus II (netCDF) file, or not readable");
  char title[MAX_LINE_LENGTH + 1] = {};
  int dimensions = 0, numPoints = 0, numElements = 0, numBlocks = 0, numNodeSets = 0, numSideSets = 0;
  if (ex_get_init(file.id, title, &dimensions, &numPoints, &numElements, &numBlocks, &numNodeSets, &numSideSets) < 0)
    return exodusFailure(path, "cannot read the header");
  if (dimensions != 3)
    return exodusFailure(path, std::to_string(dimensions) + "-dimensional (a tet mesh is 3-dimensional)");
  // A damaged header must not make the reader allocate more than the file could hold (a byte per value).
  struct stat info;
  const long long limit = stat(path.c_str(), &info) == 0 ? static_cast<long long>(info.st_size) : 0;
  if (numPoints < 0 || numElements < 0 || numBlocks < 0 || numSideSets < 0 || 3LL * numPoints > limit ||
      4LL * numElements > limit || numBlocks > limit || numSideSets > limit)
    return exodusFailure(path,
                         "the header claims " + std::to_string(numPoints) + " nodes, " + std::to_string(numElements) +
                           " elements, " + std::to_string(numBlocks) + " blocks and " + std::to_string(numSideSets) +
                           " side sets, impossible in a file of this size");
  std::vector<double> xyz[3];
  for (auto& axis : xyz)
    axis.resize(static_cast<size_t>(numPoints));
  if (numPoints > 0 && ex_get_coord(file.id, xyz[0].data(), xyz[1].data(), xyz[2].data()) < 0)
    return exodusFailure(path, "cannot read the coordinates");
  for (int i = 0; i < numPoints; ++i)
    for (int axis = 0; axis < 3; ++axis)
      mesh.points.push_back(xyz[axis][i]);
  Status s = readBlocks(path, file.id, numBlocks, numPoints, numElements, mesh);
  if (s.ok())
    s = readSideSets(path, file.id, numSideSets, mesh);
  if (s.ok())
    s = readNodalVariables(path, file.id, numPoints, mesh);
  if (s.ok() && mesh.numberOfTets() == 0)
    s = exodusFailure(path, "no tets");
  if (!s.ok())
    mesh = SolverMesh();
  return s;
}

} // namespace volgrid
