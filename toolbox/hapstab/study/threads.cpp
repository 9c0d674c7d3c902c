// hapstab/study/threads.cpp -- see threads.hpp.
#include "hapstab/study/threads.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <flint/flint.h>

#include "hapstab/study/run.hpp"

namespace hapstab::study {

bool run_threads(uint64_t n, unsigned jobs, const std::function<void(uint64_t)>& fn, const std::function<bool()>& poll,
                 unsigned poll_ms) {
  if (n == 0) return true;
  if (jobs == 0) jobs = available_cpus();
  jobs = unsigned(std::min<uint64_t>(jobs, n));
  if (jobs <= 1) {
    auto last = std::chrono::steady_clock::now();
    for (uint64_t i = 0; i < n; ++i) {
      if (poll && std::chrono::steady_clock::now() - last >= std::chrono::milliseconds(poll_ms)) {
        if (poll()) return false;
        last = std::chrono::steady_clock::now();
      }
      fn(i);
    }
    return true;
  }
  std::atomic<uint64_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex m;
  std::condition_variable done_cv;
  unsigned running = jobs;
  std::exception_ptr error;
  auto worker = [&] {
    try {
      for (uint64_t i; !stop.load(std::memory_order_relaxed) && (i = next.fetch_add(1)) < n;) fn(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (!error) error = std::current_exception();
      stop = true;
    }
    flint_cleanup();  // FLINT's thread-local caches (fmpz, Arb constants) belong to this thread: freed with it
    std::lock_guard<std::mutex> lock(m);
    if (--running == 0) done_cv.notify_all();
  };
  std::vector<std::thread> threads;
  threads.reserve(jobs);
  for (unsigned k = 0; k < jobs; ++k) threads.emplace_back(worker);
  bool stopped = false;
  {
    std::unique_lock<std::mutex> lock(m);
    while (running > 0) {
      done_cv.wait_for(lock, std::chrono::milliseconds(poll_ms));
      if (running > 0 && poll && !stopped) {
        lock.unlock();
        const bool want = poll();
        lock.lock();
        if (want) stopped = true, stop = true;
      }
    }
  }
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return !stopped;
}

}  // namespace hapstab::study
