// hapstab/sampling/series.hpp -- the series (34)/(9) of paper 001: truncated sums, a rigorous
// tail bound, an Euler-Maclaurin accelerated evaluation, and a certified (MPFI) enclosure of the
// infinite sum.
//
//   r(jw)   = T (e^{-j theta} - 1) rhat(theta),  theta = wT                           (34)
//   rhat    = sum_{n in Z} 1/(theta + 2 pi n)^2   (= 1/(4 sin^2(theta/2)))                (9)
//   r_N     = T (e^{-j theta} - 1) rhat_N,  rhat_N = sum_{|n| <= N} 1/(theta + 2 pi n)^2
// The factor T (e^{-j theta} - 1) is evaluated as (-2T sin^2(theta/2), -T sin theta): the same
// number without the cancellation of cos theta - 1, so the series' error is its truncation.
//
// TAIL BOUND (integral test). For N > |theta|/(2 pi) the functions f+(x) = 1/(theta + 2 pi x)^2 and
// f-(x) = 1/(2 pi x - theta)^2 decrease on [N, inf), so f(n) <= int_{n-1}^{n} f and
// f(n) >= int_n^{n+1} f give, for tau_N = rhat - rhat_N = sum_{n > N} (f+(n) + f-(n)),
//   1/(2pi(2pi(N+1) + theta)) + 1/(2pi(2pi(N+1) - theta)) <= tau_N
//                                        <= 1/(2pi(2pi N + theta)) + 1/(2pi(2pi N - theta)),
// and |r - r_N| = |T (e^{-j theta} - 1)| tau_N = 2T |sin(theta/2)| tau_N
//              <= 2T |sin(theta/2)| (1/(2pi(2pi N + theta)) + 1/(2pi(2pi N - theta))) ~ T|theta|/(2 pi^2 N).
// The series converges like 1/N: 30 digits by plain summation would need N ~ 1e29.
//
// ACCELERATION (Euler-Maclaurin). For f(x) = (a + b x)^{-2}, b = 2 pi, u = a + b N > 0:
//   f^{(m)}(x) = (-1)^m (m+1)! b^m (a + b x)^{-(m+2)},  so  f^{(2k-1)}(N) = -(2k)! b^{2k-1} u^{-(2k+1)},
// and Euler-Maclaurin  sum_{n>N} f(n) = int_N^inf f - f(N)/2 - sum_k B_{2k}/(2k)! f^{(2k-1)}(N) + R_K
// becomes
//   sum_{n>N} f(n) = 1/(b u) - 1/(2 u^2) + sum_{k=1}^{K} B_{2k} b^{2k-1} / u^{2k+1} + R_K.
// Every even derivative of f is positive on [N, inf), so (Graham-Knuth-Patashnik, Concrete
// Mathematics (9.80)) R_K = vartheta * B_{2K+2} b^{2K+1} / u^{2K+3} with 0 < vartheta < 1: the first omitted
// term bounds the remainder AND gives its sign. The terms behave like (2k)!/(pi u^{2k+1}), so with
// u ~ 2 pi N the error can be pushed to ~ e^{-2 pi N}: N = 0.37 d + 3 and K <~ 1.2 d terms give d digits.
// Applied to f+ (a = theta) and f- (a = -theta), with exact rational B_{2k}.
//
// CERTIFIED ENCLOSURE. In interval<D> arithmetic: rhat in rhat_N + sum over both tails of
// (S_K + [0, 1] * next term); every operation outward-rounded (MPFI), pi enclosed by mpfi_const_pi.
//
// Implements: paper 001 (9), (34).
#pragma once

#include <complex>
#include <stdexcept>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/polynomial.hpp"
#include "hapstab/sampling/r_forms.hpp"

namespace hapstab::sampling {

/// B_{2k} exactly (B_0 = 1, B_2 = 1/6, B_4 = -1/30, ...), cached, thread-safe. k <= 2000.
const rational& bernoulli_b2n(int k);

/// rhat_N = sum_{|n| <= N} 1/(theta + 2 pi n)^2 (the truncated (9)), smallest terms first.
template <class S>
S rhat_partial(const S& theta, long N) {
  if (N < 0) throw InputError("rhat_partial: number of terms N must be >= 0");
  const S twopi = 2 * pi_value<S>();
  S sum = S(0);
  for (long n = N; n >= 1; --n) {
    const S a = theta + twopi * S(n), b = theta - twopi * S(n);
    sum += 1 / (a * a) + 1 / (b * b);
  }
  return sum + 1 / (theta * theta);
}

/// r_N(jw) = T (e^{-j theta} - 1) rhat_N: (34) truncated at |n| <= N.
template <class S>
std::complex<S> r_series(const S& T, const S& theta, long N) {
  const std::complex<S> f = series_factor(T, theta);
  const S h = rhat_partial(theta, N);
  return {f.real() * h, f.imag() * h};
}

namespace detail {
template <class S>
void require_tail_valid(const S& theta, long N) {
  using std::abs;
  if (N < 1 || !certainly_greater(S(2 * pi_value<S>() * S(N)), S(abs(theta))))
    throw InputError("series tail bound: needs N > |theta|/(2 pi) (N = " + std::to_string(N) + ")");
}
}  // namespace detail

/// Upper integral bound of tau_N(theta) = sum_{|n| > N} 1/(theta + 2 pi n)^2 (N > |theta|/2pi).
template <class S>
S rhat_tail_upper(const S& theta, long N) {
  detail::require_tail_valid(theta, N);
  const S twopi = 2 * pi_value<S>();
  return 1 / (twopi * (twopi * S(N) + theta)) + 1 / (twopi * (twopi * S(N) - theta));
}

/// Lower integral bound of tau_N(theta).
template <class S>
S rhat_tail_lower(const S& theta, long N) {
  detail::require_tail_valid(theta, N);
  const S twopi = 2 * pi_value<S>();
  return 1 / (twopi * (twopi * S(N + 1) + theta)) + 1 / (twopi * (twopi * S(N + 1) - theta));
}

/// |r(jw) - r_N(jw)| <= 2T |sin(theta/2)| rhat_tail_upper(theta, N). With S = interval<D>, take
/// upper() of the result for a rigorous bound.
template <class S>
S r_series_error_bound(const S& T, const S& theta, long N) {
  using std::abs, std::sin;
  return 2 * T * abs(sin(theta / 2)) * rhat_tail_upper(theta, N);
}

/// One Euler-Maclaurin tail: sum_{n > N} 1/(a + 2 pi n)^2 = value + vartheta * next, 0 < vartheta < 1.
template <class S>
struct EMTail {
  S value;  ///< 1/(bu) - 1/(2u^2) + sum_{k=1}^{K} B_{2k} b^{2k-1}/u^{2k+1}
  S next;   ///< B_{2K+2} b^{2K+1}/u^{2K+3}: the remainder lies strictly between 0 and this
  int K;
};

/// Euler-Maclaurin tail with u = a + 2 pi N > 0, adding terms until |next| <= tol (or the terms
/// start to grow, or K = kmax). tol = 0 with kmax gives exactly kmax terms.
template <class S>
EMTail<S> em_tail(const S& u, const S& tol, int kmax) {
  using std::abs;
  const S b = 2 * pi_value<S>();
  const S u2 = u * u, b2 = b * b;
  S value = 1 / (b * u) - 1 / (2 * u2);
  S pw = b / (u2 * u);  // b^{2k-1}/u^{2k+1} at k = 1
  S term = scalar_cast<S>(bernoulli_b2n(1)) * pw;
  int K = 0;
  S prev_abs = abs(term);
  while (K < kmax && certainly_greater(S(abs(term)), tol)) {
    value += term;
    ++K;
    pw = pw * b2 / u2;
    S nt = scalar_cast<S>(bernoulli_b2n(K + 1)) * pw;
    S na = abs(nt);
    if (tol > S(0) && !(na < prev_abs)) {  // asymptotic series turned: stop here
      term = nt;
      break;
    }
    prev_abs = na;
    term = nt;
  }
  return {value, term, K};
}

/// rhat(theta) accelerated, with its error bound (from the Euler-Maclaurin remainders; does not
/// include the rounding of S, which the caller controls by the choice of S).
template <class S>
struct Accelerated {
  S rhat;
  S error_bound;
  long N;
  int K;  ///< Euler-Maclaurin terms used (max of the two tails)
};

/// N = ceil(|theta|/2pi) + ceil(0.37 digits) + 3 and enough Euler-Maclaurin terms that the
/// remainder is below 10^-digits relative to rhat.
template <class S>
Accelerated<S> rhat_accelerated(const S& theta, int digits) {
  using std::abs, std::pow;
  if (digits < 1 || digits > 1000) throw InputError("rhat_accelerated: digits must be in [1, 1000]");
  const S twopi = 2 * pi_value<S>();
  long shift = static_cast<long>(std::ceil(static_cast<double>(abs(theta) / twopi)));
  const long N = shift + static_cast<long>(std::ceil(0.37 * digits)) + 3;
  const S partial = rhat_partial(theta, N);
  const S tol = partial * pow(S(10), -digits) / 4;
  const int kmax = static_cast<int>(1.3 * digits) + 20;
  EMTail<S> tp = em_tail(theta + twopi * S(N), tol, kmax);
  EMTail<S> tm = em_tail(twopi * S(N) - theta, tol, kmax);
  return {partial + tp.value + tm.value, abs(tp.next) + abs(tm.next), N, std::max(tp.K, tm.K)};
}

/// r(jw) from the accelerated series: T (e^{-j theta} - 1) rhat, and |error| <= factor * bound.
template <class S>
struct AcceleratedR {
  std::complex<S> value;
  S error_bound;
  long N;
  int K;
};
template <class S>
AcceleratedR<S> r_series_accelerated(const S& T, const S& theta, int digits) {
  using std::abs;
  const auto a = rhat_accelerated(theta, digits);
  const std::complex<S> f = series_factor(T, theta);
  const S fa = abs(f.real()) + abs(f.imag());
  return {{f.real() * a.rhat, f.imag() * a.rhat}, fa * a.error_bound, a.N, a.K};
}

/// A certified enclosure of the infinite series (34): re, im of r(jw) and rhat of (9).
template <unsigned D>
struct SeriesEnclosure {
  interval<D> re, im, rhat;
  long N;
  int K;
};

/// Certified enclosure of (34) at exact T > 0 and theta = wT (rational, not a multiple of 2 pi):
/// rhat_N in interval arithmetic plus, for each tail, S_K + [0, 1] * next (Euler-Maclaurin with
/// the Concrete Mathematics remainder theorem); K = 0 keeps only 1/(bu) - 1/(2u^2) + [0,1] B_2 b/u^3.
template <unsigned D>
SeriesEnclosure<D> r_series_certified(const rational& T, const rational& theta, long N, int K) {
  using I = interval<D>;
  const I th = scalar_cast<I>(theta), Ti = scalar_cast<I>(T);
  detail::require_tail_valid(th, N);
  const I twopi = 2 * pi_value<I>();
  I unit;
  mpfi_interv_si(unit.backend().data(), 0, 1);  // [0, 1]
  const I partial = rhat_partial(th, N);
  EMTail<I> tp = em_tail(th + twopi * I(N), I(0), K);
  EMTail<I> tm = em_tail(twopi * I(N) - th, I(0), K);
  const I rhat = partial + tp.value + unit * tp.next + tm.value + unit * tm.next;
  const std::complex<I> f = series_factor(Ti, th);
  return {f.real() * rhat, f.imag() * rhat, rhat, N, K};
}

}  // namespace hapstab::sampling
