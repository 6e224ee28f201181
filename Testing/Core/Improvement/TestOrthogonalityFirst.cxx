// The orthogonality-first rule (OrthogonalityFirst.h): the cavity counts the splits decide on are the
// mesh's real change, flips, splits and smoothing moves under the rule add no tet under the target and
// (splits, moves) no severely non-orthogonal face, and the mesher with the rule keeps the boundary exactly,
// gives the same mesh on any thread count and fewer severe faces than without it.
#include "BadTetSplitting.h"
#include "BoundaryCheck.h"
#include "CfdQuality.h"
#include "ColouredSmoothing.h"
#include "Mesh/RandomDelaunay.h"
#include "MeshOptimization.h"
#include "Mesher.h"
#include "MesherTestShapes.h"
#include "OrthogonalityFirst.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace volgrid;

namespace
{
// Counted here from the definition (checkMesh's: the angle between the centroid line and the face
// normal), not with the editor's bookkeeping: interior faces over 70 degrees, and tets under q.
struct MeshCounts
{
  int64_t severe = 0, below = 0;
};
MeshCounts countMesh(const TetMesh& m, double q)
{
  const double limit = std::cos(quality::kSevereNonOrthogonality * 3.14159265358979323846 / 180);
  auto centroid = [&](int32_t t, double c[3])
  {
    for (int k = 0; k < 3; ++k)
      c[k] = (m.point(m.vertex(t, 0))[k] + m.point(m.vertex(t, 1))[k] + m.point(m.vertex(t, 2))[k] +
              m.point(m.vertex(t, 3))[k]) /
        4;
  };
  MeshCounts counts;
  m.forEachTet(
    [&](int32_t t)
    {
      const int32_t* w = m.vertices(t);
      counts.below += tetSineQuality(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3])) < q;
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = m.neighbor(t, i);
        if (u < t)
          continue;
        double ct[3], cu[3], n[3];
        centroid(t, ct);
        centroid(u, cu);
        int32_t f[3];
        m.faceVertices(t, i, f);
        const double *a = m.point(f[0]), *b = m.point(f[1]), *c = m.point(f[2]);
        n[0] = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        n[1] = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
        n[2] = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        const double d[3] = { cu[0] - ct[0], cu[1] - ct[1], cu[2] - ct[2] };
        const double dot = std::abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
        const double len =
          std::sqrt((n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        counts.severe += !(dot >= limit * len);
      }
    });
  return counts;
}

// The rule with every edit bound by it (no tet counts as nearly flat), so that the tests see it at work.
OrthogonalityFirst everyEditBound(double targetDegrees)
{
  OrthogonalityFirst rule = OrthogonalityFirst::forTarget(targetDegrees);
  rule.degenerateQuality = 0;
  return rule;
}

double sineOf(double degrees)
{
  return std::sin(degrees * 3.14159265358979323846 / 180);
}

// Prints the counts of a sweep of `edits`, which must have edited; with the rule, no count may have risen.
void expectNoMoreUnderTheRule(bool withRule, const char* edits, int64_t count, const MeshCounts& before,
                              const MeshCounts& after)
{
  std::printf("%s: %lld %s; severe faces %lld -> %lld, tets under 18 deg %lld -> %lld\n", withRule ? "rule" : "no rule",
              static_cast<long long>(count), edits, static_cast<long long>(before.severe),
              static_cast<long long>(after.severe), static_cast<long long>(before.below),
              static_cast<long long>(after.below));
  EXPECT_GT(count, 0) << edits << (withRule ? " with the rule" : " without it");
  if (withRule)
  {
    EXPECT_LE(after.severe, before.severe) << edits;
    EXPECT_LE(after.below, before.below) << edits;
  }
}

// meshSurface, then the independent check: a valid mesh whose boundary is the input and whose volume is the
// enclosed one.
MesherResult meshAndCheck(const SurfaceMesh& s, const MesherOptions& options)
{
  MesherResult r;
  const Status st = meshSurface(s, options, r);
  EXPECT_TRUE(st.ok()) << st.message;
  const BoundaryCheckReport br =
    checkBoundaryConformity(r.points, r.numInputPoints, r.tets, s.triangles, r.stats.enclosedVolume);
  EXPECT_TRUE(br.meshValid() && br.boundaryEqualsInput()) << br.summary();
  EXPECT_LT(br.relativeVolumeError, 1e-9);
  return r;
}
} // namespace

// For quality-driven cavities at random positions, the counts of the cavity (before committing) are the
// change of the whole mesh's counts after the insertion.
TEST(OrthogonalityFirst, CavityCountsAreTheMeshsChange)
{
  TetMesh mesh;
  randomDelaunay(mesh, 400, 11);
  std::mt19937 rng(5);
  const double q = sineOf(18), severeCosine = std::cos(quality::kSevereNonOrthogonality * 3.14159265358979323846 / 180);
  int checked = 0, withSevereChange = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    TetMesh copy = mesh;
    TetEditor editor(copy, nullptr, nullptr);
    std::vector<int32_t> live;
    copy.forEachTet([&](int32_t t) { live.push_back(t); });
    const int32_t t = live[rng() % live.size()];
    double p[3] = { 0, 0, 0 };
    std::uniform_real_distribution<double> w(0.1, 1.0);
    double ws[4], sum = 0;
    for (double& x : ws)
      sum += x = w(rng);
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k)
        p[k] += ws[i] / sum * copy.point(copy.vertex(t, i))[k];
    const int32_t nv = copy.addPoint(p);
    if (!(editor.qualityInsertion(nv, t, t, nullptr, false) > -3))
      continue;
    int newBelow = 0, oldBelow = 0;
    editor.countBelowInLastCavity(nv, q, newBelow, oldBelow);
    const int severeChange = editor.severeChangeOfLastCavity(nv, severeCosine);
    const MeshCounts before = countMesh(copy, q);
    ASSERT_GT(editor.qualityInsertion(nv, t, t, nullptr, true), -3);
    const MeshCounts after = countMesh(copy, q);
    EXPECT_EQ(after.below - before.below, newBelow - oldBelow) << trial;
    EXPECT_EQ(after.severe - before.severe, severeChange) << trial;
    ++checked;
    withSevereChange += severeChange != 0;
  }
  EXPECT_GT(checked, 30);
  EXPECT_GT(withSevereChange, 0); // else the severe counts were not put to the test
}

// Edge removals and 2-3 flips bound by the rule never raise the mesh's count of tets under the target;
// without it some do (so the rule is what holds the count).
TEST(OrthogonalityFirst, FlipsAddNoTetUnderTheTarget)
{
  const OrthogonalityFirst rule = everyEditBound(18);
  int64_t raisedWithout = 0;
  for (const bool withRule : { true, false })
  {
    TetMesh mesh;
    randomDelaunay(mesh, 300, 3);
    TetEditor editor(mesh, nullptr, nullptr);
    std::vector<int32_t> slots, created;
    mesh.forEachTet([&](int32_t t) { slots.push_back(t); });
    int64_t edits = 0;
    for (const int32_t t : slots)
      for (int e = 0; e < 6 && !mesh.isFree(t); ++e)
      {
        static constexpr int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
        const int64_t before = countMesh(mesh, rule.targetQuality).below;
        const int32_t x = mesh.vertex(t, kEdge[e][0]), y = mesh.vertex(t, kEdge[e][1]);
        const bool done = e < 4 ? tryEdgeRemoval(editor, t, x, y, 9, &created, withRule ? &rule : nullptr) ||
            (!mesh.isFree(t) && tryFlip23(editor, t, e, &created, withRule ? &rule : nullptr))
                                : tryEdgeRemoval(editor, t, x, y, 9, &created, withRule ? &rule : nullptr);
        if (!done)
          continue;
        ++edits;
        const int64_t after = countMesh(mesh, rule.targetQuality).below;
        if (withRule)
        {
          EXPECT_LE(after, before) << "tet " << t << " edge " << e;
        }
        else
          raisedWithout += after > before;
      }
    EXPECT_GT(edits, 20) << withRule;
  }
  EXPECT_GT(raisedWithout, 0);
}

// Splits of the tets under 18 degrees bound by the rule: points go in, and the mesh has no more severe
// faces and no more tets under 18 degrees than before; without the rule it gets more severe faces.
TEST(OrthogonalityFirst, SplitsAddNoSevereFaceAndNoTetUnderTheirAim)
{
  MeshCounts without;
  for (const bool withRule : { true, false })
  {
    TetMesh mesh;
    randomDelaunay(mesh, 500, 9);
    const MeshCounts before = countMesh(mesh, sineOf(18));
    SplitRequest request;
    request.degrees = 18;
    request.maxPoints = 1000;
    if (withRule)
      request.orthogonalityFirst = everyEditBound(18);
    const int64_t inserted = splitBadTets(mesh, nullptr, nullptr, request);
    const MeshCounts after = countMesh(mesh, sineOf(18));
    expectNoMoreUnderTheRule(withRule, "points", inserted, before, after);
    if (!withRule)
      without = MeshCounts{ after.severe - before.severe, after.below - before.below };
  }
  EXPECT_GT(without.severe, 0); // the rule is what holds the count
}

// Smoothing in colour classes under the rule: moves are made, and the mesh has no more severe faces and no
// more tets under the target than before the sweep; the rule undoes moves that the sweep without it keeps.
TEST(OrthogonalityFirst, ColouredSmoothingUndoesTheMovesTheRuleRefuses)
{
  const OrthogonalityFirst rule = everyEditBound(18);
  int64_t movedWith = 0, movedWithout = 0;
  for (const bool withRule : { true, false })
  {
    TetMesh mesh;
    randomDelaunay(mesh, 600, 21);
    TetEditor editor(mesh, nullptr, nullptr);
    const std::vector<uint8_t> locked = editor.lockedVertices();
    std::vector<int32_t> vertices;
    for (int32_t v = 0; v < mesh.numVertices(); ++v)
      if (!locked[v])
        vertices.push_back(v);
    const MeshCounts before = countMesh(mesh, rule.targetQuality);
    std::vector<SmoothMove> moves;
    SmoothingOptions options;
    options.belowDegrees = 30;
    smoothColoured(editor, vertices, options, 2, moves, withRule ? &rule : nullptr);
    const MeshCounts after = countMesh(mesh, rule.targetQuality);
    const int64_t moved = std::count_if(moves.begin(), moves.end(), [](SmoothMove m) { return m != SmoothMove::None; });
    expectNoMoreUnderTheRule(withRule, "moves", moved, before, after);
    (withRule ? movedWith : movedWithout) = moved;
  }
  EXPECT_LT(movedWith, movedWithout);
}

// The mesher with the rule: exact boundary and volume, the same mesh for 1, 2 and 8 threads, and fewer faces
// that a solver finds severely non-orthogonal than without it (checkMesh's definition, cfdMetrics) on a
// thin plate in a sphere, whose edges force bad tets; both on the small-mesh path and on the large-mesh one
// (smoothing in colour classes, whose moves the rule undoes class by class).
TEST(OrthogonalityFirst, MesherKeepsTheBoundaryAndTheThreadRuleWithFewerSevereFaces)
{
  const SurfaceMesh s = testshapes::plateInSphere();
  MesherOptions plain;
  plain.threads = 2;
  const MesherResult reference = meshAndCheck(s, plain);
  for (const int64_t largeMeshTets : { kLargeMeshTets, int64_t{ 0 } })
  {
    std::vector<MesherResult> results;
    for (const int threads : { 1, 2, 8 })
    {
      MesherOptions o;
      o.threads = threads;
      o.improvement.orthogonalityFirst = true;
      o.improvement.optimization.largeMeshTets = largeMeshTets;
      results.push_back(meshAndCheck(s, o));
    }
    for (size_t k = 1; k < results.size(); ++k)
    {
      EXPECT_EQ(results[k].points, results[0].points) << k;
      EXPECT_EQ(results[k].tets, results[0].tets) << k;
    }
    const int64_t severeWith =
      quality::cfdMetrics(results[0].points, results[0].tets, nullptr).severelyNonOrthogonalFaces;
    const int64_t severeWithout =
      quality::cfdMetrics(reference.points, reference.tets, nullptr).severelyNonOrthogonalFaces;
    std::printf("large-mesh path from %lld tets: severe faces %lld with the rule, %lld without\n",
                static_cast<long long>(largeMeshTets), static_cast<long long>(severeWith),
                static_cast<long long>(severeWithout));
    EXPECT_LT(severeWith, severeWithout);
  }
}
