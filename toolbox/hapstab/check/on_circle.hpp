// hapstab/check/on_circle.hpp -- polynomials in z on the unit circle, the checkers' own: with
// c = cos(theta), s = sin(theta), z = c + js and s^2 = 1 - c^2, a real polynomial p(z) is
// a(c) + js b(c) with a, b real polynomials in c; a product is
//   (a1 a2 - (1 - c^2) b1 b2) + js (a1 b2 + a2 b1).
// Used by check/bound_check.hpp (paper 001 (45)) and check/wedge_check.hpp (paper 002 (21), (25)).
#pragma once

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check::circle {

using P = Polynomial<rational>;

/// a(c) + j s b(c).
struct OnCircle {
  P a, b;
};

inline P one_minus_c2() { return P{rational(1), rational(0), rational(-1)}; }

inline OnCircle mul(const OnCircle& x, const OnCircle& y) {
  return {x.a * y.a - one_minus_c2() * x.b * y.b, x.a * y.b + x.b * y.a};
}

/// p(z) at z = c + js, by Horner.
inline OnCircle at_circle(const P& p) {
  const OnCircle z{P{rational(0), rational(1)}, P(rational(1))};
  OnCircle r{P(), P()};
  for (int k = p.degree(); k >= 0; --k) {
    r = mul(r, z);
    r.a += P(p.coeff(k));
  }
  return r;
}

}  // namespace hapstab::check::circle
