// sortedCellFaces: outward triangles and quads of tets and prisms, sorted by their point ids.
#include "CellFaces.h"

#include "TetFaces.h"

#include <algorithm>

namespace volgrid
{

std::array<int32_t, 4> cellFaceKey(int32_t a, int32_t b, int32_t c, int32_t d)
{
  std::array<int32_t, 4> k = { a, b, c, d };
  std::sort(k.begin(), k.end()); // a triangle's -1 sorts first: moved last below
  if (d < 0)
    k = { k[1], k[2], k[3], -1 };
  return k;
}

std::vector<CellFace> sortedCellFaces(const std::vector<double>& points, const std::vector<int32_t>& tets,
                                      const std::vector<int32_t>& prisms)
{
  // Outward faces of a prism whose base (0 1 2) has its normal towards the top (3 4 5).
  static const int kPrismFace[5][4] = {
    { 0, 2, 1, -1 }, { 3, 4, 5, -1 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 }
  };
  const int32_t numPrisms = static_cast<int32_t>(prisms.size() / 6);
  std::vector<CellFace> faces;
  faces.reserve(5 * static_cast<size_t>(numPrisms) + tets.size());
  for (int32_t p = 0; p < numPrisms; ++p)
  {
    const int32_t* v = prisms.data() + 6 * static_cast<size_t>(p);
    for (const auto& lf : kPrismFace)
    {
      CellFace f;
      f.loop = { v[lf[0]], v[lf[1]], v[lf[2]], lf[3] < 0 ? -1 : v[lf[3]] };
      f.key = cellFaceKey(f.loop[0], f.loop[1], f.loop[2], f.loop[3]);
      f.cell = p;
      faces.push_back(f);
    }
  }
  for (const TetFace& t : sortedTetFaces(points, tets))
    faces.push_back(
      { { t.key[0], t.key[1], t.key[2], -1 }, { t.loop[0], t.loop[1], t.loop[2], -1 }, numPrisms + t.tet });
  std::sort(faces.begin(), faces.end(),
            [](const CellFace& a, const CellFace& b) { return a.key < b.key || (a.key == b.key && a.cell < b.cell); });
  return faces;
}

} // namespace volgrid
