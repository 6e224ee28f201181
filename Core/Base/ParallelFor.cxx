#include "ParallelFor.h"

#include <algorithm>
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
      stop_ = true;
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
      std::lock_guard<std::mutex> lock(m_);
      body_ = &body;
      workers_ = workers;
      pending_ = workers - 1;
      error_ = nullptr;
      ++generation_;
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
    std::unique_lock<std::mutex> lock(m_);
    done_.wait(lock, [this]() { return pending_ == 0; });
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
    std::unique_lock<std::mutex> lock(m_);
    for (;;)
    {
      wake_.wait(lock, [&]() { return stop_ || generation_ != seen; });
      if (stop_)
        return;
      seen = generation_;
      if (k >= workers_)
        continue;
      const std::function<void(int)>* body = body_;
      lock.unlock();
      std::exception_ptr error;
      try
      {
        (*body)(k);
      }
      catch (...)
      {
        error = std::current_exception();
      }
      lock.lock();
      if (error && !error_)
        error_ = error;
      if (--pending_ == 0)
        done_.notify_all();
    }
  }

  std::mutex callMutex_; // one caller at a time
  std::mutex m_;         // guards everything below
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  const std::function<void(int)>* body_ = nullptr;
  std::exception_ptr error_;
  int workers_ = 0;
  int pending_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
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
