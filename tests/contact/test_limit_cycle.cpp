// Tests of contact/limit_cycle.hpp and contact/model.hpp: the Lur'e loop of paper 002 (Fig. 5),
// limit-cycle detection against exact rational certificates, slow decay vs sustained
// oscillation, H(z) of Fig. 1 against a closed form and a direct RK4 simulation, and the
// sweep property "no criterion is contradicted by simulation".
#include <gtest/gtest.h>

#include <cmath>

#include "hapstab/contact/conservatism.hpp"
#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/contact/model.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_limit_cycle {

using namespace hapstab;
using namespace hapstab::contact;

namespace {
TransferFunction H_of(const std::string& s) {
  ParseOptions po;
  po.variable = 'z';
  po.T = 1;
  return parse_tf(s, po);
}
}  // namespace

TEST(LimitCycle, BadInput) {
  TransferFunction H = H_of("0.5/z");
  EXPECT_THROW(make_lure_loop(H, -1, 1), InputError);
  EXPECT_THROW(make_lure_loop(H, 1, 0), InputError);
  EXPECT_THROW(make_lure_loop(H, 1, -2), InputError);
  EXPECT_THROW(make_lure_loop(H_of("-2*z/(z-0.5)"), 1, 1), InputError);  // 1 + kH(inf) = -1 <= 0
}

TEST(LimitCycle, StableLoopDecays) {
  // wedge holds with a large margin: from every start the loop settles at y = 0
  LureLoop L = make_lure_loop(H_of("0.3*(z+1)/(z^2-0.5*z+0.1)"), 1, 1);
  Oscillation o = find_oscillation(L, 20000, 2048);
  EXPECT_FALSE(o.oscillates);
  EXPECT_FALSE(o.diverged);
}

TEST(LimitCycle, HomogeneityInRho) {
  // (4) is positively homogeneous in (y, rho): the trajectory from c*s0 with c*rho is c times
  // the one from s0 with rho. Exact in rational arithmetic; in double to a few ulps.
  TransferFunction H = H_of("1.2*(z+0.4)/(z^2-0.3*z+0.2)/z");
  LureLoop L1 = make_lure_loop(H, 2, 1), L3 = make_lure_loop(H, 2, 3);
  std::vector<double> s0{2.0, -1.0, 0.5};
  std::vector<double> s3{6.0, -3.0, 1.5};
  SimTrace a = simulate(L1, s0, 500, 500), b = simulate(L3, s3, 500, 500);
  for (size_t i = 0; i < a.y.size(); ++i) EXPECT_NEAR(b.y[i], 3 * a.y[i], 1e-12 * (1 + std::abs(b.y[i])));
}

TEST(LimitCycle, OscillationCertifiedExactly) {
  // A delayed loop beyond the linear stability limit of (1 + kH)^{-1}: the contact loop is
  // unstable, the free flight is not, and the nonlinearity bounds a periodic limit cycle.
  TransferFunction H = H_of("0.5/(z-0.5)/z");
  // closed loop z^2 - 0.5 z + 0.5k: Schur stable iff k < 2 (exact)
  auto kl = closed_loop_gain_limit(H, 1e6, 1e-9);
  ASSERT_TRUE(kl.has_value());
  EXPECT_NEAR(*kl, 2.0, 1e-8);
  LureLoop L = make_lure_loop(H, 3, 1);
  Oscillation o = find_oscillation(L, 20000, 2048);
  ASSERT_TRUE(o.oscillates) << o.note;
  ASSERT_TRUE(o.period.has_value()) << o.note;
  ExactOrbit e = certify_orbit(L, o.state, *o.period);
  ASSERT_TRUE(e.found) << e.note;
  EXPECT_EQ(e.period, *o.period);
  EXPECT_GT(e.free_steps, 0);  // a limit cycle of (4) must leave contact
  // the double amplitude agrees with the exact orbit's (converged trajectory: ~1e-9 relative)
  EXPECT_NEAR(o.amplitude, static_cast<double>(mpfloat<30>(e.amplitude)), 1e-7 * o.amplitude);
  EXPECT_TRUE(e.stable);
}

TEST(LimitCycle, ExactRepeatForFiniteMemory) {
  // H = -k z^-1 ... with H = 0.5 z^-1 and k = 3 (1 + 1.5 z^-1 unstable): the state is the last
  // x only, so the orbit is reached after finitely many steps and repeats exactly.
  LureLoop L = make_lure_loop(H_of("0.5/z"), 3, 1);
  auto p = exact_repeat(L, {rational(7, 3)}, 200);
  ASSERT_TRUE(p.has_value());
  Oscillation o = find_oscillation(L, 20000, 2048);
  ASSERT_TRUE(o.period.has_value());
  EXPECT_EQ(*p, *o.period);
}

TEST(LimitCycle, SlowDecayIsNotAnOscillation) {
  // poles at 0.9995 +- small: the in-contact loop decays by ~5e-4 per sample: slow decay
  LureLoop L = make_lure_loop(H_of("0.0004*(z+1)/(z^2-1.999*z+0.9991)"), 1, 1);
  Oscillation o = detect(L, {0.0, 30.0}, 8000, 2048);
  EXPECT_FALSE(o.oscillates) << o.note;
}

// Issue 40: the red team's loop, whose in-contact linear part (1 + kH)^-1 has a pole pair of radius
// about 1.0005 (unstable). At 1,000 and 10,000 steps the motion is still in contact: growing,
// decided by the exact Schur-Cohn test, not the amplitude ratio. At 100,000 and the CLI's default
// 200,000 it has left contact and grown past 1e9 rho: diverged (it was "sustained oscillation",
// diverged false, amplitude 1e20). The window is the CLI's: min(8192, steps/4).
TEST(LimitCycle, GrowthIsDecidedWhateverTheRunLength) {
  const LureLoop L = make_lure_loop(H_of("(1/1000)*(z+1)/(z^2 - (108/100)*(99999/100000)*z + (99999/100000)^2)"), 1, 1);
  EXPECT_FALSE(L.contact_stable);
  for (long steps : {1000L, 10000L}) {
    const Oscillation o = find_oscillation(L, steps, std::min<long>(8192, steps / 4));
    EXPECT_TRUE(o.growing && o.oscillates) << steps << ": " << o.note;
    EXPECT_FALSE(o.diverged) << steps << ": " << o.note;
    EXPECT_NE(o.note.find("exact, Schur-Cohn"), std::string::npos) << o.note;
  }
  for (long steps : {100000L, 200000L}) {
    const Oscillation o = find_oscillation(L, steps, 8192);
    EXPECT_TRUE(o.diverged && o.growing && o.oscillates) << steps << ": " << o.note;
    EXPECT_GT(o.amplitude, 1e6) << steps;
  }
}

TEST(Model, MassOnlyClosedForm) {
  // F = 1/(m s^3): G(z) = T^2 (z + 1)/(2 m (z - 1)^2) exactly
  PhysicalModel pm;
  pm.m = rational(1, 4);
  pm.b = 0;
  pm.T = rational(1, 1000);
  pm.O = TransferFunction{RationalFunction<rational>(0), Domain::s, 0};
  pm.E = virtual_wall(WallKind::backward_difference, 1, 0, pm.T, 0);
  ModelH mh = model_H(pm, 40);
  Polynomial<rational> z = Polynomial<rational>::monomial(1), one(rational(1));
  RationalFunction<rational> G((z + one) * (pm.T * pm.T / (2 * pm.m)), (z - one).pow(2));
  EXPECT_TRUE(mh.G.H == G) << mh.G.to_string();
  EXPECT_EQ(mh.coefficient_error, 0);
}

TEST(Model, HandModelAgainstRK4Simulation) {
  // device 0.2 kg, 0.5 Ns/m; hand 3000 N/m, 10 Ns/m, 0.1 kg; T = 1 ms. RK4 with 200 substeps has
  // a local error ~ (h w)^5 with h w ~ 1e-3: the sampled responses agree to ~1e-10 relative.
  PhysicalModel pm;
  pm.m = rational(1, 5);
  pm.b = rational(1, 2);
  pm.T = rational(1, 1000);
  pm.O = hand_impedance(3000, 10, rational(1, 10));
  pm.E = virtual_wall(WallKind::backward_difference, 1, rational(2, 1000), pm.T, 1);
  ModelH mh = model_H(pm, 40);
  EXPECT_LT(mh.coefficient_error, 1e-38);
  const double dev = zoh_check_by_simulation(pm, mh.G, 400, 200);
  EXPECT_LT(dev, 1e-9);
  // the wall: E(1) = K = 1, so H(1) = G(1) = 1/K_hand exactly (the s = 0 pole is exact)
  Assumptions a = check_assumptions(mh.H);
  ASSERT_TRUE(a.h1.has_value());
  EXPECT_EQ(*a.h1, rational(1, 3000));
}

TEST(Model, FreeDeviceHasExactPoleAtOne) {
  PhysicalModel pm;
  pm.m = rational(1, 5);
  pm.b = rational(1, 2);
  pm.T = rational(1, 1000);
  pm.O = TransferFunction{RationalFunction<rational>(0), Domain::s, 0};
  pm.E = virtual_wall(WallKind::tustin, 1000, 2, pm.T, 0);
  ModelH mh = model_H(pm, 40);
  EXPECT_EQ(mh.H.den()(rational(1)), 0);   // integrator: exact pole at z = 1
  EXPECT_EQ(mh.H.den()(rational(-1)), 0);  // Tustin: exact pole at z = -1
  const double dev = zoh_check_by_simulation(pm, mh.G, 300, 100);
  EXPECT_LT(dev, 1e-9);
}

TEST(Conservatism, NoCriterionContradictedOnASubsetOfTheSweep) {
  // Three cases of the default family (the full sweep runs in `hapstab figure contact_conservatism`).
  auto fam = default_family();
  for (size_t i : {1u, 6u, 19u}) {
    ConservatismRow r = evaluate_case(fam[i], 12000);
    SCOPED_TRACE(r.c.name);
    ASSERT_TRUE(r.criteria_evaluated);
    EXPECT_FALSE(r.wedge_contradicted);
    EXPECT_FALSE(r.tsypkin_contradicted);
    // Tsypkin is more conservative than the wedge
    EXPECT_LE(r.k_tsypkin, r.k_wedge * (1 + 1e-9));
    if (r.k_osc) { EXPECT_GE(*r.k_osc, r.k_wedge * (1 - 1e-3)); }
  }
}

}  // namespace test_limit_cycle
