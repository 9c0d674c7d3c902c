// The loop as written, decided (stability/loop_as_written.hpp).
//  - One DOF, two deciders: the exact/certified transfer-function test and the closed-loop
//    matrix with its Stein certificate must never contradict each other, on random walls
//    K + B (z - 1)/(T z) with delays 0-3 samples, devices m s + b, hands b + k/s, couplings; both
//    must decide almost every case (the boundary cases are what they may leave undecided).
//  - Hidden modes in each block: NOT stable [exact], the mode named, whatever the rest does.
//  - More than one DOF is decided (it was "not decided here").
#include <gtest/gtest.h>

#include <random>

#include "hapstab/stability/loop_as_written.hpp"

using namespace hapstab;
using namespace hapstab::sim;
using stability::decide_loop;
using stability::Decider;

namespace {
using Q = rational;

StateSpace<Q> wall(const Q& K, const Q& B, const Q& T) {  // K + B (z - 1)/(T z): state x_{k-1}
  return {MatQ::Zero(1, 1), MatQ::Identity(1, 1), MatQ::Constant(1, 1, -B / T), MatQ::Constant(1, 1, K + B / T), T};
}
}  // namespace

TEST(LoopAsWritten, OneDofTwoDecidersAgree) {
  std::mt19937_64 g(4343);
  std::uniform_int_distribution<int> u(1, 9), coin(0, 1), dl(0, 3);
  int both = 0, stable = 0, unstable = 0;
  for (int c = 0; c < 300; ++c) {
    LoopSpec s;
    s.T = Q(1, 1000);
    s.devices = {mass_damper("d", Q(u(g), 10), Q(u(g)))};
    s.operators = {mass_spring_damper_operator("h", 0, Q(0), Q(u(g), 4), coin(g) ? Q(20 * u(g)) : Q(0))};
    s.environment = wall(Q(2000 * u(g)), Q(u(g), 4), s.T);
    s.delay = Q(dl(g)) * s.T;
    const auto tf = decide_loop(s), mx = decide_loop(s, Decider::matrix);
    if (tf.stable && mx.stable) {
      ++both;
      EXPECT_EQ(*tf.stable, *mx.stable) << "case " << c << ": " << tf.why << " | " << mx.why;
      (*tf.stable ? stable : unstable)++;
    }
  }
  EXPECT_GE(both, 290);
  EXPECT_GE(stable, 60);
  EXPECT_GE(unstable, 60);
}

TEST(LoopAsWritten, HiddenUnstableModeInEveryBlockIsNamed) {
  const Q T(1, 1000);
  auto base = [&] {
    LoopSpec s;
    s.T = T;
    s.devices = {mass_damper("d", Q(1), Q(30))};
    s.operators = {mass_spring_damper_operator("hand", 0, Q(0), Q(2), Q(0))};
    s.environment = StateSpace<Q>{MatQ(0, 0), MatQ(0, 1), MatQ(1, 0), MatQ::Constant(1, 1, Q(20000)), T};
    return s;
  };
  ASSERT_EQ(decide_loop(base()).stable, std::optional<bool>(true)) << decide_loop(base()).why;
  MatQ A2(2, 2), B2(2, 1), C2(1, 2), D1(1, 1);
  // environment: unobservable z = 2
  LoopSpec e = base();
  A2 << Q(1, 2), 0, 0, 2;
  B2 << 1, 1;
  C2 << 1, 0;
  D1 << 20000;
  e.environment = StateSpace<Q>{A2, B2, C2, D1, T};
  // coupling: uncontrollable z = 3/2
  LoopSpec v = base();
  MatQ Av(2, 2), Bv(2, 1), Cv(1, 2);
  Av << Q(1, 2), 0, 0, Q(3, 2);
  Bv << Q(1, 10000), 0;
  Cv << 1, 1;
  v.coupling = StateSpace<Q>{Av, Bv, Cv, MatQ::Zero(1, 1), T};
  // device: uncontrollable s = 1; operator: unobservable s = 2
  LoopSpec d = base();
  MatQ Ad(2, 2), Bd(2, 1), Cd(1, 2);
  Ad << -30, 0, 0, 1;
  Bd << 1, 0;
  Cd << 1, 1;
  d.devices[0].G = StateSpace<Q>{Ad, Bd, Cd, MatQ::Zero(1, 1), 0};
  d.devices[0].mass.reset();
  LoopSpec o = base();
  o.operators[0].Z = StateSpace<Q>{MatQ::Constant(1, 1, Q(2)), MatQ::Constant(1, 1, Q(1)), MatQ::Zero(1, 1), MatQ::Constant(1, 1, Q(2)), 0};
  o.operators[0].mass.clear();
  for (const auto& [s, block, where] : {std::tuple{e, "environment", "z = 2"}, {v, "coupling", "z = 1.5"},
                                        {d, "device 'd'", "s = 1"}, {o, "operator 'hand'", "s = 2"}}) {
    for (const Decider p : {Decider::automatic, Decider::matrix}) {
      const auto r = decide_loop(s, p);
      ASSERT_EQ(r.stable, std::optional<bool>(false)) << block << ": " << r.why;
      EXPECT_EQ(r.status, Status::exact) << block;
      EXPECT_NE(r.why.find(block), std::string::npos) << r.why;
      EXPECT_NE(r.why.find(where), std::string::npos) << r.why;
    }
  }
}

TEST(LoopAsWritten, TwoDofLoopsAreDecided) {
  // two light devices on a stiff static 2x2 environment (each channel far beyond its sampled
  // spring limit ~2000 N/m): NOT stable; the same with heavy damping: stable
  const Q T(1, 1000);
  for (const Q& b : {Q(1), Q(60)}) {
    LoopSpec s;
    s.T = T;
    s.devices = {mass_damper("l", Q(1), b), mass_damper("r", Q(1), b)};
    s.operators = {mass_spring_damper_operator("h1", 0, Q(0), Q(1, 2), Q(0)), mass_spring_damper_operator("h2", 1, Q(0), Q(1, 2), Q(0))};
    MatQ D(2, 2);
    D << 20000, -5000, -5000, 20000;
    s.environment = StateSpace<Q>{MatQ(0, 0), MatQ(0, 2), MatQ(2, 0), D, T};
    const auto r = decide_loop(s);
    ASSERT_TRUE(r.stable.has_value()) << r.why;
    EXPECT_EQ(*r.stable, b > 30) << r.why;
    EXPECT_EQ(r.status, Status::certified);
  }
}
