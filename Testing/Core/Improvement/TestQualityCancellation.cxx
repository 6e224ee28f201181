// The quality stage's point insertions (BadTetSplitting.h, InsertionImprovement.h) and its optimisation
// passes stop when the user cancels, leave a valid mesh, and score positions the same on any thread count.
#include "BadTetSplitting.h"
#include "InsertionImprovement.h"
#include "Mesh/RandomDelaunay.h"
#include "MeshChecker.h"
#include "MeshOptimization.h"
#include "MeshScan.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace volgrid;

namespace
{
// Says "stop" from its n-th question on.
struct CancelFrom final : Progress
{
  int questions = 0, stopAt;
  explicit CancelFrom(int n)
    : stopAt(n)
  {
  }
  void report(double, const char*) override {}
  bool cancelled() override { return ++questions >= stopAt; }
};

void expectValid(const TetMesh& mesh)
{
  MeshCheckOptions options;
  options.delaunay = false; // insertions keep the mesh valid, not Delaunay
  const MeshCheckReport r = checkMesh(mesh, options);
  EXPECT_TRUE(r.valid) << r.summary();
}
} // namespace

TEST(QualityCancellation, InsertionRoundsStopBetweenAttempts)
{
  // A Delaunay mesh of random points has slivers (worst tet near 0 deg): the rounds have work.
  TetMesh full;
  randomDelaunay(full, 3000, 11);
  TetMesh cancelled = full, once = full;
  InsertionImprovementReport work;
  improveWorstByInsertion(full, nullptr, nullptr, nullptr, InsertionImprovementOptions(), &work);
  ASSERT_GT(work.attempts, 1);
  EXPECT_FALSE(work.cancelled);

  CancelFrom atOnce(1);
  InsertionImprovementReport none;
  EXPECT_EQ(
    improveWorstByInsertion(cancelled, nullptr, nullptr, nullptr, InsertionImprovementOptions(), &none, &atOnce), 0);
  EXPECT_TRUE(none.cancelled);
  EXPECT_EQ(none.attempts, 0);

  CancelFrom afterOne(4); // the set-up asks twice (after the locks, after the list of low tets), each attempt once
  InsertionImprovementReport one;
  improveWorstByInsertion(once, nullptr, nullptr, nullptr, InsertionImprovementOptions(), &one, &afterOne);
  EXPECT_TRUE(one.cancelled);
  EXPECT_EQ(one.attempts, 1);
  expectValid(once);
}

TEST(QualityCancellation, SplittingStopsWithinSixtyFourBadTets)
{
  TetMesh mesh;
  randomDelaunay(mesh, 2000, 12);
  SplitRequest request;
  request.degrees = 25; // the slivers and more: hundreds of bad tets
  request.maxPoints = 1 << 20;
  TetMesh all = mesh;
  const int64_t everything = splitBadTets(all, nullptr, nullptr, request);
  ASSERT_GT(everything, 64);
  CancelFrom atOnce(1);
  request.progress = &atOnce;
  const int64_t stopped = splitBadTets(mesh, nullptr, nullptr, request);
  EXPECT_LE(stopped, 64);
  EXPECT_EQ(atOnce.questions, 1);
  expectValid(mesh);
}

TEST(QualityCancellation, SplittingIsTheSameOnAnyThreadCount)
{
  TetMesh one;
  randomDelaunay(one, 1500, 13);
  TetMesh two = one, eight = one;
  SplitRequest request;
  request.degrees = 15;
  request.maxPoints = 1 << 20;
  const int64_t n1 = splitBadTets(one, nullptr, nullptr, request);
  request.threads = 2;
  const int64_t n2 = splitBadTets(two, nullptr, nullptr, request);
  request.threads = 8;
  const int64_t n8 = splitBadTets(eight, nullptr, nullptr, request);
  ASSERT_GT(n1, 0);
  EXPECT_EQ(n1, n2);
  EXPECT_EQ(n1, n8);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.points, eight.points);
  EXPECT_EQ(one.tetVertices, two.tetVertices);
  EXPECT_EQ(one.tetVertices, eight.tetVertices);
  expectValid(one);
}

// An optimisation pass asks every 1024 tets (and vertices) whether to stop: a first pass over the bad tets of
// a million-tet mesh takes about a third of a second, more than a user waits after pressing stop.
TEST(QualityCancellation, OptimisationStopsWithinAPass)
{
  TetMesh full;
  randomDelaunay(full, 20000, 5);
  TetMesh cancelled = full;
  OptimizationOptions options;
  options.summaries = false;
  options.maxPasses = 1;
  OptimizationReport onePass, stopped;
  ASSERT_TRUE(optimizeMesh(full, nullptr, nullptr, nullptr, options, nullptr, &onePass).ok());
  ASSERT_GT(onePass.belowTargetBefore, 2048); // the pass has more than 1024 bad tets to go through
  // The set-up asks three times (after the editor's map, after the locks, after the sweep for the bad tets:
  // one block of slots), the pass's start fourth, its 1024th bad tet fifth.
  CancelFrom progress(5);
  const Status s = optimizeMesh(cancelled, nullptr, nullptr, nullptr, options, &progress, &stopped);
  EXPECT_EQ(s.kind, ErrorKind::Cancelled);
  EXPECT_EQ(progress.questions, 5);
  EXPECT_GT(stopped.flips23 + stopped.edgeRemovals, 0);                                      // it had begun,
  EXPECT_LT(stopped.flips23 + stopped.edgeRemovals, onePass.flips23 + onePass.edgeRemovals); // not finished
  expectValid(cancelled);
}

// The whole-mesh sweep for the bad tets asks between blocks of kSlotsPerQuestion slots (a sweep of 5M tets
// takes a quarter of a second on one thread): here a mesh whose live tets sit in three such blocks (free
// slots between them). Never told to stop, it gives what the sweep without questions gives; told to stop at
// its first question, it stops after the first block.
TEST(QualityCancellation, TheSweepForBadTetsAsksBetweenBlocks)
{
  TetMesh mesh;
  randomDelaunay(mesh, 2000, 3);
  const int32_t live = mesh.tetCapacity();
  const int32_t first = mesh.appendTets(static_cast<int32_t>(2 * kSlotsPerQuestion));
  for (int32_t t = first; t < mesh.tetCapacity(); ++t)
    mesh.tetFlags[static_cast<size_t>(t)] = TetMesh::kFree;
  // The live tets again at the end (a copy: quality is all the sweep reads).
  const int32_t copy = mesh.appendTets(live);
  std::copy_n(mesh.tetVertices.begin(), 4 * static_cast<size_t>(live),
              mesh.tetVertices.begin() + 4 * static_cast<ptrdiff_t>(copy));
  std::copy_n(mesh.tetFlags.begin(), live, mesh.tetFlags.begin() + copy);
  const double q = std::sin(20.0 * 3.14159265358979323846 / 180.0);
  std::vector<std::pair<double, int32_t>> plain, asked, stopped;
  ASSERT_TRUE(collectSineBelow(mesh, q, 2, plain));
  ASSERT_GT(plain.size(), 0u);
  CancelFrom never(1 << 30), atOnce(1);
  EXPECT_TRUE(collectSineBelow(mesh, q, 2, asked, &never));
  EXPECT_EQ(never.questions, 2); // between the three blocks
  EXPECT_EQ(asked, plain);
  EXPECT_FALSE(collectSineBelow(mesh, q, 2, stopped, &atOnce));
  EXPECT_EQ(atOnce.questions, 1);
  EXPECT_EQ(2 * stopped.size(), plain.size()); // the first block's half
}
