// The whole pipeline under a user's stop (the filter's abort): every question the stages ask is honoured.
// From any question on, the answer "stop" ends the run with ErrorKind::Cancelled, an empty result and only
// a few more questions; asking does not change the mesh. Both on the small-mesh paths and, with
// largeMeshTets lowered, on the paths of millions of tets (spatial renumbering, coloured smoothing, collapses
// throughout, blockwise summaries and map refreshes), whose whole-mesh steps ask between their blocks.
#include "Enclosures.h"
#include "Mesher.h"

#include <gtest/gtest.h>

using namespace volgrid;

namespace
{
// Counts the questions; says "stop" from the stopAt-th one on (never when stopAt is 0).
struct StopFrom final : Progress
{
  int64_t questions = 0, stopAt = 0;
  void report(double, const char*) override {}
  bool cancelled() override { return ++questions >= stopAt && stopAt > 0; }
};

SurfaceMesh sphereInSphere()
{
  SurfaceMesh s, outer;
  EnclosureOptions o;
  o.shape = EnclosureShape::Sphere;
  o.dimensions[0] = 1;
  o.targetEdgeLength = 0.15;
  EXPECT_TRUE(makeEnclosure(o, s).ok());
  o.dimensions[0] = 4;
  o.targetEdgeLength = 1.0;
  EXPECT_TRUE(makeEnclosure(o, outer).ok());
  s.append(outer);
  return s;
}

void expectEveryQuestionHonoured(const MesherOptions& options)
{
  const SurfaceMesh surface = sphereInSphere();
  MesherResult plain, asked;
  ASSERT_TRUE(meshSurface(surface, options, plain).ok());
  StopFrom counter;
  ASSERT_TRUE(meshSurface(surface, options, asked, &counter).ok());
  EXPECT_EQ(asked.tets, plain.tets) << "asking whether to stop changed the mesh";
  EXPECT_EQ(asked.points, plain.points);
  const int64_t n = counter.questions;
  ASSERT_GT(n, 20) << "the stages must ask while they work";
  for (int64_t k = 1; k <= n; ++k) // a few dozen questions at this size: every one
  {
    StopFrom stop;
    stop.stopAt = k;
    MesherResult r;
    const Status s = meshSurface(surface, options, r, &stop);
    EXPECT_EQ(s.kind, ErrorKind::Cancelled) << "stop from question " << k << " of " << n << ": " << s.message;
    EXPECT_TRUE(r.tets.empty() && r.points.empty()) << "stop from question " << k;
    EXPECT_LE(stop.questions - k, 8) << "stop from question " << k << ": asked on after the stop";
  }
}
} // namespace

TEST(MesherCancellation, EveryQuestionStopsTheRun)
{
  MesherOptions options;
  options.threads = 1; // the questions' count and order do not depend on timing
  expectEveryQuestionHonoured(options);
}

TEST(MesherCancellation, EveryQuestionStopsTheRunOnTheLargeMeshPaths)
{
  MesherOptions options;
  options.threads = 1;
  options.improvement.optimization.largeMeshTets = 2000;
  expectEveryQuestionHonoured(options);
}
