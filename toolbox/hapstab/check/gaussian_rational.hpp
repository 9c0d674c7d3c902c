// hapstab/check/gaussian_rational.hpp -- exact Gaussian rationals x + jy (x, y rational), the
// checkers' own complex numbers: a transfer function evaluated exactly at a rational point of the
// unit circle (check/passivity_level_mimo_check.hpp, check/multidof_witness_check.hpp), and the one exact
// linear solve the checkers share (solve_exact: (zI - A)^-1 B at a rational or Gaussian-rational z).
#pragma once

#include <optional>
#include <utility>
#include <vector>

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

/// X with M X = R, by Gauss-Jordan elimination with row exchanges over F (rational or Cq), exactly;
/// nullopt when M is singular. M is n x n, R n x k.
template <class F>
std::optional<std::vector<std::vector<F>>> solve_exact(std::vector<std::vector<F>> M, std::vector<std::vector<F>> R) {
  const size_t n = M.size(), k = R.empty() ? 0 : R[0].size();
  for (size_t c = 0; c < n; ++c) {
    size_t p = c;
    while (p < n && M[p][c].is_zero()) ++p;
    if (p == n) return std::nullopt;
    std::swap(M[p], M[c]);
    std::swap(R[p], R[c]);
    for (size_t i = 0; i < n; ++i) {
      if (i == c || M[i][c].is_zero()) continue;
      const F f = M[i][c] / M[c][c];
      for (size_t j = c; j < n; ++j) M[i][j] = M[i][j] - f * M[c][j];
      for (size_t j = 0; j < k; ++j) R[i][j] = R[i][j] - f * R[c][j];
    }
  }
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < k; ++j) R[i][j] = R[i][j] / M[i][i];
  return R;
}

}  // namespace hapstab::check
