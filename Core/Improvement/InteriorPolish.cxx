#include "InteriorPolish.h"

#include "CompassSearch.h"
#include "EditJournal.h"
#include "MeshOptimization.h"
#include "MeshScan.h"
#include "MeshSmoothing.h"
#include "OrthogonalityFirst.h"
#include "Quality.h"
#include "SplitCandidates.h"
#include "TetNeeds.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace volgrid
{

namespace
{
constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The step's edits on one mesh: the vertex moves, flips and collapses for one bad interior tet at a time,
// each kept only when it adds no severely non-orthogonal face and no tet under 10 degrees (see the header).
class Polish
{
public:
  Polish(TetEditor& editor, const std::vector<uint8_t>& boundaryVertex, const std::vector<uint8_t>* locked,
         const InteriorPolishOptions& options)
    : ed_(editor)
    , m_(editor.mesh)
    , boundary_(boundaryVertex)
    , locked_(locked)
    , qInterior_(std::sin(options.interiorDegrees * kDegree))
    , qBoundary_(std::sin(options.boundaryDegrees * kDegree))
    , severe_(OrthogonalityFirst::forTarget(options.interiorDegrees))
    , changedAt_(static_cast<size_t>(editor.mesh.numVertices()), -1)
  {
    needs_.mesh = &m_;
    needs_.boundaryVertex = &boundary_;
    needs_.interiorQ = qInterior_;
    needs_.boundaryQ = qBoundary_;
    needs_.counts = &counts_;
    ed_.journal = &journal_;
  }
  ~Polish() { ed_.journal = nullptr; }
  Polish(const Polish&) = delete;
  Polish& operator=(const Polish&) = delete;

  double interiorQuality() const { return qInterior_; }
  int64_t severeChange() const { return severeChange_; }

  // The mesh at the start, from `below`, its tets under the interior quality: no edit takes a tet under its
  // smallest dihedral angle or over its largest, or raises its share of tets under 10 deg. Each of those
  // tets has its angles outside [interiorDegrees, 180 - interiorDegrees], so the smallest angle (when under
  // interiorDegrees), the largest (when over 180 - interiorDegrees) and every tet under 10 deg are among
  // them; a side none of them reaches is not known here, and its floor is then every tet's own quality
  // (nothing falls).
  void start(const std::vector<std::pair<double, int32_t>>& below)
  {
    double lowest = 90, highest = 90;
    int64_t under10 = 0;
    for (const auto& entry : below)
    {
      const int32_t* w = m_.vertices(entry.second);
      double lo, hi;
      quality::tetDihedralExtremes(m_.point(w[0]), m_.point(w[1]), m_.point(w[2]), m_.point(w[3]), lo, hi);
      lowest = std::min(lowest, lo);
      highest = std::max(highest, hi);
      under10 += lo < 10;
    }
    const double interior = std::asin(qInterior_) / kDegree;
    const double minSide = lowest < interior ? lowest : 90, maxSide = highest > 180 - interior ? 180 - highest : 90;
    needs_.worstQ = std::sin(std::max(minSide, maxSide) * kDegree);
    counts_.tets = counts_.startTets = m_.numTets();
    counts_.below10 = counts_.startBelow10 = under10;
  }

  bool bad(int32_t t) const { return !m_.isFree(t) && interior(t) && quality(t) < qInterior_; }

  // A tet all of whose edits failed is tried again only once one of its vertices or their neighbours moved,
  // or a tet holding one of its vertices changed: the same tries would fail the same way.
  void failed(int32_t t)
  {
    if (static_cast<size_t>(t) >= failedAt_.size())
      failedAt_.resize(static_cast<size_t>(m_.tetCapacity()), -1);
    failedAt_[static_cast<size_t>(t)] = edits_;
  }
  bool worthTrying(int32_t t) const
  {
    if (static_cast<size_t>(t) >= failedAt_.size() || failedAt_[static_cast<size_t>(t)] < 0)
      return true;
    const int64_t at = failedAt_[static_cast<size_t>(t)];
    for (int i = 0; i < 4; ++i)
      if (changedAt_[static_cast<size_t>(m_.vertex(t, i))] > at)
        return true;
    return false;
  }

  // Smooths v for the smallest score of its star (InteriorPolish.h); true when it moved.
  bool move(int32_t v, int32_t target)
  {
    if (!movable(v))
      return false;
    ed_.star(v, star_);
    if (star_.empty())
      return false;
    std::sort(star_.begin(), star_.end()); // countRegion's order
    ed_.neighbors(v, star_, nbrs_);
    weight_.resize(star_.size());
    floor_.resize(star_.size());
    for (size_t i = 0; i < star_.size(); ++i)
    {
      const double need = needs_.need(m_.vertices(star_[i]));
      weight_[i] = 1 / need;
      floor_[i] = needs_.floor(quality(star_[i]), need);
    }
    const RegionCounts before = countRegion(m_, star_, severe_);
    const int under10 = countUnder10(star_);
    const std::array<double, 3> home = { m_.point(v)[0], m_.point(v)[1], m_.point(v)[2] };
    const SmoothingOptions so;
    // When the star's smallest score cannot rise, its tet is set aside (kept at its quality) and the next
    // smallest is tried: a tet that holds v still must not keep the target from moving.
    for (int round = 0; round <= kSetAside; ++round)
    {
      if (smoothVertexWeighted(m_, v, star_, nbrs_, weight_, floor_, so) != SmoothMove::None)
      {
        // The floors bound the sine quality, min(theta_min, 180 - theta_max): a tet over 170 deg may still
        // trade it for an angle under 10, which the share under 10 deg counts.
        const RegionCounts after = countRegion(m_, star_, severe_);
        if (countUnder10(star_) <= under10 && after.severe <= before.severe)
        {
          severeChange_ += after.severe - before.severe;
          touch(v);
          for (int32_t u : nbrs_)
            touch(u);
          return true;
        }
        std::copy(home.begin(), home.end(), m_.points.data() + 3 * static_cast<size_t>(v));
        return false;
      }
      const size_t worst = smallestScore();
      if (star_[worst] == target)
        return false;
      weight_[worst] = kAside;
      floor_[worst] = quality(star_[worst]);
    }
    return false;
  }

  // Edge removal on t's edges, then 2-3 flips of its faces, judged by TetNeeds; the first kept is the
  // edit (its new tets appended to `created`).
  bool flip(int32_t t, std::vector<int32_t>& created)
  {
    const int32_t* w = m_.vertices(t);
    const std::array<int32_t, 4> v = { w[0], w[1], w[2], w[3] };
    neighbourhood(v, {});
    const int64_t before = countRegion(m_, region_, severe_).severe;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (keep([&](std::vector<int32_t>& made)
                 { return tryEdgeRemoval(ed_, t, v[a], v[b], kMaxRing, &made, nullptr, &needs_); },
                 before, created))
          return true;
    for (int f = 0; f < 4; ++f)
      if (keep([&](std::vector<int32_t>& made) { return tryFlip23(ed_, t, f, &made, nullptr, &needs_); }, before,
               created))
        return true;
    return false;
  }

  // Inserts a point for t where the quality-driven insertion (cavity holding t) makes the best smallest
  // score of its new tets (TetNeeds): from t's centroid, circumcentre, edge midpoints and points over its
  // faces (SplitCandidates.h), then a compass search. Kept when the new tets pay for the cavity's (TetNeeds)
  // and add no severe face.
  bool split(int32_t t, std::vector<int32_t>& created)
  {
    const int32_t* w = m_.vertices(t);
    const double* p[4] = { m_.point(w[0]), m_.point(w[1]), m_.point(w[2]), m_.point(w[3]) };
    splitCandidates_.clear();
    const double lmean = splitting::addCentres(p, splitCandidates_);
    splitting::addFaceApexes(p, splitCandidates_);
    const int32_t nv = m_.addPoint(splitCandidates_[0].data()); // p may move: not used below
    boundary_.resize(static_cast<size_t>(m_.numVertices()), 0); // the new point is interior
    const NeedScore score(needs_);
    ed_.coneScore = &score;
    double best = -3;
    auto scoreAt = [&](const SplitPoint& y)
    {
      std::copy(y.begin(), y.end(), m_.points.data() + 3 * static_cast<size_t>(nv));
      const int32_t start = ed_.locate(y.data(), t);
      return start < 0 ? -3.0 : ed_.qualityInsertion(nv, start, t, nullptr, false, nullptr, kMaxCavity, best);
    };
    SplitPoint at{};
    for (const SplitPoint& y : splitCandidates_)
    {
      const double q = scoreAt(y);
      if (q > best)
      {
        best = q;
        at = y;
      }
    }
    bool kept = false;
    if (best > -3)
    {
      compassSearch(at, best, 0.2 * lmean, scoreAt,
                    [&](double step, int rounds, int) { return rounds < 12 && step > 0.01 * lmean; });
      best = -3;
      if (scoreAt(at) > -3) // the best position's cavity, as the editor's last
        kept = insertAt(nv, t, at, created);
    }
    ed_.coneScore = nullptr;
    if (!kept)
      m_.points.resize(m_.points.size() - 3);
    return kept;
  }

  // Removes a movable vertex of t, or of the nearest neighbours of t's vertices, by collapsing it onto a
  // neighbour, judged by TetNeeds. The bad tets that remain after the moves sit in clusters of points the
  // quality stage added, at spacings a tenth of their neighbours'.
  bool collapse(int32_t t, std::vector<int32_t>& created)
  {
    const int32_t* w = m_.vertices(t);
    const std::array<int32_t, 4> v = { w[0], w[1], w[2], w[3] };
    candidates_.clear();
    for (int32_t x : v)
      if (movable(x))
        candidates_.push_back(x);
    for (int32_t x : v)
    {
      nearestMovable(x);
      for (const auto& entry : near_)
        if (std::find(candidates_.begin(), candidates_.end(), entry.second) == candidates_.end())
          candidates_.push_back(entry.second);
    }
    neighbourhood(v, candidates_);
    const int64_t before = countRegion(m_, region_, severe_).severe;
    for (int32_t x : candidates_)
      if (keep([&](std::vector<int32_t>& made) { return tryVertexCollapse(ed_, x, &made, &needs_); }, before, created))
        return true;
    return false;
  }

private:
  static constexpr int kMaxRing = 9;
  static constexpr int kMaxCavity = 24; // tets a quality-driven cavity grows to, as the split rounds'

  // A cone tet's score for the editor's quality-driven insertion (TetNeeds::score).
  struct NeedScore final : TetEditor::ConeScore
  {
    explicit NeedScore(const TetNeeds& n)
      : needs(n)
    {
    }
    double operator()(const int32_t w[4], double q) const override { return needs.score(w, q); }
    const TetNeeds& needs;
  };

  // split()'s insertion of nv at `at` with the editor's last cavity, judged by TetNeeds against that
  // cavity's tets and undone unless it pays and adds no severe face.
  bool insertAt(int32_t nv, int32_t t, const SplitPoint& at, std::vector<int32_t>& created)
  {
    const TetNeeds::Region old = needs_.region(m_, ed_.lastCavity());
    region_ = ed_.lastCavity();
    std::sort(region_.begin(), region_.end());
    const int64_t before = countRegion(m_, region_, severe_).severe;
    return keep(
      [&](std::vector<int32_t>& made)
      {
        const int32_t start = ed_.locate(at.data(), t);
        if (start < 0 || !(ed_.qualityInsertion(nv, start, t, nullptr, true, &made) > -3))
          return false;
        TetNeeds::Region now;
        for (int32_t u : made)
        {
          const double q = quality(u);
          if (needs_.newScore(old, m_.vertices(u), q) < 0)
            return false;
          needs_.add(now, m_.vertices(u), q);
        }
        if (!needs_.pays(old, now))
          return false;
        needs_.record(old, now);
        return true;
      },
      before, created);
  }
  static constexpr int kSetAside = 3;
  static constexpr size_t kNearest = 4;
  static constexpr double kAside = 1e30; // the weight of a tet set aside: never the smallest score

  bool movable(int32_t v) const
  {
    return !needs_.onBoundary(v) && !(locked_ && static_cast<size_t>(v) < locked_->size() && (*locked_)[v]);
  }
  bool interior(int32_t t) const { return !needs_.touchesBoundary(m_.vertices(t)); }
  double quality(int32_t t) const { return TetNeeds::quality(m_, m_.vertices(t)); }

  size_t smallestScore() const
  {
    size_t worst = 0;
    for (size_t i = 1; i < star_.size(); ++i)
      if (quality(star_[i]) * weight_[i] < quality(star_[worst]) * weight_[worst])
        worst = i;
    return worst;
  }

  void touch(int32_t v)
  {
    if (static_cast<size_t>(v) >= changedAt_.size())
      changedAt_.resize(static_cast<size_t>(m_.numVertices()), -1);
    changedAt_[static_cast<size_t>(v)] = ++edits_;
  }

  int countUnder10(const std::vector<int32_t>& tets) const
  {
    int n = 0;
    for (int32_t u : tets)
      n += needs_.under10(m_.vertices(u), quality(u));
    return n;
  }

  // The movable neighbours of x nearest to it (at most kNearest) into near_.
  void nearestMovable(int32_t x)
  {
    ed_.star(x, star_);
    ed_.neighbors(x, star_, nbrs_);
    near_.clear();
    for (int32_t y : nbrs_)
      if (movable(y))
      {
        const double* a = m_.point(x);
        const double* b = m_.point(y);
        near_.push_back(
          { (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]), y });
      }
    const size_t n = std::min(near_.size(), kNearest);
    std::partial_sort(near_.begin(), near_.begin() + static_cast<std::ptrdiff_t>(n), near_.end());
    near_.resize(n);
  }

  // The tets the edits of t (vertices v) may remove: the stars of t's vertices and of `more`, sorted, into
  // region_.
  void neighbourhood(const std::array<int32_t, 4>& v, const std::vector<int32_t>& more)
  {
    region_.clear();
    for (int32_t x : v)
    {
      ed_.star(x, star_);
      region_.insert(region_.end(), star_.begin(), star_.end());
    }
    for (int32_t x : more)
    {
      ed_.star(x, star_);
      region_.insert(region_.end(), star_.begin(), star_.end());
    }
    std::sort(region_.begin(), region_.end());
    region_.erase(std::unique(region_.begin(), region_.end()), region_.end());
  }

  // Makes `edit` (which writes its new tets into its argument) and keeps it when the neighbourhood in
  // region_, which holds every tet it removes and had `before` severe faces, has no more after it (the same
  // space, the same faces towards the tets beyond); else undoes it (the journal). True when kept.
  template<class Edit>
  bool keep(Edit&& edit, int64_t before, std::vector<int32_t>& created)
  {
    const EditJournal::Mark mark = journal_.mark(m_, ed_.labels);
    const TetNeeds::Counts counts = counts_;
    made_.clear();
    if (!edit(made_))
    {
      journal_.changedSince(mark, restored_, moved_);
      journal_.rollback(mark, m_, ed_.labels);
      ed_.refreshVertexMap(restored_);
      counts_ = counts;
      return false;
    }
    after_.clear();
    for (int32_t u : region_)
      if (!m_.isFree(u))
        after_.push_back(u);
    after_.insert(after_.end(), made_.begin(), made_.end());
    std::sort(after_.begin(), after_.end());
    after_.erase(std::unique(after_.begin(), after_.end()), after_.end());
    const int64_t after = countRegion(m_, after_, severe_).severe;
    if (after > before)
    {
      journal_.changedSince(mark, restored_, moved_);
      journal_.rollback(mark, m_, ed_.labels);
      ed_.refreshVertexMap(restored_);
      counts_ = counts;
      return false;
    }
    journal_.clear();
    severeChange_ += after - before;
    created.insert(created.end(), made_.begin(), made_.end());
    for (int32_t u : made_)
      for (int i = 0; i < 4; ++i)
        touch(m_.vertex(u, i));
    return true;
  }

  TetEditor& ed_;
  TetMesh& m_;
  std::vector<uint8_t> boundary_; // the caller's, and 0 for the points split() adds
  const std::vector<uint8_t>* locked_;
  const double qInterior_, qBoundary_;
  const OrthogonalityFirst severe_; // its severeCosine: checkMesh's limit
  TetNeeds needs_;
  TetNeeds::Counts counts_;
  EditJournal journal_;
  int64_t severeChange_ = 0;
  int64_t edits_ = 0;              // a clock: one tick per vertex an edit changed
  std::vector<int64_t> changedAt_; // per vertex: the tick of its last change, -1 never
  std::vector<int64_t> failedAt_;  // per tet slot: the tick when its tries last failed, -1 never
  std::vector<int32_t> star_, nbrs_, candidates_, region_, after_, made_, restored_, moved_;
  std::vector<SplitPoint> splitCandidates_;
  std::vector<double> weight_, floor_;
  std::vector<std::pair<double, int32_t>> near_;
};

// The listed tets that are still bad interior tets.
void keepBad(const Polish& polish, std::vector<int32_t>& tets)
{
  tets.erase(std::remove_if(tets.begin(), tets.end(), [&](int32_t t) { return !polish.bad(t); }), tets.end());
}
} // namespace

Status polishInterior(TetEditor& editor, const std::vector<uint8_t>& boundaryVertex, const std::vector<uint8_t>* locked,
                      const InteriorPolishOptions& options, Progress* progress, InteriorPolishReport* reportOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  InteriorPolishReport local;
  InteriorPolishReport& report = reportOut ? *reportOut : local;
  auto cancelled = [&]() { return Status::failure(ErrorKind::Cancelled, "Interior polish was cancelled."); };
  Polish polish(editor, boundaryVertex, locked, options);
  // Every bad interior tet is under the interior quality: one sweep finds them all.
  std::vector<std::pair<double, int32_t>> below;
  if (!collectSineBelow(editor.mesh, polish.interiorQuality(), options.threads, below, progress))
    return cancelled();
  std::vector<int32_t> tets;
  for (const auto& entry : below)
    tets.push_back(entry.second);
  keepBad(polish, tets);
  report.before = report.after = static_cast<int64_t>(tets.size());
  if (tets.empty())
    return Status::success();
  polish.start(below);
  std::vector<int32_t> created;
  for (int pass = 0; pass < options.passes && !tets.empty(); ++pass)
  {
    if (progress && progress->cancelled())
      return cancelled();
    int64_t moves = 0;
    for (size_t k = 0; k < tets.size(); ++k)
    {
      // A tet's edits take up to a few milliseconds (a split searches a hundred cavities): asked every 16.
      if ((k & 15) == 15 && progress && progress->cancelled())
        return cancelled();
      const int32_t t = tets[k];
      if (!polish.bad(t) || !polish.worthTrying(t))
        continue;
      int64_t moved = 0;
      for (int i = 0; i < 4 && polish.bad(t); ++i)
        moved += polish.move(editor.mesh.vertex(t, i), t);
      moves += moved;
      const bool flipped = polish.bad(t) && polish.flip(t, created);
      const bool collapsed = !flipped && polish.bad(t) && polish.collapse(t, created);
      const bool split = !flipped && !collapsed && polish.bad(t) && polish.split(t, created);
      report.splits += split;
      if (!flipped && !collapsed && !split)
      {
        if (moved == 0)
          polish.failed(t);
        continue;
      }
      ++moves;
      report.flips += flipped;
      report.collapses += collapsed;
      for (int32_t u : created)
        if (polish.bad(u))
          tets.push_back(u); // looked at later in this pass
      created.clear();
    }
    report.moves += moves;
    std::sort(tets.begin(), tets.end());
    tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
    keepBad(polish, tets);
    if (moves == 0)
      break;
  }
  report.after = static_cast<int64_t>(tets.size());
  report.severeChange = polish.severeChange();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return Status::success();
}

} // namespace volgrid
