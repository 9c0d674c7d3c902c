#include "hapstab/poly/sturm.hpp"

#include <algorithm>

namespace hapstab {

namespace {

void require_nonzero(const Polynomial<rational>& p, const char* who) {
  if (p.is_zero())
    throw InputError(std::string(who) + ": the zero polynomial vanishes everywhere (infinitely many roots)");
}

// Scales by a positive constant to the primitive integer polynomial (coefficients coprime
// integers): keeps Sturm signs, tames growth, and lets sign_at evaluate without any gcd.
Polynomial<rational> positive_normalise(const Polynomial<rational>& p) {
  if (p.is_zero()) return p;
  integer L = 1, G = 0;
  for (const auto& c : p.coeffs()) L = bmp::lcm(L, den(c));
  for (const auto& c : p.coeffs()) G = bmp::gcd(G, num(c) * (L / den(c)));
  return p * rational(L, G);
}

// sign of p(a/b), b > 0: for integer coefficients the sign of sum c_i a^i b^(n-i), all in
// integers (exact, and no rational canonicalisation); otherwise by rational evaluation.
int sign_at(const Polynomial<rational>& p, const rational& x) {
  const auto& c = p.coeffs();
  for (const auto& ci : c)
    if (den(ci) != 1) return sgn(p(x));
  const integer a = num(x), b = den(x);
  integer h = num(c.back()), bp = 1;
  for (int i = static_cast<int>(c.size()) - 2; i >= 0; --i) {
    bp *= b;
    h = h * a + num(c[static_cast<size_t>(i)]) * bp;
  }
  return h > 0 ? 1 : (h < 0 ? -1 : 0);
}

}  // namespace

rational cauchy_bound(const Polynomial<rational>& p) {
  rational m = 0;
  const rational& an = p.leading();
  for (int i = 0; i < p.degree(); ++i) {
    rational r = p.coeffs()[i] / an;
    if (r < 0) r = -r;
    if (r > m) m = r;
  }
  return m + 1;
}

Polynomial<rational> square_free_part(const Polynomial<rational>& p) {
  require_nonzero(p, "square_free_part");
  if (p.degree() <= 0) return p.monic();
  Polynomial<rational> g = gcd(p, p.derivative());
  return divmod(p, g).first.monic();
}

namespace {
// -prem(a, b) made primitive, for integer a, b with deg a >= deg b: each step multiplies the
// running remainder by |lc(b)| > 0 before cancelling its leading term, so the result is a
// POSITIVE multiple of -rem(a, b) (Sturm signs kept), computed without any rational arithmetic.
Polynomial<rational> negated_pseudo_remainder(const Polynomial<rational>& a, const Polynomial<rational>& b) {
  std::vector<integer> r, B;
  for (const auto& c : a.coeffs()) r.push_back(num(c));
  for (const auto& c : b.coeffs()) B.push_back(num(c));
  const integer absL = abs(B.back());
  const bool neg = B.back() < 0;
  while (!r.empty() && r.size() >= B.size()) {
    const integer c = neg ? integer(-r.back()) : r.back();
    const size_t k = r.size() - B.size();
    for (auto& x : r) x *= absL;
    for (size_t i = 0; i + 1 < B.size(); ++i) r[k + i] -= c * B[i];
    r.pop_back();  // |L| r_top - sgn(L) r_top L = 0
    while (!r.empty() && r.back() == 0) r.pop_back();
  }
  std::vector<rational> out;
  for (auto& x : r) out.emplace_back(-x);
  return positive_normalise(Polynomial<rational>(std::move(out)));
}
}  // namespace

std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& p) {
  require_nonzero(p, "sturm_sequence");
  std::vector<Polynomial<rational>> s;
  s.push_back(positive_normalise(square_free_part(p)));
  if (s[0].degree() <= 0) return s;
  s.push_back(positive_normalise(s[0].derivative()));
  for (;;) {
    Polynomial<rational> r = negated_pseudo_remainder(s[s.size() - 2], s.back());
    if (r.is_zero()) break;
    s.push_back(std::move(r));
  }
  return s;
}

int sign_variations(const std::vector<Polynomial<rational>>& seq, const rational& x) {
  int v = 0, last = 0;
  for (const auto& p : seq) {
    int s = sign_at(p, x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

int count_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  require_nonzero(p, "count_real_roots");
  if (a >= b) return 0;
  auto s = sturm_sequence(p);
  return sign_variations(s, a) - sign_variations(s, b);
}

namespace {

// ---- Descartes' rule of signs with bisection (Vincent-Collins-Akritas) ----------------------
// A node is a polynomial P(y) whose roots in (0, 1) are those of q in one sub-interval, y = 0 at
// its left end and y = 1 at its right end. var(node) = sign variations of the coefficients of
// (1 + y)^n P(1 / (1 + y)) bounds the number of roots in (0, 1) and is exact when 0 or 1; the
// halves are 2^n P(y/2) and 2^n P((y+1)/2). Integer additions and shifts only: the coefficients
// stay near the size of q's, where a Sturm sequence of degree n grows to ~n times that size.
using Z = std::vector<integer>;

void taylor_shift_1(Z& c) {  // c(y) -> c(y + 1), in place (O(n^2) additions)
  const size_t n = c.size();
  for (size_t i = 0; i + 1 < n; ++i)
    for (size_t j = n - 1; j-- > i;) c[j] += c[j + 1];
}

int descartes_var(const Z& c) {  // variations of (1 + y)^n c(1 / (1 + y)); stops at 2
  Z r(c.rbegin(), c.rend());
  taylor_shift_1(r);
  int v = 0, last = 0;
  for (const auto& x : r) {
    const int s = x > 0 ? 1 : (x < 0 ? -1 : 0);
    if (s == 0) continue;
    if (last != 0 && s != last && ++v >= 2) return v;
    last = s;
  }
  return v;
}

// q(lo + (hi - lo) y) with integer coefficients (a positive multiple)
Z to_unit_interval(const Polynomial<rational>& q, const rational& lo, const rational& hi) {
  std::vector<rational> c = q.coeffs();
  const size_t n = c.size();
  for (size_t i = 0; i + 1 < n; ++i)  // Taylor shift by lo
    for (size_t j = n - 1; j-- > i;) c[j] += lo * c[j + 1];
  rational w = 1;
  for (size_t k = 1; k < n; ++k) c[k] *= (w *= hi - lo);
  const Polynomial<rational> moved = positive_normalise(Polynomial<rational>(std::move(c)));
  Z out;  // same degree: the leading coefficient is multiplied by (hi - lo)^n != 0
  for (const auto& x : moved.coeffs()) out.push_back(num(x));
  return out;
}

struct Descartes {
  rational lo, width;
  std::vector<RootInterval>* out;
  rational at(const integer& k, unsigned depth) const { return lo + width * rational(k, integer(1) << depth); }
  // roots of c in (0, 1), i.e. in (at(k, depth), at(k + 1, depth))
  void run(Z c, const integer& k, unsigned depth) const {
    const int v = descartes_var(c);
    if (v == 0) return;
    if (v == 1) {
      out->push_back({at(k, depth), at(k + 1, depth)});
      return;
    }
    const size_t n = c.size() - 1;
    for (size_t i = 0; i <= n; ++i) c[i] <<= static_cast<unsigned>(n - i);  // 2^n c(y/2)
    Z right = c;
    taylor_shift_1(right);  // 2^n c((y + 1)/2)
    const bool mid_root = right[0] == 0;
    run(std::move(c), 2 * k, depth + 1);
    if (mid_root) {
      out->push_back({at(2 * k + 1, depth + 1), at(2 * k + 1, depth + 1)});
      right.erase(right.begin());  // divide by y: the midpoint root is reported
    }
    run(std::move(right), 2 * k + 1, depth + 1);
  }
};

}  // namespace

std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p) {
  require_nonzero(p, "isolate_real_roots");
  if (p.degree() <= 0) return {};
  const rational B = cauchy_bound(p);  // no root on +-B
  return isolate_real_roots(p, -B, B);
}

std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  require_nonzero(p, "isolate_real_roots");
  if (a > b) throw InputError("isolate_real_roots: empty interval [" + a.str() + ", " + b.str() + "]");
  std::vector<RootInterval> out;
  const Polynomial<rational> q = positive_normalise(square_free_part(p));
  if (q.degree() <= 0) return out;
  const bool root_a = sign_at(q, a) == 0, root_b = sign_at(q, b) == 0;
  if (a == b) {
    if (root_a) out.push_back({a, a});
    return out;
  }
  if (root_a) out.push_back({a, a});
  Descartes{a, b - a, &out}.run(to_unit_interval(q, a, b), integer(0), 0);
  if (root_b) out.push_back({b, b});
  // an interval may end on a rational root (a, b, or a bisection midpoint reported exactly):
  // shrink it away until the step holds no root (Descartes count 0 is exact) and ends on a non-root
  for (auto& r : out) {
    if (r.is_exact()) continue;
    if (sign_at(q, r.lo) == 0)
      for (rational d = (r.hi - r.lo) / 2;; d /= 2)
        if (sign_at(q, r.lo + d) != 0 && descartes_var(to_unit_interval(q, r.lo, r.lo + d)) == 0) {
          r.lo += d;
          break;
        }
    if (sign_at(q, r.hi) == 0)
      for (rational d = (r.hi - r.lo) / 2;; d /= 2)
        if (sign_at(q, r.hi - d) != 0 && descartes_var(to_unit_interval(q, r.hi - d, r.hi)) == 0) {
          r.hi -= d;
          break;
        }
  }
  return out;
}

RootInterval refine_root(const Polynomial<rational>& p, RootInterval r, const rational& width) {
  require_nonzero(p, "refine_root");
  if (!(width > 0)) throw InputError("refine_root: width must be positive, got " + width.str());
  if (r.lo > r.hi) throw InputError("refine_root: lo > hi");
  const Polynomial<rational> q = positive_normalise(square_free_part(p));
  if (r.is_exact()) {
    if (q(r.lo) != 0) throw InputError("refine_root: " + r.lo.str() + " is not a root");
    return r;
  }
  int slo = sign_at(q, r.lo), shi = sign_at(q, r.hi);
  if (slo == 0) return {r.lo, r.lo};
  if (shi == 0) return {r.hi, r.hi};
  if (slo == shi)
    throw InputError("refine_root: [" + r.lo.str() + ", " + r.hi.str() + "] does not bracket a root");
  // Quadratic interval refinement (Abbott): try a secant point rounded to a grid of N cells;
  // if the root is in the grid cell around it, the width shrinks by N and N is squared;
  // otherwise bisect and fall back to N = 4.
  integer N = 4;
  bool first = true;
  while (r.hi - r.lo > width) {
    const rational w = r.hi - r.lo;
    bool done = false;
    const rational flo = q(r.lo), fhi = q(r.hi);
    {
      rational xs = r.lo - flo * w / (fhi - flo);  // in (lo, hi) since signs differ
      if (first && q(xs) == 0) return {xs, xs};     // catches rational roots of linear factors
      first = false;
      rational cells = (xs - r.lo) / w * rational(N);
      integer k = num(cells) / den(cells);  // floor (cells >= 0)
      const rational a = r.lo + w * rational(k) / rational(N), b = r.lo + w * rational(k + 1) / rational(N);
      const int sa = (k == 0) ? slo : sign_at(q, a);
      const int sb = (k + 1 == N) ? shi : sign_at(q, b);
      if (sa == 0) return {a, a};
      if (sb == 0) return {b, b};
      if (sa != sb) {
        r = {a, b};
        slo = sa;
        shi = sb;
        N = N * N;
        done = true;
      } else {
        N = (N > 16) ? integer(bmp::sqrt(N)) : integer(4);
      }
    }
    if (!done) {
      const rational m = (r.lo + r.hi) / 2;
      const int sm = sign_at(q, m);
      if (sm == 0) return {m, m};
      if (sm == slo) r.lo = m;
      else r.hi = m;
    }
  }
  return r;
}

}  // namespace hapstab
