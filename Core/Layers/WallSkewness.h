// The OpenFOAM face skewness that prism layers inherit from the wall triangulation. A prism side face
// stands on a wall edge; its skewness (primitiveMeshTools::faceSkewness: the distance from the face centre
// to where the line between the two cell centres crosses the face, over the face's extent in that
// direction, at least 0.2 of the centres' distance) tends, for thin layers, to the same measure taken in
// the surface: the edge's midpoint against the line joining its two triangles' centroids. No marching
// changes it, so an edge above checkMesh's limit (4) fails checkMesh in every layer; the user learns it
// before meshing and can refine the surface there.
#pragma once

#include <cstdint>
#include <vector>

namespace volgrid
{

struct WallSkewness
{
  int64_t edgesOverLimit = 0;         // interior wall edges above `limit`
  double worst = 0;                   // the largest edge skewness
  double worstPoint[3] = { 0, 0, 0 }; // that edge's midpoint
};

// Over the interior edges of `triangles` (3 ids each into `points`, xyz): edges shared by exactly two.
WallSkewness wallSkewness(const std::vector<double>& points, const std::vector<int32_t>& triangles, double limit = 4.0);

} // namespace volgrid
