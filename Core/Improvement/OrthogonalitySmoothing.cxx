#include "OrthogonalitySmoothing.h"

#include "CompassSearch.h"
#include "ParallelFor.h"
#include "PredicatesInline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace volgrid
{

namespace
{
using Vec = std::array<double, 3>;

constexpr double kDegree = 3.14159265358979323846 / 180.0;
const double kSine10 = std::sin(10 * kDegree);

Vec centroid(const TetMesh& m, int32_t t)
{
  const int32_t* v = m.vertices(t);
  Vec c{ 0, 0, 0 };
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k)
      c[k] += m.point(v[i])[k] / 4;
  return c;
}

// cos of the angle between the normal of face i of t and the line from c1 to c2 (1: orthogonal).
double orthogonalityCosine(const TetMesh& m, int32_t t, int i, const Vec& c1, const Vec& c2)
{
  int32_t f[3];
  m.faceVertices(t, i, f);
  return quality::triangleLineCosine(m.point(f[0]), m.point(f[1]), m.point(f[2]), c1.data(), c2.data());
}

double faceCosine(const TetMesh& m, int32_t t, int i)
{
  const int32_t u = m.neighbor(t, i);
  return u < 0 ? 1 : orthogonalityCosine(m, t, i, centroid(m, t), centroid(m, u));
}

double tetQuality(const TetMesh& m, int32_t t)
{
  const int32_t* v = m.vertices(t);
  return tetSineQuality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

// The search for one vertex: its star (the tets holding it) and the faces whose orthogonality a move of it
// changes (every face of the star's tets with a neighbour, once each).
class StarSearch
{
public:
  StarSearch(TetMesh& mesh, TetEditor& editor, double cosLimit, double qTarget)
    : m_(mesh)
    , editor_(editor)
    , cosLimit_(cosLimit)
    , qTarget_(qTarget)
  {
  }

  // The star's severe faces, and its least orthogonal face's cosine, at v's current position.
  struct Measure
  {
    int severe = 0;
    double worstCos = 1;
  };

  // The severe faces removed by the best position found for v (0: none; v stays where it was), and that
  // position in `best`.
  int search(int32_t v, Vec& best)
  {
    gather(v);
    double* x = m_.points.data() + 3 * static_cast<size_t>(v);
    const Vec x0{ x[0], x[1], x[2] };
    setFloors();
    const Measure before = measure();
    // The severe count decides; the least orthogonal face's cosine (in [0, 1]) orders equal counts.
    auto score = [&](const Vec& y)
    {
      std::copy(y.begin(), y.end(), x);
      if (!feasible())
        return -std::numeric_limits<double>::infinity();
      const Measure m = measure();
      return m.worstCos - 2.0 * m.severe;
    };
    best = x0;
    double q = before.worstCos - 2.0 * before.severe;
    const double step = 0.2 * meanEdge(v, x0);
    compassSearch(best, q, step, score, [&](double s, int rounds, int) { return rounds < 12 && s > 0.02 * step; });
    std::copy(best.begin(), best.end(), x);
    const int after = measure().severe;
    std::copy(x0.begin(), x0.end(), x);
    return before.severe - after;
  }

  const std::vector<int32_t>& starOf(int32_t v)
  {
    editor_.star(v, star_);
    return star_;
  }

private:
  // A face of the star: face i of star tet a, towards star tet b (-1: towards the tet beyond the star,
  // whose centroid does not move with v).
  struct StarFace
  {
    int a, i, b;
    Vec beyond;
  };

  void gather(int32_t v)
  {
    editor_.star(v, star_);
    faces_.clear();
    for (size_t a = 0; a < star_.size(); ++a)
      for (int i = 0; i < 4; ++i)
      {
        const int32_t u = m_.neighbor(star_[a], i);
        if (u < 0)
          continue;
        const auto at = std::find(star_.begin(), star_.end(), u);
        if (at == star_.end())
          faces_.push_back({ static_cast<int>(a), i, -1, centroid(m_, u) });
        else if (at - star_.begin() > static_cast<std::ptrdiff_t>(a))
          faces_.push_back({ static_cast<int>(a), i, static_cast<int>(at - star_.begin()), Vec{} });
      }
    centroids_.resize(star_.size());
  }

  // Per star tet: how bad it may get. No worse than before where it is under the target; and not under
  // 10 degrees, nor under the star's worst tet, where it was above them.
  void setFloors()
  {
    floor_.clear();
    double worst = 2;
    for (int32_t s : star_)
    {
      floor_.push_back(tetQuality(m_, s));
      worst = std::min(worst, floor_.back());
    }
    for (double& f : floor_)
      f = std::min({ f, qTarget_, std::max(worst, kSine10) });
  }

  Measure measure()
  {
    for (size_t a = 0; a < star_.size(); ++a)
      centroids_[a] = centroid(m_, star_[a]);
    Measure m;
    for (const StarFace& f : faces_)
    {
      const Vec& other = f.b < 0 ? f.beyond : centroids_[static_cast<size_t>(f.b)];
      const double c =
        orthogonalityCosine(m_, star_[static_cast<size_t>(f.a)], f.i, centroids_[static_cast<size_t>(f.a)], other);
      m.severe += c < cosLimit_;
      m.worstCos = std::min(m.worstCos, c);
    }
    return m;
  }

  // Every tet of the star positive and no worse than its floor.
  bool feasible() const
  {
    for (size_t k = 0; k < star_.size(); ++k)
    {
      const int32_t* w = m_.vertices(star_[k]);
      if (!(predicates::orient3dInline(m_.point(w[0]), m_.point(w[1]), m_.point(w[2]), m_.point(w[3])) > 0) ||
          !(tetQuality(m_, star_[k]) >= floor_[k]))
        return false;
    }
    return true;
  }

  // Mean length of the star's edges at v.
  double meanEdge(int32_t v, const Vec& x) const
  {
    double sum = 0;
    int n = 0;
    for (int32_t s : star_)
      for (int i = 0; i < 4; ++i)
      {
        const int32_t w = m_.vertex(s, i);
        if (w == v)
          continue;
        const double* p = m_.point(w);
        sum += std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) + (p[2] - x[2]) * (p[2] - x[2]));
        ++n;
      }
    return n ? sum / n : 0;
  }

  TetMesh& m_;
  TetEditor& editor_;
  const double cosLimit_, qTarget_;
  std::vector<int32_t> star_;
  std::vector<double> floor_; // per star tet, see setFloors()
  std::vector<StarFace> faces_;
  std::vector<Vec> centroids_;
};
} // namespace

Status smoothNonOrthogonalFaces(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                                const OrthogonalitySmoothingOptions& options, Progress* progress,
                                OrthogonalitySmoothingReport* reportOut)
{
  OrthogonalitySmoothingReport local;
  OrthogonalitySmoothingReport& report = reportOut ? *reportOut : local;
  const double cosLimit = std::cos(options.severeDegrees * kDegree);
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  TetEditor editor(mesh, constraints, nullptr); // builds its vertex map
  std::vector<uint8_t> lock = editor.lockedVertices();
  if (locked)
    for (size_t v = 0; v < std::min(lock.size(), locked->size()); ++v)
      lock[v] |= (*locked)[v];
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  auto severe = [&](int32_t t, int i) { return mesh.neighbor(t, i) >= 0 && faceCosine(mesh, t, i) < cosLimit; };
  // The tets with a severe face, in slot order (a list per range of slots, joined in order); then the stars
  // of the moved vertices. The sweep asks between blocks of slots (half a second on one thread at 5M tets).
  std::vector<int32_t> queue;
  int64_t count = 0;
  constexpr int64_t kMinSlotsPerThread = 1 << 16, kSlotsPerQuestion = int64_t{ 1 } << 20;
  const int64_t n = mesh.tetCapacity();
  for (int64_t first = 0; first < n; first += kSlotsPerQuestion)
  {
    if (first > 0 && progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    const int64_t slots = std::min(kSlotsPerQuestion, n - first);
    const size_t ranges = static_cast<size_t>(parallelRanges(options.threads, slots, kMinSlotsPerThread));
    std::vector<std::vector<int32_t>> parts(ranges);
    std::vector<int64_t> counts(ranges, 0);
    parallelFor(options.threads, slots, kMinSlotsPerThread,
                [&](int r, int64_t begin, int64_t end)
                {
                  for (int32_t t = static_cast<int32_t>(first + begin); t < first + end; ++t)
                  {
                    if (mesh.isFree(t))
                      continue;
                    bool any = false;
                    for (int i = 0; i < 4; ++i)
                      if (severe(t, i))
                      {
                        any = true;
                        counts[static_cast<size_t>(r)] += t < mesh.neighbor(t, i);
                      }
                    if (any)
                      parts[static_cast<size_t>(r)].push_back(t);
                  }
                });
    for (size_t r = 0; r < ranges; ++r)
    {
      queue.insert(queue.end(), parts[r].begin(), parts[r].end());
      count += counts[r];
    }
  }
  report.severeBefore = count;
  report.severeAfter = count;
  // The editor's map, the locks and the sweep above are each about a tenth of a second at 5M tets.
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  StarSearch search(mesh, editor, cosLimit, std::sin(options.targetDegrees * kDegree));
  Vec at, bestAt;
  // Vertices whose last search found nothing, until a move nearby.
  std::vector<uint8_t> failed(static_cast<size_t>(mesh.numVertices()), 0);
  for (size_t k = 0; k < queue.size(); ++k)
  {
    if ((k & 255) == 255 && progress && progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
    const int32_t t = queue[k];
    for (int i = 0; i < 4; ++i)
    {
      if (!severe(t, i))
        continue;
      // The vertices of the face's two tets that may move: the one whose best move removes most.
      const int32_t u = mesh.neighbor(t, i);
      int bestGain = 0;
      int32_t bestV = -1;
      const int32_t* tv = mesh.vertices(t);
      const int32_t candidates[5] = { tv[0], tv[1], tv[2], tv[3], mesh.vertex(u, mesh.mirrorFace(t, i)) };
      for (const int32_t v : candidates)
      {
        if (lock[v] || failed[v])
          continue;
        const int gain = search.search(v, at);
        failed[v] = gain <= 0;
        if (gain > bestGain)
        {
          bestGain = gain;
          bestV = v;
          bestAt = at;
        }
      }
      if (bestV < 0)
        continue;
      std::copy(bestAt.begin(), bestAt.end(), mesh.points.data() + 3 * static_cast<size_t>(bestV));
      count -= bestGain;
      ++report.moves;
      const std::vector<int32_t>& star = search.starOf(bestV);
      queue.insert(queue.end(), star.begin(), star.end());
      // A search depends on the positions in its star and on the centroids beyond: the vertices of the
      // moved vertex's star and of the tets beyond it may do better now.
      for (int32_t s : star)
        for (int j = 0; j < 4; ++j)
        {
          const int32_t* sv = mesh.vertices(s);
          failed[sv[j]] = 0;
          const int32_t beyond = mesh.neighbor(s, j);
          if (beyond >= 0)
            for (int l = 0; l < 4; ++l)
              failed[mesh.vertex(beyond, l)] = 0;
        }
    }
  }
  report.severeAfter = count;
  return Status::success();
}

} // namespace volgrid
