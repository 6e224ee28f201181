// Field point creation (paper 7.2, after Weatherill and Hassan) and clustering points.
//
// Passes over the tets; in each, every tet not examined yet (all tets in the first pass, then the tets
// created by the previous pass: an unchanged tet gives the same answer again) proposes its centroid c:
//   eq. 4  accepted when d_m > alpha * h(c), d_m the distance from c to the nearest of the tet's four
//          vertices and h the sizing field (SizingField.h: the boundary PDF interpolated, graded, capped);
//   eq. 5  and when no vertex lies within beta * h(c): neither an existing vertex nor a point accepted
//          earlier in the pass. Accepted points are inserted at once, so both kinds are mesh vertices
//          and the test is exact without a separate search structure: the nearest vertex to c is a vertex
//          of c's Bowyer-Watson cavity (in a Delaunay mesh, c's nearest neighbour becomes connected to c),
//          and the cavity is computed anyway to insert c.
// Repeated until a pass inserts nothing (or maxPasses / maxPoints). A pass's tets are those the previous
// pass's insertions created, not a sweep of the mesh: the work is proportional to the points inserted.
// alpha controls the density (smaller: more points); beta the regularity (no two points closer than
// beta * h). The defaults (OptionTable.h, the same for meshing and refinement) give mean volume edge
// lengths close to h for well-shaped boundary triangles.
//
// WHEN (documented choice): after boundary recovery and exterior removal (and Steiner removal), on the
// ghost-free mesh of the domain. The domain is then known exactly: every tet is inside, and insertion
// (TetEditor::insertPoint) grows its cavity by the exact SoS insphere test without crossing a face that
// has no neighbour (the boundary) or is listed in `constraints` (interfaces between kept regions), and
// makes it star-shaped with exact orientation tests. The boundary triangles and points are therefore kept
// exactly, and recovery works on the smaller boundary-only mesh. The paper's order (before recovery)
// works too: pass the ghost-free Delaunay mesh with `inside` (a point-in-domain test of the centroid);
// tets whose centroid is outside are skipped. Field points near a missing boundary facet may then cost
// recovery extra Steiner points, which is why the mesher should prefer the order above.
#pragma once

#include "LargeMesh.h"
#include "OptionTable.h"
#include "Progress.h"
#include "SizingField.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace volgrid
{

struct FieldPointOptions
{
  double alpha = option::alpha.defaultValue; // eq. 4 (> 0): larger = fewer points
  double beta = option::beta.defaultValue;   // eq. 5 (>= 0): minimum spacing in units of h
  int maxPasses = 64;                        // pass cap
  int64_t maxPoints = -1;                    // cap on inserted points; -1 = none
  // Global cap on tet volume (0 = none): h is capped at the edge of the regular tet of that volume, and
  // tets larger than maxVolume skip the eq. 4 test (eq. 5 still applies).
  double maxVolume = 0;
  // The tets of a pass are tested against eq. 4 on this many threads (ParallelFor.h's rule) when the
  // sizing field can be evaluated concurrently (SizingField::evaluatesConcurrently), else on one. A large
  // pass's points are inserted by regions on them too (regionTets); the rest one after the other. The mesh
  // is the same for any count.
  int threads = 1;
  // From this many tets in a pass (LargeMesh.h), the order of the tets follows space instead of the slots
  // (FieldPoints.cxx, tetsBornIn). Tests set it low to reach that order on small meshes.
  int64_t largeMeshTets = kLargeMeshTets;
  // A pass of at least 2 x regionTets tets is inserted by regions of space on the threads
  // (FieldPointRegions.h), each of about regionTets tets or more; 0 = the default. The mesh does not depend
  // on the thread count; it does on this (tests set it low to reach regions on small meshes).
  int64_t regionTets = 0;
};

struct FieldPointReport
{
  int passes = 0;
  int64_t inserted = 0;
  int64_t candidates = 0;          // centroids that passed eq. 4
  int64_t rejectedSpacing = 0;     // eq. 5
  int64_t rejectedOther = 0;       // outside (inside() false), no valid cavity
  int64_t insertedInRegions = 0;   // of `inserted`, by the regions of large passes (FieldPointRegions.h)
  int64_t deferredToOneThread = 0; // candidates the regions of a large pass left for one thread
  std::vector<int64_t> insertedPerPass;
  // Clustering.
  int64_t clusterInserted = 0;
  int64_t clusterOutside = 0;  // outside the mesh or on its boundary
  int64_t clusterRejected = 0; // too close to a vertex (duplicates) or no valid cavity
  double seconds = 0;
};

// Insert field points into a ghost-free mesh (see above). labels: optional per-tet-slot region labels
// kept in step (new tets inherit their cavity's label). inside: optional point-in-domain test of a
// centroid (for the before-recovery order); null = every tet is in the domain.
// Errors: InvalidOption (alpha <= 0, beta < 0, mesh with ghost tets), Cancelled.
Status insertFieldPoints(TetMesh& mesh, const SizingField& sizing, const FieldPointOptions& options,
                         const FaceConstraints* constraints = nullptr, std::vector<int32_t>* labels = nullptr,
                         const std::function<bool(const double*)>& inside = nullptr, Progress* progress = nullptr,
                         FieldPointReport* report = nullptr);

// Clustering (paper section 2, "a cluster of points"): insert user points into a ghost-free mesh. Points
// outside the mesh, on a constrained face, or closer than minSpacing to a vertex (exact duplicates are
// always rejected) are skipped and counted. To densify their neighbourhood, give the points a target size
// in the SizingField (SizingField::addSizedPoints) and insert field points after this call.
// vertexIds (optional) receives the mesh vertex of each point, -1 when skipped.
Status insertClusterPoints(TetMesh& mesh, const double* xyz, size_t n, double minSpacing,
                           const FaceConstraints* constraints = nullptr, std::vector<int32_t>* labels = nullptr,
                           std::vector<int32_t>* vertexIds = nullptr, Progress* progress = nullptr,
                           FieldPointReport* report = nullptr);

} // namespace volgrid
