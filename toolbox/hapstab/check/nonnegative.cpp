// hapstab/check/nonnegative.cpp -- see nonnegative.hpp.
#include "hapstab/check/nonnegative.hpp"

#include <vector>

#include "hapstab/numeric/decimal.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

P exact_quotient(const P& a, const P& b) { return divmod(a, b).first; }

int sign(const rational& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

// p times a positive rational with integer coefficients and no common factor: the same signs
// everywhere, and a Sturm sequence's numbers do not carry the contents its remainders grow.
P primitive(const P& p) {
  if (p.is_zero()) return p;
  integer l(1), g(0);
  for (const rational& c : p.coeffs()) l = lcm(l, den(c));
  for (const rational& c : p.coeffs()) g = gcd(g, integer(num(c) * (l / den(c))));
  return p * (rational(l) / rational(g));
}

// The sign of p(x), x = u/v (v > 0): of sum c_i u^i v^(d - i) = v^d p(x) by Horner's rule in integers when
// p's coefficients are integers (no gcd at each step, as a rational p(x) takes); else p(x) itself.
int sign_at(const P& p, const rational& x) {
  if (p.is_zero()) return 0;
  for (const rational& c : p.coeffs())
    if (den(c) != 1) return sign(p(x));
  const integer u = num(x), v = den(x);
  integer acc = num(p.coeffs().back()), vp(1);
  for (size_t i = p.coeffs().size() - 1; i-- > 0;) {
    vp *= v;
    acc = acc * u + num(p.coeffs()[i]) * vp;
  }
  return acc > 0 ? 1 : acc < 0 ? -1 : 0;
}

// The factors of odd multiplicity of p (Yun's algorithm): p = c prod a_i^i.
P odd_part(const P& p) {
  const P dp = p.derivative();
  if (dp.is_zero()) return P(rational(1));  // a constant: no roots
  P g = gcd(p, dp);
  P b = exact_quotient(p, g), c = exact_quotient(dp, g);
  P d = c - b.derivative();
  P odd(rational(1));
  for (int i = 1; b.degree() > 0; ++i) {
    P a = gcd(b, d);
    if (i % 2 == 1) odd *= a;
    b = exact_quotient(b, a);
    c = exact_quotient(d, a);
    d = c - b.derivative();
  }
  return odd;
}

}  // namespace

bool descartes_no_root(const P& q, const rational& a, const rational& b) {
  if (q.degree() <= 0) return true;
  const P R = reversed(q.compose(P{a, b - a})).compose(P{rational(1), rational(1)});
  int variations = 0, last = 0;
  for (const rational& c : R.coeffs()) {
    const int sg = sign(c);
    if (sg != 0 && last != 0 && sg != last) ++variations;
    if (sg != 0) last = sg;
  }
  return variations == 0;
}

std::vector<P> sturm_sequence(const P& q) {
  std::vector<P> seq{primitive(q), primitive(q.derivative())};
  while (!seq.back().is_zero() && seq.back().degree() > 0) {
    P r = divmod(seq[seq.size() - 2], seq.back()).second;
    if (r.is_zero()) break;
    seq.push_back(primitive(-r));
  }
  return seq;
}

int sturm_count(const std::vector<P>& seq, const rational& a, const rational& b) {
  auto variations = [&](const rational& x) {
    int v = 0, last = 0;
    for (const P& s : seq) {
      if (s.is_zero()) continue;
      const int sg = sign_at(s, x);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++v;
      last = sg;
    }
    return v;
  };
  return variations(a) - variations(b);
}

int sturm_count(const P& q, const rational& a, const rational& b) { return sturm_count(sturm_sequence(q), a, b); }

std::optional<std::string> nonnegative_on(const P& p, const rational& a, const rational& b) {
  if (p.is_zero()) return std::nullopt;
  // A false claim is cheap to refute: above degree 64, where the square-free part's gcds and the
  // Sturm sequence cost minutes in exact rationals (degree 400: > 60 s, coefficient growth), p is
  // first evaluated at 33 equally spaced points of [a, b]; a negative value refutes.
  if (p.degree() > 64) {
    for (int k = 0; k <= 32; ++k) {
      const rational x = a + (b - a) * rational(k, 32);
      const rational v = p(x);
      if (v < 0) return "it is negative at c = " + x.str() + " (value " + to_decimal(v, 6) + ")";
    }
  }
  P odd = odd_part(p);
  for (const rational& end : {a, b})  // a sign change at an end of [a, b] is not inside it
    while (odd.degree() > 0 && odd(end) == 0) odd = exact_quotient(odd, P{-end, rational(1)});
  // Descartes first (cheap, O(d^2)): the roots of odd in (a, b) are those of
  // R(y) = (1 + y)^d q(1/(1 + y)) in y > 0, q(u) = odd(a + (b - a) u); no sign variation in R's
  // coefficients proves there is none. Otherwise Sturm counts them.
  const bool none_inside = odd.degree() <= 0 || descartes_no_root(odd, a, b);
  if (!none_inside) {
    const int n = sturm_count(odd, a, b);
    if (n > 0)
      return "it changes sign at " + std::to_string(n) + " point(s) inside [" + a.str() + ", " + b.str() +
             "] (roots of odd multiplicity, Sturm)";
  }
  const int tries = p.degree() + 1;
  for (int k = 1; k <= tries; ++k) {
    const rational x = a + (b - a) * rational(k) / rational(tries + 1);
    const rational v = p(x);
    if (v == 0) continue;
    if (v < 0) return "it is negative at c = " + x.str() + " (value " + to_decimal(v, 6) + ")";
    return std::nullopt;
  }
  return "no point of (a, b) where it is non-zero was found";  // unreachable: p != 0 has <= deg p roots
}

}  // namespace hapstab::check
