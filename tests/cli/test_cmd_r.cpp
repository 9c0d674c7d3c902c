// `hapstab r`: runs the built command (HAPSTAB_CLI) and checks exit codes, messages and every
// printed digit against an independent reference: (37) T/2 csc(wT/2) e^{-j(wT+pi)/2} evaluated
// at 120 digits (a different formula from the (44)/cot route the command uses).
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "hapstab/numeric/decimal.hpp"

using namespace hapstab;

namespace {
using CmdRun = hapstab_test::CliRun;
CmdRun run_r(const std::string& args) { return hapstab_test::run_cli("r " + args); }
using M = mpfloat<120>;
}  // namespace

TEST(CmdR, FiftyDigitsMatchAnIndependentReference) {
  CmdRun r = run_r("--T 1/1000 --omega 1234.5 --digits 50 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  const rational T(1, 1000), w = parse_rational("1234.5");
  const M th = M(w * T), pi = boost::math::constants::pi<M>();
  const M mag = M(T) / 2 / sin(th / 2), phi = -(th + pi) / 2;  // (37)
  // both references are within 1e-115 of the truth; a 50-digit rounding boundary that close
  // would make the check ambiguous, which the two-sided comparison below rules out
  EXPECT_EQ(j["re"].get<std::string>(), to_decimal(exact_rational(M(mag * cos(phi))), 50));
  EXPECT_EQ(j["re"].get<std::string>(), "-0.0005");
  const std::string im = j["im"].get<std::string>();
  EXPECT_EQ(im, to_decimal(exact_rational(M(mag * sin(phi) * (1 + M(1e-110)))), 50));
  EXPECT_EQ(im, to_decimal(exact_rational(M(mag * sin(phi) * (1 - M(1e-110)))), 50));
  // 50 significant digits printed
  std::string digits;
  for (char c : im)
    if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
  while (!digits.empty() && digits.front() == '0') digits.erase(0, 1);
  EXPECT_GE(digits.size(), 45u);  // trailing zeros are stripped by to_decimal
  // series at N = 1000 (default) within its rigorous bound of (44)
  EXPECT_EQ(j["series_terms"].get<long>(), 1000);
  const rational bound = parse_rational(j["series_error_bound"].get<std::string>());
  const rational sre = parse_rational(j["series_re"].get<std::string>());
  const rational sim = parse_rational(j["series_im"].get<std::string>());
  const rational ire = parse_rational(j["im"].get<std::string>());
  // |series - r| <= bound + rounding of the printed 50 digits (relative 1e-49)
  EXPECT_LE(abs(sre - rational(-1, 2000)), bound);
  EXPECT_LE(abs(sim - ire), bound + abs(ire) * parse_rational("1e-49"));
  EXPECT_GT(bound, 0);
}

TEST(CmdR, HumanOutputAndEquivalentSpellings) {
  CmdRun a = run_r("--T 0.001 --omega 1234.5 --digits 30");
  ASSERT_EQ(a.code, 0) << a.out;
  EXPECT_NE(a.out.find("Re r = -0.0005"), std::string::npos) << a.out;
  CmdRun b = run_r("--T 1e-3 --omega 2469/2 --digits 30 --json");
  CmdRun c = run_r("--T 1/1000 --omega 1234.5 --digits 30 --json");
  ASSERT_EQ(b.code, 0);
  EXPECT_EQ(nlohmann::json::parse(b.out)["im"], nlohmann::json::parse(c.out)["im"]);
}

TEST(CmdR, BadInputExits2WithAClearMessage) {
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& k : {Case{"--T 0 --omega 1", "--T"}, Case{"--T -1/1000 --omega 1", "--T"},
                        Case{"--T abc --omega 1", "--T"}, Case{"--T 1/0 --omega 1", "--T"},
                        Case{"--T 1/1000 --omega 0", "pole"}, Case{"--T 1/1000 --omega 0.0e5", "pole"},
                        Case{"--T 1/1000 --omega 1..2", "--omega"}, Case{"--T 1/1000 --omega 1 --digits 0", "--digits"},
                        Case{"--T 1/1000 --omega 1 --digits 5000", "--digits"},
                        Case{"--T 1/1000 --omega 1 --terms -3", "--terms"},
                        Case{"--T 1/1000 --omega 1 --digits x", "digits"}, Case{"--T 1/1000", "omega"}}) {
    CmdRun r = run_r(k.args);
    EXPECT_EQ(r.code, 2) << k.args << "\n" << r.out;
    EXPECT_NE(r.out.find(k.says), std::string::npos) << k.args << "\n" << r.out;
  }
  EXPECT_EQ(run_r("--help").code, 0);
}

// Issue 40: w = 1e9999 exited 3, 1e50000 and 1e99999 ran past 20 s. w T is now reduced modulo 2 pi
// with pi to as many digits as w T has (sampling/r_decimal.cpp): an answer, and the right one --
// Im r = -(T/2) cot(w T/2) at T = 1/1000, w = 1e9999 is -6.5054773000921679218e-6 (mpmath at 10100
// digits). Beyond |w T| < 10^100000 (numeric/limits.hpp) the refusal states the limit.
TEST(CmdR, HugeOmegaIsReducedOrRefusedByItsLimit) {
  CmdRun r = run_r("--T 1/1000 --omega 1e9999 --digits 20 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["im"], "-6.5054773000921679218e-06");
  for (const char* w : {"1e50000", "1e99999"}) {
    r = run_r(std::string("--T 1/1000 --omega ") + w + " --digits 20 --json");
    EXPECT_EQ(r.code, 0) << w << "\n" << r.out;
  }
  r = run_r("--T 1/1000 --omega 1e999999/1e-999999");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("is not below 10^100000"), std::string::npos) << r.out;
}

TEST(CmdR, NoErrorBoundWhenTooFewTerms) {
  // wT = 100 rad: the integral bound needs N > 100/(2 pi) ~ 15.9
  CmdRun r = run_r("--T 1 --omega 100 --terms 10 --digits 10 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["series_error_bound"].is_null());
}
