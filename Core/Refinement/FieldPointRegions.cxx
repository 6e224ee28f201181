#include "FieldPointRegions.h"

#include "MeshRegions.h"
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
constexpr size_t kTestBlock = 4096;                       // tets whose sizes are asked ahead of their insertions
constexpr size_t kPrefetchTets = 16, kPrefetchPoints = 8; // how far ahead their loads start
// New slots a region sets aside per tet of the pass: about one tet in 20 gets a point, and an insertion adds
// about 6.5 tets net (a Delaunay mesh has about 6.5 tets per vertex).
constexpr double kSlotsPerTodoTet = 0.5;
constexpr double kPointsPerTodoTet = 0.125; // numbers set aside per tet of the pass (about one in 20 gets a point)

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
  tetCentroid(mesh, t, mesh.points.data() + 3 * static_cast<size_t>(id));
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

// Each region's slots: about as many as its insertions will need (a region that runs out defers the rest).
void fillPools(TetMesh& mesh, std::vector<RegionWork>& works)
{
  std::vector<TetSlotPool*> pools;
  std::vector<size_t> wants;
  for (RegionWork& w : works)
  {
    pools.push_back(&w.pool);
    wants.push_back(static_cast<size_t>(kSlotsPerTodoTet * static_cast<double>(w.todo.size())) + 64);
  }
  fillSlotPools(mesh, pools, wants);
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

} // namespace

int fieldPointRegionCount(int64_t regionTets, int64_t todoTets)
{
  return regionCountFor(todoTets, regionTets > 0 ? regionTets : kTodoTetsPerRegion, kMaxRegions);
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
  const RegionBoxes boxes = boxesOfTets(mesh, todo, regions);
  std::vector<RegionWork> works(static_cast<size_t>(regions));
  // Temporary numbers for the new points, above every final one (a region that runs out defers the rest).
  const int32_t meshVertices = mesh.numVertices();
  int32_t temporaryIds = 0;
  std::vector<uint8_t> vertexRegion = vertexRegions(mesh, boxes, threads_);
  std::vector<uint8_t> todoRegion(todo.size());
  parallelFor(threads_, static_cast<int64_t>(todo.size()), 16384,
              [&](int, int64_t from, int64_t to)
              {
                for (int64_t k = from; k < to; ++k)
                  todoRegion[static_cast<size_t>(k)] = tetRegionOf(mesh, vertexRegion, todo[static_cast<size_t>(k)]);
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
