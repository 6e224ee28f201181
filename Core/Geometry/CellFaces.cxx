// MixedCellFaces: outward triangles and quads of prisms, pyramids and tets on demand; faceNeighbours: the
// cell across each of them, by a counting sort of the faces on their smallest point id.
#include "CellFaces.h"

#include "Predicates.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

namespace volgrid
{
namespace
{
// Outward faces of a prism whose base (0 1 2) has its normal towards the top (3 4 5), of a pyramid whose
// quad (0 1 2 3) has its normal towards the apex 4 (the prism's with its top collapsed), and of a positive
// tet (a b c d): opposite d, c, b, a.
const int kPrismFace[5][4] = { { 0, 2, 1, -1 }, { 3, 4, 5, -1 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 } };
const int kPyramidFace[5][4] = { { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 }, { 2, 3, 4, -1 }, { 3, 0, 4, -1 } };
const int kTetFace[4][4] = { { 0, 2, 1, -1 }, { 0, 1, 3, -1 }, { 0, 3, 2, -1 }, { 1, 2, 3, -1 } };

std::array<int32_t, 4> localFace(const int32_t* v, const int (&lf)[4])
{
  return { v[lf[0]], v[lf[1]], v[lf[2]], lf[3] < 0 ? -1 : v[lf[3]] };
}

} // namespace

std::string cellFaceText(const std::array<int32_t, 4>& key)
{
  std::string text = "(" + std::to_string(key[0]);
  for (int k = 1; k < 4 && key[k] >= 0; ++k)
    text += " " + std::to_string(key[k]);
  return text + ")";
}

std::array<int32_t, 4> cellFaceKey(int32_t a, int32_t b, int32_t c, int32_t d)
{
  std::array<int32_t, 4> k = { a, b, c, d };
  std::sort(k.begin(), k.end()); // a triangle's -1 sorts first: moved last below
  if (d < 0)
    k = { k[1], k[2], k[3], -1 };
  return k;
}

MixedCellFaces::MixedCellFaces(const std::vector<double>& points, const std::vector<int32_t>& tets,
                               const std::vector<int32_t>& prisms, const std::vector<int32_t>& pyramids)
  : points_(points)
  , tets_(tets)
  , prisms_(prisms)
  , pyramids_(pyramids)
  , numPrisms_(static_cast<int64_t>(prisms.size() / 6))
  , numPyramids_(static_cast<int64_t>(pyramids.size() / 5))
  , numTets_(static_cast<int64_t>(tets.size() / 4))
{
}

int64_t MixedCellFaces::firstFace(int64_t cell) const
{
  const int64_t layerCells = numPrisms_ + numPyramids_;
  return cell < layerCells ? 5 * cell : 5 * layerCells + 4 * (cell - layerCells);
}

std::array<int32_t, 4> MixedCellFaces::unoriented(int64_t cell, int f) const
{
  if (cell < numPrisms_)
    return localFace(prisms_.data() + 6 * cell, kPrismFace[f]);
  if (cell < numPrisms_ + numPyramids_)
    return localFace(pyramids_.data() + 5 * (cell - numPrisms_), kPyramidFace[f]);
  return localFace(tets_.data() + 4 * (cell - numPrisms_ - numPyramids_), kTetFace[f]);
}

int64_t MixedCellFaces::cellOfFace(int64_t face, int& f) const
{
  const int64_t layerCells = numPrisms_ + numPyramids_;
  if (face < 5 * layerCells)
  {
    f = static_cast<int>(face % 5);
    return face / 5;
  }
  f = static_cast<int>((face - 5 * layerCells) % 4);
  return layerCells + (face - 5 * layerCells) / 4;
}

std::array<int32_t, 4> MixedCellFaces::loop(int64_t cell, int f) const
{
  std::array<int32_t, 4> l = unoriented(cell, f);
  if (cell >= numPrisms_ + numPyramids_)
  {
    const int32_t* v = tets_.data() + 4 * (cell - numPrisms_ - numPyramids_);
    const double* p = points_.data();
    if (predicates::orient3d(p + 3 * v[0], p + 3 * v[1], p + 3 * v[2], p + 3 * v[3]) < 0)
      std::swap(l[1], l[2]);
  }
  return l;
}

std::array<int32_t, 4> MixedCellFaces::key(int64_t cell, int f) const
{
  const std::array<int32_t, 4> l = unoriented(cell, f);
  return cellFaceKey(l[0], l[1], l[2], l[3]);
}

namespace
{
// Counting sort of the cell faces by their smallest point id: bucket p of `byPoint` is [start[p], start[p + 1]).
Status facesByFirstPoint(const MixedCellFaces& cells, int64_t numberOfPoints, std::vector<int64_t>& start,
                         std::vector<uint32_t>& byPoint)
{
  start.assign(static_cast<size_t>(numberOfPoints) + 1, 0);
  for (int64_t c = 0; c < cells.numberOfCells(); ++c)
    for (int f = 0; f < cells.numberOfFaces(c); ++f)
    {
      const std::array<int32_t, 4> key = cells.key(c, f);
      if (key[0] < 0 || std::max(key[2], key[3]) >= numberOfPoints)
        return Status::failure(ErrorKind::InvalidOption, "cell " + std::to_string(c) + " has a point id out of range " +
                                                           cellFaceText(key));
      ++start[static_cast<size_t>(key[0]) + 1];
    }
  for (size_t p = 1; p < start.size(); ++p)
    start[p] += start[p - 1];
  byPoint.resize(static_cast<size_t>(cells.numberOfCellFaces()));
  for (int64_t c = 0; c < cells.numberOfCells(); ++c)
    for (int f = 0; f < cells.numberOfFaces(c); ++f)
      byPoint[static_cast<size_t>(start[static_cast<size_t>(cells.key(c, f)[0])]++)] =
        static_cast<uint32_t>(cells.firstFace(c) + f);
  // Each bucket's start moved to the next one's: shift back.
  for (size_t p = start.size() - 1; p > 0; --p)
    start[p] = start[p - 1];
  start[0] = 0;
  return Status::success();
}
} // namespace

Status faceNeighbours(const MixedCellFaces& cells, int64_t numberOfPoints, std::vector<int32_t>& neighbour)
{
  const int64_t numCells = cells.numberOfCells(), numFaces = cells.numberOfCellFaces();
  if (numCells > std::numeric_limits<int32_t>::max() || numFaces > std::numeric_limits<uint32_t>::max())
    return Status::failure(ErrorKind::InvalidOption,
                           "the mesh has " + std::to_string(numCells) + " cells: more than 32-bit labels hold");
  std::vector<int64_t> start;
  std::vector<uint32_t> byPoint;
  Status s = facesByFirstPoint(cells, numberOfPoints, start, byPoint);
  if (!s.ok())
    return s;
  neighbour.assign(static_cast<size_t>(numFaces), -1);
  struct Entry
  {
    std::array<int32_t, 4> key;
    int32_t cell;
    uint32_t face;
    bool operator<(const Entry& o) const { return key < o.key || (key == o.key && cell < o.cell); }
  };
  std::vector<Entry> bucket;
  for (size_t p = 0; p + 1 < start.size(); ++p)
  {
    bucket.clear();
    for (int64_t i = start[p]; i < start[p + 1]; ++i)
    {
      const uint32_t id = byPoint[static_cast<size_t>(i)];
      int f = 0;
      const int64_t c = cells.cellOfFace(id, f);
      bucket.push_back({ cells.key(c, f), static_cast<int32_t>(c), id });
    }
    std::sort(bucket.begin(), bucket.end());
    for (size_t i = 0; i + 1 < bucket.size(); ++i)
    {
      if (bucket[i + 1].key != bucket[i].key)
        continue;
      if (i + 2 < bucket.size() && bucket[i + 2].key == bucket[i].key && s.ok())
        s = Status::failure(ErrorKind::InvalidOption,
                            "face " + cellFaceText(bucket[i].key) + " is shared by more than two cells (" +
                              std::to_string(bucket[i].cell) + ", " + std::to_string(bucket[i + 1].cell) + ", " +
                              std::to_string(bucket[i + 2].cell) + ")");
      neighbour[bucket[i].face] = bucket[i + 1].cell;
      neighbour[bucket[i + 1].face] = bucket[i].cell;
      ++i;
    }
  }
  return s;
}

} // namespace volgrid
