// Boundary triangle -> owning tet face, by hashing each triangle's sorted vertex triple.
#include "BoundaryFaceOwners.h"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_map>

namespace volgrid
{

const int kExodusTetSide[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 }, { 0, 2, 1 } };

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
  for (int64_t t = 0; t < numTets; ++t)
  {
    const int32_t* v = tets.data() + 4 * t;
    for (int side = 0; side < 4; ++side)
    {
      const int* f = kExodusTetSide[side];
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

} // namespace volgrid
