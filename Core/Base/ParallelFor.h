// The one place in Core that starts threads: a process-wide pool of worker threads and the parallel
// loops every threaded stage uses (the Delaunay kernel, its canonical renumbering, the surface
// intersection test, the mesh summaries of the quality stage).
//
// Thread count rule (Core, CLI and filters alike): 0 = all cores (std::thread::hardware_concurrency,
// at least 1), n > 0 = n threads, whatever the machine has (n above the core count is allowed: the
// threads then share the cores; results are the same).
//
// Determinism is the caller's part: a parallel loop's body writes per-worker or per-chunk state only,
// and the caller merges it in a fixed order, so that the result does not depend on which thread ran
// which chunk. A stage whose result depends on the number of workers says so.
//
// The pool's threads are started on first use and grow to the largest count asked for. A parallel call
// made from inside a pool worker (nesting) or while another caller holds the pool runs its workers on
// the calling thread, one after the other (same result, no deadlock): a body must never wait for
// another worker of the same call.
#pragma once

#include <cstdint>
#include <functional>

namespace volgrid
{

// The thread count rule above: requested > 0 gives requested, 0 (or less) gives the number of cores.
int resolveThreads(int requested);

// Runs body(w) for every worker w in [0, workers), each on its own thread when the pool is free
// (worker 0 on the calling thread), and returns when all have returned. workers < 1 counts as 1.
void parallelRun(int workers, const std::function<void(int worker)>& body);

// Runs body(begin, end) over [0, n) cut into `threads` (resolveThreads) contiguous ranges of nearly
// equal size, range w = [n * w / k, n * (w + 1) / k) with k ranges; one thread per range. Below
// minPerThread items per range fewer ranges are used (k >= 1). Returns k, so that a caller can size its
// per-range partials first with parallelRanges(...) below.
int parallelFor(int threads, int64_t n, int64_t minPerThread,
                const std::function<void(int range, int64_t begin, int64_t end)>& body);

// The number of ranges parallelFor(threads, n, minPerThread, ...) uses.
int parallelRanges(int threads, int64_t n, int64_t minPerThread);

} // namespace volgrid
