// Exact Schur-Cohn-Jury and Routh tests (see stability.hpp).
#include "hapstab/poly/stability.hpp"

#include <vector>

namespace hapstab {

bool schur_stable(const Polynomial<rational>& p0, std::string* why) {
  if (p0.is_zero()) throw InputError("schur_stable: the zero polynomial");
  // p as a primitive integer polynomial (the test does not see a positive scale)
  integer scale = 1;
  for (const auto& c : p0.coeffs()) scale = boost::multiprecision::lcm(scale, denominator(c));
  std::vector<integer> p;
  for (const auto& c : p0.coeffs()) p.push_back(numerator(c) * (scale / denominator(c)));
  while (p.size() > 1) {
    const integer a0 = p.front(), an = p.back();
    if (abs(a0) >= abs(an)) {
      if (why)
        *why = "Schur-Cohn test: a root with |z| >= 1 (|p(0)| >= |leading| at degree " + std::to_string(p.size() - 1) + ")";
      return false;
    }
    const size_t n = p.size() - 1;
    std::vector<integer> next(n);
    integer g = 0;
    for (size_t k = 1; k <= n; ++k) {  // coefficient k of an p - a0 p*, k >= 1 (the constant vanishes)
      next[k - 1] = an * p[k] - a0 * p[n - k];
      g = gcd(g, next[k - 1]);
    }
    if (g > 1)
      for (auto& c : next) c /= g;
    while (next.size() > 1 && next.back() == 0) next.pop_back();
    p = std::move(next);
  }
  return true;
}

bool hurwitz_stable(const Polynomial<rational>& p) {
  if (p.is_zero()) return false;
  const int n = p.degree();
  if (n == 0) return true;
  // Routh array in exact arithmetic: stable iff the n+1 first-column entries are all nonzero
  // with the sign of a_n (a zero entry means a root on or right of the axis, or a symmetric pair).
  std::vector<rational> r0, r1;
  for (int k = n; k >= 0; k -= 2) r0.push_back(p.coeff(k));
  for (int k = n - 1; k >= 0; k -= 2) r1.push_back(p.coeff(k));
  const bool positive = p.leading() > 0;
  for (int row = 1; row <= n; ++row) {
    if (r1.empty() || r1[0] == 0 || (r1[0] > 0) != positive) return false;
    const size_t L = std::max(r0.size(), r1.size());
    r0.resize(L, rational(0));
    r1.resize(L, rational(0));
    std::vector<rational> r2(L > 1 ? L - 1 : 1, rational(0));
    for (size_t k = 0; k + 1 < L; ++k) r2[k] = (r1[0] * r0[k + 1] - r0[0] * r1[k + 1]) / r1[0];
    r0 = std::move(r1);
    r1 = std::move(r2);
  }
  return true;
}

}  // namespace hapstab
