#include "FieldPointRegions.h"

#include "ParallelFor.h"
#include "TetSlotPool.h"

#include <algorithm>
#include <atomic>
#include <memory>

namespace volgrid
{

namespace
{
constexpr int64_t kTodoTetsPerRegion = 32768; // a smaller region is mostly border
constexpr int kMaxRegions = 64;
constexpr uint8_t kSpansRegions = 255;
constexpr size_t kTestBlock = 4096;                       // tets whose sizes are asked ahead of their insertions
constexpr size_t kPrefetchTets = 16, kPrefetchPoints = 8; // how far ahead their loads start
constexpr size_t kBoxSample = 32768;
// New slots a region sets aside per tet of the pass: about one tet in 20 gets a point, and an insertion adds
// about 6.5 tets net (a Delaunay mesh has about 6.5 tets per vertex).
constexpr double kSlotsPerTodoTet = 0.5;
constexpr double kPointsPerTodoTet = 0.125; // numbers set aside per tet of the pass (about one in 20 gets a point)

void centroidOf(const TetMesh& mesh, int32_t t, double* c)
{
  const int32_t* v = mesh.vertices(t);
  const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *d = mesh.point(v[2]), *e = mesh.point(v[3]);
  for (int k = 0; k < 3; ++k)
    c[k] = (a[k] + b[k] + d[k] + e[k]) / 4;
}

// The boxes: a k-d tree of `regions` leaves (a power of two), node i's children 2i+1 and 2i+2; each split
// halves the node's points across the longest side of their bounding box.
class RegionBoxes
{
public:
  RegionBoxes(const std::vector<double>& xyz, int regions)
    : split_(static_cast<size_t>(regions - 1))
  {
    std::vector<int32_t> ids(xyz.size() / 3);
    for (size_t i = 0; i < ids.size(); ++i)
      ids[i] = static_cast<int32_t>(i);
    build(xyz, ids.begin(), ids.end(), 0);
  }
  uint8_t regionOf(const double* p) const
  {
    size_t node = 0;
    while (node < split_.size())
      node = 2 * node + (p[split_[node].axis] < split_[node].at ? 1 : 2);
    return static_cast<uint8_t>(node - split_.size());
  }

private:
  struct Split
  {
    int axis = 0;
    double at = 0;
  };
  using Iter = std::vector<int32_t>::iterator;
  void build(const std::vector<double>& xyz, Iter begin, Iter end, size_t node)
  {
    if (node >= split_.size())
      return;
    double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
    for (Iter i = begin; i != end; ++i)
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], xyz[3 * static_cast<size_t>(*i) + k]);
        hi[k] = std::max(hi[k], xyz[3 * static_cast<size_t>(*i) + k]);
      }
    Split& s = split_[node];
    s.axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[s.axis] - lo[s.axis])
        s.axis = k;
    auto coordinate = [&](int32_t i) { return xyz[3 * static_cast<size_t>(i) + s.axis]; };
    Iter mid = begin + (end - begin) / 2;
    if (begin != end)
    {
      std::nth_element(begin, mid, end, [&](int32_t a, int32_t b) { return coordinate(a) < coordinate(b); });
      s.at = coordinate(*mid);
    }
    // The children get the points as regionOf() sends them.
    mid = std::partition(begin, end, [&](int32_t i) { return coordinate(i) < s.at; });
    build(xyz, begin, mid, 2 * node + 1);
    build(xyz, mid, end, 2 * node + 2);
  }
  std::vector<Split> split_;
};

// The region of tet t: its vertices' common region, or kSpansRegions.
uint8_t tetRegion(const TetMesh& mesh, const std::vector<uint8_t>& vertexRegion, int32_t t)
{
  const int32_t* v = mesh.vertices(t);
  const uint8_t r = vertexRegion[static_cast<size_t>(v[0])];
  for (int i = 1; i < 4; ++i)
    if (vertexRegion[static_cast<size_t>(v[i])] != r)
      return kSpansRegions;
  return r;
}

// What one region does, and what it leaves.
struct RegionWork
{
  std::vector<size_t> todo; // its tets' todo indices, in the pass's order
  int32_t firstId = 0;      // its points are numbered firstId, firstId + 1, ... while the regions run
  int32_t ids = 0;          // ... up to firstId + ids - 1
  int32_t inserted = 0;
  TetSlotPool pool;
  std::vector<int32_t> created;
  std::vector<size_t> deferred;
  int64_t candidates = 0, rejectedSpacing = 0, rejectedOther = 0;
};

// What every region reads and writes: the pass, the vertices' regions, the sizes asked.
struct RegionShared
{
  const FieldPointPass& pass;
  std::vector<uint8_t>& vertexRegion;
  std::vector<double>& wanted; // per todo index; each region writes its own tets' entries
  Progress* watch;             // asked for a cancel by the first thread only
  std::atomic<bool>& stop;
};

bool unchangedSincePassBegan(const TetMesh& mesh, const FieldPointPass& pass, int32_t t)
{
  return !mesh.isFree(t) && (*pass.birth)[static_cast<size_t>(t)] == pass.pass - 1;
}

// Inserts the point of the region's n-th tet when it still wants one.
void insertRegionPoint(TetEditor& editor, const RegionShared& shared, uint8_t r, RegionWork& work, size_t n,
                       std::vector<int32_t>& created)
{
  TetMesh& mesh = editor.mesh;
  const FieldPointPass& pass = shared.pass;
  const size_t k = work.todo[n];
  const int32_t t = (*pass.todo)[k];
  const double h = shared.wanted[k];
  if (!(h > 0) || !unchangedSincePassBegan(mesh, pass, t))
    return; // no point wanted, or destroyed (or its slot reused) by an insertion of this region
  if (work.inserted == work.ids)
  {
    work.deferred.push_back(k);
    return;
  }
  const int32_t id = work.firstId + work.inserted;
  centroidOf(mesh, t, mesh.points.data() + 3 * static_cast<size_t>(id));
  shared.vertexRegion[static_cast<size_t>(id)] = r;
  const auto st = editor.insertPoint(id, t, pass.beta * h, nullptr, &created);
  if (st == TetEditor::InsertStatus::Deferred)
  {
    work.deferred.push_back(k);
    return;
  }
  ++work.candidates;
  if (st != TetEditor::InsertStatus::Inserted)
  {
    ++(st == TetEditor::InsertStatus::TooClose ? work.rejectedSpacing : work.rejectedOther);
    return;
  }
  for (int32_t u : created)
    (*pass.birth)[static_cast<size_t>(u)] = pass.pass;
  work.created.insert(work.created.end(), created.begin(), created.end());
  ++work.inserted;
}

// Region r's tets, one after the other, a block at a time: the sizes of the block's unchanged tets are
// asked just before its insertions (tets destroyed by then are not asked).
void insertRegion(TetEditor& editor, const RegionShared& shared, uint8_t r, RegionWork& work)
{
  TetEditor::RegionLimit limit;
  limit.vertexRegion = shared.vertexRegion.data();
  limit.region = r;
  editor.regionLimit = &limit;
  editor.slotPool = &work.pool;
  std::vector<int32_t> created;
  for (size_t begin = 0; begin < work.todo.size(); begin += kTestBlock)
  {
    if (shared.watch && shared.watch->cancelled())
      shared.stop = true;
    if (shared.stop.load(std::memory_order_relaxed))
      break; // the rest is neither inserted nor deferred: the caller returns Cancelled
    const size_t end = std::min(work.todo.size(), begin + kTestBlock);
    const auto tetAt = [&](size_t n) { return (*shared.pass.todo)[work.todo[n]]; };
    for (size_t n = begin; n < end; ++n)
    {
      // The tets are scattered through memory: their loads start a few tets ahead (FieldPoints.cxx).
      if (n + kPrefetchTets < end)
      {
        editor.mesh.prefetchTet(tetAt(n + kPrefetchTets));
        __builtin_prefetch(&(*shared.pass.birth)[static_cast<size_t>(tetAt(n + kPrefetchTets))]);
      }
      if (n + kPrefetchPoints < end)
        editor.mesh.prefetchPoints(tetAt(n + kPrefetchPoints));
      const int32_t t = tetAt(n);
      shared.wanted[work.todo[n]] =
        unchangedSincePassBegan(editor.mesh, shared.pass, t) ? shared.pass.sizeWanted(t) : 0;
    }
    for (size_t n = begin; n < end; ++n)
      insertRegionPoint(editor, shared, r, work, n, created);
  }
  editor.regionLimit = nullptr;
  editor.slotPool = nullptr;
}

// Each region's slots, set aside before the threads start: about as many as its insertions will need (a
// region that runs out defers the rest). The mesh's free slots first, in slot order, so that each region
// writes its own stretch of the arrays; then appended ones. The free slots no region takes go back to the
// mesh's free list, the lowest first in line.
void fillPools(TetMesh& mesh, std::vector<RegionWork>& works)
{
  std::vector<int32_t> free = mesh.takeFreeSlots();
  size_t used = 0;
  for (RegionWork& w : works)
  {
    const size_t want = static_cast<size_t>(kSlotsPerTodoTet * static_cast<double>(w.todo.size())) + 64;
    const size_t fromList = std::min(free.size() - used, want);
    std::vector<int32_t> mine(free.begin() + static_cast<ptrdiff_t>(used),
                              free.begin() + static_cast<ptrdiff_t>(used + fromList));
    used += fromList;
    const int32_t appended = static_cast<int32_t>(want - fromList);
    w.pool.assign(std::move(mine), mesh.appendTets(appended), appended);
  }
  for (size_t i = free.size(); i > used; --i)
    mesh.returnSlot(free[i - 1]);
}

// After the regions: their points renumbered to follow the mesh's (region by region), the unused numbers
// and slots given back.
void closeRegions(TetMesh& mesh, int32_t meshVertices, int32_t firstTemporaryId, std::vector<RegionWork>& works)
{
  std::vector<int32_t> finalId(static_cast<size_t>(mesh.numVertices() - firstTemporaryId), -1);
  int32_t next = meshVertices;
  for (RegionWork& w : works)
    for (int32_t i = 0; i < w.inserted; ++i)
    {
      const int32_t from = w.firstId + i;
      finalId[static_cast<size_t>(from - firstTemporaryId)] = next;
      std::copy_n(mesh.points.begin() + 3 * static_cast<ptrdiff_t>(from), 3,
                  mesh.points.begin() + 3 * static_cast<ptrdiff_t>(next));
      ++next;
    }
  for (RegionWork& w : works)
    for (int32_t t : w.created)
    {
      if (mesh.isFree(t))
        continue;
      int32_t* v = mesh.tetVertices.data() + 4 * static_cast<size_t>(t);
      for (int i = 0; i < 4; ++i)
        if (v[i] >= firstTemporaryId) // temporary numbers are above every final one: a slot listed twice is fine
          v[i] = finalId[static_cast<size_t>(v[i] - firstTemporaryId)];
    }
  mesh.points.resize(3 * static_cast<size_t>(next));
  for (RegionWork& w : works)
    w.pool.returnAll(mesh);
}

// The boxes, from the centroids of (a sample of at most about 2 x kBoxSample of) the pass's tets.
RegionBoxes boxesOf(const TetMesh& mesh, const std::vector<int32_t>& todo, int regions)
{
  const size_t stride = std::max<size_t>(1, todo.size() / kBoxSample);
  std::vector<double> xyz;
  xyz.reserve(3 * (todo.size() / stride + 1));
  for (size_t k = 0; k < todo.size(); k += stride)
  {
    xyz.resize(xyz.size() + 3);
    centroidOf(mesh, todo[k], xyz.data() + xyz.size() - 3);
  }
  return RegionBoxes(xyz, regions);
}
} // namespace

int fieldPointRegionCount(int64_t regionTets, int64_t todoTets)
{
  const int64_t perRegion = regionTets > 0 ? regionTets : kTodoTetsPerRegion;
  int regions = 1;
  while (regions < kMaxRegions && todoTets / (2 * regions) >= perRegion)
    regions *= 2;
  return regions;
}

FieldPointRegions::FieldPointRegions(TetEditor& editor, int threads)
  : editor_(editor)
  , threads_(resolveThreads(threads))
{
}

FieldPointRegions::~FieldPointRegions() = default;

Status FieldPointRegions::insertPass(const FieldPointPass& pass, int regions, Progress* progress,
                                     FieldPointRegionOutcome& outcome)
{
  TetMesh& mesh = editor_.mesh;
  const std::vector<int32_t>& todo = *pass.todo;
  outcome = FieldPointRegionOutcome();
  const RegionBoxes boxes = boxesOf(mesh, todo, regions);
  std::vector<RegionWork> works(static_cast<size_t>(regions));
  // Temporary numbers for the new points, above every final one (a region that runs out defers the rest).
  const int32_t meshVertices = mesh.numVertices();
  int32_t temporaryIds = 0;
  std::vector<uint8_t> vertexRegion(static_cast<size_t>(meshVertices), kSpansRegions);
  parallelFor(threads_, meshVertices, 16384,
              [&](int, int64_t from, int64_t to)
              {
                for (int64_t v = from; v < to; ++v)
                  vertexRegion[static_cast<size_t>(v)] = boxes.regionOf(mesh.point(static_cast<int32_t>(v)));
              });
  std::vector<uint8_t> todoRegion(todo.size());
  parallelFor(threads_, static_cast<int64_t>(todo.size()), 16384,
              [&](int, int64_t from, int64_t to)
              {
                for (int64_t k = from; k < to; ++k)
                  todoRegion[static_cast<size_t>(k)] = tetRegion(mesh, vertexRegion, todo[static_cast<size_t>(k)]);
              });
  // The boxes and the two labellings above take a few tenths of a second at 10M tets; nothing is changed yet.
  if (progress && progress->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
  for (size_t k = 0; k < todo.size(); ++k)
    (todoRegion[k] == kSpansRegions ? outcome.deferred : works[todoRegion[k]].todo).push_back(k);
  for (RegionWork& w : works)
  {
    w.ids = static_cast<int32_t>(kPointsPerTodoTet * static_cast<double>(w.todo.size())) + 64;
    temporaryIds += w.ids;
  }
  const int32_t firstTemporaryId = meshVertices + temporaryIds;
  int32_t nextId = firstTemporaryId;
  for (RegionWork& w : works)
  {
    w.firstId = nextId;
    nextId += w.ids;
  }
  mesh.points.resize(3 * static_cast<size_t>(nextId), 0.0);
  vertexRegion.resize(static_cast<size_t>(nextId), kSpansRegions);
  fillPools(mesh, works);
  pass.birth->resize(static_cast<size_t>(mesh.tetCapacity()), -1);
  if (editor_.labels)
    editor_.labels->resize(static_cast<size_t>(mesh.tetCapacity()), -1);

  // The regions, on the threads in any order. The first thread runs on the calling one and watches for a cancel.
  const int workers = pass.sizeWantedConcurrently ? std::max(1, std::min(threads_, regions)) : 1;
  while (static_cast<int>(more_.size()) + 1 < workers)
    more_.emplace_back(new TetEditor(mesh, editor_.constraints, editor_.labels, TetEditor::VertexMap::None));
  std::vector<double> wanted(todo.size(), 0.0);
  std::atomic<int> nextRegion(0);
  std::atomic<bool> stop(false);
  parallelRun(workers,
              [&](int worker)
              {
                TetEditor& editor = worker == 0 ? editor_ : *more_[static_cast<size_t>(worker - 1)];
                const RegionShared shared{ pass, vertexRegion, wanted, worker == 0 ? progress : nullptr, stop };
                for (int r = nextRegion++; r < regions && !stop.load(); r = nextRegion++)
                {
                  if (worker == 0 && progress)
                    progress->report(std::min(1.0, (pass.pass - 1 + double(r) / regions) / 8.0),
                                     "Creating field points"); // as FieldPoints.cxx reports a pass
                  insertRegion(editor, shared, static_cast<uint8_t>(r), works[static_cast<size_t>(r)]);
                }
              });
  closeRegions(mesh, meshVertices, firstTemporaryId, works);
  for (RegionWork& w : works)
  {
    outcome.inserted += w.inserted;
    outcome.candidates += w.candidates;
    outcome.rejectedSpacing += w.rejectedSpacing;
    outcome.rejectedOther += w.rejectedOther;
    outcome.created.insert(outcome.created.end(), w.created.begin(), w.created.end());
    outcome.deferred.insert(outcome.deferred.end(), w.deferred.begin(), w.deferred.end());
  }
  std::sort(outcome.deferred.begin(), outcome.deferred.end());
  if (stop.load())
    return Status::failure(ErrorKind::Cancelled, "Field point creation was cancelled.");
  return Status::success();
}

} // namespace volgrid
