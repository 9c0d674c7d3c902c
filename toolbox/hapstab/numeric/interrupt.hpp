// hapstab/numeric/interrupt.hpp -- a cooperative stop for a long library computation that its
// caller runs on a worker thread and may abandon (Python's Ctrl-C: python/core.cpp's
// run_interruptible).
//
// The caller installs a stop flag for the thread that computes (InterruptScope). The loops that
// can run long call interruption_point(), which throws Interrupted once the flag is set: every
// LMI solve and interior-point iteration (lmi/solve.cpp, lmi/ipm.cpp), every Riccati point
// (lmi/kyp.cpp), a simulation's progress calls (multidof/scene_analysis.cpp). Between two such
// points the computation runs on (an exact re-check, a Stein certificate: seconds at most on
// the sizes numeric/limits.hpp admits). Interrupted is not a std::exception, so no handler of
// the library's errors (InputError, NumericalError, std::exception) turns it into a verdict: it
// unwinds to the caller. Threads the computation starts itself do not see the flag; they finish
// their part. Without a scope (the command line) interruption_point() is one thread_local load.
#pragma once

#include <atomic>

namespace hapstab {

/// Thrown by interruption_point() when the caller asked the computation to stop.
struct Interrupted {};

namespace detail {
inline thread_local const std::atomic<bool>* interrupt_flag = nullptr;
}

/// While it lives, interruption_point() on this thread throws Interrupted once `flag` is true.
class InterruptScope {
 public:
  explicit InterruptScope(const std::atomic<bool>& flag) : previous_(detail::interrupt_flag) {
    detail::interrupt_flag = &flag;
  }
  ~InterruptScope() { detail::interrupt_flag = previous_; }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

/// Throws Interrupted when this thread's scope asks to stop; nothing otherwise.
inline void interruption_point() {
  if (detail::interrupt_flag && detail::interrupt_flag->load(std::memory_order_relaxed)) throw Interrupted{};
}

}  // namespace hapstab
