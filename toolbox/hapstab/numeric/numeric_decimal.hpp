// hapstab/numeric/numeric_decimal.hpp -- a numeric (double) value as a decimal, for messages and
// notes: the one formatter of doubles the library's texts use. Exact and certified values print
// through decimal.hpp (to_decimal, decimal_outward), which round a rational correctly or outward.
#pragma once

#include <string>

namespace hapstab {

/// x with `digits` significant digits in the stream's general format (scientific when the exponent
/// is below -4 or at least `digits`, trailing zeros dropped: "0.000123", "1.5e+07").
std::string numeric_decimal(double x, int digits = 6);

}  // namespace hapstab
