// Tests of the series (34)/(9): truncation, rigorous tail bound, Euler-Maclaurin acceleration,
// certified enclosure, Bernoulli numbers. Reference: the closed form (44) / rhat = 1/(4 sin^2)
// at 100 digits (a different formula from the series under test).
#include <gtest/gtest.h>

#include <boost/math/special_functions/bernoulli.hpp>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/sampling/series.hpp"

using namespace hapstab;
using namespace hapstab::sampling;

TEST(Series, Bernoulli) {
  EXPECT_EQ(bernoulli_b2n(0), 1);
  EXPECT_EQ(bernoulli_b2n(1), rational(1, 6));
  EXPECT_EQ(bernoulli_b2n(2), rational(-1, 30));
  EXPECT_EQ(bernoulli_b2n(3), rational(1, 42));
  EXPECT_EQ(bernoulli_b2n(6), rational(-691, 2730));
  EXPECT_EQ(bernoulli_b2n(13), rational(8553103, 6));  // B_26
  // B_120 against Boost.Math at 100 digits (independent algorithm)
  mp100 b = boost::math::bernoulli_b2n<mp100>(60);
  EXPECT_LT(abs(mp100(bernoulli_b2n(60)) / b - 1), mp100(1e-95));
  EXPECT_THROW(bernoulli_b2n(-1), InputError);
}

TEST(Series, TruncationErrorLiesInsideTheIntegralBounds) {
  const mp50 T = mp50(1) / 1000;
  for (mp50 theta : {mp50("1e-6"), mp50("0.01"), mp50("1.2345"), mp50("3.14159"), mp50("-2"), mp50("20")}) {
    mp50 rh = rhat_closed(theta);
    for (long N : {4L, 10L, 100L, 1000L}) {
      if (2 * pi_value<mp50>() * N <= abs(theta)) {
        EXPECT_THROW(rhat_tail_upper(theta, N), InputError);
        continue;
      }
      mp50 tau = rh - rhat_partial(theta, N);
      EXPECT_LE(rhat_tail_lower(theta, N), tau) << theta << " " << N;
      EXPECT_LE(tau, rhat_tail_upper(theta, N)) << theta << " " << N;
      // |r - r_N| <= bound, against (44)
      auto rN = r_series(T, theta, N);
      auto r = r_eq44(T, theta);
      mp50 err = sqrt((rN.real() - r.real()) * (rN.real() - r.real()) + (rN.imag() - r.imag()) * (rN.imag() - r.imag()));
      EXPECT_LE(err, r_series_error_bound(T, theta, N) * (1 + mp50(1e-40)));
    }
  }
  EXPECT_THROW(rhat_partial(mp50(1), -1), InputError);
}

TEST(Series, DoubleTruncatedSeriesConvergesLike1OverN) {
  const double T = 1e-3, theta = 1.0;
  auto r = r_eq44(T, theta);
  double e10 = std::abs(r_series(T, theta, 10) - r), e1000 = std::abs(r_series(T, theta, 1000) - r);
  // tail ~ (1/(2 pi^2)) (1/N - 1/(2N^2) + ...) ~ 1/(2 pi^2 (N + 1/2)): ratio (1000.5)/(10.5)
  EXPECT_NEAR(e10 / e1000, 1000.5 / 10.5, 0.2);
}

TEST(Series, AcceleratedReachesTheRequestedDigits) {
  const mp100 T100 = mp100(1) / 1000;
  for (const char* ts : {"1e-8", "0.001", "0.5", "1.2345", "3.141592653589793", "-2.5", "9.5"}) {
    mp100 th(ts);
    auto ref = r_eq44(T100, th);
    mp100 mag = sqrt(ref.real() * ref.real() + ref.imag() * ref.imag());
    // 30 digits in mp50 (20 guard digits)
    auto a30 = r_series_accelerated(mp50(T100), mp50(th), 30);
    mp100 e30 = abs(mp100(a30.value.real()) - ref.real()) + abs(mp100(a30.value.imag()) - ref.imag());
    EXPECT_LT(e30 / mag, mp100(1e-30)) << ts;
    EXPECT_LT(mp100(a30.error_bound) / mag, mp100(1e-30)) << ts;
    // 80 digits in mp100
    auto a80 = r_series_accelerated(T100, th, 80);
    mp100 e80 = abs(a80.value.real() - ref.real()) + abs(a80.value.imag() - ref.imag());
    EXPECT_LT(e80 / mag, mp100(1e-80)) << ts;
    // double: 15 digits requested; rounding of ~2N+2K double operations limits it to ~1e-14
    auto ad = r_series_accelerated(static_cast<double>(T100), static_cast<double>(th), 15);
    double ed = std::abs(ad.value - std::complex<double>(static_cast<double>(ref.real()), static_cast<double>(ref.imag())));
    // th itself is rounded to double: compare against (44) at the rounded theta for th != exact
    auto refd = r_eq44(static_cast<double>(T100), static_cast<double>(th));
    EXPECT_LT(std::abs(ad.value - refd) / std::abs(refd), 1e-14) << ts << " " << ed;
  }
  EXPECT_THROW(rhat_accelerated(mp50(1), 0), InputError);
}

TEST(Series, CertifiedEnclosureContains44) {
  for (auto [Ts, ws] : std::vector<std::pair<const char*, const char*>>{
           {"1/1000", "1234.5"}, {"1/1000", "1e-5"}, {"1/1000", "3141.5"}, {"0.01", "-77"}, {"1", "20"}}) {
    rational T = parse_rational(Ts), w = parse_rational(ws), theta = T * w;
    auto e = r_series_certified<60>(T, theta, 20, 40);
    // re of (44) is exactly -T/2
    rational re = -T / 2;
    EXPECT_TRUE(exact_rational(mpfloat<60>(lower(e.re))) <= re && re <= exact_rational(mpfloat<60>(upper(e.re))))
        << Ts << " " << ws;
    mp100 th(theta), Tm(T);
    mp100 im = -Tm / 2 * cos(th / 2) / sin(th / 2);
    EXPECT_TRUE(mp100(lower(e.im)) <= im && im <= mp100(upper(e.im))) << Ts << " " << ws;
    // tight: 40 Euler-Maclaurin terms at N = 20 (u >= 2 pi 20 - 20 = 105): the remainder
    // ~ 82!/(pi u^83) <= 1e-45 relative to rhat >= 1/4
    EXPECT_LT(mp100(upper(e.im) - lower(e.im)) / abs(im), mp100(1e-40)) << Ts << " " << ws;
    EXPECT_GT(mp100(lower(e.rhat)), 0);  // Theorem 1: rhat real and positive
  }
  // K = 0: only 1/(bu) - 1/(2u^2) + [0,1] B_2 b/u^3, still an enclosure
  auto e0 = r_series_certified<40>(rational(1, 1000), rational(1, 2), 5, 0);
  mp100 im = -mp100(1) / 2000 * cos(mp100(0.25)) / sin(mp100(0.25));
  EXPECT_TRUE(mp100(lower(e0.im)) <= im && im <= mp100(upper(e0.im)));
}
