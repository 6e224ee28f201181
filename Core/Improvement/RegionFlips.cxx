#include "RegionFlips.h"

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
constexpr int64_t kBadTetsPerRegion = 4096; // in a box of about 30 times as many tets: about a tenth is border
constexpr int kMaxRegions = 64;
constexpr size_t kSlotsPerTet = 1; // a flip adds at most a few tets; a region that runs out defers the rest
constexpr size_t kSpareSlots = 256;

struct RegionWork
{
  std::vector<int32_t> queue; // its tets, ascending, then the new ones under the aim
  TetSlotPool pool;
  std::vector<int32_t> created, deferred;
  int64_t made = 0;
};

// Region r's tets, one after the other; stop is set (by the first thread, when asked to) to end all regions.
void flipRegion(TetEditor& editor, uint8_t r, const std::vector<uint8_t>& vertexRegion, RegionWork& work, double aim,
                const std::function<double(int32_t)>& quality,
                const std::function<FlipAttempt(TetEditor&, int32_t, std::vector<int32_t>&)>& attempt, Progress* watch,
                std::atomic<bool>& stop)
{
  TetEditor::RegionLimit limit;
  limit.vertexRegion = vertexRegion.data();
  limit.region = r;
  editor.regionLimit = &limit;
  editor.slotPool = &work.pool;
  std::vector<int32_t> created;
  for (size_t k = 0; k < work.queue.size(); ++k)
  {
    if ((k & 1023) == 1023 && watch && watch->cancelled())
      stop = true;
    if (stop.load(std::memory_order_relaxed))
      break;
    const int32_t t = work.queue[k];
    // A slot this region freed (and maybe reused) holds none of the others' tets: the test reads its own.
    if (editor.mesh.isFree(t) || !limit.owns(editor.mesh.vertices(t)) || !(quality(t) < aim))
      continue;
    const FlipAttempt a = attempt(editor, t, created);
    if (a == FlipAttempt::Deferred)
      work.deferred.push_back(t);
    if (a != FlipAttempt::Made)
      continue;
    ++work.made;
    work.created.insert(work.created.end(), created.begin(), created.end());
    for (int32_t u : created)
      if (quality(u) < aim)
        work.queue.push_back(u);
  }
  editor.regionLimit = nullptr;
  editor.slotPool = nullptr;
}
} // namespace

int regionFlipCount(int64_t regionTets, int64_t tets)
{
  return regionCountFor(tets, regionTets > 0 ? regionTets : kBadTetsPerRegion, kMaxRegions);
}

Status flipByRegions(TetEditor& mainEditor, const std::vector<int32_t>& sweep, int regions, int threads, double aim,
                     const std::function<double(int32_t)>& quality,
                     const std::function<FlipAttempt(TetEditor&, int32_t, std::vector<int32_t>&)>& attempt,
                     Progress* progress, RegionFlipOutcome& outcome)
{
  TetMesh& mesh = mainEditor.mesh;
  outcome = RegionFlipOutcome();
  const RegionBoxes boxes = boxesOfTets(mesh, sweep, regions);
  const std::vector<uint8_t> vertexRegion = vertexRegions(mesh, boxes, threads);
  std::vector<RegionWork> works(static_cast<size_t>(regions));
  for (int32_t t : sweep)
  {
    const uint8_t r = tetRegionOf(mesh, vertexRegion, t);
    (r == kSpansRegions ? outcome.deferred : works[r].queue).push_back(t);
  }
  std::vector<TetSlotPool*> pools;
  std::vector<size_t> wants;
  for (RegionWork& w : works)
  {
    pools.push_back(&w.pool);
    wants.push_back(kSlotsPerTet * w.queue.size() + kSpareSlots);
  }
  fillSlotPools(mesh, pools, wants);
  if (mainEditor.labels)
    mainEditor.labels->resize(static_cast<size_t>(mesh.tetCapacity()), -1);

  const int workers = std::max(1, std::min(resolveThreads(threads), regions));
  std::vector<std::unique_ptr<TetEditor>> editors;
  for (int i = 0; i < workers; ++i)
    editors.emplace_back(new TetEditor(mesh, mainEditor.constraints, mainEditor.labels, TetEditor::VertexMap::None));
  std::atomic<int> nextRegion(0);
  std::atomic<bool> stop(false);
  parallelRun(workers,
              [&](int worker)
              {
                for (int r = nextRegion++; r < regions && !stop.load(); r = nextRegion++)
                  flipRegion(*editors[static_cast<size_t>(worker)], static_cast<uint8_t>(r), vertexRegion,
                             works[static_cast<size_t>(r)], aim, quality, attempt, worker == 0 ? progress : nullptr,
                             stop);
              });
  for (RegionWork& w : works)
  {
    w.pool.returnAll(mesh);
    outcome.made += w.made;
    outcome.created.insert(outcome.created.end(), w.created.begin(), w.created.end());
    outcome.deferred.insert(outcome.deferred.end(), w.deferred.begin(), w.deferred.end());
  }
  std::sort(outcome.deferred.begin(), outcome.deferred.end());
  mainEditor.mapTetsMadeElsewhere(outcome.created);
  if (stop.load())
    return Status::failure(ErrorKind::Cancelled, "Optimisation was cancelled.");
  return Status::success();
}

} // namespace volgrid
