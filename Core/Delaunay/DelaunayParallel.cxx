// Two-thread Delaunay construction (buildDelaunay with threads > 1).
#include "DelaunayInserterImpl.h"
#include "ParallelFor.h"

#include <memory>

namespace volgrid
{

// Two threads insert the two halves (along the Hilbert curve) of each BRIO round from `round0` on.
// Every tet is acquired before it is read (see DelaunayInserter::Impl::acquire); an insertion that
// meets the other thread's tets is undone and retried by `main` after the round. New slots come from a
// pool appended to the mesh up front; when it runs out, the remaining points go to `rest`.
Status insertParallel(TetMesh& mesh, DelaunayInserter& main, const std::vector<int32_t>& order,
                      const std::vector<size_t>& roundStarts, size_t round0, const int32_t* firstTet,
                      std::vector<int32_t>& inputToVertex, std::vector<int32_t>& rest, DelaunayReport& rep,
                      Progress* progress, uint64_t seed)
{
  auto isFirstTet = [firstTet](int32_t k)
  { return k == firstTet[0] || k == firstTet[1] || k == firstTet[2] || k == firstTet[3]; };
  const int32_t m = static_cast<int32_t>(order.size());
  DelaunayInserter::Impl& mi = *main.impl_;
  const int32_t used = mesh.tetCapacity();
  const int32_t pool = std::max<int32_t>(used, static_cast<int32_t>(7.25 * m) + 64);
  mesh.appendTets(pool - used);
  std::unique_ptr<std::atomic<uint8_t>[]> owner(new std::atomic<uint8_t>[static_cast<size_t>(pool)]());
  std::atomic<int32_t> nextSlot(used);
  DelaunayInserter w0(mesh, seed + 1), w1(mesh, seed + 2);
  DelaunayInserter::Impl* workers[2] = { w0.impl_.get(), w1.impl_.get() };
  for (int i = 0; i < 2; ++i)
  {
    DelaunayInserter::Impl& w = *workers[i];
    w.sosId = mi.sosId;
    w.latticeOrientLimit = mi.latticeOrientLimit;
    w.latticeInsphereLimit2 = mi.latticeInsphereLimit2;
    w.owner = owner.get();
    w.me = static_cast<uint8_t>(i + 1);
    w.nextSlot = &nextSlot;
    w.slotLimit = pool;
    w.last = mi.last;
  }
  mi.nextSlot = &nextSlot;
  mi.slotLimit = pool;
  std::vector<int32_t> deferred[2];
  bool full = false;
  size_t r = round0;
  for (; r + 1 < roundStarts.size() && !full; ++r)
  {
    const int32_t a = static_cast<int32_t>(roundStarts[r]), b = static_cast<int32_t>(roundStarts[r + 1]);
    const int32_t mid = a + (b - a) / 2;
    // Start each thread's walks near its first point (located before the threads start).
    workers[0]->owner = workers[1]->owner = nullptr;
    workers[0]->last = workers[0]->walk(mesh.point(a), mi.liveTet(workers[0]->last));
    workers[1]->last = workers[1]->walk(mesh.point(mid), workers[0]->last);
    workers[0]->owner = workers[1]->owner = owner.get();
    auto work = [&](int i, int32_t from, int32_t to)
    {
      DelaunayInserter::Impl& w = *workers[i];
      deferred[i].clear();
      for (int32_t k = from; k < to; ++k)
      {
        if (isFirstTet(k))
          continue;
        if (w.poolFull)
        {
          deferred[i].push_back(k);
          continue;
        }
        const DelaunayInserter::Result res = w.insert(k, -1, k + 1 < to ? mesh.point(k + 1) : nullptr);
        if (res.aborted)
          deferred[i].push_back(k);
        else if (res.duplicateOf >= 0)
          inputToVertex[order[k]] = order[res.duplicateOf];
      }
    };
    parallelRun(2, [&](int w) { w == 0 ? work(0, a, mid) : work(1, mid, b); });
    for (int i = 0; i < 2; ++i)
      for (int32_t k : deferred[i])
      {
        if (full)
        {
          rest.push_back(k);
          continue;
        }
        const DelaunayInserter::Result res = mi.insert(k, -1, nullptr);
        if (res.aborted)
        {
          full = true; // the pool is exhausted
          rest.push_back(k);
        }
        else if (res.duplicateOf >= 0)
          inputToVertex[order[k]] = order[res.duplicateOf];
      }
    full = full || workers[0]->poolFull || workers[1]->poolFull;
    progress->report(static_cast<double>(b) / static_cast<double>(m), "Inserting points");
    if (progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Delaunay tetrahedralization cancelled.");
  }
  for (; r + 1 < roundStarts.size(); ++r)
    for (int32_t k = static_cast<int32_t>(roundStarts[r]); k < static_cast<int32_t>(roundStarts[r + 1]); ++k)
      if (!isFirstTet(k))
        rest.push_back(k);
  // Close the pool: drop its unused tail, free the recycled slots, report the ghost counts.
  DelaunayInserter::Impl* all[3] = { workers[0], workers[1], &mi };
  int32_t end = std::min(nextSlot.load(), pool);
  for (DelaunayInserter::Impl* w : all)
    end = std::min(end, w->poolEnd);
  mesh.truncate(end);
  for (DelaunayInserter::Impl* w : all)
  {
    for (int32_t t : w->spare)
      if (t < mesh.tetCapacity())
      {
        mesh.tetFlags[t] = 0;
        mesh.freeTet(t);
      }
    w->spare.clear();
    mesh.adjustGhostCount(w->pendingGhostDelta);
    w->pendingGhostDelta = 0;
    w->nextSlot = nullptr;
    w->owner = nullptr;
  }
  mi.last = workers[0]->last < mesh.tetCapacity() ? workers[0]->last : -1;
  rep.walkSteps += workers[0]->walkSteps + workers[1]->walkSteps;
  rep.cavityTets += workers[0]->cavityTets + workers[1]->cavityTets;
  return Status::success();
}

} // namespace volgrid
