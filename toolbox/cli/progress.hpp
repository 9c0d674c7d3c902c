// cli/progress.hpp -- which stage a long run is in, on stderr (issue 48 item 3), in the style of
// `reproduce`'s progress ("reproduce: [figure 3/12] ..."): for `multidof analyze|design` and the
// multi-DOF `stability --scene --max` (with --conservatism). A run that ends within 2 s prints
// nothing (so short runs, and the tests that read their stderr, are unchanged); past 2 s it
// prints the stages done so far with their times and the one running, then each stage as it
// starts, and at the end each stage's share of the whole:
//   multidof analyze: [1/4] reading the scene and realising its blocks: 9.8 s
//   multidof analyze: [2/4] Theorem 5's LMIs (16) ... (from 10.0 s)
//   multidof analyze: done in 25.1 s: reading the scene and realising its blocks 39%, Theorem 5's LMIs (16) 52%, ...
// As `reproduce` does, it prints whether or not stderr is a terminal; --quiet silences it. The
// 2 s are HAPSTAB_PROGRESS_AFTER seconds when that is set (0: from the start; the tests use it).
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hapstab::cli {

class StageProgress {
 public:
  /// `command` prefixes each line; `stages` names the stages in the order they will run (a
  /// stage() beyond them is counted on); quiet: prints nothing.
  StageProgress(std::string command, std::vector<std::string> stages, bool quiet);
  ~StageProgress();  ///< ends the last stage; prints the shares when anything was printed
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  /// The next stage starts (the previous one ends); `name` overrides the planned name.
  void stage(const std::string& name = "");
  /// The stages still to come, once the run knows which path it takes (replaces the plan's rest).
  void replan(const std::vector<std::string>& rest);
  /// Ends the last stage and, when anything was printed, prints each stage's share (once; the
  /// destructor calls it).
  void finish();
  /// Seconds to wait before printing: HAPSTAB_PROGRESS_AFTER, else 2.
  static double delay_seconds();

 private:
  using Clock = std::chrono::steady_clock;
  struct Done {
    std::string name;
    double seconds;
  };
  double since_start() const;
  std::string line(size_t k) const;  ///< "[k/n] name"
  void go_live();                    ///< prints what ran so far (the mutex held)
  void watch();

  std::string command_;
  std::vector<std::string> names_;
  std::vector<Done> done_;
  size_t current_ = 0;  ///< stages started (the running one is current_ - 1)
  Clock::time_point start_, stage_start_;
  bool quiet_ = false, live_ = false, finished_ = false;
  std::mutex mu_;
  std::condition_variable cv_;
  std::thread watcher_;
};

}  // namespace hapstab::cli
