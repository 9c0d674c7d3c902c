// tests/cli/cli_in_process.hpp -- cli::run_in_process (cli/command.hpp) for a test: the same run,
// its JSON recorded as run_cli records a run of the binary (cli_run.hpp: dump_json_run), so that
// ctest cli_json_schema validates what the in-process tests read too.
#pragma once

#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "cli/command.hpp"

namespace hapstab_test {

inline hapstab::cli::InProcessRun run_in_process(const std::vector<std::string>& args) {
  hapstab::cli::InProcessRun r = hapstab::cli::run_in_process(args);
  dump_json_run({{"argv", args}, {"exit", r.code}, {"json", r.json}});
  return r;
}

}  // namespace hapstab_test
