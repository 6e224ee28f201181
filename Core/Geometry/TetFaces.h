// The faces of a tet mesh as a sorted list: each tet's four faces, oriented out of the tet, sorted by their
// point ids, so that the two sides of an interior face are neighbours in the list and a boundary face
// stands alone. Shared by the OpenFOAM writer (owner/neighbour faces) and the CFD quality metrics.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

struct TetFace
{
  std::array<int32_t, 3> key;  // the point ids, sorted
  std::array<int32_t, 3> loop; // the point ids, counter-clockwise seen from outside the tet
  int32_t tet;
};

// Orientation from the exact sign of each tet (orient3d), so inverted tets get outward faces too.
std::vector<TetFace> sortedTetFaces(const std::vector<double>& points, const std::vector<int32_t>& tets);

} // namespace volgrid
