// sortedTetFaces: four outward faces per tet, sorted by their point ids.
#include "TetFaces.h"

#include "Predicates.h"

#include <algorithm>

namespace volgrid
{

std::vector<TetFace> sortedTetFaces(const std::vector<double>& points, const std::vector<int32_t>& tets)
{
  // Outward faces of a positive tet (a b c d): opposite d, c, b, a.
  static const int kFace[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
  std::vector<TetFace> faces;
  faces.reserve(tets.size());
  const double* p = points.data();
  for (size_t t = 0; t < tets.size() / 4; ++t)
  {
    const int32_t* v = tets.data() + 4 * t;
    const bool positive = predicates::orient3d(p + 3 * v[0], p + 3 * v[1], p + 3 * v[2], p + 3 * v[3]) >= 0;
    for (const auto& lf : kFace)
    {
      TetFace f;
      f.loop = { v[lf[0]], v[lf[1]], v[lf[2]] };
      if (!positive)
        std::swap(f.loop[1], f.loop[2]);
      f.key = f.loop;
      std::sort(f.key.begin(), f.key.end());
      f.tet = static_cast<int32_t>(t);
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end(),
            [](const TetFace& a, const TetFace& b) { return a.key < b.key || (a.key == b.key && a.tet < b.tet); });
  return faces;
}

} // namespace volgrid
