#include "vpSSLMatchingKernelThreads.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace vpSSLMatchingKernel {
namespace {
// More workers than this would only add wake-up latency for a kernel of a few milliseconds.
constexpr unsigned int kMaxWorkers = 63;

/*
  One job at a time. Its indices are claimed from m_claim, which packs (epoch << 32 | next index): a worker that
  wakes up after its job is over fails the compare-and-swap against the new epoch, so it can never run an index
  of a finished job nor of the next one with stale arguments.
*/
class Pool
{
public:
  static Pool &instance()
  {
    static Pool pool;
    return pool;
  }

  ~Pool()
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread &t : m_workers) {
      t.join();
    }
  }

  void run(int n, unsigned int threads, TaskFn task, const void *context)
  {
    std::unique_lock<std::mutex> busy(m_callerMutex, std::try_to_lock);
    const unsigned int helpers = std::min({threads - 1, kMaxWorkers, static_cast<unsigned int>(n - 1)});
    if (!busy.owns_lock() || helpers == 0) {
      for (int i = 0; i < n; ++i) {
        task(context, i);
      }
      return;
    }
    uint32_t epoch;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      while (m_workers.size() < helpers) {
        m_workers.emplace_back([this] { workerLoop(); });
      }
      epoch = ++m_epoch;
      m_task = task;
      m_context = context;
      m_n = n;
      m_done.store(0, std::memory_order_relaxed);
      m_claim.store(static_cast<uint64_t>(epoch) << 32, std::memory_order_release);
      m_joined = 0;
      m_wanted = helpers;
    }
    m_wake.notify_all();
    work(epoch, n, task, context);
    // Only indices claimed by workers can be pending: wait for those, not for workers still asleep. Spin a little
    // (a task lasts microseconds), then sleep: an idle core lets the scheduler move a worker that was preempted
    // in the middle of its task onto it, where spinning would keep that core busy.
    for (int spin = 0; spin < 256 && m_done.load(std::memory_order_acquire) < n; ++spin) {
      std::this_thread::yield();
    }
    if (m_done.load(std::memory_order_acquire) < n) {
      std::unique_lock<std::mutex> lock(m_doneMutex);
      m_doneCv.wait(lock, [&] { return m_done.load(std::memory_order_acquire) >= n; });
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    m_wanted = 0;
  }

private:
  Pool() = default;

  void work(uint32_t epoch, int n, TaskFn task, const void *context)
  {
    uint64_t claim = m_claim.load(std::memory_order_acquire);
    for (;;) {
      if (static_cast<uint32_t>(claim >> 32) != epoch || static_cast<int>(claim & 0xffffffffu) >= n) {
        return;
      }
      if (m_claim.compare_exchange_weak(claim, claim + 1, std::memory_order_acq_rel)) {
        task(context, static_cast<int>(claim & 0xffffffffu));
        if (m_done.fetch_add(1, std::memory_order_acq_rel) + 1 == n) {
          std::lock_guard<std::mutex> lock(m_doneMutex); // no lost wake-up between the caller's test and its wait
          m_doneCv.notify_one();
        }
        claim = m_claim.load(std::memory_order_acquire);
      }
    }
  }

  void workerLoop()
  {
    uint32_t seen = 0;
    for (;;) {
      TaskFn task;
      const void *context;
      int n;
      uint32_t epoch;
      {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_wake.wait(lock, [&] { return m_stop || (m_epoch != seen && m_joined < m_wanted); });
        if (m_stop) {
          return;
        }
        seen = epoch = m_epoch;
        ++m_joined;
        task = m_task;
        context = m_context;
        n = m_n;
      }
      work(epoch, n, task, context);
    }
  }

  std::mutex m_callerMutex; // one job at a time; a second concurrent caller runs its job alone
  std::mutex m_mutex;       // guards everything below but the two atomics
  std::condition_variable m_wake;
  std::mutex m_doneMutex; // the caller sleeps on m_doneCv until the last task is done
  std::condition_variable m_doneCv;
  std::vector<std::thread> m_workers;
  bool m_stop = false;
  uint32_t m_epoch = 0;
  unsigned int m_joined = 0, m_wanted = 0;
  TaskFn m_task = nullptr;
  const void *m_context = nullptr;
  int m_n = 0;
  std::atomic<uint64_t> m_claim{0};
  std::atomic<int> m_done{0};
};
} // namespace

void parallelFor(int n, unsigned int threads, TaskFn task, const void *context)
{
  if (n <= 0) {
    return;
  }
  Pool::instance().run(n, std::max(1u, threads), task, context);
}

unsigned int hardwareThreads()
{
  return std::max(1u, std::thread::hardware_concurrency());
}
} // namespace vpSSLMatchingKernel
