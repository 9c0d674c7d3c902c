// The long-delay path of the stability test (stability/long_delay.hpp, issue 43) against the
// polynomial path where both run (the reference: Schur-Cohn on the exact characteristic polynomial,
// or certified root enclosures, and the crossing polynomial), and at delays of thousands of samples
// against an independent long-double D-decomposition of the textbook ZOH and the Schur test.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/stability/long_delay.hpp"
#include "hapstab/stability/sampled_loop.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_long_delay {

using namespace hapstab;

namespace {

struct Case {
  std::string plant, H, op;
  int n;
};

stability::Loop make(const Case& c, const std::optional<rational>& K, stability::LoopPath path) {
  ParseOptions ps, pz;
  ps.variable = 's';
  pz.variable = 'z';
  ps.T = pz.T = rational(1, 1000);
  ps.parameters = pz.parameters = {{"m", rational(1, 2)}, {"b", rational(1, 10)}, {"B", rational(2)},
                                   {"K", K.value_or(0)}, {"bh", rational(3)}, {"kh", rational(50)}};
  stability::Loop loop;
  loop.T = rational(1, 1000);
  loop.delay = c.n;
  loop.path = path;
  loop.plant = parse_tf(c.plant, ps);
  if (!c.op.empty()) loop.operator_impedance = parse_tf(c.op, ps);
  loop.H = parse_tf(c.H, pz);
  if (!K) loop.H_gain = tf(Polynomial<rational>(rational(1)), Polynomial<rational>(rational(1)), loop.T);
  return loop;
}

std::string describe(const Case& c) { return c.plant + " | " + c.H + " | " + c.op + " | n = " + std::to_string(c.n); }

const std::vector<Case> kCases = {
    {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 0},   {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 1},
    {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 4},   {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 17},
    {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 45},  {"1/(m*s^2 + b*s)", "K", "", 9},
    {"1/(m*s^2)", "K + B*(z-1)/(T*z)", "", 0},         {"1/(m*s^2)", "K + B*(z-1)/(T*z)", "", 3},   // exact data
    {"1/(m*s^2)", "K + B*(z-1)/(T*z)", "", 30},
    {"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "bh + kh/s", 6},                                    // an operator
    {"1/(m*s^2 + b*s)", "K*(z-1/2)/(z-0.9) + B*(z-1)/(T*z)", "", 12},                            // a filtered wall
};

}  // namespace

// sup K by both paths: the same outcome, enclosures that overlap, an exact value contained.
TEST(StabilityLongDelay, MaxGainAgreesWithThePolynomialPath) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(describe(c));
    const stability::MaxGain p = stability::max_gain(make(c, std::nullopt, stability::LoopPath::polynomial), 20);
    const stability::MaxGain l = stability::max_gain(make(c, std::nullopt, stability::LoopPath::long_delay), 20);
    EXPECT_EQ(l.path, "long_delay");
    ASSERT_EQ(p.outcome, l.outcome) << p.note << " / " << l.note;
    EXPECT_EQ(p.infinite, l.infinite);
    if (p.outcome != Outcome::holds || p.infinite) continue;
    EXPECT_LE(l.enclosure.lo, p.enclosure.hi) << to_decimal(l.enclosure.lo, 25) << " vs " << to_decimal(p.enclosure.hi, 25);
    EXPECT_LE(p.enclosure.lo, l.enclosure.hi) << to_decimal(p.enclosure.lo, 25) << " vs " << to_decimal(l.enclosure.hi, 25);
    EXPECT_EQ(p.crossing, l.crossing);
    if (p.exact) { EXPECT_TRUE(l.enclosure.contains(*p.exact)); }
    EXPECT_LE(l.enclosure.hi - l.enclosure.lo, l.enclosure.lo * pow10(-20));
  }
}

// The Schur test by both paths at gains below, near and above the supremum: the same verdict.
TEST(StabilityLongDelay, SchurTestAgreesWithThePolynomialPath) {
  int stable = 0, unstable = 0;
  for (const Case& c : kCases) {
    const stability::MaxGain g = stability::max_gain(make(c, std::nullopt, stability::LoopPath::polynomial), 10);
    if (g.outcome != Outcome::holds || g.infinite) continue;
    const rational sup = g.enclosure.lo;
    for (const rational& f : {rational(1, 10), rational(99, 100), rational(101, 100), rational(3)}) {
      const rational K = parse_rational(to_decimal(sup * f, 8));
      SCOPED_TRACE(describe(c) + ", K = " + K.str());
      const auto p = stability::decide(make(c, K, stability::LoopPath::polynomial));
      const auto l = stability::decide(make(c, K, stability::LoopPath::long_delay));
      ASSERT_TRUE(p.verdict.decided()) << p.verdict.evidence;
      ASSERT_TRUE(l.verdict.decided()) << l.verdict.evidence;
      EXPECT_EQ(p.verdict.holds(), l.verdict.holds()) << p.verdict.evidence << " / " << l.verdict.evidence;
      EXPECT_EQ(p.degree, l.degree);
      (l.verdict.holds() ? stable : unstable) += 1;
    }
  }
  EXPECT_GE(stable, 15);    // both verdicts exercised
  EXPECT_GE(unstable, 15);
}

// An independent reference for the device 1/(m s^2 + b s) behind a ZOH and the wall K + B(z-1)/(Tz)
// with delay n: the textbook ZOH alpha z + beta over (z - 1)(z - e) in long double, K(theta) =
// -c0/c1 on a grid of 40 n points, every sign change of Im K bisected: the smallest positive real K.
// No Arb, no kernel, no polynomial of degree n (relative accuracy ~1e-15 at these n).
long double reference_kmax(long double m, long double b, long double B, long double T, long n) {
  const long double a = b / m, e = std::exp(-a * T);
  const long double alpha = (T - (1 - e) / a) / b, beta = ((1 - e) / a - T * e) / b;
  auto K = [&](long double th) {
    const std::complex<long double> z = std::polar(1.0L, th), zn = std::polar(1.0L, static_cast<long double>(n) * th);
    const std::complex<long double> c0 = zn * T * z * (z - 1.0L) * (z - e) + B * (z - 1.0L) * (alpha * z + beta);
    const std::complex<long double> c1 = T * z * (alpha * z + beta);
    return -c0 / c1;
  };
  const long N = 40 * n + 4000;
  const long double pi = 3.14159265358979323846264338327950288L;
  long double best = INFINITY, prev = K(pi / N).imag();
  for (long i = 2; i < N; ++i) {
    const long double th = pi * i / N, im = K(th).imag();
    if ((im > 0) != (prev > 0)) {
      long double lo = pi * (i - 1) / N, hi = th;
      for (int it = 0; it < 90; ++it) {
        const long double mid = (lo + hi) / 2;
        ((K(mid).imag() > 0) == (K(lo).imag() > 0) ? lo : hi) = mid;
      }
      const long double k = K(lo).real();
      if (k > 0) best = std::min(best, k);
    }
    prev = im;
  }
  return best;
}

// Delays of teleoperation scale: the long-delay path runs where the polynomial would have degree
// 10^3..10^4; sup K agrees with the reference above and the Schur test flips across the enclosure.
TEST(StabilityLongDelay, TeleoperationDelays) {
  for (int n : {1000, 5000}) {
    const Case c{"1/(m*s^2 + 10*b*s)", "K + B/8*(z-1)/(T*z)", "", n};  // m = 1/2, b = 1, B = 1/4
    const stability::MaxGain g = stability::max_gain(make(c, std::nullopt, stability::LoopPath::automatic), 15);
    ASSERT_EQ(g.outcome, Outcome::holds) << g.note;
    EXPECT_EQ(g.path, "long_delay") << g.plan;
    const long double ref = reference_kmax(0.5L, 1.0L, 0.25L, 1e-3L, n);
    EXPECT_NEAR(to_real<double>(g.enclosure.lo) / static_cast<double>(ref), 1, 1e-12) << to_decimal(g.enclosure.lo, 20);
    EXPECT_LE(g.enclosure.hi - g.enclosure.lo, g.enclosure.lo * pow10(-15));
    const auto below = stability::decide(make(c, g.enclosure.lo * rational(999, 1000), stability::LoopPath::automatic));
    const auto above = stability::decide(make(c, g.enclosure.hi * rational(1001, 1000), stability::LoopPath::automatic));
    EXPECT_TRUE(below.verdict.decided() && below.verdict.holds()) << below.verdict.evidence;
    EXPECT_TRUE(above.verdict.decided() && !above.verdict.holds()) << above.verdict.evidence;
    EXPECT_EQ(below.degree, n + 3);
  }
}

// The delay is limited in samples (10^6) before anything is allocated; the polynomial path,
// when asked for, refuses above its degree.
TEST(StabilityLongDelay, WorkIsBoundedByName) {
  const Case c{"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 1000001};
  try {
    stability::decide(make(c, rational(1), stability::LoopPath::automatic));
    ADD_FAILURE() << "accepted n = 1000001";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the limit of 1000000"), std::string::npos) << e.what();
  }
  const Case d{"1/(m*s^2 + b*s)", "K + B*(z-1)/(T*z)", "", 300};
  EXPECT_THROW(stability::decide(make(d, rational(1), stability::LoopPath::polynomial)), InputError);
}

// The searches with double-interval pruning (numeric/dinterval.hpp) and in Arb balls alone
// (ArbOnly): the same outcome and overlapping enclosures of sup K, the same Schur verdicts at
// gains below and above it, on the cases above (delays 0..45) and at delays of 300 and 1000.
TEST(StabilityLongDelay, DoublePruningAgreesWithArbAlone) {
  std::vector<Case> cases = kCases;
  cases.push_back({"1/(m*s^2 + 10*b*s)", "K + B/8*(z-1)/(T*z)", "", 1000});
  cases.push_back({"1/(m*s^2 + b*s)", "K*(z-1/2)/(z-0.9) + B*(z-1)/(T*z)", "", 300});
  for (const Case& c : cases) {
    SCOPED_TRACE(describe(c));
    const stability::Loop loop = make(c, std::nullopt, stability::LoopPath::long_delay);
    const stability::MaxGain fresh = stability::max_gain(loop, 20);
    stability::MaxGain arb;
    {
      const stability::detail::ArbOnly scope;
      arb = stability::max_gain(loop, 20);
    }
    ASSERT_EQ(fresh.outcome, arb.outcome) << fresh.note << " | " << arb.note;
    EXPECT_EQ(fresh.status, arb.status);
    EXPECT_EQ(fresh.infinite, arb.infinite);
    if (fresh.outcome != Outcome::holds || fresh.infinite) continue;
    EXPECT_LE(fresh.enclosure.lo, arb.enclosure.hi) << to_decimal(fresh.enclosure.lo, 25) << " vs " << to_decimal(arb.enclosure.lo, 25);
    EXPECT_LE(arb.enclosure.lo, fresh.enclosure.hi) << to_decimal(fresh.enclosure.lo, 25) << " vs " << to_decimal(arb.enclosure.lo, 25);
    EXPECT_LE(fresh.enclosure.hi - fresh.enclosure.lo, fresh.enclosure.lo * pow10(-19));
    for (const rational& k : {fresh.enclosure.lo * rational(99, 100), fresh.enclosure.hi * rational(101, 100)}) {
      const stability::Loop at = make(c, k, stability::LoopPath::long_delay);
      const auto d = stability::decide(at);
      stability::StabilityResult a;
      {
        const stability::detail::ArbOnly scope;
        a = stability::decide(at);
      }
      EXPECT_EQ(d.verdict.decided(), a.verdict.decided()) << to_decimal(k, 20);
      if (d.verdict.decided() && a.verdict.decided()) { EXPECT_EQ(d.verdict.holds(), a.verdict.holds()) << to_decimal(k, 20); }
    }
  }
}

// The crossing search's work follows the crossover band, not the delay (its gain floor |K| >=
// (|P| - |Q0|)/|Q1|, stability/long_delay.cpp): the delayed integrator c = z^n (z - 1) + K (H = K on
// 1/s behind a ZOH at T = 1), whose smallest crossing is K* = 2 sin(pi/(2 (2n + 1))) at
// theta = pi/(2n + 1), is enclosed at n = 10^3 and 10^5 after a few dozen arcs, where the
// 4 n + 64 first boxes alone would be 4 * 10^5; with Arb alone (no floor) every first box is taken.
TEST(StabilityLongDelay, CrossingSearchWorkFollowsTheCrossover) {
  for (long n : {1000L, 100000L}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    stability::detail::DelayedLoop L;
    L.n = n;
    L.exact = true;
    L.Pq = {rational(-1), rational(1)};
    L.Q0q = {rational(0)};
    L.Q1q = {rational(1)};
    for (const auto* v : {&L.Pq, &L.Q0q, &L.Q1q})
      for (const rational& x : *v) (v == &L.Pq ? L.P : v == &L.Q0q ? L.Q0 : L.Q1).emplace_back(x);
    std::string why;
    const auto s = stability::detail::smallest_crossings(L, why);
    ASSERT_TRUE(s.has_value()) << why;
    ASSERT_FALSE(s->crossings.empty());
    flint::Ball sine, cosine;
    flint::sin_cos(flint::Ball::pi() / flint::Ball(2 * (2 * n + 1)), sine, cosine);
    const flint::Ball k_star = sine * flint::Ball(2L);
    bool enclosed = false;
    for (const auto& x : s->crossings) {
      EXPECT_FALSE(x.K.below(k_star)) << "a crossing below K*";
      enclosed = enclosed || (!x.K.below(k_star) && !k_star.below(x.K));
    }
    EXPECT_TRUE(enclosed);
    EXPECT_LT(s->boxes, 200) << s->double_boxes;  // 32 and 51 arcs at this writing
    if (n == 1000) {
      const stability::detail::ArbOnly scope;
      const auto arb = stability::detail::smallest_crossings(L, why);
      ASSERT_TRUE(arb.has_value()) << why;
      EXPECT_GE(arb->boxes, 4 * n + 64);
    }
  }
}

}  // namespace test_long_delay
