// Boundary triangle -> owning tet face, by hashing each triangle's sorted vertex triple; the faces of
// prisms and pyramids by sorted keys.
#include "BoundaryFaceOwners.h"

#include "CellFaces.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace volgrid
{

const int kExodusTetSide[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, { 0, 2, 1 } };
const int kExodusWedgeSide[5][4] = { { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 0, 3, 5, 2 }, { 0, 2, 1, -1 }, { 3, 4, 5, -1 } };
const int kExodusPyramidSide[5][4] = { { 0, 1, 4, -1 },
                                       { 1, 2, 4, -1 },
                                       { 2, 3, 4, -1 },
                                       { 3, 0, 4, -1 },
                                       { 0, 3, 2, 1 } };

namespace
{
using Key = std::array<int32_t, 3>;

Key sortedKey(int32_t a, int32_t b, int32_t c)
{
  Key k = { a, b, c };
  std::sort(k.begin(), k.end());
  return k;
}

struct KeyHash
{
  size_t operator()(const Key& k) const
  {
    uint64_t h = static_cast<uint32_t>(k[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<uint32_t>(k[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<uint32_t>(k[2]);
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

// The sides of the cells of one layer kind (n points each, numbered from `first`) by sorted key.
void addLayerSides(const std::vector<int32_t>& cells, size_t n, const int (&sides)[5][4], int64_t first,
                   std::vector<std::pair<std::array<int32_t, 4>, CellSide>>& out)
{
  for (size_t c = 0; c < cells.size() / n; ++c)
    for (int side = 0; side < 5; ++side)
    {
      const int* f = sides[side];
      const int32_t* v = cells.data() + n * c;
      out.push_back(
        { cellFaceKey(v[f[0]], v[f[1]], v[f[2]], f[3] < 0 ? -1 : v[f[3]]), { first + static_cast<int64_t>(c), side } });
    }
}
} // namespace

Status findBoundaryFaceOwners(const SolverMesh& mesh, std::vector<FaceOwner>& owners)
{
  return findBoundaryFaceOwners(mesh.tets, mesh.triangles, owners);
}

Status findBoundaryFaceOwners(const std::vector<int32_t>& tets, const std::vector<int32_t>& triangles,
                              std::vector<FaceOwner>& owners)
{
  const int64_t numTriangles = static_cast<int64_t>(triangles.size() / 3);
  const int64_t numTets = static_cast<int64_t>(tets.size() / 4);
  owners.assign(static_cast<size_t>(numTriangles), FaceOwner());
  std::unordered_map<Key, int64_t, KeyHash> triangleOf;
  triangleOf.reserve(static_cast<size_t>(numTriangles));
  for (int64_t t = 0; t < numTriangles; ++t)
  {
    const int32_t* v = triangles.data() + 3 * t;
    triangleOf.emplace(sortedKey(v[0], v[1], v[2]), t);
  }
  // Only a face whose three vertices are all on triangles can be one: most faces skip the hash look-up.
  std::vector<uint8_t> onTriangle;
  for (int32_t v : triangles)
    if (v >= 0)
    {
      if (static_cast<size_t>(v) >= onTriangle.size())
        onTriangle.resize(static_cast<size_t>(v) + 1, 0);
      onTriangle[static_cast<size_t>(v)] = 1;
    }
  const auto isOnTriangle = [&](int32_t v)
  { return v >= 0 && static_cast<size_t>(v) < onTriangle.size() && onTriangle[static_cast<size_t>(v)]; };
  for (int64_t t = 0; t < numTets; ++t)
  {
    const int32_t* v = tets.data() + 4 * t;
    const bool on[4] = { isOnTriangle(v[0]), isOnTriangle(v[1]), isOnTriangle(v[2]), isOnTriangle(v[3]) };
    if (on[0] + on[1] + on[2] + on[3] < 3)
      continue;
    for (int side = 0; side < 4; ++side)
    {
      const int* f = kExodusTetSide[side];
      if (!on[f[0]] || !on[f[1]] || !on[f[2]])
        continue;
      const auto it = triangleOf.find(sortedKey(v[f[0]], v[f[1]], v[f[2]]));
      if (it != triangleOf.end() && owners[static_cast<size_t>(it->second)].tet < 0)
        owners[static_cast<size_t>(it->second)] = { t, side };
    }
  }
  std::vector<int64_t> orphans;
  for (int64_t t = 0; t < numTriangles; ++t)
    if (owners[static_cast<size_t>(t)].tet < 0)
      orphans.push_back(t);
  if (orphans.empty())
    return Status::success();
  const std::vector<int64_t> first(orphans.begin(), orphans.begin() + std::min<size_t>(orphans.size(), 5));
  return Status::failure(ErrorKind::InvalidOption,
                         std::to_string(orphans.size()) + " boundary triangle(s) are not a face of any tet (first " +
                           std::to_string(first[0]) + ")",
                         first);
}

Status findBoundaryCellSides(const SolverMesh& mesh, std::vector<CellSide>& owners)
{
  std::vector<FaceOwner> tetOwners;
  const Status tets = findBoundaryFaceOwners(mesh, tetOwners);
  if (!tets.ok() && mesh.prisms.empty() && mesh.pyramids.empty())
    return tets;
  std::vector<std::pair<std::array<int32_t, 4>, CellSide>> prismFaces; // and the pyramids'
  addLayerSides(mesh.prisms, 6, kExodusWedgeSide, mesh.numberOfTets(), prismFaces);
  addLayerSides(mesh.pyramids, 5, kExodusPyramidSide,
                mesh.numberOfTets() + static_cast<int64_t>(mesh.prismRegion.size()), prismFaces);
  std::sort(prismFaces.begin(), prismFaces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const auto prismOwner = [&](const std::array<int32_t, 4>& key)
  {
    const auto it = std::lower_bound(prismFaces.begin(), prismFaces.end(), key,
                                     [](const auto& a, const std::array<int32_t, 4>& k) { return a.first < k; });
    return it != prismFaces.end() && it->first == key ? it->second : CellSide();
  };
  owners.assign(mesh.triangles.size() / 3 + mesh.quads.size() / 4, CellSide());
  for (size_t t = 0; t < owners.size(); ++t)
  {
    const bool triangle = t < mesh.triangles.size() / 3;
    if (triangle && tetOwners[t].tet >= 0)
      owners[t] = { tetOwners[t].tet, tetOwners[t].side };
    else if (triangle)
      owners[t] = prismOwner(cellFaceKey(mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]));
    else
    {
      const int32_t* q = mesh.quads.data() + 4 * (t - mesh.triangles.size() / 3);
      owners[t] = prismOwner(cellFaceKey(q[0], q[1], q[2], q[3]));
    }
    if (owners[t].cell < 0)
      return Status::failure(ErrorKind::InvalidOption,
                             std::string("boundary ") + (triangle ? "triangle " : "quad ") +
                               std::to_string(triangle ? t : t - mesh.triangles.size() / 3) +
                               " is not a face of any tet, prism or pyramid");
  }
  return Status::success();
}

} // namespace volgrid
