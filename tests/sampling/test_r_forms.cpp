// Tests of r(jw) in every form (hapstab/sampling/r_forms.hpp, r_exact.hpp). References: the
// exact rational-function forms in t = tan(wT/2), and 100-digit MPFR evaluations of a DIFFERENT
// form than the one under test. Tolerances in units of eps = 2^-52 (double) or stated digits.
#include <gtest/gtest.h>

#include <cmath>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/sampling/r_exact.hpp"
#include "hapstab/sampling/r_forms.hpp"

using namespace hapstab;
using namespace hapstab::sampling;

namespace {
constexpr double eps = 2.220446049250313e-16;

// relative error of a double complex value against the 100-digit (44) at the SAME double inputs,
// (44) at 100 digits evaluated as cos/sin (the (38) route, no tan) so the reference is independent.
double rel_err(std::complex<double> v, double T, double theta) {
  mp100 Tm(T), th(theta);
  mp100 re = -Tm / 2, im = -Tm / 2 * cos(th / 2) / sin(th / 2);
  mp100 dr = mp100(v.real()) - re, di = mp100(v.imag()) - im;
  return static_cast<double>(sqrt(dr * dr + di * di) / sqrt(re * re + im * im));
}
double rel_err_im(std::complex<double> v, double T, double theta) {
  mp100 Tm(T), th(theta);
  mp100 im = -Tm / 2 * cos(th / 2) / sin(th / 2);
  return static_cast<double>(abs((mp100(v.imag()) - im) / im));
}
}  // namespace

TEST(RForms, AllFormsAgreeAt100Digits) {
  const mp100 T = mp100(1) / 1000;
  for (int i = 0; i <= 60; ++i) {
    // theta from 1e-8 to pi (inclusive), and a few beyond pi and negative
    mp100 th = pow(mp100(10), mp100(-8) + mp100(8) * i / 60) * boost::math::constants::pi<mp100>() / mp100(3.14159265358979);
    if (th > boost::math::constants::pi<mp100>()) th = boost::math::constants::pi<mp100>();
    for (mp100 theta : {th, mp100(-th), mp100(th + 7)}) {
      auto ref = r_eq44(T, theta);
      // 1 - cos theta at theta = 1e-8 cancels 16 of the 100 digits: compare to 1e-80 relative
      for (auto v : {r_eq35(T, theta), r_eq36(T, theta), r_eq37(T, theta), r_eq38(T, theta), r_eq44_naive(T, theta)}) {
        mp100 d = abs(v.real() - ref.real()) + abs(v.imag() - ref.imag());
        EXPECT_LT(d / (abs(ref.real()) + abs(ref.imag())), mp100(1e-80)) << "theta=" << theta;
      }
    }
  }
}

TEST(RForms, Eq44DoubleWithin4EpsOnWholeRange) {
  // the header proves <= 1.51 eps when tan is within 1 ulp; the target is 4 eps
  double worst = 0, worst_im = 0, worst38 = 0;
  const double T = 1e-3;
  for (int i = 0; i <= 20000; ++i) {
    double theta = std::pow(10.0, -8.0 + (std::log10(M_PI) + 8.0) * i / 20000);
    if (i == 20000) theta = M_PI;  // the double nearest pi (just below it)
    worst = std::max(worst, rel_err(r_eq44(T, theta), T, theta));
    worst_im = std::max(worst_im, rel_err_im(r_eq44(T, theta), T, theta));
    worst38 = std::max(worst38, rel_err(r_eq38(T, theta), T, theta));
  }
  EXPECT_LE(worst, 4 * eps);
  EXPECT_LE(worst_im, 4 * eps);  // componentwise too (re is exact)
  EXPECT_LE(worst38, 4 * eps);
  // odd T (not a power of two: T/2 is still exact)
  for (double T2 : {1.0 / 3, 7e-5, 12345.678}) {
    for (double theta : {1e-8, 3e-5, 0.1, 1.0, 2.5, 3.14}) EXPECT_LE(rel_err(r_eq44(T2, theta), T2, theta), 4 * eps);
  }
}

TEST(RForms, NaiveFormsLoseAccuracyWhereThePaperPredicts) {
  const double T = 1e-3;
  // (44) as a complex division: at theta = 1e-8, cos theta == 1 in double, re = 0 instead of -T/2
  auto v = r_eq44_naive(T, 1e-8);
  EXPECT_EQ(v.real(), 0.0);
  EXPECT_GT(rel_err(v, T, 1e-8), 1e-17);  // the relative error of the complex value ~ theta/2
  // (35) at theta = 1e-4: 1 - cos theta ~ 5e-9 has relative error ~ eps/5e-9 ~ 1e-8
  double e35 = rel_err(r_eq35(T, 1e-4), T, 1e-4);
  EXPECT_GT(e35, 1e3 * eps);
  // (37): the rounded angle (theta + pi)/2 costs ~ eps/theta in re at theta = 1e-6
  auto v37 = r_eq37(T, 1e-6);
  EXPECT_GT(std::abs(v37.real() + T / 2) / (T / 2), 1e3 * eps);
}

TEST(RForms, RhatClosedAndKClosed) {
  mp100 th("0.7");
  EXPECT_LT(abs(rhat_closed(th) - 1 / (2 - 2 * cos(th))), mp100(1e-98));
  auto k = k_closed(mp100(2), std::complex<mp100>(mp100("0.1"), mp100("0.3")));
  EXPECT_LT(abs(k.real() - 2 * exp(mp100("-0.2")) * cos(mp100("0.6"))), mp100(1e-98));
}

TEST(RExact, FormsAreOneRationalFunction) {
  ComplexRF r44 = r_over_T_eq44();
  EXPECT_TRUE(r_over_T_eq35() == r44);
  EXPECT_TRUE(r_over_T_eq36() == r44);
  EXPECT_TRUE(r_over_T_eq37() == r44);
  EXPECT_TRUE(r_over_T_eq38() == r44);
  using P = Polynomial<rational>;
  using RF = RationalFunction<rational>;
  EXPECT_EQ(r44.re, RF(P(rational(-1, 2))));
  EXPECT_EQ(r44.im, RF(P(rational(-1, 2)), P::monomial(1)));
  ComplexRF rh = rhat_from_eq44();
  EXPECT_TRUE(rh.im.is_zero());
  EXPECT_EQ(rh.re, RF(P(std::vector<rational>{1, 0, 1}), P(std::vector<rational>{0, 0, 4})));
}

TEST(RExact, BuildingBlocksMatchTrigAt100Digits) {
  // at t = p/q: theta = 2 atan(t); each block vs MPFR trig
  for (int p = -9; p <= 9; ++p) {
    if (p == 0) continue;
    rational t(p, 4);
    mp100 tm(t), th = 2 * atan(tm);
    auto chk = [&](const ComplexRF& f, mp100 re, mp100 im) {
      EXPECT_LT(abs(mp100(f.re(t)) - re) + abs(mp100(f.im(t)) - im), mp100(1e-95)) << "t=" << t;
    };
    chk(tform::exp_j_theta(), cos(th), sin(th));
    chk(tform::cos_theta(), cos(th), 0);
    chk(tform::sin_theta(), sin(th), 0);
    chk(tform::cot_half(), cos(th / 2) / sin(th / 2), 0);
    chk(tform::csc2_half(), 1 / (sin(th / 2) * sin(th / 2)), 0);
    chk(tform::csc_half_exp_minus_j_half(), cos(th / 2) / sin(th / 2), -1);
    // and the (37) form itself vs its numeric evaluation
    auto v = r_eq37(mp100(1), th);
    chk(r_over_T_eq37(), v.real(), v.imag());
  }
}
