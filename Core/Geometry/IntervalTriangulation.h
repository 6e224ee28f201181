// Reading back a polygon triangulation chosen by interval dynamic programming. The polygon's vertices are
// 0..n-1 in order; the DP records, for each chord (i, j), the apex k of the triangle on it in
// choice[i * n + j]. Edge removal (MeshEditor::removeEdge: a ring triangulation) and facet pieces
// (FacetPieces.cxx) both read their triangles back this way.
#pragma once

#include <utility>
#include <vector>

namespace volgrid
{

// Calls fn(i, k, j) for each triangle, from the chord (0, n-1) down (the piece after k first).
template<class Fn>
void forEachChosenTriangle(const std::vector<int>& choice, int n, Fn&& fn)
{
  std::vector<std::pair<int, int>> stack = { { 0, n - 1 } };
  while (!stack.empty())
  {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2)
      continue;
    const int k = choice[static_cast<size_t>(i * n + j)];
    fn(i, k, j);
    stack.push_back({ i, k });
    stack.push_back({ k, j });
  }
}

} // namespace volgrid
