// Arb enclosures of matrix exponentials (numeric/ball_expm.hpp) against closed forms evaluated
// in 100-digit MPFR: the exact value must lie within the returned radius of the double
// midpoint, and the radius must be near one rounding (<= 4 ulp of the largest entry, i.e. the
// 128-bit ball itself is negligible). Cases: a rotation (undamped oscillator, eigenvalues on
// the imaginary axis), a stiff damped mode (||A|| t = 2e4: heavy scaling and squaring), the
// ZOH pair of a mass-damper, the Gram integral of a decaying scalar, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/numeric/error.hpp"

using namespace hapstab;
using R = mp100;

namespace {

void expect_encloses(const DoubleEnclosure& e, Eigen::Index i, Eigen::Index j, const R& exact, double scale) {
  EXPECT_LE(abs(R(e.mid(i, j)) - exact), R(e.radius)) << "entry (" << i << ", " << j << ")";
  EXPECT_LE(e.radius, 4 * std::numeric_limits<double>::epsilon() * scale) << "entry (" << i << ", " << j << ")";
}

}  // namespace

TEST(BallExpm, RotationOnTheImaginaryAxis) {
  // A = [[0, 1], [-w^2, 0]], w = 3, t = 7/10: e^{At} = [[cos wt, sin(wt)/w], [-w sin wt, cos wt]]
  MatQ A(2, 2);
  A << 0, 1, -9, 0;
  const auto e = expm_enclosure(A, rational(7, 10));
  const R wt = R(21) / 10;
  expect_encloses(e, 0, 0, cos(wt), 3);
  expect_encloses(e, 0, 1, sin(wt) / 3, 3);
  expect_encloses(e, 1, 0, -3 * sin(wt), 3);
  expect_encloses(e, 1, 1, cos(wt), 3);
}

TEST(BallExpm, StiffDampedModeAndZohPair) {
  // mass-damper v' = (-b v + u)/m, x' = v with b/m = 2e4 (a stiff device), t = 1 s:
  // e^{-at} = e^{-20000} underflows double: the enclosure must still hold (mid 0, tiny radius)
  MatQ A(2, 2), B(2, 1);
  A << rational(-20000), 0, 1, 0;  // states [v; x]
  B << rational(1000), 0;            // 1/m, m = 1/1000
  const rational t(1);
  const auto zp = zoh_enclosure(A, B, t);
  const R a = 20000;
  expect_encloses(zp.Phi, 0, 0, exp(-a), 1);
  expect_encloses(zp.Phi, 1, 0, (1 - exp(-a)) / a, 1);
  expect_encloses(zp.Phi, 1, 1, R(1), 1);
  // Gamma = int_0^1 e^{As} ds B: v-row 1000 (1 - e^{-a})/a, x-row 1000 (1/a - (1 - e^{-a})/a^2)
  expect_encloses(zp.Gamma, 0, 0, 1000 * (1 - exp(-a)) / a, 1);
  expect_encloses(zp.Gamma, 1, 0, 1000 * (1 / a - (1 - exp(-a)) / (a * a)), 1);
}

TEST(BallExpm, GramIntegralOfADecayingMode) {
  // M = [[-a, 1], [0, 0]] (a state driven by a held input), Q = e1 e1^T:
  // W_11 = int_0^t e^{-2as} ds = (1 - e^{-2at})/(2a); a = 50, t = 1/10 (||M|| t = 5: two halvings)
  MatQ M(2, 2), Q = MatQ::Zero(2, 2);
  M << -50, 1, 0, 0;
  Q(0, 0) = 1;
  const auto W = gram_enclosure(M, Q, rational(1, 10));
  const R a = 50, t = R(1) / 10;
  expect_encloses(W, 0, 0, (1 - exp(-2 * a * t)) / (2 * a), 0.1);
  // W_12 = int x1 x2 ds with x1 = e^{-as}, x2 = (1 - e^{-as})/a ... by the symmetric formula
  // W_12 = int_0^t e^{-as} (1 - e^{-as})/a ds = ((1 - e^{-at})/a - (1 - e^{-2at})/(2a))/a
  const R w12 = ((1 - exp(-a * t)) / a - (1 - exp(-2 * a * t)) / (2 * a)) / a;
  expect_encloses(W, 0, 1, w12, 0.1);
  expect_encloses(W, 1, 0, w12, 0.1);
}

TEST(BallExpm, BadInputIsRefusedByName) {
  MatQ A(2, 3), B(3, 1);
  A.setZero();
  B.setZero();
  EXPECT_THROW(expm_enclosure(A, rational(1)), InputError);
  MatQ S = MatQ::Zero(2, 2);
  EXPECT_THROW(zoh_enclosure(S, B, rational(1)), InputError);
  EXPECT_THROW(zoh_enclosure(S, MatQ::Zero(2, 1), rational(-1)), InputError);
  EXPECT_THROW(gram_enclosure(S, MatQ::Zero(3, 3), rational(1)), InputError);
}
