// hapstab/study/run.hpp -- running the points of a sweep in worker processes (the SDP libraries
// are not thread-safe), checkpointed so that a killed run continues where it stopped.
//
// Each worker is a fork()ed copy that runs its share of the pending points (position k of the
// pending list goes to worker k mod jobs) and appends one record line per point to its own file
// DIR/checkpoints/part-PID.txt, in writes of whole lines at least every 0.1 s (or 64 KiB),
// fdatasync'ed at least once a second and at the end. A kill loses at most the last 0.1 s of
// points and can only tear the last line, which the reader ignores; --resume runs the points
// without a complete line again. Point i's record depends on i only, never on jobs or shards.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "hapstab/study/table.hpp"

namespace hapstab::study {

/// Runs point `index` in the worker and returns its record {"exit", "json"} or {"exit", "error"}.
using PointRunner = std::function<nlohmann::json(uint64_t index)>;

struct RunPlan {
  std::filesystem::path dir;  ///< the sweep's output folder (checkpoints/ inside)
  PointRange range;           ///< the points of this shard
  unsigned jobs = 1;
  bool quiet = false;         ///< no progress on stderr
};

struct RunResult {
  uint64_t ran = 0;           ///< points run now (the others were checkpointed already)
  bool workers_ok = true;     ///< false: a worker died (a signal or an exit code); rerun with --resume
  std::string worker_error;   ///< what happened to it
};

/// The checkpoint files already in dir/checkpoints.
std::vector<std::filesystem::path> checkpoint_files(const std::filesystem::path& dir);

/// Runs every point of plan.range without a record in `done` (loaded from the checkpoints).
RunResult run_pending(const RunPlan& plan, const RecordStore& done, const PointRunner& run_point);

/// The number of CPUs this process may run on (sched_getaffinity; Slurm's allocation too).
unsigned available_cpus();

}  // namespace hapstab::study
