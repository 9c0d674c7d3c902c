// Certified MIMO passivity levels (passivity_level_certified_mimo) against closed forms.
//
// R diag(g1, g2) R^T with the rational rotation R = (3/5, 4/5; -4/5, 3/5) has the eigenvalues
// Re g1, Re g2 of He G on the circle (R is orthogonal, exactly), so:
//   g1 = 1 + z^-1/2, g2 = 1 + (3/4) z^-2: Re g1 = 1 + cos(theta)/2 >= 1/2 (at pi), Re g2 =
//     1 + (3/4) cos(2 theta) >= 1/4 (at pi/2): ISP level 1/4 exactly, at theta = pi/2 (issue 33).
//   g1 = 1 + 1/(z - 1/2), g2 = 2 + (1/2)/(z + 3/10) (tests/lmi/test_passivity_level.cpp): Re g1 >=
//     1/3 at theta = pi, Re g2 >= 2 - 5/7: ISP 1/3; OSP: Re(1/g1) = Re(1 - 1/(z + 1/2)) >= 1/3 at
//     theta = 0, 1/g2 = 1/2 - (1/8)/(z + 11/20) >= 1/2 - (1/8)/(31/20) = 21/62 > 1/3: OSP 1/3.
// An irrational level: g1 = 1 + z^-2/2 + z^-3/5, Re g1 = 1 + cos(2t)/2 + cos(3t)/5 = (4/5) c^3 +
//   c^2 - (3/5) c + 1/2, minimal at the root of (12/5) c^2 + 2 c - 3/5 in (-1, 1), irrational.
#include <gtest/gtest.h>

#include <cmath>

#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

using namespace hapstab;
using namespace hapstab::lmi;

namespace {

using QMat = Mat<rational>;

/// A SISO FIR/IIR piece in controllable form: g = d + sum_k b_k z^-k (k = 1..n).
struct Piece {
  QMat A, B, C, D;
};
Piece fir(rational d, std::vector<rational> b) {
  const auto n = static_cast<Eigen::Index>(b.size());
  Piece p{QMat::Zero(n, n), QMat::Zero(n, 1), QMat::Zero(1, n), QMat::Constant(1, 1, d)};
  for (Eigen::Index i = 1; i < n; ++i) p.A(i, i - 1) = 1;  // shift register x_{k+1} = u_{k-1}...
  p.B(0, 0) = 1;
  for (Eigen::Index i = 0; i < n; ++i) p.C(0, i) = b[static_cast<size_t>(i)];
  return p;
}
Piece first_order(rational a, rational c, rational d) {
  return {QMat::Constant(1, 1, a), QMat::Constant(1, 1, 1), QMat::Constant(1, 1, c), QMat::Constant(1, 1, d)};
}

/// R diag(g1, g2) R^T, R = (3/5, 4/5; -4/5, 3/5).
StateSpace<rational> rotated(const Piece& g1, const Piece& g2) {
  const auto n1 = g1.A.rows(), n2 = g2.A.rows();
  QMat A = QMat::Zero(n1 + n2, n1 + n2), B = QMat::Zero(n1 + n2, 2), C = QMat::Zero(2, n1 + n2), D = QMat::Zero(2, 2);
  A.topLeftCorner(n1, n1) = g1.A;
  A.bottomRightCorner(n2, n2) = g2.A;
  B.block(0, 0, n1, 1) = g1.B;
  B.block(n1, 1, n2, 1) = g2.B;
  C.block(0, 0, 1, n1) = g1.C;
  C.block(1, n1, 1, n2) = g2.C;
  D(0, 0) = g1.D(0, 0);
  D(1, 1) = g2.D(0, 0);
  QMat R(2, 2);
  R << rational(3, 5), rational(4, 5), rational(-4, 5), rational(3, 5);
  StateSpace<rational> s;
  s.A = A;
  s.B = QMat(B * R.transpose());
  s.C = QMat(R * C);
  s.D = QMat(R * D * R.transpose());
  s.T = rational(1, 100);
  return s;
}

}  // namespace

TEST(PassivityLevelMimo, IssueExampleIspIsExactlyOneQuarter) {
  const auto sys = rotated(fir(1, {rational(1, 2)}), fir(1, {0, rational(3, 4)}));
  const auto c = passivity_level_certified_mimo(sys, PassivityKind::isp, 17, M_PI / 2 + 1e-9);
  ASSERT_EQ(c.status, Status::exact) << c.note;
  EXPECT_EQ(c.enclosure->lo, rational(1, 4));
  EXPECT_EQ(c.enclosure->hi, rational(1, 4));
  EXPECT_EQ(*c.lower_bound, rational(1, 4));
  EXPECT_NEAR(c.theta_min, M_PI / 2, 1e-12);
  // without a hint (the search starts at c = 0, +-1)
  const auto c2 = passivity_level_certified_mimo(sys, PassivityKind::isp, 30);
  ASSERT_EQ(c2.status, Status::exact) << c2.note;
  EXPECT_EQ(c2.enclosure->lo, rational(1, 4));
  // a wrong hint (theta = 0.3, where lambda_min = 1 + (3/4) cos 0.6 - far from the level) still
  // ends at the level: the decision finds the dip
  const auto c3 = passivity_level_certified_mimo(sys, PassivityKind::isp, 17, 0.3);
  ASSERT_EQ(c3.status, Status::exact) << c3.note;
  EXPECT_EQ(c3.enclosure->lo, rational(1, 4));
}

TEST(PassivityLevelMimo, RotatedFirstOrderIspAndOsp) {
  const auto sys = rotated(first_order(rational(1, 2), 1, 1), first_order(rational(-3, 10), rational(1, 2), 2));
  const auto isp = passivity_level_certified_mimo(sys, PassivityKind::isp, 17, 1.0);
  ASSERT_EQ(isp.status, Status::exact) << isp.note;
  EXPECT_EQ(isp.enclosure->lo, rational(1, 3));
  EXPECT_NEAR(isp.theta_min, M_PI, 1e-12);
  const auto osp = passivity_level_certified_mimo(sys, PassivityKind::osp, 17, 1.0);
  ASSERT_EQ(osp.status, Status::exact) << osp.note;
  EXPECT_EQ(osp.enclosure->lo, rational(1, 3));
  EXPECT_NEAR(osp.theta_min, 0, 1e-12);
  EXPECT_TRUE(osp.note.empty()) << osp.note;
}

// The irrational level of the header: its closed form in long double.
TEST(PassivityLevelMimo, IrrationalLevelIsEnclosedTightly) {
  const auto sys = rotated(fir(1, {0, rational(1, 2), rational(1, 5)}), fir(2, {rational(1, 4)}));
  const long double c = (-2.0L + std::sqrt(4.0L + 4 * (12.0L / 5) * (3.0L / 5))) / (2 * 12.0L / 5);
  const long double best = 0.8L * c * c * c + c * c - 0.6L * c + 0.5L;  // 0.4246..., g2 >= 7/4
  const auto r = passivity_level_certified_mimo(sys, PassivityKind::isp, 17, 2.0);
  ASSERT_EQ(r.status, Status::certified) << r.note;
  EXPECT_LE(r.enclosure->hi - r.enclosure->lo, pow10(-19));
  EXPECT_LE(r.enclosure->lo, r.enclosure->hi);
  // long double holds ~19 digits: agreement to 1e-15 is far inside both errors
  EXPECT_NEAR(r.level, static_cast<double>(best), 1e-15);
  EXPECT_NEAR(r.theta_min, std::acos(static_cast<double>(c)), 1e-6);
}

TEST(PassivityLevelMimo, IdenticalAxesDoubleEigenvalue) {
  // G = g I (two identical decoupled axes): every eigenvalue of He G is double, det has a
  // squared factor; the decision counts inertia, so the level (1/3, at theta = pi) is exact.
  StateSpace<rational> s;
  s.A = QMat::Zero(2, 2);
  s.A(0, 0) = s.A(1, 1) = rational(1, 2);
  s.B = QMat::Identity(2, 2);
  s.C = QMat::Identity(2, 2);
  s.D = QMat::Identity(2, 2);
  s.T = 1;
  const auto c = passivity_level_certified_mimo(s, PassivityKind::isp, 17, 3.0);
  ASSERT_EQ(c.status, Status::exact) << c.note;
  EXPECT_EQ(c.enclosure->lo, rational(1, 3));
}

TEST(PassivityLevelMimo, Refusals) {
  StateSpace<rational> s;
  s.A = QMat::Constant(1, 1, 1);  // pole at z = 1
  s.B = QMat::Constant(1, 2, 1);
  s.C = QMat::Constant(2, 1, 1);
  s.D = QMat::Identity(2, 2);
  s.T = 1;
  const auto c = passivity_level_certified_mimo(s, PassivityKind::isp);
  EXPECT_EQ(c.status, Status::failed);
  EXPECT_NE(c.note.find("Schur"), std::string::npos) << c.note;
  s.D = QMat::Identity(2, 3);
  s.B = QMat::Constant(1, 3, 1);
  EXPECT_THROW(passivity_level_certified_mimo(s, PassivityKind::isp), InputError);
}
