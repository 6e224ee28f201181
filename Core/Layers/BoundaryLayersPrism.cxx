// Prism validity and the consistent prism split of BoundaryLayers.h.
#include "BoundaryLayers.h"

#include "Predicates.h"

#include <algorithm>
#include <array>

namespace volgrid
{
namespace
{
// The five tets around the decompositions with apex at relabelled vertex 0: (0,3,4,5) plus the pyramid
// 0-(1,2,5,4) cut by either diagonal. Applied to the six relabellings (three rotations, base/top
// swapped or not) they are every tet of every decomposition of the prism.
const int kApexTets[5][4] = { { 0, 3, 4, 5 }, { 0, 1, 2, 5 }, { 0, 1, 5, 4 }, { 0, 1, 2, 4 }, { 0, 2, 5, 4 } };

std::array<int, 6> relabelling(int rotation, bool swapped)
{
  std::array<int, 6> l{};
  for (int i = 0; i < 3; ++i)
  {
    const int base = (i + rotation) % 3;
    l[i] = swapped ? base + 3 : base;
    l[i + 3] = swapped ? base : base + 3;
  }
  return l;
}

// Expected orientation of each (relabelling, apex tet) on the upright reference prism.
struct ReferenceSigns
{
  int sign[6][5];
  ReferenceSigns()
  {
    const double p[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8660254037844386, 0 },
                             { 0, 0, 1 }, { 1, 0, 1 }, { 0.5, 0.8660254037844386, 1 } };
    for (int r = 0; r < 6; ++r)
    {
      const std::array<int, 6> l = relabelling(r % 3, r >= 3);
      for (int t = 0; t < 5; ++t)
        sign[r][t] = predicates::orient3d(p[l[kApexTets[t][0]]], p[l[kApexTets[t][1]]], p[l[kApexTets[t][2]]],
                                          p[l[kApexTets[t][3]]]);
    }
  }
};
} // namespace

bool layerCellIsValid(const int32_t v[6], const double* points)
{
  static const ReferenceSigns reference;
  const auto at = [&](int k) { return points + 3 * size_t(v[k]); };
  for (int r = 0; r < 6; ++r)
  {
    const std::array<int, 6> l = relabelling(r % 3, r >= 3);
    for (int t = 0; t < 5; ++t)
    {
      const int a = l[kApexTets[t][0]], b = l[kApexTets[t][1]], c = l[kApexTets[t][2]], d = l[kApexTets[t][3]];
      if (v[a] == v[b] || v[a] == v[c] || v[a] == v[d] || v[b] == v[c] || v[b] == v[d] || v[c] == v[d])
        continue;
      if (predicates::orient3d(at(a), at(b), at(c), at(d)) != reference.sign[r][t])
        return false;
    }
  }
  return true;
}

void splitPyramid(const int32_t v[5], int32_t tets[8])
{
  const int m = static_cast<int>(std::min_element(v, v + 4) - v);
  const int32_t a = v[m], b = v[(m + 1) % 4], c = v[(m + 2) % 4], d = v[(m + 3) % 4];
  const int32_t split[8] = { a, b, c, v[4], a, c, d, v[4] };
  std::copy(split, split + 8, tets);
}

bool prismIsValid(const double* a, const double* b, const double* c, const double* d, const double* e, const double* f)
{
  static const ReferenceSigns reference;
  const double* p[6] = { a, b, c, d, e, f };
  for (int r = 0; r < 6; ++r)
  {
    const std::array<int, 6> l = relabelling(r % 3, r >= 3);
    for (int t = 0; t < 5; ++t)
      if (predicates::orient3d(p[l[kApexTets[t][0]]], p[l[kApexTets[t][1]]], p[l[kApexTets[t][2]]],
                               p[l[kApexTets[t][3]]]) != reference.sign[r][t])
        return false;
  }
  return true;
}

void splitPrism(const int32_t v[6], const double* points, int32_t tets[12])
{
  const int smallest = static_cast<int>(std::min_element(v, v + 6) - v);
  const std::array<int, 6> l = relabelling(smallest % 3, smallest >= 3);
  int32_t w[6];
  for (int i = 0; i < 6; ++i)
    w[i] = v[l[i]];
  // w[0] is the smallest id: the quads through it are cut through it; the opposite quad (1,2,5,4)
  // through its own smallest id.
  const bool diagonal15 = std::min(w[1], w[5]) < std::min(w[2], w[4]);
  const int32_t split[3][4] = { { w[0], w[3], w[4], w[5] },
                                { w[0], w[1], w[2], diagonal15 ? w[5] : w[4] },
                                { w[0], diagonal15 ? w[1] : w[2], w[5], w[4] } };
  for (int t = 0; t < 3; ++t)
  {
    int32_t* out = tets + 4 * t;
    std::copy(split[t], split[t] + 4, out);
    // Swapping base and top mirrors the labels: restore positive orientation exactly.
    if (predicates::orient3d(points + 3 * size_t(out[0]), points + 3 * size_t(out[1]), points + 3 * size_t(out[2]),
                             points + 3 * size_t(out[3])) < 0)
      std::swap(out[2], out[3]);
  }
}

} // namespace volgrid
