// c2d / expm (lti/discretize.hpp) against closed forms evaluated independently at higher
// precision (mp100 std functions, or exact rationals for tustin / backward Euler).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <boost/multiprecision/mpfr.hpp>
#include <cmath>

#include "hapstab/lti/discretize.hpp"

using namespace hapstab;

namespace {

template <class S>
Mat<S> m2(S a, S b, S c, S d) {
  Mat<S> M(2, 2);
  M << a, b, c, d;
  return M;
}

// max |X - Y| / max(1, |Y|) entrywise, in mp100.
template <class S>
mp100 rel_err(const Mat<S>& X, const Mat<mp100>& Y) {
  mp100 e = 0;
  for (Eigen::Index i = 0; i < Y.size(); ++i) {
    mp100 y = Y.data()[i];
    mp100 d = abs(mp100(X.data()[i]) - y) / (abs(y) > 1 ? abs(y) : mp100(1));
    if (d > e) e = d;
  }
  return e;
}

// Closed forms in mp100 for the mass-damper A = [[0,1],[0,-c]], B = [0;1] (c = b/m):
//   Phi = [[1, (1-e^{-cT})/c], [0, e^{-cT}]], Gamma = [(cT - 1 + e^{-cT})/c^2; (1-e^{-cT})/c].
Mat<mp100> mass_damper_closed(mp100 c, mp100 T) {
  mp100 e = exp(-c * T);
  Mat<mp100> R(2, 3);
  R << 1, (1 - e) / c, (c * T - 1 + e) / (c * c), 0, e, (1 - e) / c;
  return R;
}

template <class S>
void check_mass_damper(double tol_eps) {
  const S eps = std::numeric_limits<S>::epsilon();
  for (auto [cn, Tn] : {std::pair{5, 1000}, std::pair{1, 1}, std::pair{300, 10}, std::pair{1, 1000000}}) {
    // c = cn, T = 1/Tn  (cT from 1e-6 to 30: tiny and large arguments of the exponential)
    S c = S(cn), T = S(1) / S(Tn);
    auto p = zoh_pair<S>(m2<S>(0, 1, 0, -c), (Mat<S>(2, 1) << 0, 1).finished(), T);
    Mat<S> got(2, 3);
    got << p.Phi, p.Gamma;
    auto ref = mass_damper_closed(mp100(cn), mp100(1) / mp100(Tn));
    EXPECT_LE(rel_err<S>(got, ref), mp100(tol_eps) * mp100(eps)) << "c=" << cn << " T=1/" << Tn;
  }
}

}  // namespace

TEST(Expm, DoubleIntegratorIsExactPolynomial) {
  // e^{[[0,T],[0,0]]} = [[1,T],[0,1]]; Gamma = [T^2/2; T]. Taylor terminates: the only
  // rounding is in T itself and in the scaling (powers of two, exact) -> expect <= 2 eps.
  for (double T : {1e-3, 0.5, 3.0, 1e3}) {
    auto p = zoh_pair<double>(m2<double>(0, 1, 0, 0), (Mat<double>(2, 1) << 0, 1).finished(), T);
    EXPECT_NEAR(p.Phi(0, 1), T, 2 * DBL_EPSILON * T);
    EXPECT_EQ(p.Phi(0, 0), 1.0);
    EXPECT_EQ(p.Phi(1, 0), 0.0);
    EXPECT_NEAR(p.Gamma(0, 0), T * T / 2, 4 * DBL_EPSILON * T * T / 2);
    EXPECT_NEAR(p.Gamma(1, 0), T, 2 * DBL_EPSILON * T);
  }
}

// Tolerances: scaling-and-squaring loses about s ulps (s squarings, here s <= 6 for cT <= 30)
// on top of the Taylor truncation (eps/8) and the rounding of c, T; 64 eps covers it with
// margin in both precisions (observed: a few eps).
TEST(Expm, MassDamperDouble) { check_mass_damper<double>(64); }
TEST(Expm, MassDamper50Digits) { check_mass_damper<mp50>(64); }

TEST(Expm, FirstOrderLag50Digits) {
  // Phi = e^{-aT}, Gamma = (1 - e^{-aT})/a via expm1 (a different formula: no cancellation).
  for (int an : {1, 10, 1000}) {
    mp50 a = an, T = mp50(1) / 1000;
    Mat<mp50> A(1, 1), B(1, 1);
    A << -a;
    B << 1;
    auto p = zoh_pair<mp50>(A, B, T);
    mp100 ar = an, Tr = mp100(1) / 1000;
    mp100 phi = exp(-ar * Tr), gam = -boost::multiprecision::expm1(-ar * Tr) / ar;
    EXPECT_LE(abs(mp100(p.Phi(0, 0)) - phi) / phi, 16 * std::numeric_limits<mp50>::epsilon());
    EXPECT_LE(abs(mp100(p.Gamma(0, 0)) - gam) / gam, 16 * std::numeric_limits<mp50>::epsilon());
  }
}

TEST(Expm, UndampedOscillatorNearNyquist) {
  // w T = pi - 1e-6 (the critical frequency of paper 001): Phi = [[cos, sin/w],[-w sin, cos]].
  mp100 pi = boost::math::constants::pi<mp100>();
  mp100 T = mp100(1) / 1000, w = (pi - mp100(1e-6)) / T;
  Mat<mp50> A = m2<mp50>(0, 1, mp50(-w * w), 0);
  Mat<mp50> E = expm<mp50>(Mat<mp50>(A * mp50(T)));
  Mat<mp100> ref = m2<mp100>(cos(w * T), sin(w * T) / w, -w * sin(w * T), cos(w * T));
  // ||A T|| ~ w^2 T ~ 1e4 -> s ~ 15 squarings; each squaring of a rotation-like matrix loses
  // ~1 ulp relative to its norm (~w); 1e4 eps relative to max(1,|entry|) covers it.
  EXPECT_LE(rel_err<mp50>(E, ref) / mp100(w), mp100(1e4) * std::numeric_limits<mp50>::epsilon());
}

TEST(C2d, ZohMatchesClosedFormAndKeepsCD) {
  StateSpace<double> G{m2<double>(0, 1, 0, -5), (Mat<double>(2, 1) << 0, 1).finished(),
                       (Mat<double>(1, 2) << 0, 1).finished(), Mat<double>::Zero(1, 1), 0};
  auto d = c2d(G, rational(1, 1000));
  EXPECT_EQ(d.T, rational(1, 1000));
  EXPECT_EQ(d.C, G.C);
  auto ref = mass_damper_closed(5, mp100(1) / 1000);
  EXPECT_NEAR(d.A(1, 1), double(ref(1, 1)), 4 * DBL_EPSILON);
  EXPECT_NEAR(d.B(0, 0), double(ref(0, 2)), 8 * DBL_EPSILON * double(ref(0, 2)));
}

// Tustin / backward Euler are exact over the rationals: compare the transfer function of the
// discrete model at rational points z with G(s(z)) evaluated exactly.
TEST(C2d, TustinAndBackwardEulerExactOverRationals) {
  // G(s) = (s + 3)/(s^2 + 2 s + 5): A companion, exact.
  Mat<rational> A = m2<rational>(0, 1, -5, -2);
  Mat<rational> B(2, 1), C(1, 2), D(1, 1);
  B << 0, 1;
  C << 3, 1;
  D << 0;
  StateSpace<rational> G{A, B, C, D, 0};
  const rational T(1, 100);
  auto G_of = [](rational s) { return (s + 3) / (s * s + 2 * s + 5); };
  for (auto method : {C2dMethod::tustin, C2dMethod::backward_euler}) {
    auto d = c2d(G, T, method);
    for (rational z : {rational(2), rational(-3, 7), rational(11, 10), rational(5)}) {
      Mat<rational> zI = z * Mat<rational>::Identity(2, 2) - d.A;
      rational H = (d.C * zI.fullPivLu().solve(d.B))(0, 0) + d.D(0, 0);
      rational s = method == C2dMethod::tustin ? rational(2) / T * (z - 1) / (z + 1) : (z - 1) / (T * z);
      EXPECT_EQ(H, G_of(s)) << "z=" << z.str();
    }
  }
}

TEST(C2d, BadInputNamesTheProblem) {
  StateSpace<double> G{Mat<double>::Zero(1, 1), Mat<double>::Ones(1, 1), Mat<double>::Ones(1, 1),
                       Mat<double>::Zero(1, 1), 0};
  EXPECT_THROW(c2d(G, rational(0)), InputError);
  EXPECT_THROW(c2d(G, rational(-1)), InputError);
  auto d = c2d(G, rational(1));
  EXPECT_THROW(c2d(d, rational(1)), InputError);  // already discrete
  // backward Euler with a pole at s = 1/T: I - A T singular.
  StateSpace<rational> P{Mat<rational>::Constant(1, 1, rational(10)), Mat<rational>::Ones(1, 1),
                         Mat<rational>::Ones(1, 1), Mat<rational>::Zero(1, 1), 0};
  EXPECT_THROW(c2d(P, rational(1, 10), C2dMethod::backward_euler), InputError);
  EXPECT_THROW(c2d(P, rational(1, 5), C2dMethod::tustin), InputError);
  EXPECT_NO_THROW(c2d(P, rational(1, 5), C2dMethod::backward_euler));
  EXPECT_THROW(parse_c2d_method("foh", "scene key environment.method"), InputError);
}
