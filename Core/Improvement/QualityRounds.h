// The quality stage's rounds after the field points (MeshImprovement.h step 4), one member per kind of
// round, sharing the mesh, the constraints, the labels and the statistics of the stage:
//   optimise            flips, edge removal, smoothing (MeshOptimization.h) while a pass pays
//   optimiseSplitFloor  optimisation, splitting of what it cannot fix (BadTetSplitting.h), floor rounds
//   withCollapseRerun   optimiseSplitFloor, and again from the same start with vertex collapses when the
//                       worst tet stays low (on two threads both runs at once); the better mesh is kept (below
//                       kLargeMeshTets tets, LargeMesh.h; from there on, withCollapsesThroughout: one run with the
//                       collapses on from the start)
//   speculativeRounds   small meshes: a point for the worst tet, kept only when the worst tet improves
//   insertionRounds     vertex insertion for the worst tets (InsertionImprovement.h)
// run() is all of them in that order. Every round changes only unconstrained faces and moves no vertex of
// a constrained face or of clusterLock; stats.after.minDihedral follows the rounds (the full summary is
// the caller's, once at the end).
#pragma once

#include "BadTetSplitting.h"
#include "MeshImprovement.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

class QualityRounds
{
public:
  QualityRounds(TetMesh& mesh, const FaceConstraints& fc, const std::vector<uint8_t>& clusterLock,
                std::vector<int32_t>& tetRegion, const ImprovementOptions& options, ImprovementStatistics& stats,
                Progress* progress);

  // Every round in order. Errors: Cancelled, or optimizeMesh's.
  Status run();

  // Up to maxPasses optimisation passes towards one_.targetDegrees: the first call of a series runs up
  // to three passes, then one pass per call while a pass still pays. below (optional): in, when not
  // empty, the tets under the target in (quality, slot) order as a sweep would give them (no sweep then);
  // out, the tets under the target after the passes, in the same order.
  Status optimise(int maxPasses, std::vector<std::pair<double, int32_t>>* below = nullptr);
  // The tets under a quality, exactly, in (quality, slot) order: what a sweep would collect. degrees < 0:
  // not known.
  struct Below
  {
    std::vector<std::pair<double, int32_t>> tets;
    double degrees = -1;
  };
  // below (in and out): the tets under below.degrees as the rounds before left them (in) and as these
  // leave them (out), so that a round whose aim is no higher needs no sweep of the mesh.
  Status floorRounds(Below& below);
  Status optimiseSplitFloor(Below& below);
  Status withCollapseRerun();
  Status withCollapsesThroughout();
  Status speculativeRounds();
  Status insertionRounds();

private:
  struct Rerun;
  // withCollapseRerun's steps.
  Status concurrentRerun(Rerun& rerun);
  bool rerunPays();
  void keepTheBetter(Rerun& rerun);
  const std::vector<uint8_t>* locked() const { return clusterLock_.empty() ? nullptr : &clusterLock_; }
  // A split of the tets below `degrees` with this stage's threads and progress.
  SplitRequest splitRequest(double degrees, int64_t maxPoints, const std::vector<std::pair<double, int32_t>>* below);
  // Splits up to maxPoints of the tets under `degrees`, given exactly in `below` as optimise() leaves them;
  // afterwards `below` holds the tets under `degrees` again (no sweep: those left alone and those created).
  // Returns the number of points inserted.
  int64_t splitBelow(double degrees, int64_t maxPoints, std::vector<std::pair<double, int32_t>>& below);

  TetMesh& mesh;
  const FaceConstraints& fc_;
  const std::vector<uint8_t>& clusterLock_;
  std::vector<int32_t>& tetRegion;
  const ImprovementOptions& options;
  ImprovementStatistics& stats;
  Progress* progress;
  OptimizationOptions one_; // the options of the next optimisation call (target, vertex removal)
  double worstKept_ = 0;    // the first run's worst tet (degrees), for withCollapseRerun
  // TetEditor::lockedVertices() at the start (the rounds change no constrained face; the points they add
  // are unlocked), for every call of the rounds instead of a sweep each.
  std::vector<uint8_t> constrainedLocks_;
  // The editor of every optimisation and split call (its vertex map refreshed, not built, per call); rebuilt
  // when the mesh is replaced as a whole (keepTheBetter, speculativeRounds).
  TetEditor editor_;
};

// withCollapseRerun's second run: its own copy of the stage's start and its own rounds (vertex collapses on).
struct QualityRounds::Rerun
{
  explicit Rerun(const QualityRounds& first);
  TetMesh mesh;
  std::vector<int32_t> tetRegion;
  ImprovementStatistics stats;
  QualityRounds rounds;
};

} // namespace volgrid
