// cli/process.hpp -- running other programs from the `hapstab` command (gnuplot, the bench/chart
// scripts, hapstab itself for the example scenes): shell quoting, captured output, this program's path.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hapstab::cli {

/// `s` single-quoted for /bin/sh.
std::string shell_quote(const std::string& s);

/// Runs the shell command `cmd` with stdout and stderr in `log`; on a non-zero exit throws
/// NumericalError("<what> failed:" + the log). The log is removed on success.
void run_logged(const std::string& cmd, const std::filesystem::path& log, const std::string& what);

/// Runs argv (quoted) with stdout captured into `out`, stderr to `errfile`; returns the exit code
/// (-1 when the program could not be run or was killed).
int run_capture(const std::vector<std::string>& argv, std::string& out, const std::filesystem::path& errfile);

/// The path of the running `hapstab` executable (/proc/self/exe).
std::filesystem::path self_exe();

}  // namespace hapstab::cli
