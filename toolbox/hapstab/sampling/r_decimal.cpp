#include "hapstab/sampling/r_decimal.hpp"

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/sampling/series.hpp"

namespace hapstab::sampling {

namespace {

template <unsigned D>
bool bounded(const interval<D>& x) {
  return mpfi_bounded_p(x.backend().data()) != 0;
}

template <unsigned D>
std::optional<std::string> decide(const interval<D>& x, int digits) {
  if (!bounded(x)) return std::nullopt;
  return common_decimal(lower_rational(x), upper_rational(x), digits);
}

// theta - 2 pi k, k the integer nearest theta/(2 pi), enclosed at D digits. theta as an interval
// of D digits is 10^-D |theta| wide, wider than the period once |theta| > 10^D: the reduction is
// done at the precision of theta's integer part plus D digits (pi to that precision, MPFR's
// const_pi), so that every rung of the Ziv ladder gets D correct digits of the argument whatever
// |theta| is (below limits::periodic_argument_digits, checked by check_inputs). |theta| < 2^32
// is enclosed as it is.
template <unsigned D>
interval<D> reduced_angle(const rational& theta) {
  interval<D> out;
  const long bits = static_cast<long>(mpz_sizeinbase(num(theta).backend().data(), 2)) -
                    static_cast<long>(mpz_sizeinbase(den(theta).backend().data(), 2));
  if (bits < 32) {
    out = scalar_cast<interval<D>>(theta);
    return out;
  }
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(bits) + static_cast<mpfr_prec_t>(D * 3.33) + 64;
  mpfi_t th, twopi, q;
  mpfr_t mid;
  mpz_t k;
  mpfi_init2(th, prec), mpfi_init2(twopi, prec), mpfi_init2(q, prec), mpfr_init2(mid, prec), mpz_init(k);
  mpfi_set_q(th, theta.backend().data());
  mpfi_const_pi(twopi);
  mpfi_mul_2ui(twopi, twopi, 1);
  mpfi_div(q, th, twopi);
  mpfi_mid(mid, q);
  mpfr_get_z(k, mid, MPFR_RNDN);
  mpfi_mul_z(q, twopi, k);
  mpfi_sub(th, th, q);  // theta - 2 pi k, about 2^-(D * 3.33 + 60) wide
  mpfi_set(out.backend().data(), th);  // rounded outward to D digits
  mpfi_clear(th), mpfi_clear(twopi), mpfi_clear(q), mpfr_clear(mid), mpz_clear(k);
  return out;
}

// im of (44) at working precision D: -(T/2) cot(theta/2) with mpfi_cot (finite near theta/2 = pi/2).
template <unsigned D>
std::optional<std::string> try_im44(const rational& T, const rational& theta, int digits) {
  using I = interval<D>;
  I half = reduced_angle<D>(theta) / 2, c;
  mpfi_cot(c.backend().data(), half.backend().data());
  I im = -scalar_cast<I>(T / 2) * c;
  return decide(im, digits);
}

template <unsigned D>
std::optional<std::pair<std::string, std::string>> try_series(const rational& T, const rational& theta, long N,
                                                              int digits) {
  using I = interval<D>;
  // r_series(T, theta, N) with the factor T (e^{-j theta} - 1) taken at the reduced angle (it is
  // 2 pi periodic) and the sum over n at theta itself
  const I th = scalar_cast<I>(theta);
  const std::complex<I> f = series_factor(scalar_cast<I>(T), reduced_angle<D>(theta));
  const I h = rhat_partial(th, N);
  const std::complex<I> r(f.real() * h, f.imag() * h);
  auto a = decide(r.real(), digits), b = decide(r.imag(), digits);
  if (!a || !b) return std::nullopt;
  return std::make_pair(*a, *b);
}

// The precision ladder (compile-time MPFI types); the first rung with D >= digits + 10 is tried
// first, then each larger one (Ziv).
template <class Fn>
auto ziv(int digits, Fn&& attempt, int* used = nullptr) {
  using R = decltype(attempt(std::integral_constant<unsigned, 40>{}));
  R r{};
  auto tryD = [&](auto Dc) {
    constexpr unsigned D = decltype(Dc)::value;
    if (r || static_cast<int>(D) < digits + 10) return;
    r = attempt(Dc);
    if (r && used) *used = static_cast<int>(D);
  };
  tryD(std::integral_constant<unsigned, 40>{});
  tryD(std::integral_constant<unsigned, 80>{});
  tryD(std::integral_constant<unsigned, 160>{});
  tryD(std::integral_constant<unsigned, 320>{});
  tryD(std::integral_constant<unsigned, 640>{});
  tryD(std::integral_constant<unsigned, 1280>{});
  tryD(std::integral_constant<unsigned, 4000>{});
  return r;
}

void check_inputs(const rational& T, const rational& omega, int digits) {
  if (T <= 0) throw InputError("T = " + T.str() + " must be positive (a sample period)");
  if (omega == 0)
    throw InputError("omega = 0 is a pole of r(jw) = T/(e^{jwT} - 1) (the poles are w = 2 pi k / T; with T "
                     "and w rational only w = 0 is one)");
  if (digits < 1 || digits > 1000)
    throw InputError("digits = " + std::to_string(digits) + " is outside [1, 1000]");
  // r is 2 pi periodic in theta = w T; reducing theta needs pi to as many digits as theta has
  // (reduced_angle): beyond the limit that is refused, not attempted
  static const rational limit = pow10(limits::periodic_argument_digits);  // once (GMP compares sizes first)
  const rational theta = abs(omega * T);
  if (theta >= limit)
    throw InputError("omega: |w T| = " + decimal_outward(theta, 3, -1) + " is not below 10^" +
                     std::to_string(limits::periodic_argument_digits) +
                     " (r(jw) is periodic in w T; reducing w T modulo 2 pi takes pi to as many digits as w T has)");
}

}  // namespace

std::pair<std::string, std::string> r44_decimal(const rational& T, const rational& omega, int digits) {
  check_inputs(T, omega, digits);
  const rational theta = omega * T;
  auto im = ziv(digits, [&](auto Dc) { return try_im44<decltype(Dc)::value>(T, theta, digits); });
  if (!im)
    throw NumericalError("r(jw): wT/2 = " + to_decimal(theta / 2, 20) +
                         " is too close to a multiple of pi (a pole) to decide " + std::to_string(digits) +
                         " digits with 4000-digit intervals");
  return {to_decimal(-T / 2, digits), *im};
}

RDecimal r_decimal(const rational& T, const rational& omega, long N, int digits) {
  check_inputs(T, omega, digits);
  if (N < 0 || N > 100000000) throw InputError("terms N = " + std::to_string(N) + " is outside [0, 1e8]");
  const rational theta = omega * T;
  RDecimal out;
  auto im = ziv(
      digits, [&](auto Dc) { return try_im44<decltype(Dc)::value>(T, theta, digits); }, &out.precision_digits);
  if (!im)
    throw NumericalError("r(jw): wT/2 = " + to_decimal(theta / 2, 20) +
                         " is too close to a multiple of pi (a pole) to decide " + std::to_string(digits) +
                         " digits with 4000-digit intervals");
  out.re = to_decimal(-T / 2, digits);
  out.im = *im;
  auto s = ziv(digits, [&](auto Dc) { return try_series<decltype(Dc)::value>(T, theta, N, digits); });
  if (!s) throw NumericalError("r(jw): the truncated series could not be decided to " + std::to_string(digits) + " digits");
  out.series_re = s->first;
  out.series_im = s->second;
  out.series_terms = N;
  // rigorous error bound, 60-digit intervals, rounded up to 3 significant digits
  using I = interval<60>;
  const I th = scalar_cast<I>(theta);
  const I twopi = 2 * pi_value<I>();
  if (N >= 1 && certainly_greater(I(twopi * I(N)), I(abs(th)))) {
    I b = r_series_error_bound(scalar_cast<I>(T), th, N);
    rational hi = upper_rational(b);
    out.series_error_bound = decimal_outward(hi, 3, +1);  // >= hi: rounded up
  }
  return out;
}

}  // namespace hapstab::sampling
