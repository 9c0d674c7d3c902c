// hapstab/numeric/double_double.hpp -- double-double arithmetic (an unevaluated sum hi + lo of
// two doubles, ~32 significant digits) for the fast path of the passivity bound (45)
// (passivity/fast.cpp): error-free transformations two_sum / fast_two_sum and an fma
// product (Dekker, Knuth; the QD library's "sloppy" addition).
#pragma once

#include <cmath>
#include <vector>

#include <gmp.h>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

struct dd {
  double hi = 0, lo = 0;
};
inline dd two_sum(double a, double b) {
  double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
inline dd fast_two_sum(double a, double b) {
  double s = a + b;
  return {s, b - (s - a)};
}
inline dd operator+(dd a, dd b) {
  dd s = two_sum(a.hi, b.hi);
  s.lo += a.lo + b.lo;
  return fast_two_sum(s.hi, s.lo);
}
inline dd operator-(dd a) { return {-a.hi, -a.lo}; }
inline dd operator-(dd a, dd b) { return a + (-b); }
inline dd operator*(dd a, dd b) {
  double p = a.hi * b.hi;
  double e = std::fma(a.hi, b.hi, -p);
  e += a.hi * b.lo + a.lo * b.hi;
  return fast_two_sum(p, e);
}
inline dd operator/(dd a, dd b) {
  double q1 = a.hi / b.hi;
  dd r = a - b * dd{q1, 0};
  double q2 = r.hi / b.hi;
  r = r - b * dd{q2, 0};
  double q3 = r.hi / b.hi;
  return dd{q1, 0} + dd{q2, 0} + dd{q3, 0};
}

/// q in double-double: hi = q truncated to double (mpq_get_d), lo = the exact remainder rounded,
/// so |hi + lo - q| <= 2^-106 |q|.
inline dd to_dd(const rational& q) {
  double h = mpq_get_d(q.backend().data());
  rational r = q - exact_rational(h);
  return {h, mpq_get_d(r.backend().data())};
}

/// Horner in double-double for coefficients split into hi[] and lo[] (ascending), at a double x.
inline dd horner_dd(const std::vector<double>& hi, const std::vector<double>& lo, double x) {
  dd r{0, 0};
  for (size_t i = hi.size(); i-- > 0;) r = r * dd{x, 0} + dd{hi[i], lo[i]};
  return r;
}

}  // namespace hapstab
