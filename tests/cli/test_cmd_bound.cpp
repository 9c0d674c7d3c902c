// Tests of `hapstab bound`: JSON output against an independent 100-digit reference (direct complex
// evaluation, dense sampling and golden section -- tests/passivity/reference.hpp), the enclosure
// containing it, --batch, --explain, and bad inputs refused with exit code 2.
#include <gtest/gtest.h>

#include "cli/cli_run.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "passivity/reference.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_cmd_bound {

using namespace hapstab;
using testref::R;

namespace {

using hapstab_test::CliRun;
CliRun run(const std::string& args) { return hapstab_test::run_cli(args); }

R ref_of(const std::string& expr, const std::string& T, int n, std::map<std::string, rational> par = {},
         std::vector<double> res = {}) {
  ParseOptions o;
  o.variable = 'z';
  o.T = parse_rational(T);
  o.parameters = std::move(par);
  auto H = parse_tf(expr, o).H;
  return testref::reference(H, o.T, n, 0, res).value;
}

/// 30 requested digits: |bound - ref| <= 1e-28 |ref| (the printed value is rounded to 30 significant
/// digits, 0.5e-29 relative, and the reference is good to ~40 digits), and lo <= ref <= hi up to
/// the reference error 1e-38 relative.
void check(const std::string& args, const R& ref, const std::string& expect_cf = "") {
  CliRun r = run("bound --json --digits 30 " + args);
  ASSERT_EQ(r.code, 0) << args << "\n" << r.out;
  auto j = nlohmann::json::parse(r.out);
  R v = R(parse_rational(j["bound"].get<std::string>()));
  R lo = R(parse_rational(j["enclosure"][0].get<std::string>()));
  R hi = R(parse_rational(j["enclosure"][1].get<std::string>()));
  R scale = std::max(R(1e-300), abs(ref));
  EXPECT_LE(abs(v - ref), R("1e-28") * scale) << args << " " << j.dump() << " ref " << ref.str(35);
  EXPECT_LE(lo, ref + R("1e-38") * scale) << args;
  EXPECT_GE(hi, ref - R("1e-38") * scale) << args;
  if (!expect_cf.empty()) { EXPECT_EQ(j["closed_form"], expect_cf) << args; }
}

}  // namespace

TEST(CmdBound, CatalogueAgreesWithReference) {
  std::map<std::string, rational> KB{{"K", rational(1000)}, {"B", rational(5)}};
  check("--H 'K + B*(z-1)/(T*z)' --T 1/1000 --set K=1000 --set B=5", ref_of("K + B*(z-1)/(T*z)", "1/1000", 0, KB),
        "virtual wall (backward difference)");
  check("--H 'K + B*(z-1)/(T*z)' --T 1/1000 --set K=1000 --set B=5 --delay 1",
        ref_of("K + B*(z-1)/(T*z)", "1/1000", 1, KB), "virtual wall with delay n = 1");
  check("--H 'K + B*(z-1)/(T*z)' --T 1/1000 --set K=20000 --set B=5 --delay 1",
        ref_of("K + B*(z-1)/(T*z)", "1/1000", 1, {{"K", 20000}, {"B", 5}}), "virtual wall with delay n = 1");
  check("--H 'K + B*(z-1)/(T*z)' --T 1/1000 --set K=1000 --set B=5 --delay 3", ref_of("K + B*(z-1)/(T*z)", "1/1000", 3, KB));
  check("--H '(z-1)/(z+0.5)' --T 0.001", ref_of("(z-1)/(z+0.5)", "0.001", 0), "IIR (z-1)/(z+a)");
  check("--H '(1-z)/(z+0.5)' --T 0.001", ref_of("(1-z)/(z+0.5)", "0.001", 0), "IIR (1-z)/(z+a)");
  check("--H 'K + 2*B/T*(z-1)/(z+1)' --T 1/1000 --set K=1000 --set B=5 --delay 1",
        ref_of("K + 2*B/T*(z-1)/(z+1)", "1/1000", 1, KB), "Tustin wall with delay n = 1");
  check("--H '((z-1)/(T*z))^3' --T 1/100", ref_of("((z-1)/(T*z))^3", "1/100", 0));
  check("--H '(z-1)*(1+z^-1+z^-2+z^-3)' --T 1/1000 --delay 1", ref_of("(z-1)*(1+z^-1+z^-2+z^-3)", "1/1000", 1));
}

TEST(CmdBound, RandomAndResonances) {
  // narrow resonance, pole radius 0.9999 at angle acos(0.8)
  check("--H '(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)' --T 1/1000",
        ref_of("(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)", "1/1000", 0, {}, {std::acos(0.8)}));
  check("--H '(z^2+0.3)/((z^2-2*0.99995*0.3*z+0.99995^2)*(z^2-0.5*z+0.3)*(z+0.7))' --T 1/1000 --delay 2",
        ref_of("(z^2+0.3)/((z^2-2*0.99995*0.3*z+0.99995^2)*(z^2-0.5*z+0.3)*(z+0.7))", "1/1000", 2, {}, {std::acos(0.3)}));
  check("--H '(3*z^6-z^5+2*z^3-z+1)/((z^2-1.2*z+0.5)*(z^2+0.3*z+0.9)*(z^2-0.1*z+0.05))' --T 1/1000",
        ref_of("(3*z^6-z^5+2*z^3-z+1)/((z^2-1.2*z+0.5)*(z^2+0.3*z+0.9)*(z^2-0.1*z+0.05))", "1/1000", 0));
}

TEST(CmdBound, InfiniteAndPolesOnCircle) {
  CliRun r = run("bound --json --H '1/(z-1)' --T 1/1000");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["bound"], "inf");
  EXPECT_EQ(j["status"], "exact");
  CliRun t = run("bound --json --H '1000 + 2*5/T*(z-1)/(z+1)' --T 1/1000 --frac-delay 0.0005");
  ASSERT_EQ(t.code, 0) << t.out;
  EXPECT_EQ(nlohmann::json::parse(t.out)["bound"], "inf");
  CliRun u = run("bound --json --H '1000 + 2*5/T*(z-1)/(z+1)' --T 1/1000");
  ASSERT_EQ(u.code, 0) << u.out;
  auto ju = nlohmann::json::parse(u.out);
  EXPECT_EQ(ju["bound"], "-4.5");
  EXPECT_EQ(ju["status"], "exact");
  EXPECT_EQ(ju["closed_form"], "Tustin wall");
}

// A pole pair on the circle, cos theta_p = -7/100, behind t_d = T/2: in c = cos(wT/2) the objective is
// f = -(9/800) c/(c^2 - 93/200), a simple pole at sqrt(93/200) whose isolating interval [0, 1] ended at
// A's root c = 0, where the sign test read f(0) = 0: "b* = 0 [exact]" (issue 46's campaign
// indep_bound_inf_inside, seed 97, 24 cases of q = 2). mpmath on paper 001's definition: f(theta_p +
// 1e-9) = +1.538e7, f(theta_p - 1e-9) = -1.538e7, so b* = +inf. With and without whole samples.
TEST(CmdBound, PoleOnTheCircleWhoseIntervalEndsAtAZeroOfTheNumerator) {
  for (const char* delay : {"", " --delay 1", " --delay 2"}) {
    CliRun r = run(std::string("bound --json --H '-45*z/(z^2 + (7/50)*z + 1)' --T 1/1000 --frac-delay 1/2000") + delay);
    ASSERT_EQ(r.code, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["bound"], "inf") << delay;
    EXPECT_EQ(j["status"], "exact") << delay;
  }
}

TEST(CmdBound, BadInputExit2) {
  for (const char* a : {"--H 'z/(z-2)' --T 1", "--H 'z^2/(z-0.5)' --T 1", "--H '1/(z-z)' --T 1", "--H '1' --T 0",
                        "--H '1' --T -1", "--H '1' --T 1 --eta -1", "--H '1' --T 1 --delay -1", "--H '' --T 1",
                        "--H '1/((z-2)*(z-1/2))' --T 1", "--H '1+' --T 1"}) {
    CliRun r = run(std::string("bound --json ") + a);
    EXPECT_EQ(r.code, 2) << a << "\n" << r.out;
    EXPECT_FALSE(r.out.empty()) << a;
  }
  CliRun r = run("bound --H 'z/(z-2)' --T 1");
  EXPECT_NE(r.out.find("unstable"), std::string::npos) << r.out;
  CliRun c = run("bound --H 'z^2/(z-0.5)' --T 1");
  EXPECT_NE(c.out.find("not causal"), std::string::npos) << c.out;
  CliRun ok = run("bound --json --H '1/(z^2+1)' --T 1");  // poles on the circle are not an error
  EXPECT_EQ(ok.code, 0) << ok.out;
}

TEST(CmdBound, BatchAndExplain) {
  std::string file = std::string(::testing::TempDir()) + "/bound_batch.txt";
  {
    std::ofstream f(file);
    f << "# a comment\n";
    f << "'K + B*(z-1)/(T*z)' --T 1/1000 --set K=1000 --set B=5\n";
    f << "--H '(z-1)/(z+0.5)' --T 0.001\n";
    f << "--H 'z/(z-2)' --T 1\n";
  }
  CliRun r = run("bound --batch " + file);
  EXPECT_EQ(r.code, 2);  // the worst line
  std::istringstream in(r.out);
  std::string line;
  std::vector<nlohmann::json> js;
  while (std::getline(in, line))
    if (!line.empty()) js.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(js.size(), 3u);
  EXPECT_EQ(js[0]["bound"], "5.5");
  EXPECT_EQ(js[1]["bound"], "0.002");
  EXPECT_TRUE(js[2].contains("error"));
  CliRun e = run("bound --explain --H 'K + B*(z-1)/(T*z)' --T 1/1000 --set K=1000 --set B=5 --delay 1");
  EXPECT_EQ(e.code, 0);
  EXPECT_NE(e.out.find("(53)"), std::string::npos) << e.out;
  EXPECT_NE(e.out.find("agrees"), std::string::npos) << e.out;
}

// Example 4's backward difference H_m z^-n is tight for an even n, and for m = 1 at every n: the
// closed form's name says which (issue 31: with n = 1 it said "with even delay n").
TEST(CmdBound, ExplainNamesTheDelayOfTheBackwardDifference) {
  CliRun odd = run("bound --explain --H 'B*(z-1)/(T*z)' --T 1/1000 --set B=5 --delay 1");
  EXPECT_EQ(odd.code, 0) << odd.out;
  EXPECT_NE(odd.out.find("closed form: backward difference H_1 with delay n = 1 (m = 1: any n) Example 4"),
            std::string::npos) << odd.out;
  EXPECT_EQ(odd.out.find("even"), std::string::npos) << odd.out;
  EXPECT_NE(odd.out.find("-> agrees"), std::string::npos) << odd.out;
  CliRun even = run("bound --explain --H 'B*(z-1)^2/(T^2*z^2)' --T 1/1000 --set B=5 --delay 2");
  EXPECT_EQ(even.code, 0) << even.out;
  EXPECT_NE(even.out.find("closed form: backward difference H_2 with delay n = 2 (even) Example 4"), std::string::npos)
      << even.out;
}

TEST(CmdBound, DampingCheckNecessaryConditionAndExitCode) {
  // b* = KT/2 + B = 12: b = 12.5 passes (exit 0), b = 11 fails (exit 1); at w* = pi/T the
  // small-gain form (14) and its rewriting (15) give the same verdict as b > b*
  const std::string wall = "bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --set K=20000 --set B=2 --json --damping ";
  CliRun ok = run(wall + "12.5");
  ASSERT_EQ(ok.code, 0) << ok.out;
  auto j = nlohmann::json::parse(ok.out);
  EXPECT_TRUE(j["damping"]["passive"].get<bool>());
  EXPECT_TRUE(j["damping"]["eq14_holds"].get<bool>());
  EXPECT_TRUE(j["damping"]["eq15_holds"].get<bool>());
  EXPECT_NEAR(j["damping"]["eq15_rhs"].get<double>(), 12.0, 1e-12);
  CliRun bad = run(wall + "11");
  ASSERT_EQ(bad.code, 1) << bad.out;
  auto k = nlohmann::json::parse(bad.out);
  EXPECT_FALSE(k["damping"]["passive"].get<bool>());
  EXPECT_FALSE(k["damping"]["eq14_holds"].get<bool>());
  EXPECT_FALSE(k["damping"]["eq15_holds"].get<bool>());
  // an integrator: no damping suffices
  EXPECT_EQ(run("bound --H \"z/(z-1)\" --T 1 --damping 1000").code, 1);
  EXPECT_EQ(run("bound --H \"1\" --T 1 --damping -1").code, 2);
}

TEST(CmdBound, QuantumAndCoulombReportTheFrictionConditionBesideBstar) {
  // Abbott-Okamura: the spring K = 1000 with Delta = 1 mm needs f_c >= K Delta/2 = 1/2 N (exact,
  // tight); b* = KT/2 = 1/2 as before.
  const std::string spring = "bound --H K --T 1/1000 --set K=1000 --json --quantum 1/1000 ";
  CliRun ok = run(spring + "--coulomb 1/2 --damping 1");
  ASSERT_EQ(ok.code, 0) << ok.out;
  auto j = nlohmann::json::parse(ok.out);
  EXPECT_EQ(j["bound"], "0.5");
  EXPECT_EQ(j["friction"]["fc_star_exact"], "1/2");
  EXPECT_EQ(j["friction"]["status"], "exact");
  EXPECT_TRUE(j["friction"]["tight"].get<bool>());
  EXPECT_TRUE(j["friction"]["holds"].get<bool>());  // equality is still passive
  EXPECT_TRUE(j["passive"].get<bool>());
  // f_c below the condition: exit 1 even though b > b*
  CliRun low = run(spring + "--coulomb 0.499 --damping 1");
  ASSERT_EQ(low.code, 1) << low.out;
  auto k = nlohmann::json::parse(low.out);
  EXPECT_FALSE(k["friction"]["holds"].get<bool>());
  EXPECT_TRUE(k["damping"]["passive"].get<bool>());
  EXPECT_FALSE(k["passive"].get<bool>());
  // the human output does not call the device passive before saying it is not (issue 31)
  CliRun text = run("bound --H K --T 1/1000 --set K=1000 --quantum 1/1000 --coulomb 0.499 --damping 1");
  ASSERT_EQ(text.code, 1) << text.out;
  EXPECT_EQ(text.out.find("passive (b > b*)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("damping b = 1: b > b* (the damping condition holds; the friction condition below)"),
            std::string::npos) << text.out;
  EXPECT_NE(text.out.find("friction condition FAILS (f_c < f_c*): not passive"), std::string::npos) << text.out;
  // --quantum alone reports f_c* and exits 0 (nothing to check)
  CliRun only = run(spring);
  ASSERT_EQ(only.code, 0) << only.out;
  EXPECT_FALSE(nlohmann::json::parse(only.out)["friction"].contains("holds"));
}

TEST(CmdBound, FrictionConditionOfTheDelayedSpringDamper) {
  // K + B(z-1)/(Tz) with delay n = 3: taps (K + B/T) z^-3 - (B/T) z^-4, f_c* = Delta (K/2 + B/T)
  // = 1e-3 (500 + 2000) = 5/2, independent of n; the witness (blocks of n + 1 = 4) makes it tight.
  CliRun r = run("bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --set K=1000 --set B=2 --delay 3 --json "
                 "--quantum 1/1000 --coulomb 3");
  ASSERT_EQ(r.code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["friction"]["fc_star_exact"], "5/2");
  EXPECT_EQ(j["friction"]["taps"], nlohmann::json({"0", "0", "0", "3000", "-2000"}));
  EXPECT_TRUE(j["friction"]["tight"].get<bool>());
  // the human text names the verdict
  CliRun h = run("bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --set K=1000 --set B=2 --quantum 1/1000 --coulomb 2");
  ASSERT_EQ(h.code, 1) << h.out;
  EXPECT_NE(h.out.find("f_c* = Delta/2 sum|w_k| = 5/2"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("friction condition FAILS"), std::string::npos) << h.out;
  // an IIR wall: the condition is not derived -> exit 2 naming why
  EXPECT_EQ(run("bound --H \"1/(z-1/2)\" --T 1 --quantum 1").code, 2);
}

TEST(CmdBound, ExplainSeesWholeSampleFractionalDelayAndDirichletConstants) {
  // t_d = T is the integer delay n = 1: Tustin with n = 1, KT/2 + B + |KT - 2B| = 14.5 (once the
  // matcher took it for the delay-free Tustin wall, -4.5, and printed DISAGREES)
  CliRun t = run("bound --H \"K + 2*B/T*(z-1)/(z+1)\" --T 1/1000 --set K=1000 --set B=5 --frac-delay 1/1000 --json");
  ASSERT_EQ(t.code, 0) << t.out;
  auto j = nlohmann::json::parse(t.out);
  EXPECT_EQ(j["bound"], "14.5");
  EXPECT_EQ(j["closed_form"], "Tustin wall with delay n = 1");
  EXPECT_EQ(j["closed_form_value"], "14.5");
  // Dirichlet kernel (50): C and D to the digits asked, enclosing 0.21723362821122165740827932556...
  CliRun d = run("bound --H \"(z-1)*(1+z^-1+z^-2+z^-3+z^-4+z^-5)\" --T 1 --allow-noncausal --json --digits 25");
  ASSERT_EQ(d.code, 0) << d.out;
  auto k = nlohmann::json::parse(d.out);
  const R C("0.2172336282112216574082793255624707342");
  EXPECT_LE(R(k["dirichlet_C"][0].get<std::string>()), C);
  EXPECT_GE(R(k["dirichlet_C"][1].get<std::string>()), C);
  EXPECT_LE(R(k["dirichlet_C"][1].get<std::string>()) - R(k["dirichlet_C"][0].get<std::string>()), R("1e-25"));
  EXPECT_LE(abs(R(k["dirichlet_D"][0].get<std::string>()) - (1 - C) / 2), R("1e-25"));
}

TEST(CmdBound, BatchLineWithTwoExpressionsIsAnError) {
  const std::string f = ::testing::TempDir() + "/two_exprs.txt";
  std::ofstream(f) << "z/(z-0.5) --T 1 1/(z-0.25)\n1/(z-0.5) --T 1\n";
  CliRun r = run("bound --batch " + f);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("unexpected '1/(z-0.25)'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"bound\":\"5\""), std::string::npos) << r.out;  // the next line still runs
}

// Stop 87's review: b* = 15 + 1e-40 (eta = 1e-40) printed "b* = 15 [exact]" and "passive iff b > 15", and a
// damping of 15 + 1e-41 then "b = 15: NOT passive (b <= b*)" under it. An exact value whose decimal is
// rounded says so and prints the rational; an exact decimal prints as before.
TEST(CmdBound, AnExactValueItsDecimalRoundsSaysSo) {
  const std::string wall = "bound --H \"K + B*(z-1)/(T*z)\" --set K=20000 --set B=5 --T 1/1000 ";
  const CliRun r = run(wall + "--eta 1e-40 --damping 15.00000000000000000000000000000000000000001");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("b* = 15 (rounded; exactly 150000000000000000000000000000000000000001/1" + std::string(40, '0') + ")   [exact]"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("passive iff b > b* (above)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("damping b = 15 (rounded; exactly 1500000000000000000000000000000000000000001/1"), std::string::npos) << r.out;
  const CliRun plain = run(wall);
  EXPECT_NE(plain.out.find("b* = 15   [exact]"), std::string::npos) << plain.out;
  EXPECT_NE(plain.out.find("passive iff b > 15\n"), std::string::npos) << plain.out;
}

// Stop 87's review: `bound --batch FILE --delay 5 --damping 1 --certificate c.json` printed FILE's cases and
// dropped every option beside --batch (no verdict against the damping, no certificate, no warning).
TEST(CmdBound, BatchRefusesOptionsItWouldIgnore) {
  const std::string f = ::testing::TempDir() + "/one_case.txt";
  std::ofstream(f) << "1/(z-0.5) --T 1\n";
  for (const char* extra : {"--delay 5", "--damping 1", "--certificate c.json", "--H \"1/(z-1)\""}) {
    CliRun r = run("bound --batch " + f + " " + extra);
    EXPECT_EQ(r.code, 2) << extra << "\n" << r.out;
    EXPECT_NE(r.out.find("would be ignored"), std::string::npos) << r.out;
  }
  EXPECT_EQ(run("bound --batch " + f).code, 0);
}

// `bound --max K --damping b` (passivity/max_gain.hpp): the closed form in JSON and text, b* at the
// answer (--explain's check, and a separate `bound` run at the printed K), the exit codes, the --b
// spelling, batch lines and the refusals.
TEST(CmdBound, MaxGainAgainstTheClosedFormAndBoundAtTheAnswer) {
  const std::string wall = "bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --set B=1/2 ";
  // n = 0: K_max = 2(b - B)/T = 1000 exactly, and bound at K = 1000 prints b* = b = 1
  auto j = nlohmann::json::parse(run(wall + "--damping 1 --max K --json").out);
  EXPECT_EQ(j["max"], "1000");
  EXPECT_EQ(j["exact"], "1000");
  EXPECT_EQ(j["status"], "exact");
  EXPECT_EQ(j["closed_form_equation"], "(46)");
  EXPECT_EQ(j["closed_form_value"], "1000");
  EXPECT_TRUE(j["closed_form_agrees"].get<bool>());
  EXPECT_EQ(nlohmann::json::parse(run(wall + "--set K=1000 --json").out)["bound"], "1");
  // n = 1, b = 3/2 < 5B: K T = 2 sqrt(B(2b - B)) - 2B = sqrt(5) - 1 (a newcomer's 1236.07 by hand)
  CliRun h = run(wall + "--delay 1 --b 3/2 --max K --explain");
  ASSERT_EQ(h.code, 0) << h.out;
  EXPECT_NE(h.out.find("sup K = 1236.06797749978969640917366873   [certified]"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("virtual wall with delay n = 1 (53)"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("-> agrees"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("b* = b within the enclosure"), std::string::npos) << h.out;
  auto k = nlohmann::json::parse(run(wall + "--delay 1 --b 3/2 --max K --json --explain").out);
  const R want = (2 * sqrt(R("1.25")) - 1) * 1000;
  EXPECT_LE(R(k["enclosure"][0].get<std::string>()), want);
  EXPECT_GE(R(k["enclosure"][1].get<std::string>()), want);
  EXPECT_TRUE(k["check"]["holds"].get<bool>());
  // bound at the printed (rounded) K: b* = 3/2 to the printed digits
  auto at = nlohmann::json::parse(run(wall + "--delay 1 --json --set K=" + k["max"].get<std::string>()).out);
  EXPECT_LE(abs(R(at["bound"].get<std::string>()) - R("1.5")), R("1e-28"));
  // K_max = 0 (exit 1): not passive at K = 0; infinite: a Tustin wall in B
  CliRun zero = run(wall + "--damping 1/2 --max K --json");
  EXPECT_EQ(zero.code, 1) << zero.out;
  EXPECT_EQ(nlohmann::json::parse(zero.out)["max"], "0");
  auto inf = nlohmann::json::parse(
      run("bound --H \"K + B*2*(z-1)/(T*(z+1))\" --T 1/1000 --set K=1000 --damping 1 --max B --json").out);
  EXPECT_EQ(inf["max"], "inf");
  EXPECT_EQ(inf["closed_form_value"], "inf");
}

TEST(CmdBound, MaxGainRefusesByNameAndRunsInBatches) {
  const std::string wall = "bound --H \"K + B*(z-1)/(T*z)\" --T 1/1000 --set B=1/2 ";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {wall + "--max K", "needs --damping"},
      {wall + "--max K --damping 1 --method fast", "certified only"},
      {wall + "--max K --damping 1 --quantum 1/1000", "friction condition"},
      {wall + "--max K --damping 1 --set K=5", "do not --set it"},
      {"bound --H \"K^2 + 1\" --T 1/1000 --max K --damping 1", "affine in K"},
      {"bound --num \"1 0\" --den \"1 0\" --T 1/1000 --max K --damping 1", "needs H as an expression"},
      {"bound --H \"1 + K/(z-2)\" --T 1/1000 --max K --damping 1", "the part of H in K"},
      {wall + "--max K --damping 0", "must be > 0"}};
  for (const auto& [args, says] : bad) {
    CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(says), std::string::npos) << args << "\n" << r.out;
  }
  const std::string f = ::testing::TempDir() + "/max_lines.txt";
  std::ofstream(f) << "\"K + B*(z-1)/(T*z)\" --T 1/1000 --set B=1/2 --max K --damping 1\n"
                   << "\"K + B*(z-1)/(T*z)\" --T 1/1000 --set B=2 --max K --damping 1\n";
  CliRun r = run("bound --batch " + f);
  EXPECT_EQ(r.code, 1) << r.out;  // the second line: K_max = 0
  EXPECT_NE(r.out.find("\"max\":\"1000\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"max\":\"0\""), std::string::npos) << r.out;
}

}  // namespace test_cmd_bound
