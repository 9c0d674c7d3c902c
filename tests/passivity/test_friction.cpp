// Tests of hapstab/passivity/friction.hpp: the FIR taps of H z^-n, the sign witness that makes
// f_c* = (Delta/2) sum |w_k| necessary, and the closed forms of Abbott-Okamura (spring) and of
// the delayed spring-damper.
#include <gtest/gtest.h>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/friction.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_friction {

using namespace hapstab;
using namespace hapstab::passivity;

namespace {

RationalFunction<rational> H_of(const std::string& expr, std::map<std::string, rational> par = {}) {
  ParseOptions o;
  o.variable = 'z';
  o.T = rational(1, 1000);
  o.parameters = std::move(par);
  return parse_tf(expr, o).H;
}

std::vector<rational> R(std::initializer_list<int> v) {
  std::vector<rational> r;
  for (int x : v) r.emplace_back(x);
  return r;
}

}  // namespace

TEST(Friction, AbbottOkamuraSpring) {
  // K Delta / 2 for the spring, any delay; tight
  for (int n = 0; n <= 6; ++n) {
    const FrictionCondition c = friction_condition(H_of("K", {{"K", rational(1000)}}), n, rational(1, 1000));
    EXPECT_EQ(c.fc_star, rational(1, 2)) << n;
    EXPECT_TRUE(c.tight) << n;
    EXPECT_EQ(c.taps.size(), size_t(n) + 1);
  }
}

TEST(Friction, SpringDamperIsDeltaTimesKHalfPlusBOverT) {
  for (int n = 0; n <= 6; ++n) {
    const auto H = H_of("K + B*(z-1)/(T*z)", {{"K", rational(20000)}, {"B", rational(5)}});
    const FrictionCondition c = friction_condition(H, n, rational(1, 4096));
    EXPECT_EQ(c.fc_star, rational(1, 4096) * (rational(10000) + rational(5000))) << n;
    ASSERT_EQ(c.taps.size(), size_t(n) + 2);
    EXPECT_EQ(c.taps[size_t(n)], rational(25000));
    EXPECT_EQ(c.taps[size_t(n) + 1], rational(-5000));
    EXPECT_TRUE(c.tight) << n;
    // the witness switches and satisfies s_{j-k} = sign(w_k) s_j at every switch
    const auto& s = c.witness;
    const int P = int(s.size());
    int switches = 0;
    for (int j = 0; j < P; ++j) {
      if (s[size_t((j + 1) % P)] == s[size_t(j)]) continue;
      ++switches;
      EXPECT_EQ(s[size_t(((j - n) % P + P) % P)], s[size_t(j)]);
      EXPECT_EQ(s[size_t(((j - n - 1) % P + P) % P)], -s[size_t(j)]);
    }
    EXPECT_GT(switches, 0);
  }
}

TEST(Friction, WitnessSearchFindsAndRefuses) {
  EXPECT_FALSE(sign_witness(R({1, -1, 1})).empty());  // alternating signs: the alternating sequence
  EXPECT_FALSE(sign_witness(R({1, 1, -1})).empty());  // blocks of two
  EXPECT_TRUE(sign_witness(R({-1})).empty());          // a negative spring: s_j = -s_j is impossible
  EXPECT_TRUE(sign_witness(R({1, -1, -1})).empty());   // s_{j-1} = s_{j-2} = -s_j contradicts itself
  EXPECT_TRUE(sign_witness(R({1, 0, 0, 0, 0, 0, 0, 0, 1})).empty());  // 9 taps: not searched
  // not tight -> sufficient only, f_c* still the l1 level
  const FrictionCondition c = friction_condition(H_of("-K", {{"K", rational(10)}}), 0, rational(1, 10));
  EXPECT_FALSE(c.tight);
  EXPECT_EQ(c.fc_star, rational(1, 2));
  EXPECT_NE(c.why.find("sufficient only"), std::string::npos);
  // a fractional delay keeps f_c* sufficient without a necessity claim
  EXPECT_FALSE(friction_condition(H_of("K", {{"K", rational(10)}}), 0, rational(1, 10), true).tight);
}

TEST(Friction, FirTapsAndRefusals) {
  EXPECT_FALSE(fir_taps(H_of("1/(z-1/2)"), 0).has_value());
  // z is not causal without delay, z z^-1 = 1 is
  EXPECT_THROW(fir_taps(H_of("z"), 0), InputError);
  const auto t = fir_taps(H_of("z"), 1);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, R({1}));
  EXPECT_THROW(friction_condition(H_of("1"), 0, rational(0)), InputError);
  EXPECT_THROW(friction_condition(H_of("1/(z-1/2)"), 0, rational(1)), InputError);
  // W = 0: nothing quantized reaches the device
  EXPECT_EQ(friction_condition(H_of("0"), 0, rational(1)).fc_star, rational(0));
}

}  // namespace test_friction
