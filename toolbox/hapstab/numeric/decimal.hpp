// hapstab/numeric/decimal.hpp -- exact decimal <-> rational conversion.
//
// Input is exact (DESIGN.md): "0.001", "1e-3", "1/1000" and "+.001" all parse to the
// rational 1/1000. Output: decimal strings with D significant digits, correctly rounded
// (round-half-even) from an exact rational, or from an enclosure when the enclosure is
// narrow enough to decide every printed digit, or rounded outward (decimal_outward) so that a
// printed enclosure still contains the value.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

/// Parses a decimal ("-12.5e-3"), a fraction of decimals ("3/4", "1e-3/7") or an integer.
/// Throws InputError naming `what` and the text when it is not a number.
rational parse_rational(std::string_view text, std::string_view what = "number");

/// Same, but returns nullopt instead of throwing.
std::optional<rational> try_parse_rational(std::string_view text);

/// x with `digits` significant digits, correctly rounded to nearest (ties to even),
/// in scientific notation when the exponent is outside [-5, digits), e.g. "-0.0005", "1.25e+12".
std::string to_decimal(const rational& x, int digits);

/// The decimal string with `digits` significant digits that both ends of [lo, hi] round to,
/// or nullopt when the enclosure is too wide to decide them (caller then raises precision).
std::optional<std::string> common_decimal(const rational& lo, const rational& hi, int digits);

/// q with `digits` significant digits rounded outward (dir = -1 toward -inf, +1 toward +inf): the
/// nearest such decimal on that side, q itself when it has at most `digits` digits, so that a
/// printed enclosure still contains the value.
std::string decimal_outward(const rational& q, int digits, int dir);

/// q rounded to a double outward (dir = -1 toward -inf, +1 toward +inf; 0 to nearest): the
/// nearest double on that side, q itself when it is one, so that [double_outward(lo, -1),
/// double_outward(hi, +1)] still contains what [lo, hi] contains (beyond the double range:
/// -inf/+inf on the outward side, the largest finite double on the inward side).
double double_outward(const rational& q, int dir);

/// 10^e, exact.
rational pow10(long e);

/// Exact rational value of a finite binary floating number (double or MPFR).
rational exact_rational(double x);
template <unsigned D>
rational exact_rational(const mpfloat<D>& x) {
  // x = m * 2^e exactly (mpfr_get_z_2exp). An infinite or NaN x has no rational value:
  // mpfr_get_z_2exp would return 0 (the verify-random campaign found an interval [-inf, inf]
  // turned into the exact value [0, 0] this way), so it is refused.
  if (!mpfr_number_p(x.backend().data())) throw NumericalError("exact_rational: value is not finite");
  integer m;
  long e = mpfr_get_z_2exp(m.backend().data(), x.backend().data());
  rational q(m);
  if (e >= 0) q *= rational(integer(1) << e);
  else q /= rational(integer(1) << -e);
  return q;
}

}  // namespace hapstab
