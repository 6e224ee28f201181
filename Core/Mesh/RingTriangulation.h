// The tets that replace the star of an edge (x, y) in edge removal, shared by recovery
// (MeshEditor::removeEdge) and the optimiser (tryEdgeRemoval): the ring of vertices around the edge is
// triangulated by maxMinTriangulation (IntervalTriangulation.h), and each triangle (a, b, c) of the ring
// gives the tets (a, b, c, y) and (a, c, b, x).
#pragma once

#include "IntervalTriangulation.h"

#include <array>
#include <cstdint>
#include <vector>

namespace volgrid
{

// Appends the tets of the ring triangulation held in choice (ring.size() vertices), in the given order.
inline void appendRingTets(const std::vector<int>& choice, const std::vector<int32_t>& ring, int32_t x, int32_t y,
                           ChordOrder order, std::vector<std::array<int32_t, 4>>& out)
{
  forEachChosenTriangle(
    choice, static_cast<int>(ring.size()),
    [&](int i, int k, int j)
    {
      out.push_back(
        { { ring[static_cast<size_t>(i)], ring[static_cast<size_t>(k)], ring[static_cast<size_t>(j)], y } });
      out.push_back(
        { { ring[static_cast<size_t>(i)], ring[static_cast<size_t>(j)], ring[static_cast<size_t>(k)], x } });
    },
    order);
}

} // namespace volgrid
