// Tests of the starred transform (4) and the sampling argument (40)-(44) (starred.hpp).
// References: closed forms derived independently (coth of the sampling identity, T e^{-sT}).
#include <gtest/gtest.h>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/sampling/r_decimal.hpp"
#include "hapstab/sampling/starred.hpp"

using namespace hapstab;
using namespace hapstab::sampling;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

TEST(Starred, OneOverSSquaredIsMinusTRhat) {
  // G = 1/s^2 at s = j w: (1/T) sum 1/(j(w + n w_s))^2 = -T rhat_N(wT), term by term
  RF G(P(1), P::monomial(2));
  const mp50 T = mp50(1) / 100, w = 37;
  auto v = starred_transform(G, T, std::complex<mp50>(0, w), 50);
  EXPECT_LT(abs(v.real() + T * rhat_partial(mp50(w * T), 50)), mp50(1e-45));
  EXPECT_LT(abs(v.imag()), mp50(1e-45));
}

TEST(Starred, FirstOrderMatchesCoth) {
  // sum_n 1/(z + 2 pi j n) (symmetric) = coth(z/2)/2, z = (s + a) T: (1/T) sum G(s + j n w_s)
  RF G(P(1), P(std::vector<rational>{2, 1}));  // 1/(s + 2)
  const double T = 0.1;
  std::complex<double> s(0.3, 5.0);
  std::complex<double> z = (s + 2.0) * T;
  std::complex<double> ref = 0.5 / std::tanh(z / 2.0);
  auto v = starred_transform(G, T, s, 100000);
  // symmetric truncation error ~ |z|/(2 pi^2 N) <= 1e-6 here; summation error ~ N eps
  EXPECT_LT(std::abs(v - ref), 2e-6);
  // a pole hit exactly is refused
  RF H(P(1), P::monomial(1));
  EXPECT_THROW(starred_transform(H, 1.0, std::complex<double>(0, 0), 3), InputError);
}

TEST(Starred, TriangleSamplesAndK) {
  const rational T(1, 1000);
  EXPECT_EQ(triangle_c(rational(0), T), 0);
  EXPECT_EQ(triangle_c(T, T), T);
  EXPECT_EQ(triangle_c(2 * T, T), 0);
  EXPECT_EQ(triangle_c(3 * T, T), 0);
  EXPECT_EQ(triangle_c(T / 2, T), T / 2);
  EXPECT_EQ(triangle_c(rational(-1), T), 0);
  EXPECT_EQ(triangle_c(3 * T / 2, T), T / 2);
  // sum_k c(kT) e^{-ksT} = T e^{-sT}
  const mp50 Tm(T);
  std::complex<mp50> s(mp50(3), mp50(1234.5));
  auto sum = triangle_sample_sum(Tm, s, 10);
  auto k = k_closed(Tm, s);
  EXPECT_LT(abs(sum.real() - k.real()) + abs(sum.imag() - k.imag()), mp50(1e-48));
  // C(s) = ((1 - e^{-sT})/s)^2: the starred sum of C (truncated) approaches k(s)
  auto Cst = starred_transform_fn([&](const std::complex<mp50>& x) { return triangle_C(Tm, x); }, Tm, s, 2000);
  // truncation: |tail| <= (1/T)|1-e^{-sT}|^2 T^2 tau_N(wT) (starred.hpp), here ~ 4e-8
  std::complex<mp50> om(1 - exp(-s.real() * Tm) * cos(s.imag() * Tm), exp(-s.real() * Tm) * sin(s.imag() * Tm));
  mp50 bound = Tm * (om.real() * om.real() + om.imag() * om.imag()) * rhat_tail_upper(mp50(s.imag() * Tm), 2000);
  mp50 err = sqrt((Cst.real() - k.real()) * (Cst.real() - k.real()) + (Cst.imag() - k.imag()) * (Cst.imag() - k.imag()));
  EXPECT_LE(err, bound);
  EXPECT_GT(err, bound / 10);  // and the bound is not loose by more than 10x
}

TEST(Starred, CertifiedTriangleStarredEqualsTExp) {
  const rational T(1, 1000);
  for (auto [sg, w] : std::vector<std::pair<rational, rational>>{{0, rational(12345, 10)}, {rational(3), 100},
                                                                  {rational(-50), rational(3000)}}) {
    auto [re, im] = starred_triangle_certified<50>(T, sg, w, 200);
    auto k = k_closed(mp100(T), std::complex<mp100>(mp100(sg), mp100(w)));
    EXPECT_TRUE(mp100(lower(re)) <= k.real() && k.real() <= mp100(upper(re)));
    EXPECT_TRUE(mp100(lower(im)) <= k.imag() && k.imag() <= mp100(upper(im)));
    // width: the tail box is [-1,1] * T^2 tau_N, multiplied by (1-e^{-sT})^2/T (complex): <= 4x
    mp100 Tm(T), a = exp(-mp100(sg) * Tm);
    mp100 om2 = (1 - a * cos(mp100(w) * Tm)) * (1 - a * cos(mp100(w) * Tm)) + a * a * sin(mp100(w) * Tm) * sin(mp100(w) * Tm);
    mp100 tail = Tm * om2 * rhat_tail_upper(mp100(w * T), 200);
    EXPECT_LT(mp100(upper(re) - lower(re)), 4.01 * tail);
  }
}

TEST(RDecimal, CorrectlyRoundedAgainstIndependentReference) {
  // im of (44) at T = 1/1000, w = 1234.5 to 50 digits vs (35) evaluated at 120 digits
  const rational T(1, 1000), w = parse_rational("1234.5");
  auto [re, im] = r44_decimal(T, w, 50);
  EXPECT_EQ(re, "-0.0005");
  using M = mpfloat<120>;
  M th = M(w * T);
  M ref_im = M(T) / 2 * (-sin(th)) / (1 - cos(th));
  EXPECT_EQ(im, to_decimal(exact_rational(ref_im), 50));
  auto full = r_decimal(T, w, 1000, 30);
  EXPECT_EQ(full.re, "-0.0005");
  EXPECT_EQ(full.im, to_decimal(exact_rational(ref_im), 30));
  ASSERT_TRUE(full.series_error_bound.has_value());
  // series at N=1000 vs its 120-digit value via rhat_partial
  auto rs = r_series(M(T), th, 1000);
  EXPECT_EQ(full.series_re, to_decimal(exact_rational(rs.real()), 30));
  EXPECT_EQ(full.series_im, to_decimal(exact_rational(rs.imag()), 30));
  // and the series really is within the bound of (44)
  M err = abs(rs.imag() - ref_im);
  EXPECT_LE(exact_rational(err), parse_rational(*full.series_error_bound));
}

TEST(RDecimal, BadInput) {
  EXPECT_THROW(r44_decimal(0, 1, 10), InputError);
  EXPECT_THROW(r44_decimal(-1, 1, 10), InputError);
  EXPECT_THROW(r44_decimal(1, 0, 10), InputError);
  EXPECT_THROW(r44_decimal(1, 1, 0), InputError);
  EXPECT_THROW(r44_decimal(1, 1, 1001), InputError);
  EXPECT_THROW(r_decimal(1, 1, -1, 10), InputError);
  // huge wT still fine (argument reduction in MPFR): w = 1e12, T = 1
  auto [re, im] = r44_decimal(1, parse_rational("1e12"), 20);
  using M = mpfloat<200>;
  M th = M(parse_rational("1e12"));
  EXPECT_EQ(im, to_decimal(exact_rational(M(-cos(th / 2) / sin(th / 2) / 2)), 20));
}
