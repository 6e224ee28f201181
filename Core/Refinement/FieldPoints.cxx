#include "FieldPoints.h"

#include "FieldPointRegions.h"

#include "LargeMesh.h"
#include "ParallelFor.h"
#include "SpatialSort.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace volgrid
{

namespace
{
constexpr size_t kTestBlock = 32768; // tets tested ahead of the insertions (testTets)

inline double dist(const double* a, const double* b)
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}
inline double volume(const double* a, const double* b, const double* c, const double* d)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
    6.0;
}
double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
void sortAlongHilbertCurve(const TetMesh& mesh, std::vector<int32_t>& tets)
{
  std::vector<double> centroids;
  centroids.reserve(3 * tets.size());
  for (int32_t t : tets)
  {
    const int32_t* v = mesh.vertices(t);
    for (int k = 0; k < 3; ++k)
      centroids.push_back((mesh.point(v[0])[k] + mesh.point(v[1])[k] + mesh.point(v[2])[k] + mesh.point(v[3])[k]) / 4);
  }
  std::vector<int32_t> order(tets.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int32_t>(i);
  hilbertSort(centroids.data(), order);
  std::vector<int32_t> sorted(tets.size());
  for (size_t i = 0; i < order.size(); ++i)
    sorted[i] = tets[static_cast<size_t>(order[i])];
  tets.swap(sorted);
}

// Whether tet t is alive and was born before `pass` (in the previous pass, or listed in the first): a tet the
// pass destroyed, or whose slot it reused, is not.
bool unchangedSincePassBegan(const TetMesh& mesh, const std::vector<int32_t>& birth, int pass, int32_t t)
{
  return !mesh.isFree(t) && birth[static_cast<size_t>(t)] == pass - 1;
}

// The loads of the tets a pass asks about, started ahead: the tet (its flags, vertices and birth)
// kPrefetchTets tets ahead, its points kPrefetchPoints ahead (the tets are scattered through memory).
constexpr size_t kPrefetchTets = 16, kPrefetchPoints = 8;
void prefetchTet(const TetMesh& mesh, const std::vector<int32_t>& birth, int32_t t)
{
  mesh.prefetchTet(t);
  __builtin_prefetch(&birth[static_cast<size_t>(t)]);
}

// The size at tet t's centroid when t asks for a point there (eq. 4, or t is larger than the volume cap),
// else 0.
double sizeWhereAPointIsWanted(const TetMesh& mesh, const SizingField& sizing, const FieldPointOptions& options,
                               double hVol, int32_t t)
{
  const int32_t* v = mesh.vertices(t);
  const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]), *d = mesh.point(v[3]);
  const double cen[3] = { (a[0] + b[0] + c[0] + d[0]) / 4, (a[1] + b[1] + c[1] + d[1]) / 4,
                          (a[2] + b[2] + c[2] + d[2]) / 4 };
  double h = sizing.evaluate(cen);
  if (hVol > 0)
    h = std::min(h, hVol);
  if (!(h > 0) || !std::isfinite(h))
    return 0;
  const double dm = std::min(std::min(dist(cen, a), dist(cen, b)), std::min(dist(cen, c), dist(cen, d)));
  const bool big = options.maxVolume > 0 && volume(a, b, c, d) > options.maxVolume;
  return dm > options.alpha * h || big ? h : 0;
}

// sizeWhereAPointIsWanted for the tets todo[order[begin, end)] of pass `pass` (order null: todo[begin, end)),
// ahead of the insertions among them. A tet the pass reaches alive and not born in the pass is unchanged since
// the pass began, so the answers are those the pass would get; they depend on nothing else, so the tets are
// split across threads when the field allows. (A block at a time: the insertions that follow find its tets
// still in the caches.) Tets that earlier insertions of the pass already destroyed are skipped: the pass
// skips them too.
void testTets(const TetMesh& mesh, const SizingField& sizing, const FieldPointOptions& options, double hVol,
              const std::vector<int32_t>& birth, int pass, const std::vector<int32_t>& todo, const size_t* order,
              size_t begin, size_t end, std::vector<double>& wanted)
{
  wanted.resize(todo.size());
  const int threads = sizing.evaluatesConcurrently() ? options.threads : 1;
  parallelFor(threads, static_cast<int64_t>(end - begin), 8192,
              [&](int, int64_t from, int64_t to)
              {
                const size_t first = begin + static_cast<size_t>(from), last = begin + static_cast<size_t>(to);
                const auto tetAt = [&](size_t n) { return todo[order ? order[n] : n]; };
                for (size_t n = first; n < last; ++n)
                {
                  if (n + kPrefetchTets < last)
                    prefetchTet(mesh, birth, tetAt(n + kPrefetchTets));
                  if (n + kPrefetchPoints < last)
                    mesh.prefetchPoints(tetAt(n + kPrefetchPoints));
                  const size_t k = order ? order[n] : n;
                  const int32_t t = todo[k];
                  wanted[k] = unchangedSincePassBegan(mesh, birth, pass, t)
                    ? sizeWhereAPointIsWanted(mesh, sizing, options, hVol, t)
                    : 0;
                }
              });
}

// The next pass's tets: those born in `pass` and still alive, each once (a slot created, destroyed and
// reused in the pass is listed twice). Few: in slot order, as a sweep of the mesh would list them. From
// largeMeshTets: in the order the insertions created them, which follows the insertions through space
// (along the Hilbert curve from the first pass on), so that consecutive insertions work in the same part
// of the mesh without sorting the tets again.
void tetsBornIn(const TetMesh& mesh, std::vector<int32_t>& birth, int pass, int64_t largeMeshTets,
                std::vector<int32_t>& created, std::vector<int32_t>& todo)
{
  todo.clear();
  if (static_cast<int64_t>(created.size()) < largeMeshTets)
  {
    std::sort(created.begin(), created.end());
    created.erase(std::unique(created.begin(), created.end()), created.end());
    for (int32_t t : created)
      if (!mesh.isFree(t) && birth[t] == pass)
        todo.push_back(t);
    return;
  }
  constexpr int32_t kListed = -2; // a birth no pass has: the tet is in todo already
  for (int32_t t : created)
    if (!mesh.isFree(t) && birth[t] == pass)
    {
      todo.push_back(t);
      birth[t] = kListed;
    }
  for (int32_t t : todo)
    birth[t] = pass;
}
} // namespace

Status insertFieldPoints(TetMesh& mesh, const SizingField& sizing, const FieldPointOptions& options,
                         const FaceConstraints* constraints, std::vector<int32_t>* labels,
                         const std::function<bool(const double*)>& inside, Progress* progress,
                         FieldPointReport* reportOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (!(options.alpha > 0) || !std::isfinite(options.alpha) || !(options.beta >= 0) || !std::isfinite(options.beta) ||
      !(options.maxVolume >= 0))
    return Status::failure(ErrorKind::InvalidOption, "Field points need alpha > 0, beta >= 0 and maxVolume >= 0.");
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InvalidOption, "Field points are inserted into a mesh without ghost tets.");
  FieldPointReport local;
  FieldPointReport& report = reportOut ? *reportOut : local;
  TetEditor editor(mesh, constraints, labels, TetEditor::VertexMap::None);
  // h cap from maxVolume: edge of the regular tet of that volume, V = L^3 / (6 sqrt 2).
  const double hVol = options.maxVolume > 0 ? std::cbrt(options.maxVolume * 6.0 * std::sqrt(2.0)) : 0;
  std::vector<int32_t> birth(static_cast<size_t>(mesh.tetCapacity()), 0), created, todo, bornThisPass;
  std::vector<double> wanted;
  FieldPointRegions regionInserter(editor, options.threads);
  mesh.forEachTet([&](int32_t t) { todo.push_back(t); }); // the first pass examines every tet
  int64_t total = 0;
  for (int pass = 1; pass <= options.maxPasses; ++pass)
  {
    if (progress && progress->cancelled()) // the next pass's list, its sort and its regions' set-up follow
      return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
    // Many tets in the first pass (largeMeshTets): along the Hilbert curve, so that consecutive insertions work
    // in the same part of the mesh, whose tets are still in the caches (slot order jumps across the domain).
    // The later passes keep that order (tetsBornIn).
    if (pass == 1 && static_cast<int64_t>(todo.size()) >= options.largeMeshTets)
      sortAlongHilbertCurve(mesh, todo);
    bornThisPass.clear();
    int64_t insertedThisPass = 0;
    // One candidate, on this thread: false when the point cap is reached.
    auto insertCandidate = [&](size_t k)
    {
      const int32_t t = todo[k];
      const double h = wanted[k];
      if (!(h > 0) || !unchangedSincePassBegan(mesh, birth, pass, t))
        return true; // no point wanted, or destroyed (or its slot reused) by an insertion of this pass
      const int32_t* v = mesh.vertices(t);
      const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]), *d = mesh.point(v[3]);
      const double cen[3] = { (a[0] + b[0] + c[0] + d[0]) / 4, (a[1] + b[1] + c[1] + d[1]) / 4,
                              (a[2] + b[2] + c[2] + d[2]) / 4 };
      ++report.candidates;
      if (inside && !inside(cen))
      {
        ++report.rejectedOther;
        return true;
      }
      const int32_t nv = mesh.addPoint(cen);
      const auto st = editor.insertPoint(nv, t, options.beta * h, nullptr, &created);
      if (st != TetEditor::InsertStatus::Inserted)
      {
        mesh.points.resize(mesh.points.size() - 3);
        (st == TetEditor::InsertStatus::TooClose ? report.rejectedSpacing : report.rejectedOther)++;
        return true;
      }
      if (birth.size() < static_cast<size_t>(mesh.tetCapacity()))
        birth.resize(static_cast<size_t>(mesh.tetCapacity()) + 1024, -1);
      for (int32_t u : created)
        birth[u] = pass;
      bornThisPass.insert(bornThisPass.end(), created.begin(), created.end());
      ++insertedThisPass;
      ++total;
      return !(options.maxPoints >= 0 && total >= options.maxPoints);
    };
    // The tets todo[order[0, count)] (order null: todo[0, count)), one after the other on this thread, their
    // sizes asked a block at a time. False when cancelled.
    auto insertInOrder = [&](const size_t* order, size_t count)
    {
      for (size_t n = 0, tested = 0; n < count; ++n)
      {
        if (n == tested)
        {
          if (progress && progress->cancelled())
            return false;
          tested = std::min(count, n + kTestBlock);
          testTets(mesh, sizing, options, hVol, birth, pass, todo, order, n, tested, wanted);
        }
        if (((n + 1) & 4095) == 0 && progress)
        {
          if (progress->cancelled())
            return false;
          progress->report(std::min(1.0, (pass - 1 + double(n + 1) / count) / 8.0), "Creating field points");
        }
        if (!insertCandidate(order ? order[n] : n))
          break;
      }
      return true;
    };
    const int regions = inside || options.maxPoints >= 0 ? 1 : fieldPointRegionCount(options.regionTets, todo.size());
    bool finished = true;
    if (regions > 1)
    {
      // A large pass: its regions on the threads, then what they left, here (FieldPointRegions.h).
      FieldPointPass fp;
      fp.todo = &todo;
      fp.birth = &birth;
      fp.pass = pass;
      fp.beta = options.beta;
      fp.sizeWanted = [&](int32_t t) { return sizeWhereAPointIsWanted(mesh, sizing, options, hVol, t); };
      fp.sizeWantedConcurrently = sizing.evaluatesConcurrently();
      FieldPointRegionOutcome out;
      const Status s = regionInserter.insertPass(fp, regions, progress, out);
      insertedThisPass += out.inserted;
      total += out.inserted;
      report.candidates += out.candidates;
      report.rejectedSpacing += out.rejectedSpacing;
      report.rejectedOther += out.rejectedOther;
      report.insertedInRegions += out.inserted;
      report.deferredToOneThread += static_cast<int64_t>(out.deferred.size());
      bornThisPass.swap(out.created);
      if (!s.ok())
        return s;
      finished = insertInOrder(out.deferred.data(), out.deferred.size());
    }
    else
      finished = insertInOrder(nullptr, todo.size());
    if (!finished)
      return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
    report.passes = pass;
    report.insertedPerPass.push_back(insertedThisPass);
    report.inserted += insertedThisPass;
    if (insertedThisPass == 0 || (options.maxPoints >= 0 && total >= options.maxPoints))
      break;
    tetsBornIn(mesh, birth, pass, options.largeMeshTets, bornThisPass, todo);
  }
  if (progress)
    progress->report(1.0, "Creating field points");
  report.seconds += secondsSince(t0);
  return Status::success();
}

Status insertClusterPoints(TetMesh& mesh, const double* xyz, size_t n, double minSpacing,
                           const FaceConstraints* constraints, std::vector<int32_t>* labels,
                           std::vector<int32_t>* vertexIds, Progress* progress, FieldPointReport* reportOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  if (mesh.numGhostTets() > 0)
    return Status::failure(ErrorKind::InvalidOption, "Cluster points are inserted into a mesh without ghost tets.");
  if (!(minSpacing >= 0))
    return Status::failure(ErrorKind::InvalidOption, "The cluster point spacing must be >= 0.");
  FieldPointReport local;
  FieldPointReport& report = reportOut ? *reportOut : local;
  TetEditor editor(mesh, constraints, labels);
  if (vertexIds)
    vertexIds->assign(n, -1);
  int32_t hint = -1;
  mesh.forEachTet(
    [&](int32_t t)
    {
      if (hint < 0)
        hint = t;
    });
  std::vector<int32_t> created;
  for (size_t i = 0; i < n; ++i)
  {
    if ((i & 1023) == 1023 && progress)
    {
      if (progress->cancelled())
        return Status::failure(ErrorKind::Cancelled, "Cluster point insertion was cancelled.");
      progress->report(double(i) / n, "Inserting cluster points");
    }
    const double* p = xyz + 3 * i;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || hint < 0)
    {
      ++report.clusterOutside;
      continue;
    }
    const int32_t t = editor.locateRobust(p, hint);
    if (t < 0)
    {
      ++report.clusterOutside;
      continue;
    }
    const int32_t nv = mesh.addPoint(p);
    const auto st = editor.insertPoint(nv, t, minSpacing, nullptr, &created);
    if (st != TetEditor::InsertStatus::Inserted)
    {
      mesh.points.resize(mesh.points.size() - 3);
      (st == TetEditor::InsertStatus::NotInside ? report.clusterOutside : report.clusterRejected)++;
      continue;
    }
    hint = created.front();
    ++report.clusterInserted;
    if (vertexIds)
      (*vertexIds)[i] = nv;
  }
  report.seconds += secondsSince(t0);
  return Status::success();
}

} // namespace volgrid
