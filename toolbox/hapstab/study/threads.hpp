// hapstab/study/threads.hpp -- the points of a study over one library function, on threads of
// this process. A sweep of commands (run.hpp) runs worker processes: a command may call the SDP
// libraries, which are not thread-safe. A study over a thread-safe library function (b*, r(jw),
// the sampled loop's stability, the passivity levels, whose SDP solves lmi serialises) runs here
// instead, without a process per worker: Python's vectorised calls (hapstab.bound with
// params={"K": array}) are this.
//
// Point i is fn(i), on one of `jobs` threads, the points handed out one at a time from a shared
// counter (their costs differ by orders of magnitude: an exact point against a certified one).
// fn must turn a point's own failure into data (its record); an exception that escapes fn stops
// the run and is rethrown by run_threads. While the threads work, the calling thread calls
// `poll` every `poll_ms` milliseconds: when it returns true the run stops after the points in
// progress (Python's Ctrl-C), and run_threads returns false.
#pragma once

#include <cstdint>
#include <functional>

namespace hapstab::study {

/// Runs fn(0), ..., fn(n - 1) on `jobs` threads (0: available_cpus(), never more than n);
/// true when every point ran, false when `poll` stopped it. jobs == 1 runs on the calling thread
/// (poll between points).
bool run_threads(uint64_t n, unsigned jobs, const std::function<void(uint64_t)>& fn,
                 const std::function<bool()>& poll = {}, unsigned poll_ms = 20);

}  // namespace hapstab::study
