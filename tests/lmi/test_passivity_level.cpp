// Passivity levels (paper 000, Lemmas 1 and 2) against closed forms derived by hand.
//
// First order G(z) = d + c/(z - a), |a| < 1, c > 0: with u = cos(theta),
//   Re G = d + c (u - a)/(1 - 2 a u + a^2), whose u-derivative is c (1 - a^2)/(...)^2 > 0, so
//   the minimum is at u = -1: ISP level phi* = d - c/(1 + a).
// OSP level = ISP level of 1/G (Re G/|G|^2 = Re(1/G)). For a = 1/2, c = 1, d = 1:
//   phi* = 1 - 2/3 = 1/3;  1/G = (z - 1/2)/(z + 1/2) = 1 - 1/(z + 1/2), whose Re is minimal at
//   u = +1: 1 - 1/(3/2) = 1/3, so delta* = 1/3 as well.
#include <gtest/gtest.h>

#include <cmath>

#include "hapstab/lmi/passivity_level.hpp"

using namespace hapstab;
using namespace hapstab::lmi;
using Eigen::MatrixXd;

namespace {
StateSpace<double> first_order(double a, double c, double d) {
  MatrixXd A(1, 1), B(1, 1), C(1, 1), D(1, 1);
  A << a;
  B << 1;
  C << c;
  D << d;
  return ss<double>(A, B, C, D, rational(1, 100));
}
const Backend kBoth[] = {Backend::dsdp, Backend::csdp};
}  // namespace

TEST(PassivityLevel, FirstOrderIspAllMethods) {
  auto sys = first_order(0.5, 1.0, 1.0);
  const double exact = 1.0 / 3.0;
  auto f = passivity_level_freq(sys, PassivityKind::isp);
  // Golden section to |dtheta| < 1e-12 at the end point theta = pi (the grid contains pi):
  // the value there is exact up to rounding, ~10 ulp.
  EXPECT_NEAR(f.level, exact, 1e-14);
  EXPECT_NEAR(f.theta_min, M_PI, 1e-6);
  for (Backend b : kBoth)
    for (int lemma : {1, 2}) {
      auto l = passivity_level_lmi(sys, PassivityKind::isp, lemma, b);
      ASSERT_EQ(l.status, "numeric") << l.method << " " << l.note;
      // The LMI optimum is approached within the strict threshold 1e-7 (equilibrated) plus
      // the solver's gap tolerance; 1e-5 absolute covers both with margin.
      EXPECT_NEAR(l.level, exact, 1e-5) << l.method;
      ASSERT_TRUE(l.certified) << l.method << " " << l.note;
      EXPECT_LE(l.lower_bound, rational(1, 3)) << l.method;  // a proven lower bound can't exceed sup
      EXPECT_GT(l.lower_bound, rational(1, 3) - rational(1, 10000)) << l.method;
    }
}

TEST(PassivityLevel, FirstOrderOspAllMethods) {
  auto sys = first_order(0.5, 1.0, 1.0);
  const double exact = 1.0 / 3.0;
  auto f = passivity_level_freq(sys, PassivityKind::osp);
  EXPECT_NEAR(f.level, exact, 1e-13);
  EXPECT_NEAR(f.theta_min, 0.0, 1e-6);
  for (Backend b : kBoth)
    for (int lemma : {1, 2}) {
      auto l = passivity_level_lmi(sys, PassivityKind::osp, lemma, b);
      ASSERT_EQ(l.status, "numeric") << l.method << " " << l.note;
      EXPECT_NEAR(l.level, exact, 1e-5) << l.method;
      ASSERT_TRUE(l.certified) << l.method << " " << l.note;
      EXPECT_LE(l.lower_bound, rational(1, 3)) << l.method;
    }
}

// MIMO: U blockdiag(G1, G2) U^T with a rotation U has He G = U He(blockdiag) U^T, so the ISP
// level is min(1/3, 2 - 0.5/0.7 = 9/7) = 1/3.
TEST(PassivityLevel, RotatedMimoIsp) {
  MatrixXd A(2, 2), B = MatrixXd::Identity(2, 2), C(2, 2), D(2, 2);
  A << 0.5, 0, 0, -0.3;
  C << 1, 0, 0, 0.5;
  D << 1, 0, 0, 2;
  const double t = 0.7;
  MatrixXd U(2, 2);
  U << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  auto sys = ss<double>(A, B * U.transpose(), U * C, U * D * U.transpose(), rational(1, 100));
  auto f = passivity_level_freq(sys, PassivityKind::isp);
  EXPECT_NEAR(f.level, 1.0 / 3.0, 1e-13);  // rotation by U adds a few ulp
  for (Backend b : kBoth) {
    auto l = passivity_level_lmi(sys, PassivityKind::isp, 1, b);
    EXPECT_NEAR(l.level, 1.0 / 3.0, 1e-5) << l.method << " " << l.note;
    EXPECT_TRUE(l.certified) << l.method;
  }
}

// G(z) = (z - 1)/z has a zero ON the unit circle (z = 1): Re G = 1 - cos(theta) >= 0 (ISP
// level 0, attained at theta = 0) and Re G/|G|^2 = 1/2 for theta != 0. The frequency method
// reports 1/2 (to ~1e-8: cancellation near theta = 0, a failure mode shared with any double
// frequency sweep such as MATLAB's getPassiveIndex) and notes the singular frequency. The strict Lemma 1 LMI has no solution for any
// delta (the inequality is an equality at theta = 0): it must fail, never invent a level.
TEST(PassivityLevel, ZeroOnTheUnitCircle) {
  MatrixXd A = MatrixXd::Zero(1, 1), B = MatrixXd::Ones(1, 1), C = -MatrixXd::Ones(1, 1), D = MatrixXd::Ones(1, 1);
  auto sys = ss<double>(A, B, C, D, rational(1, 1000));
  auto fi = passivity_level_freq(sys, PassivityKind::isp);
  EXPECT_NEAR(fi.level, 0.0, 1e-15);
  auto fo = passivity_level_freq(sys, PassivityKind::osp);
  // Near theta = 0 both Re G = 1 - cos(theta) and |G|^2 cancel catastrophically (relative
  // error ~ eps/theta^2), and golden section homes in on theta -> 0: 1e-7 is what double gives.
  EXPECT_NEAR(fo.level, 0.5, 1e-7);
  EXPECT_FALSE(fo.note.empty());
  auto l = passivity_level_lmi(sys, PassivityKind::osp, 1);
  EXPECT_EQ(l.status, "failed") << l.level;
  EXPECT_FALSE(l.certified);
}

TEST(PassivityLevel, BadInput) {
  MatrixXd A = MatrixXd::Zero(1, 1), B = MatrixXd::Ones(1, 2), C = MatrixXd::Ones(1, 1), D = MatrixXd::Ones(1, 2);
  auto sys = ss<double>(A, B, C, D, rational(1, 100));
  EXPECT_THROW(passivity_level_freq(sys, PassivityKind::isp), InputError);  // not square
  auto cont = first_order(0.5, 1, 1);
  cont.T = 0;
  EXPECT_THROW(passivity_level_lmi(cont, PassivityKind::isp), InputError);  // continuous
  auto unstable = first_order(1.5, 1, 1);
  EXPECT_EQ(passivity_level_freq(unstable, PassivityKind::isp).status, "failed");
}
