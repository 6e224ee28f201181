// The boundary faces of a tet mesh, for tests that check that an operation kept the boundary (header-only,
// test code).
#pragma once

#include "TetMesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>

namespace volgrid
{
namespace testmesh
{

// The faces without a neighbour, each rotated to start at its smallest vertex id (which keeps its
// orientation), so that two meshes with the same oriented boundary give the same set.
inline std::set<std::array<int32_t, 3>> hullFaces(const TetMesh& m)
{
  std::set<std::array<int32_t, 3>> faces;
  m.forEachTet(
    [&](int32_t t)
    {
      for (int i = 0; i < 4; ++i)
        if (m.neighbor(t, i) < 0)
        {
          int32_t f[3];
          m.faceVertices(t, i, f);
          std::rotate(f, std::min_element(f, f + 3), f + 3);
          faces.insert({ f[0], f[1], f[2] });
        }
    });
  return faces;
}

} // namespace testmesh
} // namespace volgrid
