// hapstab/check/reciprocal.cpp -- see reciprocal.hpp.
#include "hapstab/check/reciprocal.hpp"

#include <vector>

#include "hapstab/check/nonnegative.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check::detail {

namespace {

using P = Polynomial<rational>;

rational power(const rational& x, long n) {
  rational r(1);
  for (long i = 0; i < n; ++i) r *= x;
  return r;
}

/// The coefficients' sign variations of p (zeros skipped): Descartes' bound of its positive roots.
int coefficient_variations(const P& p) {
  int v = 0, last = 0;
  for (const rational& c : p.coeffs()) {
    const int sg = c > 0 ? 1 : c < 0 ? -1 : 0;
    if (sg != 0 && last != 0 && sg != last) ++v;
    if (sg != 0) last = sg;
  }
  return v;
}

}  // namespace

rational resultant(const P& f0, const P& g0) {
  if (f0.is_zero() || g0.is_zero()) throw InputError("resultant: a zero polynomial (checker defect)");
  P f = f0, g = g0;
  rational r(1);
  while (true) {
    const long m = f.degree(), n = g.degree();
    if (n == 0) return r * power(g.coeff(0), m);  // Res(f, g0) = g0^m
    if (m == 0) return r * power(f.coeff(0), n);  // Res(f0, g) = f0^n
    P rem = divmod(f, g).second;
    if (rem.is_zero()) return rational(0);  // g divides f: a common root
    // Res(f, g) = (-1)^(mn) Res(g, f) = (-1)^(mn) lc(g)^(m - deg r) Res(g, r), f = q g + r
    if ((m * n) % 2 != 0) r = -r;
    r *= power(g.leading(), m - rem.degree());
    f = std::move(g);
    g = std::move(rem);
  }
}

rational reciprocal_resultant(const P& c) {
  const long d = c.degree();
  if (d < 1) throw InputError("reciprocal_resultant: degree < 1 (checker defect)");
  const P star = reversed(c);  // z^d c(1/z): its degree drops by the multiplicity of the root 0 of c
  return power(c.leading(), d - star.degree()) * resultant(c, star);
}

P reciprocal_resultant(const P& c0, const P& c1) {
  const long d = c0.degree();
  if (d < 1 || c1.degree() >= d) throw InputError("reciprocal_resultant: need deg c1 < deg c0 >= 1 (checker defect)");
  const long N = 2 * d;  // D has degree <= 2d in K: its values at K = 0 .. 2d determine it
  std::vector<rational> a;
  for (long i = 0; i <= N; ++i) a.push_back(reciprocal_resultant(c0 + c1 * P(rational(i))));
  for (long j = 1; j <= N; ++j)  // Newton's divided differences at the points x_i = i
    for (long i = N; i >= j; --i) a[static_cast<size_t>(i)] = (a[static_cast<size_t>(i)] - a[static_cast<size_t>(i - 1)]) / rational(j);
  P D(a[static_cast<size_t>(N)]);
  for (long i = N - 1; i >= 0; --i) D = D * P{rational(-i), rational(1)} + P(a[static_cast<size_t>(i)]);
  return D;
}

int roots_between(const P& p, const rational& a, const std::optional<rational>& b, bool closed_b) {
  if (p.is_zero()) throw InputError("roots_between: the zero polynomial (checker defect)");
  if (p.degree() <= 0) return 0;
  P q = divmod(p, gcd(p, p.derivative())).first;  // square-free: every root simple
  const auto drop = [&](const rational& x) {
    if (q.degree() > 0 && q(x) == 0) {
      q = divmod(q, P{-x, rational(1)}).first;
      return 1;
    }
    return 0;
  };
  drop(a);
  int count = 0;
  if (b && drop(*b) == 1 && closed_b) count = 1;
  if (q.degree() <= 0) return count;
  rational upper;
  if (b) {
    upper = *b;
  } else {  // Cauchy: every root x has |x| < 1 + max |q_i/q_d|
    rational m(0);
    for (int i = 0; i < q.degree(); ++i) {
      const rational v = abs(q.coeff(i) / q.leading());
      if (v > m) m = v;
    }
    upper = abs(a) + m + 1;
    if (coefficient_variations(q.compose(P{a, rational(1)})) == 0) return count;  // none in (a, inf): Descartes
  }
  if (upper <= a) return count;
  if (descartes_no_root(q, a, upper)) return count;
  return count + sturm_count(q, a, upper);
}

}  // namespace hapstab::check::detail
