// hapstab/numeric/eigen_traits.hpp -- the one place that tells Eigen about Boost numbers.
//
// Boost 1.74's boost/multiprecision/eigen.hpp is incomplete (no infinity/quiet_NaN/digits,
// a wrong lowest()), so this header replaces it; never include both. Covered: every
// bmp::number<Backend, et_off> used in scalar.hpp (rational, mpfloat<D>, interval<D>).
// For `rational`, epsilon() and dummy_precision() are 0: exact arithmetic has no rounding,
// so Eigen's pivoting thresholds compare against an exact zero. MatQ, the exact matrix, is
// defined here once.
#pragma once

#include <Eigen/Core>
#include <limits>

#include "hapstab/numeric/scalar.hpp"

namespace Eigen {

template <class Backend>
struct NumTraits<boost::multiprecision::number<Backend, boost::multiprecision::et_off>> {
  using Self = boost::multiprecision::number<Backend, boost::multiprecision::et_off>;
  using Real = Self;
  using NonInteger = Self;
  using Literal = Self;
  using Nested = Self;
  static constexpr bool exact =
      boost::multiprecision::number_category<Self>::value == boost::multiprecision::number_kind_rational;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 8,
    AddCost = 32,
    MulCost = 64
  };
  static Real epsilon() { return exact ? Real(0) : std::numeric_limits<Self>::epsilon(); }
  static Real dummy_precision() { return exact ? Real(0) : Real(1000) * epsilon(); }
  static Real highest() {
    if constexpr (exact) return Real(std::numeric_limits<double>::max());
    else return (std::numeric_limits<Self>::max)();
  }
  static Real lowest() { return -highest(); }
  static Real infinity() {
    if constexpr (exact) return highest();
    else return std::numeric_limits<Self>::infinity();
  }
  static Real quiet_NaN() {
    if constexpr (exact) return Real(0);
    else return std::numeric_limits<Self>::quiet_NaN();
  }
  static int digits10() { return exact ? 0 : std::numeric_limits<Self>::digits10; }
  static int digits() { return exact ? 0 : std::numeric_limits<Self>::digits; }
  static int max_digits10() { return exact ? 0 : std::numeric_limits<Self>::max_digits10; }
};

}  // namespace Eigen

namespace hapstab {

/// A dynamic-size matrix of exact rationals: the one name for it in every module.
using MatQ = Eigen::Matrix<rational, Eigen::Dynamic, Eigen::Dynamic>;

}  // namespace hapstab
