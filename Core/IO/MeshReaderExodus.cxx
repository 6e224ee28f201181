// Exodus II reader (Debian's libexoIIv2c): the TETRA element blocks are the regions (in file order, named
// after the block); WEDGE and PYRAMID blocks the boundary-layer prisms and pyramids (Exodus's node orders
// are SolverMesh's, as MeshWriterExodus.cxx writes them), in the region of the block's name without
// "_prisms" / "_pyramids" (a new region when no block had that name). The side sets are the patches (named
// after the set), each side a boundary triangle or quad taken from its element in the Exodus side order
// (kExodusTetSide, kExodusWedgeSide, kExodusPyramidSide); nodal variables at the last time step are the
// point fields (a solver's target size, ...). Blocks of other element types are refused.
#include "BoundaryFaceOwners.h"
#include "MeshReader.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exodusII.h>
#include <iterator>
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

// An element by its Exodus number: which kind of cell (Kind) and its index among those.
enum class Kind : int8_t
{
  Tet,
  Prism,
  Pyramid
};
struct CellRef
{
  Kind kind = Kind::Tet;
  int64_t index = 0;
};

// The label named `name` (without `suffix`, as the writer names a layer block "<region><suffix>"): the
// first region of that name, else a new one.
int32_t regionNamed(NameTable& names, const std::string& block, const std::string& suffix)
{
  const bool suffixed =
    block.size() > suffix.size() && block.compare(block.size() - suffix.size(), suffix.size(), suffix) == 0;
  const std::string base = suffixed ? block.substr(0, block.size() - suffix.size()) : block;
  for (const auto& entry : names)
    if (entry.second == base)
      return entry.first;
  const int32_t label = names.empty() ? 1 : names.rbegin()->first + 1;
  names[label] = base;
  return label;
}

Status readBlocks(const std::string& path, int file, int numBlocks, int64_t numPoints, int numElements,
                  SolverMesh& mesh, std::vector<CellRef>& elementOf)
{
  std::vector<int> ids(static_cast<size_t>(numBlocks));
  if (numBlocks > 0 && ex_get_elem_blk_ids(file, ids.data()) < 0)
    return exodusFailure(path, "cannot read the element block ids");
  const std::vector<std::string> names = entityNames(file, EX_ELEM_BLOCK, numBlocks);
  // The element types read by their name's start, their nodes, where they go and the writer's suffix.
  const struct
  {
    const char* prefix;
    int nodes;
    Kind kind;
    std::vector<int32_t>* cells;
    std::vector<int32_t>* regions;
    const char* suffix;
  } kinds[] = { { "TET", 4, Kind::Tet, &mesh.tets, &mesh.tetRegion, nullptr },
                { "WEDGE", 6, Kind::Prism, &mesh.prisms, &mesh.prismRegion, "_prisms" },
                { "PYRA", 5, Kind::Pyramid, &mesh.pyramids, &mesh.pyramidRegion, "_pyramids" } };
  for (int b = 0; b < numBlocks; ++b)
  {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, perElement = 0, attributes = 0;
    if (ex_get_elem_block(file, ids[b], type, &count, &perElement, &attributes) < 0)
      return exodusFailure(path, "cannot read element block " + std::to_string(ids[b]));
    const std::string upperType = upper(type);
    if (count == 0)
      continue;
    if (count < 0 || count > numElements - static_cast<int>(elementOf.size()))
      return exodusFailure(path,
                           "element block " + std::to_string(ids[b]) + " claims " + std::to_string(count) +
                             " elements of " + std::to_string(numElements));
    const auto* kind =
      std::find_if(std::begin(kinds), std::end(kinds),
                   [&](const auto& k) { return upperType.compare(0, std::strlen(k.prefix), k.prefix) == 0; });
    if (kind == std::end(kinds) || perElement != kind->nodes)
      return exodusFailure(path,
                           "element block " + std::to_string(ids[b]) + " holds " + type + " elements with " +
                             std::to_string(perElement) +
                             " nodes (only 4-node tets, 6-node wedges and 5-node pyramids are read)");
    std::vector<int> connectivity(static_cast<size_t>(count) * static_cast<size_t>(perElement));
    if (ex_get_elem_conn(file, ids[b], connectivity.data()) < 0)
      return exodusFailure(path, "cannot read the connectivity of block " + std::to_string(ids[b]));
    for (int v : connectivity)
    {
      if (v < 1 || v > numPoints)
        return exodusFailure(path,
                             "block " + std::to_string(ids[b]) + " names node " + std::to_string(v) + " of " +
                               std::to_string(numPoints));
      kind->cells->push_back(v - 1);
    }
    const std::string name = names[b].empty() ? "block" + std::to_string(ids[b]) : names[b];
    int32_t region = 0;
    if (kind->suffix)
      region = regionNamed(mesh.regionNames, name, kind->suffix);
    else
    {
      region = mesh.regionNames.empty() ? 1 : mesh.regionNames.rbegin()->first + 1;
      mesh.regionNames[region] = name;
    }
    const int64_t first = static_cast<int64_t>(kind->regions->size());
    kind->regions->insert(kind->regions->end(), static_cast<size_t>(count), region);
    for (int e = 0; e < count; ++e)
      elementOf.push_back({ kind->kind, first + e });
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

Status readSideSets(const std::string& path, int file, int numSets, const std::vector<CellRef>& elementOf,
                    SolverMesh& mesh)
{
  std::vector<int> ids(static_cast<size_t>(numSets));
  if (numSets > 0 && ex_get_side_set_ids(file, ids.data()) < 0)
    return exodusFailure(path, "cannot read the side set ids");
  const std::vector<std::string> names = entityNames(file, EX_SIDE_SET, numSets);
  const int64_t numCells = static_cast<int64_t>(elementOf.size());
  for (int k = 0; k < numSets; ++k)
  {
    int numSides = 0, numFactors = 0;
    if (ex_get_side_set_param(file, ids[k], &numSides, &numFactors) < 0 || numSides < 0 || numSides > 5 * numCells)
      return exodusFailure(path,
                           "cannot read side set " + std::to_string(ids[k]) + " (or it has more sides than the cells)");
    std::vector<int> elements(static_cast<size_t>(numSides)), sides(static_cast<size_t>(numSides));
    if (numSides > 0 && ex_get_side_set(file, ids[k], elements.data(), sides.data()) < 0)
      return exodusFailure(path, "cannot read the sides of side set " + std::to_string(ids[k]));
    const int32_t patch = k + 1;
    mesh.patchNames[patch] = names[k].empty() ? "sideset" + std::to_string(ids[k]) : names[k];
    for (int s = 0; s < numSides; ++s)
    {
      const CellRef cell = elements[s] >= 1 && elements[s] <= numCells ? elementOf[elements[s] - 1] : CellRef();
      const int numCellSides = cell.kind == Kind::Tet ? 4 : 5;
      if (elements[s] < 1 || elements[s] > numCells || sides[s] < 1 || sides[s] > numCellSides)
        return exodusFailure(path,
                             "side set " + std::to_string(ids[k]) + " names side " + std::to_string(sides[s]) +
                               " of element " + std::to_string(elements[s]) + " of " + std::to_string(numCells) +
                               " (tets have sides 1-4, wedges and pyramids 1-5)");
      if (cell.kind == Kind::Tet)
      {
        const int32_t* tet = mesh.tets.data() + 4 * cell.index;
        for (int corner : kExodusTetSide[sides[s] - 1])
          mesh.triangles.push_back(tet[corner]);
        mesh.trianglePatch.push_back(patch);
        continue;
      }
      const bool prism = cell.kind == Kind::Prism;
      const int32_t* v = prism ? mesh.prisms.data() + 6 * cell.index : mesh.pyramids.data() + 5 * cell.index;
      const int* side = prism ? kExodusWedgeSide[sides[s] - 1] : kExodusPyramidSide[sides[s] - 1];
      const bool quad = side[3] >= 0;
      for (int corner = 0; corner < (quad ? 4 : 3); ++corner)
        (quad ? mesh.quads : mesh.triangles).push_back(v[side[corner]]);
      (quad ? mesh.quadPatch : mesh.trianglePatch).push_back(patch);
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
  std::vector<CellRef> elementOf; // by Exodus element number - 1
  Status s = readBlocks(path, file.id, numBlocks, numPoints, numElements, mesh, elementOf);
  if (s.ok())
    s = readSideSets(path, file.id, numSideSets, elementOf, mesh);
  if (s.ok())
    s = readNodalVariables(path, file.id, numPoints, mesh);
  if (s.ok() && !finishReadCells(mesh))
    s = exodusFailure(path, "no tets, wedges or pyramids");
  if (!s.ok())
    mesh = SolverMesh();
  return s;
}

} // namespace volgrid
