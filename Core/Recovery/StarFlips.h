// Flips that reshape the neighbourhood of a boundary Steiner point p that Steiner removal could not
// remove (SteinerRemoval.h).
//
// Why: a segment Steiner point is rounded to doubles, so it lies just off its segment. On planar CAD
// faces its star then holds flat tets between the two diagonals of a flat quad: one diagonal is the
// boundary's, the other an interior edge lying (almost) in the boundary plane. No point sees such a
// cavity and the cone from a cavity vertex does not close when the tets beyond the quad have different
// apexes. Removing the interior diagonal (edge removal: 3-2, 4-4, n-to-(2n-4), exact validity checks,
// never a constraint edge nor an edge along a split segment) or the interior edges next to it changes
// the star so that the removal succeeds.
//
// starFlipCandidates lists the interior edges of p's star and of the tets sharing a face with it,
// nearest first; removeEdgeKeepingRegion flips one away, giving the new tets the region of the old
// ones (a removed edge is interior to one region: no constraint face contains it).
#pragma once

#include "MeshEditor.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

// Edges (x, y) of the tets of p's star and of their face neighbours that are not boundary edges.
// Edges through p come first, then those of the star's outer faces, then those one layer out.
void starFlipCandidates(MeshEditor& editor, const BoundaryConstraints& bc, int32_t p,
                        std::vector<std::pair<int32_t, int32_t>>& out);

// Edge removal of xy (when still an edge) with the region labels of tetRegion kept in step.
bool removeEdgeKeepingRegion(MeshEditor& editor, const BoundaryConstraints& bc, int32_t x, int32_t y,
                             std::vector<int32_t>* tetRegion);

} // namespace volgrid
