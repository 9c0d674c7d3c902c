// hapstab/numeric/ball.hpp -- a real Arb ball (arb_t) as a value type with arithmetic, at the
// working precision of this thread (BallPrecision), for code that evaluates formulas in ball
// arithmetic: the long-delay paths of the passivity bound and of the stability test, and the
// certified root tests of stability/sampled_loop.cpp. Every operation returns a ball proven to
// contain the exact result for every point of its operands (Arb's contract); a ball that Arb
// cannot bound is non-finite, and bounds() refuses it (NumericalError), never a number.
//
// Like numeric/flint.hpp (which it includes), only .cpp files include this header.
#pragma once

#include <string>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::flint {

/// The working precision (bits) of every Ball operation on this thread.
inline thread_local long ball_prec = 128;

/// Sets ball_prec for a scope and restores it after.
class BallPrecision {
 public:
  explicit BallPrecision(long bits) : saved_(ball_prec) { ball_prec = bits; }
  ~BallPrecision() { ball_prec = saved_; }
  BallPrecision(const BallPrecision&) = delete;
  BallPrecision& operator=(const BallPrecision&) = delete;

 private:
  long saved_;
};

class Ball {
 public:
  Ball() { arb_init(x_); }
  Ball(const rational& q) {  // NOLINT: exact data -> ball (exact when dyadic)
    arb_init(x_);
    set(x_, q, ball_prec);
  }
  explicit Ball(long v) {
    arb_init(x_);
    arb_set_si(x_, v);
  }
  explicit Ball(int v) : Ball(static_cast<long>(v)) {}
  explicit Ball(double d) {  // exact: every double is dyadic
    arb_init(x_);
    arb_set_d(x_, d);
  }
  Ball(const arb_t x) {  // NOLINT
    arb_init(x_);
    arb_set(x_, x);
  }
  Ball(const Ball& o) {
    arb_init(x_);
    arb_set(x_, o.x_);
  }
  Ball(Ball&& o) noexcept {
    arb_init(x_);
    arb_swap(x_, o.x_);
  }
  Ball& operator=(const Ball& o) {
    arb_set(x_, o.x_);
    return *this;
  }
  Ball& operator=(Ball&& o) noexcept {
    arb_swap(x_, o.x_);
    return *this;
  }
  ~Ball() { arb_clear(x_); }
  arb_struct* get() { return x_; }
  const arb_struct* get() const { return x_; }

  /// The ball holding every point of [lo, hi] (lo <= hi, exact rationals).
  static Ball hull(const rational& lo, const rational& hi) {
    Ball r(lo);
    arb_union(r.x_, r.x_, Ball(hi).x_, ball_prec);
    return r;
  }
  static Ball pi() {
    Ball r;
    arb_const_pi(r.x_, ball_prec);
    return r;
  }

  friend Ball operator+(const Ball& a, const Ball& b) { Ball r; arb_add(r.x_, a.x_, b.x_, ball_prec); return r; }
  friend Ball operator-(const Ball& a, const Ball& b) { Ball r; arb_sub(r.x_, a.x_, b.x_, ball_prec); return r; }
  friend Ball operator*(const Ball& a, const Ball& b) { Ball r; arb_mul(r.x_, a.x_, b.x_, ball_prec); return r; }
  friend Ball operator/(const Ball& a, const Ball& b) { Ball r; arb_div(r.x_, a.x_, b.x_, ball_prec); return r; }
  friend Ball operator*(const Ball& a, long k) { Ball r; arb_mul_si(r.x_, a.x_, k, ball_prec); return r; }
  Ball operator-() const { Ball r; arb_neg(r.x_, x_); return r; }
  Ball& operator+=(const Ball& b) { arb_add(x_, x_, b.x_, ball_prec); return *this; }
  Ball& operator-=(const Ball& b) { arb_sub(x_, x_, b.x_, ball_prec); return *this; }
  Ball& operator*=(const Ball& b) { arb_mul(x_, x_, b.x_, ball_prec); return *this; }

  bool positive() const { return arb_is_positive(x_); }          ///< every point > 0
  bool negative() const { return arb_is_negative(x_); }          ///< every point < 0
  bool contains_zero() const { return arb_contains_zero(x_); }
  bool is_zero() const { return arb_is_zero(x_); }               ///< exactly 0
  bool finite() const { return arb_is_finite(x_); }
  bool exact() const { return arb_is_exact(x_); }
  /// Every point of *this is below every point of b.
  bool below(const Ball& b) const { return arb_lt(x_, b.x_); }
  /// The upper (lower) end of the ball as an exact ball of radius 0; +inf (-inf) when the ball is
  /// not finite: the one-sided bounds a branch-and-bound compares exactly (arb_lt on exact balls).
  Ball upper_end() const { return end(true); }
  Ball lower_end() const { return end(false); }
  /// +inf or -inf as an exact ball.
  static Ball infinity(bool positive) {
    Ball r;
    arf_t a;
    arf_init(a);
    if (positive) arf_pos_inf(a);
    else arf_neg_inf(a);
    arb_set_arf(r.x_, a);
    arf_clear(a);
    return r;
  }
  /// The midpoint as a ball of radius 0.
  Ball mid() const { Ball r; arb_get_mid_arb(r.x_, x_); return r; }
  /// An upper bound of the radius, as a double (for comparisons only).
  double radius() const { return mag_get_d(arb_radref(x_)); }
  /// An upper bound of |x| for every point x of the ball, rounded up to a double (for decisions).
  double abs_upper() const {
    arf_t u;
    arf_init(u);
    arb_get_abs_ubound_arf(u, x_, 64);
    const double d = arf_get_d(u, ARF_RND_UP);
    arf_clear(u);
    return d;
  }
  /// The ball's ends as exact rationals (NumericalError when it is not finite).
  Enclosure<rational> bounds() const {
    if (!arb_is_finite(x_)) throw NumericalError("ball arithmetic lost the enclosure (a non-finite ball)");
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x_, ball_prec);
    arb_get_ubound_arf(hi, x_, ball_prec);
    Enclosure<rational> e{to_rational(lo), to_rational(hi)};
    arf_clear(lo);
    arf_clear(hi);
    return e;
  }
  /// The nearest double of the midpoint (for starting points and figures, never a result).
  double to_double() const { return arf_get_d(arb_midref(x_), ARF_RND_NEAR); }

 private:
  Ball end(bool up) const {
    if (!arb_is_finite(x_)) return infinity(up);
    Ball r;
    arf_t a;
    arf_init(a);
    if (up) arb_get_ubound_arf(a, x_, ball_prec);
    else arb_get_lbound_arf(a, x_, ball_prec);
    arb_set_arf(r.x_, a);
    arf_clear(a);
    return r;
  }
  arb_t x_;
};

inline Ball abs(const Ball& a) { Ball r; arb_abs(r.get(), a.get()); return r; }
inline Ball sqr(const Ball& a) { return a * a; }
inline Ball sqrt(const Ball& a) { Ball r; arb_sqrt(r.get(), a.get(), ball_prec); return r; }
inline void sin_cos(const Ball& x, Ball& s, Ball& c) { arb_sin_cos(s.get(), c.get(), x.get(), ball_prec); }
inline Ball atan2(const Ball& y, const Ball& x) { Ball r; arb_atan2(r.get(), y.get(), x.get(), ball_prec); return r; }
inline Ball acos(const Ball& x) { Ball r; arb_acos(r.get(), x.get(), ball_prec); return r; }
/// The ball holding a and b (and everything between).
inline Ball hull(const Ball& a, const Ball& b) { Ball r; arb_union(r.get(), a.get(), b.get(), ball_prec); return r; }
/// a intersected with b; false when they are disjoint (r is then unchanged).
inline bool intersect(Ball& r, const Ball& a, const Ball& b) { return arb_intersection(r.get(), a.get(), b.get(), ball_prec); }
/// a widened by +-e (e >= 0, a rational bound).
inline Ball widen(const Ball& a, const rational& e) {
  Ball r = a, w(e);
  arb_add_error(r.get(), w.get());
  return r;
}

/// A complex number as two real balls (a rectangle holding it): what the argument principle and
/// the crossing search of the long-delay stability path evaluate polynomials at e^{j theta} in.
struct CBall {
  Ball re, im;
};
inline CBall operator+(const CBall& a, const CBall& b) { return {a.re + b.re, a.im + b.im}; }
inline CBall operator-(const CBall& a, const CBall& b) { return {a.re - b.re, a.im - b.im}; }
inline CBall operator*(const CBall& a, const CBall& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
inline CBall operator*(const Ball& k, const CBall& a) { return {k * a.re, k * a.im}; }
inline Ball norm(const CBall& a) { return sqr(a.re) + sqr(a.im); }  ///< |a|^2
inline CBall conj(const CBall& a) { return {a.re, -a.im}; }
inline CBall operator/(const CBall& a, const CBall& b) {
  const Ball d = norm(b);
  const CBall t = a * conj(b);
  return {t.re / d, t.im / d};
}
/// e^{j theta} for every theta in the ball.
inline CBall unit(const Ball& theta) {
  CBall z;
  sin_cos(theta, z.im, z.re);
  return z;
}
/// p(z) for real coefficients (ascending), by Horner.
inline CBall horner(const std::vector<Ball>& p, const CBall& z) {
  if (p.empty()) return {Ball(0L), Ball(0L)};
  CBall r{p.back(), Ball(0L)};
  for (size_t i = p.size() - 1; i-- > 0;) {
    r = r * z;
    r.re += p[i];
  }
  return r;
}
/// True when the rectangle holds 0 (its real and imaginary parts both contain 0).
inline bool contains_zero(const CBall& a) { return a.re.contains_zero() && a.im.contains_zero(); }
/// The argument of a complex ball whose rectangle excludes 0 and lies in the half-plane of its
/// centre, in (-pi, pi]; a ball straddling the negative real axis gets a wide result.
inline Ball arg(const CBall& a) { return atan2(a.im, a.re); }

}  // namespace hapstab::flint
