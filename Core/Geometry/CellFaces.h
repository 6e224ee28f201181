// The faces of a mixed prism + pyramid + tet mesh without a list of them: each cell's faces are computed on
// demand, oriented out of the cell (triangles and quads), and faceNeighbours matches the two sides of every
// interior face by their point ids. The OpenFOAM writer's owner/neighbour faces, for meshes with and
// without boundary-layer prisms and pyramids, at 4 bytes per cell face instead of a sorted face list.
#pragma once

#include "Status.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

// The sorted point ids of a triangle or (d >= 0) a quad; a triangle's fourth entry is -1.
std::array<int32_t, 4> cellFaceKey(int32_t a, int32_t b, int32_t c, int32_t d = -1);
// "(a b c)" or "(a b c d)": a face for a message.
std::string cellFaceText(const std::array<int32_t, 4>& key);

// Cells numbered prisms first (0..P-1), then pyramids (P..P+Y-1), then tets (P+Y..). Cell faces are numbered
// densely in that order: 5 per prism and pyramid, 4 per tet. Holds references: the arrays must outlive it.
class MixedCellFaces
{
public:
  // Prisms in the SolverMesh order (base a,b,c whose normal points to the top a',b',c') and pyramids in
  // theirs (quad q0..q3 turning towards the apex), both of which the layer mesher checks exactly; tets of
  // either orientation (the exact sign of each decides).
  MixedCellFaces(const std::vector<double>& points, const std::vector<int32_t>& tets,
                 const std::vector<int32_t>& prisms, const std::vector<int32_t>& pyramids);

  int64_t numberOfCells() const { return numPrisms_ + numPyramids_ + numTets_; }
  int64_t numberOfCellFaces() const { return 5 * (numPrisms_ + numPyramids_) + 4 * numTets_; }
  int numberOfFaces(int64_t cell) const { return cell < numPrisms_ + numPyramids_ ? 5 : 4; }
  int64_t firstFace(int64_t cell) const;
  int64_t cellOfFace(int64_t face, int& f) const; // the cell of a cell face, and its f
  // Face f of `cell`, counter-clockwise seen from outside the cell; a triangle's fourth entry is -1.
  std::array<int32_t, 4> loop(int64_t cell, int f) const;
  // The same face's sorted point ids (cellFaceKey), without the orientation test.
  std::array<int32_t, 4> key(int64_t cell, int f) const;

private:
  std::array<int32_t, 4> unoriented(int64_t cell, int f) const;

  const std::vector<double>& points_;
  const std::vector<int32_t>& tets_;
  const std::vector<int32_t>& prisms_;
  const std::vector<int32_t>& pyramids_;
  int64_t numPrisms_, numPyramids_, numTets_;
};

// For every cell face (by its number), the cell on the other side, or -1 where it is on the boundary. The
// faces are matched by their point ids, bucketed by the smallest one: 4 bytes per cell face beside the
// result's 4, and 8 per point. Fails, naming the face and three of its cells, when more than two cells share
// a face; the result is still filled then (the first two cells of such a face paired, the others left on the
// boundary), for a measure of a broken mesh.
Status faceNeighbours(const MixedCellFaces& cells, int64_t numberOfPoints, std::vector<int32_t>& neighbour);

} // namespace volgrid
