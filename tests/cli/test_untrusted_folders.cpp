// tests/cli: the second hardening pass (issue 32). A sweep folder, a spec and a --batch file
// received from someone else are untrusted (docs/security.md):
//   - `sweep plot DIR` runs nothing DIR holds: planted labels.gp files are never loaded (the plot
//     data goes to a private folder, names reach gnuplot as -e values); planted symbolic links
//     cannot make it write outside DIR; points.csv must be a regular file inside DIR;
//   - the files a spec's [args] or a --batch line name (--scene, --ss, --mat) must lie inside
//     that file's folder, as the files a scene names do;
//   - a TOML table header of 50,000 dotted keys (SIGSEGV inside toml++) is refused by name in
//     simulate, sweep and reproduce; absurd sizes (axes, delays, degrees, parameter chains) are
//     refused by name, exit 2, before the memory they would take is allocated.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_run.hpp"
#include "cli/command.hpp"
#include "cli/mat_fixture.hpp"
#include "cli/scenes.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using hapstab_test::run_cli;
using hapstab_test::slurp;

fs::path fresh_dir(const std::string& name) { return hapstab_test::fresh_dir("folders_" + name); }
void write(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
#else
constexpr bool sanitized = false;
#endif

// `hapstab ARGS` with its address space limited to `mb` MB (RLIMIT_AS, ulimit -v): a refusal
// that happens before the allocation it prevents passes; one that allocates first dies of
// bad_alloc (exit 3). Unlimited under AddressSanitizer, which reserves terabytes of shadow.
hapstab_test::CliRun run_limited(const std::string& args, int mb) {
  return run_cli(args, sanitized ? "" : "ulimit -v " + std::to_string(mb * 1024) + ";");
}

const std::string wall_spec =
    "command = \"bound\"\n[args]\nH = \"K + B*(z-1)/(T*z)\"\nT = \"1/1000\"\ndelay = 1\n[axes]\n"
    "K = { values = [\"0\", \"1000\"] }\nB = { values = [\"0\", \"5\"] }\n";

const std::string small_scene =
    "[scene]\nname = \"s\"\nT = \"1/1000\"\n[parameters]\nk = \"100\"\n[[device]]\nname = \"d\"\nm = \"1/10\"\nb = \"1\"\n"
    "[environment]\ntf = \"k\"\n[simulate]\nsteps = 20\n";

std::string deep_header() {
  std::string s = "[a";
  for (int i = 0; i < 50000; ++i) s += ".a";
  return s + "]\nx = 1\n";
}

}  // namespace

// The red team's finding: a received sweep folder shipping plot-data/labels.gp (read-only, or
// on a read-only mount) got its own file loaded by gnuplot, and its system(...) ran.
TEST(UntrustedFolders, SweepPlotRunsNothingTheFolderHolds) {
  const fs::path d = fresh_dir("plot");
  write(d / "s.toml", wall_spec);
  ASSERT_EQ(run_cli("sweep " + q(d / "s.toml") + " --out " + q(d / "o") + " --quiet").code, 0);
  const fs::path marker = d / "PWNED";
  const std::string payload = "system('touch " + marker.string() + "')\nxname = 'x'\nmap_plot = \"system('touch " +
                              marker.string() + "')\"\n";
  fs::create_directories(d / "o" / "plot-data");
  write(d / "o" / "plot-data" / "labels.gp", payload);
  fs::permissions(d / "o" / "plot-data" / "labels.gp", fs::perms::owner_read | fs::perms::group_read);
  // a planted link where the figure goes, pointing at a file outside
  write(d / "victim", "keep me");
  fs::create_directories(d / "o" / "figures");
  fs::create_symlink(d / "victim", d / "o" / "figures" / "sweep_map.svg");
  for (const std::string extra : {"", " --contour"}) {
    const auto r = run_cli("sweep plot " + q(d / "o") + " --x K --y B --z bound --format svg" + extra);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_FALSE(fs::exists(marker)) << "gnuplot ran the folder's labels.gp";
  }
  EXPECT_EQ(slurp(d / "victim"), "keep me");
  EXPECT_FALSE(fs::is_symlink(d / "o" / "figures" / "sweep_map.svg"));
  EXPECT_NE(slurp(d / "o" / "figures" / "sweep_map.svg").find("certified / exact"), std::string::npos);
  EXPECT_NE(slurp(d / "o" / "figures" / "sweep_contour.svg").find("bound"), std::string::npos);
  EXPECT_EQ(slurp(d / "o" / "plot-data" / "labels.gp"), payload);  // nothing written into the folder's data
  fs::permissions(d / "o" / "plot-data" / "labels.gp", fs::perms::owner_all);
  fs::remove_all(d);
}

TEST(UntrustedFolders, SweepPlotRefusesLinksOutOfTheFolder) {
  const fs::path d = fresh_dir("plot_links");
  write(d / "s.toml", wall_spec);
  ASSERT_EQ(run_cli("sweep " + q(d / "s.toml") + " --out " + q(d / "o") + " --quiet").code, 0);
  // figures/ a link to a folder outside: refused, nothing written there
  fs::create_directories(d / "outside");
  fs::create_directory_symlink(d / "outside", d / "o" / "figures");
  auto r = run_cli("sweep plot " + q(d / "o") + " --x K --y B --z bound --format svg");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("sweep plot: '" + (d / "o" / "figures").string() + "' is a symbolic link or not a folder"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(fs::is_empty(d / "outside"));
  // points.csv a link to /dev/zero, or a FIFO: refused before reading (no 2 GB read, no block)
  fs::remove(d / "o" / "figures");
  fs::rename(d / "o" / "points.csv", d / "points.csv");
  fs::create_symlink("/dev/zero", d / "o" / "points.csv");
  r = run_cli("sweep plot " + q(d / "o") + " --x K --y B --z bound");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("sweep plot: 'points.csv' leads out of"), std::string::npos) << r.out;
  fs::remove(d / "o" / "points.csv");
  ASSERT_EQ(::mkfifo((d / "o" / "points.csv").c_str(), 0600), 0);
  r = run_cli("sweep plot " + q(d / "o") + " --x K --y B --z bound");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("'points.csv' is not a regular file"), std::string::npos) << r.out;
  fs::remove_all(d);
}

// `[args] ss = "/etc/passwd"` put the file's content into points.csv; `scene = "/dev/zero"`
// exhausted memory. A spec reads only files in its own folder.
TEST(UntrustedFolders, SpecArgsReadOnlyFilesInsideTheSpecFolder) {
  const fs::path d = fresh_dir("spec_files");
  fs::create_directories(d / "spec");
  fs::create_directories(d / "elsewhere");
  write(d / "elsewhere" / "secret.json", "{\"A\": [[0]], \"B\": [[1]], \"C\": [[1]], \"D\": [[1]], \"T\": \"1\"}");
  struct Case {
    std::string command, key, value, what;
  };
  const std::vector<Case> cases = {
      {"passivity-level", "ss", "/etc/passwd", "is an absolute path"},
      {"passivity-level", "ss", "../elsewhere/secret.json", "climbs out of the scene's folder with '..'"},
      {"simulate", "scene", "/dev/zero", "is an absolute path"},
      {"multidof analyze", "scene", "../missing.toml", "climbs out"},
      {"bound", "mat", "/etc/passwd:num,den", "is an absolute path"},
  };
  for (const auto& c : cases) {
    write(d / "spec" / "s.toml", "command = \"" + c.command + "\"\n[args]\n" + c.key + " = \"" + c.value +
                                     "\"\n[axes]\nk = { values = [\"1\"] }\n");
    const auto r = run_cli("sweep " + q(d / "spec" / "s.toml") + " --out " + q(d / "o") + " --quiet");
    EXPECT_EQ(r.code, 2) << c.value << "\n" << r.out;
    EXPECT_NE(r.out.find("s.toml: args." + c.key + ": '" + c.value.substr(0, c.value.find(':'))), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(c.what), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("root:"), std::string::npos) << r.out;
    fs::remove_all(d / "o");
  }
  // a link inside the folder that leads out is refused too
  fs::create_symlink(d / "elsewhere" / "secret.json", d / "spec" / "linked.json");
  write(d / "spec" / "s.toml", "command = \"passivity-level\"\n[args]\nss = \"linked.json\"\n[axes]\nk = { values = [\"1\"] }\n");
  auto r = run_cli("sweep " + q(d / "spec" / "s.toml") + " --out " + q(d / "o") + " --quiet");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("leads out of the scene's folder"), std::string::npos) << r.out;
  // a scene in the spec's folder runs, whatever the working folder
  write(d / "spec" / "wall.toml", small_scene);
  write(d / "spec" / "s.toml", "command = \"simulate\"\n[args]\nscene = \"wall.toml\"\n[axes]\nk = { values = [\"100\", \"200\"] }\n");
  r = run_cli("sweep " + q(d / "spec" / "s.toml") + " --out " + q(d / "o2") + " --quiet");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(slurp(d / "o2" / "points.csv").find("\n1,"), std::string::npos) << slurp(d / "o2" / "points.csv");
  fs::remove_all(d);
}

// `--mat /abs/path` worked in a batch line; `bound --batch /dev/zero` read 2 GB and exited 0.
TEST(UntrustedFolders, BatchLinesReadOnlyFilesInsideTheBatchFolder) {
  const fs::path d = fresh_dir("batch_files");
  fs::create_directories(d / "b");
  fs::create_directories(d / "elsewhere");
  for (const fs::path& p : {d / "b" / "plant.mat", d / "elsewhere" / "plant.mat"})
    hapstab_test::write_mat_file(p, {hapstab_test::mat_double("num", 1, 2, {1, 0}),
                                     hapstab_test::mat_double("den", 1, 2, {1, -0.5})});
  write(d / "b" / "cases.txt", "--mat plant.mat --T 1/1000\n--mat " + (d / "elsewhere" / "plant.mat").string() +
                                   " --T 1/1000\n--mat ../elsewhere/plant.mat:num,den --T 1/1000\n");
  const auto r = run_cli("bound --batch " + q(d / "b" / "cases.txt"));
  EXPECT_EQ(r.code, 2) << r.out;
  std::vector<nlohmann::json> lines;
  std::istringstream in(r.out);
  for (std::string l; std::getline(in, l);) lines.push_back(nlohmann::json::parse(l));
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_TRUE(lines[0].contains("bound")) << lines[0];
  EXPECT_EQ(lines[1]["exit"], 2);
  EXPECT_NE(lines[1]["error"].get<std::string>().find("--batch line 2: --mat: '" + (d / "elsewhere" / "plant.mat").string() +
                                                      "' is an absolute path"),
            std::string::npos)
      << lines[1];
  EXPECT_NE(lines[2]["error"].get<std::string>().find("--batch line 3: --mat: '../elsewhere/plant.mat' climbs out"),
            std::string::npos)
      << lines[2];
  const auto z = run_cli("bound --batch /dev/zero");
  EXPECT_EQ(z.code, 2) << z.out;
  EXPECT_NE(z.out.find("--batch: '/dev/zero' is not a regular file"), std::string::npos) << z.out;
  fs::remove_all(d);
}

// Every option whose help says it reads a file is an input_file_options() entry, so that a new
// one cannot slip past the rule above; the others that mention files write them, or are the
// untrusted file itself (--batch, reserved in specs).
TEST(UntrustedFolders, EveryFileReadingOptionIsListed) {
  std::vector<std::pair<CLI::App*, hapstab::cli::Runner>> runners;
  auto app = hapstab::cli::make_app(runners);
  const auto& inputs = hapstab::cli::input_file_options();
  const std::set<std::string> not_inputs{"out", "curve", "batch", "format", "table", "datadir", "name", "python"};
  std::vector<CLI::App*> todo{app.get()};
  int seen = 0;
  while (!todo.empty()) {
    CLI::App* a = todo.back();
    todo.pop_back();
    for (CLI::App* s : a->get_subcommands([](CLI::App*) { return true; })) todo.push_back(s);
    for (const CLI::Option* o : a->get_options()) {
      if (o->get_lnames().empty()) continue;  // positional arguments name folders and specs
      const std::string name = o->get_lnames().front(), help = o->get_description();
      std::string lower = help;
      for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (lower.find("file") == std::string::npos && lower.find(".mat") == std::string::npos) continue;
      ++seen;
      const bool listed = std::find(inputs.begin(), inputs.end(), name) != inputs.end();
      EXPECT_TRUE(listed || not_inputs.count(name)) << a->get_name() << " --" << name << ": " << help;
    }
  }
  EXPECT_GE(seen, 4);
}

// A table header of 50,000 dotted keys (100 KB) crashed simulate, sweep and reproduce (SIGSEGV
// inside toml++; one such file in examples/ killed reproduce without a report).
TEST(UntrustedFolders, DeepTomlIsRefusedEverywhere) {
  const fs::path d = fresh_dir("deep");
  write(d / "deep.toml", small_scene + deep_header());
  auto r = run_cli("simulate --scene " + q(d / "deep.toml") + " --out " + q(d / "o"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("deep.toml:14: a key or table nested 5000"), std::string::npos) << r.out;
  write(d / "spec.toml", wall_spec + deep_header());
  r = run_cli("sweep " + q(d / "spec.toml") + " --out " + q(d / "o2"));
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("spec.toml:9: a key or table nested 5000"), std::string::npos) << r.out;
  // reproduce: each such scene is a failed row, the others still run; a FIFO does not block it
  fs::create_directories(d / "data" / "examples");
  fs::create_directory_symlink(fs::path(HAPSTAB_SOURCE_DIR) / "plots", d / "data" / "plots");
  fs::copy_file(d / "deep.toml", d / "data" / "examples" / "a_deep.toml");
  ASSERT_EQ(::mkfifo((d / "data" / "examples" / "b_fifo.toml").c_str(), 0600), 0);
  ::setenv("HAPSTAB_DATA_DIR", (d / "data").c_str(), 1);
  const auto runs = hapstab::cli::run_scenes("", d / "out", true);
  ::unsetenv("HAPSTAB_DATA_DIR");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_NE(runs[0].error.find("levels deep (table header"), std::string::npos) << runs[0].error;
  EXPECT_NE(runs[1].error.find("is not a regular file"), std::string::npos) << runs[1].error;
  fs::remove_all(d);
}

// Two random axes of 10^7 reached 1.5 GB before the point limit was checked; to = "1e-200000"
// parsed for more than 55 s. Both are refused before the work, in 1 GB of address space.
TEST(UntrustedFolders, SpecSizesAreRefusedBeforeTheWork) {
  const fs::path d = fresh_dir("spec_sizes");
  write(d / "axes.toml", "command = \"bound\"\n[args]\nH = \"K + B\"\nT = \"1/1000\"\n[axes]\n"
                         "K = { random = 10000000, from = \"0\", to = \"1\", seed = 1 }\n"
                         "B = { random = 10000000, from = \"0\", to = \"1\", seed = 2 }\n");
  auto r = run_limited("sweep " + q(d / "axes.toml") + " --out " + q(d / "o"), 1024);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("axes.B: the axes up to this one make 100000000000000 points, more than the limit of 10^9"),
            std::string::npos)
      << r.out;
  write(d / "tiny.toml", "command = \"bound\"\n[args]\nH = \"K\"\nT = \"1/1000\"\n[axes]\n"
                         "K = { from = \"0\", to = \"1e-200000\", points = 1000 }\n");
  r = run_limited("sweep " + q(d / "tiny.toml") + " --out " + q(d / "o2"), 1024);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("axes.K.to: '1e-200000' has 664387 bits"), std::string::npos) << r.out;
  fs::remove_all(d);
}

// [delay] samples = 2e8 allocated 7.2 GB and ended in bad_alloc (exit 3); time = "1e30" said
// "negative time step". Both are refused naming the key (delay.samples, delay.time: the scene
// reader checks before anything converts t_d / T), exit 2, in 1 GB of address space; a delay
// longer than the run (10^7 samples, 20 steps) runs in it.
TEST(UntrustedFolders, DelaysAreBoundedByName) {
  const fs::path d = fresh_dir("delay");
  for (const std::string key : {"samples", "time"}) {
    const std::string delay = key + (key == "samples" ? " = \"200000000\"" : " = \"1e30\"");
    write(d / "s.toml", small_scene + "[delay]\n" + delay + "\n");
    const auto r = run_limited("simulate --scene " + q(d / "s.toml") + " --out " + q(d / "o") + " --quiet", 1024);
    EXPECT_EQ(r.code, 2) << delay << "\n" << r.out;
    EXPECT_NE(r.out.find("delay." + key + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("sample periods, more than the limit of 10000000"), std::string::npos) << r.out;
  }
  write(d / "s.toml", small_scene + "[delay]\nsamples = \"10000000\"\n");
  const auto r = run_limited("simulate --scene " + q(d / "s.toml") + " --out " + q(d / "o") + " --quiet --json", 1024);
  EXPECT_EQ(r.code, 0) << r.out;
  fs::remove_all(d);
}

// `wedge --H "1/(2*z^9999 + 1)"` reached 5.7 GB in 30 s; only bound and stability had a degree
// limit. Now the parser applies one limit for every command.
TEST(UntrustedFolders, OneDegreeLimitForEveryCommand) {
  const std::string H = " --H '1/(2*z^9999 + 1)' --T 1/1000";
  for (const std::string cmd : {"wedge", "limit-cycle --gain 1", "passivity-level", "bound", "plot nyquist --out /nonexistent/x"}) {
    const auto r = run_limited(cmd + H, 1024);
    EXPECT_EQ(r.code, 2) << cmd << "\n" << r.out;
    EXPECT_NE(r.out.find("has degree 9999, more than the limit of 200 for a model"), std::string::npos) << cmd << "\n" << r.out;
  }
}

// 1000 chained [parameters] took 20 s (cubic); 2000 more than 50 s.
TEST(UntrustedFolders, ParameterChainsAreLinearAndCapped) {
  const fs::path d = fresh_dir("params");
  auto chain = [](int n) {
    std::string s = "[parameters]\n";
    for (int k = n - 1; k > 0; --k) s += "p" + std::to_string(k) + " = \"p" + std::to_string(k - 1) + " + 1\"\n";
    return s + "p0 = \"1\"\n";
  };
  const std::string loop = "[[device]]\nname = \"d\"\nm = \"1/10\"\nb = \"1\"\n[environment]\ntf = \"p999\"\n[simulate]\nsteps = 20\n";
  write(d / "ok.toml", "[scene]\nname = \"p\"\nT = \"1/1000\"\n" + chain(1000) + loop);
  auto r = run_cli("simulate --scene " + q(d / "ok.toml") + " --out " + q(d / "o") + " --quiet --json");
  EXPECT_EQ(r.code, 0) << r.out.substr(0, 2000);
  write(d / "many.toml", "[scene]\nname = \"p\"\nT = \"1/1000\"\n" + chain(2000) + loop);
  r = run_cli("simulate --scene " + q(d / "many.toml") + " --out " + q(d / "o") + " --quiet");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("many.toml: parameters: 2000 parameters, more than the limit of 1000"), std::string::npos) << r.out;
  fs::remove_all(d);
}
