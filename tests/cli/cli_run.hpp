// tests/cli/cli_run.hpp -- running the built `hapstab` command from a test (HAPSTAB_CLI is its
// path, set by tests/CMakeLists.txt): exit code and stdout+stderr together; the JSON a run
// printed; a temp folder of the test process's own.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
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

/// The JSON `hapstab ARGS` printed; a test failure (and null) when it did not exit 0.
inline nlohmann::json json_of(const std::string& args) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.code, 0) << args << "\n" << r.out;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

/// TMP/hapstab_PREFIX_PID/NAME: a folder no other test process shares (ctest -j runs them in parallel).
inline std::filesystem::path temp_path(const std::string& prefix, const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("hapstab_" + prefix + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d / name;
}

}  // namespace hapstab_test
