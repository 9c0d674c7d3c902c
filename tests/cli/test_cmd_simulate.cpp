// `hapstab simulate`: files, summary keys, exit codes and messages for bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;

namespace {

struct Run {
  int code;
  std::string out, err;
};
Run run(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("hapstab_sim_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = std::string(HAPSTAB_CLI) + " " + args + " >" + (dir / "o").string() + " 2>" + (dir / "e").string();
  int rc = std::system(cmd.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  return {WEXITSTATUS(rc), slurp(dir / "o"), slurp(dir / "e")};
}
std::string example(const char* name) { return std::string(HAPSTAB_SOURCE_DIR) + "/examples/" + name; }
fs::path tmp(const char* name) { return fs::temp_directory_path() / (std::string("hapstab_sim_") + name + std::to_string(::getpid())); }
std::string write_scene(const char* name, const std::string& text) {
  auto p = tmp(name);
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace

TEST(CmdSimulate, WritesSeriesScriptAndSummary) {
  const auto out = tmp("out_wall");
  auto r = run("simulate --scene " + example("002_bias_wall.toml") + " --out " + out.string() + " --json --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"diverged", "max_velocity", "energy_generated", "limit_cycle"}) EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_FALSE(j["diverged"].get<bool>());
  // the scene is built to show a limit cycle of contact and release
  ASSERT_FALSE(j["limit_cycle"].is_null()) << r.out;
  EXPECT_GT(j["limit_cycle"]["period"].get<double>(), 0);
  EXPECT_GT(j["limit_cycle"]["amplitude"].get<double>(), 0);
  EXPECT_TRUE(fs::exists(out / "samples.csv"));
  EXPECT_TRUE(fs::exists(out / "fine.csv"));
  EXPECT_TRUE(fs::exists(out / "plot.gp"));
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(out / "summary.json")), j);
  std::ifstream csv(out / "samples.csv");
  // ONE header row, `name_j [unit]`, then numbers (pandas.read_csv / readtable read it as is)
  std::string h1, row1;
  std::getline(csv, h1);
  std::getline(csv, row1);
  EXPECT_EQ(h1, "t [s],x_0 [m],v_0 [m/s],u_0 [N],fh_0 [N],E_port_0 [J],E_act_0 [J],E_po_0 [J],storage_0 [J]") << h1;
  EXPECT_EQ(row1.rfind("0,", 0), 0u) << row1;
  std::ifstream fine(out / "fine.csv");
  std::getline(fine, h1);
  std::getline(fine, row1);
  EXPECT_EQ(h1, "t [s],x_0 [m],v_0 [m/s]") << h1;
  EXPECT_NE(row1.find_first_of("0123456789"), std::string::npos) << row1;
  EXPECT_EQ(row1.find_first_of("[]"), std::string::npos) << row1;
  // plot.gp skips exactly that one row
  std::stringstream gp;
  gp << std::ifstream(out / "plot.gp").rdbuf();
  EXPECT_NE(gp.str().find("'samples.csv' skip 1 "), std::string::npos);
  EXPECT_EQ(gp.str().find("skip 2"), std::string::npos);
  // each DOF is named by its device (the scene's "display"), in one colour of the shared palette
  EXPECT_NE(gp.str().find("dof_0 = (fmt eq 'tex') ? 'display' : 'display'"), std::string::npos) << gp.str();
  EXPECT_EQ(gp.str().find("'DOF 0"), std::string::npos) << gp.str();
  EXPECT_NE(gp.str().find("set linetype 1 lc rgb '#0072B2'"), std::string::npos);
  EXPECT_NE(gp.str().find("lt 1 title dof_0"), std::string::npos);
}

TEST(CmdSimulate, TightnessBothSidesOfTheBound) {
  auto below = run("simulate --scene " + example("001_tightness_below.toml") + " --out " + tmp("below").string() + " --json --quiet");
  auto above = run("simulate --scene " + example("001_tightness_above.toml") + " --out " + tmp("above").string() + " --json --quiet");
  ASSERT_EQ(below.code, 0) << below.err;
  ASSERT_EQ(above.code, 0) << above.err;
  auto jb = nlohmann::json::parse(below.out), ja = nlohmann::json::parse(above.out);
  EXPECT_GT(jb["energy_generated"].get<double>(), 0) << below.out;
  EXPECT_EQ(ja["energy_generated"].get<double>(), 0) << above.out;
  EXPECT_FALSE(ja["diverged"].get<bool>());
}

TEST(CmdSimulate, BadInputExitsTwoWithAMessage) {
  const std::string base = "[scene]\nT = \"1/1000\"\n[[device]]\nname = \"d\"\nm = \"1\"\nb = \"1\"\n";
  struct Case {
    std::string text, needle;
  };
  const std::vector<Case> cases = {
      {base + "[[operator]]\ndofs = [\"ghost\"]\nb = \"1\"\n[simulate]\nsteps = 10\n", "ghost"},
      {base + "[environment]\ntf = [[\"1\",\"0\"],[\"0\",\"1\"]]\n[simulate]\nsteps = 10\n", "incompatible dimensions"},
      {base + "[[operator]]\ntf = \"1/(s-2)\"\n[simulate]\nsteps = 10\n", "unstable"},
      {"[scene]\nT = \"0\"\n[[device]]\nm = \"1\"\n[simulate]\nsteps = 10\n", "scene.T"},
      {base + "[simulate]\nsteps = -5\n", "simulate.steps"},
      {base + "[simulate]\nsteps = 100000000\n", "--force"},
      // issue 40: times converted to a sample index are range-checked first (a bias start of
      // 1e16 s acted from t = 0), non-finite and inverted values are refused by name, and an empty
      // [delay] is not "no delay"
      {base + "[[input]]\ntype = \"bias\"\nforce = \"1\"\nstart = \"1e16\"\n[simulate]\nsteps = 10\n", "input[0].start"},
      {base + "[[input]]\ntype = \"bias\"\nforce = \"1\"\nstart = \"1e19\"\n[simulate]\nsteps = 10\n", "input[0].start"},
      {base + "[[input]]\ntype = \"bias\"\nforce = \"1\"\nstart = \"-1\"\n[simulate]\nsteps = 10\n", "input[0].start"},
      {base + "[[input]]\ntype = \"impulse\"\nmagnitude = \"1\"\ntime = \"1e19\"\n[simulate]\nsteps = 10\n", "input[0].time"},
      {base + "[[input]]\ntype = \"profile\"\nvalues = [nan, 1.0, inf]\n[simulate]\nsteps = 10\n", "input[0].values[0]: must be a finite number"},
      {base + "[[input]]\ntype = \"profile\"\nvalues = [1.0, inf]\n[simulate]\nsteps = 10\n", "input[0].values[1]"},
      {base + "[simulate]\nsteps = 10\nsubsteps = 2\nwindow = [nan, inf]\n", "simulate.window: must be a finite number"},
      {base + "[simulate]\nsteps = 10\nsubsteps = 2\nwindow = [\"0.009\", \"0.001\"]\n", "simulate.window: reversed"},
      {base + "[simulate]\nsteps = 10\nmax_velocity = inf\n", "simulate.max_velocity"},
      {base + "[delay]\n[simulate]\nsteps = 10\n", "delay: empty"},
      {base + "[delay]\ntime = \"1e16\"\n[simulate]\nsteps = 10\n", "delay.time"},
      {base + "[delay]\nsamples = \"1e8\"\n[simulate]\nsteps = 10\n", "delay.samples"},
  };
  for (const auto& c : cases) {
    auto file = write_scene("bad.toml", c.text);
    auto r = run("simulate --scene " + file + " --out " + tmp("bad_out").string() + " --quiet");
    EXPECT_EQ(r.code, 2) << c.text << "\n" << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bad.toml"), std::string::npos) << r.err;
  }
  auto r = run("simulate --scene /nonexistent.toml --out " + tmp("x").string());
  EXPECT_EQ(r.code, 2);
}
