// The figures of part "ext" (cli/figures_ext.cpp): the Z-width region's closed-form corners
// (n = 0: K_max = 2b/T at B = 0, B_max = b at K = 0), the stability limit's closed form at B = 0,
// and the passivity controller's effect.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "cli/cli_run.hpp"

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
  const auto r = hapstab_test::run_cli("figure ext_pc_wall --format png --out " + d.string());
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
