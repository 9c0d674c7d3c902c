// The figures of part "ext" (cli/figures_ext.cpp): the Z-width region's closed-form corners
// (n = 0: K_max = 2b/T at B = 0, B_max = b at K = 0), the stability limit's closed form at B = 0,
// and the passivity controller's effect; and the benchmark charts' timing line (cli/figure.hpp,
// bench_timing_vars: the machine from the Google Benchmark JSON's context, a warning when the load
// average exceeded the CPU count, "not recorded" rather than a failure without it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "cli/cli_run.hpp"
#include "cli/figure.hpp"

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("hapstab_ext_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Rows of numbers of a data file's block `index` (blocks separated by two blank lines).
std::vector<std::vector<double>> block(const fs::path& f, int index) {
  std::ifstream in(f);
  std::vector<std::vector<double>> rows;
  int blank = 0, at = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) {
      if (++blank == 2) ++at;
      continue;
    }
    blank = 0;
    if (line[0] == '#' || at != index) continue;
    std::istringstream ss(line);
    std::vector<double> r;
    for (double x; ss >> x;) r.push_back(x);
    rows.push_back(r);
  }
  return rows;
}

std::string timing_of(const hapstab::cli::GnuplotVars& v) {
  for (const auto& [k, t] : v.text)
    if (k == "timing") return t;
  return "(no timing variable)";
}

}  // namespace

TEST(ExtFigures, ZWidthRegionHasTheClosedFormCorners) {
  const fs::path d = fresh_dir("zwidth");
  const auto r = hapstab_test::run_cli("figure ext_zwidth --format png --out " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto n0 = block(d / "data" / "ext_zwidth_region.dat", 0);
  ASSERT_EQ(n0.size(), 61u);
  EXPECT_NEAR(n0.front()[0], 4000, 1e-9);  // b* = KT/2: K_max = 2b/T
  EXPECT_NEAR(n0.back()[1], 2, 1e-9);      // b* = B: B_max = b
  for (const auto& p : n0) EXPECT_NEAR(p[0] * 1e-3 / 2 + p[1], 2, 1e-9);  // the line KT/2 + B = b
  // a delay shrinks the region: n = 3 reaches less stiffness
  const auto n3 = block(d / "data" / "ext_zwidth_region.dat", 3);
  ASSERT_EQ(n3.size(), 61u);
  EXPECT_LT(n3.front()[0], n0.front()[0]);
  // the stable walls of the device with m = 0.1 kg: at B = 0, n = 0 the closed form of claim
  // ext.stability.damper_n0, K = b(1 - e)/((m/b)(1 - e) - T e) with e = exp(-bT/m), above 2b/T
  const auto s0 = block(d / "data" / "ext_zwidth_stable.dat", 0);
  ASSERT_EQ(s0.size(), 60u);  // every ray but the pure damper
  const double e = std::exp(-2 * 1e-3 / 0.1), k_stab = 2 * (1 - e) / ((0.1 / 2) * (1 - e) - 1e-3 * e);
  EXPECT_NEAR(s0.front()[0], k_stab, 1e-8 * k_stab);
  EXPECT_GT(s0.front()[0], 4000);
  EXPECT_EQ(s0.front()[1], 0);
  EXPECT_TRUE(fs::exists(d / "figures" / "ext_zwidth.png"));
  fs::remove_all(d);
}

TEST(ExtFigures, PassivityControllerFigureData) {
  const fs::path d = fresh_dir("pc");
  const auto r = hapstab_test::run_cli("figure ext_pc_wall --format png,svg --out " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto off = block(d / "data" / "ext_pc_wall_off.dat", 0), on = block(d / "data" / "ext_pc_wall_on.dat", 0);
  ASSERT_EQ(off.size(), on.size());
  ASSERT_GT(on.size(), 900u);
  double min_on = 0, min_off = 0;
  for (size_t i = 0; i < on.size(); ++i) {
    min_on = std::min(min_on, on[i][3]);
    min_off = std::min(min_off, off[i][3]);
  }
  EXPECT_LT(min_off, -1.0);  // without the PC the interface generates energy
  EXPECT_GE(min_on, 0.0);    // with it, not
  double early = 0;  // |x| over the first 0.1 s (the impulse starts at x = 0)
  for (size_t i = 0; i < 100; ++i) early = std::max(early, std::fabs(on[i][1]));
  EXPECT_LT(std::fabs(on.back()[1]), 1e-3 * early);  // decays
  // Column 5, the force the wall commands (before the PC): without the PC it is the applied force;
  // with it the applied force is 0 up to rounding at every sample where the wall commands one --
  // the PC cancels the wall, it does not chatter. (The old |u| curve drew that rounding residue,
  // ~1e-17 N, on a log axis.) The last row has no commanded force (NaN, not read here).
  size_t commanded = 0, cancelled = 0;
  for (size_t i = 0; i + 1 < on.size(); ++i) {
    ASSERT_EQ(on[i].size(), 5u) << "row " << i;
    ASSERT_EQ(off[i].size(), 5u) << "row " << i;
    EXPECT_LE(std::fabs(off[i][4] - off[i][2]), 1e-9 * std::fabs(off[i][2])) << "row " << i;
    if (on[i][4] == 0) continue;
    ++commanded;
    if (std::fabs(on[i][2]) <= 1e-12 * std::fabs(on[i][4])) ++cancelled;
  }
  EXPECT_GT(commanded, 900u);
  EXPECT_EQ(cancelled, commanded);
  EXPECT_EQ(on.back().size(), 4u);
  // the figure says so, with the count (gnuplot computes it from the data)
  std::ifstream svg(d / "figures" / "ext_pc_wall.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("at " + std::to_string(cancelled) + " of the " + std::to_string(commanded) + " samples"),
            std::string::npos);
  fs::remove_all(d);
}

TEST(ExtFigures, SimulateReportsFrictionEventsAndThePassivityController) {
  const fs::path d = fresh_dir("sim");
  const std::string src = HAPSTAB_SOURCE_DIR;
  auto r = hapstab_test::run_cli("simulate --scene " + src + "/examples/ext_friction_below.toml --json --quiet --out " +
                                 (d / "below").string());
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["friction_events"].get<long>(), 100);
  EXPECT_EQ(j["quantum"], "0.001");
  EXPECT_NE(j["method"].get<std::string>().find("Coulomb friction"), std::string::npos);
  // a scene file with the PC section
  const fs::path scene = d / "pc.toml";
  {
    std::ifstream in(src + "/examples/001_tightness_below.toml");
    std::ofstream out(scene);
    out << in.rdbuf() << "\n[passivity_controller]\ndofs = [\"haptic\"]\n";
  }
  r = hapstab_test::run_cli("simulate --scene " + scene.string() + " --json --quiet --out " + (d / "pc").string());
  ASSERT_EQ(r.code, 0) << r.out;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["trend"], "decaying");
  EXPECT_GT(j["pc_active_samples"].get<long>(), 0);
  EXPECT_GT(j["pc_dissipated"][0].get<double>(), 0.0);
  fs::remove_all(d);
}

TEST(BenchCharts, TimingLineNamesTheMachineAndWarnsWhenLoaded) {
  const fs::path d = fresh_dir("benchtiming");
  std::ofstream(d / "sim_bench.json") << R"({"context": {"date": "2026-11-25T20:23:39+00:00", "num_cpus": 2,
    "mhz_per_cpu": 2096, "load_avg": [10.9482, 10.4, 8.6]}, "benchmarks": []})";
  const std::string loaded = timing_of(hapstab::cli::bench_timing_vars("sim", d));
  EXPECT_NE(loaded.find("timed 2026-11-25 on 2 CPUs at 2096 MHz, load average 10.9"), std::string::npos) << loaded;
  EXPECT_NE(loaded.find("(loaded:"), std::string::npos) << loaded;
  std::ofstream(d / "lmi_bench.json") << R"({"context": {"date": "2026-11-25T20:23:39+00:00", "num_cpus": 8,
    "mhz_per_cpu": 3000, "load_avg": [0.5, 0.4, 0.3]}, "benchmarks": []})";
  const std::string idle = timing_of(hapstab::cli::bench_timing_vars("lmi", d));
  EXPECT_NE(idle.find("load average 0.5"), std::string::npos) << idle;
  EXPECT_EQ(idle.find("(loaded:"), std::string::npos) << idle;
  EXPECT_EQ(timing_of(hapstab::cli::bench_timing_vars("contact", d)), "timing conditions not recorded");
  std::ofstream(d / "passivity_bench.json") << "{\"context\": {\"num_cpus\": 2}}";  // no load_avg
  EXPECT_NE(timing_of(hapstab::cli::bench_timing_vars("passivity", d)).find("not recorded"), std::string::npos);
  fs::remove_all(d);
}
