// Explicit instantiations of the exact (rational) polynomial algebra, and to_string.
#include "hapstab/poly/polynomial.hpp"

#include "hapstab/poly/rational_function.hpp"

namespace hapstab {

template class Polynomial<rational>;
template std::pair<Polynomial<rational>, Polynomial<rational>> divmod(const Polynomial<rational>&,
                                                                      const Polynomial<rational>&);
template Polynomial<rational> gcd(Polynomial<rational>, Polynomial<rational>);
template class RationalFunction<rational>;

std::string to_string(const Polynomial<rational>& p, const std::string& var) {
  if (p.is_zero()) return "0";
  std::string out;
  for (int k = p.degree(); k >= 0; --k) {
    const rational& c = p.coeffs()[k];
    if (c == 0) continue;
    const bool neg = c < 0;
    const rational a = neg ? rational(-c) : c;
    if (out.empty()) out += neg ? "-" : "";
    else out += neg ? " - " : " + ";
    if (k == 0) {
      out += a.str();
    } else {
      if (a != 1) out += a.str() + "*";
      out += var;
      if (k > 1) out += "^" + std::to_string(k);
    }
  }
  return out;
}

}  // namespace hapstab
