// Multi-threaded Delaunay construction (buildDelaunay with threads > 1).
#include "DelaunayInserterImpl.h"
#include "ParallelFor.h"

#include <memory>

namespace volgrid
{

namespace
{
// The number of chunks a round of `size` points is cut into: one per worker, but never below
// kParallelMinChunk points per chunk (a small chunk is mostly border, where insertions conflict).
int chunksOf(int32_t size, int workers)
{
  return static_cast<int>(std::max<int64_t>(1, std::min<int64_t>(workers, size / kParallelMinChunk)));
}
} // namespace

// `workers` threads insert the contiguous chunks (along the Hilbert curve) of each BRIO round from
// `round0` on. Every tet is acquired before it is read (see DelaunayInserter::Impl::acquire); an
// insertion that meets another worker's tets is undone, kept in its worker's deferred list, and retried
// by `main` alone after the round (deferred lists in worker order). New slots come from a pool appended
// to the mesh up front (one atomic counter); when it runs out, the remaining points go to `rest`. The
// tets built are the unique Delaunay ones whatever the interleaving; only their slots differ, which
// canonicalizeTets removes.
Status insertParallel(TetMesh& mesh, DelaunayInserter& main, const std::vector<int32_t>& order,
                      const std::vector<size_t>& roundStarts, size_t round0, const int32_t* firstTet,
                      std::vector<int32_t>& inputToVertex, std::vector<int32_t>& rest, DelaunayReport& rep,
                      Progress* progress, uint64_t seed, int workers)
{
  auto isFirstTet = [firstTet](int32_t k)
  { return k == firstTet[0] || k == firstTet[1] || k == firstTet[2] || k == firstTet[3]; };
  workers = std::max(1, std::min(workers, kMaxParallelWorkers));
  const int32_t m = static_cast<int32_t>(order.size());
  DelaunayInserter::Impl& mi = *main.impl_;
  const int32_t used = mesh.tetCapacity();
  const int32_t pool = std::max<int32_t>(used, static_cast<int32_t>(7.25 * m) + 64);
  mesh.appendTets(pool - used);
  std::unique_ptr<std::atomic<uint8_t>[]> owner(new std::atomic<uint8_t>[static_cast<size_t>(pool)]());
  std::atomic<int32_t> nextSlot(used);
  std::vector<std::unique_ptr<DelaunayInserter>> inserters;
  std::vector<DelaunayInserter::Impl*> ws;
  for (int i = 0; i < workers; ++i)
  {
    inserters.emplace_back(new DelaunayInserter(mesh, seed + 1 + static_cast<uint64_t>(i)));
    DelaunayInserter::Impl& w = *inserters.back()->impl_;
    w.sosId = mi.sosId;
    w.latticeOrientLimit = mi.latticeOrientLimit;
    w.latticeInsphereLimit2 = mi.latticeInsphereLimit2;
    w.me = static_cast<uint8_t>(i + 1);
    w.nextSlot = &nextSlot;
    w.slotLimit = pool;
    w.last = mi.last;
    ws.push_back(&w);
  }
  mi.nextSlot = &nextSlot;
  mi.slotLimit = pool;
  std::vector<std::vector<int32_t>> deferred(static_cast<size_t>(workers));
  std::vector<int32_t> cut(static_cast<size_t>(workers) + 1);
  bool full = false;
  size_t r = round0;
  for (; r + 1 < roundStarts.size() && !full; ++r)
  {
    const int32_t a = static_cast<int32_t>(roundStarts[r]), b = static_cast<int32_t>(roundStarts[r + 1]);
    const int k = chunksOf(b - a, workers);
    for (int i = 0; i <= k; ++i)
      cut[i] = a + static_cast<int32_t>(static_cast<int64_t>(b - a) * i / k);
    // Start each worker's walks near its first point (located before the workers start, without owners).
    int32_t from = mi.liveTet(ws[0]->last);
    for (int i = 0; i < k; ++i)
    {
      ws[i]->owner = nullptr;
      ws[i]->last = from = ws[i]->walk(mesh.point(cut[i]), from);
      ws[i]->owner = owner.get();
    }
    auto work = [&](int i)
    {
      DelaunayInserter::Impl& w = *ws[i];
      std::vector<int32_t>& def = deferred[i];
      def.clear();
      const int32_t to = cut[i + 1];
      for (int32_t q = cut[i]; q < to; ++q)
      {
        if (isFirstTet(q))
          continue;
        if (w.poolFull)
        {
          def.push_back(q);
          continue;
        }
        const DelaunayInserter::Result res = w.insert(q, -1, q + 1 < to ? mesh.point(q + 1) : nullptr);
        if (res.aborted)
          def.push_back(q);
        else if (res.duplicateOf >= 0)
          inputToVertex[order[q]] = order[res.duplicateOf];
      }
    };
    parallelRun(k, work);
    for (int i = 0; i < k; ++i)
    {
      rep.deferred += deferred[i].size();
      for (int32_t q : deferred[i])
      {
        if (full)
        {
          rest.push_back(q);
          continue;
        }
        const DelaunayInserter::Result res = mi.insert(q, -1, nullptr);
        if (res.aborted)
        {
          full = true; // the pool is exhausted
          rest.push_back(q);
        }
        else if (res.duplicateOf >= 0)
          inputToVertex[order[q]] = order[res.duplicateOf];
      }
      full = full || ws[i]->poolFull;
    }
    progress->report(static_cast<double>(b) / static_cast<double>(m), "Inserting points");
    if (progress->cancelled())
      return Status::failure(ErrorKind::Cancelled, "Delaunay tetrahedralization cancelled.");
  }
  for (; r + 1 < roundStarts.size(); ++r)
    for (int32_t q = static_cast<int32_t>(roundStarts[r]); q < static_cast<int32_t>(roundStarts[r + 1]); ++q)
      if (!isFirstTet(q))
        rest.push_back(q);
  // Close the pool: drop its unused tail, free the recycled slots, report the ghost counts.
  ws.push_back(&mi);
  int32_t end = std::min(nextSlot.load(), pool);
  for (DelaunayInserter::Impl* w : ws)
    end = std::min(end, w->poolEnd);
  mesh.truncate(end);
  for (DelaunayInserter::Impl* w : ws)
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
  ws.pop_back();
  mi.last = ws[0]->last < mesh.tetCapacity() ? ws[0]->last : -1;
  for (DelaunayInserter::Impl* w : ws)
  {
    rep.walkSteps += w->walkSteps;
    rep.cavityTets += w->cavityTets;
  }
  return Status::success();
}

} // namespace volgrid
