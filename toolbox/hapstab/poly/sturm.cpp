// Sturm sequences and Descartes isolation on FLINT's fmpz_poly: the polynomial of interest is
// made a primitive integer polynomial once (square-free part, denominators cleared, content
// divided out, sign kept), and every inner loop -- pseudo-remainders, Taylor shifts, halvings,
// sign variations, sign evaluations -- runs on integers. Each result is the same as the
// previous rational/Boost implementation's (bench/exact_core_before.hpp keeps it as the
// reference): the polynomials differ from it at most by a positive constant, which changes no
// sign and no variation count.
#include "hapstab/poly/sturm.hpp"

#include <algorithm>

#include "hapstab/poly/flint_poly.hpp"

namespace hapstab {

using flint::Fmpz;
using flint::FmpzPoly;

namespace {

void require_nonzero(const Polynomial<rational>& p, const char* who) {
  if (p.is_zero())
    throw InputError(std::string(who) + ": the zero polynomial vanishes everywhere (infinitely many roots)");
}

// p divided by its (non-negative) content: primitive, same signs everywhere.
void make_primitive(FmpzPoly& p) {
  Fmpz c;
  fmpz_poly_content(c.get(), p.get());
  if (!fmpz_is_zero(c.get()) && !fmpz_is_one(c.get())) fmpz_poly_scalar_divexact_fmpz(p.get(), p.get(), c.get());
}

// The primitive integer polynomial that is a positive multiple of p.
FmpzPoly primitive_integer(const Polynomial<rational>& p) {
  flint::FmpqPoly q;
  flint::to_flint(p, q);
  FmpzPoly z;
  fmpq_poly_get_numerator(z.get(), q.get());  // times the positive common denominator
  make_primitive(z);
  return z;
}

Polynomial<rational> to_polynomial(const FmpzPoly& p) {
  std::vector<rational> c;
  for (long i = 0; i < p.length(); ++i) c.emplace_back(flint::to_integer(p.coeff(i)));
  return Polynomial<rational>(std::move(c));
}

// sign of p(a/b), b > 0: the sign of the homogeneous sum c_i a^i b^(n-i), in integers.
int sign_at(const FmpzPoly& p, const rational& x) {
  const long len = p.length();
  if (len == 0) return 0;
  Fmpz a, b, h, bp;
  flint::set(a.get(), num(x));
  flint::set(b.get(), den(x));
  fmpz_set(h.get(), p.coeff(len - 1));
  fmpz_one(bp.get());
  for (long i = len - 2; i >= 0; --i) {
    fmpz_mul(bp.get(), bp.get(), b.get());
    fmpz_mul(h.get(), h.get(), a.get());
    fmpz_addmul(h.get(), p.coeff(i), bp.get());
  }
  return fmpz_sgn(h.get());
}

// the primitive integer square-free part of p (a positive multiple of square_free_part(p))
FmpzPoly square_free_integer(const Polynomial<rational>& p) { return primitive_integer(square_free_part(p)); }

// -prem(a, b) made primitive: lc(b)^d a = Q b + R, so R is a positive multiple of rem(a, b)
// unless lc(b) < 0 and d is odd; the result is the primitive POSITIVE multiple of -rem(a, b)
// (Sturm signs kept).
FmpzPoly negated_pseudo_remainder(const FmpzPoly& a, const FmpzPoly& b) {
  FmpzPoly r;
  ulong d = 0;
  fmpz_poly_pseudo_rem(r.get(), &d, a.get(), b.get());
  const bool lc_negative = fmpz_sgn(b.coeff(b.length() - 1)) < 0;
  if (!(lc_negative && (d % 2 == 1))) fmpz_poly_neg(r.get(), r.get());
  make_primitive(r);
  return r;
}

std::vector<FmpzPoly> integer_sturm_sequence(const Polynomial<rational>& p) {
  std::vector<FmpzPoly> s;
  s.push_back(square_free_integer(p));
  if (s[0].length() <= 1) return s;
  FmpzPoly d;
  fmpz_poly_derivative(d.get(), s[0].get());
  make_primitive(d);
  s.push_back(std::move(d));
  for (;;) {
    FmpzPoly r = negated_pseudo_remainder(s[s.size() - 2], s.back());
    if (r.length() == 0) break;
    s.push_back(std::move(r));
  }
  return s;
}

int variations_at(const std::vector<FmpzPoly>& seq, const rational& x) {
  int v = 0, last = 0;
  for (const auto& p : seq) {
    const int s = sign_at(p, x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
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
  flint::FmpqPoly f, d, g, q;
  flint::to_flint(p, f);
  fmpq_poly_derivative(d.get(), f.get());
  fmpq_poly_gcd(g.get(), f.get(), d.get());
  fmpq_poly_div(q.get(), f.get(), g.get());
  fmpq_poly_make_monic(q.get(), q.get());
  return flint::from_flint(q);
}

std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& p) {
  require_nonzero(p, "sturm_sequence");
  std::vector<Polynomial<rational>> out;
  for (const auto& s : integer_sturm_sequence(p)) out.push_back(to_polynomial(s));
  return out;
}

int sign_variations(const std::vector<Polynomial<rational>>& seq, const rational& x) {
  std::vector<FmpzPoly> z;
  for (const auto& p : seq) z.push_back(primitive_integer(p));  // positive multiples: same signs
  return variations_at(z, x);
}

int count_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  require_nonzero(p, "count_real_roots");
  if (a >= b) return 0;
  const auto s = integer_sturm_sequence(p);
  return variations_at(s, a) - variations_at(s, b);
}

namespace {

// ---- Descartes' rule of signs with bisection (Vincent-Collins-Akritas) ----------------------
// A node is a polynomial P(y) whose roots in (0, 1) are those of q in one sub-interval, y = 0 at
// its left end and y = 1 at its right end. var(node) = sign variations of the coefficients of
// (1 + y)^n P(1 / (1 + y)) bounds the number of roots in (0, 1) and is exact when 0 or 1; the
// halves are 2^n P(y/2) and 2^n P((y+1)/2). Integer shifts and Taylor shifts only (FLINT's
// fmpz_poly_taylor_shift): the coefficients stay near the size of q's, where a Sturm sequence of
// degree n grows to ~n times that size.

void taylor_shift_1(FmpzPoly& c) {  // c(y) -> c(y + 1), in place
  Fmpz one;
  fmpz_one(one.get());
  fmpz_poly_taylor_shift(c.get(), c.get(), one.get());
}

int descartes_var(const FmpzPoly& c) {  // variations of (1 + y)^n c(1 / (1 + y)); stops at 2
  const long len = c.length();
  FmpzPoly r;
  fmpz_poly_reverse(r.get(), c.get(), len);
  taylor_shift_1(r);
  int v = 0, last = 0;
  for (long i = 0; i < r.length(); ++i) {
    const int s = fmpz_sgn(r.coeff(i));
    if (s == 0) continue;
    if (last != 0 && s != last && ++v >= 2) return v;
    last = s;
  }
  return v;
}

// a positive multiple of q(lo + (hi - lo) y), primitive, q integer of degree n:
// with lo = a/b and hi - lo = c/d, b^n d^n q(a/b + (c/d) y) = sum_i [q~(x + a)]_i (b c)^i d^(n-i),
// q~(x) = b^n q(x/b) = sum_i q_i b^(n-i) x^i.
FmpzPoly to_unit_interval(const FmpzPoly& q, const rational& lo, const rational& hi) {
  const long len = q.length(), n = len - 1;
  const rational w = hi - lo;
  Fmpz a, b, bc, d, pw;
  flint::set(a.get(), num(lo));
  flint::set(b.get(), den(lo));
  flint::set(d.get(), den(w));
  flint::set(bc.get(), num(w));
  fmpz_mul(bc.get(), bc.get(), b.get());
  FmpzPoly t(q);
  fmpz_one(pw.get());
  for (long i = n - 1; i >= 0; --i) {  // q~: coefficient i times b^(n-i)
    fmpz_mul(pw.get(), pw.get(), b.get());
    fmpz_mul(t.get()->coeffs + i, t.get()->coeffs + i, pw.get());
  }
  fmpz_poly_taylor_shift(t.get(), t.get(), a.get());
  fmpz_one(pw.get());
  for (long i = n; i >= 0; --i) {  // times d^(n-i)
    fmpz_mul(t.get()->coeffs + i, t.get()->coeffs + i, pw.get());
    fmpz_mul(pw.get(), pw.get(), d.get());
  }
  fmpz_one(pw.get());
  for (long i = 1; i <= n; ++i) {  // times (b c)^i
    fmpz_mul(pw.get(), pw.get(), bc.get());
    fmpz_mul(t.get()->coeffs + i, t.get()->coeffs + i, pw.get());
  }
  make_primitive(t);  // same degree: the leading coefficient gets the factor (bc)^n != 0
  return t;
}

struct Descartes {
  rational lo, width;
  std::vector<RootInterval>* out;
  rational at(const integer& k, unsigned depth) const { return lo + width * rational(k, integer(1) << depth); }
  // roots of c in (0, 1), i.e. in (at(k, depth), at(k + 1, depth))
  void run(FmpzPoly c, const integer& k, unsigned depth) const {
    const int v = descartes_var(c);
    if (v == 0) return;
    if (v == 1) {
      out->push_back({at(k, depth), at(k + 1, depth)});
      return;
    }
    const long n = c.length() - 1;
    for (long i = 0; i < n; ++i)  // 2^n c(y/2)
      fmpz_mul_2exp(c.get()->coeffs + i, c.get()->coeffs + i, static_cast<ulong>(n - i));
    FmpzPoly right(c);
    taylor_shift_1(right);  // 2^n c((y + 1)/2)
    const bool mid_root = fmpz_is_zero(right.coeff(0));
    run(std::move(c), 2 * k, depth + 1);
    if (mid_root) {
      out->push_back({at(2 * k + 1, depth + 1), at(2 * k + 1, depth + 1)});
      fmpz_poly_shift_right(right.get(), right.get(), 1);  // divide by y: the midpoint root is reported
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

namespace {

// isolate_real_roots on [a, b] for q, the primitive square-free integer part of p
std::vector<RootInterval> isolate_integer(const FmpzPoly& q, const rational& a, const rational& b) {
  if (a > b) throw InputError("isolate_real_roots: empty interval [" + a.str() + ", " + b.str() + "]");
  std::vector<RootInterval> out;
  if (q.length() <= 1) return out;
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

}  // namespace

std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b) {
  require_nonzero(p, "isolate_real_roots");
  return isolate_integer(square_free_integer(p), a, b);
}

namespace {

// 2^(E n) q(X / 2^E), n = deg q: the value of q at the dyadic X / 2^E times a positive power of
// two (same sign), by Horner in integers: h <- h X + q_i 2^(E (n - i)).
void value_at_dyadic(Fmpz& h, const FmpzPoly& q, const Fmpz& X, ulong E) {
  const long n = q.length() - 1;
  Fmpz t;
  fmpz_set(h.get(), q.coeff(n));
  for (long i = n - 1; i >= 0; --i) {
    fmpz_mul(h.get(), h.get(), X.get());
    fmpz_mul_2exp(t.get(), q.coeff(i), E * static_cast<ulong>(n - i));
    fmpz_add(h.get(), h.get(), t.get());
  }
}

rational dyadic(const Fmpz& X, ulong E) { return rational(flint::to_integer(X.get()), integer(1) << E); }

// x * 2^E rounded up (ceil) or down, x rational
void scaled_round(Fmpz& out, const rational& x, ulong E, bool up) {
  Fmpz a, b;
  flint::set(a.get(), num(x));
  flint::set(b.get(), den(x));
  fmpz_mul_2exp(a.get(), a.get(), E);
  if (up) fmpz_cdiv_q(out.get(), a.get(), b.get());
  else fmpz_fdiv_q(out.get(), a.get(), b.get());
}

// (R - L) / 2^E <= width = a/b  <=>  (R - L) b <= a 2^E
bool narrow_enough(const Fmpz& L, const Fmpz& R, ulong E, const Fmpz& wa, const Fmpz& wb) {
  Fmpz l, r;
  fmpz_sub(l.get(), R.get(), L.get());
  fmpz_mul(l.get(), l.get(), wb.get());
  fmpz_mul_2exp(r.get(), wa.get(), E);
  return fmpz_cmp(l.get(), r.get()) <= 0;
}

RootInterval refine_integer(const FmpzPoly& q, RootInterval r, const rational& width) {
  if (!(width > 0)) throw InputError("refine_root: width must be positive, got " + width.str());
  if (r.lo > r.hi) throw InputError("refine_root: lo > hi");
  if (r.is_exact()) {
    if (sign_at(q, r.lo) != 0) throw InputError("refine_root: " + r.lo.str() + " is not a root");
    return r;
  }
  int slo = sign_at(q, r.lo), shi = sign_at(q, r.hi);
  if (slo == 0) return {r.lo, r.lo};
  if (shi == 0) return {r.hi, r.hi};
  if (slo == shi)
    throw InputError("refine_root: [" + r.lo.str() + ", " + r.hi.str() + "] does not bracket a root");
  const long n = q.length() - 1;
  if (n == 1) {  // the root -q0/q1, exactly
    const rational x = -rational(flint::to_integer(q.coeff(0)), flint::to_integer(q.coeff(1)));
    return {x, x};
  }
  // 1. onto dyadic end points: with 2^-E <= (hi - lo)/8, L = ceil(lo 2^E) and R = floor(hi 2^E)
  //    lie inside and R - L >= 6; where a sign test shows the root outside [L, R], the bracket
  //    is the short piece [lo, L] or [R, hi] (<= 1/8 of the width) and the step repeats.
  Fmpz L, R, HL, HR;
  ulong E = 0;
  for (;;) {
    const rational w = r.hi - r.lo;
    if (w <= width) return r;
    // w = a/b > 2^(bits a - 1 - bits b), so 2^E w >= 8 for E = bits b - bits a + 4
    const long e = static_cast<long>(bmp::msb(den(w))) - static_cast<long>(bmp::msb(num(w))) + 4;
    E = static_cast<ulong>(std::max(0L, e));
    scaled_round(L, r.lo, E, true);
    scaled_round(R, r.hi, E, false);
    value_at_dyadic(HL, q, L, E);
    const int sl = fmpz_sgn(HL.get());
    if (sl == 0) return {dyadic(L, E), dyadic(L, E)};
    if (sl != slo) {
      r.hi = dyadic(L, E);
      shi = sl;
      continue;
    }
    value_at_dyadic(HR, q, R, E);
    const int sr = fmpz_sgn(HR.get());
    if (sr == 0) return {dyadic(R, E), dyadic(R, E)};
    if (sr != shi) {
      r.lo = dyadic(R, E);
      slo = sr;
      continue;
    }
    break;
  }
  // 2. quadratic interval refinement on [L, R] / 2^E: the secant guess k = floor(N HL/(HL - HR))
  //    picks one of N = 2^j cells; if q changes sign across it, it is the new bracket and j
  //    doubles, else j halves (at least 2) and the bracket is bisected. Every test is exact.
  Fmpz wa, wb, W, k, t, a, b, Ha, Hb;
  flint::set(wa.get(), num(width));
  flint::set(wb.get(), den(width));
  ulong j = 2;
  auto rescale = [&](ulong s) {  // X / 2^E -> (X 2^s) / 2^(E + s); values times 2^(s n)
    fmpz_mul_2exp(L.get(), L.get(), s);
    fmpz_mul_2exp(R.get(), R.get(), s);
    fmpz_mul_2exp(HL.get(), HL.get(), s * static_cast<ulong>(n));
    fmpz_mul_2exp(HR.get(), HR.get(), s * static_cast<ulong>(n));
    E += s;
  };
  while (!narrow_enough(L, R, E, wa, wb)) {
    fmpz_sub(W.get(), R.get(), L.get());
    {  // no cells finer than the target needs: (R - L) / 2^E / width < 2^need
      const long need = static_cast<long>(fmpz_bits(W.get()) + fmpz_bits(wb.get())) -
                        static_cast<long>(fmpz_bits(wa.get())) - static_cast<long>(E) + 2;
      j = std::min<ulong>(j, static_cast<ulong>(std::max(2L, need)));
    }
    const ulong v = fmpz_val2(W.get());
    if (v < j) {
      rescale(j - v);
      fmpz_sub(W.get(), R.get(), L.get());
    }
    fmpz_mul_2exp(t.get(), HL.get(), j);
    fmpz_sub(a.get(), HL.get(), HR.get());
    fmpz_fdiv_q(k.get(), t.get(), a.get());  // in [0, N - 1]: HL, HR have opposite signs
    fmpz_fdiv_q_2exp(W.get(), W.get(), j);   // the cell width
    fmpz_set(a.get(), L.get());
    fmpz_addmul(a.get(), k.get(), W.get());
    fmpz_add(b.get(), a.get(), W.get());
    if (fmpz_is_zero(k.get())) fmpz_set(Ha.get(), HL.get());
    else value_at_dyadic(Ha, q, a, E);
    if (fmpz_equal(b.get(), R.get())) fmpz_set(Hb.get(), HR.get());
    else value_at_dyadic(Hb, q, b, E);
    const int sa = fmpz_sgn(Ha.get()), sb = fmpz_sgn(Hb.get());
    if (sa == 0) return {dyadic(a, E), dyadic(a, E)};
    if (sb == 0) return {dyadic(b, E), dyadic(b, E)};
    if (sa != sb) {
      fmpz_swap(L.get(), a.get());
      fmpz_swap(R.get(), b.get());
      fmpz_swap(HL.get(), Ha.get());
      fmpz_swap(HR.get(), Hb.get());
      j *= 2;
      continue;
    }
    j = std::max<ulong>(2, j / 2);
    fmpz_add(t.get(), L.get(), R.get());
    if (fmpz_is_odd(t.get())) {
      rescale(1);
      fmpz_add(t.get(), L.get(), R.get());
    }
    fmpz_fdiv_q_2exp(t.get(), t.get(), 1);  // the midpoint
    value_at_dyadic(Ha, q, t, E);
    const int sm = fmpz_sgn(Ha.get());
    if (sm == 0) return {dyadic(t, E), dyadic(t, E)};
    if (sm == fmpz_sgn(HL.get())) {
      fmpz_swap(L.get(), t.get());
      fmpz_swap(HL.get(), Ha.get());
    } else {
      fmpz_swap(R.get(), t.get());
      fmpz_swap(HR.get(), Ha.get());
    }
  }
  return {dyadic(L, E), dyadic(R, E)};
}

}  // namespace

RootRefiner::RootRefiner(const Polynomial<rational>& p) {
  require_nonzero(p, "refine_root");
  q_ = std::make_shared<const FmpzPoly>(square_free_integer(p));
}

std::vector<RootInterval> RootRefiner::isolate(const rational& a, const rational& b) const {
  return isolate_integer(*q_, a, b);
}

RootInterval RootRefiner::refine(RootInterval r, const rational& width) const { return refine_integer(*q_, r, width); }

RootInterval refine_root(const Polynomial<rational>& p, RootInterval r, const rational& width) {
  return RootRefiner(p).refine(r, width);
}

}  // namespace hapstab
