// Independent check of a mesher result: the tets are valid, their boundary is exactly the input
// surface, and they fill exactly the enclosed volume. Works on plain arrays (no TetMesh), so it can check
// any tet mesh (VolGrid's or TetGen's) against a surface.
#pragma once

#include "Regions.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace volgrid
{

struct BoundaryCheckReport
{
  int64_t tets = 0;
  int64_t invertedTets = 0;           // exact orient3d <= 0
  int64_t badIds = 0;                 // vertex ids out of range or repeated in a tet
  int64_t overSharedFaces = 0;        // faces used by more than two tets
  int64_t sameOrientationFaces = 0;   // interior faces listed in the same orientation by both tets
  int64_t boundaryFaces = 0;          // faces used by one tet
  int64_t boundaryFacesNotInput = 0;  // boundary faces that are not input triangles
  int64_t inputTrianglesNotFaces = 0; // input triangles that are not faces of the mesh
  int64_t inputTrianglesInterior = 0; // input triangles with tets on both sides (keep-all interfaces)
  int64_t boundaryPointsAdded = 0;    // vertices of boundary faces that are not input points
  std::vector<int64_t> firstProblems; // first offending tet or triangle ids
  double tetVolume = 0;
  double enclosedVolume = 0;
  double relativeVolumeError = 0;

  bool meshValid() const
  {
    return invertedTets == 0 && badIds == 0 && overSharedFaces == 0 && sameOrientationFaces == 0;
  }
  bool boundaryEqualsInput() const
  {
    return boundaryFacesNotInput == 0 && inputTrianglesNotFaces == 0 && boundaryPointsAdded == 0;
  }
  bool ok(double volumeTolerance = 1e-9) const
  {
    return meshValid() && boundaryEqualsInput() && relativeVolumeError <= volumeTolerance;
  }
  std::string summary() const;
};

// points: 3 per point (the first numInputPoints are the input points); tets: 4 per tet; triangles: the
// input triangles (3 per triangle, ids into points); enclosedVolume: the expected volume. sharedFaces
// (optional) receives the two tets of every face that exactly two tets share, as the check's face matching
// finds them, so that a caller measuring neighbours (SizeRatio.h) needs no matching of its own. threads: the
// tet loop and the face matching on that many threads (ParallelFor.h's rule); the report is the same for any.
BoundaryCheckReport checkBoundaryConformity(const std::vector<double>& points, int32_t numInputPoints,
                                            const std::vector<int32_t>& tets, const std::vector<int32_t>& triangles,
                                            double enclosedVolume,
                                            std::vector<std::pair<int32_t, int32_t>>* sharedFaces = nullptr,
                                            int threads = 1);

// Volume of the domain the region rule selects, from the surface alone: every shell is oriented
// consistently first (so the input orientation does not matter for EvenOdd/KeepAll), shellDepth is the
// number of closed shells containing each shell. EvenOdd: sum of (-1)^depth |V|; KeepAll: sum of |V| of
// the outermost shells; Orientation: the signed volume with the input orientation as given (normals
// pointing away from the domain are its outward normals, so the signed volume is the domain's volume).
double enclosedVolume(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                      const std::vector<int32_t>& triangleShell, const std::vector<int>& shellDepth, RegionRule rule);

} // namespace volgrid
