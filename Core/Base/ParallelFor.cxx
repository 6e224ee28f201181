#include "ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace volgrid
{

namespace
{
thread_local bool insidePool = false; // a pool worker, or a caller running its worker 0

// How long a worker that finished its part, and a caller waiting for its workers, watch for the next
// event before they sleep on a condition variable. Waking a sleeping thread costs tens of microseconds on
// a virtual machine, which is what a parallel call of small parts (the candidate scoring of a split, a
// colour class of the smoothing) takes as a whole: without the watch, such calls were slower on two threads
// than on one.
constexpr std::chrono::microseconds kWatch{ 200 };

// Spins until ready() or kWatch has passed; true when ready.
template<typename Ready>
bool watchFor(Ready&& ready)
{
  const auto until = std::chrono::steady_clock::now() + kWatch;
  for (int k = 1;; ++k)
  {
    if (ready())
      return true;
    if ((k & 63) == 0 && std::chrono::steady_clock::now() >= until)
      return false;
    std::this_thread::yield();
  }
}

// Worker k of the pool runs body(k) of each call with more than k workers (the caller runs worker 0).
class Pool
{
public:
  static Pool& instance()
  {
    static Pool pool;
    return pool;
  }

  ~Pool()
  {
    {
      std::lock_guard<std::mutex> lock(m_);
      stop_.store(true);
    }
    wake_.notify_all();
    for (std::thread& t : threads_)
      t.join();
  }

  // False when the pool cannot take the call (nested, or held by another caller).
  bool run(int workers, const std::function<void(int)>& body)
  {
    if (insidePool)
      return false;
    std::unique_lock<std::mutex> call(callMutex_, std::try_to_lock);
    if (!call.owns_lock())
      return false;
    while (static_cast<int>(threads_.size()) < workers - 1)
    {
      const int k = static_cast<int>(threads_.size()) + 1;
      threads_.emplace_back([this, k]() { loop(k); });
    }
    {
      // Published under the lock (a worker about to sleep sees the call or is woken by the notify) and
      // released by the generation (a watching worker that sees it sees the rest).
      std::lock_guard<std::mutex> lock(m_);
      body_ = &body;
      workers_ = workers;
      pending_.store(workers - 1);
      error_ = nullptr;
      generation_.store(generation_.load() + 1, std::memory_order_release);
    }
    wake_.notify_all();
    std::exception_ptr callerError;
    insidePool = true;
    try
    {
      body(0);
    }
    catch (...)
    {
      callerError = std::current_exception();
    }
    insidePool = false;
    auto finished = [this]() { return pending_.load(std::memory_order_acquire) == 0; };
    std::unique_lock<std::mutex> lock(m_, std::defer_lock);
    if (!watchFor(finished))
    {
      lock.lock();
      done_.wait(lock, finished);
    }
    else
      lock.lock(); // error_ is guarded
    body_ = nullptr;
    const std::exception_ptr error = callerError ? callerError : error_;
    lock.unlock();
    if (error)
      std::rethrow_exception(error);
    return true;
  }

private:
  void loop(int k)
  {
    insidePool = true;
    uint64_t seen = 0;
    for (;;)
    {
      auto called = [&]() { return stop_.load() || generation_.load(std::memory_order_acquire) != seen; };
      const bool watched = watchFor(called);
      // The call's generation, worker count and body together, under the lock they are published with (read
      // one by one, a worker not needed by one call could pair its generation with the next call's count).
      std::unique_lock<std::mutex> lock(m_);
      if (!watched)
        wake_.wait(lock, called);
      if (stop_.load())
        return;
      seen = generation_.load();
      const int workers = workers_;
      const std::function<void(int)>* body = body_;
      lock.unlock();
      if (k >= workers)
        continue;
      std::exception_ptr error;
      try
      {
        (*body)(k);
      }
      catch (...)
      {
        error = std::current_exception();
      }
      if (error)
      {
        std::lock_guard<std::mutex> guard(m_);
        if (!error_)
          error_ = error;
      }
      // The last worker wakes a caller that sleeps; under the lock, so that the wake-up cannot fall between
      // the caller's test and its wait.
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1)
      {
        std::lock_guard<std::mutex> guard(m_);
        done_.notify_all();
      }
    }
  }

  std::mutex callMutex_; // one caller at a time
  std::mutex m_;         // guards a call's publication (below), error_ and the condition variables' waits
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  const std::function<void(int)>* body_ = nullptr; // with workers_ and generation_: written together
  std::exception_ptr error_;
  int workers_ = 0;
  std::atomic<int> pending_{ 0 };
  std::atomic<uint64_t> generation_{ 0 };
  std::atomic<bool> stop_{ false };
};
} // namespace

int resolveThreads(int requested)
{
  if (requested > 0)
    return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallelRun(int workers, const std::function<void(int worker)>& body)
{
  if (workers <= 1)
  {
    body(0);
    return;
  }
  if (Pool::instance().run(workers, body))
    return;
  for (int w = 0; w < workers; ++w)
    body(w);
}

int parallelRanges(int threads, int64_t n, int64_t minPerThread)
{
  const int64_t perThread = std::max<int64_t>(1, minPerThread);
  const int64_t most = std::max<int64_t>(1, n / perThread);
  return static_cast<int>(std::min<int64_t>(resolveThreads(threads), most));
}

int parallelFor(int threads, int64_t n, int64_t minPerThread,
                const std::function<void(int range, int64_t begin, int64_t end)>& body)
{
  const int k = parallelRanges(threads, n, minPerThread);
  const int64_t total = std::max<int64_t>(0, n);
  parallelRun(k, [&](int w) { body(w, total * w / k, total * (w + 1) / k); });
  return k;
}

} // namespace volgrid
