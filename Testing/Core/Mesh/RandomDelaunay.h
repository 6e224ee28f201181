// The Mesh tests' input: a ghost-free Delaunay mesh of n uniform random points in the unit cube.
#pragma once

#include "Delaunay.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

inline void randomDelaunay(volgrid::TetMesh& mesh, int n, unsigned seed = 7)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz;
  for (int i = 0; i < 3 * n; ++i)
    xyz.push_back(u(rng));
  std::vector<int32_t> map;
  volgrid::DelaunayOptions opt;
  opt.keepGhosts = false;
  ASSERT_TRUE(volgrid::buildDelaunay(xyz.data(), static_cast<size_t>(n), opt, mesh, map).ok());
}

// The mesh's tets as plain arrays (4 vertex ids per tet, in slot order), as the array-based checks take them.
inline std::vector<int32_t> flatTets(const volgrid::TetMesh& mesh)
{
  std::vector<int32_t> tets;
  mesh.forEachTet(
    [&](int32_t u)
    {
      for (int i = 0; i < 4; ++i)
        tets.push_back(mesh.vertex(u, i));
    });
  return tets;
}
