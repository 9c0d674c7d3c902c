// tests/cli: the bad-input catalogue. Every option of every command (read from its --help, so a
// new option without a row here fails the first test) has at least one bad value below; each
// must exit 2 with a message that names what is wrong -- never a crash, an "internal error",
// exit 3, or work done before the input is checked. Arguments go to the command as an argument
// vector (report::run_process), never through a shell.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hapstab/report/process.hpp"
#include "test_files.hpp"

namespace {

using hapstab::report::run_process;

struct Case {
  std::string command;            ///< "bound", "multidof design", ...
  std::string option;             ///< the option whose value is bad ("name" for a positional)
  std::vector<std::string> args;  ///< the whole argument list after the command
  std::string says;               ///< a fragment the message must hold
};

std::vector<std::string> words(const std::string& command) {
  std::vector<std::string> w;
  std::stringstream ss(command);
  for (std::string x; ss >> x;) w.push_back(x);
  return w;
}

hapstab::report::ProcessResult run(const std::string& command, const std::vector<std::string>& args) {
  std::vector<std::string> argv{HAPSTAB_CLI};
  for (const auto& w : words(command)) argv.push_back(w);
  argv.insert(argv.end(), args.begin(), args.end());
  hapstab::report::ProcessOptions o;
  o.time_limit = 120;
  return run_process(argv, o);
}

const std::string kWall = "K + B*(z-1)/(T*z)";
const std::string kScene = std::string(HAPSTAB_SOURCE_DIR) + "/examples/001_tightness_below.toml";
const std::string kMulti = std::string(HAPSTAB_SOURCE_DIR) + "/examples/multidof_case_ii_nominal.toml";

std::vector<Case> catalogue(const std::string& out) {
  const std::vector<std::string> rlim{"--H", "1/(z-1/2)", "--T", "1", "--gain", "1", "--rho", "1/10"};
  auto with = [](std::vector<std::string> a, std::initializer_list<std::string> more) {
    a.insert(a.end(), more);
    return a;
  };
  return {
      {"r", "--T", {"--T", "0", "--omega", "1"}, "--T"},
      {"r", "--omega", {"--T", "1", "--omega", "abc"}, "--omega"},
      // beyond the argument-reduction limit: refused at once (issue 40: 1e50000 ran past 20 s)
      {"r", "--omega", {"--T", "1/1000", "--omega", "1e100004"}, "not below 10^100000"},
      {"r", "--terms", {"--T", "1", "--omega", "1", "--terms", "-5"}, "--terms"},
      {"r", "--digits", {"--T", "1", "--omega", "1", "--digits", "0"}, "--digits"},
      {"r", "--json", {"--T", "1", "--omega", "1", "--json=maybe"}, "--json"},
      {"bound", "--H", {"--H", "1/(z-", "--T", "1/1000"}, "column 6"},
      {"bound", "--H", {"--H", std::string(300, '(') + "z" + std::string(300, ')'), "--T", "1"}, "nested deeper than 200"},
      {"bound", "--T", {"--H", "1", "--T", "-1"}, "--T"},
      {"bound", "--set", {"--H", "K", "--T", "1", "--set", "K"}, "--set 'K'"},
      {"bound", "--set", {"--H", "K", "--T", "1", "--set", "K=x"}, "--set K"},
      {"bound", "--delay", {"--H", "1", "--T", "1", "--delay", "-2"}, "--delay"},
      {"bound", "--delay", {"--H", "1", "--T", "1", "--delay", "2000000"}, "more than the limit of 1000000"},
      {"bound", "--frac-delay", {"--H", "1", "--T", "1", "--frac-delay", "x"}, "--frac-delay"},
      {"bound", "--eta", {"--H", "1", "--T", "1", "--eta", "-1"}, "--eta"},
      {"bound", "--digits", {"--H", "1", "--T", "1", "--digits", "5"}, "--digits"},
      {"bound", "--method", {"--H", "1", "--T", "1", "--method", "fastest"}, "--method"},
      {"bound", "--grid-points", {"--H", "1", "--T", "1", "--method", "grid", "--grid-points", "1"}, "--grid-points"},
      {"bound", "--explain", {"--H", "1", "--T", "1", "--explain=maybe"}, "--explain"},
      {"bound", "--allow-noncausal", {"--H", "z", "--T", "1", "--allow-noncausal=maybe"}, "--allow-noncausal"},
      {"bound", "--damping", {"--H", "1", "--T", "1", "--damping", "abc"}, "--damping"},
      {"bound", "--max", {"--H", "K", "--T", "1", "--max", "K"}, "--max K needs --damping"},
      {"bound", "--max", {"--H", "K^2", "--T", "1", "--max", "K", "--b", "1"}, "affine in K"},
      {"bound", "--quantum", {"--H", "1", "--T", "1", "--quantum", "0"}, "--quantum must be > 0"},
      {"bound", "--quantum", {"--H", "1", "--T", "1", "--quantum", "abc"}, "--quantum"},
      {"bound", "--quantum", {"--H", "1/(z-1/2)", "--T", "1", "--quantum", "1/1000"}, "FIR walls only"},
      {"bound", "--coulomb", {"--H", "1", "--T", "1", "--quantum", "1", "--coulomb", "-1"}, "--coulomb must be >= 0"},
      {"bound", "--coulomb", {"--H", "1", "--T", "1", "--coulomb", "1"}, "--coulomb needs --quantum"},
      {"bound", "--json", {"--H", "1", "--T", "1", "--json=maybe"}, "--json"},
      {"bound", "--curve", {"--H", "1", "--T", "1", "--curve", "/nonexistent-dir/x.dat"}, "--curve"},
      {"bound", "--batch", {"--batch", "/nonexistent.txt"}, "--batch"},
      {"bound", "--num", {"--num", "1 x", "--den", "1", "--T", "1"}, "--num: coefficient 2"},
      {"bound", "--den", {"--num", "1", "--den", "0 1", "--T", "1"}, "--den: the leading coefficient"},
      {"bound", "--mat", {"--mat", "/nonexistent.mat:G", "--T", "1"}, "--mat /nonexistent.mat"},
      {"stability", "--plant", {"--plant", "1/(s", "--H", "1", "--T", "1"}, "--plant: expression"},
      {"stability", "--plant", {"--plant", "s", "--H", "1", "--T", "1"}, "not strictly proper"},
      {"stability", "--H", {"--plant", "1/s^2", "--H", "z^3", "--T", "1"}, "not causal"},
      {"stability", "--T", {"--plant", "1/s^2", "--H", "1", "--T", "0"}, "--T"},
      {"stability", "--delay", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--delay", "-1"}, "--delay"},
      {"stability", "--delay", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--delay", "2000000"}, "--delay"},
      {"stability", "--scene", {"--scene", "/nonexistent/scene.toml"}, "--scene"},
      {"stability", "--operator", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--operator", "q"}, "--operator"},
      {"stability", "--set", {"--plant", "1/s^2", "--H", "K", "--T", "1", "--set", "K"}, "--set 'K'"},
      {"stability", "--max", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--max", "K"}, "does not depend on K"},
      {"stability", "--conservatism", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--conservatism"}, "--conservatism compares"},
      {"stability", "--max", {"--plant", "1/(m*s^2)", "--H", "1", "--T", "1", "--max", "m"}, "appears in --plant"},
      {"stability", "--scene", {"--scene", "no/such/scene.toml"}, "no/such/scene.toml"},
      {"stability", "--scene", {"--scene", std::string(HAPSTAB_SOURCE_DIR) + "/tests/cli/scenes/hidden_env.toml", "--H", "1"}, "--scene replaces --plant, --H"},
      {"stability", "--scene", {"--scene", std::string(HAPSTAB_SOURCE_DIR) + "/tests/scene/data/bias_wall_contacts.toml"}, "unknown section [contacts]"},
      {"stability", "--scene", {"--scene", std::string(HAPSTAB_SOURCE_DIR) + "/examples/002_bias_wall.toml"}, "stability does not model [contact]"},
      {"stability", "--max", {"--plant", "1/s^2", "--H", "1/(1+K*z)", "--T", "1", "--max", "K"}, "affine"},
      {"stability", "--digits", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--digits", "0"}, "--digits"},
      {"stability", "--json", {"--plant", "1/s^2", "--H", "1", "--T", "1", "--json=maybe"}, "--json"},
      {"wedge", "--H", {"--H", "1/(", "--T", "1"}, "--H"},
      {"wedge", "--num", {"--num", "[1", "--den", "1"}, "--num: '['"},
      {"wedge", "--den", {"--num", "1", "--den", "[]"}, "--den: no coefficients"},
      {"wedge", "--mat", {"--mat", "/nonexistent.mat"}, "--mat /nonexistent.mat"},
      {"wedge", "--T", {"--H", "1", "--T", "x"}, "--T"},
      {"wedge", "--set", {"--H", "K", "--T", "1", "--set", "=3"}, "--set"},
      {"wedge", "--digits", {"--H", "1", "--T", "1", "--digits", "100"}, "--digits"},
      {"wedge", "--json", {"--H", "1", "--T", "1", "--json=maybe"}, "--json"},
      {"passivity-level", "--H", {"--H", "z+", "--T", "1"}, "column 3"},
      {"passivity-level", "--T", {"--H", "1", "--T", "0"}, "--T"},
      {"passivity-level", "--set", {"--H", "K", "--T", "1", "--set", "K=abc"}, "--set K"},
      {"passivity-level", "--ss", {"--ss", "/nonexistent.json"}, "--ss"},
      {"passivity-level", "--num", {"--num", "1", "--T", "1"}, "--num needs --den"},
      {"passivity-level", "--den", {"--den", "1", "--T", "1"}, "--den needs --num"},
      {"passivity-level", "--mat", {"--mat", "/nonexistent.mat", "--T", "1"}, "--mat /nonexistent.mat"},
      {"passivity-level", "--kind", {"--H", "1", "--T", "1", "--kind", "wrong"}, "--kind"},
      {"passivity-level", "--backend", {"--H", "1", "--T", "1", "--backend", "magic"}, "--backend"},
      {"passivity-level", "--lemma", {"--H", "1", "--T", "1", "--lemma", "3"}, "--lemma"},
      {"passivity-level", "--grid", {"--H", "1", "--T", "1", "--grid", "1"}, "--grid"},
      {"passivity-level", "--digits", {"--H", "1", "--T", "1", "--digits", "5"}, "--digits"},
      {"passivity-level", "--json", {"--H", "1", "--T", "1", "--json=maybe"}, "--json"},
      {"limit-cycle", "--H", {"--H", "(", "--T", "1", "--gain", "1", "--rho", "1"}, "--H"},
      {"limit-cycle", "--T", {"--H", "1/(z-1/2)", "--T", "-1", "--gain", "1", "--rho", "1"}, "--T"},
      {"limit-cycle", "--gain", {"--H", "1/(z-1/2)", "--T", "1", "--gain", "abc", "--rho", "1"}, "--gain"},
      {"limit-cycle", "--rho", {"--H", "1/(z-1/2)", "--T", "1", "--gain", "1", "--rho", "x"}, "--rho"},
      {"limit-cycle", "--steps", with(rlim, {"--steps", "-1"}), "--steps"},
      {"limit-cycle", "--num", {"--num", "1/0", "--den", "1", "--T", "1", "--gain", "1", "--rho", "1"}, "--num"},
      {"limit-cycle", "--den", {"--num", "1", "--den", "1 2 x", "--T", "1", "--gain", "1", "--rho", "1"}, "--den"},
      {"limit-cycle", "--mat", {"--mat", "/nonexistent.mat", "--T", "1", "--gain", "1", "--rho", "1"}, "--mat"},
      {"limit-cycle", "--set", with(rlim, {"--set", "K"}), "--set"},
      {"limit-cycle", "--exact", with(rlim, {"--exact=maybe"}), "--exact"},
      {"limit-cycle", "--json", with(rlim, {"--json=maybe"}), "--json"},
      {"simulate", "--scene", {"--scene", "/nonexistent.toml", "--out", out}, "the scene file: "},
      {"simulate", "--out", {"--scene", kScene, "--out", "/proc/nope"}, "--out"},
      {"simulate", "--json", {"--scene", kScene, "--out", out, "--json=maybe"}, "--json"},
      {"simulate", "--quiet", {"--scene", kScene, "--out", out, "--quiet=maybe"}, "--quiet"},
      {"simulate", "--force", {"--scene", kScene, "--out", out, "--force=maybe"}, "--force"},
      {"simulate", "--max-output", {"--scene", kScene, "--out", out, "--max-output", "abc"}, "--max-output"},
      // a NaN, infinite or negative limit disabled the check (issue 40)
      {"simulate", "--max-output", {"--scene", kScene, "--out", out, "--max-output", "nan"}, "--max-output"},
      {"simulate", "--max-output", {"--scene", kScene, "--out", out, "--max-output", "inf"}, "--max-output"},
      {"simulate", "--max-output", {"--scene", kScene, "--out", out, "--max-output", "-1"}, "--max-output"},
      {"simulate", "--set", {"--scene", kScene, "--out", out, "--set", "nope=1"}, "parameters.nope"},
      {"simulate", "--format", {"--scene", kScene, "--out", out, "--format", "xls"}, "--format"},
      {"plot", "name", {"polar", "--H", "1", "--T", "1", "--out", out}, "expected nyquist or bode"},
      {"plot", "--H", {"bode", "--H", "1/(z", "--T", "1", "--out", out}, "--H"},
      {"plot", "--num", {"bode", "--num", "a", "--den", "1", "--T", "1", "--out", out}, "--num"},
      {"plot", "--den", {"bode", "--num", "1", "--den", "0", "--T", "1", "--out", out}, "--den"},
      {"plot", "--mat", {"bode", "--mat", "/nonexistent.mat", "--T", "1", "--out", out}, "--mat"},
      {"plot", "--T", {"bode", "--H", "1", "--T", "0", "--out", out}, "--T"},
      {"plot", "--set", {"bode", "--H", "K", "--T", "1", "--set", "K", "--out", out}, "--set"},
      {"plot", "--delay", {"bode", "--H", "1", "--T", "1", "--delay", "-1", "--out", out}, "--delay"},
      {"plot", "--out", {"bode", "--H", "1", "--T", "1", "--out", "/proc/nope"}, "--out"},
      {"plot", "--format", {"bode", "--H", "1", "--T", "1", "--out", out, "--format", "gif"}, "--format"},
      {"plot", "--name", {"bode", "--H", "1", "--T", "1", "--out", out, "--name", "../x"}, "--name"},
      {"plot", "--digits", {"bode", "--H", "1", "--T", "1", "--out", out, "--digits", "3"}, "--digits"},
      {"plot", "--wedge", {"bode", "--H", "1", "--T", "1", "--out", out, "--wedge"}, "--wedge"},
      {"plot", "--json", {"bode", "--H", "1", "--T", "1", "--out", out, "--json=maybe"}, "--json"},
      {"proofs", "--only", {"--only", "999"}, "--only"},
      {"proofs", "--out", {"--out", "/proc/nope/x"}, "--out"},
      {"proofs", "--quiet", {"--quiet=maybe"}, "--quiet"},
      {"proofs", "--json", {"--json=maybe"}, "--json"},
      {"proofs", "--table", {"--table", "/nonexistent.md"}, "--table"},
      {"proofs", "--print-table", {"--print-table=maybe"}, "--print-table"},
      {"reproduce", "--out", {"--out", "/proc/nope", "--only", "toolbox"}, "--out"},
      {"reproduce", "--only", {"--out", out, "--only", "999"}, "--only"},
      {"reproduce", "--format", {"--out", out, "--format", "gif"}, "--format"},
      {"reproduce", "--quiet", {"--out", out, "--quiet=maybe"}, "--quiet"},
      {"figure", "name", {"nosuchfigure", "--out", out}, "unknown figure"},
      {"figure", "name", {"../../escape", "--out", out}, "unknown figure"},
      {"figure", "--out", {"sim_tightness", "--out", "/proc/nope"}, "--out"},
      {"figure", "--format", {"sim_tightness", "--out", out, "--format", "gif"}, "--format"},
      {"figure", "--list", {"--list=maybe"}, "--list"},
      {"multidof analyze", "--scene", {"--scene", "/nonexistent.toml"}, "the scene file: "},
      {"multidof analyze", "--scene", {"--scene", "/dev/zero"}, "is not a regular file"},  // never read: a device, not a scene
      {"multidof analyze", "--backend", {"--scene", kMulti, "--backend", "magic"}, "--backend"},
      {"multidof analyze", "--set", {"--scene", kMulti, "--set", "nope=1"}, "parameters.nope"},
      {"multidof analyze", "--json", {"--scene", kMulti, "--json=maybe"}, "--json"},
      {"multidof design", "--scene", {"--scene", "/nonexistent.toml"}, "the scene file: "},
      {"multidof design", "--backend", {"--scene", kMulti, "--backend", "magic"}, "--backend"},
      {"multidof design", "--set", {"--scene", kMulti, "--set", "nope=1"}, "parameters.nope"},
      {"multidof design", "--json", {"--scene", kMulti, "--json=maybe"}, "--json"},
      {"multidof design", "--duration", {"--scene", kMulti, "--duration", "-1"}, "--duration"},
      {"multidof design", "--iterations", {"--scene", kMulti, "--iterations", "0"}, "--iterations"},
  };
}

const char* const kCommands[] = {"r",           "bound",    "wedge",     "passivity-level", "limit-cycle",    "simulate",
                                 "proofs",      "reproduce", "figure",   "multidof analyze", "multidof design", "plot",
                                 "stability"};

TEST(BadInput, EveryOptionOfEveryCommandHasACase) {
  const auto cases = catalogue("unused");
  std::set<std::pair<std::string, std::string>> covered;
  for (const auto& c : cases) covered.insert({c.command, c.option});
  const std::regex option(R"(^\s+(?:-[a-zA-Z], ?)?(--[A-Za-z][A-Za-z-]*))");
  for (const std::string command : kCommands) {
    const auto help = run(command, {"--help"});
    ASSERT_EQ(help.exit_code, 0) << command << ": " << help.err;
    std::stringstream lines(help.out);
    int options = 0;
    for (std::string line; std::getline(lines, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, option) || m[1] == "--help") continue;
      ++options;
      EXPECT_TRUE(covered.count({command, m[1]})) << "hapstab " << command << " " << m[1] << " has no bad-input case";
    }
    EXPECT_GT(options, 0) << command << ": no option read from --help";
  }
  // a positional argument is in the catalogue too
  EXPECT_TRUE(covered.count({"figure", "name"}));
}

TEST(BadInput, EachCaseExitsTwoAndSaysWhat) {
  const auto dir = hapstab_test::fresh_dir("bad_input");
  const auto out = (dir / "out").string();
  for (const auto& c : catalogue(out)) {
    const auto r = run(c.command, c.args);
    const std::string all = r.out + r.err;
    EXPECT_EQ(r.exit_code, 2) << "hapstab " << c.command << " (" << c.option << "): " << r.describe() << "\n" << all;
    EXPECT_NE(all.find(c.says), std::string::npos) << "hapstab " << c.command << " (" << c.option << ") did not say '"
                                                    << c.says << "':\n" << all.substr(0, 600);
    EXPECT_EQ(all.find("internal error"), std::string::npos) << all;
    // every error, CLI11's parse errors included, is one line starting "hapstab: error: " (issue 31)
    EXPECT_EQ(r.err.rfind("hapstab: error: ", 0), 0u) << "hapstab " << c.command << " (" << c.option << "):\n" << r.err;
  }
  std::filesystem::remove_all(dir);
}

// A word where a command belongs is named, with the nearest command (issue 31: these printed
// "A subcommand is required / Run with --help" without naming the word).
TEST(BadInput, UnknownCommandIsNamedWithTheNearestOne) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"boundd"}, "hapstab: error: unknown command 'boundd'; did you mean 'bound'?\n"},
      {{"stabilty", "--max", "K"}, "hapstab: error: unknown command 'stabilty'; did you mean 'stability'?\n"},
      {{"figures", "--list"}, "hapstab: error: unknown command 'figures'; did you mean 'figure'?\n"},
      {{"limit"}, "hapstab: error: unknown command 'limit'; did you mean 'limit-cycle'?\n"},
      {{"multidof", "analyse", "--scene", "x.toml"},
       "hapstab: error: unknown command 'analyse' of 'multidof'; did you mean 'analyze'?\n"},
  };
  for (const auto& [args, says] : cases) {
    std::vector<std::string> argv{HAPSTAB_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto r = run_process(argv);
    EXPECT_EQ(r.exit_code, 2) << args[0];
    EXPECT_EQ(r.err, says);
    EXPECT_EQ(r.out, "");
  }
  // nothing near: the commands are listed; no command at all: which ones there are
  auto r = run_process({HAPSTAB_CLI, "xyzzy"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("hapstab: error: unknown command 'xyzzy' (commands: r, bound, wedge, limit-cycle, "
                        "passivity-level, multidof, ", 0), 0u) << r.err;
  r = run_process({HAPSTAB_CLI});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("hapstab: error: hapstab needs a command: r, bound, ", 0), 0u) << r.err;
  r = run_process({HAPSTAB_CLI, "multidof"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("hapstab: error: hapstab multidof needs a command: analyze, design ", 0), 0u) << r.err;
  // an unknown option of a known command: named, with the nearest option of that command (or
  // where to find them), as commands and scene keys are
  r = run_process({HAPSTAB_CLI, "bound", "--bogus"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "hapstab: error: unknown option '--bogus' of 'hapstab bound' (hapstab bound --help lists its options)\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> options{
      {{"bound", "--H", "1", "--T", "1", "--dealy", "3"}, "unknown option '--dealy' of 'hapstab bound'; did you mean '--delay'?"},
      {{"stability", "--digitz=3"}, "unknown option '--digitz' of 'hapstab stability'; did you mean '--digits'?"},
      {{"sweep", "plot", "d", "--x", "K", "--z", "b", "--levles", "3"},
       "unknown option '--levles' of 'hapstab sweep plot'; did you mean '--levels'?"}};
  for (const auto& [args, says] : options) {
    std::vector<std::string> argv{HAPSTAB_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    r = run_process(argv);
    EXPECT_EQ(r.exit_code, 2) << args[0];
    EXPECT_EQ(r.err, "hapstab: error: " + says + "\n");
  }
}

// `hapstab --help` lists the papers' commands first (001, 002, 000), then the tools, then the
// reproduction, each group under its heading.
TEST(BadInput, HelpListsTheCommandsInTheirGroups) {
  const auto r = run_process({HAPSTAB_CLI, "--help"});
  ASSERT_EQ(r.exit_code, 0);
  size_t at = 0;
  for (const char* word : {"Paper 001", "  r ", "  bound ", "Paper 002", "  wedge ", "  limit-cycle ", "Paper 000",
                           "  passivity-level ", "  multidof ", "Tools", "  stability ", "  simulate ", "  plot ",
                           "  sweep ", "Reproduction", "  proofs ", "  figure ", "  reproduce "}) {
    const size_t next = r.out.find(word, at);
    ASSERT_NE(next, std::string::npos) << "'" << word << "' not after position " << at << " in\n" << r.out;
    at = next + 1;
  }
}

}  // namespace
