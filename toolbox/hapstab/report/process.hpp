// hapstab/report/process.hpp -- running another program (gnuplot, a bench chart script, hapstab
// itself for an example scene) without a shell: posix_spawn with an argument vector, so no
// string -- a path under --out, a scene's name -- is ever read by /bin/sh. The child's stdin is
// /dev/null, its stdout and stderr come back through pipes, its exit status is checked, and a
// time limit stops it (docs/security.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hapstab::report {

struct ProcessOptions {
  std::filesystem::path working_dir;   ///< empty: this process's
  double time_limit = 0;               ///< seconds; 0 = none. The child is killed (SIGKILL) at the limit
  std::size_t max_output = 64u << 20;  ///< bytes kept of stdout, and of stderr; the rest is read and dropped
};

struct ProcessResult {
  int exit_code = -1;      ///< the child's exit status; -1 when it did not exit normally
  int signal = 0;          ///< the signal that ended it, 0 if none
  bool timed_out = false;  ///< stopped at ProcessOptions::time_limit
  double time_limit = 0;   ///< the limit it ran under (seconds; 0 = none)
  bool started = false;    ///< false: the program could not be run (`err` says why)
  std::string out, err;
  bool ok() const { return started && exit_code == 0; }
  /// "exit code 3", "killed by signal 11", "stopped at the time limit of 300 s", "could not be run: ...".
  std::string describe() const;
};

/// Runs argv[0] (looked up in PATH when it holds no '/') with arguments argv[1..].
ProcessResult run_process(const std::vector<std::string>& argv, const ProcessOptions& options = {});

/// run_process, and on anything but exit code 0 throws NumericalError("<what> failed (<describe>):\n"
/// + its stderr and stdout).
ProcessResult run_checked(const std::vector<std::string>& argv, const std::string& what,
                          const ProcessOptions& options = {});

}  // namespace hapstab::report
