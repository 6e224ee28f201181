// Mesh optimisation beyond the paper: topological improvement interleaved with smoothing (after
// Freitag/Ollivier-Gooch and Klingner/Shewchuk), until every tet reaches a target quality or a pass limit.
//
// Quality: tetSineQuality() (TetEditor.h), i.e. min(theta_min, 180 - theta_max) over the dihedral angles.
// Each pass:
//   1. every tet below the target (worst first) tries, keeping the best strict improvement of the worst
//      tet of the affected region:
//        - edge removal on each of its six edges: the ring of n tets around an interior edge is replaced by
//          the best triangulation of the ring polygon joined to the edge's two ends (2n-4 tets; n = 3 is the
//          3-2 flip), found by dynamic programming over the polygon's triangulations (max-min quality);
//        - 2-3 flips of its four faces (the smallest multi-face removal; general multi-face removal is
//          not implemented yet);
//      tets created by a successful operation are examined in the same pass when still below target;
//   2. smoothing (MeshSmoothing.h) of the unlocked vertices of the tets still below target;
//   3. optionally (vertexRemoval), for the tets still far below target, the collapse of one of their
//      unlocked vertices onto a neighbour.
// Stops when nothing changed in a pass, every tet reaches the target, or after maxPasses.
// Cost: one sweep over the mesh per call (the tets below the target; plus the summaries unless
// options.summaries is off); the passes then work on that list and on the tets they change (created by a
// flip or a collapse, or in the star of a moved vertex), never on the whole mesh again.
//
// Constraints: faces without neighbour and faces in `constraints` are never removed (an edge is removed
// only when its ring is closed and no face around it is constrained; a face is flipped only when not
// constrained), constrained-face vertices never move, no vertex is added, and only unlocked vertices are
// removed (vertexRemoval). Every new tet is checked with the exact orient3d (strictly positive) before
// any change. So the boundary is unchanged and
// the mesh stays valid. Works on a ghost-free TetMesh; region labels (optional, per tet slot) and kUser
// flag bits are carried to the new tets (a flip never mixes regions: interface faces are constrained).
#pragma once

#include "LargeMesh.h"

#include "MeshSmoothing.h"
#include "OptionTable.h"
#include "OrthogonalityFirst.h"
#include "TetNeeds.h"
#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace volgrid
{

struct OptimizationOptions
{
  double targetDegrees = option::targetAngle.defaultValue; // target for min(theta_min, 180 - theta_max)
  int maxPasses = static_cast<int>(option::passes.defaultValue);
  bool smoothing = true;
  bool flips = true;       // 2-3 flips
  bool edgeRemoval = true; // includes 3-2 flips
  int maxRing = 9;         // largest edge ring considered by edge removal
  // From this many tets on (LargeMesh.h), a pass works in memory order: the flips visit
  // the tets below the target by slot (the quality stage renumbers large meshes in space, so slot order
  // follows space) instead of worst first, and the smoothing step runs on all threads in colour classes
  // (ColouredSmoothing.h: the same mesh at any thread count). Below, worst first and one vertex after the
  // other, as small meshes always were (another order gives a different, not a better, mesh). The quality
  // stage (MeshImprovement.h) takes the same size for its own large-mesh choices (spatial renumbering,
  // one run with collapses from the start); tests lower it to take those paths on small meshes.
  int64_t largeMeshTets = kLargeMeshTets;
  // On large meshes, a flip sweep of at least 2 x regionTets tets below the target is cut into regions of
  // space of about regionTets of them each, flipped on all threads (RegionFlips.h); 0 = the default. The
  // mesh does not depend on the thread count; it does on this (tests set it low to reach regions).
  int64_t regionTets = 0;
  // Removal of unlocked vertices of the tets below vertexRemovalDegrees after the flips and moves of a
  // pass, by collapsing them onto a neighbour (see tryVertexCollapse); the removed vertex stays in
  // mesh.points, used by no tet (callers that write every point keep it off).
  bool vertexRemoval = false;
  double vertexRemovalDegrees = 5.0;
  // Whole-mesh summaries before and after (report.before, report.after): two sweeps over the mesh per
  // call. false leaves them empty; report.minDihedralBefore/After are set either way (from the tets below
  // the target when the minimum lies among them, else by a sweep).
  bool summaries = true;
  // Threads for the whole-mesh sweeps (ParallelFor.h: 0 = all cores); the result is the same for any value.
  int threads = 0;
  SmoothingOptions smoothingOptions = SmoothingOptions{ 1, true, 12, 90.0 };
  // Off by default. On (OrthogonalityFirst.h), unless the worst tet it changes is nearly flat: no flip or
  // edge removal leaves more tets under its target than it removes, and no smoothing move leaves more of
  // them or more severely non-orthogonal faces in the moved vertex's star.
  OrthogonalityFirst orthogonalityFirst;
};

// Dihedral-angle summary of the finite tets (degrees).
struct DihedralSummary
{
  int64_t tets = 0;
  double minDihedral = 180;
  double maxDihedral = 0;
  int64_t below10 = 0;  // tets with a dihedral angle under 10 degrees
  int64_t above170 = 0; // tets with a dihedral angle above 170 degrees
  int64_t inverted = 0; // exact orient3d <= 0
  double shareBelow10() const { return tets ? double(below10) / tets : 0; }
};
// threads: the rule of ParallelFor.h (0 = all cores); the summary is the same for any value. progress
// (optional) is asked between blocks of a million slots (a summary of 5M tets takes 0.3 s on 2 cores);
// when it says stop, the summary ends early and covers part of the mesh (the caller, asking again, stops).
DihedralSummary summarizeDihedrals(const TetMesh& mesh, int threads = 0, Progress* progress = nullptr);
// The same over plain arrays: n tets of 4 vertex ids each (rows with a negative id are skipped), and
// optional per-tet flags (TetMesh::kFree rows skipped). No adjacency needed.
DihedralSummary summarizeDihedrals(const double* points, const int32_t* tetVertices, const uint8_t* tetFlags, int64_t n,
                                   int threads = 0, Progress* progress = nullptr);

struct OptimizationReport
{
  DihedralSummary before, after;
  double minDihedralBefore = 180, minDihedralAfter = 180; // the mesh's smallest dihedral angle (degrees)
  int passes = 0;
  int64_t flips23 = 0;
  int64_t edgeRemovals = 0; // of which 3-2 flips:
  int64_t flips32 = 0;
  int64_t flipsInRegions = 0; // of the flips and edge removals, those made by regions on the threads
  int64_t smoothMoves = 0;
  int64_t vertexRemovals = 0;
  int64_t belowTargetBefore = 0, belowTargetAfter = 0;
  double seconds = 0;
};

// The tets below the target as a call of optimizeMesh leaves them, for the next call on the same mesh:
// a series of calls with the same target and nothing else editing the mesh between them then sweeps the
// mesh once, not once per call. The caller clears it (valid = false) when anything else edits the mesh.
struct OptimizationWorklist
{
  bool valid = false;
  double targetDegrees = 0;
  std::vector<std::pair<double, int32_t>> below; // (sine quality, tet), sorted
  // 1 for a vertex whose smoothing found no move and none of whose tets changed since: smoothing it again
  // would find none either (its outcome depends only on its star), so it is skipped.
  std::vector<uint8_t> unmoved;
  // Optional: TetEditor::lockedVertices() of this mesh and constraints, kept by the caller from call to
  // call (a vertex past its end is a point added since, unlocked), so that no call sweeps the mesh for it.
  const std::vector<uint8_t>* constrainedLocks = nullptr;
  // Optional: the caller's editor of this mesh with the same constraints and labels, through which every
  // edit of the mesh since its vertex map was built went: its map is refreshed (TetEditor::refreshVertexMap,
  // the map a new editor would build) instead of built by a sweep.
  TetEditor* editor = nullptr;
};

// Improve the mesh in place. locked: optional extra per-vertex locks. labels: optional per-tet-slot
// labels kept in step. worklist (optional): used when valid for options.targetDegrees instead of a sweep,
// and left valid for the next call. Errors: InvalidOption (ghost tets, bad options), Cancelled.
Status optimizeMesh(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                    std::vector<int32_t>* labels, const OptimizationOptions& options, Progress* progress = nullptr,
                    OptimizationReport* report = nullptr, OptimizationWorklist* worklist = nullptr);

// Building blocks (the editor's vertex map must be current). Each returns true after a strict improvement
// of the worst tet of the affected region; created receives the new tets. rule (optional): refused when it
// binds and the new tets hold more under its target than the old ones (OrthogonalityFirst.h). needs
// (optional): instead of the worst tet, what TetNeeds::pays asks.
bool tryEdgeRemoval(TetEditor& editor, int32_t t, int32_t x, int32_t y, int maxRing, std::vector<int32_t>* created,
                    const OrthogonalityFirst* rule = nullptr, const TetNeeds* needs = nullptr);
bool tryFlip23(TetEditor& editor, int32_t t, int face, std::vector<int32_t>* created,
               const OrthogonalityFirst* rule = nullptr, const TetNeeds* needs = nullptr);
// Removes unlocked vertex v (no constrained face through it) by collapsing it onto the neighbour w whose
// collapse gives the best worst tet: the star's tets holding w go, the others get w for v. Only when every
// new tet is strictly positive (exact orient3d) and the worst tet of the star strictly improves. v is then
// used by no tet (its coordinates stay in mesh.points). Typical use: Steiner points that boundary recovery
// left next to the boundary, squeezed between nearly coplanar faces no move can open.
// needs (optional): the collapse pays as TetNeeds asks instead.
bool tryVertexCollapse(TetEditor& editor, int32_t v, std::vector<int32_t>* created, const TetNeeds* needs = nullptr);

} // namespace volgrid
