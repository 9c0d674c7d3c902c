// hapstab/check/schur_cohn.cpp -- see schur_cohn.hpp.
#include "hapstab/check/schur_cohn.hpp"

#include <vector>

#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

SchurCohn schur_cohn(const Polynomial<rational>& p) {
  if (p.is_zero()) throw InputError("schur_cohn: the zero polynomial");
  std::vector<rational> a = p.coeffs();
  while (a.size() > 1) {
    const size_t d = a.size() - 1;
    const rational &a0 = a.front(), &ad = a.back();
    if (abs(a0) >= abs(ad))
      return {false, "Schur-Cohn step at degree " + std::to_string(d) + ": |p_0| = " + abs(a0).str() + " >= |p_d| = " +
                         abs(ad).str() + " (a root on or outside the unit circle)"};
    std::vector<rational> q(d);
    for (size_t i = 0; i < d; ++i) q[i] = ad * a[i + 1] - a0 * a[d - 1 - i];
    const rational lead = q.back();  // ad^2 - a0^2 > 0
    for (rational& x : q) x /= lead;
    a = std::move(q);
  }
  return {true, "every Schur-Cohn step passes (|p_0| < |p_d| at each degree)"};
}

}  // namespace hapstab::check
