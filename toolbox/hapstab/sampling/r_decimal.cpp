#include "hapstab/sampling/r_decimal.hpp"

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"
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

// im of (44) at working precision D: -(T/2) cot(theta/2) with mpfi_cot (finite near theta/2 = pi/2).
template <unsigned D>
std::optional<std::string> try_im44(const rational& T, const rational& theta, int digits) {
  using I = interval<D>;
  I half = scalar_cast<I>(theta / 2), c;
  mpfi_cot(c.backend().data(), half.backend().data());
  I im = -scalar_cast<I>(T / 2) * c;
  return decide(im, digits);
}

template <unsigned D>
std::optional<std::pair<std::string, std::string>> try_series(const rational& T, const rational& theta, long N,
                                                              int digits) {
  using I = interval<D>;
  const I th = scalar_cast<I>(theta);
  const std::complex<I> r = r_series(scalar_cast<I>(T), th, N);
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
    out.series_error_bound = to_decimal(hi * rational(101, 100), 3);  // >= hi (see r_decimal.hpp)
  }
  return out;
}

}  // namespace hapstab::sampling
