// What prism side faces inherit from the wall triangulation, in OpenFOAM's checkMesh measures. A prism
// side face stands on a wall edge, between the columns over the edge's two triangles; for thin layers the
// two cell centres tend to the triangles' centroids, so both measures tend to their values in the surface:
//   skewness          (primitiveMeshTools::faceSkewness: the distance from the face centre to where the
//                     line between the cell centres crosses the face, over the face's extent in that
//                     direction, at least 0.2 of the centres' distance): the edge's midpoint against the
//                     line joining the two centroids; checkMesh's limit is 4.
//   non-orthogonality (the angle between the face's normal and that line): the side face's normal is
//                     across the edge and across the marching direction (the mean of the two triangles'
//                     normals), so a line between centroids that runs along the edge gives a large angle;
//                     checkMesh counts faces above 70 deg as severely non-orthogonal.
// No marching changes either, so an edge above a limit fails it in every layer; the user learns it before
// meshing and can refine or re-triangulate the surface there.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

// One measure over the interior wall edges.
struct WallEdgeExtreme
{
  int64_t edgesOverLimit = 0;         // edges above the limit
  double worst = 0;                   // the largest value
  double worstPoint[3] = { 0, 0, 0 }; // that edge's midpoint
};

struct WallFaceQuality
{
  WallEdgeExtreme skewness;
  WallEdgeExtreme nonOrthogonality; // degrees
};

// Over the interior edges of `triangles` (3 ids each into `points`, xyz, consistently oriented): edges
// shared by exactly two.
WallFaceQuality wallFaceQuality(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                                double skewnessLimit = 4.0, double nonOrthogonalityLimitDegrees = 70.0);

// The interior edges of `triangles` whose skewness is above the limit: 2 point ids each, in triangle order.
std::vector<int32_t> skewedWallEdges(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                                     double skewnessLimit = 4.0);

// The warnings for a user (none when no edge is over a limit): how many edges, the worst and where, what
// checkMesh will then report, and what to do.
std::vector<std::string> wallFaceWarnings(const WallFaceQuality& quality);

} // namespace volgrid
