// hapstab/sampling/starred.hpp -- the starred transform (4) and the sampling argument (40)-(44)
// of paper 001.
//
//   G*(s) = (1/T) sum_{n in Z} G(s + j n w_s),  w_s = 2 pi / T                              (4)
//   k(s)  = (1 - e^{-sT}) r(s) = C*(s),  C(s) = ((1 - e^{-sT})/s)^2                     (40)-(42)
//   c(t)  = t on [0, T), 2T - t on [T, 2T], 0 otherwise  (the triangle, C = L[c])        (43)
//   C*(s) = sum_{k >= 0} c(kT) e^{-ksT} = T e^{-sT}   since c(kT) = T [k = 1]               (42)
// Because e^{-(s + j n w_s) T} = e^{-sT}, C(s + j n w_s) = (1 - e^{-sT})^2/(s + j n w_s)^2, and
// |s + j n w_s| >= |w + n w_s| (s = sigma + j w), so the tail of C*(s) beyond |n| > N is bounded by
// (1/T)|1 - e^{-sT}|^2 T^2 tau_N(wT) with tau_N the bound of series.hpp: a certified enclosure.
//
// Implements: paper 001 (4), (40), (41), (42), (43).
#pragma once

#include <complex>
#include <utility>

#include "hapstab/poly/rational_function.hpp"
#include "hapstab/sampling/series.hpp"

namespace hapstab::sampling {

/// (4) truncated at |n| <= N for any callable G(std::complex<S>) -> std::complex<S>.
template <class S, class Fn>
std::complex<S> starred_transform_fn(Fn&& G, const S& T, const std::complex<S>& s, long N) {
  if (N < 0) throw InputError("starred_transform: N must be >= 0");
  const S ws = 2 * pi_value<S>() / T;
  std::complex<S> sum = G(s);
  for (long n = 1; n <= N; ++n) {
    const S shift = ws * S(n);
    sum += G(std::complex<S>(s.real(), s.imag() + shift));
    sum += G(std::complex<S>(s.real(), s.imag() - shift));
  }
  return {sum.real() / T, sum.imag() / T};
}

/// (4) truncated at |n| <= N for a rational G(s) with exact coefficients, evaluated in complex<S>.
/// Throws InputError if s + j n w_s hits a pole exactly (in S).
template <class S>
std::complex<S> starred_transform(const RationalFunction<rational>& G, const S& T, const std::complex<S>& s, long N) {
  return starred_transform_fn(
      [&G](const std::complex<S>& x) {
        const std::complex<S> d = G.den()(x);
        if (maybe_zero(d.real()) && maybe_zero(d.imag())) throw InputError("starred_transform: s + j n w_s is a pole of G");
        const std::complex<S> n = G.num()(x);
        const S dd = d.real() * d.real() + d.imag() * d.imag();
        return std::complex<S>((n.real() * d.real() + n.imag() * d.imag()) / dd,
                               (n.imag() * d.real() - n.real() * d.imag()) / dd);
      },
      T, s, N);
}

/// c(t) of (43): the triangle of height T on [0, 2T] (exact in `rational`).
template <class S>
S triangle_c(const S& t, const S& T) {
  if (t < S(0) || t > 2 * T) return S(0);
  if (t < T) return t;
  return 2 * T - t;
}

/// C(s) = ((1 - e^{-sT})/s)^2, the Laplace transform of (43) (s != 0).
template <class S>
std::complex<S> triangle_C(const S& T, const std::complex<S>& s) {
  using std::cos, std::exp, std::sin;
  const S a = exp(-s.real() * T), ph = -s.imag() * T;
  const std::complex<S> one_minus(1 - a * cos(ph), -a * sin(ph));
  const std::complex<S> q = one_minus / s;
  return q * q;
}

/// sum_{k=0}^{K} c(kT) e^{-ksT}: the last sum of (42) (equal to T e^{-sT} for every K >= 1).
template <class S>
std::complex<S> triangle_sample_sum(const S& T, const std::complex<S>& s, int K) {
  using std::cos, std::exp, std::sin;
  std::complex<S> sum(0, 0);
  for (int k = 0; k <= K; ++k) {
    const S c = triangle_c(S(k) * T, T);
    if (c == S(0)) continue;
    const S a = exp(-S(k) * s.real() * T), ph = -S(k) * s.imag() * T;
    sum += std::complex<S>(c * a * cos(ph), c * a * sin(ph));
  }
  return sum;
}

/// Certified enclosure (boxes re, im) of C*(s) = (1/T) sum_n C(s + j n w_s) at s = sigma + j w,
/// T, sigma, w exact: the |n| <= N part in intervals plus the tail disc of radius
/// (1/T)|1 - e^{-sT}|^2 T^2 rhat_tail_upper(wT, N), added to both re and im as [-rad, rad].
template <unsigned D>
std::pair<interval<D>, interval<D>> starred_triangle_certified(const rational& T, const rational& sigma,
                                                               const rational& w, long N) {
  using I = interval<D>;
  using std::cos, std::exp, std::sin, std::sqrt;
  const I Ti = scalar_cast<I>(T), si = scalar_cast<I>(sigma), wi = scalar_cast<I>(w);
  const I ws = 2 * pi_value<I>() / Ti;
  // (1 - e^{-sT})^2
  const I a = exp(-si * Ti), ph = -wi * Ti;
  const I omr = 1 - a * cos(ph), omi = -a * sin(ph);
  const I pr = omr * omr - omi * omi, pim = 2 * omr * omi;
  // sum_{|n| <= N} 1/(s + j n w_s)^2 = sum 1/(sigma + j y)^2 = (sigma^2 - y^2 - 2 j sigma y)/(sigma^2 + y^2)^2
  I sr(0), sim(0);
  for (long n = N; n >= -N; --n) {
    const I y = wi + ws * I(n);
    const I d = si * si + y * y;
    const I dd = d * d;
    sr += (si * si - y * y) / dd;
    sim += -2 * si * y / dd;
  }
  const I tail = Ti * Ti * rhat_tail_upper(scalar_cast<I>(w * T), N);  // >= |sum_{|n|>N} ...|
  I box;
  mpfi_interv_si(box.backend().data(), -1, 1);
  sr += box * tail;
  sim += box * tail;
  return {(pr * sr - pim * sim) / Ti, (pr * sim + pim * sr) / Ti};
}

}  // namespace hapstab::sampling
