// tests/cli/cli_run.hpp -- running the built `hapstab` command from a test (HAPSTAB_CLI is its
// path, set by tests/CMakeLists.txt): exit code and stdout+stderr together.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace hapstab_test {

struct CliRun {
  int code;
  std::string out;
};

/// `env`: assignments put before the command, e.g. "HAPSTAB_DATA_DIR=/tmp/x".
inline CliRun run_cli(const std::string& args, const std::string& env = "") {
  const std::string cmd = (env.empty() ? "" : env + " ") + std::string(HAPSTAB_CLI) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, ""};
  std::string out;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int st = pclose(p);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

}  // namespace hapstab_test
