// `hapstab passivity-level`: known levels (closed forms), the JSON keys, exit codes.
// G(z) = 1 + 1/(z - 1/2): ISP level = d - c/(1 + a) = 1 - 2/3 = 1/3 (minimum of Re G at theta = pi),
// OSP level = ISP level of 1/G = 1 - 1/(z + 1/2) -> 1 - 1/(3/2) = 1/3 (at theta = 0); derivation
// in tests/lmi/test_passivity_level.cpp.
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "hapstab/numeric/decimal.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_cmd_passivity_level {

using namespace hapstab;

namespace {
using hapstab_test::CliRun;
CliRun run(const std::string& args) { return hapstab_test::run_cli("passivity-level " + args); }
std::string write_tmp(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}
std::string read_file(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(CmdPassivityLevel, TransferFunctionIspAndOsp) {
  for (std::string kind : {"isp", "osp"}) {
    CliRun r = run("--H \"1 + 1/(z-0.5)\" --T 0.01 --kind " + kind + " --json");
    ASSERT_EQ(r.code, 0) << r.out;
    auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.contains("level") && j.contains("method") && j.contains("status") && j.contains("certified"));
    // SISO: the certified frequency path is the main result, exact here (minimiser at theta =
    // pi or 0, rational)
    EXPECT_EQ(j["level"].get<double>(), 1.0 / 3.0) << r.out;
    EXPECT_EQ(j["status"], "exact") << r.out;
    EXPECT_TRUE(j["certified"].get<bool>()) << r.out;
    // the exact level 1/3, and its bounds rounded outward (issue 40: both were 0.33333333333333333)
    EXPECT_EQ(j["exact"], "1/3") << r.out;
    EXPECT_EQ(j["lower_bound"], "0.33333333333333333") << r.out;
    EXPECT_EQ(j["upper_bound"], "0.33333333333333334") << r.out;
    EXPECT_EQ(j["value"], "0.33333333333333333");
    // LMI level: within the strict threshold + solver tolerance (1e-5, see lmi tests); its
    // certified lower bound never exceeds the true level 1/3
    EXPECT_NEAR(j["lmi"]["level"].get<double>(), 1.0 / 3.0, 1e-5) << r.out;
    EXPECT_TRUE(j["lmi"]["certified"].get<bool>()) << r.out;
    EXPECT_LE(parse_rational(j["lmi"]["lower_bound"].get<std::string>()), rational(1, 3));
    EXPECT_NEAR(j["frequency"]["level"].get<double>(), 1.0 / 3.0, 1e-13);
  }
}

// Zeros +-j on the unit circle: Re(1/G) = 3/8 wherever G != 0, Re G >= 0 = Re G(j). The strict
// Lemma 1 LMI has no solution (tight at theta = pi/2 for every delta); the certified path
// gives both levels exactly. --backend ipm keeps the run short (CSDP loops on this LMI until
// its time limit, tests/lmi/test_solve.cpp).
TEST(CmdPassivityLevel, ZerosOnTheUnitCircleCertified) {
  CliRun o = run("--H \"(z^2+1)/(z^2-1/4)\" --T 1/100 --kind osp --backend ipm --json");
  ASSERT_EQ(o.code, 0) << o.out;
  auto jo = nlohmann::json::parse(o.out);
  EXPECT_EQ(jo["status"], "exact") << o.out;
  EXPECT_EQ(jo["level"].get<double>(), 0.375);
  EXPECT_EQ(jo["lmi"]["status"], "failed") << o.out;
  // the grid misses the exact zero (theta = pi/2 is not a grid point) but flags the dip
  EXPECT_NE(jo["frequency"]["note"].get<std::string>().find("nearly singular"), std::string::npos) << o.out;
  CliRun i = run("--H \"(z^2+1)/(z^2-1/4)\" --T 1/100 --kind isp --json");
  ASSERT_EQ(i.code, 0) << i.out;
  auto ji = nlohmann::json::parse(i.out);
  EXPECT_EQ(ji["level"].get<double>(), 0.0);
  EXPECT_EQ(ji["value"], "0");
  EXPECT_NEAR(ji["theta"].get<double>(), M_PI / 2, 1e-12);
}

// G = 1/(z - 1/2): Re(1/G) = cos(theta) - 1/2 >= -3/2, but D = 0 makes (2)'s bottom-right
// block B'PB > 0, so Lemma 1 holds for no delta: -3/2 is only an upper bound, never "the level".
TEST(CmdPassivityLevel, NegativeOspFrequencyValueIsAnUpperBound) {
  CliRun r = run("--H \"1/(z-1/2)\" --T 1/100 --kind osp --backend csdp --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "upper_bound") << r.out;
  EXPECT_FALSE(j["certified"].get<bool>());
  EXPECT_TRUE(j["lower_bound"].is_null());
  EXPECT_EQ(parse_rational(j["upper_bound"].get<std::string>()), rational(-3, 2));
  EXPECT_FALSE(j["certified_frequency"]["is_level"].get<bool>());
  EXPECT_EQ(j["lmi"]["status"], "failed");
}

// G = -1 + 1/(z + 1/2) = (1/2 - z)/(z + 1/2), D = -1: Lemma 1 has a level (the LMI's, numeric, the
// printed result) and the certified frequency value beside it bounds it from above. By hand: on the
// circle Re(1/G) = -(3/4)/(5/4 - cos theta), least at theta = 0: -3. The JSON encloses the level in
// [the LMI's exactly checked lower bound, -3], and --certificate writes both (it wrote nothing before:
// "not the level here"): lo by Lemma 1 at the rounded P for G's realisation (A = -1/2), hi = -3.
TEST(CmdPassivityLevel, UpperBoundBesideTheLmiLevel) {
  CliRun r = run("--H \"-1 + 1/(z + 1/2)\" --T 1/100 --kind osp --backend csdp --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "numeric") << r.out;
  EXPECT_FALSE(j["certified_frequency"]["is_level"].get<bool>());
  EXPECT_EQ(j["upper_bound"], "-3") << r.out;
  ASSERT_TRUE(j["lower_bound"].is_string()) << r.out;
  const rational lo = parse_rational(j["lower_bound"].get<std::string>());
  EXPECT_LT(lo, rational(-3));
  EXPECT_GT(lo, rational(-301, 100));
  EXPECT_EQ(j["enclosure"][1], "-3") << r.out;
  const std::string cert = write_tmp("pl_lmi_upper.json", "");
  CliRun c = run("--H \"-1 + 1/(z + 1/2)\" --T 1/100 --kind osp --backend csdp --certificate " + cert);
  ASSERT_EQ(c.code, 0) << c.out;
  const auto k = nlohmann::json::parse(read_file(cert));
  EXPECT_EQ(k["claim"]["status"], "bounds");  // lo by Lemma 1 at P for G's realisation, hi = -3 at its witness
  EXPECT_EQ(k["claim"]["hi"], "-3");
  EXPECT_EQ(k["claim"]["lo"], j["lower_bound"].is_string() ? nlohmann::json(parse_rational(j["lower_bound"].get<std::string>()).str()) : nlohmann::json());
  EXPECT_EQ(k["evidence"]["A"], nlohmann::json::array({nlohmann::json::array({"-1/2"})}));
  EXPECT_NE(c.out.find("[exact upper bound on the level, not the level: see note]"), std::string::npos) << c.out;
}

TEST(CmdPassivityLevel, StateSpaceFileMimo) {
  // blockdiag(1 + 1/(z - 1/2), 2 + 0.5/(z + 0.3)): ISP = min(1/3, 2 - 0.5/0.7) = 1/3.
  std::string f = write_tmp("pl_mimo.json",
                            R"({"A": [[0.5, 0], [0, -0.3]], "B": [[1, 0], [0, 1]], "C": [[1, 0], [0, "1/2"]],
                                "D": [[1, 0], [0, 2]], "T": "1/100"})");
  CliRun r = run("--ss " + f + " --kind isp --backend csdp --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  // the certified frequency level is the result (exact: 1/3 at theta = pi); the LMI beside it
  EXPECT_EQ(j["status"], "exact") << r.out;
  EXPECT_EQ(j["lower_bound"], "0.33333333333333333") << r.out;  // 1/3 to 17 digits, rounded down
  EXPECT_EQ(j["upper_bound"], "0.33333333333333334") << r.out;  // and up
  EXPECT_EQ(j["exact"], "1/3") << r.out;
  EXPECT_NEAR(j["theta"].get<double>(), M_PI, 1e-12);
  EXPECT_NEAR(j["lmi"]["level"].get<double>(), 1.0 / 3.0, 1e-5);
  EXPECT_NE(j["lmi"]["method"].get<std::string>().find("CSDP"), std::string::npos);
}

// A one-input --ss is certified on the model as written, not on its doubles: G = 1 + 1/(z - 1/10)
// (1/10 has no double). By hand: Re G is least at theta = pi, 1 - 1/(11/10) = 1/11 (ISP); 1/G =
// 1 - 1/(z + 9/10), Re least at theta = 0: 1 - 1/(19/10) = 9/19 (OSP). Before, the doubles' level
// came out, and A = 1/3 printed 0.24999999999999999 "exact" for 1/4.
TEST(CmdPassivityLevel, StateSpaceFileSisoIsTheModelAsWritten) {
  std::string f = write_tmp("pl_siso_exact.json", R"({"A": [["1/10"]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"})");
  CliRun r = run("--ss " + f + " --kind isp --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "exact") << r.out;
  EXPECT_EQ(j["exact"], "1/11") << r.out;
  CliRun o = run("--ss " + f + " --kind osp --json");
  ASSERT_EQ(o.code, 0) << o.out;
  auto k = nlohmann::json::parse(o.out);
  EXPECT_EQ(k["status"], "exact") << o.out;
  EXPECT_EQ(k["exact"], "9/19") << o.out;
  std::string third = write_tmp("pl_siso_third.json", R"({"A": [["1/3"]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"})");
  CliRun t = run("--ss " + third + " --kind isp");
  EXPECT_NE(t.out.find("isp level = 0.25   [exact"), std::string::npos) << t.out;
}

// Issue 33's example: R diag(g1, g2) R^T, R = (3/5, 4/5; -4/5, 3/5) exactly as written (not its
// doubles), g1 = 1 + z^-1/2, g2 = 1 + (3/4) z^-2. ISP level exactly 1/4 at theta = pi/2 (the LMI
// alone gave 0.249999699484, numeric). The OSP level is enclosed, and the LMI's certified lower
// bound lies below the enclosure.
TEST(CmdPassivityLevel, StateSpaceFileMimoCertified) {
  std::string f = write_tmp("pl_mimo_rot.json",
                            R"({"A": [[0, 0, 0], [0, 0, 0], [0, 1, 0]],
                                "B": [["3/5", "-4/5"], ["4/5", "3/5"], [0, 0]],
                                "C": [["3/10", 0, "3/5"], ["-2/5", 0, "9/20"]],
                                "D": [[1, 0], [0, 1]], "T": "1/1000"})");
  CliRun r = run("--ss " + f + " --kind isp --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "exact") << r.out;
  EXPECT_EQ(j["value"], "0.25") << r.out;
  EXPECT_EQ(parse_rational(j["lower_bound"].get<std::string>()), rational(1, 4));
  EXPECT_EQ(parse_rational(j["upper_bound"].get<std::string>()), rational(1, 4));
  EXPECT_NEAR(j["theta"].get<double>(), M_PI / 2, 1e-12);
  ASSERT_TRUE(j["lmi"]["lower_bound"].is_string()) << r.out;
  EXPECT_LE(parse_rational(j["lmi"]["lower_bound"].get<std::string>()), rational(1, 4));
  CliRun o = run("--ss " + f + " --kind osp --json");
  ASSERT_EQ(o.code, 0) << o.out;
  auto k = nlohmann::json::parse(o.out);
  ASSERT_TRUE(k["status"] == "certified" || k["status"] == "exact") << o.out;
  const rational lo = parse_rational(k["lower_bound"].get<std::string>()),
                 hi = parse_rational(k["upper_bound"].get<std::string>());
  EXPECT_LE(lo, hi);
  EXPECT_LE(hi - lo, rational(1, 1000000000000LL));
  if (k["lmi"]["lower_bound"].is_string()) { EXPECT_LE(parse_rational(k["lmi"]["lower_bound"].get<std::string>()), hi); }
  CliRun t = run("--ss " + f + " --kind isp");
  EXPECT_NE(t.out.find("isp level = 0.25   [exact"), std::string::npos) << t.out;
}

TEST(CmdPassivityLevel, BadInputExits2) {
  EXPECT_EQ(run("--H \"1/(z-0.5)\"").code, 2);                       // no --T
  EXPECT_EQ(run("--H \"1/(z-0.5)\" --T 0.01 --kind xsp").code, 2);   // bad kind
  EXPECT_EQ(run("--ss /nonexistent/file.json").code, 2);
  EXPECT_EQ(run("--H \"z^2/(z-0.5)\" --T 0.01").code, 2);            // not causal
  CliRun circle = run("--H \"1/(z-1)\" --T 0.01");                    // pole on the unit circle
  EXPECT_EQ(circle.code, 2) << circle.out;
  EXPECT_NE(circle.out.find("unit circle"), std::string::npos) << circle.out;
  EXPECT_EQ(run("--H \"1/(z-0.5)\" --T 0.01 --digits 5").code, 2);
  std::string bad = write_tmp("pl_bad.json", R"({"A": [[0.5]], "B": [[1]], "C": [[1]], "D": [[1, 2]], "T": 0.01})");
  CliRun r = run("--ss " + bad);
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("D"), std::string::npos) << r.out;
  std::string notjson = write_tmp("pl_notjson.json", "{A: 1");
  EXPECT_EQ(run("--ss " + notjson).code, 2);
  EXPECT_EQ(run("--ss " + bad + " --H \"1\" --T 1").code, 2);  // both sources
}

}  // namespace test_cmd_passivity_level
