// Exact Schur-Cohn-Jury and Routh tests, unit-circle roots and marginal stability (see
// stability.hpp).
#include "hapstab/poly/stability.hpp"

#include <optional>
#include <vector>

#include "hapstab/poly/sturm.hpp"
#include "hapstab/poly/unit_circle.hpp"

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

namespace {


// Distinct roots of the square-free s on |z| = 1: z = -1, and the real roots t of the common
// factor of Re, Im of (1 - jt)^m s(z(t)) (the other points of the circle).
int circle_roots_of_square_free(const QPoly& s) {
  const int m = s.degree();
  int on = (s(rational(-1)) == 0) ? 1 : 0;
  ComplexPolynomial cp = unit_circle_polynomial(s, m);
  QPoly h = cp.re.is_zero() ? cp.im : (cp.im.is_zero() ? cp.re : gcd(cp.re, cp.im));
  if (h.degree() > 0) on += static_cast<int>(isolate_real_roots(h).size());
  return on;
}

}  // namespace

int unit_circle_roots(const QPoly& p) {
  if (p.is_zero()) throw InputError("unit_circle_roots: the zero polynomial");
  if (p.degree() <= 0) return 0;
  QPoly g = gcd(p, reversed(p));  // every unit-circle root of p, and reciprocal pairs (r, 1/r)
  return g.degree() > 0 ? circle_roots_of_square_free(square_free_part(g)) : 0;
}

namespace {
bool marginally_stable_uncached(const QPoly& d, std::string* detail);
}

bool marginally_stable(const QPoly& d, std::string* detail) {
  if (d.is_zero()) throw InputError("the denominator of H is zero");
  if (d.degree() == 0) return true;
  // The last question this thread asked, answered again without the exact work: a vectorised
  // bound over a parameter of H's numerator asks about one denominator at every point.
  struct Last {
    QPoly d;
    bool stable = false;
    std::string detail;
  };
  thread_local std::optional<Last> last;
  if (!last || !(last->d == d)) {
    std::string why;
    const bool stable = marginally_stable_uncached(d, &why);
    last = Last{d, stable, std::move(why)};
  }
  if (!last->stable && detail) *detail = last->detail;
  return last->stable;
}

namespace {
bool marginally_stable_uncached(const QPoly& d, std::string* detail) {
  QPoly g = gcd(d, reversed(d));  // every unit-circle root of d, and reciprocal pairs (r, 1/r)
  QPoly d1 = d;
  if (g.degree() > 0) {
    for (QPoly h = gcd(d1, g); h.degree() > 0; h = gcd(d1, g)) d1 = divmod(d1, h).first;
    // all roots of g must lie on the circle
    QPoly s = square_free_part(g);
    if (circle_roots_of_square_free(s) != s.degree()) {
      if (detail) *detail = "a reciprocal pair of poles (r, 1/r) off the unit circle: one has |z| > 1";
      return false;
    }
    // a pole on the circle must be simple: a repeated one is a root of d' too (z/(z-1)^2 has an
    // impulse response k that grows without bound)
    if (gcd(s, d.derivative()).degree() > 0) {
      if (detail) *detail = "a repeated pole on the unit circle |z| = 1 (its impulse response grows without bound)";
      return false;
    }
  }
  // d1 has no roots on the circle: Schur-Cohn decides the rest
  std::string why;
  if (!schur_stable(d1, &why)) {
    if (detail) *detail = why;
    return false;
  }
  return true;
}
}  // namespace

}  // namespace hapstab
