#include "hapstab/numeric/numeric_decimal.hpp"

#include <sstream>

namespace hapstab {

std::string numeric_decimal(double x, int digits) {
  std::ostringstream o;
  o.precision(digits);
  o << x;
  return o.str();
}

}  // namespace hapstab
