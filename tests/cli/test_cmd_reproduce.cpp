// tests/cli: `hapstab reproduce` judges the example scenes by their [reproduce] tables. A copy of
// the data tree (plots/ and the paper-001 scenes, HAPSTAB_DATA_DIR) gets one scene whose stated
// expectation is false: reproduce must exit 1 and the report must say which key differed;
// with the expectation corrected it exits 0. Also the expectation syntax errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& f) {
  std::ifstream in(f);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A data tree with plots/ and examples/001_*.toml, plus `extra` as examples/001_zz_check.toml
// (and each of `more` as examples/001_zz_NAME.toml).
fs::path data_tree(const std::string& name, const std::string& extra,
                   const std::vector<std::pair<std::string, std::string>>& more = {}) {
  const fs::path root = fs::path(::testing::TempDir()) / name;
  fs::remove_all(root);
  fs::create_directories(root / "examples");
  fs::copy(fs::path(HAPSTAB_SOURCE_DIR) / "plots", root / "plots");
  for (const auto& e : fs::directory_iterator(fs::path(HAPSTAB_SOURCE_DIR) / "examples"))
    if (e.path().filename().string().rfind("001_", 0) == 0) fs::copy(e.path(), root / "examples" / e.path().filename());
  std::ofstream(root / "examples" / "001_zz_check.toml") << extra;
  for (const auto& [stem, text] : more) std::ofstream(root / "examples" / ("001_zz_" + stem + ".toml")) << text;
  return root;
}

// The below-the-bound scene with its [reproduce] table replaced.
std::string below_with(const std::string& table) {
  std::string s = read(fs::path(HAPSTAB_SOURCE_DIR) / "examples" / "001_tightness_below.toml");
  s = s.substr(0, s.find("[reproduce]"));
  return s + "[reproduce]\npaper = \"001\"\nclaim = \"test\"\n" + table + "\n";
}

hapstab_test::CliRun reproduce(const fs::path& root) {
  return hapstab_test::run_cli("reproduce --only 001 --format png --quiet --out " + (root / "out").string(),
                               "HAPSTAB_DATA_DIR=" + root.string());
}

}  // namespace

TEST(CmdReproduce, SceneExpectationsDecideTheExitCode) {
  // growing and generating energy is what happens below b*: claiming it decays must fail
  const fs::path bad = data_tree("repro_bad", below_with("simulate = { trend = \"decaying\", energy_generated = \"> 1\" }"));
  auto r = reproduce(bad);
  EXPECT_EQ(r.code, 1) << r.out;
  const std::string md = read(bad / "out" / "report.md");
  EXPECT_NE(md.find("001_zz_check.toml"), std::string::npos) << md.substr(0, 2000);
  EXPECT_NE(md.find("trend is growing, expected decaying"), std::string::npos) << md.substr(0, 2000);

  const fs::path good = data_tree("repro_good", below_with("simulate = { trend = \"growing\", energy_generated = \"> 1\" }"));
  r = reproduce(good);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(read(good / "out" / "report.md").find("3 scene runs (3 as expected, 0 not)"), std::string::npos);
}

TEST(CmdReproduce, MalformedExpectationIsAFailureThatSaysWhy) {
  const fs::path root = data_tree("repro_malformed", below_with("simulate = { energy_generated = \"> lots\" }"));
  const auto r = reproduce(root);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(read(root / "out" / "report.md").find("cannot read the number in '> lots'"), std::string::npos);
}

// Strict expectations (issue 29): a misspelled key, a key the command does not print, a value
// of another type and a command without expectations each fail the scene, saying why; before,
// a missing key read as null = false, a non-boolean counted as true when non-null, and a scene
// without expectations passed on exit 0 or 1.
TEST(CmdReproduce, ExpectationsAreStrict) {
  struct Case {
    std::string name, table, why;
  };
  const std::vector<Case> cases = {
      {"typo", "simulate = { trend = \"growing\", diverged_typo = false }",
       "001_zz_typo.toml:53: unknown key reproduce.simulate.diverged_typo; did you mean reproduce.simulate.diverged?"},
      {"missing", "", "the scene states no expectation for simulate: add"},
      {"empty", "simulate = {}", "the scene states no expectation for simulate"},
      {"not_printed", "simulate = { trend = \"growing\", friction_events = \"== 0\" }",
       "friction_events: simulate does not print it"},
      {"bool_vs_string", "simulate = { trend = true }", "trend is \"growing\" (a string), expected a boolean (true)"},
      {"string_vs_bool", "simulate = { diverged = \"false\" }", "diverged is false (a boolean), expected the string 'false'"},
      {"number_vs_object", "simulate = { limit_cycle = \"> 0\" }", "limit_cycle is null, expected a number > 0"},
  };
  // one reproduce run for all of them (each scene is a row of the report), beside one that holds
  std::vector<std::pair<std::string, std::string>> scenes;
  for (const auto& c : cases) scenes.emplace_back(c.name, below_with(c.table));
  const fs::path root = data_tree("repro_strict", below_with("simulate = { limit_cycle = \"== null\", trend = \"growing\" }"), scenes);
  const auto r = reproduce(root);
  EXPECT_EQ(r.code, 1) << r.out;
  const std::string md = read(root / "out" / "report.md");
  for (const auto& c : cases) EXPECT_NE(md.find(c.why), std::string::npos) << c.name << ": " << md.substr(0, 4000);
  EXPECT_NE(md.find("10 scene runs (3 as expected, 7 not)"), std::string::npos) << md.substr(0, 4000);
}

// The Python examples are figures of the report (issue 18): each PNG an example prints is a
// figure of the section "From Python", with its PDF beside it.
TEST(CmdReproduce, PythonExamplesAreFiguresOfTheReport) {
  if (!fs::is_directory(fs::path(HAPSTAB_CLI).parent_path() / "python" / "hapstab"))
    GTEST_SKIP() << "the Python package was not built (HAPSTAB_PYTHON=OFF)";
  const fs::path root = fs::path(::testing::TempDir()) / "repro_python";
  fs::remove_all(root);
  const auto r = hapstab_test::run_cli("reproduce --only python --format png --quiet --out " + (root / "out").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("3 figures drawn, 0 failed"), std::string::npos) << r.out;
  const std::string md = read(root / "out" / "report.md");
  EXPECT_NE(md.find("## From Python"), std::string::npos) << md;
  for (const char* fig : {"python_fig2_nyquist_maps", "python_kb_map", "python_multidof_velocities"}) {
    EXPECT_NE(md.find(std::string("](figures/") + fig + ".png)"), std::string::npos) << fig;
    EXPECT_TRUE(fs::exists(root / "out" / "figures" / (std::string(fig) + ".pdf"))) << fig;
  }
  EXPECT_NE(read(root / "out" / "index.html").find("python_kb_map.pdf"), std::string::npos);
}
