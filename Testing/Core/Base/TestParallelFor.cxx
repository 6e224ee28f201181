// The one thread pool of Core (Core/ParallelFor.h): the thread count rule, ranges that cover the work
// exactly once whatever the thread count (more threads than cores included), nested calls, exceptions.
#include "ParallelFor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace volgrid;

TEST(ParallelFor, ThreadCountRule)
{
  EXPECT_EQ(resolveThreads(1), 1);
  EXPECT_EQ(resolveThreads(8), 8);
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(resolveThreads(0), cores);
  EXPECT_EQ(resolveThreads(-3), cores);
}

TEST(ParallelFor, RangesCoverEveryItemOnceForAnyThreadCount)
{
  const int64_t n = 100003;
  for (int threads : { 0, 1, 2, 3, 8, 17 })
  {
    std::vector<int> hits(static_cast<size_t>(n), 0);
    std::vector<int64_t> begins(64, -1);
    const int k = parallelFor(threads, n, 1000,
                              [&](int range, int64_t begin, int64_t end)
                              {
                                begins[static_cast<size_t>(range)] = begin;
                                for (int64_t i = begin; i < end; ++i)
                                  ++hits[static_cast<size_t>(i)];
                              });
    EXPECT_EQ(k, parallelRanges(threads, n, 1000));
    EXPECT_EQ(k, std::min<int64_t>(resolveThreads(threads), n / 1000));
    for (int64_t i = 0; i < n; ++i)
      ASSERT_EQ(hits[static_cast<size_t>(i)], 1) << "threads " << threads << " item " << i;
    for (int r = 0; r < k; ++r)
      EXPECT_EQ(begins[static_cast<size_t>(r)], n * r / k);
  }
  // Small work: one range.
  EXPECT_EQ(parallelRanges(8, 10, 1000), 1);
  EXPECT_EQ(parallelRanges(8, 0, 1000), 1);
}

TEST(ParallelFor, NestedCallsRunAndRepeatedCallsReuseThePool)
{
  std::atomic<int64_t> sum{ 0 };
  for (int repeat = 0; repeat < 50; ++repeat)
    parallelRun(4, [&](int w) { parallelRun(3, [&](int v) { sum += (w + 1) * 10 + v; }); });
  // Per outer call: sum over w of 3 * (w + 1) * 10 + (0 + 1 + 2) = 300 + 12 = 312.
  EXPECT_EQ(sum.load(), 50 * 312);
}

TEST(ParallelFor, AnExceptionReachesTheCaller)
{
  EXPECT_THROW(parallelRun(3,
                           [](int w)
                           {
                             if (w == 2)
                               throw std::runtime_error("worker 2");
                           }),
               std::runtime_error);
  // The pool still works afterwards.
  std::atomic<int> n{ 0 };
  parallelRun(3, [&](int) { ++n; });
  EXPECT_EQ(n.load(), 3);
}

// Calls in quick succession with a worker count that changes from call to call, as the candidate scoring of
// a split makes them: the workers that watch for the next call instead of sleeping must still run each
// call's body exactly once per worker, and never a worker the call did not ask for.
TEST(ParallelFor, QuickCallsOfChangingWidthRunEachWorkerOnce)
{
  constexpr int kCalls = 20000, kMost = 6;
  std::vector<std::atomic<int>> runs(static_cast<size_t>(kCalls) * kMost);
  for (int call = 0; call < kCalls; ++call)
  {
    const int workers = 1 + (call * 7919) % kMost;
    parallelRun(workers, [&](int w) { ++runs[static_cast<size_t>(call) * kMost + w]; });
  }
  int64_t wrong = 0;
  for (int call = 0; call < kCalls; ++call)
  {
    const int workers = 1 + (call * 7919) % kMost;
    for (int w = 0; w < kMost; ++w)
      wrong += runs[static_cast<size_t>(call) * kMost + w].load() != (w < workers ? 1 : 0);
  }
  EXPECT_EQ(wrong, 0);
}
