// Tests of the t = tan(theta/2) substitution (hapstab/poly/unit_circle.hpp). Reference 1: at
// rational t, H(z) evaluated in exact Gaussian-rational arithmetic at z = (1 - t^2 + 2jt)/(1 + t^2)
// (no substitution algebra involved) must equal Re/Im exactly. Reference 2: at many real t,
// direct complex<mp100> evaluation at z = e^{j theta}, theta = 2 atan(t), agrees to ~1e-90.
#include <gtest/gtest.h>

#include <complex>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/poly/unit_circle.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_unit_circle {

using namespace hapstab;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

namespace {
struct Gq {  // exact complex rational
  rational re, im;
};
Gq mul(const Gq& a, const Gq& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
Gq horner(const P& p, const Gq& z) {
  Gq r{0, 0};
  for (int k = p.degree(); k >= 0; --k) {
    r = mul(r, z);
    r.re += p.coeff(k);
  }
  return r;
}
Gq div(const Gq& a, const Gq& b) {
  rational d = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}
P X() { return P::monomial(1); }

std::vector<RF> cases() {
  std::vector<RF> v;
  // K + B (z-1)/(T z), T = 1/1000: a virtual wall
  rational T(1, 1000);
  v.push_back(RF(P(1000)) + RF((X() - P(1)) * rational(5), X() * T));
  // a resonance near the unit circle: 1/(z^2 - 1.8 z + 0.9801) (poles 0.99 e^{+-j...})
  v.push_back(RF(P(1), P(std::vector<rational>{parse_rational("0.9801"), parse_rational("-1.8"), rational(1)})));
  // a pole exactly at z = -1 (t -> infinity) and a zero at z = 1 (t = 0)
  v.push_back(RF(X() - P(1), X() + P(1)));
  // improper in z, degree 5 over degree 2, odd coefficients
  v.push_back(RF(P(std::vector<rational>{rational(1, 3), rational(-2, 7), 0, rational(5), parse_rational("1e-6"), 3}),
                 P(std::vector<rational>{rational(2), rational(1, 11), rational(1, 5)})));
  // a constant
  v.push_back(RF(P(rational(-3, 4))));
  return v;
}
}  // namespace

TEST(UnitCircle, ExactAtRationalT) {
  for (const RF& H : cases()) {
    ReIm ri = on_unit_circle(H);
    for (int i = -40; i <= 40; ++i) {
      rational t = rational(i, 7) + rational(i * i, 13);
      rational den = 1 + t * t;
      Gq z{(1 - t * t) / den, 2 * t / den};
      Gq n = horner(H.num(), z), d = horner(H.den(), z);
      if (d.re == 0 && d.im == 0) continue;  // a pole on the circle
      Gq h = div(n, d);
      EXPECT_EQ(ri.re(t), h.re) << "t=" << t;
      EXPECT_EQ(ri.im(t), h.im) << "t=" << t;
    }
  }
}

TEST(UnitCircle, AgreesWithDirectEvaluationAt100Digits) {
  for (const RF& H : cases()) {
    ReIm ri = on_unit_circle(H);
    for (int i = 0; i < 200; ++i) {
      // t from 1e-6 to 1e6, log-spaced, both signs
      mp100 t = pow(mp100(10), mp100(-6) + mp100(12) * i / 199);
      if (i % 2) t = -t;
      mp100 theta = 2 * atan(t);
      std::complex<mp100> z(cos(theta), sin(theta));
      std::complex<mp100> h = H.num()(z) / H.den()(z);
      mp100 re = ri.re(t), im = ri.im(t);
      mp100 scale = abs(h) + 1;
      // both routes round at the 1e-100 level; the resonance amplifies by <= 1e4 and the
      // degree-5 case at |t|=1e6 by t^10 / t^10 cancellation-free ratios: 1e-85 is ample
      EXPECT_LT(abs(re - h.real()) / scale, 1e-85) << "t=" << t;
      EXPECT_LT(abs(im - h.imag()) / scale, 1e-85) << "t=" << t;
    }
  }
}

TEST(UnitCircle, KnownForms) {
  // Re z = (1 - t^2)/(1 + t^2), Im z = 2t/(1 + t^2)
  ReIm z = on_unit_circle(RF(X()));
  EXPECT_EQ(z.re, RF(P(1) - X() * X(), P(1) + X() * X()));
  EXPECT_EQ(z.im, RF(X() * rational(2), P(1) + X() * X()));
  // 1/(z - 1) = -1/2 - j/(2t): Re = -1/2 exactly (the root of (44)'s exact real part)
  ReIm r = on_unit_circle(RF(P(1), X() - P(1)));
  EXPECT_EQ(r.re, RF(P(rational(-1, 2))));
  EXPECT_EQ(r.im, RF(P(rational(-1, 2)), X()));
  // |z| = 1: Re^2 + Im^2 = 1
  EXPECT_EQ(z.re * z.re + z.im * z.im, RF(P(1)));
  // complex polynomial helpers
  ComplexPolynomial a{P(1), X()};
  EXPECT_EQ(norm(a), P(1) + X() * X());
  EXPECT_EQ(pow(a, 2).re, P(1) - X() * X());
  EXPECT_EQ((a - a).re, P());
  EXPECT_THROW(unit_circle_polynomial(X().pow(3), 2), InputError);
}

}  // namespace test_unit_circle
