// Surface repair for Surface Prep (paper 6.1, 6.3): weld, remove zero-area and duplicate triangles,
// stitch, fill boundary loops, orient shells consistently and away from the domain.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "SurfaceMesh.h"

#include <string>
#include <vector>

namespace volgrid
{

struct SurfaceRepairOptions
{
  // Points on open edges closer than weldTolerance * (bounding-box diagonal) are merged; 0 = exactly
  // coincident only. (Points of closed parts are never welded: they are distinct vertices.)
  double weldTolerance = 0.0;
  bool removeDegenerate = true; // repeated ids or exactly collinear corners
  bool removeDuplicates = true; // same point set as an earlier triangle
  // Stitch: boundary points within stitchTolerance * diagonal are merged (parts sharing a seam).
  bool stitch = true;
  double stitchTolerance = 0.0; // 0: exact coincidence only
  // Fill boundary loops with at most this many edges (0: no filling).
  int maxHoleEdges = 0;
  bool refineFilledHoles = true;  // insert points so patch edges match the surrounding edge lengths
  int fairingIterations = 30;     // smoothing of the inserted points (0: flat refinement)
  bool orientConsistently = true; // flip triangles so each shell is consistently oriented
  bool orientForDomain = true;    // closed shells: even nesting depth outward, odd depth inward
  Progress* progress = nullptr;
};

struct SurfaceRepairReport
{
  int64_t weldedPoints = 0;
  int64_t removedDegenerate = 0;
  int64_t removedDuplicates = 0;
  int64_t stitchedPoints = 0;
  int64_t unreferencedPointsRemoved = 0;
  int64_t loopsFilled = 0;
  int64_t loopsLeftOpen = 0;
  int64_t trianglesAdded = 0;
  int64_t pointsAdded = 0;
  int64_t trianglesFlipped = 0; // by the consistency pass
  int64_t shellsFlipped = 0;    // by the domain orientation pass
  int64_t nonOrientableShells = 0;
  std::vector<std::string> notes;
  std::string summary() const;
};

// Runs the enabled steps in order: weld, remove degenerate, remove duplicates, stitch, fill, orient.
// Unreferenced points are dropped at the end. Point ids change; patch ids follow their triangles
// (filled patches take the patch id of a neighbouring triangle).
Status repairSurface(SurfaceMesh& mesh, const SurfaceRepairOptions& options, SurfaceRepairReport* report = nullptr);

// The individual steps (each returns its count).
int64_t weldPoints(SurfaceMesh& mesh, double absoluteTolerance, bool boundaryOnly = false);
int64_t removeDegenerateTriangles(SurfaceMesh& mesh);
int64_t removeDuplicateTriangles(SurfaceMesh& mesh);
// Returns the number of loops filled; loopsLeftOpen receives loops larger than maxEdges (or unfillable).
int64_t fillHoles(SurfaceMesh& mesh, int maxEdges, bool refine, int fairingIterations, int64_t* loopsLeftOpen = nullptr,
                  int64_t* pointsAdded = nullptr, int64_t* trianglesAdded = nullptr);
// Flips triangles so that every edge-connected shell is consistently oriented (BFS across manifold
// edges). Returns the number of flipped triangles; nonOrientable counts shells that cannot be.
int64_t orientShellsConsistently(SurfaceMesh& mesh, int64_t* nonOrientable = nullptr);
// Flips closed shells so that normals point away from the domain: depth 0 (outermost) outward, depth 1
// inward, depth 2 outward... Returns the number of shells flipped.
int64_t orientShellsForDomain(SurfaceMesh& mesh);

} // namespace volgrid
