// hapstab/check/gaussian_rational.hpp -- exact Gaussian rationals x + jy (x, y rational), the
// checkers' own complex numbers: a transfer function evaluated exactly at a rational point of the
// unit circle (check/passivity_level_mimo_check.hpp, check/multidof_witness_check.hpp).
#pragma once

#include <utility>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::check {

struct Cq {
  rational re, im;
  Cq() = default;
  Cq(rational r, rational i = rational(0)) : re(std::move(r)), im(std::move(i)) {}
  bool is_zero() const { return re.is_zero() && im.is_zero(); }
};
inline Cq operator+(const Cq& a, const Cq& b) { return {a.re + b.re, a.im + b.im}; }
inline Cq operator-(const Cq& a, const Cq& b) { return {a.re - b.re, a.im - b.im}; }
inline Cq operator*(const Cq& a, const Cq& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
/// b != 0 (the caller checks).
inline Cq operator/(const Cq& a, const Cq& b) {
  const rational n = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / n, (a.im * b.re - a.re * b.im) / n};
}
inline Cq conj(const Cq& a) { return {a.re, -a.im}; }

}  // namespace hapstab::check
