// Grid control and element quality as one mesher stage (paper 2, 4, 7.2 and 7.6; issue 4): the glue
// between the mesher (Mesher.h) and the stages SizingField.h, FieldPoints.h, MeshSmoothing.h and
// MeshOptimization.h, plus adaptivity of an existing tet mesh.
//
// improveDomainMesh() runs on the mesh of the domain once the boundary is recovered, the exterior removed
// and the boundary Steiner points removed (Mesher.cxx step 5b):
//   1. Constraints: faces without a neighbour (the domain boundary) are constrained by TetEditor; the
//      live boundary subfaces that have tets on both sides (interfaces between kept regions, KeepAll)
//      are added to a FaceConstraints set, so that no stage crosses or changes them.
//   2. Sizing field: the boundary PDF (eq. 3) at the surface points, the optional clustering sizes as
//      sized nodes, the optional background cloud / callback, graded and capped (SizingField.h).
//   3. Clustering points (optional), then field points (eq. 4 and 5), both by constrained Bowyer-Watson
//      insertion that never crosses a constrained face.
//   4. Optimisation: flips, edge removal and smoothing towards a target minimum dihedral angle
//      (MeshOptimization.h), which never changes a constrained face and never moves its vertices; the
//      tets it cannot fix (slivers and caps spanned by boundary vertices) are split by a point placed by
//      search and inserted with a quality-driven cavity (TetEditor::qualityInsertion, only when it
//      strictly improves), then optimisation runs again. Then floor rounds aim 2 degrees above the
//      worst tet while that pays. When the worst tet is still under 5 degrees with an interior vertex
//      (typically recovery's Steiner points pinned against nearly coplanar boundary faces), the whole
//      stage runs again from the same start with vertex collapses (MeshOptimization.h, vertexRemoval),
//      and the mesh whose worst tet is better is kept (from kLargeMeshTets tets, LargeMesh.h: one run
//      with collapses from the start instead). On small meshes speculative rounds then try a
//      few points and keep them only when the worst tet improves. Last, on any mesh size, vertex insertion
//      as an improvement operation for the worst tets (InsertionImprovement.h): a point searched in the
//      frame of each face of the tet, flipped and smoothed around, kept only when its region improves.
//   5. Orthogonality: vertex moves for the faces a finite-volume solver finds severely non-orthogonal
//      (OrthogonalitySmoothing.h), never making a tet worse than step 4 left it below its target.
// The boundary is therefore the input boundary, exactly: same points, same triangles. New vertices are
// marked VertexKind::SteinerInterior in `kinds` (field and cluster points are strictly interior), region
// labels follow the tets, and the editor's vertex map is rebuilt for the output stage.
//
// refineTetMesh() is the paper's section 4 adaptivity: an existing tet mesh (e.g. a VolGrid mesh read
// back) and a target edge length per vertex (e.g. from a solver's error estimate) -> field points where
// the target is smaller than the current spacing, then optimisation; the boundary faces (and the faces
// between different regions) are kept exactly.
#pragma once

#include "FieldPoints.h"
#include "MeshEditor.h"
#include "MeshOptimization.h"
#include "Progress.h"
#include "SizingField.h"
#include "Status.h"
#include "SurfaceMesh.h"
#include "TetMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace volgrid
{

// Grid control and quality options (a member of MesherOptions; shared by the CLI and the filter).
struct ImprovementOptions
{
  ImprovementOptions();

  // Field points (paper 7.2): alpha (eq. 4: larger = fewer points), beta (eq. 5: spacing in units of h),
  // maxVolume (global cap on tet volume, 0 = none). Defaults and valid ranges: OptionTable.h.
  bool fieldPoints = true;
  FieldPointOptions fieldPointOptions;
  // Sizing: gradation (size growth bound between neighbours, > 1), maxEdgeLength (0 = none), scale (the
  // boundary PDF times scale is the target edge length at the boundary points).
  SizingOptions sizing;
  // Clustering: points (x,y,z each) inserted into the domain; clusterSizes (empty, or one target edge
  // length per point; <= 0 or non-finite = none) densify their neighbourhood through the sizing field.
  std::vector<double> clusterPoints;
  std::vector<double> clusterSizes;
  // Background sizing cloud: points (x,y,z each) with one target edge length each, interpolated linearly
  // in space (e.g. a coarse background mesh or a CFD solution's point array).
  std::vector<double> sizingPoints;
  std::vector<double> sizingValues;
  // Optional sizing callback h(x) (combined by min with the rest).
  std::function<double(const double*)> sizingFunction;
  // Optimisation (flips, edge removal, smoothing) towards a target min(theta_min, 180 - theta_max).
  bool optimize = true;
  OptimizationOptions optimization;
  // Rounds of splitting the tets still below the target by a point placed by search and inserted with a
  // quality-driven cavity, each followed by optimisation (0 = no point added by the quality stage).
  int splitRounds = 3;
  // Rounds aimed 2 degrees above the current worst tet once the target is met or no longer improves
  // (0 = stop at the target).
  int floorRounds = 4;
  // Meshes of at most 5,000 tets: rounds that insert a point for the worst tet, optimise, and keep the
  // result only if the worst tet got better (0 = none).
  int speculativeRounds = 12;
  // Rounds of vertex insertion as an improvement operation for the worst tets, any mesh size
  // (InsertionImprovement.h; 0 = none).
  int insertionRounds = 12;
  // After the rounds: vertex moves for the faces a finite-volume solver finds severely non-orthogonal,
  // never making a tet worse than the rounds left it below the target (OrthogonalitySmoothing.h).
  bool orthogonalitySmoothing = true;
  // Last: moves, flips and collapses for the tets with no boundary vertex whose angles leave [15, 165]
  // degrees, leaving the worst angles, the share under 10 degrees and the severe faces no worse
  // (InteriorPolish.h).
  bool interiorPolish = true;
  // Off by default. On: the flips, splits, insertion rounds and smoothing moves keep what a finite-volume
  // solver sees first, adding no tets under the target and no severely non-orthogonal faces where they
  // edit, except for nearly flat tets (OrthogonalityFirst.h). Fewer severe faces, a smaller worst angle.
  bool orthogonalityFirst = false;
  // Threads for the stage's threaded steps (ParallelFor.h rule: 0 = all cores; meshSurface sets it from
  // MesherOptions::threads). The result is the same for any value.
  int threads = 0;
};

struct ImprovementStatistics
{
  int64_t fieldPoints = 0; // field points inserted (and still in the mesh, see removedPoints)
  int fieldPasses = 0;
  int64_t fieldPointsInRegions = 0; // of those inserted, by the regions of large passes (FieldPointRegions.h)
  int64_t clusterPoints = 0;        // clustering points inserted
  int64_t clusterSkipped = 0;       // outside, on the boundary, duplicates or too close
  int64_t interfaceFaces = 0;       // interior faces kept as constraints (region interfaces)
  int64_t latticeNodes = 0;         // sizing nodes away from the boundary (size from the gradation)
  // The largest boundary spacing, within its depth limit, that the max-edge cap meets (the size grades
  // down from such triangles to the cap: CoarseBoundaryFloor.h); 0 when the cap holds everywhere.
  double coarseBoundaryFloor = 0;
  DihedralSummary before, after; // dihedral angles before the field points and after everything
  int optimizationPasses = 0;
  int64_t flips = 0;          // 2-3 flips and edge removals
  int64_t flipsInRegions = 0; // of those, made by regions on the threads (RegionFlips.h)
  int64_t smoothMoves = 0;
  // Interior faces over 70 degrees of non-orthogonality (OpenFOAM's severe limit) before and after the
  // orthogonality smoothing, and the vertices it moved.
  int64_t severeFacesBefore = 0, severeFacesAfter = 0, orthogonalityMoves = 0;
  int64_t splitPoints = 0; // points inserted to split tets optimisation could not fix (still in the mesh)
  // Interior points removed by optimisation's vertex collapses: boundary recovery's Steiner points and
  // field or split points (fieldPoints and splitPoints count only those left).
  int64_t removedPoints = 0;
  // Tets under 10 degrees whose four vertices are boundary (or interface) vertices: bounded by the
  // surface triangles, not by the optimisation.
  int64_t boundaryForcedBelow10 = 0;
  // Tets with no vertex on a constrained face whose dihedral angles leave [15, 165] degrees
  // (kInteriorDegrees, TetNeeds.h): before the interior polish (InteriorPolish.h) and in the final mesh.
  int64_t interiorOutsideBeforePolish = 0, interiorOutside = 0;
  double secondsSizing = 0, secondsFieldPoints = 0, secondsOptimization = 0;
  double secondsPolish = 0; // the interior polish, a part of secondsOptimization
};

// The mesher's stage (see above). `surface` gives the boundary points and triangles for the PDF;
// `kinds` is extended to the new vertices; tetRegion (per tet slot) is kept in step.
// Errors: InvalidOption (bad option values), Cancelled.
Status improveDomainMesh(MeshEditor& editor, const BoundaryConstraints& bc, const SurfaceMesh& surface,
                         std::vector<VertexKind>& kinds, std::vector<int32_t>& tetRegion,
                         const ImprovementOptions& options, ImprovementStatistics& stats, Progress* progress = nullptr);

// A ghost-free TetMesh with adjacency from a tet list (4 ids per tet; negatively oriented tets are
// reoriented). Faces shared by two tets are linked, the others have no neighbour.
// Errors: InvalidOption (bad ids, a flat tet, a face shared by more than two tets).
Status tetMeshFromTets(const std::vector<double>& points, const std::vector<int32_t>& tets, TetMesh& mesh);

struct RefineOptions
{
  FieldPointOptions fieldPointOptions; // alpha, beta: the same defaults as for meshing (OptionTable.h)
  double gradation = 0;                // > 1: grade the target sizes over the mesh edges first
  bool optimize = true;
  OptimizationOptions optimization;
};

struct RefineReport
{
  int64_t inserted = 0;
  int passes = 0;
  DihedralSummary before, after;
  double seconds = 0;
};

// Paper section 4: refine `mesh` (ghost-free) where targetSize (one per vertex; non-finite or <= 0 =
// no target there) is smaller than the current spacing. Faces without a neighbour, and faces between
// tets of different `regions` labels (optional, per tet slot), are kept exactly. regions is kept in step.
Status refineTetMesh(TetMesh& mesh, const std::vector<double>& targetSize, std::vector<int32_t>* regions,
                     const RefineOptions& options, Progress* progress = nullptr, RefineReport* report = nullptr);

} // namespace volgrid
