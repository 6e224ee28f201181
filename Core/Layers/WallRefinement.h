// Splitting the wall triangles around the edges whose prism side faces checkMesh would call highly skewed
// (WallFaceQuality.h). Such an edge lies between two long triangles whose centroids pass far from it, a
// fan of needles from a wing root to its leading edge for instance: no marching can fix its side faces,
// but smaller triangles beside it bring the centroids to it. Each round bisects the longest edge of both
// triangles of every skewed edge at its midpoint, and splits every triangle of the surface that has a
// bisected edge (into 2, 3 or 4, keeping its orientation and patch), so the surface stays conforming:
// a wall point on the edge of a symmetry plane splits the plane's triangle too.
//
// The surface keeps its shape: a new point is its edge's midpoint rounded to doubles (on an axis-aligned
// plane exactly in the plane). Only its triangulation changes, and only where an edge was over the limit.
#pragma once

#include "SurfaceMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

struct WallRefinement
{
  int64_t skewedEdgesBefore = 0; // wall edges over the limit in the input
  int64_t skewedEdgesAfter = 0;  // left when the rounds stopped (0 unless maxRounds was too few)
  int64_t splitEdges = 0;        // edges bisected: the points added
  int64_t addedTriangles = 0;
  int rounds = 0;
};

// Refines `surface` (merged points) around the interior wall edges whose skewness is above
// `skewnessLimit`, where isWall[t] marks the layered triangles. Appends the new points after the existing ones and rewrites the
// triangles in place (a split triangle's first part keeps its index); isWall follows the triangles.
WallRefinement refineSkewedWall(SurfaceMesh& surface, std::vector<uint8_t>& isWall, double skewnessLimit = 4.0,
                                int maxRounds = 8);

// The triangles of `surface` that isWall marks, 3 point ids each.
std::vector<int32_t> wallTriangles(const SurfaceMesh& surface, const std::vector<uint8_t>& isWall);

// What a user should know of it (empty when nothing was split): how many edges were split and why, and
// what is left over the limit.
std::string wallRefinementNote(const WallRefinement& refinement);

} // namespace volgrid
