// tests/check/test_check.cpp -- the checkers of check/ on certificates whose truth is known by
// hand (issue 47): b* of H = K with and without a delay (exact closed forms below), r(jw) against
// cot(1/2) from a table, the non-negativity test on polynomials with known roots, and the largest
// stable gain of the mass on a virtual wall with delays 0 and 1 (closed forms below), MIMO ISP levels
// (a diagonal G: the least SISO level; a coupled 2x2 against mpmath). The
// mutation campaign (tests/check/mutate.py, ctest check_mutations) runs them against producers.
#include <cmath>

#include <gtest/gtest.h>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/certificate.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/max_positive.hpp"
#include "hapstab/check/reciprocal.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {
namespace {

using P = Polynomial<rational>;
const rational m1(-1), p1(1);

// Above degree 64 a negative value at one of 33 equally spaced points refutes before the gcds and the
// Sturm sequence (fuzz_certificate's first timeout: a degree-400 objective of a false fractional-delay
// claim ran over a minute); a polynomial >= 0 of that degree still goes the whole way.
TEST(Nonnegative, HighDegreeRefutedBySamplingAndProvenWhole) {
  const P x{rational(0), rational(1)};
  P t = P(rational(1));  // (x^2 + 1/4)^40 (x - 1/2)^2 >= 0, degree 82, tangent at 1/2
  for (int k = 0; k < 40; ++k) t = t * (x * x + P(rational(1, 4)));
  const P h = x - rational(1, 2);
  EXPECT_FALSE(nonnegative_on(t * h * h, m1, p1));
  const auto why = nonnegative_on(t * h, m1, p1);  // negative on [-1, 1/2)
  ASSERT_TRUE(why);
  EXPECT_NE(why->find("negative at c = -1"), std::string::npos) << *why;
  // negative only on a sliver between two grid points: Sturm finds the two sign changes
  const P g = x - rational(51, 100);  // the grid is -1 + k/16: 1/2 and 9/16 on either side of the sliver
  const auto sliver = nonnegative_on(t * (g * g - P(rational(1, 1000000))), m1, p1);
  ASSERT_TRUE(sliver);
  EXPECT_NE(sliver->find("changes sign at 2 point(s)"), std::string::npos) << *sliver;
}

// Numbers as the certificate writes them and as a hand may edit them (fuzz_certificate's findings):
// "010" is ten (GMP's base-0 reading, Boost's default, took it as octal eight, where the
// independent checker reads ten), and a JSON integer above the range of long is refused by name
// (nlohmann::json wraps 2^64 - 1 to -1: "side": 18446744073709551615 read as -1).
TEST(CertificateFields, DecimalLeadingZerosAndIntegersBeyondLong) {
  EXPECT_EQ(detail::exact_string("010", "x"), rational(10));
  EXPECT_EQ(detail::exact_string("-007/0010", "x"), rational(-7, 10));
  EXPECT_EQ(detail::exact_string("0000011669853858064382902", "x"), rational(integer("11669853858064382902")));
  EXPECT_EQ(detail::exact_string("0", "x"), rational(0));
  const auto big = nlohmann::json::parse(R"({"side": 18446744073709551615, "n": -3, "k": 5})");
  EXPECT_THROW(detail::integer_field(big, "side", "evidence", -1, 1), InputError);
  EXPECT_THROW(detail::integer_field(big, "n", "model", 0, 10), InputError);
  EXPECT_EQ(detail::integer_field(big, "k", "model", 0, 10), 5);
  try {
    detail::integer_field(big, "side", "evidence", -1, 1);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("evidence.side: 18446744073709551615 is outside [-1, 1]"), std::string::npos) << e.what();
  }
}

// fuzz_certificate's first timeout, kept whole: a fractional delay t_d/T = 1/400 (the objective has
// degree 400 in c = cos(wT/400)), a claim far below b* and a band end far below cos(pi/400). It ran
// over a minute in the gcds and the Sturm sequence; the sampling of step 0 refutes it at once.
TEST(CertificateFields, FalseClaimOfDegree400IsRefutedBySampling) {
  const auto c = nlohmann::json::parse(R"json({"certificate": "hapstab", "claim": {"hi": "-68166199999779/221000000000000",
"lo": "-78166200000221/221000000000000", "status": "certified"},
"evidence": {"domain_c_lo": "884/1260", "witness_c": "279/1250"}, "kind": "bound",
"model": {"H": "-K", "T": "1/0010", "delay": 0, "eta": "0", "frac_delay": "1/4000",
"set": {"K": "1000"}}, "produced_by": "hapstab 0.1.0", "version": 1})json");
  const Verdict v = check_certificate(c);
  EXPECT_FALSE(v.verified);
  EXPECT_NE(v.reason.find("it is negative at c = "), std::string::npos) << v.reason;
}

TEST(Nonnegative, KnownSigns) {
  const P x{rational(0), rational(1)};
  EXPECT_FALSE(nonnegative_on(x * x, m1, p1));                          // double root inside
  EXPECT_TRUE(nonnegative_on(x, m1, p1));                               // changes sign at 0
  EXPECT_FALSE(nonnegative_on(P(rational(0)), m1, p1));                 // zero
  EXPECT_TRUE(nonnegative_on(P(rational(-1)), m1, p1));                 // negative constant
  EXPECT_FALSE(nonnegative_on(p1 - x * x, m1, p1));                     // roots at both ends
  EXPECT_TRUE(nonnegative_on(x * x - p1, m1, p1));                      // negative inside
  const P h = x - rational(1, 2);
  EXPECT_FALSE(nonnegative_on(h * h * (x + rational(2)), m1, p1));      // tangent at 1/2
  EXPECT_TRUE(nonnegative_on(h * h * h, m1, p1));                       // triple root: a sign change
  EXPECT_FALSE(nonnegative_on((p1 - x) * (p1 - x) * (p1 - x), m1, p1)); // >= 0 on [-1, 1), root at 1
  EXPECT_TRUE(nonnegative_on((x - p1) * (x - p1) * (x - p1), m1, p1));
  // a double root just inside and a simple root just outside
  const P g = x - rational(999999, 1000000);
  EXPECT_FALSE(nonnegative_on(g * g * (rational(1000001, 1000000) - x), m1, p1));
}

nlohmann::json bound_cert(const std::string& H, const std::string& K, const std::string& T, int delay,
                          const nlohmann::json& claim, const std::string& witness) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "bound"},
          {"model", {{"H", H}, {"set", {{"K", K}}}, {"T", T}, {"delay", delay}, {"eta", "0"}}},
          {"claim", claim}, {"evidence", {{"witness_c", witness}}}};
}

// H = K: f = Re{T K/(1 - z)} = T K/2 for every w, so b* = T K/2 exactly.
TEST(BoundCheck, ConstantGainExact) {
  const auto ok = check_certificate(bound_cert("K", "4", "1/2", 0, {{"status", "exact"}, {"value", "1"}}, "1/3"));
  EXPECT_TRUE(ok.verified) << ok.reason;
  const auto high = check_certificate(bound_cert("K", "4", "1/2", 0, {{"status", "exact"}, {"value", "2"}}, "0"));
  EXPECT_FALSE(high.verified);
  EXPECT_NE(high.reason.find("not shown"), std::string::npos) << high.reason;
  const auto low = check_certificate(bound_cert("K", "4", "1/2", 0, {{"status", "exact"}, {"value", "1/2"}}, "0"));
  EXPECT_FALSE(low.verified);
  EXPECT_NE(low.reason.find("fails"), std::string::npos) << low.reason;
}

// H = K z^-1: Re{T K conj(z)/(1 - z)} = (T K/2)(c + (1 + c)) = (T K/2)(1 + 2c), maximal at c = 1:
// b* = 3 T K/2 = 3 for K = 4, T = 1/2.
TEST(BoundCheck, OneSampleDelayExact) {
  EXPECT_TRUE(check_certificate(bound_cert("K", "4", "1/2", 1, {{"status", "exact"}, {"value", "3"}}, "1")).verified);
  // the witness c = 1/2 gives 2 < 3: the lower bound is not shown
  EXPECT_FALSE(check_certificate(bound_cert("K", "4", "1/2", 1, {{"status", "exact"}, {"value", "3"}}, "1/2")).verified);
  EXPECT_TRUE(check_certificate(bound_cert("K", "4", "1/2", 1,
                                           {{"status", "certified"}, {"lo", "2"}, {"hi", "3"}, {"printed_lo", "2.0"},
                                            {"printed_hi", "3"}},
                                           "1/2"))
                  .verified);
  // the printed enclosure must be the claimed one
  EXPECT_FALSE(check_certificate(bound_cert("K", "4", "1/2", 1,
                                            {{"status", "certified"}, {"lo", "2"}, {"hi", "3"}, {"printed_hi", "3.5"}},
                                            "1/2"))
                   .verified);
  // the delay is part of the model: without it b* = 1 and the claim 3 is refuted
  EXPECT_FALSE(check_certificate(bound_cert("K", "4", "1/2", 0, {{"status", "exact"}, {"value", "3"}}, "1")).verified);
}

TEST(BoundCheck, MalformedNamesTheField) {
  auto c = bound_cert("K", "4", "1/2", 1, {{"status", "exact"}, {"value", "3"}}, "1");
  auto expect_field = [](const nlohmann::json& j, const std::string& field) {
    try {
      check_certificate(j);
      ADD_FAILURE() << "accepted without " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  auto d = c;
  d["model"].erase("T");
  expect_field(d, "model.T");
  d = c;
  d["model"]["frac_delay"] = "0.002";
  expect_field(d, "model.frac_delay");
  d = c;
  d["evidence"]["omega"] = "1";
  expect_field(d, "evidence.omega");
  d = c;
  d["claim"]["value"] = "0.5";
  expect_field(d, "claim.value");
  d = c;
  d["evidence"].erase("witness_c");
  expect_field(d, "evidence.witness_c");
  d = c;
  d["model"]["H"] = "K*(";
  expect_field(d, "model.H");
  d = c;
  d["kind"] = "bound-inf";  // no such kind (b* = +inf is the bound kind's claim "infinite")
  expect_field(d, "kind");
}

// The band [cos(pi/q), 1] decided exactly at rational points: cos(pi/2) = 0, cos(pi/3) = 1/2,
// cos(pi/10) = 0.95105..., cos(pi/5) = 0.80901...
TEST(BoundObjective, BandEnds) {
  using detail::at_or_below_domain_end;
  using detail::in_domain;
  EXPECT_TRUE(at_or_below_domain_end(rational(0), 2) && at_or_below_domain_end(rational(1, 2), 3));
  EXPECT_FALSE(at_or_below_domain_end(rational(1, 100), 2) || at_or_below_domain_end(rational(51, 100), 3));
  EXPECT_TRUE(at_or_below_domain_end(rational(-1), 1) && !at_or_below_domain_end(rational(0), 1));
  // far below the end too (not only within (cos(2 pi/q), cos(pi/q)]): 0.8 < cos(pi/5) and 0, -1/2
  for (const rational& c : {rational(95, 100), rational(8, 10), rational(0), rational(-1, 2), rational(-1)})
    EXPECT_TRUE(at_or_below_domain_end(c, 10)) << c.str();
  EXPECT_FALSE(at_or_below_domain_end(rational(96, 100), 10));
  EXPECT_TRUE(in_domain(rational(96, 100), 10) && !in_domain(rational(95, 100), 10) && !in_domain(rational(0), 10));
  EXPECT_TRUE(in_domain(rational(-1), 1) && !in_domain(rational(-1), 2) && in_domain(rational(0), 2));
}

nlohmann::json frac_cert(const std::string& H, const std::string& T, const std::string& td, const nlohmann::json& claim,
                         const std::string& witness, const std::string& c_lo = "") {
  nlohmann::json j{{"certificate", "hapstab"}, {"version", 1}, {"kind", "bound"},
                   {"model", {{"H", H}, {"set", {{"K", "2"}, {"B", "2"}}}, {"T", T}, {"delay", 0}, {"frac_delay", td}, {"eta", "0"}}},
                   {"claim", claim}, {"evidence", {{"witness_c", witness}}}};
  if (!c_lo.empty()) j["evidence"]["domain_c_lo"] = c_lo;
  return j;
}

// H = K, t_d = tau T: Re{T K e^{-j tau th}/(1 - e^{j th})} = T K sin((tau + 1/2) th)/(2 sin(th/2)),
// th = wT. tau = 1/2: T K cos(th/2) = T K c in c = cos(wT/2) on [0, 1]: b* = T K = 1 (T = 1/2, K = 2).
TEST(BoundCheck, FractionalDelayHalfSample) {
  auto exact = [](const std::string& v) { return nlohmann::json{{"status", "exact"}, {"value", v}}; };
  const Verdict ok = check_certificate(frac_cert("K", "1/2", "1/4", exact("1"), "1", "0"));
  EXPECT_TRUE(ok.verified) << ok.reason;
  EXPECT_TRUE(check_certificate(frac_cert("K", "1/2", "1/4", exact("1"), "1")).verified);  // c_lo = -1: f = c on [-1, 1]
  const Verdict low = check_certificate(frac_cert("K", "1/2", "1/4", exact("1"), "1/2", "0"));
  EXPECT_FALSE(low.verified);
  EXPECT_NE(low.reason.find("not shown"), std::string::npos) << low.reason;
  const nlohmann::json wide{{"status", "certified"}, {"lo", "-1/2"}, {"hi", "1"}};
  const Verdict outside = check_certificate(frac_cert("K", "1/2", "1/4", wide, "-1/2", "0"));  // f(-1/2) = -1/2, but w > pi/T
  EXPECT_FALSE(outside.verified);
  EXPECT_NE(outside.reason.find("outside the band"), std::string::npos) << outside.reason;
  const Verdict end = check_certificate(frac_cert("K", "1/2", "1/4", exact("1"), "1", "1/10"));
  EXPECT_FALSE(end.verified);
  EXPECT_NE(end.reason.find("domain_c_lo"), std::string::npos) << end.reason;
  // the delay is part of the model: t_d = 0 gives b* = T K/2
  auto no_delay = frac_cert("K", "1/2", "0", exact("1"), "1");
  EXPECT_FALSE(check_certificate(no_delay).verified);
  EXPECT_THROW(check_certificate(frac_cert("K", "1/2", "-1/4", exact("1"), "1")), InputError);
}

// H = -K, tau = 1/4, c = cos(wT/4) = cos(x): f = -T K sin(3x)/(2 sin(2x)) = -T K (4c^2 - 1)/(4c),
// decreasing in c on the band [cos(pi/4), 1]: b* = -T K sqrt(2)/4 = -0.35355339059327376220042...
// (T K = 1), at the irrational end wT = pi. Below the band, f -> +inf at c -> 0+.
TEST(BoundCheck, FractionalDelayMaximumAtAnIrrationalEnd) {
  const nlohmann::json claim{{"status", "certified"}, {"lo", "-3535533905932737623/10000000000000000000"},
                             {"hi", "-3535533905932737621/10000000000000000000"}};
  const std::string inside = "70710678118654752441/100000000000000000000";  // sqrt(2)/2 = 0.70710678118654752440084...
  const std::string below = "70710678118654752440/100000000000000000000";
  const Verdict ok = check_certificate(frac_cert("-K", "1/2", "1/8", claim, inside, below));
  EXPECT_TRUE(ok.verified) << ok.reason;
  // a witness just beyond the end (w > pi/T), a c_lo just above it, and no c_lo (the band [-1, 1] meets the pole at c = 0)
  EXPECT_FALSE(check_certificate(frac_cert("-K", "1/2", "1/8", claim, below, below)).verified);
  EXPECT_FALSE(check_certificate(frac_cert("-K", "1/2", "1/8", claim, inside, inside)).verified);
  EXPECT_FALSE(check_certificate(frac_cert("-K", "1/2", "1/8", claim, inside)).verified);
  // hi just below b*: the upper bound fails
  const nlohmann::json over{{"status", "certified"}, {"lo", "-3535533905932737624/10000000000000000000"},
                            {"hi", "-3535533905932737623/10000000000000000000"}};
  EXPECT_FALSE(check_certificate(frac_cert("-K", "1/2", "1/8", over, inside, below)).verified);
}

// The Tustin damper H = B (z - 1)/(z + 1) = j B tan(th/2) with T = 1, B = 2, tau = 5/4:
// f = tan(th/2) sin(5 th/4) - cos(5 th/4) (sup 1.7381038413... inside, by mpmath), -> -inf at th -> pi
// (sin(5 pi/4) < 0), +inf just beyond: (hi - eta) B - A changes sign at the irrational end c =
// cos(pi/4), and only the test with U_3 shows the bound.
TEST(BoundCheck, FractionalDelayPoleAtTheEndFromBelow) {
  const std::string below = "70710678118654752440/100000000000000000000";
  auto claim = [](const std::string& hi) { return nlohmann::json{{"status", "certified"}, {"lo", "-1"}, {"hi", hi}}; };
  const Verdict ok = check_certificate(frac_cert("B*(z-1)/(z+1)", "1", "5/4", claim("2"), "1", below));
  EXPECT_TRUE(ok.verified) << ok.reason;
  EXPECT_NE(ok.reason.find("U_3"), std::string::npos) << ok.reason;
  const Verdict low = check_certificate(frac_cert("B*(z-1)/(z+1)", "1", "5/4", claim("3/2"), "1", below));
  EXPECT_FALSE(low.verified);
  EXPECT_NE(low.reason.find("fails"), std::string::npos) << low.reason;
}

nlohmann::json max_cert(const std::string& H, const nlohmann::json& claim, const nlohmann::json& evidence) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "bound-max"},
          {"model", {{"H", H}, {"set", {{"B", "1"}}}, {"name", "K"}, {"T", "1/1000"}, {"delay", 0}, {"eta", "0"}, {"damping", "2"}}},
          {"claim", claim}, {"evidence", evidence}};
}

// The wall K + B (z - 1)/(T z) without delay: b*(K) = K T/2 + B (paper 001 (46), at w = pi/T, c = -1),
// so with B = 1, b = 2, T = 1/1000: b*(0) = 1 and K_max = 2 (b - B)/T = 2000 exactly.
TEST(BoundMaxCheck, WallWithoutDelay) {
  auto exact = [](const std::string& v) { return nlohmann::json{{"status", "exact"}, {"value", v}}; };
  const nlohmann::json ev{{"b0_hi", "1"}, {"witness_c", "-1"}};
  const std::string wall = "K + B*(z-1)/(T*z)";
  const Verdict ok = check_certificate(max_cert(wall, exact("2000"), ev));
  EXPECT_TRUE(ok.verified) << ok.reason;
  EXPECT_TRUE(check_certificate(max_cert(wall, {{"status", "certified"}, {"lo", "1999"}, {"hi", "2001"}}, ev)).verified);
  const Verdict above = check_certificate(max_cert(wall, exact("2001"), ev));  // b*(2001) > b
  EXPECT_FALSE(above.verified);
  EXPECT_NE(above.reason.find("K_max >= "), std::string::npos) << above.reason;
  const Verdict below = check_certificate(max_cert(wall, exact("1999"), ev));  // b*(1999) < b
  EXPECT_FALSE(below.verified);
  EXPECT_NE(below.reason.find("K_max <= "), std::string::npos) << below.reason;
  EXPECT_FALSE(check_certificate(max_cert(wall, exact("2000"), {{"b0_hi", "2"}, {"witness_c", "-1"}})).verified);    // b0 < b
  EXPECT_FALSE(check_certificate(max_cert(wall, exact("2000"), {{"b0_hi", "1/2"}, {"witness_c", "-1"}})).verified);  // b*(0) = 1
  // K_max = 0 needs b*(0) >= b: here b*(0) = 1 < 2
  EXPECT_FALSE(check_certificate(max_cert(wall, exact("0"), {{"witness_c", "-1"}})).verified);
  // f1 = T/2 > 0: not infinite
  EXPECT_FALSE(check_certificate(max_cert(wall, {{"status", "exact"}, {"infinite", true}}, {{"b0_hi", "1"}})).verified);
  // H = B (z - 1)/(T z) - K: f1 = -T/2 < 0, b*(K) = 1 - K T/2 < 2 for every K >= 0
  const Verdict inf = check_certificate(max_cert("B*(z-1)/(T*z) - K", {{"status", "exact"}, {"infinite", true}}, {{"b0_hi", "1"}}));
  EXPECT_TRUE(inf.verified) << inf.reason;
  // the model: the parameter given a value, H not affine in it, H not depending on it
  auto d = max_cert(wall, exact("2000"), ev);
  d["model"]["set"]["K"] = "1";
  EXPECT_THROW(check_certificate(d), InputError);
  EXPECT_THROW(check_certificate(max_cert("K*K/1000 + B*(z-1)/(T*z)", exact("2000"), ev)), InputError);
  EXPECT_THROW(check_certificate(max_cert("K/(1 + K) + B*(z-1)/(T*z)", exact("2000"), ev)), InputError);
  EXPECT_THROW(check_certificate(max_cert("B*(z-1)/(T*z)", exact("2000"), ev)), InputError);
  // affine though written with K twice and a division: (K^2 + K)/(K + 1) = K where defined
  EXPECT_TRUE(check_certificate(max_cert("(K*K + K)/(K + 1) + B*(z-1)/(T*z)", exact("2000"), ev)).verified);
}

// H = B + K with t_d = T/2: b*(K) = T (B + K) (cos(wT/2) at w = 0), so B = 3000 gives b*(0) = 3 >= b = 2:
// K_max = 0 by the witness c = 1 alone; a domain_c_lo beyond the band's end (cos(pi/2) = 0) is
// refuted although no upper bound reads it.
TEST(BoundMaxCheck, ZeroChecksEveryEvidence) {
  auto c = max_cert("B + K", {{"status", "exact"}, {"value", "0"}}, {{"witness_c", "1"}, {"domain_c_lo", "0"}});
  c["model"]["set"]["B"] = "3000";
  c["model"]["frac_delay"] = "1/2000";
  const Verdict ok = check_certificate(c);
  EXPECT_TRUE(ok.verified) << ok.reason;
  c["evidence"]["domain_c_lo"] = "1/2";
  EXPECT_FALSE(check_certificate(c).verified);
}

// H = K with a delay of n samples: b*(K) = (2n + 1) K T/2 (paper 001, Example 4), so K_max =
// 2 b/((2n + 1) T): n = 1, b = 2, T = 1/1000 gives 4000/3, attained at w = 0 (c = 1).
TEST(BoundMaxCheck, DelayedGain) {
  auto c = max_cert("K", {{"status", "exact"}, {"value", "4000/3"}}, {{"b0_hi", "0"}, {"witness_c", "1"}});
  c["model"]["delay"] = 1;
  const Verdict ok = check_certificate(c);
  EXPECT_TRUE(ok.verified) << ok.reason;
  c["model"]["delay"] = 0;  // b*(K) = K T/2: K_max = 4000
  EXPECT_FALSE(check_certificate(c).verified);
}

nlohmann::json level_cert(const std::string& H, const std::string& kind, const nlohmann::json& claim, const std::string& witness) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "passivity-level"},
          {"model", {{"H", H}, {"set", nlohmann::json::object()}, {"T", "1/1000"}, {"kind", kind}}},
          {"claim", claim}, {"evidence", {{"witness_c", witness}}}};
}

// G = 1 + 1/(z - 1/2) = (z + 1/2)/(z - 1/2), c = cos(theta): Re G = 1 + (c - 1/2)/(5/4 - c), increasing
// in c, so phi* = Re G(-1) = 1/3; 1/G = (z - 1/2)/(z + 1/2), Re(1/G) = (3/4)/(5/4 + c), so delta* =
// Re(1/G)(1) = 1/3.
TEST(PassivityLevelCheck, FirstOrder) {
  auto exact = [](const std::string& v) { return nlohmann::json{{"status", "exact"}, {"value", v}}; };
  const std::string G = "1 + 1/(z-0.5)";
  const Verdict isp = check_certificate(level_cert(G, "isp", exact("1/3"), "-1"));
  EXPECT_TRUE(isp.verified) << isp.reason;
  const Verdict osp = check_certificate(level_cert(G, "osp", exact("1/3"), "1"));
  EXPECT_TRUE(osp.verified) << osp.reason;
  const Verdict away = check_certificate(level_cert(G, "isp", exact("1/3"), "1"));  // Re G(1) = 2
  EXPECT_FALSE(away.verified);
  EXPECT_NE(away.reason.find("not shown"), std::string::npos) << away.reason;
  const Verdict high = check_certificate(level_cert(G, "isp", exact("1/2"), "-1"));
  EXPECT_FALSE(high.verified);
  EXPECT_NE(high.reason.find("phi* >= "), std::string::npos) << high.reason;
  EXPECT_TRUE(check_certificate(level_cert(G, "isp", {{"status", "certified"}, {"lo", "0"}, {"hi", "1/2"}}, "-1/2")).verified);  // Re G(-1/2) = 3/7
  // hypotheses: G Schur stable; OSP: no zero of G on the circle and delta* > 0
  EXPECT_THROW(check_certificate(level_cert("1/(z - 2)", "isp", exact("0"), "1")), InputError);
  EXPECT_THROW(check_certificate(level_cert("(z + 1)/(z - 0.5)", "osp", exact("0"), "1")), InputError);
  EXPECT_THROW(check_certificate(level_cert("(z + 1)/(z - 0.5)", "osp", exact("1/10"), "1")), InputError);  // zero at theta = pi
  EXPECT_THROW(check_certificate(level_cert("1/(z - 0.5)", "osp", exact("-3/2"), "-1")), InputError);  // an upper bound only
  EXPECT_THROW(check_certificate(level_cert("z^2/(z - 0.5)", "isp", exact("0"), "1")), InputError);   // not causal
}

// ---- passivity-level-mimo (check/passivity_level_mimo_check.hpp): square MIMO ISP levels known by
// hand or from mpmath, never from hapstab.
nlohmann::json mimo_cert(const nlohmann::json& A, const nlohmann::json& B, const nlohmann::json& C, const nlohmann::json& D,
                         const nlohmann::json& claim, const nlohmann::json& evidence = nlohmann::json::object()) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "passivity-level-mimo"},
          {"model", {{"A", A}, {"B", B}, {"C", C}, {"D", D}, {"T", "1/100"}, {"kind", "isp"}}},
          {"claim", claim}, {"evidence", evidence}};
}
using Rows = std::vector<std::vector<std::string>>;
nlohmann::json mat(const Rows& rows) {  // an array of arrays (a braced list of pairs would make an object)
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : rows) j.push_back(nlohmann::json(r));
  return j;
}
nlohmann::json exact_claim(const std::string& v) { return {{"status", "exact"}, {"value", v}}; }
nlohmann::json range_claim(const std::string& lo, const std::string& hi) { return {{"status", "certified"}, {"lo", lo}, {"hi", hi}}; }
nlohmann::json witness(const std::string& c, const std::string& s) { return {{"witness_c", c}, {"witness_s", s}}; }

// G = diag(g1, g2), g1 = 1 + 1/(z - 1/2) = (z + 1/2)/(z - 1/2): Re g1 = (3/4)/(5/4 - c), min 1/3 at
// theta = pi; g2 = 1 + (3/4) z^-2: Re g2 = 1 + (3/4) cos 2theta, min 1/4 at theta = pi/2 (z = j). He G
// is diagonal, so phi* = min(1/3, 1/4) = 1/4, exactly, at a point inside (0, pi) where only g2 touches.
const nlohmann::json diagA = mat({{"1/2", "0", "0"}, {"0", "0", "0"}, {"0", "1", "0"}});
const nlohmann::json diagB = mat({{"1", "0"}, {"0", "1"}, {"0", "0"}});
const nlohmann::json diagC = mat({{"1", "0", "0"}, {"0", "0", "3/4"}});
const nlohmann::json I2 = mat({{"1", "0"}, {"0", "1"}});

TEST(PassivityLevelMimoCheck, DiagonalIsTheLeastSisoLevel) {
  const Verdict v = check_certificate(mimo_cert(diagA, diagB, diagC, I2, exact_claim("1/4")));
  EXPECT_TRUE(v.verified) << v.reason;
  for (const char* wrong : {"1/3", "1/4000000000000000000000000000000000000001", "2499999999999999999999999999/10000000000000000000000000000"}) {
    const Verdict w = check_certificate(mimo_cert(diagA, diagB, diagC, I2, exact_claim(wrong)));
    EXPECT_FALSE(w.verified) << wrong;
  }
  // an enclosure: the witness z = j (c = 0, s = 1) has lambda_min = 1/4 <= hi; z = 1 has 3
  EXPECT_TRUE(check_certificate(mimo_cert(diagA, diagB, diagC, I2, range_claim("0", "1/4"), witness("0", "1"))).verified);
  EXPECT_TRUE(check_certificate(mimo_cert(diagA, diagB, diagC, I2, range_claim("-1", "3/10"), witness("-21/221", "220/221"))).verified);  // t = 11/10: Re g2 = 0.2635
  const Verdict far = check_certificate(mimo_cert(diagA, diagB, diagC, I2, range_claim("0", "1/2"), witness("1", "0")));
  EXPECT_FALSE(far.verified);
  EXPECT_NE(far.reason.find("not shown"), std::string::npos) << far.reason;
  const Verdict off = check_certificate(mimo_cert(diagA, diagB, diagC, I2, range_claim("0", "1/2"), witness("1/2", "1/2")));
  EXPECT_FALSE(off.verified);
  EXPECT_NE(off.reason.find("not on the unit circle"), std::string::npos) << off.reason;
  // g1 alone (the first channel, one input): the SISO level 1/3 at theta = pi, an end of [0, pi]
  EXPECT_TRUE(check_certificate(mimo_cert(mat({{"1/2"}}), mat({{"1"}}), mat({{"1"}}), mat({{"1"}}), exact_claim("1/3"))).verified);
  EXPECT_FALSE(check_certificate(mimo_cert(mat({{"1/2"}}), mat({{"1"}}), mat({{"1"}}), mat({{"1"}}), exact_claim("1/4"))).verified);
}

// A coupled 2x2: A = [[0, 1/2], [-1/2, 0]] (poles +-j/2), B = [[1, 0], [1/3, 1]], C = [[1, 0], [1/4, 1]],
// D = [[2, 1/3], [-1/5, 3/2]]. mpmath at 60 digits (lambda_min of the 2x2 He G in closed form, a grid of
// 2000 points, then findroot on its derivative): phi* = 0.13457867356938227191106546829846038338722...
// at theta = 2.07007320998374244491066298922; the witness is tan(theta/2) rounded to 30 digits.
const nlohmann::json cA = mat({{"0", "1/2"}, {"-1/2", "0"}}), cB = mat({{"1", "0"}, {"1/3", "1"}}),
                     cC = mat({{"1", "0"}, {"1/4", "1"}}), cD = mat({{"2", "1/3"}, {"-1/5", "3/2"}});
const nlohmann::json cW = witness("-28706733526243037880659009817130398777347852942453452692249/59956733526243037880659009817130398777347852942453452692249",
                                  "52637755892421837435168465889250000000000000000000000000000/59956733526243037880659009817130398777347852942453452692249");

TEST(PassivityLevelMimoCheck, CoupledAgainstMpmath) {
  const std::string lo = "134578673569382271911/1000000000000000000000", hi = "134578673569382271912/1000000000000000000000";
  const Verdict v = check_certificate(mimo_cert(cA, cB, cC, cD, range_claim(lo, hi), cW));
  EXPECT_TRUE(v.verified) << v.reason;
  // lo 10^-20 above the level; hi 10^-20 below it
  const Verdict high = check_certificate(mimo_cert(cA, cB, cC, cD, range_claim(hi, "134578673569382271913/1000000000000000000000"), cW));
  EXPECT_FALSE(high.verified);
  EXPECT_NE(high.reason.find("phi* >= "), std::string::npos) << high.reason;
  const Verdict low = check_certificate(mimo_cert(cA, cB, cC, cD, range_claim("0", "134578673569382271910/1000000000000000000000"), cW));
  EXPECT_FALSE(low.verified);
  EXPECT_NE(low.reason.find("not shown"), std::string::npos) << low.reason;
  // the level is irrational: no exact claim holds
  EXPECT_FALSE(check_certificate(mimo_cert(cA, cB, cC, cD, exact_claim(lo))).verified);
}

// G = diag(g1, 1/5): He G has the eigenvalue 1/5 at every theta, so phi* = 1/5 but det(He G - I/5) = 0
// identically: an exact claim is not decided (refuted, saying so), an enclosure is verified.
TEST(PassivityLevelMimoCheck, ConstantEigenvalue) {
  const nlohmann::json A = mat({{"1/2"}}), B = mat({{"1", "0"}}), C = mat({{"1"}, {"0"}}), D = mat({{"1", "0"}, {"0", "1/5"}});
  const Verdict e = check_certificate(mimo_cert(A, B, C, D, exact_claim("1/5")));
  EXPECT_FALSE(e.verified);
  EXPECT_NE(e.reason.find("identically 0"), std::string::npos) << e.reason;
  EXPECT_TRUE(check_certificate(mimo_cert(A, B, C, D, range_claim("199999/1000000", "1/5"), witness("1", "0"))).verified);
}

// OSP (the pencil He G - nu G^H G; delta* = min lambda_min(He G^-1)), by hand and from mpmath.
// diag(g1, g2) as above: Re(1/g1) = (3/4)/(5/4 + c), min 1/3 at theta = 0; 1/g2 = z^2/(z^2 + 3/4),
// Re(1/g2) = (1 + (3/4) cos 2theta)/(25/16 + (3/2) cos 2theta), decreasing in cos 2theta, min 4/7 at
// theta = 0 and pi. So delta* = 1/3 exactly (theta = 0). The coupled 2x2: mpmath at 60 digits (the 2x2
// He G^-1's least eigenvalue in closed form, 2000 points, findroot on its derivative): delta* =
// 0.204061059135553914835147667520313286655... at theta = 1.86918105428121633121375653104; the witness
// is tan(theta/2) rounded to 30 digits.
nlohmann::json osp(nlohmann::json c) {
  c["model"]["kind"] = "osp";
  return c;
}

TEST(PassivityLevelMimoCheck, OspByHandAndAgainstMpmath) {
  const Verdict v = check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, exact_claim("1/3"))));
  EXPECT_TRUE(v.verified) << v.reason;
  EXPECT_NE(v.reason.find("det G != 0 on the circle"), std::string::npos) << v.reason;
  for (const char* wrong : {"1/4", "4/7", "3333333333333333333333333334/10000000000000000000000000000"})
    EXPECT_FALSE(check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, exact_claim(wrong)))).verified) << wrong;
  // the witness z = 1 (theta = 0) has the pencil singular at 1/3: not > 0 at hi = 1/3
  EXPECT_TRUE(check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, range_claim("1/4", "1/3"), witness("1", "0")))).verified);
  const Verdict far = check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, range_claim("1/4", "1/3"), witness("-1", "0"))));
  EXPECT_FALSE(far.verified);  // at theta = pi the least eigenvalue of He G^-1 is 4/7 > 1/3
  EXPECT_NE(far.reason.find("delta* <= "), std::string::npos) << far.reason;
  // the ISP claim's value is not the OSP level
  EXPECT_FALSE(check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, exact_claim("1/4")))).verified);
  // lo <= 0: not the level (refuted, saying why)
  const Verdict neg = check_certificate(osp(mimo_cert(diagA, diagB, diagC, I2, range_claim("-1", "1/3"), witness("1", "0"))));
  EXPECT_FALSE(neg.verified);
  EXPECT_NE(neg.reason.find("lo > 0"), std::string::npos) << neg.reason;

  const nlohmann::json oW = witness("-208191918127890245872492649742460031681211876814435161/708191918127890245872492649742460031681211876814435161",
                                    "676898750277979347572454619000000000000000000000000000/708191918127890245872492649742460031681211876814435161");
  const std::string lo = "204061059135553914835/1000000000000000000000", hi = "204061059135553914836/1000000000000000000000";
  const Verdict c = check_certificate(osp(mimo_cert(cA, cB, cC, cD, range_claim(lo, hi), oW)));
  EXPECT_TRUE(c.verified) << c.reason;
  const Verdict high = check_certificate(osp(mimo_cert(cA, cB, cC, cD, range_claim(hi, "204061059135553914837/1000000000000000000000"), oW)));
  EXPECT_FALSE(high.verified);
  EXPECT_NE(high.reason.find("delta* >= "), std::string::npos) << high.reason;
  const Verdict low = check_certificate(osp(mimo_cert(cA, cB, cC, cD, range_claim("1/10", "204061059135553914834/1000000000000000000000"), oW)));
  EXPECT_FALSE(low.verified);
  EXPECT_NE(low.reason.find("not shown"), std::string::npos) << low.reason;
  // the ISP certificate's witness and enclosure do not prove the OSP level
  EXPECT_FALSE(check_certificate(osp(mimo_cert(cA, cB, cC, cD,
                                               range_claim("134578673569382271911/1000000000000000000000",
                                                           "134578673569382271912/1000000000000000000000"), cW))).verified);
}

// OSP needs G regular on the circle: a zero of det G at z = -1 or inside (0, pi) is refused by name.
TEST(PassivityLevelMimoCheck, OspRefusesAZeroOnTheCircle) {
  // diag(g1, 1 + 1/z): the second channel vanishes at z = -1
  const nlohmann::json A = mat({{"1/2", "0"}, {"0", "0"}}), B = mat({{"1", "0"}, {"0", "1"}}), C = mat({{"1", "0"}, {"0", "1"}});
  try {
    check_certificate(osp(mimo_cert(A, B, C, I2, range_claim("1/10", "1/3"), witness("1", "0"))));
    ADD_FAILURE() << "a zero of G at z = -1 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("z = -1"), std::string::npos) << e.what();
  }
  // diag(g1, 1 + z^-2): zeros at z = +-j, inside the arc
  const nlohmann::json A3 = mat({{"1/2", "0", "0"}, {"0", "0", "0"}, {"0", "1", "0"}}), C3 = mat({{"1", "0", "0"}, {"0", "0", "1"}});
  try {
    check_certificate(osp(mimo_cert(A3, diagB, C3, I2, range_claim("1/10", "1/3"), witness("1", "0"))));
    ADD_FAILURE() << "zeros of G at z = +-j accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vanishes on the unit circle"), std::string::npos) << e.what();
  }
}

TEST(PassivityLevelMimoCheck, Malformed) {
  auto bad = [](nlohmann::json c, const std::string& field) {
    try {
      check_certificate(c);
      ADD_FAILURE() << "accepted; expected an error naming " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  const nlohmann::json ok = mimo_cert(diagA, diagB, diagC, I2, range_claim("0", "1/4"), witness("0", "1"));
  nlohmann::json c = ok;
  c["model"]["kind"] = "ips";
  bad(c, "model.kind");
  c = ok;
  c["model"]["A"][0][0] = "3/2";  // a pole at 3/2: not Schur stable
  bad(c, "model.A");
  c = ok;
  c["model"]["D"] = mat({{"1", "0", "0"}, {"0", "1", "0"}});
  bad(c, "model.D");
  c = ok;
  c["model"]["C"] = mat({{"1", "0", "0"}});  // one output, two inputs
  bad(c, "model.C");
  c = ok;
  c["model"]["B"][0][0] = "0.5";
  bad(c, "model.B[0][0]");
  c = ok;
  c["evidence"].erase("witness_s");
  bad(c, "evidence.witness_s");
  c = ok;
  c["evidence"]["witness_v"] = "1";
  bad(c, "evidence.witness_v");
  c = mimo_cert(diagA, diagB, diagC, I2, exact_claim("1/4"), witness("0", "1"));  // an exact claim reads no witness
  bad(c, "evidence.witness_c");
  c = ok;
  c["model"]["H"] = "1/z";
  bad(c, "model.H");
  c = ok;
  c["model"]["T"] = "0";
  bad(c, "model.T");
}

// r(j 1) at T = 1: Im r = -(1/2) cot(1/2) = -0.91524386085622595963... (mpmath, 40 digits)
TEST(RCheck, CotOneHalf) {
  auto cert = [](const std::string& re, const std::string& lo, const std::string& hi) {
    return nlohmann::json{{"certificate", "hapstab"}, {"version", 1}, {"kind", "r"},
                          {"model", {{"T", "1"}, {"omega", "1"}}},
                          {"claim", {{"re", re}, {"im_lo", lo}, {"im_hi", hi}}}};
  };
  EXPECT_TRUE(check_certificate(cert("-1/2", "-91524386085622596/100000000000000000", "-91524386085622595/100000000000000000")).verified);
  EXPECT_FALSE(check_certificate(cert("-1/2", "-91524386085622595/100000000000000000", "-91524386085622594/100000000000000000")).verified);
  EXPECT_FALSE(check_certificate(cert("1/2", "-1", "0")).verified);
}

TEST(SchurCohn, KnownRoots) {
  const P z{rational(0), rational(1)};
  EXPECT_TRUE(schur_cohn(z - rational(1, 2)).stable);
  EXPECT_FALSE(schur_cohn(z + rational(1)).stable);                             // a root on the circle
  EXPECT_TRUE(schur_cohn(z * z + rational(1, 4)).stable);                       // +-j/2
  EXPECT_TRUE(schur_cohn(z * z - z + rational(1, 2)).stable);                   // (1 +- j)/2, |.| = 0.707
  EXPECT_FALSE(schur_cohn((z - rational(1, 2)) * (z - rational(2))).stable);    // one root outside
  EXPECT_FALSE(schur_cohn((z - rational(1, 2)) * (z * z + rational(1))).stable);  // +-j on the circle
  EXPECT_TRUE(schur_cohn(P(rational(3))).stable);                               // no roots
  EXPECT_TRUE(schur_cohn(rational(-7) * (z + rational(9, 10)) * (z - rational(99, 100))).stable);
}

nlohmann::json stability_cert(const std::string& plant, const std::string& H, int delay, bool stable,
                              const std::vector<std::string>& charpoly) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability"},
          {"model", {{"plant", plant}, {"H", H}, {"set", {{"m", "1"}, {"K", "1000"}, {"B", "2"}}}, {"T", "1/1000"}, {"delay", delay}}},
          {"claim", {{"status", "exact"}, {"stable", stable}}}, {"evidence", {{"charpoly", charpoly}}}};
}

// The mass 1/(m s^2) behind a zero-order hold: P_d = T^2 (z + 1)/(2 m (z - 1)^2) (a table of
// z-transforms). With H = K + B (z - 1)/(T z), m = 1, K = 1000, B = 2, T = 1/1000, by hand:
// c = z (z - 1)^2 + (T^2/2)(z + 1)((K + B/T) z - B/T) = z^3 - 3997/2000 z^2 + 2001/2000 z - 1/1000,
// stable by Jury's conditions for a cubic (c(1) = 1/1000 > 0, -c(-1) = 4 > 0, |a0| < 1,
// |a0^2 - 1| = 0.999999 > |a0 a2 - a1| = 0.9985015).
TEST(StabilityCheck, MassOnAVirtualWall) {
  const std::vector<std::string> c{"-1/1000", "2001/2000", "-3997/2000", "1"};
  const auto ok = check_certificate(stability_cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, true, c));
  EXPECT_TRUE(ok.verified) << ok.reason;
  // any non-zero multiple of the polynomial is the same evidence
  EXPECT_TRUE(check_certificate(stability_cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, true, {"2/1000", "-2001/1000", "3997/1000", "-2"})).verified);
  const auto flipped = check_certificate(stability_cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, false, c));
  EXPECT_FALSE(flipped.verified);
  EXPECT_NE(flipped.reason.find("every Schur-Cohn step passes"), std::string::npos) << flipped.reason;
  // the polynomial of another loop (one coefficient moved) is refuted before any root test
  const auto moved = check_certificate(stability_cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 0, true, {"-1/1000", "2001/2000", "-3996/2000", "1"}));
  EXPECT_FALSE(moved.verified);
  EXPECT_NE(moved.reason.find("z^2"), std::string::npos) << moved.reason;
  // the delay is part of the loop: z^1 changes the polynomial's degree
  EXPECT_FALSE(check_certificate(stability_cert("1/(m*s^2)", "K + B*(z-1)/(T*z)", 1, true, c)).verified);
}

// H = K alone: c = (z - 1)^2 + a (z + 1), a = K T^2/(2 m) = 1/2000: c(0) = 1 + a > 1 = the leading
// coefficient, so NOT stable (a spring alone on a sampled mass); with the operator's mass c s,
// P_eff = 1/((m + c) s^2).
TEST(StabilityCheck, SpringAloneAndOperatorMass) {
  const std::vector<std::string> c{"2001/2000", "-3999/2000", "1"};
  EXPECT_TRUE(check_certificate(stability_cert("1/(m*s^2)", "K", 0, false, c)).verified);
  EXPECT_FALSE(check_certificate(stability_cert("1/(m*s^2)", "K", 0, true, c)).verified);
  auto op = stability_cert("1/(m*s^2)", "K", 0, false, {"4001/4000", "-7999/4000", "1"});  // a = 1/4000
  op["model"]["operator"] = "m*s";
  const auto v = check_certificate(op);
  EXPECT_TRUE(v.verified) << v.reason;
}

// The zero-order hold of 1/s^3 at T = 1 is (z^2 + 4 z + 1)/(6 (z - 1)^3) (a table): with H = 1,
// c = (z - 1)^3 + (z^2 + 4 z + 1)/6 = z^3 - 17/6 z^2 + 22/6 z - 5/6; |a0^2 - 1| = 11/36 <
// |a0 a2 - a1| = 47/36, so NOT stable (Jury).
TEST(StabilityCheck, TripleIntegrator) {
  nlohmann::json c = stability_cert("1/s^3", "1", 0, false, {"-5/6", "22/6", "-17/6", "1"});
  c["model"]["T"] = "1";
  const auto v = check_certificate(c);
  EXPECT_TRUE(v.verified) << v.reason;
}

// One pole off s = 0 (check/loop_model.hpp): the lag 1/(s + 1) at T = 1, H = K: P_d = (1 - E)/(z - E),
// E = e^-1, so c = z - E + K (1 - E), its root E - K (1 - E) inside iff K < (1 + E)/(1 - E) =
// 2.1639534...: K = 2 stable, K = 3 NOT stable (by hand). The evidence is empty, the status certified.
nlohmann::json lag_cert(const std::string& K, bool stable) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability"},
          {"model", {{"plant", "1/(s + 1)"}, {"H", "K"}, {"set", {{"K", K}}}, {"T", "1"}, {"delay", 0}}},
          {"claim", {{"status", "certified"}, {"stable", stable}}}, {"evidence", nlohmann::json::object()}};
}

TEST(StabilityCheck, OnePoleOffZeroByHand) {
  const auto two = check_certificate(lag_cert("2", true));
  EXPECT_TRUE(two.verified) << two.reason;
  EXPECT_NE(two.reason.find("E = e^(-1)"), std::string::npos) << two.reason;
  EXPECT_TRUE(check_certificate(lag_cert("3", false)).verified);
  EXPECT_TRUE(check_certificate(lag_cert("2163953/1000000", true)).verified);   // 1e-7 below the boundary
  EXPECT_TRUE(check_certificate(lag_cert("2163954/1000000", false)).verified);  // 1e-7 above it
  EXPECT_FALSE(check_certificate(lag_cert("2", false)).verified);
  EXPECT_FALSE(check_certificate(lag_cert("3", true)).verified);
  auto with_poly = lag_cert("2", true);
  with_poly["evidence"]["charpoly"] = {"1", "1"};
  EXPECT_THROW(check_certificate(with_poly), InputError);  // no rational polynomial to hand over
  auto exact = lag_cert("2", true);
  exact["claim"]["status"] = "exact";
  EXPECT_THROW(check_certificate(exact), InputError);
  auto three = lag_cert("2", true);
  three["model"]["plant"] = "1/(s^3 + s^2 + s + 1)";  // three poles off s = 0: beyond this checker
  EXPECT_THROW(check_certificate(three), InputError);
}

// Two poles off s = 0 (check/loop_model.hpp): the undamped spring 1/(s^2 + 1) at T = 1, H = K. By
// hand: Phi = [[cos 1, sin 1], [-sin 1, cos 1]], R = -s (R0 = 0, R1 = -1), Q = 1, Ndp = 0, so P_d =
// (1 - cos 1)(z + 1)/(z^2 - 2 cos(1) z + 1) (the ZOH table) and c = z^2 - 2 cos(1) z + 1 + K (1 - cos 1)(z + 1);
// Jury (|a0| < 1, |a1| < 1 + a0) holds iff -1 < K < 0. At K = 0 the roots e^{+-j} are on the circle:
// no enclosure decides, and the checker says so rather than guess.
nlohmann::json spring_cert(const std::string& K, bool stable) {
  auto c = lag_cert(K, stable);
  c["model"]["plant"] = "1/(s^2 + 1)";
  return c;
}

TEST(StabilityCheck, SpringByHand) {
  for (const auto& [K, st] : std::vector<std::pair<std::string, bool>>{
           {"-1/2", true}, {"1/1000", false}, {"-999/1000", true}, {"-1001/1000", false}, {"-1/1000000", true}}) {
    const auto v = check_certificate(spring_cert(K, st));
    EXPECT_TRUE(v.verified) << K << ": " << v.reason;
    EXPECT_FALSE(check_certificate(spring_cert(K, !st)).verified) << K;
  }
  EXPECT_NE(check_certificate(spring_cert("-1/2", true)).reason.find("e^{A_c T}"), std::string::npos);
  EXPECT_THROW(check_certificate(spring_cert("0", true)), InputError);  // roots on the circle: undecidable
  // a wall -4 cancels the spring 4 of 1/(s^2 + s + 4): c(1) = det(I - Phi) (1 + H(1) P(0)) = 0 exactly
  auto cancelled = spring_cert("-4", false);
  cancelled["model"]["plant"] = "1/(s^2 + s + 4)";
  EXPECT_TRUE(check_certificate(cancelled).verified) << check_certificate(cancelled).reason;
  cancelled["claim"]["stable"] = true;
  EXPECT_FALSE(check_certificate(cancelled).verified);
  cancelled["evidence"]["argument_principle"] = true;
  EXPECT_FALSE(check_certificate(cancelled).verified);
  cancelled["claim"]["stable"] = false;
  EXPECT_TRUE(check_certificate(cancelled).verified);
  auto with_poly = spring_cert("-1/2", true);
  with_poly["evidence"]["charpoly"] = {"1", "1"};
  EXPECT_THROW(check_certificate(with_poly), InputError);
  auto damped = spring_cert("1", true);  // a double pole at s = -1 (Phi not diagonalisable), H = 1: stable,
  damped["model"]["plant"] = "1/(s^2 + 2*s + 1)";  // spectral radius 0.520260095022889 (the loop built in mpmath)
  EXPECT_TRUE(check_certificate(damped).verified);
}

// evidence.argument_principle (z^n never expanded): the delayed integrator 1/s behind a ZOH at T = 1
// under H = K, c = z^n (z - 1) + K, is stable iff 0 < K < K* = 2 sin(pi/(2 (2n + 1))) (on the circle
// |z - 1| = K and (n + 1/2) theta + pi/2 = pi: theta = pi/(2n + 1)); n = 50: K* = 0.0311036238407017...
nlohmann::json integrator_cert(const std::string& K, bool stable, long n = 50) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability"},
          {"model", {{"plant", "1/s"}, {"H", "K"}, {"set", {{"K", K}}}, {"T", "1"}, {"delay", n}}},
          {"claim", {{"status", "certified"}, {"stable", stable}}}, {"evidence", {{"argument_principle", true}}}};
}

TEST(StabilityCheck, ArgumentPrincipleByHand) {
  for (const auto& [K, st] : std::vector<std::pair<std::string, bool>>{
           {"31/1000", true}, {"312/10000", false}, {"3110362/100000000", true}, {"3110363/100000000", false}, {"-1/100", false}}) {
    const auto v = check_certificate(integrator_cert(K, st));
    EXPECT_TRUE(v.verified) << K << ": " << v.reason;
    EXPECT_FALSE(check_certificate(integrator_cert(K, !st)).verified) << K;
  }
  EXPECT_NE(check_certificate(integrator_cert("31/1000", true)).reason.find("51 of the 51 roots inside"), std::string::npos);
  EXPECT_TRUE(check_certificate(integrator_cert("0", false)).verified);  // c(1) = 0: a root on the circle, exactly
  EXPECT_TRUE(check_certificate(integrator_cert("3/10000", true, 5000)).verified);  // K* = 3.1413e-4 at n = 5000
  auto exact = integrator_cert("31/1000", true);
  exact["claim"]["status"] = "exact";
  EXPECT_THROW(check_certificate(exact), InputError);
  auto flag = integrator_cert("31/1000", true);
  flag["evidence"]["argument_principle"] = false;
  EXPECT_THROW(check_certificate(flag), InputError);
  // poles off s = 0 too (e^{pT}, e^{A_c T} in balls): the same verdicts as the resultant (a
  // mass-damper) and interval Schur-Cohn (a spring) paths, on both sides of their boundaries
  for (const std::string plant : {"1/(s + 1)", "1/(s*(s + 1/2))", "1/(s^2 + s + 4)", "1/(s^2 - 1/4)"})
    for (const std::string K : {"1/100", "1/20", "1/5", "2/3", "3/2"}) {
      auto winding = integrator_cert(K, true, 12);
      winding["model"]["plant"] = plant;
      nlohmann::json other = winding;
      other["evidence"] = nlohmann::json::object();
      const bool st = check_certificate(other).verified;  // the no-evidence paths' verdict
      if (!st) other["claim"]["stable"] = false, winding["claim"]["stable"] = false;
      EXPECT_TRUE(check_certificate(other).verified) << plant << " K = " << K;
      const auto v = check_certificate(winding);
      EXPECT_TRUE(v.verified) << plant << " K = " << K << ": " << v.reason;
    }
}

TEST(StabilityCheck, RefusesWhatItCannotModel) {
  auto expect_field = [](const nlohmann::json& j, const std::string& field) {
    try {
      check_certificate(j);
      ADD_FAILURE() << "accepted: " << j.dump();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  const std::vector<std::string> c{"-1/1000", "2001/2000", "-3997/2000", "1"};
  expect_field(stability_cert("1/(m*s^2 + s)", "K + B*(z-1)/(T*z)", 0, true, c), "pole off s = 0");
  expect_field(stability_cert("1/m", "K", 0, true, c), "not strictly proper");
  expect_field(stability_cert("1/(m*s^2)", "K*z^2", 0, true, c), "not causal");
  auto d = stability_cert("1/(m*s^2)", "K", 0, true, c);
  d["model"]["frac_delay"] = "1/2000";
  expect_field(d, "model.frac_delay");
  d = stability_cert("1/(m*s^2)", "K", 0, true, c);
  d["claim"]["stable"] = "yes";
  expect_field(d, "claim.stable");
}

// A scene as the model (check/scene_model.hpp): MassOnAVirtualWall's loop written as a one-DOF scene,
// K given by a parameter defined from another and overridden by model.set; the checker reads the
// loop from the text itself (the derived model is the --plant/--H one), and the same charpoly is
// the evidence. What the reading does not model is refused by name.
nlohmann::json scene_cert(const std::string& scene, bool stable, const nlohmann::json& set = nlohmann::json::object()) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability"}, {"model", {{"scene", scene}, {"set", set}}},
          {"claim", {{"status", "exact"}, {"stable", stable}}},
          {"evidence", {{"charpoly", {"-1/1000", "2001/2000", "-3997/2000", "1"}}}}};
}

const char* const kWallScene = R"toml([scene]
name = "mass on a wall"
T = "1/1000"
[parameters]
k = "7"
K = "k*1000"
B = 2
[[device]]
name = "arm"
m = "1"
[environment]
tf = "K + B*(z-1)/(T*z)"
[[input]]
type = "impulse"
magnitude = "1"
)toml";

TEST(StabilityCheck, SceneByHand) {
  const nlohmann::json set{{"k", "1"}};
  const auto ok = check_certificate(scene_cert(kWallScene, true, set));
  EXPECT_TRUE(ok.verified) << ok.reason;
  EXPECT_FALSE(check_certificate(scene_cert(kWallScene, false, set)).verified);
  EXPECT_FALSE(check_certificate(scene_cert(kWallScene, true)).verified);  // k = 7: another loop, another polynomial
  const nlohmann::json m = detail::scene_loop_model(scene_cert(kWallScene, true, set)["model"]);
  EXPECT_EQ(m["plant"], "1/((1)*s^2 + (0)*s)");
  EXPECT_EQ(m["H"], "(1)*(((1)*1000) + (2)*(z-1)/(T*z))");
  EXPECT_EQ(m["T"], "1/1000");
  EXPECT_EQ(m["delay"], 0);
  // Tustin of K + B s, an operator m, b, k, a delay in time
  std::string s = kWallScene;
  const std::string wall_tf = "tf = \"K + B*(z-1)/(T*z)\"";
  s.replace(s.find(wall_tf), wall_tf.size(), "domain = \"s\"\nmethod = \"tustin\"\ntf = \"K + B*s\"\n[delay]\ntime = \"2*T\"");
  s += "[[operator]]\ndofs = \"arm\"\nm = \"1/10\"\nk = \"40\"\n";
  const nlohmann::json t = detail::scene_loop_model(scene_cert(s, true)["model"]);
  EXPECT_EQ(t["H"], "(1)*(((7)*1000) + (2)*(2*(z-1)/(T*(z+1))))") << t.dump();
  EXPECT_EQ(t["operator"], "(1/10)*s + (0) + (40)/s");
  EXPECT_EQ(t["delay"], 2);
  auto refused = [](const std::string& text, const nlohmann::json& set, const std::string& field) {
    try {
      detail::scene_loop_model(scene_cert(text, true, set)["model"]);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  const std::string w = kWallScene;
  refused(w + "[coupling]\ntf = \"1\"\n", set, "[coupling]");
  refused(w + "[contact]\n", set, "[contact]");
  refused(w + "[delay]\nsamples = \"3/2\"\n", set, "not a whole number");
  refused(w + "[[device]]\nname = \"second\"\nm = \"1\"\n", set, "2 tables");
  refused(w, {{"kk", "1"}}, "model.set.kk");
  std::string cycle = w;
  cycle.replace(cycle.find("k = \"7\""), 7, "k = \"K\"");  // k and K name each other
  refused(cycle, nlohmann::json::object(), "cycle");
  std::string ss = w;
  ss.replace(ss.find("m = \"1\""), 7, "ss = { A = [[\"0\"]], B = [[\"1\"]], C = [[\"1\"]], D = [[\"0\"]] }");
  refused(ss, set, "device.ss");
  refused("[scene]\nT = \"1/1000\"\n", nlohmann::json::object(), "[[device]]");
  refused("not toml = = 1", set, "not TOML");
}

// The closed loop of a stability-loop certificate (check/stability_loop_check.hpp), by hand: one mass
// m = 2 under a spring wall E = K = 100, T = 1/10, no delay. The state (v, x): Phi = [[1, 0], [T, 1]],
// Gamma = [T/m; T^2/(2m)], u = -K x, so M = [[1, -K T/m], [T, 1 - K T^2/(2m)]] = [[1, -5], [1/10, 3/4]]
// (det M = 3/4 + 1/2 = 5/4 > 1: NOT stable, the sampled spring on a mass). With b = 1: Phi's first
// column is (e^{-bT/m}, (m/b)(1 - e^{-bT/m})). With a delay of one sample the force moves to a buffer;
// with a coupling the wall sees x + V u.
TEST(StabilityLoopCheck, ClosedLoopByHand) {
  const std::string scene = "[scene]\nT = \"1/10\"\n[[device]]\nname = \"a\"\nm = \"2\"\n[environment]\ntf = \"100\"\n";
  const nlohmann::json model{{"scene", scene}, {"set", nlohmann::json::object()}};
  const auto M = scene_loop_matrix(model, 128);
  ASSERT_EQ(M.size(), 2u);
  const rational want[2][2] = {{rational(1), rational(-5)}, {rational(1, 10), rational(3, 4)}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      EXPECT_LE(M[i][j].first, want[i][j]);
      EXPECT_GE(M[i][j].second, want[i][j]);
      EXPECT_LT(rational(M[i][j].second - M[i][j].first), rational(1, 1000000000));
    }
  std::string damped = scene;
  damped.replace(damped.find("m = \"2\""), 7, "m = \"2\"\nb = \"1\"");
  const auto D = scene_loop_matrix({{"scene", damped}, {"set", nlohmann::json::object()}}, 128);
  const double e = std::exp(-0.05);  // e^{-bT/m}
  EXPECT_NEAR(D[0][0].first.convert_to<double>(), e, 1e-12);  // M[0][0] = Phi[0][0] (the force depends on x only)
  EXPECT_NEAR(D[1][0].first.convert_to<double>(), 2 * (1 - e), 1e-12);
  std::string delayed = scene + "[delay]\nsamples = 1\n";
  const auto Dl = scene_loop_matrix({{"scene", delayed}, {"set", nlohmann::json::object()}}, 128);
  ASSERT_EQ(Dl.size(), 3u);  // (v, x, u_{k-1})
  EXPECT_EQ(Dl[2][1].first, rational(-100));  // u_k = -K x_k
  EXPECT_LE(Dl[0][2].first, rational(1, 20));  // Gamma_v = T/m
  EXPECT_GE(Dl[0][2].second, rational(1, 20));
  // the same device as ss with the velocity as its state: the same M; as tf = "1/(2*s)", realised with
  // the state 2 v (1/(2s) = (1/2)/s: B = 1, C = 1/2), so M in that basis: [[1, -10], [1/20, 3/4]]
  const std::pair<std::string, std::vector<rational>> forms[] = {
      {"ss = { A = [[\"0\"]], B = [[\"1/2\"]], C = [[\"1\"]], D = [[\"0\"]] }", {1, -5, rational(1, 10), rational(3, 4)}},
      {"tf = \"1/(2*s)\"", {1, -10, rational(1, 20), rational(3, 4)}}};
  for (const auto& [dev, entries] : forms) {
    std::string other = scene;
    other.replace(other.find("m = \"2\""), 7, dev);
    const auto Mo = scene_loop_matrix({{"scene", other}, {"set", nlohmann::json::object()}}, 128);
    ASSERT_EQ(Mo.size(), 2u) << dev;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        EXPECT_LE(Mo[i][j].first, entries[size_t(2 * i + j)]) << dev;
        EXPECT_GE(Mo[i][j].second, entries[size_t(2 * i + j)]) << dev;
      }
  }
  // a coupling V = 1/100 (a spring's compliance) in parallel: x_e = x + V u, u = -K x_e, so
  // u = -K/(1 + K V) x = -50 x and M = [[1, -5/2], [1/10, 7/8]]
  const auto Cp = scene_loop_matrix({{"scene", scene + "[coupling]\ntf = \"1/100\"\n"}, {"set", nlohmann::json::object()}}, 128);
  ASSERT_EQ(Cp.size(), 2u);
  const rational coupled[2][2] = {{rational(1), rational(-5, 2)}, {rational(1, 10), rational(7, 8)}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      EXPECT_LE(Cp[i][j].first, coupled[i][j]);
      EXPECT_GE(Cp[i][j].second, coupled[i][j]);
    }
}

// A P that proves the hand loop above NOT stable: M^T P M - P = -I solved for M = [[1, -5], [1/10, 3/4]]
// is indefinite; the checker verifies P - M^T P M > 0 over M's enclosure and w^T P w < 0. A P for
// another loop, the claim flipped, and scenes beyond the reading are refused or refuted.
TEST(StabilityLoopCheck, SteinCertificateByHand) {
  const std::string scene = "[scene]\nT = \"1/10\"\n[[device]]\nname = \"a\"\nm = \"2\"\n[environment]\ntf = \"100\"\n";
  // P - M^T P M = I exactly for this P (both eigenvalues of M have |z| = sqrt(5)/2 > 1: P < 0)
  nlohmann::json cert{{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability-loop"},
                      {"model", {{"scene", scene}, {"set", nlohmann::json::object()}}},
                      {"claim", {{"status", "certified"}, {"stable", false}}},
                      {"evidence", {{"P", nlohmann::json::array({nlohmann::json::array({"-1461/800", "29/40"}), nlohmann::json::array({"29/40", "-229/2"})})},
                                    {"w", nlohmann::json::array({"1", "0"})}}}};
  const auto v = check_certificate(cert);
  EXPECT_TRUE(v.verified) << v.reason;
  auto flipped = cert;
  flipped["claim"]["stable"] = true;
  flipped["evidence"].erase("w");
  EXPECT_FALSE(check_certificate(flipped).verified);
  auto other = cert;
  other["model"]["scene"] = "[scene]\nT = \"1/10\"\n[[device]]\nname = \"a\"\nm = \"2\"\nb = \"40\"\n[environment]\ntf = \"100\"\n";
  EXPECT_FALSE(check_certificate(other).verified);  // a damped loop: this P does not prove it
  for (const auto& [edit, field] : std::vector<std::pair<std::string, std::string>>{
           {"[contact]\n", "[contact]"}, {"[delay]\nsamples = \"1/2\"\n", "not a whole number"},
           {"[[operator]]\ntf = \"1/s\"\n", "pole at s = 0"}}) {
    auto c = cert;
    c["model"]["scene"] = scene + edit;
    try {
      check_certificate(c);
      ADD_FAILURE() << "accepted: " << edit;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

// Res(f, g) = lc(f)^deg g prod_{f(a) = 0} g(a): Res(z - 2, z - 5) = -3; Res_{d,d}(c, c*) with
// c* = z^d c(1/z): c = z - 1/2, c* = 1 - z/2, Res = c*(1/2) = 3/4; c = z^2 (c* = 1, formal degree 2):
// lc^2 c*(0)^2 = 1; c = z - 1 (a root on the circle): 0.
TEST(Reciprocal, ResultantsByHand) {
  const P x{rational(0), rational(1)};
  EXPECT_EQ(detail::resultant(x - rational(2), x - rational(5)), rational(-3));
  EXPECT_EQ(detail::resultant(x * x - rational(1), x - rational(2)), rational(3));  // g(1) g(-1) = (-1)(-3)
  EXPECT_EQ(detail::reciprocal_resultant(x - rational(1, 2)), rational(3, 4));
  EXPECT_EQ(detail::reciprocal_resultant(x * x), rational(1));
  EXPECT_EQ(detail::reciprocal_resultant(x - rational(1)), rational(0));
  EXPECT_EQ(detail::reciprocal_resultant((x - rational(2)) * (x - rational(1, 2))), rational(0));  // 2, 1/2
}

// The family of the mass 1/(m s^2) on K + B (z - 1)/(T z), delay 0: c = z (z - 1)^2 + g (z + 1)((K + B/T) z - B/T),
// g = T^2/(2 m); by hand (the Sylvester determinant of c and c*, factored),
//   D(K) = K T^4 (4 B m - 2 B^2 T - K T (2 m + B T))^2 / (4 m^5),
// so for m = 1, T = 1/1000, B = 2: D = K (1001 K - 3996000)^2 / 10^24.
TEST(Reciprocal, WallFamilyByHand) {
  const P z{rational(0), rational(1)}, g(rational(1, 2000000));
  const P c0 = z * (z - rational(1)) * (z - rational(1)) + g * (z + rational(1)) * (z * rational(2000) - rational(2000));
  const P c1 = g * (z + rational(1)) * z;
  const P K{rational(0), rational(1)};
  const P f = K * rational(1001) - rational(3996000);
  rational scale(1);
  for (int i = 0; i < 24; ++i) scale /= 10;
  EXPECT_EQ(detail::reciprocal_resultant(c0, c1), K * f * f * P(scale));
  EXPECT_EQ(detail::roots_between(K * f * f, rational(0), rational(3996000, 1001), false), 0);
  EXPECT_EQ(detail::roots_between(K * f * f, rational(0), rational(3996000, 1001), true), 1);
  EXPECT_EQ(detail::roots_between(K * f * f, rational(0), std::nullopt, false), 1);
  EXPECT_EQ(detail::roots_between(K, rational(0), std::nullopt, false), 0);
}

nlohmann::json smax_cert(const nlohmann::json& claim, const nlohmann::json& evidence, int delay = 0,
                         const std::string& H = "K + B*(z-1)/(T*z)", const nlohmann::json& set = {{"m", "1"}, {"B", "2"}}) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "stability-max"},
          {"model", {{"plant", "1/(m*s^2)"}, {"H", H}, {"set", set}, {"name", "K"}, {"T", "1/1000"}, {"delay", delay}}},
          {"claim", claim}, {"evidence", evidence}};
}

// Delay 0: the loop is stable iff 0 < K < (2B/T)(2m - BT)/(2m + BT) (Jury's conditions for the
// cubic; docs/stability.md), so K_max = 3996000/1001 exactly for m = 1, T = 1/1000, B = 2 -- a root
// pair meets the circle there (the double root of D above), at a rational K.
TEST(StabilityMaxCheck, WallWithoutDelayExact) {
  const nlohmann::json at{{"stable_at", "1000"}};
  const Verdict ok = check_certificate(smax_cert({{"status", "exact"}, {"value", "3996000/1001"}}, at));
  EXPECT_TRUE(ok.verified) << ok.reason;
  const Verdict above = check_certificate(smax_cert({{"status", "exact"}, {"value", "3996001/1001"}}, at));
  EXPECT_FALSE(above.verified);
  EXPECT_NE(above.reason.find("has 1 root(s) in (0, "), std::string::npos) << above.reason;
  const Verdict below = check_certificate(smax_cert({{"status", "exact"}, {"value", "3995999/1001"}}, at));
  EXPECT_FALSE(below.verified);
  EXPECT_NE(below.reason.find("is stable"), std::string::npos) << below.reason;
  // the evidence point must lie in (0, lo), and the loop must be stable there
  EXPECT_FALSE(check_certificate(smax_cert({{"status", "exact"}, {"value", "3996000/1001"}}, {{"stable_at", "3996000/1001"}})).verified);
  EXPECT_FALSE(check_certificate(smax_cert({{"status", "exact"}, {"value", "3996000/1001"}}, {{"stable_at", "0"}})).verified);
  // never +inf: as K grows a root goes to infinity (deg c1 < deg c0); D has the root 3996000/1001
  const Verdict inf = check_certificate(smax_cert({{"status", "certified"}, {"infinite", true}}, at));
  EXPECT_FALSE(inf.verified);
  EXPECT_NE(inf.reason.find("(0, inf)"), std::string::npos) << inf.reason;
}

// Delay 1: D(K) = K T^4 (2 m T^3 K^2 + (B^2 T^3 + 12 m^2 T) K + 2 B^3 T^2 + 8 B^2 T m - 8 B m^2)^2/(16 m^7)
// (the same determinant), so K_max is the positive root of K^2 + 6000002 K - 7983992000 for m = 1,
// T = 1/1000, B = 2: K_max = sqrt(9007989992001) - 3000001 = 1330.36990919414872...
TEST(StabilityMaxCheck, WallWithOneSampleDelayEnclosure) {
  auto claim = [](const char* lo, const char* hi) { return nlohmann::json{{"status", "certified"}, {"lo", lo}, {"hi", hi}}; };
  const nlohmann::json at{{"stable_at", "1"}};
  const Verdict ok = check_certificate(smax_cert(claim("1330369/1000", "133037/100"), at, 1));
  EXPECT_TRUE(ok.verified) << ok.reason;
  EXPECT_FALSE(check_certificate(smax_cert(claim("133037/100", "1330371/1000"), at, 1)).verified);   // lo past the root
  EXPECT_FALSE(check_certificate(smax_cert(claim("1330368/1000", "1330369/1000"), at, 1)).verified);  // hi below it
  // the delay-0 value claimed for the delay-1 loop (a producer that dropped the delay)
  EXPECT_FALSE(check_certificate(smax_cert({{"status", "exact"}, {"value", "3996000/1001"}}, {{"stable_at", "1000"}}, 1)).verified);
  // printed decimals must be the claimed numbers
  auto printed = smax_cert(claim("1330369/1000", "133037/100"), at, 1);
  printed["claim"]["printed_lo"] = "1330.369";
  printed["claim"]["printed_hi"] = "1330.371";
  EXPECT_FALSE(check_certificate(printed).verified);
}

// Not stable at small K: a spring alone on the sampled mass (B = 0): c = (z - 1)^2 + a (z + 1) with
// a = K T^2/2, c(0)/lc = 1 + a > 1, NOT stable for every K > 0, and D = K T^4 (2 K T m)^2/(4 m^5) has
// no positive root: K_max = 0. A damper gain K (z - 1)/(T z) leaves the mass's root at z = 1 for every
// K: D = 0 identically, K_max = 0.
TEST(StabilityMaxCheck, NotStableAtSmallGains) {
  for (int delay : {0, 1}) {
    const Verdict v = check_certificate(smax_cert({{"status", "exact"}, {"value", "0"}}, {{"unstable_at", "1"}}, delay, "K + B*(z-1)/(T*z)",
                                                  {{"m", "1"}, {"B", "0"}}));
    EXPECT_TRUE(v.verified) << v.reason;
  }
  const Verdict fixed = check_certificate(smax_cert({{"status", "exact"}, {"value", "0"}}, {{"unstable_at", "5"}}, 0, "K*(z-1)/(T*z)", {{"m", "1"}}));
  EXPECT_TRUE(fixed.verified) << fixed.reason;
  EXPECT_NE(fixed.reason.find("D = 0 identically"), std::string::npos) << fixed.reason;
  // K_max = 0 claimed for the stable wall: stable at 1, or (above the crossing) D has a root below
  EXPECT_FALSE(check_certificate(smax_cert({{"status", "exact"}, {"value", "0"}}, {{"unstable_at", "1"}})).verified);
  const Verdict past = check_certificate(smax_cert({{"status", "exact"}, {"value", "0"}}, {{"unstable_at", "5000"}}));
  EXPECT_FALSE(past.verified);
  EXPECT_NE(past.reason.find("root(s) in (0, 5000]"), std::string::npos) << past.reason;
}

TEST(StabilityMaxCheck, MalformedNamesTheField) {
  auto expect_field = [](const nlohmann::json& j, const std::string& field) {
    try {
      const Verdict v = check_certificate(j);
      ADD_FAILURE() << "not refused as malformed: " << v.reason;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  const nlohmann::json claim{{"status", "exact"}, {"value", "3996000/1001"}}, at{{"stable_at", "1000"}};
  expect_field(smax_cert(claim, at, 0, "K*K + B*(z-1)/(T*z)"), "not affine");
  expect_field(smax_cert(claim, at, 0, "K + B*(z-1)/(T*z)", {{"m", "1"}, {"B", "2"}, {"K", "1"}}), "model.set");
  expect_field(smax_cert(claim, {{"stable_at", "1000"}, {"unstable_at", "1"}}), "evidence.unstable_at");
  expect_field(smax_cert(claim, nlohmann::json::object()), "evidence.stable_at");
  auto c = smax_cert(claim, at);
  c["model"]["plant"] = "1/((m + K)*s^2)";
  expect_field(c, "model.plant");
  c = smax_cert(claim, at);
  c["model"]["plant"] = "1/(m*s^2 + s)";
  expect_field(c, "pole off s = 0");
  c = smax_cert(claim, at);
  c["model"].erase("name");
  expect_field(c, "model.name");
  c = smax_cert(claim, at);
  c["model"]["H"] = "K*z^2";
  expect_field(c, "not causal");
}

TEST(MaxPositive, KnownSigns) {
  const P x{rational(0), rational(1)};
  EXPECT_TRUE(max_positive_on(x, -x, m1, p1));                                   // |c| = 0 at c = 0
  EXPECT_FALSE(max_positive_on(p1 + x, p1 - x, m1, p1));                         // 1 + |c|
  EXPECT_TRUE(max_positive_on(x * x - rational(1, 4), x * x - rational(1, 4), m1, p1));
  EXPECT_FALSE(max_positive_on(x * x + rational(1, 4), P(rational(-1)), m1, p1));
  // both <= 0 on [1/2, 1/sqrt(3)] (an end irrational)
  EXPECT_TRUE(max_positive_on(x * x - rational(1, 3), rational(1, 2) - x, m1, p1));
  EXPECT_TRUE(max_positive_on(P(), P(), m1, p1));
  // non-strict (max >= 0): an end where both vanish passes by itself but stands for no cell -- the
  // first mutation campaign of the wedge's gains found this accepted: -(1 + c) < 0 inside
  const P v = -(x + p1);
  EXPECT_TRUE(max_positive_on(v, v, m1, p1, false));
  EXPECT_TRUE(max_positive_on(v * (x - rational(1, 2)), v, m1, p1, false));
  EXPECT_FALSE(max_positive_on(-v, -v, m1, p1, false));             // 1 + c >= 0
  EXPECT_FALSE(max_positive_on(x * x, -x * x, m1, p1, false));      // >= 0 with a double root
  EXPECT_TRUE(max_positive_on(x, -x - rational(1, 2), m1, p1, false));  // both < 0 on (-1/2, 0)
}

nlohmann::json wedge_cert(const std::string& H, const std::string& K, std::vector<bool> claims) {
  nlohmann::json claim{{"status", "exact"}};
  const char* keys[] = {"wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative"};
  for (size_t i = 0; i < 5; ++i) claim[keys[i]] = static_cast<bool>(claims[i]);
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "wedge"},
          {"model", {{"H", H}, {"set", {{"K", K}}}, {"T", "1"}}}, {"claim", claim}, {"evidence", nlohmann::json::object()}};
}

// H = K/z: Re H = K cos(theta), Im H = -K sin(theta); (25) is |K| (1 + cos) + K cos + 1 and (21)
// K cos + 1, both with minimum 1 - K at theta = pi for K > 0: they hold iff K < 1; (1 + H)^-1 has
// its pole at z = -K; H(1) = K.
TEST(WedgeCheck, OneSampleDelay) {
  auto verified = [](const nlohmann::json& c) {
    const Verdict v = check_certificate(c);
    EXPECT_TRUE(v.verified) << v.reason;
    return v.verified;
  };
  verified(wedge_cert("K/z", "1/2", {true, true, true, true, true}));
  verified(wedge_cert("K/z", "1", {false, false, true, false, true}));  // margin exactly 0 at theta = pi
  verified(wedge_cert("K/z", "2", {false, false, true, false, true}));
  verified(wedge_cert("K/z", "-1/2", {true, true, true, true, false}));  // 3/2 and 1 - cos/2
  verified(wedge_cert("K", "3", {true, true, true, true, true}));
  const Verdict wrong = check_certificate(wedge_cert("K/z", "1", {true, false, true, false, true}));
  EXPECT_FALSE(wrong.verified);
  EXPECT_NE(wrong.reason.find("claim.wedge"), std::string::npos) << wrong.reason;
  EXPECT_THROW(check_certificate(wedge_cert("K/(z - 1)", "1", {true, true, true, true, true})), InputError);
  EXPECT_THROW(check_certificate(wedge_cert("K*z", "1", {true, true, true, true, true})), InputError);  // not causal
}

// The margins and gains k* of H = K/z (above): K = 1/2: the wedge's left side is 1/2 + cos(theta),
// min -1/2 at theta = pi, so its margin (min + 1) is 1/2 and k* = -1/(-1/2) = 2; Tsypkin's is
// cos(theta)/2, margin 1/2, k* = 2. K = -1/2: the wedge's left side is 1/2 at every theta (margin
// 3/2, k* = +inf); Tsypkin's -cos(theta)/2, min -1/2 at theta = 0 (c = 1): margin 1/2, k* = 2.
nlohmann::json margins(nlohmann::json c, const nlohmann::json& wm, const nlohmann::json& wg, const nlohmann::json& tm,
                       const nlohmann::json& tg, const std::string& wc, const std::string& tc) {
  c["claim"]["wedge_margin"] = wm;
  c["claim"]["wedge_gain"] = wg;
  c["claim"]["tsypkin_margin"] = tm;
  c["claim"]["tsypkin_gain"] = tg;
  if (!wc.empty()) c["evidence"]["wedge_witness_c"] = wc;
  if (!tc.empty()) c["evidence"]["tsypkin_witness_c"] = tc;
  return c;
}
nlohmann::json range(const std::string& lo, const std::string& hi, const std::string& printed = "") {
  nlohmann::json r{{"lo", lo}, {"hi", hi}};
  if (!printed.empty()) r["printed"] = printed;
  return r;
}

TEST(WedgeCheck, MarginsAndGainsByHand) {
  const nlohmann::json half = wedge_cert("K/z", "1/2", {true, true, true, true, true});
  const nlohmann::json inf{{"infinite", true}};
  auto verdict = [](const nlohmann::json& c) { return check_certificate(c); };
  Verdict v = verdict(margins(half, range("1/2", "1/2", "0.5"), range("2", "2", "2"), range("1/2", "1/2", "0.5"), range("2", "2", "2"), "-1", "-1"));
  EXPECT_TRUE(v.verified) << v.reason;
  v = verdict(margins(half, range("49/100", "51/100", "0.5"), range("19/10", "21/10", "2"), range("1/2", "1/2"), range("2", "2"), "-1/2", "-1"));
  EXPECT_FALSE(v.verified);  // c0 = -1/2: the wedge's left side + 1 is 1 there, not <= 51/100
  EXPECT_NE(v.reason.find("witness"), std::string::npos) << v.reason;
  v = verdict(margins(half, range("51/100", "52/100"), range("2", "2"), range("1/2", "1/2"), range("2", "2"), "-1", "-1"));
  EXPECT_FALSE(v.verified);  // above the margin
  EXPECT_NE(v.reason.find("wedge_margin"), std::string::npos) << v.reason;
  v = verdict(margins(half, range("1/2", "1/2", "0.6"), range("2", "2"), range("1/2", "1/2"), range("2", "2"), "-1", "-1"));
  EXPECT_FALSE(v.verified);  // the printed decimal is not the margin rounded
  EXPECT_NE(v.reason.find("printed"), std::string::npos) << v.reason;
  v = verdict(margins(half, range("1/2", "1/2"), inf, range("1/2", "1/2"), range("2", "2"), "-1", "-1"));
  EXPECT_FALSE(v.verified);  // k* = +inf needs the left side >= 0; it is -1/2 at theta = pi
  v = verdict(margins(half, range("1/2", "1/2"), range("2", "3"), range("1/2", "1/2"), range("21/10", "3"), "-1", "-1"));
  EXPECT_FALSE(v.verified);  // Tsypkin's k* >= 21/10 fails
  EXPECT_NE(v.reason.find("tsypkin_gain"), std::string::npos) << v.reason;

  const nlohmann::json neg = wedge_cert("K/z", "-1/2", {true, true, true, true, false});  // H(1) = -1/2
  v = verdict(margins(neg, range("3/2", "3/2", "1.5"), inf, range("1/2", "1/2", "0.5"), range("2", "2", "2"), "0", "1"));
  EXPECT_TRUE(v.verified) << v.reason;
  v = verdict(margins(neg, range("3/2", "3/2"), range("1", "100"), range("1/2", "1/2"), range("2", "2"), "0", "1"));
  EXPECT_FALSE(v.verified);  // a finite k* claimed where the left side is 1/2 everywhere
  EXPECT_THROW(check_certificate(margins(half, range("1/2", "1/2"), range("2", "2"), range("1/2", "1/2"), range("2", "2"), "", "-1")),
               InputError);  // the wedge's witness missing
  EXPECT_THROW(check_certificate(margins(half, range("1/2", "1/2"), range("0", "2"), range("1/2", "1/2"), range("2", "2"), "-1", "-1")),
               InputError);  // k* lo = 0
  EXPECT_THROW(check_certificate(margins(half, range("1/2", "1/2", "x"), range("2", "2"), range("1/2", "1/2"), range("2", "2"), "-1", "-1")),
               InputError);  // printed not a decimal
}

nlohmann::json inf_cert(const std::string& H, const std::string& K, int delay, const std::string& pole, int side) {
  nlohmann::json c = bound_cert(H, K, "1/1000", delay, {{"status", "exact"}, {"infinite", true}}, "0");
  c["evidence"] = {{"pole_c", pole}, {"side", side}};
  return c;
}

// b* = +inf by hand. H = K z/(z^2 + 1): on the circle z/(z^2 + 1) = 1/(2c), real, and
// Re{1/(1 - z)} = 1/2, so f = T K/(4c) (n = 0) and T K (1 + 2c)/(4c) (n = 1): +inf as c -> 0 from
// above when K > 0, -inf from below. H = K/(z - 1): f = -T K Re{1/(z - 1)^2} = T K c/(2(1 - c)),
// +inf as c -> 1 from below when K > 0 (no band above c = 1).
TEST(BoundCheck, InfiniteByHand) {
  for (int n : {0, 1}) {
    const Verdict up = check_certificate(inf_cert("K*z/(z^2 + 1)", "3", n, "0", 1));
    EXPECT_TRUE(up.verified) << up.reason;
    const Verdict down = check_certificate(inf_cert("K*z/(z^2 + 1)", "3", n, "0", -1));
    EXPECT_FALSE(down.verified);
    EXPECT_NE(down.reason.find("-inf"), std::string::npos) << down.reason;
    EXPECT_TRUE(check_certificate(inf_cert("K*z/(z^2 + 1)", "-3", n, "0", -1)).verified);
    EXPECT_FALSE(check_certificate(inf_cert("K*z/(z^2 + 1)", "-3", n, "0", 1)).verified);  // the sign flip
  }
  EXPECT_TRUE(check_certificate(inf_cert("K/(z - 1)", "2", 0, "1", -1)).verified);
  EXPECT_FALSE(check_certificate(inf_cert("K/(z - 1)", "-2", 0, "1", -1)).verified);
  EXPECT_FALSE(check_certificate(inf_cert("K/(z - 1)", "2", 0, "1", 1)).verified);    // no band above c = 1
  EXPECT_FALSE(check_certificate(inf_cert("K/(z - 1)", "2", 0, "1/2", -1)).verified); // not a pole
  EXPECT_FALSE(check_certificate(inf_cert("K/(z - 1)", "2", 0, "2", -1)).verified);   // outside the band
  EXPECT_THROW(check_certificate(inf_cert("K/(z - 1)", "2", 0, "1", 0)), InputError);
  nlohmann::json both = inf_cert("K/(z - 1)", "2", 0, "1", -1);
  both["claim"]["value"] = "1";
  EXPECT_THROW(check_certificate(both), InputError);
}

// The Tustin wall with t_d = T/2 (q = 2, c = cos(wT/2), the band [0, 1]): the pole z = -1 is c = 0,
// the band's end; b* = +inf there (sin(pi/2) > 0), from above. With t_d = 3T/2 (issue 46 item 1) the
// objective tends to -inf there: the same claim is refuted.
TEST(BoundCheck, InfiniteTustinHalfSample) {
  nlohmann::json c = inf_cert("K + B*2*(z-1)/(T*(z+1))", "20", 0, "0", 1);
  c["model"]["set"]["B"] = "5";
  c["model"]["frac_delay"] = "1/2000";
  const Verdict v = check_certificate(c);
  EXPECT_TRUE(v.verified) << v.reason;
  c["model"]["frac_delay"] = "3/2000";
  const Verdict w = check_certificate(c);
  EXPECT_FALSE(w.verified);
  EXPECT_NE(w.reason.find("-inf"), std::string::npos) << w.reason;
  c["model"]["frac_delay"] = "1/2000";
  c["evidence"]["side"] = -1;  // below the band's end: outside the band
  EXPECT_FALSE(check_certificate(c).verified);
}

nlohmann::json lc_cert(const std::string& gain, const std::string& rho, long period, const std::string& amp,
                       const std::string& printed, long free, const nlohmann::json& y) {
  return {{"certificate", "hapstab"}, {"version", 1}, {"kind", "limit-cycle"},
          {"model", {{"H", "1/z"}, {"set", nlohmann::json::object()}, {"T", "1"}, {"gain", gain}, {"rho", rho}}},
          {"claim", {{"status", "exact"}, {"period", period}, {"amplitude", amp}, {"printed_amplitude", printed}, {"free_steps", free}}},
          {"evidence", {{"y", y}}}};
}

// H = 1/z: y_{j+1} = -k max(y_j, -rho). k = 2, rho = 1 from y = 2: 2 -> -4 (out of contact) -> 2:
// period 2, amplitude (2 + 4)/2 = 3, one free sample; the linearisation is (-2)(0) = 0: attracting.
// k = 1 from y = 1/2: 1/2 -> -1/2 -> 1/2 in contact: J = (-1)(-1) = 1, not attracting. From y = 1 the
// orbit 1 -> -1 touches y = -rho: attraction is beyond the checker.
TEST(LimitCycleCheck, FirstOrderByHand) {
  nlohmann::json c = lc_cert("2", "1", 2, "3", "3", 1, {"2"});
  c["claim"]["attracting"] = true;
  Verdict v = check_certificate(c);
  EXPECT_TRUE(v.verified) << v.reason;
  auto refuted = [&](const char* key, const nlohmann::json& value, const char* why) {
    nlohmann::json m = c;
    if (std::string(key) == "y") m["evidence"]["y"] = value;
    else if (std::string(key) == "rho") m["model"]["rho"] = value;
    else m["claim"][key] = value;
    const Verdict r = check_certificate(m);
    EXPECT_FALSE(r.verified) << key;
    EXPECT_NE(r.reason.find(why), std::string::npos) << r.reason;
  };
  refuted("period", 1, "does not repeat");
  refuted("period", 4, "least period");
  refuted("amplitude", "4", "amplitude");
  refuted("printed_amplitude", "3.6", "printed_amplitude");
  refuted("free_steps", 0, "free_steps");
  refuted("attracting", false, "attracting");
  refuted("y", nlohmann::json{"2000001/1000000"}, "does not repeat");
  refuted("rho", "2", "does not repeat");
  nlohmann::json phase = c;
  phase["evidence"]["y"] = {"-4"};
  EXPECT_TRUE(check_certificate(phase).verified);  // the same orbit one sample later
  nlohmann::json scaled = c;                        // (4) is homogeneous in (y, rho)
  scaled["model"]["rho"] = "2";
  scaled["evidence"]["y"] = {"4"};
  scaled["claim"]["amplitude"] = "6";
  scaled["claim"]["printed_amplitude"] = "6.0";
  EXPECT_TRUE(check_certificate(scaled).verified);

  nlohmann::json neutral = lc_cert("1", "1", 2, "1/2", "0.5", 0, {"1/2"});
  neutral["claim"]["attracting"] = false;
  v = check_certificate(neutral);
  EXPECT_TRUE(v.verified) << v.reason;
  neutral["claim"]["attracting"] = true;
  EXPECT_FALSE(check_certificate(neutral).verified);

  nlohmann::json touching = lc_cert("1", "1", 2, "1", "1", 0, {"1"});
  EXPECT_TRUE(check_certificate(touching).verified);
  touching["claim"]["attracting"] = true;
  EXPECT_THROW(check_certificate(touching), InputError);

  nlohmann::json bad = c;
  bad["evidence"]["y"] = {"2", "-4"};
  EXPECT_THROW(check_certificate(bad), InputError);  // n = 1 output expected
  bad = c;
  bad["model"]["H"] = "2";
  EXPECT_THROW(check_certificate(bad), InputError);  // no state
  bad = c;
  bad["model"]["gain"] = "-1";
  EXPECT_THROW(check_certificate(bad), InputError);
  bad = c;
  bad["model"]["H"] = "-2 + 1/z";
  EXPECT_THROW(check_certificate(bad), InputError);  // 1 + k H(inf) = -3 <= 0: no unique solution
}

}  // namespace
}  // namespace hapstab::check
