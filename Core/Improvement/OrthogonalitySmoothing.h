// Vertex moves for the faces a finite-volume solver finds severely non-orthogonal (issue 16, acceptance 6).
//
// A solver such as OpenFOAM measures an interior face by the angle between the line joining its two cells'
// centroids and the face's normal (checkMesh's non-orthogonality; above 70 degrees it calls the face
// severe). The quality stage optimises dihedral angles, which is a different thing: on the ONERA M6 domain
// it leaves 1,021 severe faces where the mesh before it had 588, and raising its target angle does not
// lower the count (a tet with good dihedral angles can still sit sheared against its neighbour). Flips do
// not help either: of the 2-3 and 3-2 flips that remove severe faces there, none keeps the tets' quality.
//
// This stage works on the severe faces only. For each, the unlocked vertices of its two tets are tried:
// a compass search moves the vertex to make the least orthogonal face of its star (every face of every tet
// holding it, towards the tets beyond too) as orthogonal as it can, under two constraints:
//   - every tet of the star stays strictly positive (exact orient3d),
//   - each tet of the star keeps a sine quality of at least min(its own before, the target's, max(the
//     star's worst before, 10 degrees)): a tet under the target gets no worse, a tet over it may give up
//     angle down to the target or to the star's worst tet, and none falls under 10 degrees that was not
//     (so the minimum dihedral angle and the share of tets under 10 degrees never get worse).
// The move that removes the most severe faces is kept, when it removes at least one. Every move made lowers
// the mesh's severe count, so the stage ends; it is a worklist (the tets around a moved vertex are
// examined again), after one sweep over the mesh. Locked vertices (on constrained faces: the boundary and
// region interfaces; or locked by the caller) never move, so the boundary is kept exactly.
#pragma once

#include "CfdQuality.h"
#include "OptionTable.h"
#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

struct OrthogonalitySmoothingOptions
{
  // checkMesh's limit for a severely non-orthogonal face.
  double severeDegrees = quality::kSevereNonOrthogonality;
  // The quality stage's target for min(theta_min, 180 - theta_max).
  double targetDegrees = option::targetAngle.defaultValue;
  // The sweep for the severe faces runs on this many threads (ParallelFor.h's rule); the mesh is the same
  // for any count.
  int threads = 0;
};

struct OrthogonalitySmoothingReport
{
  int64_t severeBefore = 0; // interior faces above severeDegrees before the stage
  int64_t severeAfter = 0;
  int64_t moves = 0;
};

// See above. locked: optional extra per-vertex locks (non-zero = keep). Errors: Cancelled.
Status smoothNonOrthogonalFaces(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                                const OrthogonalitySmoothingOptions& options, Progress* progress = nullptr,
                                OrthogonalitySmoothingReport* report = nullptr);

} // namespace volgrid
