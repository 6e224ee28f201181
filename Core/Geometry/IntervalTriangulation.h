// Interval dynamic programming over a polygon whose vertices are 0..n-1 in order: the triangulation that
// maximises its smallest triangle score, and reading it back. The DP records, for each chord (i, j), the
// apex k of the triangle on it in choice[i * n + j]. Edge removal (a ring triangulation: MeshEditor::removeEdge
// in recovery, tryEdgeRemoval in the optimiser) runs the DP; they and facet pieces (FacetPieces.cxx, a DP of
// its own with a lexicographic cost) read their triangles back with forEachChosenTriangle.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace volgrid
{

// best(i, j) = max over i < k < j of min(best(i, k), best(k, j), score(i, k, j, bound)), polygon sides
// (j = i + 1) being +inf. Every longer chord starts at `floor` and a split must beat the chord's value so
// far strictly, so ties keep the first k, and a chord that nothing beats keeps floor and choice -1 (no
// polygon containing it can beat floor either). score(i, k, j, bound) is asked only when both sub-polygons
// beat `bound` (the chord's value so far); it may stop early and return any value <= bound once the
// triangle cannot beat it. Returns whether the whole polygon beats floor; choice then holds its apexes.
template<class Score>
bool maxMinTriangulation(int n, double floor, std::vector<double>& best, std::vector<int>& choice, Score&& score)
{
  if (n < 3)
    return false;
  const size_t nn = static_cast<size_t>(n) * static_cast<size_t>(n);
  best.assign(nn, floor);
  choice.assign(nn, -1);
  for (int i = 0; i + 1 < n; ++i)
    best[static_cast<size_t>(i * n + i + 1)] = std::numeric_limits<double>::infinity();
  for (int len = 2; len < n; ++len)
    for (int i = 0; i + len < n; ++i)
    {
      const int j = i + len;
      double bound = floor;
      int bestK = -1;
      for (int k = i + 1; k < j; ++k)
      {
        const double sub = std::min(best[static_cast<size_t>(i * n + k)], best[static_cast<size_t>(k * n + j)]);
        if (!(sub > bound))
          continue;
        const double q = std::min(sub, score(i, k, j, bound));
        if (q > bound)
        {
          bound = q;
          bestK = k;
        }
      }
      best[static_cast<size_t>(i * n + j)] = bound;
      choice[static_cast<size_t>(i * n + j)] = bestK;
    }
  return best[static_cast<size_t>(n - 1)] > floor;
}

// The order of the triangles read back. It decides the ids of the tets made from them (and so the output
// mesh), so each caller keeps the order it has always used.
enum class ChordOrder
{
  PieceAfterApexFirst, // after (i, k, j), the piece (k, j) and all of it first: recovery, facet pieces
  PieceBeforeApexFirst // after (i, k, j), the piece (i, k) and all of it first: the optimiser
};

// Calls fn(i, k, j) for each triangle, from the chord (0, n-1) down, depth first in the given order.
template<class Fn>
void forEachChosenTriangle(const std::vector<int>& choice, int n, Fn&& fn,
                           ChordOrder order = ChordOrder::PieceAfterApexFirst)
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
    if (order == ChordOrder::PieceAfterApexFirst)
    {
      stack.push_back({ i, k });
      stack.push_back({ k, j });
    }
    else
    {
      stack.push_back({ k, j });
      stack.push_back({ i, k });
    }
  }
}

} // namespace volgrid
