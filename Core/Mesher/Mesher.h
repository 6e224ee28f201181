// The boundary-conforming mesher: closed triangulated surfaces in, tetrahedra of the enclosed volume out,
// with the input boundary kept exactly (same points, same triangles, no point added on the boundary).
//
// Pipeline (paper 3.2 and 7.1-7.5):
//   1. Validate: exactly coincident points are merged (input point i after merging is output point i),
//      then SurfaceChecks rejects open surfaces, non-manifold edges, degenerate or duplicated triangles,
//      self-intersections and intersecting shells with a Status naming the defect.
//   2. Insert the boundary points with the exact Delaunay kernel (Delaunay.h), together with the eight
//      corners of a far box (the paper's super-hexahedron, only so that no boundary edge lies on the
//      hull; they end up in the exterior and are removed with it).
//   3. Recover the missing boundary edges and facets: flips, then Steiner points (BoundaryRecovery.h).
//   4. Remove the exterior by flood fill and select the regions (Regions.h).
//   5. Remove every Steiner point that lies on the boundary by relocating it inside (SteinerRemoval.h).
//      When 3 or 5 fails, 3-5 are redone once from the Delaunay mesh of step 2, first splitting the input
//      segments the first attempt had to split while the mesh is still Delaunay (presplitSegments).
//   5b. Grid control and quality: field points, clustering, optimisation (MeshImprovement.h).
//   6. Output the tets (positively oriented, labelled by region) and the boundary triangles with PatchId.
// Anything that cannot be recovered is reported with ErrorKind::RecoveryFailed, never hidden.
#pragma once

#include "MeshImprovement.h"
#include "Progress.h"
#include "Regions.h"
#include "Status.h"
#include "SurfaceMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace volgrid
{

// Options shared by the CLI (`volgrid mesh`) and the VTK filter (vtkVolGridTetrahedralize).
struct MesherOptions
{
  // Which enclosed regions form the domain (Regions.h): EvenOdd (default; any input orientation),
  // Orientation (facet normals point away from the domain, as in the paper), KeepAll (every enclosed
  // region, labelled).
  RegionRule regionRule = RegionRule::EvenOdd;
  // Run the surface defect checks first (strongly recommended: the mesher assumes valid input).
  bool checkSurface = true;
  // Exact self-intersection test inside checkSurface (the costliest check).
  bool checkSelfIntersections = true;
  // Boundary recovery may add Steiner points where flips are not enough (false: flips only).
  bool allowSteinerPoints = true;
  // Maximum number of Steiner points recovery may add; -1 = automatic (4 x triangles + 1000).
  int64_t maxSteinerPoints = -1;
  // Remove the Steiner points recovery put on the boundary (TetGen's -Y). false keeps them: the boundary
  // is then split (subfaces), which the output reports as steinerBoundary > 0.
  bool removeBoundarySteiner = true;
  // Check the result (exact orientation, adjacency, boundary = input, volume) and fail on a violation.
  bool verify = false;
  // Threads (the rule of ParallelFor.h: 0 = all cores): the surface checks, the Delaunay kernel (one
  // Hilbert chunk per thread) and the quality stage's mesh summaries, all on Core's one thread pool. The mesh does
  // not depend on this value: every threaded step merges its partial results in a fixed order.
  int threads = 0;
  // Grid control and quality after step 5 (MeshImprovement.h): field points, sizing, clustering,
  // optimisation. On by default.
  ImprovementOptions improvement;
};

struct MesherStatistics
{
  int64_t inputPoints = 0;  // after exact merging
  int64_t mergedPoints = 0; // coincident input points merged
  int64_t inputTriangles = 0;
  int64_t points = 0; // output points
  int64_t tets = 0;
  int64_t regions = 0;
  int64_t missingEdges = 0;    // boundary edges missing from the Delaunay tetrahedralization
  int64_t missingFacets = 0;   // facets still missing once all edges were present
  int64_t flips = 0;           // flips done by recovery
  int64_t steinerInterior = 0; // points added strictly inside the domain
  int64_t steinerBoundary = 0; // points left on the boundary (0 unless removeBoundarySteiner is off)
  int64_t steinerInserted = 0; // boundary Steiner points recovery inserted (all later relocated)
  int recoveryAttempts = 0;    // 2: the retry with presplit segments ran; 3: also the one with segment cones
  double enclosedVolume = 0;   // volume of the domain computed from the input surface
  double tetVolume = 0;        // sum of the output tets' volumes
  double secondsCheck = 0, secondsDelaunay = 0, secondsRecovery = 0, secondsExterior = 0, secondsSteiner = 0,
         secondsTotal = 0;
  // Grid control and quality (field, cluster and split points are not counted in steinerInterior).
  ImprovementStatistics improvement;
  double secondsImprovement = 0;
  int64_t forcedTets = 0; // tets marked in MesherResult::tetForced
};

struct MesherResult
{
  std::vector<double> points; // input points (merged) first, added points after
  int32_t numInputPoints = 0;
  std::vector<int32_t> inputToOutputPoint; // original input point id -> output point id
  std::vector<int32_t> tets;               // 4 per tet, orient3d > 0
  std::vector<int32_t> tetRegion;          // region label per tet (0..regions-1)
  // Per tet, 1 when the input surface forces its shape: a dihedral angle under 10 or over 170 degrees
  // (sine quality, TetEditor.h) with all four vertices on the input boundary, so that no flip or move can
  // change it without changing the boundary; else 0. The cell array Forced; stats.forcedTets counts them.
  std::vector<uint8_t> tetForced;
  std::vector<int32_t> boundaryTriangles;     // 3 per triangle: the input triangles bounding the domain
  std::vector<int32_t> boundaryInputTriangle; // input triangle id of each boundary triangle
  std::vector<int32_t> boundaryPatch;         // PatchId: the input patch id if present, else the shell index
  std::vector<int32_t> triangleShell;         // shell index of each input triangle
  MesherStatistics stats;
  std::vector<std::string> warnings;
};

// Mesh the volume enclosed by `surface`. On failure the result is empty and the Status says why.
Status meshSurface(const SurfaceMesh& surface, const MesherOptions& options, MesherResult& result,
                   Progress* progress = nullptr);

} // namespace volgrid
