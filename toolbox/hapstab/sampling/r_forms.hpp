// hapstab/sampling/r_forms.hpp -- r(jw) of paper 001 in every form, templated on the scalar
// (double, mpfloat<D>, interval<D>; with interval<D> every form is a rigorous enclosure).
//
// All forms take theta = wT (the normalised frequency, radians per sample) and T:
//   (34) r = sum_n T (e^{-j theta} - 1)/(theta + 2 n pi)^2             (series; r_series, series.hpp)
//   (35) r = T/2 (e^{-j theta} - 1)/(1 - cos theta)
//   (36) r = (e^{-j theta} - 1) T/4 csc^2(theta/2)
//   (37) r = T/2 csc(theta/2) e^{-j(theta + pi)/2}
//   (38) r = -T/2 (1 + j cot(theta/2))
//   (44) r = T/(e^{j theta} - 1)
// Poles: theta = 2 pi k. Derivation of (44) = (38): e^{j theta} - 1 = 2j sin(theta/2) e^{j theta/2}, so
//   T/(e^{j theta} - 1) = -j T e^{-j theta/2} / (2 sin(theta/2)) = -T/2 - j (T/2) cot(theta/2):
// the real part is exactly -T/2 and Im r = -(T/2) cot(theta/2) (proofs/sampling_identities.cpp
// proves all forms equal as rational functions of t = tan(theta/2)).
//
// Accuracy in double (bench/sampling.cpp charts it over theta in [1e-8, pi]; relative error of the
// complex value against a 100-digit evaluation at the same double inputs):
//   r_eq44        re = -T/2 is exact (a power-of-two scaling); im = -(T/2)/tan(theta/2).
//                 theta/2 is exact, glibc's tan is within 1 ulp (|d1| <= 2^-52 relative), the
//                 division adds |d2| <= 2^-53, (T/2) is exact: im~ = im (1+d1)^{-1}(1+d2), so
//                 |im~ - im|/|im| <= 2^-52 + 2^-53 + 2^-104 < 1.51 eps (eps = 2^-52), and the
//                 complex relative error is <= that too (re exact). Measured (bench/sampling.cpp,
//                 201 wT in [1e-8, pi], componentwise): worst 0.67 eps; 8.5 ns CPU per evaluation.
//                 (Valid while T/2 and the result are normal numbers: T >= 2^-1021.)
//   r_eq38        as (44) with cot = cos/sin: <= (1 + 1 + 1/2 + 1/2) ulp ~ 2 eps.
//   r_eq44_naive  the complex division as written: e^{j theta} - 1 = (cos theta - 1) + j sin theta;
//                 cos theta - 1 cancels, relative error ~ eps/theta^2 in re, and for theta < 1.5e-8
//                 cos theta rounds to 1, re = 0 (instead of -T/2): 100 % error.
//   r_eq35        1 - cos theta in the denominator and cos theta - 1 in the numerator: ~ eps/theta^2
//                 (measured 8e6 eps at wT = 1e-4, 1.3e3 eps at 1e-2); at wT = 1e-8, 1 - cos == 0: inf.
//   r_eq36        cos theta - 1 in the numerator: re has ~ eps/theta^2; im is accurate.
//   r_eq37        the angle (theta + pi)/2 is rounded (and pi is rounded to double): cos of it
//                 ~ -theta/2 has absolute error ~ eps, so re has relative error ~ eps/theta (8e7 eps
//                 at wT = 1e-8); near wT = pi, Im ~ (T/2)(pi - wT)/2 is lost the same way (4.5e15 eps
//                 at the double nearest pi).
//
// Implements: paper 001 (34), (35), (36), (37), (38), (44).
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <complex>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab::sampling {

/// a > b for certain. For interval<D> this compares lower(a) > upper(b): Boost's interval
/// comparisons throw (inside noexcept, i.e. terminate) when the intervals overlap.
template <class S>
bool certainly_greater(const S& a, const S& b) {
  if constexpr (detail::is_interval<S>::value) {
    return mpfr_cmp(a.backend().left_data(), b.backend().right_data()) > 0;
  } else {
    return a > b;
  }
}

/// x could be zero (interval containing 0, or a floating/rational zero).
template <class S>
bool maybe_zero(const S& x) {
  if constexpr (detail::is_interval<S>::value) {
    return mpfi_has_zero(x.backend().data()) != 0;
  } else {
    return x == S(0);
  }
}

/// pi in S. For intervals straight from MPFI: Boost's pi<> for an MPFI type would instantiate
/// its constant initializer, which computes pi, ln 2, Euler's and Catalan's constants at every
/// precision used when the program starts (measured: 40 ms per process at 4000 digits).
template <class S>
S pi_value() {
  if constexpr (detail::is_interval<S>::value) {
    S x;
    mpfi_const_pi(x.backend().data());
    return x;
  } else {
    return boost::math::constants::pi<S>();
  }
}

/// (35): T/2 (e^{-j theta} - 1)/(1 - cos theta), as written.
template <class S>
std::complex<S> r_eq35(const S& T, const S& theta) {
  using std::cos, std::sin;
  const S c = cos(theta);
  const S f = T / 2 / (1 - c);
  return {f * (c - 1), -f * sin(theta)};
}

/// (36): (e^{-j theta} - 1) T/4 csc^2(theta/2), as written.
template <class S>
std::complex<S> r_eq36(const S& T, const S& theta) {
  using std::cos, std::sin;
  const S s = sin(theta / 2);
  const S f = T / 4 / (s * s);
  return {(cos(theta) - 1) * f, -sin(theta) * f};
}

/// (37): T/2 csc(theta/2) e^{-j(theta + pi)/2}, as written.
template <class S>
std::complex<S> r_eq37(const S& T, const S& theta) {
  using std::cos, std::sin;
  const S m = T / 2 / sin(theta / 2);
  const S phi = -(theta + pi_value<S>()) / 2;
  return {m * cos(phi), m * sin(phi)};
}

/// (38): -T/2 (1 + j cot(theta/2)), cot = cos/sin.
template <class S>
std::complex<S> r_eq38(const S& T, const S& theta) {
  using std::cos, std::sin;
  const S h = T / 2;
  return {-h, -h * (cos(theta / 2) / sin(theta / 2))};
}

/// (44): T/(e^{j theta} - 1), evaluated accurately as re = -T/2, im = -(T/2)/tan(theta/2)
/// (<= 1.51 eps relative in double, see the header comment).
template <class S>
std::complex<S> r_eq44(const S& T, const S& theta) {
  using std::tan;
  const S h = T / 2;
  return {-h, -h / tan(theta / 2)};
}

/// (44) as written: the complex division T/((cos theta - 1) + j sin theta). Loses everything
/// for small theta (kept to show why r_eq44 is computed the way it is).
template <class S>
std::complex<S> r_eq44_naive(const S& T, const S& theta) {
  using std::cos, std::sin;
  const S dr = cos(theta) - 1, di = sin(theta);
  const S n = dr * dr + di * di;
  return {T * dr / n, -T * di / n};
}

/// r^(theta) of (9) in closed form: sum_n 1/(theta + 2 n pi)^2 = 1/(4 sin^2(theta/2)).
template <class S>
S rhat_closed(const S& theta) {
  using std::sin;
  const S s = sin(theta / 2);
  return 1 / (4 * s * s);
}

/// The factor T (e^{-j theta} - 1) of (34)/(9), with cos theta - 1 = -2 sin^2(theta/2) (no cancellation).
template <class S>
std::complex<S> series_factor(const S& T, const S& theta) {
  using std::sin;
  const S s = sin(theta / 2);
  return {-2 * T * s * s, -T * sin(theta)};
}

/// k(s) = T e^{-sT} of (42)-(44) at s = sigma + j w (complex s), closed form.
template <class S>
std::complex<S> k_closed(const S& T, const std::complex<S>& s) {
  using std::cos, std::exp, std::sin;
  const S a = exp(-s.real() * T), ph = -s.imag() * T;
  return {T * a * cos(ph), T * a * sin(ph)};
}

}  // namespace hapstab::sampling
