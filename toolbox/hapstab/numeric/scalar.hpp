// hapstab/numeric/scalar.hpp -- the scalar tower (DESIGN.md, "Numbers and honesty").
//
//   double                         fast path; every double result states its error
//   mp50, mp100, mp1000            fixed-precision MPFR (50/100/1000 decimal digits); fixed
//                                  precision, never MPFR's process-wide default precision
//   rational                       exact GMP rational (mpq) with expression templates off,
//                                  so it behaves inside Eigen products
//   interval<D>, ival50, ival100   MPFI interval enclosures for certified results
//
// Include "hapstab/numeric/eigen_traits.hpp" (not boost/multiprecision/eigen.hpp) when a
// Boost number goes into an Eigen matrix.
#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <boost/multiprecision/mpfi.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <string>

namespace hapstab {

namespace bmp = boost::multiprecision;

using integer = bmp::number<bmp::gmp_int, bmp::et_off>;
using rational = bmp::number<bmp::gmp_rational, bmp::et_off>;

template <unsigned Digits10>
using mpfloat = bmp::number<bmp::mpfr_float_backend<Digits10>, bmp::et_off>;
using mp50 = mpfloat<50>;
using mp100 = mpfloat<100>;
using mp1000 = mpfloat<1000>;

template <unsigned Digits10>
using interval = bmp::number<bmp::mpfi_float_backend<Digits10>, bmp::et_off>;
using ival50 = interval<50>;
using ival100 = interval<100>;

/// Numerator and denominator of an exact rational.
inline integer num(const rational& q) { return bmp::numerator(q); }
inline integer den(const rational& q) { return bmp::denominator(q); }

/// The sign of an exact rational: -1, 0 or +1.
inline int sgn(const rational& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

/// Converts an exact rational to a floating type, correctly rounded for MPFR types
/// (mpfr_set_q) and for double (within 1/2 ulp via a 60-digit intermediate).
template <class Real>
Real to_real(const rational& q) {
  if constexpr (std::is_same_v<Real, double>) {
    return static_cast<double>(mpfloat<60>(q));
  } else {
    return Real(q);
  }
}

}  // namespace hapstab
