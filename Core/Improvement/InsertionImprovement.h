// Vertex insertion as a mesh improvement operation (after Klingner and Shewchuk, "Aggressive tetrahedral
// mesh improvement"): the last resort of the quality stage (MeshImprovement.h) for the worst tets, which
// flips, smoothing, collapses and improving splits (BadTetSplitting.h) left as they are. Typical cases:
// a tet of four boundary vertices on a needle-shaped boundary triangle inside a thin wedge of the domain
// (the tet's worst angle is set by its fourth vertex, not by the triangle), or a tiny model without
// interior points whose few tets are all spanned by boundary vertices.
//
// For each of the worst tets t (quality q_t = tetSineQuality):
//   1. Position: a new interior point w is placed where the quality-driven insertion
//      (TetEditor::qualityInsertion, cavity holding t) makes the best worst new tet; searched in the local
//      frame of each face of t (the frame scales with the face: sqrt(area) in-plane and off-plane), from a
//      grid of starts, then a pattern search from the best two whose steps shrink to 1e-6 of the frame, so
//      that a point can find room inside a wedge of a degree against a needle triangle. When steps 2 and 3
//      fail for a tet with two boundary faces, again from starts a hundred times closer to the faces (two
//      boundary triangles folded onto each other leave a wedge of a tenth of a degree).
//   2. Insertion even when w alone does not beat q_t, then local improvement of its neighbourhood: edge
//      removals and 2-3 flips of the new tets (each a strict local improvement, MeshOptimization.h) and
//      optimisation-based smoothing (MeshSmoothing.h) of w and of the unlocked vertices of the new tets
//      still near q_t (a moved vertex's star counts as new tets), a few rounds; last, a pattern search on
//      w's position along the axes and the face normals of its star's worst tet.
//   3. Kept only when t is gone and every tet created by the attempt (and still alive) is strictly better
//      than q_t (the worst tet of the changed region strictly improves) with no dihedral angle under the
//      mesh's smallest one (so the minimum dihedral angle never drops). Otherwise the mesh is restored.
// Every validity decision is the editors' exact orient3d; constrained faces (the boundary, interfaces)
// are never crossed, so the boundary stays exactly the input triangles. Labels (per tet slot) follow.
#pragma once

#include "OrthogonalityFirst.h"
#include "Progress.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

struct InsertionImprovementOptions
{
  int rounds = 12;         // rounds, while the mesh's worst tet improves (the worst tets collected anew)
  int tetsPerRound = 4;    // worst tets attempted per round
  double aboveWorst = 2.0; // only tets within this many degrees of the mesh's worst tet are attempted
  // No round when the worst tet is at plateauDegrees or better (e.g. the optimisation's target) and more
  // than max(plateauTets, tets / 200) tets are within aboveWorst of it.
  double plateauDegrees = 18.0;
  int64_t plateauTets = 64;
  int threads = 0; // for the whole-mesh summaries (ParallelFor.h rule; same result for any value)
  // Off by default. On (OrthogonalityFirst.h), an attempt for a tet that is not nearly flat is also undone
  // when the tets it changed hold more tets under the rule's target, or more severely non-orthogonal
  // faces, than before; its flips keep the rule too.
  OrthogonalityFirst orthogonalityFirst;
};

struct InsertionImprovementReport
{
  int64_t attempts = 0;   // worst tets tried
  int64_t kept = 0;       // points left in the mesh
  bool cancelled = false; // progress->cancelled() stopped the rounds (between two attempts: the mesh is valid)
};

// Improves the worst tets of `mesh` (ghost-free) by vertex insertion (see above). locked: optional extra
// per-vertex locks (vertices of constrained faces never move anyway). labels: optional, per tet slot.
// Returns the number of points kept. progress (optional): asked before every attempt whether to stop, told
// after every round ("Optimising").
int64_t improveWorstByInsertion(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                                std::vector<int32_t>* labels, const InsertionImprovementOptions& options,
                                InsertionImprovementReport* report = nullptr, Progress* progress = nullptr);

} // namespace volgrid
