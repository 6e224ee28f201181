// The faces of a mixed tet + prism + pyramid mesh as a sorted list, as TetFaces.h does for tets: every cell's faces
// oriented out of the cell (triangles and quads), sorted by their point ids, so that the two sides of an
// interior face are neighbours in the list and a boundary face stands alone. The OpenFOAM writer's
// owner/neighbour faces for meshes with boundary-layer prisms and pyramids.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

struct CellFace
{
  std::array<int32_t, 4> key;  // the point ids sorted; a triangle's fourth entry is -1
  std::array<int32_t, 4> loop; // counter-clockwise seen from outside the cell; a triangle's fourth is -1
  int32_t cell;                // prisms first (0..P-1), then pyramids (P..P+Y-1), then tets (P+Y..)
  int size() const { return loop[3] < 0 ? 3 : 4; }
};

// The sorted key of a triangle or (d >= 0) a quad, as CellFace::key.
std::array<int32_t, 4> cellFaceKey(int32_t a, int32_t b, int32_t c, int32_t d = -1);

// Tets oriented by the exact sign of each (orient3d, as sortedTetFaces); prisms in the SolverMesh order
// (base a,b,c whose normal points to the top a',b',c') and pyramids in theirs (quad q0..q3 turning
// towards the apex), both of which the layer mesher checks exactly.
std::vector<CellFace> sortedCellFaces(const std::vector<double>& points, const std::vector<int32_t>& tets,
                                      const std::vector<int32_t>& prisms, const std::vector<int32_t>& pyramids);

} // namespace volgrid
