// hapstab/numeric/dinterval.hpp -- intervals of doubles [lo, hi] that contain the exact result of
// every operation, computed in round-to-nearest (no rounding-mode switch) and widened outward by
// an a priori bound of each operation's rounding error: the cheap enclosures the long-delay
// branch-and-bounds (passivity/long_delay.cpp, stability/long_delay.cpp) prune with before they
// take Arb (numeric/ball.hpp) for the few boxes that need more than 53 bits. In the style of the
// Stein check's bounds (numeric/ball_matrix.cpp, Higham's standard model), in units of u = 2^-53:
//
// One operation. For x, y doubles and op in {+, -, *, /}, round to nearest gives r = fl(x op y)
// with x op y = r (1 + d) + e, |d| <= u, |e| <= 2^-1075 (e only below the normal range; Higham
// (2.4), (2.5) with the underflow term). outward(r) = [fl(r - w), fl(r + w)] with
// w = fl(|r| 2^-51 + 2^-1074) >= 4u|r| + 2^-1074 (|r| 2^-51 is exact or below the normal range,
// where the added 2^-1074 dominates). Then fl(r + w) >= r + w - u|r + w| >= r + 4u|r| + 2^-1074
// - u(1 + 4u)|r| - 2^-1075 > r + u|r| + 2^-1075 >= x op y (and likewise below): the exact result
// lies inside, with room (3u|r|) for the rounding of the widening itself. With a fused
// multiply-add (fp-contraction of x * y + w) r is replaced by the exact x y in the same chain of
// inequalities and the bound still holds: nothing here depends on how the compiler contracts.
// Products and quotients of intervals take the end products that are the least and the greatest
// (by the ends' signs; all four when both intervals hold 0, and for quotients); since
// r -> r - 3u|r| is increasing, widening the smallest of them downward (the largest upward)
// covers every one.
// Overflow, an infinite or NaN end, or a quotient by an interval that holds 0 gives the whole
// line [-inf, +inf], which decides nothing (the caller then takes Arb).
//
// Conversions. An integer x (|x| < 2^127) rounds to a double d with |x - d| <= u|d| (or 2u|d| if
// truncated): [fl(d - w), fl(d + w)] above covers it. A rational is rounded outward exactly
// (double_outward, numeric/decimal.hpp).
//
// sin and cos of pi k/D for integers k, D (0 < D < 2^123). The reduction is exact, in integers:
// k mod 2D, then the symmetries sin(x + pi) = -sin x, sin(pi - x) = sin x, sin(pi/2 - x) = cos x
// bring the angle to y = pi K/D' with 0 <= K/D' <= 1/4 -- no argument loses a bit to the
// reduction however large k is (nu theta at nu ~ 10^5: the ~17 bits a floating-point reduction
// of fl(nu theta) would lose are never lost). Then, in round to nearest (u = 2^-53, gamma_k =
// k u/(1 - k u), Higham ch. 3 and (5.3)):
//  * y^ = fl(fl(K)/fl(D') * fl(pi)): five roundings (|fl(pi) - pi| < u pi), |y^ - y| <= gamma_5 y;
//  * the Taylor polynomials s(y) = y sum_{k=0}^{9} (-1)^k y^{2k}/(2k+1)!, c(y) = sum_{k=0}^{10}
//    (-1)^k y^{2k}/(2k)! by Horner in x^ = fl(y^ y^), with rounded coefficients: each term
//    a_k x^k is perturbed by the coefficient's rounding, k roundings of x and 2k + 1 of Horner, so
//    |fl(s) - s(y^)| <= gamma_30 y^ sum |a_k| y^2k <= gamma_30 sinh(y^) <= 34 u y^ and
//    |fl(c) - c(y^)| <= gamma_32 cosh(y^) <= 43 u (y^ <= 0.786: sinh y <= 1.11 y, cosh y <= 1.33);
//  * the series' tails (alternating, decreasing terms: the first left out bounds the rest)
//    |sin - s| <= y^21/21! <= 1.6e-22 y, |cos - c| <= y^22/22! <= 4.5e-24 (0.786^20/21! and
//    0.786^22/22! are checked in rationals by the unit test);
//  * y^ for y: |sin y - sin y^|, |cos y - cos y^| <= |y - y^| <= gamma_5 y <= 5.01 u y^ (1 + 6u).
// So sin(pi k/D) lies within 40 u y^ + 1.6e-22 y^ (+ room) of fl(s), which is added as 48 u y^,
// and cos within 43 u + 4 u + 4.5e-24, added as 52 u; the ends are widened as above, and the
// result intersected with [-1, 1]. About 25 flops: ~30 ns, against ~1 us for Arb's sin_cos.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

namespace dint_detail {
inline double widen_amount(double r) { return std::fabs(r) * 0x1p-51 + 0x1p-1074; }
inline double down(double r) { return r - widen_amount(r); }
inline double up(double r) { return r + widen_amount(r); }
}  // namespace dint_detail

/// A closed interval of doubles holding an exact real (see the header); [-inf, inf] when unknown.
struct Dint {
  double lo = 0, hi = 0;
  Dint() = default;
  explicit constexpr Dint(double x) : lo(x), hi(x) {}  ///< the exact point x
  constexpr Dint(double a, double b) : lo(a), hi(b) {}  ///< [a, b], exact ends (a <= b)
  static constexpr Dint entire() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  /// [lo', hi'] from round-to-nearest ends (widened outward; see the header)
  static Dint rounded(double a, double b) {
    const double l = dint_detail::down(a), h = dint_detail::up(b);
    if (!(l >= -std::numeric_limits<double>::max() && h <= std::numeric_limits<double>::max())) return entire();
    return {l, h};
  }
  static Dint from_i128(__int128 x) {
    const double d = static_cast<double>(x);
    return rounded(d, d);
  }
  /// q rounded outward (numeric/decimal.hpp's double_outward: exact, checked there); beyond the
  /// double range an infinite end, i.e. the whole line
  static Dint from_rational(const rational& q) {
    const Dint r{double_outward(q, -1), double_outward(q, +1)};
    return r.finite() ? r : entire();
  }
  bool finite() const { return lo > -std::numeric_limits<double>::infinity() && hi < std::numeric_limits<double>::infinity(); }
  bool positive() const { return lo > 0; }   ///< every point > 0
  bool negative() const { return hi < 0; }   ///< every point < 0
  bool contains_zero() const { return !(lo > 0) && !(hi < 0); }
  double abs_upper() const { return std::max(-lo, hi); }
  double mid() const { return finite() ? lo + 0.5 * (hi - lo) : 0.0; }  ///< a double inside (when finite)
  double radius() const { return 0.5 * (hi - lo); }                     ///< for heuristics only
  Dint operator-() const { return {-hi, -lo}; }
  /// [lo - e, hi + e] for e >= 0 (an added error bound)
  Dint widened(double e) const { return rounded(lo - e, hi + e); }
  /// the intersection with [a, b] (which must meet it)
  Dint clamp(double a, double b) const { return {std::max(lo, a), std::min(hi, b)}; }
};

inline Dint operator+(const Dint& a, const Dint& b) { return Dint::rounded(a.lo + b.lo, a.hi + b.hi); }
inline Dint operator-(const Dint& a, const Dint& b) { return Dint::rounded(a.lo - b.hi, a.hi - b.lo); }
inline Dint operator*(const Dint& a, const Dint& b) {
  // by the signs of the ends: the two end products that are the least and the greatest
  if (a.lo >= 0) {
    if (b.lo >= 0) return Dint::rounded(a.lo * b.lo, a.hi * b.hi);
    if (b.hi <= 0) return Dint::rounded(a.hi * b.lo, a.lo * b.hi);
    return Dint::rounded(a.hi * b.lo, a.hi * b.hi);
  }
  if (a.hi <= 0) {
    if (b.lo >= 0) return Dint::rounded(a.lo * b.hi, a.hi * b.lo);
    if (b.hi <= 0) return Dint::rounded(a.hi * b.hi, a.lo * b.lo);
    return Dint::rounded(a.lo * b.hi, a.lo * b.lo);
  }
  if (b.lo >= 0) return Dint::rounded(a.lo * b.hi, a.hi * b.hi);
  if (b.hi <= 0) return Dint::rounded(a.hi * b.lo, a.lo * b.lo);
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return Dint::rounded(std::min(std::min(p1, p2), std::min(p3, p4)), std::max(std::max(p1, p2), std::max(p3, p4)));
}
inline Dint operator/(const Dint& a, const Dint& b) {
  if (b.contains_zero() || !b.finite()) return Dint::entire();
  const double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo, p4 = a.hi / b.hi;
  return Dint::rounded(std::min(std::min(p1, p2), std::min(p3, p4)), std::max(std::max(p1, p2), std::max(p3, p4)));
}
inline Dint operator*(const Dint& a, long k) { return a * Dint(static_cast<double>(k)); }  // |k| < 2^53: exact
inline Dint& operator+=(Dint& a, const Dint& b) { return a = a + b; }
inline Dint& operator-=(Dint& a, const Dint& b) { return a = a - b; }
inline Dint& operator*=(Dint& a, const Dint& b) { return a = a * b; }
inline Dint hull(const Dint& a, const Dint& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

/// pi, enclosed: fl(pi) = 3.141592653589793115997963... < pi < next(fl(pi))
inline Dint dint_pi() { return {3.141592653589793, std::nextafter(3.141592653589793, 4.0)}; }

/// sin(pi k/D) and cos(pi k/D) enclosed (see the header); false (s, c untouched) when D is not in
/// (0, 2^123).
inline bool sin_cos_pi(__int128 k, __int128 D, Dint& s, Dint& c) {
  if (D <= 0 || D >= (static_cast<__int128>(1) << 123)) return false;
  __int128 K;
  constexpr __int128 small = static_cast<__int128>(1) << 62;
  if (D < small && k < small && k > -small) {  // in 64 bits: a hardware division
    const long D2 = static_cast<long>(2 * D);
    K = static_cast<long>(k) % D2;
  } else {
    K = k % (2 * D);
  }
  if (K < 0) K += 2 * D;
  bool neg_s = false, neg_c = false, swap = false;
  if (K >= D) K -= D, neg_s = !neg_s, neg_c = !neg_c;  // x + pi
  if (2 * K > D) K = D - K, neg_c = !neg_c;            // pi - x
  if (4 * K > D) K = D - 2 * K, D = 2 * D, swap = true;  // pi/2 - x: now K/D <= 1/4
  constexpr double u = 0x1p-53;
  const double y = static_cast<double>(K) / static_cast<double>(D) * 3.141592653589793, x = y * y;
  double ps = -1.0 / 121645100408832000.0;  // -1/19!, then down to 1/1! (the coefficients rounded)
  constexpr double sc[] = {1.0, -1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880, -1.0 / 39916800,
                           1.0 / 6227020800.0, -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};
  for (int j = 8; j >= 0; --j) ps = ps * x + sc[j];
  constexpr double cc[] = {1.0, -1.0 / 2, 1.0 / 24, -1.0 / 720, 1.0 / 40320, -1.0 / 3628800,
                           1.0 / 479001600, -1.0 / 87178291200.0, 1.0 / 20922789888000.0,
                           -1.0 / 6402373705728000.0};
  double pc = 1.0 / 2432902008176640000.0;  // 1/20!
  for (int j = 9; j >= 0; --j) pc = pc * x + cc[j];
  const double sv = y * ps, es = 48 * u * y;
  Dint sy = Dint::rounded(sv - es, sv + es), cy = Dint::rounded(pc - 52 * u, pc + 52 * u);
  if (swap) std::swap(sy, cy);
  s = (neg_s ? -sy : sy).clamp(-1, 1);
  c = (neg_c ? -cy : cy).clamp(-1, 1);
  return true;
}


/// sqrt of the nonnegative part (IEEE sqrt is correctly rounded: one rounding); the whole line
/// when the interval is not finite or reaches below 0.
inline Dint sqrt(const Dint& a) {
  if (!a.finite() || a.lo < 0) return Dint::entire();
  return Dint::rounded(std::sqrt(a.lo), std::sqrt(a.hi));
}

namespace dint_detail {
/// atan(x) for a double x >= 0, enclosed: atan x = pi/2 - atan(1/x) for x > 1, then twice
/// t -> t/(1 + sqrt(1 + t^2)) (atan t = 2 atan t', exact identities, each step in interval
/// operations) to t'' <= tan(pi/16) < 0.19892, and the alternating series of decreasing terms
/// atan y = sum_{k=0}^{11} (-1)^k y^{2k+1}/(2k+1) + R, |R| <= y^25/25 <= 6e-19 y (checked in
/// rationals by the unit test), by interval Horner.
inline Dint atan_point(double x) {
  const bool big = x > 1;
  Dint t = big ? Dint(1.0) / Dint(x) : Dint(x);
  for (int i = 0; i < 2; ++i) t = t / (Dint(1.0) + sqrt(Dint(1.0) + t * t));
  static const auto coefficients = [] {
    std::array<Dint, 12> c;
    for (int k = 0; k < 12; ++k) c[static_cast<size_t>(k)] = Dint::from_rational(rational(k % 2 == 0 ? 1 : -1, 2 * k + 1));
    return c;
  }();
  const Dint y2 = t * t;
  Dint p = coefficients[11];
  for (int k = 10; k >= 0; --k) p = p * y2 + coefficients[static_cast<size_t>(k)];
  Dint a = (Dint(4.0) * (t * p)).widened(4 * 6e-19 * t.hi);
  if (big) a = dint_pi() * Dint(0.5) - a;
  return a;
}
}  // namespace dint_detail

/// atan over an interval (atan is increasing: its ends' enclosures).
inline Dint atan(const Dint& a) {
  if (!a.finite()) return Dint::entire();
  auto at = [](double x) { return x >= 0 ? dint_detail::atan_point(x) : -dint_detail::atan_point(-x); };
  return {at(a.lo).lo, at(a.hi).hi};
}

/// A complex number as two double intervals (a rectangle holding it), the double-interval twin of
/// flint::CBall (numeric/ball.hpp) with the same operations.
struct CDint {
  Dint re, im;
};
inline CDint operator+(const CDint& a, const CDint& b) { return {a.re + b.re, a.im + b.im}; }
inline CDint operator-(const CDint& a, const CDint& b) { return {a.re - b.re, a.im - b.im}; }
inline CDint operator*(const CDint& a, const CDint& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
inline CDint operator*(const Dint& k, const CDint& a) { return {k * a.re, k * a.im}; }
/// x^2 (>= 0 where x holds 0: tighter than x * x)
inline Dint sqr(const Dint& x) {
  if (!x.contains_zero()) return x * x;
  const double m = x.abs_upper();
  return {0.0, Dint::rounded(m * m, m * m).hi};
}
inline Dint norm(const CDint& a) { return sqr(a.re) + sqr(a.im); }  ///< |a|^2
inline CDint conj(const CDint& a) { return {a.re, -a.im}; }
inline CDint operator/(const CDint& a, const CDint& b) {
  const Dint d = norm(b);
  const CDint t = a * conj(b);
  return {t.re / d, t.im / d};
}
inline CDint horner(const std::vector<Dint>& p, const CDint& z) {
  if (p.empty()) return {Dint(0.0), Dint(0.0)};
  CDint r{p.back(), Dint(0.0)};
  for (size_t i = p.size() - 1; i-- > 0;) {
    r = r * z;
    r.re += p[i];
  }
  return r;
}
inline bool contains_zero(const CDint& a) { return a.re.contains_zero() && a.im.contains_zero(); }
/// The argument in (-pi, pi] of every point of the rectangle, when it lies in one of the open
/// half-planes re > 0, im > 0, im < 0 (atan(im/re), pi/2 - atan(re/im), -pi/2 - atan(re/im));
/// else (it straddles the negative real axis or holds 0) the whole line, which decides nothing.
inline Dint arg(const CDint& a) {
  if (a.re.positive()) return atan(a.im / a.re);
  const Dint half_pi = dint_pi() * Dint(0.5);
  if (a.im.positive()) return half_pi - atan(a.re / a.im);
  if (a.im.negative()) return -half_pi - atan(a.re / a.im);
  return Dint::entire();
}

}  // namespace hapstab
