#include "BadTetSplitting.h"

#include "CompassSearch.h"
#include "ParallelFor.h"
#include "ScoringHelpers.h"
#include "SplitCandidates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

namespace volgrid
{

namespace
{

using Point = SplitPoint;
using namespace splitting;

// The tets below quality qT, worst first (or `below` as given), less the first `skip` of them.
std::vector<std::pair<double, int32_t>> collectBadTets(const TetMesh& mesh, double qT,
                                                       const std::vector<std::pair<double, int32_t>>* below,
                                                       size_t skip)
{
  std::vector<std::pair<double, int32_t>> bad;
  if (below)
    bad = *below;
  else
  {
    mesh.forEachTet(
      [&](int32_t t)
      {
        const int32_t* v = mesh.vertices(t);
        const double q = tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
        if (q < qT)
          bad.emplace_back(q, t);
      });
    std::sort(bad.begin(), bad.end());
  }
  bad.erase(bad.begin(), bad.begin() + static_cast<std::ptrdiff_t>(std::min(skip, bad.size())));
  return bad;
}

// Appends the points off each edge midpoint of tet p along the normals of the edge's two faces, both
// ways, at half and at the full edge length: the point that opens a crease or an interior edge of a cap
// spanned by four boundary vertices is often there.
void addEdgeOffsets(const double* const p[4], std::vector<Point>& cand)
{
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
    {
      const double len = std::sqrt(sqDist(p[i], p[j]));
      for (int k = 0; k < 4; ++k)
      {
        if (k == i || k == j)
          continue;
        double n[3];
        const double nn = triangleNormal(p[i], p[j], p[k], n);
        if (!(nn > 0))
          continue;
        for (const double scale : { 0.5, -0.5, 1.0, -1.0 })
          cand.push_back({ (p[i][0] + p[j][0]) / 2 + scale * len * n[0] / nn,
                           (p[i][1] + p[j][1]) / 2 + scale * len * n[1] / nn,
                           (p[i][2] + p[j][2]) / 2 + scale * len * n[2] / nn });
      }
    }
}

// The search for the best position of the new vertex nv (coordinates at x) that removes bad tet t.
// A position scores the worst new tet when its cavity replaces t and beats what it replaces, else -3.
struct PositionSearch
{
  TetEditor& editor;
  double* x;
  int32_t nv;
  int32_t t;
  bool speculative;
  // Positive: |cos| limit of a severely non-orthogonal face. Positions adding such faces score -3, or with
  // preferOrthogonal (a nearly flat tet, which is split anyway) less the more they add: 3 (1 - 1 / (1 + n))
  // for n faces, so that any position adding none beats one adding some.
  double severeCosine = 0;
  bool preferOrthogonal = false;
  double best = -3; // best score so far: positions that cannot beat it are pruned
  Point at{};

  double score(const double* y)
  {
    if (!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(y[2]))
      return -3.0;
    std::copy(y, y + 3, x);
    const int32_t start = editor.locate(y, t);
    if (start < 0)
      return -3.0;
    double replaced = 2;
    const double q = editor.qualityInsertion(nv, start, t, &replaced, false, nullptr, 24, best);
    if (!(q > replaced || (speculative && q > 0)))
      return -3.0;
    if (!(severeCosine > 0))
      return q;
    const int added = editor.severeChangeOfLastCavity(nv, severeCosine);
    if (added <= 0)
      return q;
    return preferOrthogonal ? q - 3.0 * (1.0 - 1.0 / (1.0 + added)) : -3.0;
  }

  // The quality the insertion at `at` gives when it counts (as score() without the penalty), else -3.
  double rawQuality()
  {
    std::copy(at.begin(), at.end(), x);
    const int32_t start = editor.locate(x, t);
    double replaced = 2;
    const double q = start < 0 ? -3 : editor.qualityInsertion(nv, start, t, &replaced, false);
    return q > replaced || (speculative && q > 0) ? q : -3.0;
  }

  // Best of the candidates [begin, end), in order (the first of equal scores wins).
  void scan(const std::vector<Point>& cand, size_t begin = 0, size_t end = SIZE_MAX)
  {
    for (size_t k = begin; k < std::min(end, cand.size()); ++k)
    {
      const double q = score(cand[k].data());
      if (q > best)
      {
        best = q;
        at = cand[k];
      }
    }
  }

  // Compass search from the best candidate, for at most 12 rounds, down to a step of 1% of lmean.
  void refine(double lmean)
  {
    compassSearch(
      at, best, 0.2 * lmean, [&](const Point& y) { return score(y.data()); },
      [&](double step, int rounds, int) { return rounds < 12 && step > 0.01 * lmean; });
  }
};

// Whether inserting nv (at its coordinates) in the quality-driven cavity from `start` holding t leaves more
// tets under q than the cavity held.
bool addsTetsUnder(TetEditor& editor, int32_t nv, int32_t start, int32_t t, double q)
{
  if (!(editor.qualityInsertion(nv, start, t, nullptr, false) > -3))
    return false; // the insertion below fails the same way
  int after = 0, before = 0;
  editor.countBelowInLastCavity(nv, q, after, before);
  return after > before;
}

// Candidate scoring on several threads. Each worker has an editor (stamps, cavity) and a vertex slot of
// its own and only reads the mesh. The candidates are cut into contiguous ranges, one per worker; each
// range keeps its first best, and the first best of the ranges in order is what PositionSearch::scan
// finds alone: a range prunes by its own best only, and a position that cannot beat that cannot be the
// first best overall. So the mesh does not depend on the thread count.
class ParallelScan
{
public:
  ParallelScan(TetMesh& mesh, const FaceConstraints* constraints, int threads)
    : mesh_(mesh)
    , helpers_(mesh, constraints, threads)
  {
  }

  // Scores `cand` for bad tet t into `search` (whose vertex nv is the last point of the mesh).
  void run(PositionSearch& search, const std::vector<Point>& cand)
  {
    const int ranges = parallelRanges(helpers_.count(), static_cast<int64_t>(cand.size()), kMinCandidatesPerThread);
    if (ranges <= 1)
      return search.scan(cand);
    std::vector<PositionSearch> parts;
    helpers_.withSlots(search.nv, ranges,
                       [&]
                       {
                         for (int r = 0; r < ranges; ++r)
                         {
                           const int32_t slot = search.nv + r;
                           double* x = mesh_.points.data() + 3 * static_cast<size_t>(slot);
                           if (r == 0)
                           {
                             parts.push_back(search); // keeps the best so far, which prunes its range
                             parts.back().x = x;
                           }
                           else
                             parts.push_back(PositionSearch{ helpers_.helper(r), x, slot, search.t, search.speculative,
                                                             search.severeCosine, search.preferOrthogonal });
                         }
                         parallelFor(ranges, static_cast<int64_t>(cand.size()), kMinCandidatesPerThread,
                                     [&](int r, int64_t begin, int64_t end) {
                                       parts[static_cast<size_t>(r)].scan(cand, static_cast<size_t>(begin),
                                                                          static_cast<size_t>(end));
                                     });
                       });
    search.x = mesh_.points.data() + 3 * static_cast<size_t>(search.nv);
    for (const PositionSearch& part : parts)
      if (part.best > search.best)
      {
        search.best = part.best;
        search.at = part.at;
      }
  }

private:
  static constexpr int64_t kMinCandidatesPerThread = 8;
  TetMesh& mesh_;
  ScoringHelpers helpers_;
};
} // namespace

int64_t splitBadTets(TetMesh& mesh, const FaceConstraints* constraints, std::vector<int32_t>* labels,
                     const SplitRequest& request)
{
  const bool speculative = request.speculative;
  ParallelScan parallelScan(mesh, constraints, resolveThreads(request.threads));
  std::optional<TetEditor> ownEditor; // builds its vertex map
  if (request.editor)
  {
    if (!request.editor->refreshVertexMap({}, request.progress))
      return 0; // cancelled: the caller asks again
  }
  else
    ownEditor.emplace(mesh, constraints, labels);
  TetEditor& editor = ownEditor ? *ownEditor : *request.editor;
  const std::vector<uint8_t> locked = request.constrainedLocks ? *request.constrainedLocks : editor.lockedVertices();
  const double qT = std::sin(request.degrees * 3.14159265358979323846 / 180.0);
  auto quality = [&](int32_t t)
  {
    const int32_t* v = mesh.vertices(t);
    return tetSineQuality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
  };
  // Vertices inserted by this call are interior: past the end of `locked`, which predates them.
  auto isLocked = [&](int32_t x) { return static_cast<size_t>(x) < locked.size() && locked[x] != 0; };
  int64_t inserted = 0;
  std::vector<Point> cand;
  std::vector<int32_t> created;
  size_t tried = 0;
  for (const auto& b : collectBadTets(mesh, qT, request.below, request.skip))
  {
    const int32_t t = b.second;
    if (inserted >= request.maxPoints)
      break;
    if ((++tried & 63) == 0 && request.progress && request.progress->cancelled())
      break;
    if (mesh.isFree(t) || quality(t) >= qT) // replaced by an earlier insertion
      continue;
    const double qt = quality(t);
    const int32_t* v = mesh.vertices(t);
    const int32_t tv[4] = { v[0], v[1], v[2], v[3] };
    const double* p[4] = { mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3]) };
    cand.clear();
    const double lmean = addCentres(p, cand);
    addFaceApexes(p, cand);
    if (isLocked(tv[0]) && isLocked(tv[1]) && isLocked(tv[2]) && isLocked(tv[3]))
      addEdgeOffsets(p, cand);
    const int32_t nv = mesh.addPoint(cand[0].data()); // coordinates overwritten below (p may move)
    double* x = mesh.points.data() + 3 * static_cast<size_t>(nv);
    const OrthogonalityFirst& rule = request.orthogonalityFirst;
    const bool orthogonal = rule.binds(qt);
    PositionSearch search{
      editor, x, nv, t, speculative, rule.enabled ? rule.severeCosine : 0, rule.enabled && !orthogonal
    };
    parallelScan.run(search, cand);
    if (search.best > -3)
      search.refine(lmean);
    if (search.preferOrthogonal && search.best > -3)
      search.best = search.rawQuality(); // the score less its penalty, for the test below
    if (search.best > 0 && (search.best > qt || speculative))
    {
      std::copy(search.at.begin(), search.at.end(), search.x);
      const int32_t start = editor.locate(search.x, t);
      if (start >= 0 && !(orthogonal && !speculative && addsTetsUnder(editor, nv, start, t, qT)) &&
          editor.qualityInsertion(nv, start, t, nullptr, true, &created) > -3) // inserted
      {
        ++inserted;
        if (request.created)
          request.created->insert(request.created->end(), created.begin(), created.end());
        continue;
      }
    }
    mesh.points.resize(mesh.points.size() - 3); // the last vertex, used by no tet
  }
  return inserted;
}

} // namespace volgrid
