#include "MeshOptimization.h"
#include "ColouredSmoothing.h"
#include "MeshScan.h"
#include "ParallelFor.h"
#include "RegionFlips.h"

#include "RingTriangulation.h"

#include "Predicates.h"
#include "PredicatesInline.h"
#include "Quality.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

namespace volgrid
{

namespace
{
inline double tetQ(const TetMesh& m, int32_t a, int32_t b, int32_t c, int32_t d)
{
  return tetSineQuality(m.point(a), m.point(b), m.point(c), m.point(d));
}
inline double tetQ(const TetMesh& m, int32_t t)
{
  const int32_t* w = m.vertices(t);
  return tetQ(m, w[0], w[1], w[2], w[3]);
}
inline bool positive(const TetMesh& m, const std::array<int32_t, 4>& q)
{
  return predicates::orient3dInline(m.point(q[0]), m.point(q[1]), m.point(q[2]), m.point(q[3])) > 0;
}

// Sine of the dihedral angle at each edge (0,1) (0,2) (0,3) (1,2) (1,3) (2,3) of tet t (unsigned).
void edgeSines(const TetMesh& m, int32_t t, double s[6])
{
  const int32_t* w = m.vertices(t);
  const double *a = m.point(w[0]), *b = m.point(w[1]), *c = m.point(w[2]), *d = m.point(w[3]);
  double ang[6];
  quality::tetDihedralAngles(a, b, c, d, ang);
  for (int i = 0; i < 6; ++i)
    s[i] = std::sin(ang[i] * 3.14159265358979323846 / 180.0);
}
constexpr int kEdge[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };

struct Scratch
{
  std::vector<int32_t> ring, tets;
  std::vector<double> Q;
  std::vector<int> K;
  std::vector<std::array<int32_t, 4>> newTets;
};
Scratch& scratch()
{
  static thread_local Scratch s;
  return s;
}

} // namespace

namespace
{
// The smallest and largest dihedral angles of a tet (Quality.h). This summary runs after every
// optimisation pass.
void minMaxDihedral(const double* p0, const double* p1, const double* p2, const double* p3, double& lo, double& hi)
{
  quality::tetDihedralExtremes(p0, p1, p2, p3, lo, hi);
}
} // namespace

DihedralSummary summarizeDihedrals(const TetMesh& mesh, int threads, Progress* progress)
{
  return summarizeDihedrals(mesh.points.data(), mesh.tetVertices.data(), mesh.tetFlags.data(), mesh.tetCapacity(),
                            threads, progress);
}

DihedralSummary summarizeDihedrals(const double* points, const int32_t* tetVertices, const uint8_t* tetFlags, int64_t n,
                                   int threads, Progress* progress)
{
  // Runs over the whole mesh several times per optimisation and insertion round (a tenth of a second per
  // 800,000 tets): the tet slots are split between threads, the partial summaries merged (min, max and
  // counts, so the result does not depend on the split).
  auto point = [points](int32_t v) { return points + 3 * static_cast<size_t>(v); };
  auto summarize = [&](int64_t begin, int64_t end, DihedralSummary& s)
  {
    for (int64_t t = begin; t < end; ++t)
    {
      if (tetFlags && (tetFlags[t] & TetMesh::kFree))
        continue;
      const int32_t* w = tetVertices + 4 * t;
      if ((w[0] | w[1] | w[2] | w[3]) < 0)
        continue;
      const double *a = point(w[0]), *b = point(w[1]), *c = point(w[2]), *d = point(w[3]);
      double lo, hi;
      minMaxDihedral(a, b, c, d, lo, hi);
      ++s.tets;
      s.minDihedral = std::min(s.minDihedral, lo);
      s.maxDihedral = std::max(s.maxDihedral, hi);
      s.below10 += lo < 10;
      s.above170 += hi > 170;
      s.inverted += predicates::orient3dInline(a, b, c, d) <= 0;
    }
  };
  constexpr int64_t kMinPerThread = 25000, kSlotsPerQuestion = int64_t{ 1 } << 20;
  const int64_t block = progress ? kSlotsPerQuestion : std::max<int64_t>(n, 1);
  DihedralSummary s;
  std::vector<DihedralSummary> parts;
  for (int64_t first = 0; first < n; first += block)
  {
    if (first > 0 && progress->cancelled())
      break;
    const int64_t count = std::min(block, n - first);
    parts.assign(static_cast<size_t>(parallelRanges(threads, count, kMinPerThread)), DihedralSummary());
    parallelFor(threads, count, kMinPerThread,
                [&](int k, int64_t begin, int64_t end)
                { summarize(first + begin, first + end, parts[static_cast<size_t>(k)]); });
    for (const DihedralSummary& p : parts) // min, max and counts: the same for any split
    {
      s.tets += p.tets;
      s.minDihedral = std::min(s.minDihedral, p.minDihedral);
      s.maxDihedral = std::max(s.maxDihedral, p.maxDihedral);
      s.below10 += p.below10;
      s.above170 += p.above170;
      s.inverted += p.inverted;
    }
  }
  return s;
}

namespace
{
// Whether rule refuses replacing the tets `old` (worst quality qOld) by `replacement`: it binds and the
// replacement holds more tets under its target.
bool addsTetsUnderTarget(const TetMesh& m, const OrthogonalityFirst* rule, double qOld, const std::vector<int32_t>& old,
                         const std::vector<std::array<int32_t, 4>>& replacement)
{
  if (!rule || !rule->binds(qOld))
    return false;
  int64_t before = 0, after = 0;
  for (int32_t u : old)
    before += tetQ(m, u) < rule->targetQuality;
  for (const auto& q : replacement)
    after += tetQ(m, q[0], q[1], q[2], q[3]) < rule->targetQuality;
  return after > before;
}

// Whether `replacement` pays for tets whose Region is `old`: each new tet over its floor, and
// TetNeeds::pays. now: the Region of the replacement.
bool paysForNeeds(const TetMesh& m, const TetNeeds& needs, const TetNeeds::Region& old,
                  const std::vector<std::array<int32_t, 4>>& replacement, TetNeeds::Region& now)
{
  now = TetNeeds::Region();
  for (const auto& q : replacement)
  {
    const double quality = tetQ(m, q[0], q[1], q[2], q[3]);
    if (needs.newScore(old, q.data(), quality) < 0)
      return false;
    needs.add(now, q.data(), quality);
  }
  return needs.pays(old, now);
}

// editor.replace, and with needs its counts after the edit (TetNeeds::record).
bool replaceFor(TetEditor& editor, const std::vector<int32_t>& old, const std::vector<std::array<int32_t, 4>>& tets,
                std::vector<int32_t>* created, const TetNeeds* needs, const TetNeeds::Region& oldRegion,
                const TetNeeds::Region& newRegion)
{
  if (!editor.replace(old, tets, created))
    return false;
  if (needs)
    needs->record(oldRegion, newRegion);
  return true;
}
} // namespace

bool tryEdgeRemoval(TetEditor& editor, int32_t t, int32_t x, int32_t y, int maxRing, std::vector<int32_t>* created,
                    const OrthogonalityFirst* rule, const TetNeeds* needs)
{
  Scratch& s = scratch();
  TetMesh& m = editor.mesh;
  if (!editor.edgeRing(t, x, y, s.ring, s.tets, maxRing))
    return false;
  const int n = static_cast<int>(s.ring.size());
  double qOld = 2;
  for (int32_t u : s.tets)
    qOld = std::min(qOld, tetQ(m, u));
  const TetNeeds::Region old = needs ? needs->region(m, s.tets) : TetNeeds::Region();
  const std::vector<int32_t>& r = s.ring;
  // A tet's score: its quality, or with needs its score (TetNeeds.h).
  auto tetScore = [&](int32_t a, int32_t b, int32_t c, int32_t d)
  {
    const double q = tetQ(m, a, b, c, d);
    const int32_t w[4] = { a, b, c, d };
    return needs ? needs->newScore(old, w, q) : q;
  };
  // Only a triangulation better than the old star is used: the DP's floor. A split that cannot beat the
  // chord's best so far is skipped without its second tet.
  const double floor = needs ? old.score : std::max(qOld, 0.0);
  auto score = [&](int i, int k, int j, double bound)
  {
    const double q1 = tetScore(r[i], r[k], r[j], y);
    if (!(q1 > bound))
      return q1;
    return std::min(q1, tetScore(r[i], r[j], r[k], x));
  };
  if (!maxMinTriangulation(n, floor, s.Q, s.K, score))
    return false;
  s.newTets.clear();
  appendRingTets(s.K, r, x, y, ChordOrder::PieceBeforeApexFirst, s.newTets);
  for (const auto& q : s.newTets)
    if (!positive(m, q))
      return false;
  TetNeeds::Region now;
  if (addsTetsUnderTarget(m, rule, qOld, s.tets, s.newTets) ||
      (needs && !paysForNeeds(m, *needs, old, s.newTets, now)))
    return false;
  return replaceFor(editor, s.tets, s.newTets, created, needs, old, now); // replace() does not touch this scratch
}

bool tryFlip23(TetEditor& editor, int32_t t, int face, std::vector<int32_t>* created, const OrthogonalityFirst* rule,
               const TetNeeds* needs)
{
  TetMesh& m = editor.mesh;
  if (editor.isConstrainedFace(t, face))
    return false;
  const int32_t u = m.neighbor(t, face);
  const int j = m.mirrorFace(t, face);
  const int32_t d = m.vertex(t, face), e = m.vertex(u, j);
  int32_t f[3];
  m.faceVertices(t, face, f);
  const double qOld = std::min(tetQ(m, t), tetQ(m, u));
  std::vector<std::array<int32_t, 4>>& nt = scratch().newTets;
  nt.clear();
  nt.push_back({ f[0], f[1], e, d });
  nt.push_back({ f[1], f[2], e, d });
  nt.push_back({ f[2], f[0], e, d });
  std::vector<int32_t>& old = scratch().tets;
  old.assign({ t, u });
  double qNew = 2;
  for (const auto& q : nt)
    qNew = std::min(qNew, tetQ(m, q[0], q[1], q[2], q[3]));
  const TetNeeds::Region oldRegion = needs ? needs->region(m, old) : TetNeeds::Region();
  TetNeeds::Region now;
  if (needs ? !paysForNeeds(m, *needs, oldRegion, nt, now) : !(qNew > qOld))
    return false;
  if (!(qNew > 0))
    return false;
  for (const auto& q : nt)
    if (!positive(m, q))
      return false;
  if (addsTetsUnderTarget(m, rule, qOld, old, nt))
    return false;
  return replaceFor(editor, old, nt, created, needs, oldRegion, now);
}

bool tryVertexCollapse(TetEditor& editor, int32_t v, std::vector<int32_t>* created, const TetNeeds* needs)
{
  Scratch& s = scratch();
  TetMesh& m = editor.mesh;
  editor.star(v, s.tets);
  if (s.tets.size() < 4)
    return false;
  double qOld = 2;
  for (int32_t t : s.tets)
  {
    qOld = std::min(qOld, tetQ(m, t));
    const int iv = m.localIndex(t, v);
    for (int i = 0; i < 4; ++i) // the faces through v disappear: none may be constrained
      if (i != iv && editor.isConstrainedFace(t, i))
        return false;
  }
  editor.neighbors(v, s.tets, s.ring);
  const TetNeeds::Region old = needs ? needs->region(m, s.tets) : TetNeeds::Region();
  // The star of v, coned from w over its outer faces not through w: those new tets tile the star exactly
  // when all are strictly positive (their signed volumes add up to the star's, each point covered once).
  // Each w scores its worst new tet (with needs: its smallest score, -1 under a floor or with more tets
  // under 10 degrees).
  double best = needs ? old.score : qOld;
  int32_t bestW = -1;
  for (int32_t w : s.ring)
  {
    double q = 2;
    int below10 = 0;
    for (int32_t t : s.tets)
    {
      const int32_t* x = m.vertices(t);
      if (x[0] == w || x[1] == w || x[2] == w || x[3] == w)
        continue;
      std::array<int32_t, 4> n = { x[0], x[1], x[2], x[3] };
      *std::find(n.begin(), n.end(), v) = w;
      const double qn = tetQ(m, n[0], n[1], n[2], n[3]);
      if (needs)
      {
        below10 += needs->under10(n.data(), qn);
        q = std::min(q, below10 > old.below10 ? -1.0 : needs->newScore(old, n.data(), qn));
      }
      else
        q = std::min(q, qn);
      if (!(q > best))
        break;
    }
    if (!(q > best))
      continue;
    bool valid = true;
    for (int32_t t : s.tets)
    {
      const int32_t* x = m.vertices(t);
      if (x[0] == w || x[1] == w || x[2] == w || x[3] == w)
        continue;
      std::array<int32_t, 4> n = { x[0], x[1], x[2], x[3] };
      *std::find(n.begin(), n.end(), v) = w;
      if (!positive(m, n))
      {
        valid = false;
        break;
      }
    }
    if (valid)
    {
      best = q;
      bestW = w;
    }
  }
  if (bestW < 0 || !(best > 0))
    return false;
  s.newTets.clear();
  for (int32_t t : s.tets)
  {
    const int32_t* x = m.vertices(t);
    if (x[0] == bestW || x[1] == bestW || x[2] == bestW || x[3] == bestW)
      continue;
    std::array<int32_t, 4> n = { x[0], x[1], x[2], x[3] };
    *std::find(n.begin(), n.end(), v) = bestW;
    s.newTets.push_back(n);
  }
  TetNeeds::Region now;
  if (needs && !paysForNeeds(m, *needs, old, s.newTets, now)) // the share under 10 deg
    return false;
  if (!replaceFor(editor, s.tets, s.newTets, created, needs, old, now))
    return false;
  editor.forgetVertex(v);
  return true;
}

namespace
{
// The mesh's smallest dihedral angle as summarizeDihedrals() gives it, from `below` (every tet whose sine
// quality is under sin(targetDegrees), as optimizeMesh collects them): a tet with an angle under the
// target is among them, so when their smallest angle is under the target (with a margin far above the
// rounding of either measure) it is the mesh's. Otherwise a sweep.
double smallestDihedral(const TetMesh& mesh, const std::vector<std::pair<double, int32_t>>& below, double targetDegrees,
                        int threads)
{
  double m = 180;
  for (const auto& b : below)
  {
    const int32_t* w = mesh.vertices(b.second);
    double lo, hi;
    minMaxDihedral(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]), lo, hi);
    m = std::min(m, lo);
  }
  return m < targetDegrees - 1e-6 ? m : summarizeDihedrals(mesh, threads).minDihedral;
}

// The smoothing step of a pass on all threads (ColouredSmoothing.h): the unlocked vertices of `verts`
// not known to be unmoved, then those that a move of the first sweep touched (as the one-by-one order
// retries a vertex after a neighbour moved). moved(v) is called for each move, in vertex order. stop() is
// asked before and after each sweep (each up to a fifth of a second on one thread in a first pass at 5M
// tets), progress between its colour classes.
template<typename Moved, typename Stop>
void smoothInColourClasses(TetEditor& editor, const std::vector<int32_t>& verts, const std::vector<uint8_t>& lock,
                           std::vector<uint8_t>& unmoved, const OptimizationOptions& options, Moved&& moved,
                           Stop&& stop, Progress* progress)
{
  std::vector<int32_t> sweep, skipped;
  std::vector<SmoothMove> moves;
  for (int32_t v : verts)
    if (!lock[v])
      (unmoved[v] ? skipped : sweep).push_back(v);
  for (int round = 0; round < 2; ++round)
  {
    if (stop())
      return;
    if (round == 1)
    {
      sweep.clear();
      for (int32_t v : skipped)
        if (!unmoved[v])
          sweep.push_back(v);
    }
    smoothColoured(editor, sweep, options.smoothingOptions, options.threads, moves, &options.orthogonalityFirst,
                   progress);
    if (stop()) // a class that did not move for a cancel is not known to be unmoved
      return;
    for (size_t i = 0; i < sweep.size(); ++i)
      unmoved[sweep[i]] = moves[i] == SmoothMove::None;
    for (size_t i = 0; i < sweep.size(); ++i)
      if (moves[i] != SmoothMove::None)
        moved(sweep[i]);
  }
}

// Edge removal on the edges of tet t (smallest dihedral angle first), then 2-3 flips of its faces: the
// first strict improvement is kept (created receives the new tets). Deferred when that improvement needs a
// tet outside the editor's region (RegionFlips.h).
FlipAttempt tryFlipsOf(TetEditor& editor, int32_t t, const OptimizationOptions& options, OptimizationReport& report,
                       std::vector<int32_t>& created)
{
  TetMesh& mesh = editor.mesh;
  if (options.edgeRemoval)
  {
    double s[6];
    edgeSines(mesh, t, s);
    int order[6] = { 0, 1, 2, 3, 4, 5 };
    std::sort(order, order + 6, [&](int a, int b) { return s[a] < s[b]; });
    const int32_t* w = mesh.vertices(t);
    const int32_t vv[4] = { w[0], w[1], w[2], w[3] };
    for (int e = 0; e < 6; ++e)
    {
      editor.lastReplaceDeferred = false;
      if (tryEdgeRemoval(editor, t, vv[kEdge[order[e]][0]], vv[kEdge[order[e]][1]], options.maxRing, &created,
                         &options.orthogonalityFirst))
      {
        ++report.edgeRemovals;
        report.flips32 += created.size() == 2;
        return FlipAttempt::Made;
      }
      if (editor.lastReplaceDeferred)
        return FlipAttempt::Deferred;
    }
  }
  if (options.flips)
    for (int f = 0; f < 4; ++f)
    {
      editor.lastReplaceDeferred = false;
      if (tryFlip23(editor, t, f, &created, &options.orthogonalityFirst))
      {
        ++report.flips23;
        return FlipAttempt::Made;
      }
      if (editor.lastReplaceDeferred)
        return FlipAttempt::Deferred;
    }
  return FlipAttempt::None;
}
// What optimizeMesh's passes share. The passes work on a worklist, not on the whole mesh: the tets below
// the target at the start of the call are collected once (`bad`); from then on the only tets whose quality
// can have changed are those created by flips, edge removals and collapses and those in the star of a
// moved vertex (`touched`). The tets below a limit are therefore found among the last collection and the
// touched tets: the same set, in the same (quality, slot) order, as a sweep over the whole mesh, at a cost
// proportional to the work.
struct OptimizationPasses
{
  TetMesh& mesh;
  TetEditor& editor;
  const OptimizationOptions& options;
  OptimizationReport& report;
  const std::vector<uint8_t>& lock;
  std::vector<uint8_t>& unmoved;
  // A collapse of v depends on v's star alone: one that failed fails again until a tet of the star changes.
  std::vector<uint8_t> uncollapsible;
  std::vector<std::pair<double, int32_t>> bad, worst;
  std::vector<int32_t> queue, created, verts, touched, candidates, star;
  int64_t changes = 0; // in the current pass
  // Asked every 1024 tets or vertices of a pass whether to stop (a first pass over a million tets takes
  // about a third of a second); stopped says it did, leaving a valid mesh (each edit is whole).
  Progress* progress = nullptr;
  bool stopped = false;

  bool askedToStop(size_t k)
  {
    if ((k & 1023) == 1023 && progress && progress->cancelled())
      stopped = true;
    return stopped;
  }

  OptimizationPasses(TetMesh& m, TetEditor& e, const OptimizationOptions& o, OptimizationReport& r,
                     const std::vector<uint8_t>& l, std::vector<uint8_t>& u)
    : mesh(m)
    , editor(e)
    , options(o)
    , report(r)
    , lock(l)
    , unmoved(u)
  {
  }

  // The tets in `tets` changed: their vertices' smoothing and collapse may succeed again.
  void changed(const std::vector<int32_t>& tets)
  {
    for (int32_t u : tets)
      for (int i = 0; i < 4; ++i)
        unmoved[mesh.vertex(u, i)] = 0;
    if (!uncollapsible.empty())
      for (int32_t u : tets)
        for (int i = 0; i < 4; ++i)
          uncollapsible[mesh.vertex(u, i)] = 0;
  }

  // The live tets under qLimit among `bad` and `touched`, in (quality, slot) order.
  void collectBelow(double qLimit, std::vector<std::pair<double, int32_t>>& out)
  {
    candidates.clear();
    for (const auto& b : bad)
      candidates.push_back(b.second);
    candidates.insert(candidates.end(), touched.begin(), touched.end());
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    out.clear();
    for (int32_t t : candidates)
      if (!mesh.isFree(t))
      {
        const double q = tetQ(mesh, t);
        if (q < qLimit)
          out.emplace_back(q, t);
      }
    std::sort(out.begin(), out.end());
  }

  // Flips on every bad tet (worst first; by slot on large meshes, where many are first flipped by regions on
  // the threads), and on the new tets still under qT.
  void flipBadTets(double qT)
  {
    queue.clear();
    for (const auto& b : bad)
      queue.push_back(b.second);
    if (mesh.numTets() >= options.largeMeshTets)
    {
      std::sort(queue.begin(), queue.end());
      const int regions = regionFlipCount(options.regionTets, static_cast<int64_t>(queue.size()));
      if (regions > 1 && !flipByRegions(qT, regions))
        return;
    }
    for (size_t k = 0; k < queue.size() && !askedToStop(k); ++k)
    {
      const int32_t t = queue[k];
      if (mesh.isFree(t) || tetQ(mesh, t) >= qT)
        continue;
      if (tryFlipsOf(editor, t, options, report, created) == FlipAttempt::Made)
      {
        ++changes;
        touched.insert(touched.end(), created.begin(), created.end());
        changed(created);
        for (int32_t u : created)
          if (tetQ(mesh, u) < qT)
            queue.push_back(u);
      }
    }
  }

  // The queue's flips by regions on the threads (RegionFlips.h); the queue becomes what they left. False when
  // cancelled (stopped).
  bool flipByRegions(double qT, int regions)
  {
    std::atomic<int64_t> edgeRemovals(0), flips32(0), flips23(0);
    auto attempt = [&](TetEditor& regionEditor, int32_t t, std::vector<int32_t>& made)
    {
      OptimizationReport counts;
      const FlipAttempt a = tryFlipsOf(regionEditor, t, options, counts, made);
      edgeRemovals += counts.edgeRemovals;
      flips32 += counts.flips32;
      flips23 += counts.flips23;
      return a;
    };
    RegionFlipOutcome out;
    const Status s = volgrid::flipByRegions(
      editor, queue, regions, options.threads, qT, [&](int32_t t) { return tetQ(mesh, t); }, attempt, progress, out);
    report.edgeRemovals += edgeRemovals;
    report.flips32 += flips32;
    report.flips23 += flips23;
    changes += out.made;
    report.flipsInRegions += out.made;
    created.clear();
    for (int32_t u : out.created)
      if (!mesh.isFree(u))
        created.push_back(u);
    touched.insert(touched.end(), created.begin(), created.end());
    changed(created);
    queue.swap(out.deferred);
    stopped = stopped || !s.ok();
    return s.ok();
  }

  // Smoothing of the vertices of the tets under qT (in colour classes on all threads on large meshes).
  void smoothBadTets(double qT)
  {
    collectBelow(qT, worst);
    verts.clear();
    for (const auto& w : worst)
      for (int i = 0; i < 4; ++i)
        verts.push_back(mesh.vertex(w.second, i));
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    auto moved = [&](int32_t v)
    {
      ++report.smoothMoves;
      ++changes;
      editor.star(v, star);
      touched.insert(touched.end(), star.begin(), star.end());
      changed(star);
    };
    if (mesh.numTets() >= options.largeMeshTets)
      smoothInColourClasses(
        editor, verts, lock, unmoved, options, moved, [&] { return askedToStop(1023); }, progress);
    else
      for (size_t k = 0; k < verts.size() && !askedToStop(k); ++k)
      {
        const int32_t v = verts[k];
        if (lock[v] || unmoved[v])
          continue;
        // The orthogonality-first rule, when it binds the star: no more tets under the target nor severe faces.
        const RegionCounts before = countStar(v);
        const std::array<double, 3> at = { mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2] };
        if (smoothVertex(editor, v, options.smoothingOptions) == SmoothMove::None)
          unmoved[v] = 1;
        else if (options.orthogonalityFirst.binds(before.worst) && countStar(v).worseThan(before))
        {
          std::copy(at.begin(), at.end(), mesh.points.data() + 3 * static_cast<size_t>(v));
          unmoved[v] = 1;
        }
        else
          moved(v);
      }
  }

  // OrthogonalityFirst.h's counts over v's star (empty when the rule is off).
  RegionCounts countStar(int32_t v)
  {
    if (!options.orthogonalityFirst.enabled)
      return RegionCounts{};
    editor.star(v, star);
    std::sort(star.begin(), star.end());
    return countRegion(mesh, star, options.orthogonalityFirst);
  }

  // Last resort, after flips and moves: collapse an unlocked vertex of the tets still far below the
  // target (worst first), e.g. recovery's Steiner points pinned against nearly coplanar boundary faces.
  void collapseWorst()
  {
    const double qR =
      std::sin(std::min(options.targetDegrees, options.vertexRemovalDegrees) * 3.14159265358979323846 / 180.0);
    collectBelow(qR, worst);
    for (const auto& w : worst)
    {
      const int32_t t = w.second;
      if (mesh.isFree(t) || tetQ(mesh, t) >= qR)
        continue;
      const int32_t* x = mesh.vertices(t);
      const int32_t vv[4] = { x[0], x[1], x[2], x[3] };
      for (int i = 0; i < 4; ++i)
      {
        if (lock[vv[i]] || uncollapsible[vv[i]])
          continue;
        if (!tryVertexCollapse(editor, vv[i], &created))
        {
          uncollapsible[vv[i]] = 1;
          continue;
        }
        ++report.vertexRemovals;
        ++changes;
        touched.insert(touched.end(), created.begin(), created.end());
        changed(created);
        break;
      }
    }
  }
};
} // namespace

Status optimizeMesh(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                    std::vector<int32_t>* labels, const OptimizationOptions& options, Progress* progress,
                    OptimizationReport* reportOut, OptimizationWorklist* worklist)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InvalidOption, "Optimisation works on a mesh without ghost tets.");
  if (!(options.targetDegrees > 0 && options.targetDegrees < 90) || options.maxPasses < 0 || options.maxRing < 3)
    return Status::failure(ErrorKind::InvalidOption,
                           "Optimisation needs 0 < targetDegrees < 90, maxPasses >= 0 and maxRing >= 3.");
  OptimizationReport local;
  OptimizationReport& report = reportOut ? *reportOut : local;
  if (options.summaries)
    report.before = summarizeDihedrals(mesh, options.threads);
  std::optional<TetEditor> ownEditor;
  if (worklist && worklist->editor)
  {
    if (!worklist->editor->refreshVertexMap({}, progress))
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  }
  else
    ownEditor.emplace(mesh, constraints, labels);
  TetEditor& editor = ownEditor ? *ownEditor : *worklist->editor;
  // The map's refresh and the sweep below each take a tenth of a second or more at 5M tets.
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  std::vector<uint8_t> lock =
    worklist && worklist->constrainedLocks ? *worklist->constrainedLocks : editor.lockedVertices();
  lock.resize(static_cast<size_t>(mesh.numVertices()), 0);
  if (progress && progress->cancelled()) // the locks are a sweep of the mesh too
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  if (locked)
    for (size_t v = 0; v < lock.size() && v < locked->size(); ++v)
      lock[v] |= (*locked)[v];
  const double qT = std::sin(options.targetDegrees * 3.14159265358979323846 / 180.0);
  const bool resume = worklist && worklist->valid && worklist->targetDegrees == options.targetDegrees;
  std::vector<uint8_t> localUnmoved;
  OptimizationPasses p(mesh, editor, options, report, lock, worklist ? worklist->unmoved : localUnmoved);
  p.progress = progress;
  if (resume)
    p.bad.swap(worklist->below); // exactly what a sweep would collect: the mesh is as the last call left it
  else
  {
    if (!collectSineBelow(mesh, qT, options.threads, p.bad, progress))
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    std::sort(p.bad.begin(), p.bad.end());
    p.unmoved.clear();
    if (progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  }
  p.unmoved.resize(static_cast<size_t>(mesh.numVertices()), 0);
  p.uncollapsible.assign(options.vertexRemoval ? p.unmoved.size() : 0, 0);
  if (worklist)
    worklist->valid = false; // until this call ends
  report.belowTargetBefore = static_cast<int64_t>(p.bad.size());
  report.minDihedralBefore = options.summaries ? report.before.minDihedral
                                               : smallestDihedral(mesh, p.bad, options.targetDegrees, options.threads);
  for (int pass = 0; pass < options.maxPasses && !p.bad.empty(); ++pass)
  {
    if (progress)
    {
      if (progress->cancelled())
        return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
      progress->report(double(pass) / options.maxPasses, "Optimising");
    }
    p.changes = 0;
    p.touched.clear();
    p.flipBadTets(qT);
    if (options.smoothing && !p.stopped)
      p.smoothBadTets(qT);
    // Coloured smoothing and the collapses each take up to 0.2 s in a first pass at 5M tets.
    if (p.stopped || (progress && progress->cancelled()))
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    if (options.vertexRemoval)
      p.collapseWorst();
    if (progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    report.passes = pass + 1;
    p.collectBelow(qT, p.bad);
    if (p.changes == 0)
      break;
  }
  report.belowTargetAfter = static_cast<int64_t>(p.bad.size());
  if (worklist)
  {
    worklist->below = p.bad;
    worklist->targetDegrees = options.targetDegrees;
    worklist->valid = true;
  }
  if (options.summaries)
    report.after = summarizeDihedrals(mesh, options.threads);
  report.minDihedralAfter = options.summaries ? report.after.minDihedral
                                              : smallestDihedral(mesh, p.bad, options.targetDegrees, options.threads);
  report.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return Status::success();
}

} // namespace volgrid
