// Progress on stderr (issue 48 item 3, cli/progress.hpp): `multidof analyze|design` and the
// multi-DOF `stability --scene --max` name each stage as it starts and end with each stage's
// share; --quiet silences it. The 2 s after which a run prints are HAPSTAB_PROGRESS_AFTER = 0
// here, so that what is printed does not depend on how fast the machine is.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "cli/cli_run.hpp"

using hapstab_test::run_cli;

namespace {

const std::string kEx = std::string(HAPSTAB_SOURCE_DIR) + "/examples/";
const std::string kNow = "HAPSTAB_PROGRESS_AFTER=0";

// The shares of the final line "COMMAND: done in X s: stage a N%, stage b M%, ..." (-1: no such line).
int shares_total(const std::string& out, const std::string& command) {
  const size_t at = out.find(command + ": done in ");
  if (at == std::string::npos) return -1;
  const std::string line = out.substr(at, out.find('\n', at) - at);
  int total = 0;
  const std::regex pct(R"((\d+)%)");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), pct); it != std::sregex_iterator(); ++it)
    total += std::stoi((*it)[1]);
  return total;
}

void expect_lines(const std::string& out, const std::vector<std::string>& lines) {
  size_t from = 0;
  for (const auto& l : lines) {
    const size_t at = out.find(l, from);
    EXPECT_NE(at, std::string::npos) << "missing, or out of order: " << l << "\n" << out;
    if (at != std::string::npos) from = at;
  }
}

}  // namespace

TEST(Progress, MultidofAnalyzeNamesEachStageAndItsShare) {
  const std::string args = "multidof analyze --scene " + kEx + "multidof_case_ii_nominal.toml";
  const auto r = run_cli(args, kNow);
  expect_lines(r.out, {"multidof analyze: [1/5] reading the scene ... (from ",
                       "multidof analyze: [2/5] realising the blocks (E reduced, hidden modes) ... (from ",
                       "multidof analyze: [3/5] Theorem 5's LMIs (16) and their certificate ... (from ",
                       "multidof analyze: [4/5] Assumption 1 and the hidden modes ... (from ",
                       "multidof analyze: [5/5] the loop as written (closed-loop decision) ... (from ",
                       "multidof analyze: done in "});
  const int total = shares_total(r.out, "multidof analyze");
  EXPECT_GE(total, 96) << r.out;  // five rounded shares of the whole
  EXPECT_LE(total, 104) << r.out;
  // --quiet: nothing on stderr, the same exit and the JSON alone on stdout
  const auto q = run_cli(args + " --quiet --json", kNow);
  EXPECT_EQ(q.code, r.code) << q.out;
  EXPECT_EQ(q.out.find("multidof analyze:"), std::string::npos) << q.out;
  EXPECT_TRUE(nlohmann::json::accept(q.out)) << q.out;
}

TEST(Progress, MultidofDesignNamesEachStage) {
  const auto r = run_cli("multidof design --scene " + kEx + "multidof_case_ii_nominal.toml", kNow);
  expect_lines(r.out, {"multidof design: [1/6] reading the scene", "multidof design: [2/6] realising the blocks",
                       "multidof design: [3/6] Theorem 6's design (CCL) and its verification",
                       "multidof design: [4/6] Assumption 1 and the hidden modes",
                       "multidof design: [5/6] the loop with the designed V (closed-loop decision)",
                       "multidof design: [6/6] the simulated cross-check", "multidof design: done in "});
  const auto q = run_cli("multidof design --quiet --scene " + kEx + "multidof_case_ii_nominal.toml", kNow);
  EXPECT_EQ(q.code, r.code);
  EXPECT_EQ(q.out.find("multidof design:"), std::string::npos) << q.out;
}

TEST(Progress, StabilityMaxWithConservatismNamesEachStage) {
  const std::string args = "stability --scene " + kEx + "multidof_case_ii_coupling.toml --max kc --conservatism";
  const auto r = run_cli(args, kNow);
  expect_lines(r.out, {"stability --max: [1/4] reading the scene", "stability --max: [2/4] Theorem 5's largest kc",
                       "stability --max: [3/4] the closed loop's dependence on kc",
                       "stability --max: [4/4] the supremum: bisection on certified verdicts", "stability --max: done in "});
  const auto q = run_cli(args + " --quiet --json", kNow);
  EXPECT_EQ(q.code, r.code);
  EXPECT_TRUE(nlohmann::json::accept(q.out)) << q.out;
}
