#include "InsertionImprovement.h"

#include "CompassSearch.h"
#include "MeshOptimization.h"
#include "MeshScan.h"
#include "MeshSmoothing.h"
#include "ParallelFor.h"
#include "Predicates.h"
#include "Quality.h"
#include "ScoringHelpers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <set>
#include <utility>

namespace volgrid
{

namespace
{
double tetQuality(const TetMesh& m, int32_t t)
{
  const int32_t* v = m.vertices(t);
  return tetSineQuality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

double minDihedral(const TetMesh& m, int32_t t)
{
  const int32_t* v = m.vertices(t);
  double a[6];
  quality::tetDihedralAngles(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), a);
  return *std::min_element(a, a + 6);
}

// The smallest and the largest dihedral angle of the mesh (two angles per tet, not six: this runs twice
// per round over the whole mesh).
std::pair<double, double> dihedralRange(const TetMesh& mesh, int threads)
{
  const DihedralSummary s = summarizeDihedrals(mesh, threads);
  return { s.minDihedral, s.maxDihedral };
}

double degreesToQuality(double degrees)
{
  return std::sin(std::min(90.0, degrees) * 3.14159265358979323846 / 180.0);
}

// One sweep per round instead of four: every tet under `limit` (sine quality), worst first. A tet outside
// has every dihedral angle in [asin(limit), 180 - asin(limit)], so the mesh's worst quality, the tets
// under a smaller limit, its smallest angle and its dihedral range follow exactly from these tets whenever
// the extreme lies among them; otherwise (rare: a mesh with no tet that bad) a sweep as before.
class LowTets
{
public:
  // progress (optional): asked during the sweep; when it says stop, the list is incomplete (the caller stops).
  LowTets(const TetMesh& mesh, double limit, int threads, Progress* progress = nullptr)
    : mesh_(mesh)
    , limit_(limit)
    , threads_(threads)
  {
    std::vector<std::pair<double, int32_t>> low;
    collectSineBelow(mesh, limit, threads, low, progress);
    for (const auto& e : low)
      tets_.push_back(entry(e.first, e.second));
    std::sort(tets_.begin(), tets_.end());
  }

  double worstQuality() const { return tets_.empty() ? minSineQuality(mesh_, threads_) : tets_.front().q; }

  // The tets under q, in (quality, slot) order.
  void below(double q, std::vector<std::pair<double, int32_t>>& out) const
  {
    if (q > limit_)
    {
      collectSineBelow(mesh_, q, threads_, out);
      std::sort(out.begin(), out.end());
      return;
    }
    out.clear();
    for (const Entry& t : tets_)
      if (t.q < q)
        out.emplace_back(t.q, t.t);
  }

  // After edits that touched only `changed` (slots, repeats allowed; free ones included): the list is what
  // a new sweep would give, from those slots alone.
  void update(std::vector<int32_t>& changed)
  {
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    auto touched = [&](int32_t t) { return std::binary_search(changed.begin(), changed.end(), t); };
    tets_.erase(std::remove_if(tets_.begin(), tets_.end(), [&](const Entry& e) { return touched(e.t); }), tets_.end());
    for (int32_t t : changed)
    {
      if (t >= mesh_.tetCapacity() || mesh_.isFree(t))
        continue;
      const double q = tetQuality(mesh_, t);
      if (q < limit_)
        tets_.push_back(entry(q, t));
    }
    std::sort(tets_.begin(), tets_.end());
  }

  // The mesh's smallest dihedral angle (of the six angles of each tet).
  double smallestAngle() const
  {
    double m = 180;
    for (const Entry& t : tets_)
      m = std::min(m, minDihedral(mesh_, t.t));
    if (m < boundDegrees())
      return m;
    mesh_.forEachTet([&](int32_t t) { m = std::min(m, minDihedral(mesh_, t)); });
    return m;
  }

  // dihedralRange() of the mesh.
  std::pair<double, double> range() const
  {
    double lo = 180, hi = 0;
    for (const Entry& t : tets_)
    {
      lo = std::min(lo, t.lo);
      hi = std::max(hi, t.hi);
    }
    if (lo < boundDegrees() && hi > 180 - boundDegrees())
      return { lo, hi };
    return dihedralRange(mesh_, threads_);
  }

private:
  // A listed tet with its extreme dihedral angles, kept from when it was listed (a tet that changes is
  // listed again): range() then reads them instead of computing them again every round.
  struct Entry
  {
    double q;
    int32_t t;
    double lo, hi;
    bool operator<(const Entry& o) const { return q < o.q || (q == o.q && t < o.t); }
  };

  Entry entry(double q, int32_t t) const
  {
    Entry e{ q, t, 0, 0 };
    const int32_t* v = mesh_.vertices(t);
    quality::tetDihedralExtremes(mesh_.point(v[0]), mesh_.point(v[1]), mesh_.point(v[2]), mesh_.point(v[3]), e.lo,
                                 e.hi);
    return e;
  }

  // Angles outside [bound, 180 - bound] occur only among the collected tets (the margin is far above the
  // rounding difference between the angle and the sine measures).
  double boundDegrees() const { return std::asin(std::min(1.0, limit_)) * 180 / 3.14159265358979323846 - 1e-6; }

  const TetMesh& mesh_;
  double limit_;
  int threads_;
  std::vector<Entry> tets_;
};

// The local frame of a face: centroid, two in-plane axes, the unit normal towards `side`, and the scale
// sqrt(area) (a needle triangle gets steps fine enough for the thin wedge over it).
struct Frame
{
  double g[3], e1[3], e2[3], n[3], s;
};

bool faceFrame(const double* a, const double* b, const double* c, const double* side, Frame& f)
{
  double u[3], w[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = b[k] - a[k];
    w[k] = c[k] - a[k];
    f.g[k] = (a[k] + b[k] + c[k]) / 3;
  }
  double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
  const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (!(nn > 0) || !(lu > 0))
    return false;
  const double towards = (side[0] - a[0]) * n[0] + (side[1] - a[1]) * n[1] + (side[2] - a[2]) * n[2];
  const double sign = towards >= 0 ? 1.0 : -1.0;
  for (int k = 0; k < 3; ++k)
  {
    f.n[k] = sign * n[k] / nn;
    f.e1[k] = u[k] / lu;
  }
  f.e2[0] = f.n[1] * f.e1[2] - f.n[2] * f.e1[1];
  f.e2[1] = f.n[2] * f.e1[0] - f.n[0] * f.e1[2];
  f.e2[2] = f.n[0] * f.e1[1] - f.n[1] * f.e1[0];
  f.s = std::sqrt(nn / 2);
  return std::isfinite(f.s);
}

std::array<double, 3> at(const Frame& f, const std::array<double, 3>& x)
{
  std::array<double, 3> p;
  for (int k = 0; k < 3; ++k)
    p[k] = f.g[k] + f.s * (x[0] * f.e1[k] + x[1] * f.e2[k] + x[2] * f.n[k]);
  return p;
}

// Scores positions of the new vertex of an attempt for tet t: the worst new tet of the quality-driven
// insertion at y (cavity holding t), -3 when none; best and bestAt keep the first best it scored. It
// writes only the coordinates of its own vertex slot nv and its own editor's scratch, so scorers with
// editors and slots of their own may score at once.
struct PositionScorer
{
  TetEditor* editor;
  int32_t nv;
  int32_t t;
  double best = -3;
  std::array<double, 3> bestAt{};

  double score(const std::array<double, 3>& y)
  {
    if (!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(y[2]))
      return -3;
    TetMesh& m = editor->mesh;
    std::copy(y.begin(), y.end(), m.points.data() + 3 * static_cast<size_t>(nv));
    const int32_t start = editor->locate(y.data(), t);
    if (start < 0)
      return -3;
    const double q = editor->qualityInsertion(nv, start, t, nullptr, false, nullptr, 24, -3);
    if (!(q > 0))
      return -3;
    if (q > best)
    {
      best = q;
      bestAt = y;
    }
    return q;
  }
};

// The scorers of an attempt: the attempt's own editor and vertex, and, on more threads, the helpers'
// editors with vertex slots after it, which exist only while they score.
class Scorers
{
public:
  Scorers(TetMesh& mesh, const FaceConstraints* constraints, int threads)
    : helpers_(mesh, constraints, threads)
  {
  }
  int count() const { return helpers_.count(); }

  // Scores ys[k] into qs[k] (the score, best not kept), on up to count() threads; the same values for any
  // count, since a score depends on the position alone. own: the attempt's scorer (its vertex is the
  // mesh's last).
  void scoreAll(const PositionScorer& own, const std::vector<std::array<double, 3>>& ys, std::vector<double>& qs)
  {
    qs.assign(ys.size(), -3);
    const int ranges = parallelRanges(count(), static_cast<int64_t>(ys.size()), kMinPositionsPerThread);
    std::vector<PositionScorer> scorers = scorersFor(own, ranges);
    helpers_.withSlots(own.nv, ranges,
                       [&]
                       {
                         parallelFor(ranges, static_cast<int64_t>(ys.size()), kMinPositionsPerThread,
                                     [&](int r, int64_t begin, int64_t end)
                                     {
                                       for (int64_t k = begin; k < end; ++k)
                                         qs[static_cast<size_t>(k)] = scorers[static_cast<size_t>(r)].score(ys[k]);
                                     });
                       });
  }

  // Runs search(scorer, i) for i in [0, n) (n <= 2 searches, each scoring with its own scorer), at once on
  // two threads when there are, and folds their bests into own in order: what the searches one after the
  // other with own alone would leave there.
  template<typename Search>
  void searchEach(PositionScorer& own, int n, Search&& search)
  {
    const int ranges = std::min(n, count());
    std::vector<PositionScorer> scorers = scorersFor(own, ranges);
    for (PositionScorer& sc : scorers)
      sc.best = -3;
    helpers_.withSlots(own.nv, ranges,
                       [&]
                       {
                         if (ranges <= 1)
                           for (int i = 0; i < n; ++i)
                             search(scorers[0], i);
                         else
                           parallelRun(ranges, [&](int r) { search(scorers[static_cast<size_t>(r)], r); });
                       });
    for (const PositionScorer& sc : scorers)
      if (sc.best > own.best)
      {
        own.best = sc.best;
        own.bestAt = sc.bestAt;
      }
  }

private:
  static constexpr int64_t kMinPositionsPerThread = 16;

  // scorers[0] scores with own's editor and vertex, scorers[r] with helper r and the slot own.nv + r.
  std::vector<PositionScorer> scorersFor(const PositionScorer& own, int ranges)
  {
    std::vector<PositionScorer> scorers{ own };
    for (int r = 1; r < ranges; ++r)
      scorers.push_back({ &helpers_.helper(r), own.nv + r, own.t });
    return scorers;
  }

  ScoringHelpers helpers_;
};

class Attempt
{
public:
  // minDihedralFloor: the mesh's smallest dihedral angle; no new tet may go under it (the sine quality
  // also weighs the largest angle, so a better worst quality alone could still lower the minimum angle).
  Attempt(TetEditor& editor, Scorers& scorers, const std::vector<uint8_t>& locked, double minDihedralFloor,
          const OrthogonalityFirst& rule)
    : ed_(editor)
    , scorers_(scorers)
    , m_(editor.mesh)
    , locked_(locked)
    , floor_(minDihedralFloor)
    , rule_(rule)
  {
  }

  // Inserts a point for tet t and improves around it; true when kept (see the header).
  bool run(int32_t t)
  {
    const double qt = tetQuality(m_, t);
    nv_ = m_.addPoint(m_.point(m_.vertex(t, 0))); // coordinates overwritten by each trial position
    // Heights over t's faces of a hundredth of the face and less when the usual ones fail and t spans two
    // boundary triangles: folded onto each other, they leave a point room only in a wedge of a tenth of a
    // degree (a flat tet of four boundary vertices on cheburashka). For every failing tet they cost time
    // (the ONERA M6 domain: 1.2 s more) and changed the worst tets only by chance.
    int constrainedFaces = 0;
    for (int i = 0; i < 4; ++i)
      constrainedFaces += ed_.isConstrainedFace(t, i) ? 1 : 0;
    if (searchPosition(t, kHeights) && tryPosition(t, qt))
      return true;
    if (constrainedFaces >= 2 && searchPosition(t, kThinHeights) && tryPosition(t, qt))
      return true;
    m_.points.resize(m_.points.size() - 3); // the new point, used by no tet
    return false;
  }

private:
  static const std::vector<double> kHeights, kThinHeights; // over a face, in units of sqrt(its area)

  // The position where the quality-driven insertion makes the best worst new tet, into best_ and
  // bestAt_: from a grid of starts in the frame of each face of t at the given heights (only towards t
  // across a constrained face), then a pattern search from the best two (200 positions each at most).
  // False when no position makes a valid cavity.
  bool searchPosition(int32_t t, const std::vector<double>& heights)
  {
    PositionScorer own{ &ed_, nv_, t };
    struct Start
    {
      double q;
      int face;
      std::array<double, 3> x;
    };
    std::vector<Start> grid, starts;
    std::vector<std::array<double, 3>> ys;
    Frame frames[4];
    for (int i = 0; i < 4; ++i)
    {
      int32_t f[3];
      m_.faceVertices(t, i, f);
      if (!faceFrame(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), m_.point(m_.vertex(t, i)), frames[i]))
        continue;
      const bool bothSides = !ed_.isConstrainedFace(t, i);
      for (const double x : { -0.5, 0.0, 0.5 })
        for (const double y : { -0.5, 0.0, 0.5 })
          for (const double z : heights)
          {
            if (z < 0 && !bothSides)
              continue;
            grid.push_back({ -3, i, { x, y, z } });
            ys.push_back(at(frames[i], grid.back().x));
          }
    }
    // The grid's scores depend on the positions alone: scored at once, then taken in grid order.
    std::vector<double> qs;
    scorers_.scoreAll(own, ys, qs);
    for (size_t k = 0; k < grid.size(); ++k)
    {
      if (qs[k] > own.best)
      {
        own.best = qs[k];
        own.bestAt = ys[k];
      }
      if (qs[k] > -3)
        starts.push_back({ qs[k], grid[k].face, grid[k].x });
    }
    std::sort(starts.begin(), starts.end(), [](const Start& a, const Start& b) { return a.q > b.q; });
    if (starts.size() > 2)
      starts.resize(2);
    // A pattern search from each of the best two (their paths do not depend on each other).
    scorers_.searchEach(own, static_cast<int>(starts.size()),
                        [&](PositionScorer& scorer, int i)
                        {
                          const Frame& f = frames[starts[static_cast<size_t>(i)].face];
                          std::array<double, 3> x = starts[static_cast<size_t>(i)].x;
                          double q = starts[static_cast<size_t>(i)].q;
                          compassSearch(
                            x, q, 0.25, [&](const std::array<double, 3>& y) { return scorer.score(at(f, y)); },
                            [](double step, int, int evals) { return step > 1e-6 && evals < 200; });
                        });
    best_ = own.best;
    bestAt_ = own.bestAt;
    return best_ > 0;
  }

  // Inserts the new point at bestAt_, then improves the new tets; undone (the editor's journal) unless
  // the region improved (see the header). True when kept.
  bool tryPosition(int32_t t, double qt)
  {
    const EditJournal::Mark saved = ed_.journal->mark(m_, ed_.labels);
    if (!insertAndImprove(t, qt))
      return false;
    const bool improved = minOverCreated(tetQuality, 2) > qt && minOverCreated(minDihedral, 180) >= floor_;
    if (improved && !rule_.binds(qt))
      return true;
    ed_.journal->changedSince(saved, restored_, moved_);
    const RegionCounts after = improved ? countRegionOf(created_) : RegionCounts{};
    ed_.journal->rollback(saved, m_, ed_.labels);
    ed_.refreshVertexMap(restored_);
    if (!improved)
      return false;
    // The rule: the same tets as before the attempt (the slots it wrote and still alive, the stars of the
    // points it moved) against what it left. Kept: done again, which gives the same mesh (each step is a
    // function of the mesh, which the rollback restored slot for slot).
    const RegionCounts before = countRegionOf(restored_);
    if (after.worseThan(before))
      return false;
    if (insertAndImprove(t, qt) && minOverCreated(tetQuality, 2) > qt && minOverCreated(minDihedral, 180) >= floor_)
      return true;
    ed_.journal->changedSince(saved, restored_, moved_); // not reached while each step is deterministic
    ed_.journal->rollback(saved, m_, ed_.labels);
    ed_.refreshVertexMap(restored_);
    return false;
  }

  // The attempt's edits: nv_ at bestAt_ with the quality-driven cavity holding t, then the improvement of
  // its neighbourhood. False (nothing changed) when the insertion fails.
  bool insertAndImprove(int32_t t, double qt)
  {
    std::copy(bestAt_.begin(), bestAt_.end(), m_.points.data() + 3 * static_cast<size_t>(nv_));
    const int32_t start = ed_.locate(m_.point(nv_), t);
    created_.clear();
    if (start < 0 || !(ed_.qualityInsertion(nv_, start, t, nullptr, true, &created_) > -3))
      return false;
    improveAround(qt);
    return true;
  }

  // OrthogonalityFirst.h's counts over the live tets of `slots` and the stars of the points moved_ lists.
  RegionCounts countRegionOf(const std::vector<int32_t>& slots)
  {
    region_.clear();
    for (int32_t c : slots)
      if (c < m_.tetCapacity() && !m_.isFree(c))
        region_.push_back(c);
    for (int32_t p : moved_)
      if (p < m_.numVertices() && ed_.tetOf(p) >= 0)
      {
        ed_.star(p, star_);
        region_.insert(region_.end(), star_.begin(), star_.end());
      }
    std::sort(region_.begin(), region_.end());
    region_.erase(std::unique(region_.begin(), region_.end()), region_.end());
    return countRegion(m_, region_, rule_);
  }

  // The live tets created by this attempt (a freed slot is only reused by a later creation, also listed).
  void aliveCreated(std::vector<int32_t>& out) const
  {
    out.clear();
    for (int32_t c : created_)
      if (!m_.isFree(c))
        out.push_back(c);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // The smallest `measure` (tetQuality, minDihedral) over the live tets this attempt created.
  double minOverCreated(double (*measure)(const TetMesh&, int32_t), double none) const
  {
    std::vector<int32_t> alive;
    aliveCreated(alive);
    double q = none;
    for (int32_t c : alive)
      q = std::min(q, measure(m_, c));
    return q;
  }

  // Moves w to raise the worst tet of its star, by a pattern search whose directions are the axes and the
  // face normals of the star's worst tet (the room is often a wedge of a degree, which axis steps alone
  // cannot follow), down to steps of 1e-7 of the distance to its nearest neighbour (300 positions at
  // most). A position counts only when every tet of the star stays strictly positive (exact orient3d).
  // True when w moved.
  bool patternSearchVertex(int32_t w)
  {
    ed_.star(w, star_);
    double* x = m_.points.data() + 3 * static_cast<size_t>(w);
    auto starMin = [&](int32_t* worstTet)
    {
      double q = 2;
      for (int32_t u : star_)
      {
        const int32_t* v = m_.vertices(u);
        if (predicates::orient3d(m_.point(v[0]), m_.point(v[1]), m_.point(v[2]), m_.point(v[3])) <= 0)
          return -3.0;
        const double qu = tetQuality(m_, u);
        if (qu < q)
        {
          q = qu;
          if (worstTet)
            *worstTet = u;
        }
      }
      return q;
    };
    int32_t worstTet = -1;
    double q = starMin(&worstTet);
    if (!(q > -3) || worstTet < 0)
      return false;
    double reach = 1e300;
    for (int32_t u : star_)
      for (int i = 0; i < 4; ++i)
      {
        const double* p = m_.point(m_.vertex(u, i));
        if (m_.vertex(u, i) != w)
          reach = std::min(
            reach,
            std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) + (p[2] - x[2]) * (p[2] - x[2])));
      }
    bool movedAny = false;
    std::array<double, 3> dirs[14];
    auto setDirections = [&]()
    {
      for (int k = 0; k < 3; ++k)
      {
        dirs[2 * k] = { 0, 0, 0 };
        dirs[2 * k][k] = 1;
        dirs[2 * k + 1] = { 0, 0, 0 };
        dirs[2 * k + 1][k] = -1;
      }
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        m_.faceVertices(worstTet, i, f);
        Frame fr;
        if (!faceFrame(m_.point(f[0]), m_.point(f[1]), m_.point(f[2]), m_.point(m_.vertex(worstTet, i)), fr))
          fr.n[0] = fr.n[1] = fr.n[2] = 0;
        dirs[6 + 2 * i] = { fr.n[0], fr.n[1], fr.n[2] };
        dirs[7 + 2 * i] = { -fr.n[0], -fr.n[1], -fr.n[2] };
      }
    };
    setDirections();
    int evals = 0;
    for (double step = 0.25 * reach; step > 1e-7 * reach && evals < 300;)
    {
      bool moved = false;
      const std::array<double, 3> from = { x[0], x[1], x[2] };
      for (const auto& d : dirs)
      {
        for (int k = 0; k < 3; ++k)
          x[k] = from[k] + step * d[k];
        ++evals;
        int32_t wt = worstTet;
        const double qy = starMin(&wt);
        if (qy > q)
        {
          q = qy;
          worstTet = wt;
          moved = movedAny = true;
          break;
        }
      }
      if (!moved)
      {
        std::copy(from.begin(), from.end(), x);
        step *= 0.5;
      }
      else
        setDirections();
    }
    return movedAny;
  }

  // Flips of the new tets within a few degrees of q_t (each a strict local improvement) and smoothing of
  // the new point, while something changes (a few rounds).
  void improveAround(double qt)
  {
    const double aim = degreesToQuality(sineQualityToDegrees(qt) + 5);
    SmoothingOptions smooth;
    smooth.passes = 1;
    smooth.optimize = true;
    smooth.optimizeIterations = 30;
    std::vector<int32_t> alive, made;
    std::vector<std::pair<double, int32_t>> order;
    std::set<int32_t> smoothed; // this round's
    for (int round = 0; round < 4; ++round)
    {
      bool changed = false;
      aliveCreated(alive);
      order.clear();
      for (int32_t c : alive)
      {
        const double q = tetQuality(m_, c);
        if (q < aim)
          order.emplace_back(q, c);
      }
      std::sort(order.begin(), order.end());
      for (const auto& oc : order)
      {
        const int32_t c = oc.second;
        if (m_.isFree(c))
          continue;
        const int32_t* v = m_.vertices(c);
        const int32_t cv[4] = { v[0], v[1], v[2], v[3] };
        bool done = false;
        for (int i = 0; i < 4 && !done; ++i)
          for (int j = i + 1; j < 4 && !done; ++j)
            done = tryEdgeRemoval(ed_, c, cv[i], cv[j], 9, &made, &rule_);
        for (int f = 0; f < 4 && !done; ++f)
          done = tryFlip23(ed_, c, f, &made, &rule_);
        if (done)
        {
          created_.insert(created_.end(), made.begin(), made.end());
          changed = true;
        }
      }
      if (ed_.tetOf(nv_) >= 0 && smoothVertex(ed_, nv_, smooth) != SmoothMove::None)
        changed = true;
      // The other unlocked vertices of the new tets still near q_t, each once a round (smoothed again for
      // every such tet it is in, a vertex took six times the work; the worst tet the rounds reach then moves
      // by chance, up or down by a degree or two): a moved vertex changes its whole star, which then counts
      // as created (judged with the new tets, restored with them).
      aliveCreated(alive);
      smoothed.clear();
      for (int32_t c : alive)
      {
        if (m_.isFree(c) || !(tetQuality(m_, c) < aim))
          continue;
        const int32_t* v = m_.vertices(c);
        const int32_t cv[4] = { v[0], v[1], v[2], v[3] };
        for (int32_t u : cv)
        {
          if (u == nv_ || isLocked(u) || !smoothed.insert(u).second)
            continue;
          ed_.journal->savePoint(m_, u); // undone with the attempt
          if (smoothVertex(ed_, u, smooth) != SmoothMove::None)
          {
            ed_.star(u, made);
            created_.insert(created_.end(), made.begin(), made.end());
            changed = true;
          }
        }
      }
      if (!changed)
        break;
    }
    // Last, the fine position of w within what the flips left it.
    if (ed_.tetOf(nv_) >= 0)
      patternSearchVertex(nv_);
  }

  bool isLocked(int32_t u) const { return static_cast<size_t>(u) < locked_.size() && locked_[u] != 0; }

  TetEditor& ed_;
  Scorers& scorers_;
  std::vector<int32_t> restored_, moved_; // tryPosition()'s undo: the slots it restores
  TetMesh& m_;
  const std::vector<uint8_t>& locked_; // vertices that never move (points added later are free)
  const double floor_;
  const OrthogonalityFirst& rule_;
  std::vector<int32_t> region_; // countRegion()'s
  int32_t nv_ = -1;
  double best_ = -3;
  std::array<double, 3> bestAt_{};
  std::vector<int32_t> created_, star_;
};
const std::vector<double> Attempt::kHeights = { 0.03, 0.1, 0.3, 0.8, -0.03, -0.1, -0.3, -0.8 };
const std::vector<double> Attempt::kThinHeights = { 0.001, 0.003, 0.01, -0.001, -0.003, -0.01 };
} // namespace

int64_t improveWorstByInsertion(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                                std::vector<int32_t>* labels, const InsertionImprovementOptions& options,
                                InsertionImprovementReport* report, Progress* progress)
{
  InsertionImprovementReport local;
  InsertionImprovementReport& rep = report ? *report : local;
  TetEditor editor(mesh, constraints, labels);
  EditJournal journal; // undo of an attempt and of a round (no copy of the mesh)
  Scorers scorers(mesh, constraints, options.threads);
  editor.journal = &journal;
  std::vector<uint8_t> lock = editor.lockedVertices();
  if (locked)
    for (size_t v = 0; v < std::min(lock.size(), locked->size()); ++v)
      lock[v] |= (*locked)[v];
  int64_t kept = 0;
  // The editor's map, the locks and the first list of low tets are each a sweep of the mesh (a tenth of a
  // second at 5M tets): asked between them.
  auto stop = [&]
  {
    if (!progress || !progress->cancelled())
      return false;
    rep.cancelled = true;
    rep.kept = kept;
    return true;
  };
  if (stop())
    return 0;
  double floor = -1; // the mesh's smallest dihedral angle, once a round runs
  std::vector<std::pair<double, int32_t>> worst;
  std::vector<std::array<int32_t, 4>> quads;
  double previousWorst = -3;
  int stale = 0;                               // rounds in a row after which the mesh's worst tet was no better
  std::pair<double, double> lastRange{ 0, 0 }; // the dihedral range after the previous round
  // The tets a round looks at lie within aboveWorst of the worst, which is rarely above the plateau.
  const double lowLimit = degreesToQuality(options.plateauDegrees + 2 * options.aboveWorst);
  std::unique_ptr<LowTets> low; // the tets under lowLimit in the mesh as it is now
  std::vector<int32_t> changed, moved, star;
  for (int round = 0; round < options.rounds; ++round)
  {
    // The worst tets: those within aboveWorst degrees of the worst one, at most tetsPerRound (a tet tried in
    // vain is tried again: the points kept since may have made room). Rounds go on while points are kept and the mesh's
    // worst tet improves at least every second round (two equal worst tets need a round each when the first point
    // pushes into the second's).
    if (!low)
    {
      low = std::make_unique<LowTets>(mesh, lowLimit, options.threads, progress);
      if (stop())
        return kept;
    }
    const double q0 = low->worstQuality();
    stale = q0 > previousWorst ? 0 : stale + 1;
    if (!(q0 > 0) || sineQualityToDegrees(q0) >= 60 || stale >= 2)
      break;
    previousWorst = q0;
    const int64_t keptBefore = kept;
    const double qLimit = degreesToQuality(sineQualityToDegrees(q0) + options.aboveWorst);
    low->below(qLimit, worst);
    // A plateau of many tets near a worst tet already at the optimisation's target gains little per point.
    if (sineQualityToDegrees(q0) >= options.plateauDegrees &&
        static_cast<int64_t>(worst.size()) > std::max<int64_t>(options.plateauTets, mesh.numTets() / 200))
      break;
    if (floor < 0)
      floor = low->smallestAngle();
    // A round must raise the smallest angle or leave the largest alone: where the worst tet is forced by
    // the surface (a wedge's 1 degree edge), new points replace it with tets that the sine quality ranks
    // better but whose largest angle reaches 178 degrees, for nothing.
    // (The mesh has not changed since the last round's rangeAfter, when there was one.)
    const std::pair<double, double> rangeBefore = round > 0 ? lastRange : low->range();
    journal.clear();
    const EditJournal::Mark before = journal.mark(mesh, labels);
    std::sort(worst.begin(), worst.end());
    quads.clear();
    size_t n = 0;
    for (const auto& w : worst)
    {
      const int32_t* v = mesh.vertices(w.second);
      std::array<int32_t, 4> key = { v[0], v[1], v[2], v[3] };
      std::sort(key.begin(), key.end());
      if (n == static_cast<size_t>(options.tetsPerRound))
        break;
      worst[n++] = w;
      quads.push_back(key);
    }
    worst.resize(n);
    for (size_t k = 0; k < worst.size(); ++k)
    {
      const int32_t t = worst[k].second;
      if (mesh.isFree(t))
        continue;
      std::array<int32_t, 4> key = { mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3) };
      std::sort(key.begin(), key.end());
      if (key != quads[k])
        continue; // replaced by an earlier attempt
      if (stop())
        return kept;
      Attempt attempt(editor, scorers, lock, floor, options.orthogonalityFirst);
      ++rep.attempts;
      if (attempt.run(t))
        ++kept;
    }
    if (progress)
      progress->report((round + 1.0) / options.rounds, "Optimising");
    if (kept == keptBefore)
      break;
    // The next round's list: this one with the tets the kept attempts changed (no sweep of the mesh).
    journal.changedSince(before, changed, moved);
    for (int32_t t = before.capacity; t < mesh.tetCapacity(); ++t)
      changed.push_back(t);
    for (int32_t v : moved)
    {
      editor.star(v, star);
      changed.insert(changed.end(), star.begin(), star.end());
    }
    low->update(changed);
    const std::pair<double, double> rangeAfter = low->range();
    lastRange = rangeAfter;
    if (!(rangeAfter.first > rangeBefore.first) && rangeAfter.second > rangeBefore.second)
    {
      journal.rollback(before, mesh, labels);
      editor.refreshVertexMap(changed); // the slots the round changed: restored now
      kept = keptBefore;
      break;
    }
  }
  rep.kept = kept;
  return kept;
}

} // namespace volgrid
