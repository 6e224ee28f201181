// Quality of boundary-layer prisms (wedges), the counterpart of Quality.h's tet metrics for mixed grids.
// A prism is given in SolverMesh's order: base a,b,c whose normal ((b-a) x (c-a)) points to the top
// a',b',c' (a' above a). VTK_WEDGE lists the triangles the other way round: (a c b a' c' b').
//
// Definitions:
// - Corner tets: at each of the six corners, the tet of the corner and its three neighbours (the two along
//   its triangle, the one along its column), ordered so that it is positive in a valid prism: at a,
//   (a, b, c, a'); at a', (a', c', b', a); and so on round both triangles.
// - NonPositiveCorners: how many corner tets are not positive, decided exactly (predicates::orient3d). A
//   prism with 0 has every corner convex and well oriented; any other count is an inverted or folded cell.
// - MinScaledJacobian: the smallest over the corners of (e1 x e2).e3 / (|e1| |e2| |e3|) / sin(60 deg), with
//   e1, e2 the corner's triangle edges and e3 its column edge (Verdict's wedge scaled Jacobian). 1 for a
//   right prism on an equilateral triangle, whatever its height (so thin layers are not penalised), lower
//   for sheared or skewed columns and twisted triangles, <= 0 for an inverted corner; 0 when an edge has
//   zero length.
// - Volume: the sum of the signed volumes of the tets (a b c a'), (b c a' b'), (c a' b' c').
#pragma once

#include <cstdint>

namespace volgrid
{
namespace quality
{

struct PrismMetrics
{
  double volume;
  double minScaledJacobian;
  int nonPositiveCorners; // 0..6
};

// p: the six points (xyz triples) in SolverMesh's order.
PrismMetrics prismMetrics(const double* const p[6]);

} // namespace quality
} // namespace volgrid
