#include "hapstab/poly/sturm.hpp"

#include <algorithm>

namespace hapstab {

namespace {

int sgn(const rational& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

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

// 1 + max |a_i / a_n|: every root x has |x| < bound (Cauchy).
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

struct Isolator {
  std::vector<Polynomial<rational>> seq;
  const Polynomial<rational>& q() const { return seq.front(); }
  int V(const rational& x) const { return sign_variations(seq, x); }
  // roots in the open interval (a, b), a < b, given V(a), V(b) and q(b)
  void run(const rational& lo, const rational& hi, int vlo, int vhi, std::vector<RootInterval>& out) const {
    // invariant: q(lo) != 0, q(hi) != 0, so roots in (lo, hi) = vlo - vhi
    const int n = vlo - vhi;
    if (n <= 0) return;
    if (n == 1) {
      out.push_back({lo, hi});
      return;
    }
    const rational mid = (lo + hi) / 2;
    if (sign_at(q(), mid) == 0) {
      // exact rational root: separate it by a small non-root neighbourhood, then recurse.
      rational d = (hi - lo) / 4;
      for (;;) {
        rational a = mid - d, b = mid + d;
        if (sign_at(q(), a) != 0 && sign_at(q(), b) != 0 && V(a) - V(b) == 1) {
          run(lo, a, vlo, V(a), out);
          out.push_back({mid, mid});
          run(b, hi, V(b), vhi, out);
          return;
        }
        d /= 2;
      }
    }
    const int vm = V(mid);
    run(lo, mid, vlo, vm, out);
    run(mid, hi, vm, vhi, out);
  }
};

}  // namespace

Polynomial<rational> square_free_part(const Polynomial<rational>& p) {
  require_nonzero(p, "square_free_part");
  if (p.degree() <= 0) return p.monic();
  Polynomial<rational> g = gcd(p, p.derivative());
  return divmod(p, g).first.monic();
}

std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& p) {
  require_nonzero(p, "sturm_sequence");
  std::vector<Polynomial<rational>> s;
  s.push_back(positive_normalise(square_free_part(p)));
  if (s[0].degree() <= 0) return s;
  s.push_back(positive_normalise(s[0].derivative()));
  for (;;) {
    Polynomial<rational> r = divmod(s[s.size() - 2], s.back()).second;
    if (r.is_zero()) break;
    s.push_back(positive_normalise(-r));
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

std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p) {
  require_nonzero(p, "isolate_real_roots");
  std::vector<RootInterval> out;
  if (p.degree() <= 0) return out;
  Isolator iso{sturm_sequence(p)};
  const rational B = cauchy_bound(iso.q());
  iso.run(-B, B, iso.V(-B), iso.V(B), out);
  return out;
}

std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  require_nonzero(p, "isolate_real_roots");
  if (a > b) throw InputError("isolate_real_roots: empty interval [" + a.str() + ", " + b.str() + "]");
  std::vector<RootInterval> out;
  const Polynomial<rational> q = positive_normalise(square_free_part(p));
  for (const auto& r : isolate_real_roots(p)) {
    if (r.hi < a || r.lo > b) continue;
    if (r.is_exact()) {
      out.push_back(r);
      continue;
    }
    rational lo = std::max(r.lo, a), hi = std::min(r.hi, b);
    const int sl = sign_at(q, lo), sh = sign_at(q, hi);
    if (sl == 0) out.push_back({lo, lo});
    else if (sh == 0) out.push_back({hi, hi});
    else if (sl != sh) out.push_back({lo, hi});
    // else: the root of [r.lo, r.hi] lies outside [a, b]
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
