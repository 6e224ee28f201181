// sortedCellFaces: outward triangles and quads of tets, prisms and pyramids, sorted by their point ids.
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

namespace
{
// The five outward faces of each cell of `cells` (n points each, local loops `local`), numbered from `first`.
void addCellFaces(const std::vector<int32_t>& cells, size_t n, const int (&local)[5][4], int32_t first,
                  std::vector<CellFace>& faces)
{
  for (size_t c = 0; c < cells.size() / n; ++c)
  {
    const int32_t* v = cells.data() + n * c;
    for (const auto& lf : local)
    {
      CellFace f;
      f.loop = { v[lf[0]], v[lf[1]], v[lf[2]], lf[3] < 0 ? -1 : v[lf[3]] };
      f.key = cellFaceKey(f.loop[0], f.loop[1], f.loop[2], f.loop[3]);
      f.cell = first + static_cast<int32_t>(c);
      faces.push_back(f);
    }
  }
}
} // namespace

std::vector<CellFace> sortedCellFaces(const std::vector<double>& points, const std::vector<int32_t>& tets,
                                      const std::vector<int32_t>& prisms, const std::vector<int32_t>& pyramids)
{
  // Outward faces of a prism whose base (0 1 2) has its normal towards the top (3 4 5), and of a pyramid
  // whose quad (0 1 2 3) has its normal towards the apex 4: the prism's with its top collapsed.
  static const int kPrismFace[5][4] = {
    { 0, 2, 1, -1 }, { 3, 4, 5, -1 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 }
  };
  static const int kPyramidFace[5][4] = {
    { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 }, { 2, 3, 4, -1 }, { 3, 0, 4, -1 }
  };
  const int32_t numPrisms = static_cast<int32_t>(prisms.size() / 6);
  const int32_t numLayerCells = numPrisms + static_cast<int32_t>(pyramids.size() / 5);
  std::vector<CellFace> faces;
  faces.reserve(5 * static_cast<size_t>(numLayerCells) + tets.size());
  addCellFaces(prisms, 6, kPrismFace, 0, faces);
  addCellFaces(pyramids, 5, kPyramidFace, numPrisms, faces);
  for (const TetFace& t : sortedTetFaces(points, tets))
    faces.push_back(
      { { t.key[0], t.key[1], t.key[2], -1 }, { t.loop[0], t.loop[1], t.loop[2], -1 }, numLayerCells + t.tet });
  std::sort(faces.begin(), faces.end(),
            [](const CellFace& a, const CellFace& b) { return a.key < b.key || (a.key == b.key && a.cell < b.cell); });
  return faces;
}

} // namespace volgrid
