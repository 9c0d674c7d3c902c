// tests/cli: `hapstab multidof analyze|design` on the Sec. VI scenes and on inconsistent
// scenes (exit 2 with a message naming the inconsistency).
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

namespace {

using hapstab_test::CliRun;
CliRun run(const std::string& args) { return hapstab_test::run_cli(args); }
std::string ex(const std::string& f) { return std::string(HAPSTAB_SOURCE_DIR) + "/examples/" + f; }
std::string read(const std::string& f) {
  std::ifstream in(f);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
std::string tmp_scene(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}
std::string replace(std::string s, const std::string& a, const std::string& b) {
  const auto p = s.find(a);
  if (p == std::string::npos) ADD_FAILURE() << "pattern not found: " << a;
  else s.replace(p, a.size(), b);
  return s;
}

}  // namespace

TEST(CmdMultidof, AnalyzeTableJson) {
  struct Case {
    const char* file;
    bool feasible;
  };
  for (const Case c : {Case{"multidof_case_i_nominal.toml", true}, Case{"multidof_case_i_perturbed.toml", false},
                       Case{"multidof_case_ii_nominal.toml", true}, Case{"multidof_case_ii_perturbed.toml", true}}) {
    const auto r = run("multidof analyze --json --scene " + ex(c.file));
    // exit 0 only when stability is concluded: the LMIs feasible AND Assumption 1 (the case-i
    // operator of Sec. VI is not passive, see below)
    const bool concluded = c.feasible && std::string(c.file).find("case_ii") != std::string::npos;
    ASSERT_EQ(r.code, concluded ? 0 : 1) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["feasible"].get<bool>(), c.feasible) << c.file;
    EXPECT_EQ(j["stability_concluded"].get<bool>(), concluded) << c.file;
    EXPECT_TRUE(j["certified"].get<bool>()) << c.file;
    for (const char* k : {"gamma", "q_v", "margin", "assumptions"}) EXPECT_TRUE(j.contains(k)) << k;
    if (c.feasible) {
      for (const auto& g : j["gamma"]) EXPECT_GE(g.get<double>(), 1.0);
      EXPECT_EQ(j["q_v"].size(), 2u);
    }
    // Assumption 1(b): the case-i operator of Sec. VI is not passive; the diagonal one is
    bool op_ok = true;
    for (const auto& a : j["assumptions"])
      if (a["name"].get<std::string>().find("operator") != std::string::npos) op_ok &= a["holds"].get<bool>();
    EXPECT_EQ(op_ok, std::string(c.file).find("case_ii") != std::string::npos) << c.file;
  }
}

TEST(CmdMultidof, DesignVerified) {
  const auto r = run("multidof design --json --scene " + ex("multidof_case_ii_perturbed.toml"));
  ASSERT_EQ(r.code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["feasible"].get<bool>());
  EXPECT_TRUE(j["certified"].get<bool>());
  for (const char* k : {"converged", "iterations", "A_V", "B_V", "C_V", "D_V", "verification"}) EXPECT_TRUE(j.contains(k)) << k;
  for (const auto& v : j["verification"]) EXPECT_EQ(v["verdict"].get<std::string>(), "pass") << v.dump();
  const auto n = run("multidof design --json --scene " + ex("multidof_case_i_perturbed.toml"));
  EXPECT_EQ(n.code, 1) << n.out;
  const auto jn = nlohmann::json::parse(n.out);
  EXPECT_TRUE(jn["convex_infeasible"].get<bool>());
  EXPECT_TRUE(jn["convex_certified"].get<bool>());
}

TEST(CmdMultidof, InconsistentScenesExit2) {
  const std::string base = read(ex("multidof_case_i_nominal.toml"));
  // coupling block sizes that do not add up
  auto r = run("multidof design --scene " + tmp_scene("md_bad_blocks.toml", replace(base, "mbar = [1, 1]", "mbar = [1, 2]")));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("do not add up"), std::string::npos) << r.out;
  // unstable environment: a negative mass makes E unstable
  r = run("multidof analyze --scene " + tmp_scene("md_unstable.toml", replace(base, "M = \"0.3\"", "M = \"-0.3\"")));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("not stable"), std::string::npos) << r.out;
  // non-square structure where a square one is required: a 2x1 perturbation of C_E
  r = run("multidof analyze --scene " +
          tmp_scene("md_nonsquare.toml", replace(base, "# perturb_C = [[\"0\", \"1\"], [\"1\", \"0\"]]  (the perturbed environment of Sec. VI)",
                                           "perturb_C = [[\"0\", \"1\"]]")));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("perturb_C"), std::string::npos) << r.out;
  // wrong number of OSP levels
  r = run("multidof analyze --scene " + tmp_scene("md_osp.toml", replace(base, "osp = [\"1.37\", \"1.37\"]", "osp = [\"1.37\"]")));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("osp"), std::string::npos) << r.out;
}
