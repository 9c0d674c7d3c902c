// Certified maximisation of the exact objective f(c) of (45) on c in [-1, 1] (bound.hpp):
// Descartes root isolation of the critical points, Newton polish started in double and finished
// in MPFR, MPFI mean-value enclosure; exact where the maximiser is rational.
#include <cmath>
#include <limits>
#include <optional>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::passivity {


namespace detail {

std::string enclosure_decimal(const rational& lo, const rational& hi, int digits) {
  const SharedDecimal s = shared_decimal(lo, hi, digits);
  return s.digits >= 2 || lo == hi ? s.text : to_decimal((lo + hi) / 2, 3);
}

namespace {

/// p scaled to integer coefficients with content 1 (same roots): its exact sign evaluations and
/// its double image (the Newton start) work on small integers instead of rationals.
QPoly primitive(const QPoly& p) {
  integer L = 1, G = 0;
  for (const auto& c : p.coeffs()) L = lcm(L, den(c));
  std::vector<rational> v;
  for (const auto& c : p.coeffs()) v.push_back(c * rational(L));
  for (const auto& c : v) G = gcd(G, num(c));
  if (G > 1)
    for (auto& c : v) c /= rational(G);
  return QPoly(std::move(v));
}

struct Candidate {
  rational vlo, vhi;  // value enclosure
  rational clo, chi;  // location enclosure in c
  bool exact = false;
  bool endpoint_zero = false, endpoint_pi = false;
};

/// Sign of f just inside [-1,1] on each side of the root of B isolated by r (+1 means f -> +inf).
/// Returns true if f -> +inf from some side inside [-1, 1].
bool pole_goes_to_plus_inf(const QPoly& A, const QPoly& B, RootInterval r) {
  QPoly q = square_free_part(A * B);
  QPoly sb = square_free_part(B);
  rational lo = r.lo, hi = r.hi;
  // narrowed until A B has no other root in it and none at its ends: an end where A vanishes has no
  // sign (the interval [0, 1] of the pole sqrt(93/200) with A = -9c/800 read f(0) = 0: b* = 0 [exact]
  // for an objective unbounded above, issue 46's campaign indep_bound_inf_inside)
  for (int k = 0; k < 400 && !r.is_exact() && (count_real_roots(q, lo, hi) != 1 || q(lo) == 0 || q(hi) == 0); ++k) {
    r = refine_root(sb, r, (hi - lo) / 4);
    lo = r.lo;
    hi = r.hi;
  }
  if (r.is_exact()) {  // a rational pole: a symmetric neighbourhood free of other roots of A B
    rational dl = rational(1, 1024);
    for (int k = 0; k < 400; ++k, dl /= 2) {
      lo = r.lo - dl;
      hi = r.lo + dl;
      if (q(lo) != 0 && q(hi) != 0 && count_real_roots(q, lo, hi) == 1) break;
    }
  }
  bool plus = false;
  auto f = [&](const rational& x) { return A(x) / B(x); };
  if (lo >= -1 && lo < 1 && !(r.is_exact() && r.lo == -1)) plus = plus || f(lo) > 0;
  if (hi <= 1 && hi > -1 && !(r.is_exact() && r.lo == 1)) plus = plus || f(hi) > 0;
  // an exact root at the endpoint -1 (w = pi/T) only has the side c > -1; at 1 only c < 1
  if (r.is_exact() && r.lo == -1) plus = f(hi) > 0;
  if (r.is_exact() && r.lo == 1) plus = f(lo) > 0;
  return plus;
}

/// The critical-point polynomial q (primitive, square-free) and f = A/B with f' = Pd/B^2, each
/// converted once to the types the polish and the enclosure evaluate them in.
template <unsigned D>
struct CriticalContext {
  using R = mpfloat<D>;
  using I = interval<D>;
  const QPoly& q;
  const QPoly &A, &B, &Pd;
  Polynomial<double> q_d, dq_d;
  Polynomial<R> q_R, dq_R;
  Polynomial<I> q_I, A_I, B_I, Pd_I;
  CriticalContext(const QPoly& q_, const QPoly& A_, const QPoly& B_, const QPoly& Pd_)
      : q(q_), A(A_), B(B_), Pd(Pd_) {
    const QPoly dq = q.derivative();
    // q scaled by a power of two so that its double image neither overflows nor underflows
    long ex = 0;
    for (const auto& c : q.coeffs())
      if (c != 0) ex = std::max(ex, static_cast<long>(msb(abs(num(c)))) - static_cast<long>(msb(den(c))));
    const rational sc = ex > 900 ? rational(1, integer(1) << static_cast<unsigned>(ex - 900)) : rational(1);
    q_d = (q * sc).template cast<double>();
    dq_d = (dq * sc).template cast<double>();
    q_R = q.template cast<R>();
    dq_R = dq.template cast<R>();
    q_I = q.template cast<I>();
    A_I = A.template cast<I>();
    B_I = B.template cast<I>();
    Pd_I = Pd.template cast<I>();
  }
};

/// Safeguarded Newton (bisection when a step leaves the bracket) on the critical-point polynomial
/// q inside r: first in double to ~1e-15 for a starting point only (double signs of q may be
/// wrong near the root: the bracket is not narrowed by them), then in R, where two or three
/// quadratic steps reach the precision.
template <unsigned D>
mpfloat<D> polish_root(const CriticalContext<D>& cx, const RootInterval& r) {
  using R = mpfloat<D>;
  const int sa = sgn(cx.q(r.lo));
  R a = to_real<R>(r.lo), b = to_real<R>(r.hi);
  R x = (a + b) / 2;
  {
    double ad = static_cast<double>(a), bd = static_cast<double>(b), xd = 0.5 * (ad + bd);
    for (int it = 0; it < 200 && bd - ad > 4e-16 * std::max(1.0, std::abs(xd)); ++it) {
      const double qx = cx.q_d(xd), dx = cx.dq_d(xd);
      if (qx == 0 || !std::isfinite(qx)) break;
      if ((qx > 0 ? 1 : -1) == sa) ad = xd; else bd = xd;
      double xn = (dx != 0) ? xd - qx / dx : 0.5 * (ad + bd);
      if (!(xn > ad && xn < bd)) xn = 0.5 * (ad + bd);
      const bool done = std::abs(xn - xd) < 1e-16 * std::max(1.0, std::abs(xd));
      xd = xn;
      if (done) break;
    }
    if (R(xd) > a && R(xd) < b) x = R(xd);
  }
  const R tol = pow(R(10), -static_cast<int>(D) + 6);
  for (int it = 0; it < 400; ++it) {
    R qx = cx.q_R(x), dx = cx.dq_R(x);
    if (qx == 0) break;
    if ((qx > 0 ? 1 : -1) == sa) a = x; else b = x;
    R xn = (dx != 0) ? x - qx / dx : (a + b) / 2;
    if (!(xn > a && xn < b)) xn = (a + b) / 2;
    R step = abs(xn - x);
    x = xn;
    if (step < tol || b - a < tol) break;
  }
  return x;
}

/// A rational maximiser (e.g. cos wT = KT/(4B) for the delayed wall) is found exactly: test the
/// continued-fraction convergents of x with denominators below 10^12; the rational root of q in
/// r, or nullopt.
template <unsigned D>
std::optional<rational> rational_root_near(const CriticalContext<D>& cx, const RootInterval& r,
                                           const mpfloat<D>& x) {
  using R = mpfloat<D>;
  R y = x;
  integer h0 = 0, h1 = 1, k0 = 1, k1 = 0;
  const R close = pow(R(10), -static_cast<int>(D) + 12);
  const integer kmax(1000000000000LL);
  for (int it = 0; it < 60; ++it) {
    R fl = floor(y);
    integer ai;
    mpfr_get_z(ai.backend().data(), fl.backend().data(), MPFR_RNDD);
    integer h2 = ai * h1 + h0, k2 = ai * k1 + k0;
    if (k2 > kmax) break;
    // a rational root equals x to working precision: test exactly only such a convergent
    if (abs(x - R(h2) / R(k2)) < close * std::max(R(1), abs(x))) {
      rational cand(h2, k2);
      if (cand >= r.lo && cand <= r.hi && cx.q(cand) == 0) return cand;
      break;
    }
    h0 = h1; h1 = h2; k0 = k1; k1 = k2;
    R frac = y - fl;
    if (frac == 0) break;
    y = 1 / frac;
  }
  return std::nullopt;
}

/// Polishes and encloses one irrational critical point; returns false when precision D was not
/// enough to decide `digits` digits of the value.
template <unsigned D>
bool enclose_critical(const CriticalContext<D>& cx, RootInterval r, int digits, Candidate& out) {
  using R = mpfloat<D>;
  using I = interval<D>;
  const QPoly &q = cx.q, &A = cx.A, &B = cx.B;
  const R x = polish_root<D>(cx, r);
  if (auto cand = rational_root_near<D>(cx, r, x)) {
    rational v = A(*cand) / B(*cand);
    out = {v, v, *cand, *cand, true, false, false};
    return true;
  }
  rational xr = exact_rational(x);
  rational delta = pow10(-static_cast<int>(D) + 20);  // margin for the sign test; the mean-value form squares it
  rational lo = std::max(r.lo, xr - delta), hi = std::min(r.hi, xr + delta);
  auto sign_at = [&](const rational& t) {
    I v = cx.q_I(ival<D>(t, t));
    return lower(v) > 0 ? 1 : (upper(v) < 0 ? -1 : 0);
  };
  int sl = sign_at(lo), sh = sign_at(hi);
  if (!(sl != 0 && sh != 0 && sl != sh)) {
    RootInterval rr = refine_root(q, r, delta);  // exact fallback
    if (rr.is_exact()) {
      rational v = A(rr.lo) / B(rr.lo);
      out = {v, v, rr.lo, rr.lo, true, false, false};
      return true;
    }
    lo = rr.lo;
    hi = rr.hi;
  }
  // mean-value form: f(X) in f(m) + f'(X) (X - m), f' = Pd / B^2
  rational m = (lo + hi) / 2;
  I X = ival<D>(lo, hi), Mi = ival<D>(m, m);
  I fm = cx.A_I(Mi) / cx.B_I(Mi);
  I BX = cx.B_I(X);
  I fx = fm + (cx.Pd_I(X) / (BX * BX)) * (X - Mi);
  // cancellation in f = A/B near a cluster of poles (B ~ 1e-24 at c = -1 + 3e-12 in the
  // campaign's case) can leave an unbounded interval: not enough precision, never a value
  if (!isfinite(lower(fx)) || !isfinite(upper(fx))) return false;
  out.vlo = lower_rational(fx);
  out.vhi = upper_rational(fx);
  out.clo = lo;
  out.chi = hi;
  out.exact = false;
  if (out.vlo == out.vhi) return true;
  return common_decimal(out.vlo, out.vhi, digits).has_value() || out.vhi - out.vlo < abs(out.vlo) * pow10(-digits - 2);
}

/// The maximiser w = q acos(c)/T of candidate c (w = 0, pi/T at the ends), enclosed, into b.
template <unsigned D>
void omega_of(const Candidate& c, const rational& T, int q, int digits, Bound& b) {
  if (c.endpoint_zero) {
    b.omega = "0";
    b.omega_enclosure = Enclosure<rational>{0, 0};
    b.where = "w = 0";
    return;
  }
  interval<D> w;
  if (c.endpoint_pi) {
    w = ipi<D>() / ival<D>(T, T);
    b.where = "w = pi/T";
  } else {
    w = acos(ival<D>(c.clo, c.chi)) * interval<D>(q) / ival<D>(T, T);
    if (b.where.empty()) b.where = "interior";
  }
  b.omega_enclosure = Enclosure<rational>{lower_rational(w), upper_rational(w)};
  b.omega = enclosure_decimal(b.omega_enclosure->lo, b.omega_enclosure->hi, digits);
}

/// The objective does not depend on c (f' = 0): every w attains it, exactly.
void constant_objective(const QPoly& A, const QPoly& B, const BoundProblem& pb, int digits, Bound& out) {
  const rational one(1);
  rational v = A(one) / B(one) + pb.eta;
  out.status = Status::exact;
  out.enclose(v, v);
  out.decimal = to_decimal(v, digits);
  out.omega = "0";
  out.omega_enclosure = Enclosure<rational>{0, 0};
  out.where = "constant (every w attains it)";
}

/// The factor of B whose roots are the ends' images of z = -1 under the fractional-delay
/// substitution: w^q = -1, i.e. c = cos((2k + 1) pi/q), the roots of T_q(c) + 1 (T_q(cos x) =
/// cos(q x)). Its root cos(pi/q) is the domain's end; the others lie below it, outside.
QPoly end_pole_factor(const QPoly& B, int q) {
  const ChebyshevTables<rational> t = chebyshev_tables<rational>(q);
  std::vector<rational> c = t.T[static_cast<size_t>(q)];
  c[0] += 1;
  return gcd(B, QPoly(std::move(c)));
}

/// A pole of f = A/B at the end of the domain, w = pi/T (c = end, exactly: rational for q <= 3, the
/// root cos(pi/q) of T_q + 1 otherwise): the sign of f just INSIDE the domain (c > end) -- +1: f ->
/// +inf there, -1: f -> -inf (the end is no candidate and the maximum lies inside), 0: no pole at
/// the end. Only that side counts: the other one is outside [0, pi/T] (before, both sides of a
/// rational end were looked at, and t_d = 1.5 T gave "+inf [exact]" for b* = 7.32).
int end_pole_side(const QPoly& A, const QPoly& B, const Domain& dom) {
  if (B.degree() <= 0) return 0;
  if (dom.end_exact()) {
    if (B(dom.end_lo) != 0) return 0;
  } else {
    const QPoly g = end_pole_factor(B, dom.q);
    if (g.degree() <= 0 || count_real_roots(g, dom.end_lo, dom.end_hi) == 0) return 0;
  }
  // x > end with no root of A B in (end, x]: f has one sign there, that of f(x); for an irrational
  // end the enclosure [end_lo, end_hi] must hold no root of A B but the pole itself
  const QPoly ab = square_free_part(A * B);
  if (!dom.end_exact() && count_real_roots(ab, dom.end_lo, dom.end_hi) != 1)
    throw NumericalError("the pole of the objective at w = pi/T could not be separated from another root of its numerator");
  rational x = dom.end_hi + (1 - dom.end_hi) / 2;
  for (int k = 0; k < 4000 && count_real_roots(ab, dom.end_hi, x) != 0; ++k) x = dom.end_hi + (x - dom.end_hi) / 2;
  if (count_real_roots(ab, dom.end_hi, x) != 0)
    throw NumericalError("the side of the pole of the objective at w = pi/T could not be decided");
  return A(x) / B(x) > 0 ? 1 : -1;
}

/// B without its root at the domain's end (end_pole_side decided that one).
QPoly without_end_pole(const QPoly& B, const Domain& dom) {
  const QPoly sb = square_free_part(B);
  if (dom.end_exact()) return divmod(sb, QPoly(std::vector<rational>{-dom.end_lo, rational(1)})).first;
  return divmod(sb, end_pole_factor(sb, dom.q)).first;
}

/// b* = +inf: f -> +inf at the end w = pi/T from inside the domain.
template <unsigned D>
void infinite_at_end(const BoundProblem& pb, const Domain& dom, Bound& out) {
  out.infinite = true;
  out.status = Status::exact;
  out.decimal = "inf";
  Candidate c{0, 0, dom.end_lo, dom.end_hi, dom.end_exact(), false, true};
  out.where = "pole at z = -1 (w = pi/T): Re -> +inf";
  omega_of<D>(c, pb.T, dom.q, 17, out);
}

/// True (and `out` set to b* = +inf) when f = A/B has a pole in the domain near which f -> +inf.
/// `end_pole` is end_pole_side's answer: a pole at the end is decided there, not here.
template <unsigned D>
bool pole_to_plus_infinity(const QPoly& A, const QPoly& B, const BoundProblem& pb, int digits, const Domain& dom,
                           int end_pole, Bound& out) {
  const rational one(1), mone = dom.end_lo;
  if (end_pole > 0) {
    infinite_at_end<D>(pb, dom, out);
    return true;
  }
  // poles of f on [-1, 1]: only possible when H has a pole on the unit circle (B = |D z^n|^2 > 0
  // otherwise), i.e. when gcd(D, z^deg D D(1/z)) is non-trivial -- skips a root isolation
  const bool circle_poles = gcd(pb.H.den(), reversed(pb.H.den())).degree() > 0;
  if (!circle_poles || B.degree() <= 0) return false;
  const QPoly Bin = end_pole != 0 ? without_end_pole(B, dom) : square_free_part(B);
  if (Bin.degree() <= 0) return false;
  for (auto r : isolate_real_roots(Bin, mone, one)) {
    if (!dom.end_exact()) {  // a pole near the irrational end cos(pi/q): inside or outside?
      if (r.lo < dom.end_hi) r = refine_root(Bin, r, (dom.end_hi - dom.end_lo) / 4);
      if (r.hi <= dom.end_lo) continue;
      if (r.lo < dom.end_hi)
        throw NumericalError("a pole of the objective at w = pi/T could not be placed inside or outside [0, pi/T]");
    }
    if (pole_goes_to_plus_inf(A, B, r)) {
      out.infinite = true;
      out.status = Status::exact;
      out.decimal = "inf";
      RootInterval rr = r.is_exact() ? r : refine_root(square_free_part(B), r, pow10(-40));
      Candidate c{0, 0, rr.lo, rr.hi, rr.is_exact(), rr.is_exact() && rr.lo == 1, rr.is_exact() && rr.lo == -1};
      // (a pole at z = 1 never gets here: integrator_pole decided it)
      out.where = c.endpoint_pi ? "pole at z = -1 (w = pi/T): Re -> +inf" : "pole on the unit circle: Re -> +inf";
      omega_of<D>(c, pb.T, dom.q, std::min(digits, 17), out);
      return true;
    }
  }
  return false;
}

/// The values at the ends of the domain: w = 0 (c = 1) and w = pi/T (c = c_end).
/// (`end_pole` != 0: f has a pole at w = pi/T; it goes to -inf there, so that end is no candidate.)
template <unsigned D>
std::vector<Candidate> end_candidates(const QPoly& A, const QPoly& B, const Domain& dom, int end_pole) {
  const rational one(1), mone = dom.end_lo;
  std::vector<Candidate> cands;
  if (B(one) != 0) {
    rational v = A(one) / B(one);
    cands.push_back({v, v, one, one, true, true, false});
  }
  if (end_pole != 0) return cands;
  if (dom.end_exact() && B(mone) != 0) {
    rational v = A(mone) / B(mone);
    cands.push_back({v, v, mone, mone, true, false, true});
  } else if (!dom.end_exact()) {  // w = pi/T at the irrational c = cos(pi/q): an MPFI enclosure
    using I = interval<D>;
    I X = ival<D>(dom.end_lo, dom.end_hi);
    I Bx = B.template cast<I>()(X);
    if (!(lower(Bx) > 0 || upper(Bx) < 0))
      throw NumericalError("the objective at w = pi/T could not be enclosed (denominator interval contains 0)");
    I v = A.template cast<I>()(X) / Bx;
    cands.push_back({lower_rational(v), upper_rational(v), dom.end_lo, dom.end_hi, false, false, true});
  }
  return cands;
}

/// Appends the critical points of f (roots of Pd that are not poles) in the domain to `cands`;
/// false when precision D was not enough for one of them.
template <unsigned D>
bool add_critical_candidates(const QPoly& A, const QPoly& B, const QPoly& Pd, int digits, const Domain& dom,
                             int end_pole, std::vector<Candidate>& cands) {
  const rational one(1), mone = dom.end_lo;
  // a critical point that may lie just outside an irrational end only widens the upper end of the
  // enclosure (its value differs from the end's by ~f'' (end_hi - end_lo)^2): its lower end is the end's
  const size_t end_index = cands.empty() ? 0 : cands.size() - 1;
  // critical points: roots of Pd that are not poles
  QPoly Pc = Pd;
  for (QPoly g = gcd(Pc, B); g.degree() > 0; g = gcd(Pc, B)) Pc = divmod(Pc, g).first;
  if (Pc.degree() <= 0) return true;
  QPoly q = primitive(square_free_part(Pc));
  std::optional<CriticalContext<D>> cx;  // built at the first irrational critical point
  for (auto r : isolate_real_roots(q, mone, one)) {
    bool straddles = false;  // isolated only up to the irrational end cos(pi/q): in or out?
    if (!dom.end_exact() && r.lo < dom.end_hi) {
      r = refine_root(q, r, (dom.end_hi - dom.end_lo) / 4);
      if (r.hi <= dom.end_lo) continue;
      straddles = r.lo < dom.end_hi;
      if (straddles && (end_pole != 0 || cands.empty()))  // no end value to fall back on
        throw NumericalError("a critical point of the objective at w = pi/T could not be placed inside or outside [0, pi/T]");
    }
    if (r.is_exact()) {
      if (r.lo == 1 || r.lo == dom.end_lo) continue;  // the endpoint value is already a candidate
      rational v = A(r.lo) / B(r.lo);
      Candidate c{v, v, r.lo, r.lo, true, false, false};
      if (straddles) c.vlo = std::min(c.vlo, cands[end_index].vlo), c.exact = false;
      cands.push_back(c);
      continue;
    }
    Candidate c;
    if (!cx) cx.emplace(q, A, B, Pd);
    if (!enclose_critical<D>(*cx, r, digits, c)) return false;
    if (straddles) c.vlo = std::min(c.vlo, cands[end_index].vlo);
    cands.push_back(c);
  }
  return true;
}

/// b* from the candidates: exact when the best is exact and dominates every other upper bound,
/// else the enclosure [max lo, max hi].
template <unsigned D>
void maximum_of(const std::vector<Candidate>& cands, const BoundProblem& pb, int digits, const Domain& dom,
                Bound& out) {
  // max over candidates: b* in [max lo, max hi]
  size_t best = 0;
  for (size_t i = 1; i < cands.size(); ++i)
    if (cands[i].vhi > cands[best].vhi || (cands[i].vhi == cands[best].vhi && cands[i].exact)) best = i;
  rational mlo = cands[0].vlo;
  for (const auto& c : cands) mlo = std::max(mlo, c.vlo);
  const Candidate& cb = cands[best];
  bool dominated = true;  // is the best exact candidate >= every other upper bound?
  for (size_t i = 0; i < cands.size(); ++i)
    if (i != best && cands[i].vhi > cb.vlo) dominated = false;
  if (cb.exact && dominated) {
    out.status = Status::exact;
    out.enclose(cb.vlo + pb.eta, cb.vlo + pb.eta);
    out.decimal = to_decimal(out.value, digits);
  } else {
    out.status = Status::certified;
    out.enclose(mlo + pb.eta, cb.vhi + pb.eta);
    out.decimal = enclosure_decimal(out.enclosure->lo, out.enclosure->hi, digits);
  }
  omega_of<D>(cb, pb.T, dom.q, digits, out);
}

}  // namespace

template <unsigned D>
bool certified_rational(const QRatFun& f, const BoundProblem& pb, int digits, Bound& out, const Domain& dom) {
  const QPoly& A = f.num();
  const QPoly& B = f.den();
  out = Bound{};
  out.method = "certified: exact f(cos wT), Descartes root isolation, MPFR Newton, MPFI enclosure (" +
               std::to_string(digits) + " digits)";
  // constant objective
  QPoly Pd = A.derivative() * B - A * B.derivative();
  if (Pd.is_zero()) {
    constant_objective(A, B, pb, digits, out);
    return true;
  }
  const int end_pole = end_pole_side(A, B, dom);
  if (pole_to_plus_infinity<D>(A, B, pb, digits, dom, end_pole, out)) return true;
  std::vector<Candidate> cands = end_candidates<D>(A, B, dom, end_pole);
  if (!add_critical_candidates<D>(A, B, Pd, digits, dom, end_pole, cands)) return false;
  if (cands.empty()) throw NumericalError("no candidate for the maximum (f -> -inf everywhere?)");
  maximum_of<D>(cands, pb, digits, dom, out);
  return true;
}
template bool certified_rational<50>(const QRatFun&, const BoundProblem&, int, Bound&, const Domain&);
template bool certified_rational<100>(const QRatFun&, const BoundProblem&, int, Bound&, const Domain&);
template bool certified_rational<300>(const QRatFun&, const BoundProblem&, int, Bound&, const Domain&);

/// An uncancelled pole of H at z = 1 (an integrator, residue rho): b* = +inf whatever the sign of
/// rho. Near w = 0 the objective is ~ T rho/(wT)^2, so rho > 0 sends it to +inf; for rho < 0 it goes
/// to -inf and (45) alone would give a finite number, but (45) assumes H stable and its sufficiency
/// proof (Sec. IV) fails: with a passive spring operator Z_O = k_o/s the loop at low frequency is
/// m s^3 + b s^2 + k_o s + rho/T, whose constant term is negative, so it has a real root s > 0 for
/// every b (tests/passivity: the simulator confirms the divergence).
std::optional<Bound> integrator_pole(const BoundProblem& p) {
  if (p.H.den()(rational(1)) != 0) return std::nullopt;
  Bound out;
  out.infinite = true;
  out.status = Status::exact;
  out.decimal = "inf";
  out.omega = "0";
  out.omega_enclosure = Enclosure<rational>{0, 0};
  out.where = "pole of H at z = 1 (w = 0) not cancelled: an integrator; no finite b makes the loop passive";
  out.method = "exact: H(z) has a simple pole at z = 1 (the denominator vanishes at 1 after cancellation)";
  return out;
}

Bound certified_exact(const BoundProblem& q, int digits) {
  if (q.frac_delay) {
    Bound b;
    if (!certified_fractional_exact(q, digits, static_cast<int>(fractional_exact_limit(q)), b))
      throw NumericalError("could not decide " + std::to_string(digits) + " digits of the bound by the exact path");
    return b;
  }
  const Objective o = objective(q.H, q.T, q.delay);
  Bound b;
  if (digits <= 30 && certified_rational<50>(o.f, q, digits, b)) return b;
  if (digits <= 80 && certified_rational<100>(o.f, q, digits, b)) return b;
  if (certified_rational<300>(o.f, q, digits, b)) return b;
  throw NumericalError("could not decide " + std::to_string(digits) + " digits of the bound");
}

}  // namespace detail

}  // namespace hapstab::passivity
