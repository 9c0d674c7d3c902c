// hapstab/numeric/shared_decimal.hpp -- what may be printed of a value known only by its
// enclosure: the digits both ends share (numeric/decimal.hpp's common_decimal, searched down from
// the asked digits), and how many. `bound`, `stability --max` and `wedge` print through it.
#pragma once

#include <string>

#include "hapstab/numeric/decimal.hpp"

namespace hapstab {
/// What may be printed of a value known by its enclosure [lo, hi]: the decimal with the most
/// significant digits, at most `digits`, that both ends round to (so the value rounds to it too),
/// and how many digits that is; {"", 0} when the ends do not share even the first digit. An exact
/// value (lo == hi) keeps all `digits`. The one implementation behind every certified decimal.
struct SharedDecimal {
  std::string text;
  int digits = 0;
};
SharedDecimal shared_decimal(const rational& lo, const rational& hi, int digits);

}  // namespace hapstab
