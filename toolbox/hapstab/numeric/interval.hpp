// hapstab/numeric/interval.hpp -- the small helpers every certified computation needs on the
// MPFI enclosures interval<D> (numeric/scalar.hpp), in one place:
//
//   ival<D>(a, b)           the enclosure of [a, b] for exact rationals a <= b (outward-rounded)
//   lower_rational(x)       the ends of an enclosure as exact rationals (the MPFR ends, exactly)
//   upper_rational(x)
//   ipi<D>()                pi, enclosed (mpfi_const_pi)
#pragma once

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

/// The outward-rounded enclosure of [a, b] at D decimal digits (mpfi_interv_q).
template <unsigned D>
interval<D> ival(const rational& a, const rational& b) {
  interval<D> x;
  mpfi_interv_q(x.backend().data(), a.backend().data(), b.backend().data());
  return x;
}

/// The left end of x as an exact rational (x must be bounded).
template <unsigned D>
rational lower_rational(const interval<D>& x) {
  return exact_rational(mpfloat<D>(lower(x)));
}

/// The right end of x as an exact rational (x must be bounded).
template <unsigned D>
rational upper_rational(const interval<D>& x) {
  return exact_rational(mpfloat<D>(upper(x)));
}

/// An enclosure of pi at D decimal digits.
template <unsigned D>
interval<D> ipi() {
  interval<D> x;
  mpfi_const_pi(x.backend().data());
  return x;
}

}  // namespace hapstab
