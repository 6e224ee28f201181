#include "QualityRounds.h"

#include "BadTetSplitting.h"
#include "InsertionImprovement.h"
#include "MeshScan.h"
#include "ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

namespace volgrid
{

namespace
{
// The worst tet's min(theta_min, 180 - theta_max) in degrees (a sweep on `threads`, MeshScan.h).
double worstSineDegrees(const TetMesh& mesh, int threads)
{
  return sineQualityToDegrees(minSineQuality(mesh, threads));
}

int64_t countBelow(const TetMesh& mesh, double degrees, int threads)
{
  return countSineBelow(mesh, std::sin(degrees * 3.14159265358979323846 / 180.0), threads);
}

// The tets under `degrees` in (quality, slot) order, as optimizeMesh and splitBadTets sweep for them.
void collectSortedBelow(const TetMesh& mesh, double degrees, int threads, std::vector<std::pair<double, int32_t>>& out)
{
  collectSineBelow(mesh, std::sin(degrees * 3.14159265358979323846 / 180.0), threads, out);
  std::sort(out.begin(), out.end());
}

// Whether a tet under `degrees` has a vertex on no constrained face and not locked by the caller: only
// then can a vertex collapse touch the worst tets.
bool hasUnlockedVertexBelow(TetMesh& mesh, const FaceConstraints& fc, const std::vector<uint8_t>& extraLock,
                            double degrees)
{
  TetEditor probe(mesh, &fc, nullptr); // builds its vertex map
  const std::vector<uint8_t> lock = probe.lockedVertices();
  const double q = std::sin(degrees * 3.14159265358979323846 / 180.0);
  bool found = false;
  mesh.forEachTet(
    [&](int32_t t)
    {
      const int32_t* v = mesh.vertices(t);
      if (found || !(tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])) < q))
        return;
      for (int i = 0; i < 4; ++i)
        if (!lock[v[i]] && !(static_cast<size_t>(v[i]) < extraLock.size() && extraLock[v[i]]))
          found = true;
    });
  return found;
}

} // namespace

QualityRounds::QualityRounds(TetMesh& mesh_, const FaceConstraints& fc, const std::vector<uint8_t>& clusterLock,
                             std::vector<int32_t>& tetRegion_, const ImprovementOptions& options_,
                             ImprovementStatistics& stats_, Progress* progress_)
  : mesh(mesh_)
  , fc_(fc)
  , clusterLock_(clusterLock)
  , tetRegion(tetRegion_)
  , options(options_)
  , stats(stats_)
  , progress(progress_)
  , one_(options_.optimization)
  , editor_(mesh_, &fc, &tetRegion_)
{
  one_.threads = options.threads;
  one_.maxPasses = 1;
  one_.vertexRemoval = false;     // a second attempt, withCollapseRerun
  one_.summaries = false;         // the rounds decide on the smallest angle only; one summary at the end
  if (options.orthogonalityFirst) // aimed at the stage's target throughout, also in the floor rounds
    one_.orthogonalityFirst = OrthogonalityFirst::forTarget(options.optimization.targetDegrees);
  constrainedLocks_ = editor_.lockedVertices();
  editor_.refreshThreads = options.threads;
}

Status QualityRounds::run()
{
  Status s = withCollapseRerun();
  if (!s.ok())
    return s;
  s = speculativeRounds();
  if (!s.ok())
    return s;
  return insertionRounds();
}

Status QualityRounds::optimise(int maxPasses, std::vector<std::pair<double, int32_t>>* below)
{
  OptimizationWorklist worklist; // one sweep for the series of calls below (nothing else edits between)
  worklist.constrainedLocks = &constrainedLocks_;
  worklist.editor = &editor_;
  if (below && !below->empty())
  {
    worklist.valid = true;
    worklist.targetDegrees = one_.targetDegrees;
    worklist.below = std::move(*below);
  }
  for (int pass = 0; pass < maxPasses; pass += one_.maxPasses)
  {
    one_.maxPasses = pass == 0 ? std::min(3, maxPasses) : 1;
    OptimizationReport orep;
    Status os = optimizeMesh(mesh, &fc_, locked(), &tetRegion, one_, progress, &orep, &worklist);
    if (!os.ok())
      return os;
    stats.after.minDihedral = orep.minDihedralAfter; // what the rounds below decide on (summary: at the end)
    stats.optimizationPasses += orep.passes;
    stats.flips += orep.flips23 + orep.edgeRemovals;
    stats.flipsInRegions += orep.flipsInRegions;
    stats.smoothMoves += orep.smoothMoves;
    const int64_t gained = orep.belowTargetBefore - orep.belowTargetAfter;
    const bool minImproved = orep.minDihedralAfter > orep.minDihedralBefore + 1.0;
    if (orep.belowTargetAfter == 0 || orep.passes == 0 || (gained <= orep.belowTargetBefore / 50 && !minImproved))
      break;
  }
  if (below)
  {
    if (worklist.valid)
      below->swap(worklist.below);
    else // no pass ran: the mesh is as it was
      collectSortedBelow(mesh, one_.targetDegrees, options.threads, *below);
  }
  return Status::success();
}

// Beyond the target the mesh's minimum is decided by its few worst tets: while it pays, aim a little
// above the current worst (flips, smoothing and splitting touch only the tets below the aim and accept
// strict improvements only), so a mesh already past the target still gets better where it is worst.
SplitRequest QualityRounds::splitRequest(double degrees, int64_t maxPoints,
                                         const std::vector<std::pair<double, int32_t>>* below)
{
  SplitRequest request;
  request.degrees = degrees;
  request.maxPoints = maxPoints;
  request.below = below;
  request.threads = options.threads;
  request.progress = progress;
  request.constrainedLocks = &constrainedLocks_;
  request.editor = &editor_;
  request.orthogonalityFirst = one_.orthogonalityFirst;
  return request;
}

int64_t QualityRounds::splitBelow(double degrees, int64_t maxPoints, std::vector<std::pair<double, int32_t>>& below)
{
  std::vector<int32_t> candidates;
  SplitRequest request = splitRequest(degrees, maxPoints, &below);
  request.created = &candidates;
  const int64_t inserted = splitBadTets(mesh, &fc_, &tetRegion, request);
  for (const auto& b : below)
    candidates.push_back(b.second);
  collectSineBelowAmong(mesh, std::sin(degrees * 3.14159265358979323846 / 180.0), candidates, below);
  return inserted;
}

namespace
{
// below restricted to the tets under `degrees` (exact when degrees <= below.degrees); false when that
// is not known without a sweep.
bool narrowBelow(QualityRounds::Below& below, double degrees)
{
  if (below.degrees < 0 || degrees > below.degrees)
    return false;
  const double q = std::sin(degrees * 3.14159265358979323846 / 180.0);
  below.tets.erase(std::find_if(below.tets.begin(), below.tets.end(), [&](const auto& t) { return !(t.first < q); }),
                   below.tets.end());
  below.degrees = degrees;
  return true;
}
} // namespace

Status QualityRounds::floorRounds(Below& below)
{
  std::vector<std::pair<double, int32_t>> low;
  double lastWorst = 0;
  for (int round = 0; round < options.floorRounds; ++round)
  {
    if (progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    // The worst tet and the tets under the aim a little above it: from the tets the last round left under its
    // aim when there are some and the aim does not rise (the worst tet is among them), else from one sweep for
    // the tets a little above the aim.
    double worst = 0;
    const bool carried = below.degrees >= 0 && !below.tets.empty();
    if (carried)
      worst = sineQualityToDegrees(below.tets.front().first);
    else
    {
      const double lowDegrees = std::min(90.0, std::max(lastWorst + 2.0, options.optimization.targetDegrees) + 3.0);
      collectSortedBelow(mesh, lowDegrees, options.threads, low);
      worst = low.empty() ? worstSineDegrees(mesh, options.threads) : sineQualityToDegrees(low.front().first);
      below.tets.swap(low);
      below.degrees = below.tets.empty() ? -1 : lowDegrees;
    }
    if (!(worst > 0) || worst >= 60)
      break;
    one_.targetDegrees = std::max(worst + 2.0, options.optimization.targetDegrees);
    if (!narrowBelow(below, one_.targetDegrees))
    {
      if (carried) // the aim rose above the carried tets: sweep for them
      {
        collectSortedBelow(mesh, one_.targetDegrees, options.threads, below.tets);
        below.degrees = one_.targetDegrees;
      }
      else
        below.tets.clear();
    }
    const int64_t count = below.degrees >= 0 ? static_cast<int64_t>(below.tets.size())
                                             : countBelow(mesh, one_.targetDegrees, options.threads);
    // A plateau of many tets just above the worst (typically at the target) needs global work: not here.
    if (count > std::max<int64_t>(64, mesh.numTets() / 200))
      break;
    Status fs = optimise(2, &below.tets);
    if (!fs.ok())
      return fs;
    stats.splitPoints += splitBelow(one_.targetDegrees, 64, below.tets);
    fs = optimise(1, &below.tets);
    if (!fs.ok())
      return fs;
    below.degrees = one_.targetDegrees; // optimise() and splitBelow() leave the tets under their target
    const double after =
      below.tets.empty() ? worstSineDegrees(mesh, options.threads) : sineQualityToDegrees(below.tets.front().first);
    if (after < worst + 0.05)
      break;
    lastWorst = after;
  }
  return Status::success();
}

// The stage: optimisation, splitting of what it cannot fix, floor rounds.
Status QualityRounds::optimiseSplitFloor(Below& below)
{
  one_.targetDegrees = options.optimization.targetDegrees;
  below.tets.clear(); // after each optimisation: the tets under the target
  Status ps = optimise(options.optimization.maxPasses, &below.tets);
  if (!ps.ok())
    return ps;
  // What optimisation cannot fix (slivers spanned by boundary vertices): split by a point inside, then
  // optimise again. At most splitRounds rounds.
  for (int round = 0; round < options.splitRounds && stats.after.minDihedral < options.optimization.targetDegrees;
       ++round)
  {
    if (progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    const int64_t n =
      splitBelow(options.optimization.targetDegrees, std::max<int64_t>(200, mesh.numTets() / 20), below.tets);
    stats.splitPoints += n;
    if (n == 0)
      break;
    const double minBefore = stats.after.minDihedral;
    Status ps = optimise(std::min(3, options.optimization.maxPasses), &below.tets);
    if (!ps.ok())
      return ps;
    if (stats.after.minDihedral < minBefore + 0.1)
      break;
  }
  below.degrees = options.optimization.targetDegrees;
  return floorRounds(below);
}

// Vertex collapses (optimization.vertexRemoval) are a second attempt, from the same start, when the
// worst tet stays under vertexRemovalDegrees (typically recovery's Steiner points pinned against
// nearly coplanar boundary faces, which no flip, move or added point opens); the better of the two
// meshes is kept (collapses coarsen the mesh and change what later rounds reach: kept only when the
// worst tet gets better).
Status QualityRounds::withCollapseRerun()
{
  if (options.optimization.vertexRemoval && mesh.numTets() >= options.optimization.largeMeshTets)
    return withCollapsesThroughout();
  Below below;
  if (!options.optimization.vertexRemoval)
    return optimiseSplitFloor(below);
  Rerun rerun(*this);
  if (resolveThreads(options.threads) > 1)
    return concurrentRerun(rerun);
  Status s = optimiseSplitFloor(below);
  if (!s.ok() || !rerunPays())
    return s;
  Below rerunBelow;
  s = rerun.rounds.optimiseSplitFloor(rerunBelow);
  if (!s.ok())
    return s;
  keepTheBetter(rerun);
  return Status::success();
}

// The second run's own mesh, labels and statistics, copied from the stage's start, and its rounds (vertex
// collapses on).
QualityRounds::Rerun::Rerun(const QualityRounds& first)
  : mesh(first.mesh)
  , tetRegion(first.tetRegion)
  , stats(first.stats)
  , rounds(mesh, first.fc_, first.clusterLock_, tetRegion, first.options, stats, first.progress)
{
  rounds.one_.vertexRemoval = true;
}

namespace
{
// The second run's progress beside the first: no reports (the first run's thread makes them) and a stop
// flag that the first run's thread sets.
class StopFlagProgress final : public Progress
{
public:
  explicit StopFlagProgress(const std::atomic<bool>& stop)
    : stop_(stop)
  {
  }
  void report(double, const char*) override {}
  bool cancelled() override { return stop_.load(); }

private:
  const std::atomic<bool>& stop_;
};

// The first run's progress: the caller's, whose cancel also stops the second run.
class StoppingProgress final : public Progress
{
public:
  StoppingProgress(Progress* to, std::atomic<bool>& stop)
    : to_(to)
    , stop_(stop)
  {
  }
  void report(double fraction, const char* stage) override
  {
    if (to_)
      to_->report(fraction, stage);
  }
  bool cancelled() override
  {
    const bool c = to_ && to_->cancelled();
    if (c)
      stop_ = true;
    return c;
  }

private:
  Progress* to_;
  std::atomic<bool>& stop_;
};
} // namespace

// Both runs at once, one thread each (their parallel loops then run on their own thread: the meshes are the
// same as one run after the other). The caller's thread runs the first and keeps the caller's progress:
// afterwards it stops the second when the first leaves it nothing to win, else waits for it, reporting and
// asking whether to stop, so that a cancel still takes effect at once.
Status QualityRounds::concurrentRerun(Rerun& rerun)
{
  std::atomic<bool> stop{ false }, secondStarted{ false }, secondDone{ false };
  StopFlagProgress secondProgress(stop);
  StoppingProgress firstProgress(progress, stop);
  Progress* const callerProgress = progress;
  const std::thread::id caller = std::this_thread::get_id();
  Status first, second;
  bool pays = false;
  parallelRun(2,
              [&](int worker)
              {
                if (worker == 1)
                {
                  if (stop)
                    return;
                  // On the caller's thread when the pool was busy (the workers then run one after the other).
                  rerun.rounds.progress = std::this_thread::get_id() == caller ? callerProgress : &secondProgress;
                  secondStarted = true;
                  Below below;
                  second = rerun.rounds.optimiseSplitFloor(below);
                  secondDone = true;
                  return;
                }
                progress = &firstProgress;
                Below below;
                first = optimiseSplitFloor(below);
                progress = callerProgress;
                pays = first.ok() && rerunPays();
                if (!pays)
                  stop = true;
                while (pays && secondStarted && !secondDone)
                {
                  if (progress)
                  {
                    progress->report(0, "Optimising"); // the bar stays; its observers (abort buttons) run
                    if (progress->cancelled())
                      stop = true;
                  }
                  std::this_thread::sleep_for(std::chrono::milliseconds(20));
                }
              });
  if (!first.ok())
    return first;
  if (!pays)
    return Status::success();
  if (!second.ok())
    return second;
  keepTheBetter(rerun);
  return Status::success();
}

// Whether the collapses may do better than the first run: its worst tet is under the collapse threshold
// and a vertex that could go is there.
bool QualityRounds::rerunPays()
{
  worstKept_ = worstSineDegrees(mesh, options.threads);
  const double removalDegrees = std::min(options.optimization.vertexRemovalDegrees, options.optimization.targetDegrees);
  return worstKept_ < removalDegrees && hasUnlockedVertexBelow(mesh, fc_, clusterLock_, removalDegrees);
}

// The second run's mesh replaces the first's when its worst tet is better. Either way the options go on
// from where the second run left them (as when both run on this object one after the other).
void QualityRounds::keepTheBetter(Rerun& rerun)
{
  one_ = rerun.rounds.one_;
  one_.vertexRemoval = false;
  if (worstSineDegrees(rerun.mesh, options.threads) > worstKept_)
  {
    mesh = std::move(rerun.mesh);
    editor_.rebuildVertexMap();
    tetRegion = std::move(rerun.tetRegion);
    stats = rerun.stats;
  }
}

// From kLargeMeshTets (LargeMesh.h) a second run of the whole stage would cost as much as the first: one
// run instead, with the collapses on from its first pass, then collapse passes over what the split rounds
// left below the target and the floor rounds again. Measured on the ONERA M6 domain at 5.5M tets: with
// collapses only after a first run, the worst tet stayed at 1.9 deg with 60,000 tets under the target
// (too many for the floor rounds); with them from the start, 3.4 deg before the insertion rounds, in less
// time (a collapse removes tets that flips and moves would otherwise revisit every pass).
Status QualityRounds::withCollapsesThroughout()
{
  one_.vertexRemoval = true;
  Below below;
  Status s = optimiseSplitFloor(below);
  if (s.ok())
  {
    one_.targetDegrees = options.optimization.targetDegrees;
    if (!narrowBelow(below, one_.targetDegrees))
      below.tets.clear(); // optimise() sweeps
    s = optimise(3, &below.tets);
    below.degrees = one_.targetDegrees;
  }
  one_.vertexRemoval = false;
  if (!s.ok())
    return s;
  return floorRounds(below);
}

// Small meshes (a few boundary triangles, few or no field points) often end as a tie with any
// Delaunay-based mesher: no single flip, move or improving insertion helps. Speculative rounds insert
// the best point found for the worst tet, optimise around it, and keep the result only when the
// mesh's worst tet got better (else the mesh is restored: a copy is cheap at this size, and the next
// bad tet is tried).
// With many tets below the aim (a surface whose own triangles force bad tets, e.g. falcon1.stl: 10%
// under 10 deg) a round costs a full optimisation of all of them: fewer rounds then.
Status QualityRounds::speculativeRounds()
{
  Status s;
  constexpr int64_t kSpeculativeMaxBad = 32;
  constexpr int kSpeculativeRoundsManyBad = 4;
  int rounds = options.speculativeRounds;
  for (int round = 0, skip = 0; round < rounds && mesh.numTets() <= 5000; ++round)
  {
    const double worst = worstSineDegrees(mesh, options.threads);
    if (!(worst > 0) || worst >= 60)
      break;
    if (countBelow(mesh, std::max(worst + 2.0, options.optimization.targetDegrees), options.threads) >
        kSpeculativeMaxBad)
      rounds = std::min(rounds, kSpeculativeRoundsManyBad);
    const TetMesh savedMesh = mesh;
    const std::vector<int32_t> savedRegion = tetRegion;
    const DihedralSummary savedAfter = stats.after;
    one_.targetDegrees = std::max(worst + 2.0, options.optimization.targetDegrees);
    // Up to three points (each for the worst tet after the previous one), judged after each.
    int64_t n = 0;
    bool improved = false;
    for (int depth = 0; depth < 3 && !improved; ++depth)
    {
      SplitRequest request = splitRequest(one_.targetDegrees, 1, nullptr);
      request.speculative = true;
      request.skip = depth == 0 ? static_cast<size_t>(skip) : 0;
      const int64_t k = splitBadTets(mesh, &fc_, &tetRegion, request);
      if (k == 0)
        break;
      n += k;
      s = optimise(3);
      if (!s.ok())
        return s;
      improved = worstSineDegrees(mesh, options.threads) > worst + 0.01;
    }
    if (improved)
    {
      stats.splitPoints += n;
      skip = 0;
      continue;
    }
    mesh = savedMesh;
    editor_.rebuildVertexMap();
    tetRegion = savedRegion;
    stats.after = savedAfter;
    if (countBelow(mesh, one_.targetDegrees, options.threads) <= ++skip)
      break;
  }
  return Status::success();
}

// What is still worst (typically tets of four boundary vertices on a needle triangle in a thin wedge,
// on any mesh size): a point inserted for it, flipped and smoothed around, kept only when its region's
// worst tet improves.
Status QualityRounds::insertionRounds()
{
  if (options.insertionRounds <= 0)
    return Status::success();
  InsertionImprovementOptions io;
  io.rounds = options.insertionRounds;
  io.plateauDegrees = options.optimization.targetDegrees;
  io.threads = options.threads;
  io.orthogonalityFirst = one_.orthogonalityFirst;
  InsertionImprovementReport report;
  stats.splitPoints += improveWorstByInsertion(mesh, &fc_, locked(), &tetRegion, io, &report, progress);
  if (report.cancelled)
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  return Status::success();
}

} // namespace volgrid
