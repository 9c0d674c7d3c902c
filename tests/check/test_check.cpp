// tests/check/test_check.cpp -- the checkers of check/ on certificates whose truth is known by
// hand (issue 47): b* of H = K with and without a delay (exact closed forms below), r(jw) against
// cot(1/2) from a table, and the non-negativity test on polynomials with known roots. The
// mutation campaign (tests/check/mutate.py, ctest check_mutations) runs them against producers.
#include <gtest/gtest.h>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {
namespace {

using P = Polynomial<rational>;
const rational m1(-1), p1(1);

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
  d["model"]["frac_delay"] = "1/2000";
  expect_field(d, "model.frac_delay");
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
  d["kind"] = "wedge";
  expect_field(d, "kind");
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

}  // namespace
}  // namespace hapstab::check
