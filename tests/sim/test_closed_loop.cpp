// The sampled closed loop as one matrix (sim/closed_loop.hpp) against the simulator
// (sim/simulator.hpp), which runs the same loop step by step: after a unit impulse on DOF 0
// at t = 0 the sampled positions y_k = positions M^k jump e_0 must equal the simulator's
// samples to within 1e-10 of the run's largest |y| (both are the exact ZOH rounded to double;
// 400 steps of double recursion). Random loops of 1-3 DOF: mass-damper devices, operators
// m s + b + k/s (the spring gives the conserved quantity the Kalman split removes), walls
// K + B (z - 1)/(T z) with springs between neighbours, a coupling admittance in some, and
// integer and fractional delays. Also: the exact M of a nilpotent plant (pure masses, no
// damping) lies inside the enclosed one, and z = 1 (the DC test) is found exactly.
#include <gtest/gtest.h>

#include <random>

#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/sim/simulator.hpp"

using namespace hapstab;
using namespace hapstab::sim;

namespace {
using Q = rational;

LoopSpec random_loop(std::mt19937_64& g, int N) {
  std::uniform_int_distribution<int> u(1, 9), coin(0, 1), dl(0, 5);
  LoopSpec s;
  s.T = Q(1, 1000);
  for (int j = 0; j < N; ++j) {
    s.devices.push_back(mass_damper("d" + std::to_string(j), Q(u(g), 10), Q(u(g), 2)));
    s.operators.push_back(mass_spring_damper_operator("h" + std::to_string(j), j, Q(u(g) - 1, 20), Q(u(g), 4),
                                                      coin(g) ? Q(10 * u(g)) : Q(0)));
  }
  // E = diag(K_j + B_j (z - 1)/(T z)) + neighbour springs: state = x_{k-1} per DOF
  MatQ A = MatQ::Zero(N, N), B = MatQ::Identity(N, N), C = MatQ::Zero(N, N), D = MatQ::Zero(N, N);
  for (int j = 0; j < N; ++j) {
    const Q K(200 * u(g)), Bd(u(g), 10);
    D(j, j) = K + Bd / s.T;
    C(j, j) = -Bd / s.T;
    if (j + 1 < N) {
      const Q kc(50 * u(g));
      D(j, j) += kc, D(j + 1, j + 1) += kc, D(j, j + 1) -= kc, D(j + 1, j) -= kc;
    }
  }
  s.environment = StateSpace<Q>{A, B, C, D, s.T};
  if (coin(g)) {  // V = T z / ((kc T + bc) z - bc) per DOF: state v_{k-1}
    MatQ Av = MatQ::Zero(N, N), Bv = MatQ::Zero(N, N), Cv = MatQ::Zero(N, N), Dv = MatQ::Zero(N, N);
    for (int j = 0; j < N; ++j) {
      const Q kc(1000 * u(g)), bc(u(g));
      const Q a = kc * s.T + bc;
      Av(j, j) = bc / a;
      Bv(j, j) = s.T * bc / (a * a);
      Cv(j, j) = 1;
      Dv(j, j) = s.T / a;
    }
    s.coupling = StateSpace<Q>{Av, Bv, Cv, Dv, s.T};
  }
  static const Q delays[] = {Q(0), Q(1), Q(2), Q(1, 2), Q(3, 2), Q(7, 10)};
  s.delay = delays[dl(g)] * s.T;
  s.impulses = {{0, Q(0), Q(1)}};
  return s;
}

}  // namespace

TEST(ClosedLoop, MatrixReproducesTheSimulator) {
  std::mt19937_64 g(1038);
  int compared = 0, fractional = 0, coupled = 0, conserved = 0;
  for (int c = 0; c < 60; ++c) {
    const int N = 1 + c % 3;
    const LoopSpec s = random_loop(g, N);
    const SampledClosedLoop cl = sampled_closed_loop(s);
    SimOptions o;
    o.steps = 400;
    o.energy = false;
    o.max_velocity = 1e30;
    const SimResult r = Simulator(s).run(o);
    Eigen::VectorXd X = Eigen::MatrixXd(cl.jump.cast<double>()).col(0);
    const Eigen::MatrixXd Py = cl.positions.cast<double>();
    double peak = 0, worst = 0;
    const size_t rows = std::min<size_t>(r.samples.rows(), 400);
    std::vector<double> ym;
    for (size_t k = 0; k < rows; ++k) {
      const Eigen::VectorXd y = Py * X;
      for (int j = 0; j < N; ++j) {
        const double ys = r.samples.x[k * size_t(N) + size_t(j)];
        peak = std::max(peak, std::abs(ys));
        worst = std::max(worst, std::abs(ys - y(j)));
      }
      X = cl.M.mid * X;
    }
    ASSERT_GT(peak, 0) << "case " << c;
    EXPECT_LE(worst, 1e-10 * peak) << "case " << c << ": N = " << N << ", delay " << s.delay;
    ++compared;
    fractional += bmp::denominator(s.delay / s.T) != 1;
    coupled += s.coupling.has_value();
    conserved += cl.conserved > 0;
  }
  EXPECT_EQ(compared, 60);
  EXPECT_GE(fractional, 10);
  EXPECT_GE(coupled, 10);
  EXPECT_GE(conserved, 10);
}

TEST(ClosedLoop, NilpotentPlantIsExactAndInsideTheEnclosure) {
  // pure masses (no damping), hands of pure inertia: e^{AT} is a finite sum
  LoopSpec s;
  s.T = Q(1, 100);
  s.devices = {mass_damper("a", Q(1), Q(0)), mass_damper("b", Q(2), Q(0))};
  s.operators = {mass_spring_damper_operator("ha", 0, Q(1, 2), Q(0), Q(0)), mass_spring_damper_operator("hb", 1, Q(1, 3), Q(0), Q(0))};
  MatQ D(2, 2);
  D << 30, -10, -10, 30;
  s.environment = StateSpace<Q>{MatQ(0, 0), MatQ(0, 2), MatQ(2, 0), D, s.T};
  s.delay = Q(1, 200);  // half a period: both pieces exact
  const SampledClosedLoop cl = sampled_closed_loop(s);
  ASSERT_TRUE(cl.exact.has_value());
  for (Eigen::Index i = 0; i < cl.M.rows(); ++i)
    for (Eigen::Index j = 0; j < cl.M.cols(); ++j)
      EXPECT_LE(abs(rational(cl.M.mid(i, j)) - (*cl.exact)(i, j)), rational(cl.M.rad(i, j)) + rational(1e-300))
          << i << ", " << j;
}

TEST(ClosedLoop, NonlinearPartsAreRefusedByName) {
  LoopSpec s;
  s.T = Q(1, 1000);
  s.devices = {mass_damper("d", Q(1), Q(1))};
  s.environment = StateSpace<Q>{MatQ(0, 0), MatQ(0, 1), MatQ(1, 0), MatQ::Constant(1, 1, Q(100)), s.T};
  s.contact = {0};
  try {
    sampled_closed_loop(s);
    FAIL() << "contact accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[contact]"), std::string::npos) << e.what();
  }
}
