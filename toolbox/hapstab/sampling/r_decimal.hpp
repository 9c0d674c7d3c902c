// hapstab/sampling/r_decimal.hpp -- r(jw) of paper 001 as correctly rounded decimal strings
// (what `hapstab r` prints), by Ziv's strategy: evaluate in MPFI intervals at increasing
// precision until every printed digit is decided (common_decimal of both ends).
//
//   re = -T/2                       exact rational (44)/(38), printed correctly rounded
//   im = -(T/2) cot(wT/2)            (44)/(38), certified enclosure -> correctly rounded digits
//   series_re/im                    (34) truncated at |n| <= N, certified -> correctly rounded
//   series_error_bound              |r - r_N| <= 2T|sin(wT/2)| tau_N (series.hpp), rounded UP to 3 digits
//
// Implements: paper 001 (34), (38), (44).
#pragma once

#include <optional>
#include <string>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::sampling {

struct RDecimal {
  std::string re, im;                         ///< (44), `digits` significant digits, correctly rounded
  std::string series_re, series_im;           ///< (34) truncated at |n| <= N, correctly rounded
  std::optional<std::string> series_error_bound;  ///< none when N <= |wT|/(2 pi) (bound not valid)
  long series_terms = 0;                      ///< N
  int precision_digits = 0;                   ///< working precision that decided im
};

/// Throws InputError for T <= 0, w = 0 (a pole of r), N < 0, digits outside [1, 1000];
/// NumericalError if wT/2 is so close to a multiple of pi that 4000-digit intervals cannot decide.
RDecimal r_decimal(const rational& T, const rational& omega, long N, int digits);

/// Only the closed form (44): {re, im} correctly rounded (same rules).
std::pair<std::string, std::string> r44_decimal(const rational& T, const rational& omega, int digits);

}  // namespace hapstab::sampling
