// hapstab/check/affine.cpp -- see affine.hpp.
#include "hapstab/check/affine.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "hapstab/numeric/error.hpp"

namespace hapstab::check::detail {

using RF = RationalFunction<rational>;

// H = H0 + K H1, proven (affine.hpp): D + 1 values of K where H(k) = H0 + k H1 exactly.
Affine prove_affine(const std::string& text, ParseOptions po, const std::string& K) {
  constexpr long max_degree = 64;
  std::pair<long, long> deg;
  try {
    deg = ParsedExpression(text, po, {K}).degree_bound();
  } catch (const InputError& e) {
    throw InputError(std::string("model.H: ") + e.what());
  }
  Affine a;
  a.D = std::max(deg.first, deg.second + 1);
  if (a.D > max_degree)
    throw InputError("model.H: its degree in " + K + " is bounded only by " + std::to_string(a.D) + " (above " +
                     std::to_string(max_degree) + "): not proven affine in " + K);
  auto at = [&](const rational& k) {
    po.parameters[K] = k;
    return parse_tf(text, po).H;
  };
  try {
    a.H0 = at(rational(0));
    a.H1 = at(rational(1)) - a.H0;
  } catch (const InputError& e) {
    throw InputError("model.H at " + K + " = 0 or 1: " + e.what());
  }
  if (a.H1.is_zero()) throw InputError("model.H: does not depend on model.name = " + K);
  long proven = 2, tried = 0;
  for (long j = 2; proven < a.D + 1; ++j) {
    const rational k = j % 2 == 0 ? rational(j, 5) : rational(-j, 11);  // distinct, never 0 or 1
    std::optional<RF> h;
    try {
      h = at(k);
    } catch (const InputError&) {  // the expression divides by zero at k: at most dd such values
      if (++tried > a.D + deg.second + 2) throw InputError("model.H: undefined at too many values of " + K);
      continue;
    }
    if (*h != a.H0 + RF(k) * a.H1)
      throw InputError("model.H: not affine in " + K + " (H(" + k.str() + ") != H(0) + " + k.str() + " (H(1) - H(0)))");
    ++proven;
  }
  return a;
}

}  // namespace hapstab::check::detail
