// Implementation of hapstab/passivity/bound.hpp (paper 001, (45) and (54)); see the header
// for the c = cos(wT) form of the objective and why it never cancels.
#include "hapstab/passivity/bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/double_double.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"
#include "hapstab/poly/sturm.hpp"
#include "hapstab/poly/unit_circle.hpp"

namespace hapstab::passivity {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

// ---------------------------------------------------------------------------------------------
// small helpers
namespace {

// Chebyshev T_0..T_M and U_0..U_M as integer coefficient tables (ascending), by the recurrence
// X_{m+1} = 2c X_m - X_{m-1}.
using ZTable = std::vector<std::vector<integer>>;
ZTable chebyshev(int M, bool second_kind) {
  ZTable t(static_cast<size_t>(M) + 1);
  t[0] = {integer(1)};
  if (M >= 1) t[1] = second_kind ? std::vector<integer>{integer(0), integer(2)} : std::vector<integer>{integer(0), integer(1)};
  for (int m = 1; m < M; ++m) {
    auto& next = t[m + 1];
    next.assign(static_cast<size_t>(m) + 2, integer(0));
    for (size_t k = 0; k < t[m].size(); ++k) next[k + 1] += 2 * t[m][k];
    for (size_t k = 0; k < t[m - 1].size(); ++k) next[k] -= t[m - 1][k];
  }
  return t;
}

// p scaled to integer coefficients: p = ints / scale, scale > 0 the lcm of the denominators
std::vector<integer> integer_coeffs(const std::vector<rational>& p, integer& scale) {
  scale = 1;
  for (const auto& c : p) scale = bmp::lcm(scale, den(c));
  std::vector<integer> out;
  for (const auto& c : p) out.push_back(num(c) * (scale / den(c)));
  return out;
}

/// Best decimal for an enclosure: the common rounding at `digits` digits, else fewer digits.
std::string enclosure_decimal(const rational& lo, const rational& hi, int digits) {
  if (lo == hi) return to_decimal(lo, digits);
  for (int d = digits; d >= 2; --d)
    if (auto s = common_decimal(lo, hi, d)) return *s;
  return to_decimal((lo + hi) / 2, 3);
}

/// p scaled to integer coefficients with content 1 (same roots): its exact sign evaluations and
/// its double image (the Newton start) work on small integers instead of rationals.
P primitive(const P& p) {
  integer L = 1, G = 0;
  for (const auto& c : p.coeffs()) L = lcm(L, den(c));
  std::vector<rational> v;
  for (const auto& c : p.coeffs()) v.push_back(c * rational(L));
  for (const auto& c : v) G = gcd(G, num(c));
  if (G > 1)
    for (auto& c : v) c /= rational(G);
  return P(std::move(v));
}

}  // namespace

double Bound::value_double() const {
  if (infinite) return std::numeric_limits<double>::infinity();
  return to_real<double>((lo + hi) / 2);
}

// ---------------------------------------------------------------------------------------------
// assumptions: causality, stability (poly/stability.hpp: Schur-Cohn on the part off the unit
// circle, exact root isolation on it)
BoundProblem with_integer_delay(BoundProblem p) {
  if (p.frac_delay && p.T > 0 && den(*p.frac_delay / p.T) == 1) {
    p.delay += static_cast<int>(num(*p.frac_delay / p.T).convert_to<long>());
    p.frac_delay.reset();
  }
  return p;
}

void check_problem_size(const BoundProblem& p) {
  const long degree = std::max<long>(p.H.num().degree(), long(p.H.den().degree()) + p.delay);
  if (degree > limits::bound_degree)
    throw InputError("the objective of (45) has degree " + std::to_string(degree) +
                     " (max(deg N, deg D + n)), more than the limit of " + std::to_string(limits::bound_degree) +
                     " (the exact path costs about degree^4: 4 s at 160, 18 s at 200)");
}

void check_assumptions(const BoundProblem& p) {
  if (p.T <= 0) throw InputError("T must be > 0 (got " + to_decimal(p.T, 17) + ")");
  if (p.delay < 0) throw InputError("the delay n must be >= 0 (got " + std::to_string(p.delay) + ")");
  if (p.eta < 0) throw InputError("the operator shortage eta must be >= 0 (got " + to_decimal(p.eta, 17) + ")");
  if (p.frac_delay && *p.frac_delay < 0)
    throw InputError("the fractional delay t_d must be >= 0 (got " + to_decimal(*p.frac_delay, 17) + ")");
  if (p.H.den().is_zero()) throw InputError("H has a zero denominator");
  check_problem_size(p);
  if (!p.allow_noncausal && p.H.num().degree() > p.H.den().degree() + p.delay)
    throw InputError("H z^-n is not causal: numerator degree " + std::to_string(p.H.num().degree()) +
                     " > denominator degree " + std::to_string(p.H.den().degree()) + " + n = " +
                     std::to_string(p.delay) + " in z (the FIR form (47) needs --allow-noncausal or --delay >= 1)");
  std::string why;
  if (!marginally_stable(p.H.den(), &why))
    throw InputError("H is unstable (assumption of (45): H stable): " + why);
}

// ---------------------------------------------------------------------------------------------
// the exact objective in c = cos(wT)
Objective objective(const RF& H, const rational& T, int delay) {
  // in integers: N = alpha n, D = beta d (shifted by z^n), so a, cs carry alpha beta and e beta^2
  integer alpha, beta;
  const std::vector<integer> n = integer_coeffs(H.num().coeffs(), alpha);
  std::vector<integer> d = integer_coeffs(H.den().coeffs(), beta);
  d.insert(d.begin(), static_cast<size_t>(delay), integer(0));  // D' = D z^n
  const int nn = static_cast<int>(n.size()), nd = static_cast<int>(d.size());
  const int M = std::max(nn, nd);
  std::vector<integer> a(M + 1, integer(0)), cs(M + 1, integer(0)), e(M + 1, integer(0));
  for (int k = 0; k < nn; ++k)
    for (int l = 0; l < nd; ++l) {
      if (n[k] == 0 || d[l] == 0) continue;
      const integer pr = n[k] * d[l];
      const int m = k - l;
      if (m == 0) a[0] += pr;
      else if (m > 0) { a[m] += pr; cs[m] += pr; }
      else { a[-m] += pr; cs[-m] -= pr; }
    }
  for (int l = 0; l < nd; ++l)
    for (int l2 = l; l2 < nd; ++l2) {
      if (d[l] == 0 || d[l2] == 0) continue;
      if (l2 == l) e[0] += d[l] * d[l];
      else e[l2 - l] += 2 * d[l] * d[l2];
    }
  const ZTable Tm = chebyshev(M, false), Um = chebyshev(M, true);
  std::vector<integer> R(M + 1, integer(0)), Q(M + 1, integer(0)), B(M + 1, integer(0));
  for (int m = 0; m <= M; ++m)
    for (size_t k = 0; k < Tm[m].size(); ++k) {
      R[k] += a[m] * Tm[m][k];
      B[k] += e[m] * Tm[m][k];
      if (m >= 1 && k < Um[m - 1].size()) Q[k] += cs[m] * Um[m - 1][k];
    }
  auto poly = [](const std::vector<integer>& c, const rational& scale) {
    std::vector<rational> r;
    for (const auto& x : c) r.emplace_back(rational(x) * scale);
    return P(std::move(r));
  };
  const rational ab = 1 / rational(alpha * beta), bb = 1 / rational(beta * beta);
  Objective o;
  o.R = poly(R, ab);
  o.Q = poly(Q, ab);
  o.B = poly(B, bb);
  // f = (T/2)(R - (1 + c) Q) / B = (T/2)(beta/alpha)(R' - (1 + c) Q') / B' in the integer pieces
  std::vector<integer> A(R);
  for (int k = 0; k <= M; ++k) {
    A[k] -= Q[k];
    if (k + 1 <= M) A[k + 1] -= Q[k];
  }
  o.f = RF(poly(A, T / 2 * rational(beta) / rational(alpha)), poly(B, rational(1)));
  return o;
}

// ---------------------------------------------------------------------------------------------
// certified maximisation of a rational function of c on [-1, 1]
namespace {

struct Candidate {
  rational vlo, vhi;  // value enclosure
  rational clo, chi;  // location enclosure in c
  bool exact = false;
  bool endpoint_zero = false, endpoint_pi = false;
};

/// Sign of f just inside [-1,1] on each side of the root of B isolated by r (+1 means f -> +inf).
/// Returns true if f -> +inf from some side inside [-1, 1].
bool pole_goes_to_plus_inf(const P& A, const P& B, RootInterval r) {
  P q = square_free_part(A * B);
  P sb = square_free_part(B);
  rational lo = r.lo, hi = r.hi;
  for (int k = 0; k < 400 && !r.is_exact() && count_real_roots(q, lo, hi) != 1; ++k) {
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
  const P& q;
  const P &A, &B, &Pd;
  Polynomial<double> q_d, dq_d;
  Polynomial<R> q_R, dq_R;
  Polynomial<I> q_I, A_I, B_I, Pd_I;
  CriticalContext(const P& q_, const P& A_, const P& B_, const P& Pd_)
      : q(q_), A(A_), B(B_), Pd(Pd_) {
    const P dq = q.derivative();
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

/// Polishes and encloses one irrational critical point; returns false when precision D was not
/// enough to decide `digits` digits of the value.
template <unsigned D>
bool enclose_critical(const CriticalContext<D>& cx, RootInterval r, int digits, Candidate& out) {
  using R = mpfloat<D>;
  using I = interval<D>;
  const P &q = cx.q, &A = cx.A, &B = cx.B;
  const int sa = sgn(q(r.lo));
  // safeguarded Newton (bisection when a step leaves the bracket): first in double to ~1e-15 for
  // a starting point only (double signs of q may be wrong near the root: the bracket is not
  // narrowed by them), then in R, where two or three quadratic steps reach the precision
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
  // a rational maximiser (e.g. cos wT = KT/(4B) for the delayed wall) is found exactly: test the
  // continued-fraction convergents of x with denominators below 10^12
  {
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
        if (cand >= r.lo && cand <= r.hi && q(cand) == 0) {
          rational v = A(cand) / B(cand);
          out = {v, v, cand, cand, true, false, false};
          return true;
        }
        break;
      }
      h0 = h1; h1 = h2; k0 = k1; k1 = k2;
      R frac = y - fl;
      if (frac == 0) break;
      y = 1 / frac;
    }
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

/// The domain of the maximisation in certified_rational: c in [c_end, 1], where c = cos(wT/q) and
/// c_end = cos(pi/q) is the image of w = pi/T. q = 1 (c = cos wT, c_end = -1) without a fractional
/// delay; q > 1 for t_d = (p/q) T (certified_frac_exact). [end_lo, end_hi] are rational bounds of
/// c_end, equal when c_end is rational (q = 1, 2, 3).
struct Domain {
  rational end_lo = -1, end_hi = -1;
  int q = 1;
  bool end_exact() const { return end_lo == end_hi; }
};

template <unsigned D>
void omega_of(const Candidate& c, const rational& T, int q, int digits, Bound& b) {
  if (c.endpoint_zero) {
    b.omega = "0";
    b.omega_lo = b.omega_hi = 0;
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
  b.omega_lo = lower_rational(w);
  b.omega_hi = upper_rational(w);
  b.omega = enclosure_decimal(b.omega_lo, b.omega_hi, digits);
}

template <unsigned D>
bool certified_rational(const RF& f, const BoundProblem& pb, int digits, Bound& out, const Domain& dom = {}) {
  const P& A = f.num();
  const P& B = f.den();
  out = Bound{};
  out.method = "certified: exact f(cos wT), Descartes root isolation, MPFR Newton, MPFI enclosure (" +
               std::to_string(digits) + " digits)";
  const rational one(1), mone = dom.end_lo;
  // constant objective
  P Pd = A.derivative() * B - A * B.derivative();
  if (Pd.is_zero()) {
    rational v = A(one) / B(one) + pb.eta;
    out.status = Status::exact;
    out.lo = out.hi = v;
    out.value = to_decimal(v, digits);
    out.omega = "0";
    out.where = "constant (every w attains it)";
    return true;
  }
  // poles of f on [-1, 1]: only possible when H has a pole on the unit circle (B = |D z^n|^2 > 0
  // otherwise), i.e. when gcd(D, z^deg D D(1/z)) is non-trivial -- skips a root isolation
  const bool circle_poles = gcd(pb.H.den(), reversed(pb.H.den())).degree() > 0;
  if (circle_poles && B.degree() > 0) {
    for (auto r : isolate_real_roots(B, mone, one)) {
      if (!dom.end_exact()) {  // a pole near the irrational end cos(pi/q): inside or outside?
        if (r.lo < dom.end_hi) r = refine_root(square_free_part(B), r, (dom.end_hi - dom.end_lo) / 4);
        if (r.hi <= dom.end_lo) continue;
        if (r.lo < dom.end_hi)
          throw NumericalError("a pole of the objective at w = pi/T could not be placed inside or outside [0, pi/T]");
      }
      if (pole_goes_to_plus_inf(A, B, r)) {
        out.infinite = true;
        out.status = Status::exact;
        out.value = "inf";
        RootInterval rr = r.is_exact() ? r : refine_root(square_free_part(B), r, pow10(-40));
        Candidate c{0, 0, rr.lo, rr.hi, rr.is_exact(), rr.is_exact() && rr.lo == 1, rr.is_exact() && rr.lo == -1};
        // (a pole at z = 1 never gets here: integrator_pole decided it)
        out.where = c.endpoint_pi ? "pole at z = -1 (w = pi/T): Re -> +inf" : "pole on the unit circle: Re -> +inf";
        omega_of<D>(c, pb.T, dom.q, std::min(digits, 17), out);
        return true;
      }
    }
  }
  std::vector<Candidate> cands;
  if (B(one) != 0) {
    rational v = A(one) / B(one);
    cands.push_back({v, v, one, one, true, true, false});
  }
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
  // a critical point that may lie just outside an irrational end only widens the upper end of the
  // enclosure (its value differs from the end's by ~f'' (end_hi - end_lo)^2): its lower end is the end's
  const size_t end_index = cands.empty() ? 0 : cands.size() - 1;
  // critical points: roots of Pd that are not poles
  P Pc = Pd;
  for (P g = gcd(Pc, B); g.degree() > 0; g = gcd(Pc, B)) Pc = divmod(Pc, g).first;
  if (Pc.degree() > 0) {
    P q = primitive(square_free_part(Pc));
    std::optional<CriticalContext<D>> cx;  // built at the first irrational critical point
    for (auto r : isolate_real_roots(q, mone, one)) {
      bool straddles = false;  // isolated only up to the irrational end cos(pi/q): in or out?
      if (!dom.end_exact() && r.lo < dom.end_hi) {
        r = refine_root(q, r, (dom.end_hi - dom.end_lo) / 4);
        if (r.hi <= dom.end_lo) continue;
        straddles = r.lo < dom.end_hi;
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
  }
  if (cands.empty()) throw NumericalError("no candidate for the maximum (f -> -inf everywhere?)");

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
  out.lo = mlo + pb.eta;
  out.hi = cb.vhi + pb.eta;
  if (cb.exact && dominated) {
    out.status = Status::exact;
    out.lo = out.hi = cb.vlo + pb.eta;
    out.value = to_decimal(out.lo, digits);
  } else {
    out.status = Status::certified;
    out.value = enclosure_decimal(out.lo, out.hi, digits);
  }
  omega_of<D>(cb, pb.T, dom.q, digits, out);
  return true;
}

// ---- fractional delay -----------------------------------------------------------------------
// f_tau(theta) B(c) = (T/2)[ (R - (1+c)Q) cos(tau theta) + ((1-c)Q + R) sin(tau theta) cot(theta/2) ],
// tau = t_d/T, c = cos theta.

int multiplicity_at_minus_one(P p, P& rest) {
  int k = 0;
  const P lin(std::vector<rational>{rational(1), rational(1)});
  while (!p.is_zero() && p(rational(-1)) == 0) {
    p = divmod(p, lin).first;
    ++k;
  }
  rest = p;
  return k;
}

/// Sign of sin(pi tau) and cos(pi tau) for rational tau, exactly.
void trig_signs(const rational& tau, int& ssin, int& scos) {
  // reduce x = tau mod 2 into [0, 2)
  rational x;
  integer fl = num(tau / 2) / den(tau / 2);
  if (tau < 0 && fl * den(tau / 2) != num(tau / 2)) fl -= 1;
  x = tau - 2 * rational(fl);
  ssin = (x == 0 || x == 1) ? 0 : (x < 1 ? 1 : -1);
  if (x == rational(1, 2) || x == rational(3, 2)) scos = 0;
  else scos = (x < rational(1, 2) || x > rational(3, 2)) ? 1 : -1;
}

/// Exact divergence test at wT = pi for a pole of W at z = -1. Returns +1 (f -> +inf), -1
/// (f -> -inf), 0 (finite or undecided; `decided` says which).
int divergence_at_pi(const Objective& o, const rational& T, const rational& tau, bool& decided) {
  decided = true;
  P Bm, A1, E1;
  int m = multiplicity_at_minus_one(o.B, Bm);
  if (m == 0) return 0;
  const P one_plus_c(std::vector<rational>{rational(1), rational(1)});
  const P one_minus_c(std::vector<rational>{rational(1), rational(-1)});
  P Araw = o.R - one_plus_c * o.Q;
  P E = one_minus_c * o.Q + o.R;
  int a = Araw.is_zero() ? 1000 : multiplicity_at_minus_one(Araw, A1);
  int k = E.is_zero() ? 1000 : multiplicity_at_minus_one(E, E1);
  // (1 + c) = 2 sin^2(eps/2) ~ eps^2/2, eps = pi - theta
  rational alpha = a < 1000 ? A1(rational(-1)) / pow10(0) : rational(0);
  rational e = k < 1000 ? E1(rational(-1)) : rational(0);
  for (int i = 0; i < a && a < 1000; ++i) alpha /= 2;
  for (int i = 0; i < k && k < 1000; ++i) e /= 2;
  int ss, sc;
  trig_signs(tau, ss, sc);
  // leading terms (order in eps, sign): even from cos(pi tau), odd from sin(pi tau)
  struct Term { int order; int sign; };
  std::vector<Term> terms;
  if (sc != 0) {
    if (a < 1000 && k < 1000 && a == k + 1) {
      rational coef = alpha - e * tau / 2;
      if (coef == 0) { decided = false; return 0; }
      terms.push_back({2 * a, sgn(coef) * sc});
    } else {
      if (a < 1000) terms.push_back({2 * a, sgn(alpha) * sc});
      if (k < 1000) terms.push_back({2 * k + 2, -sgn(e) * sgn(tau) * sc});
    }
  }
  if (ss != 0) {
    if (a < 1000 && k < 1000 && a == k) {
      rational coef = alpha * tau + e / 2;
      if (coef == 0) { decided = false; return 0; }
      terms.push_back({2 * a + 1, sgn(coef) * ss});
    } else {
      if (a < 1000) terms.push_back({2 * a + 1, sgn(alpha) * sgn(tau) * ss});
      if (k < 1000) terms.push_back({2 * k + 1, sgn(e) * ss});
    }
  }
  if (terms.empty()) return 0;
  auto lead = *std::min_element(terms.begin(), terms.end(), [](auto& x, auto& y) { return x.order < y.order; });
  (void)T;
  if (lead.order >= 2 * m) return 0;  // finite limit
  return lead.sign;                   // B > 0 near the pole
}

template <unsigned D>
interval<D> frac_objective(const Objective& o, const rational& T, const rational& tau, const interval<D>& th) {
  using I = interval<D>;
  I c = cos(th);
  I one(1);
  I Rv = o.R(c), Qv = o.Q(c), Bv = o.B(c);
  I taui = ival<D>(tau, tau);
  I g;
  auto u = upper(th);
  if (u * mpfloat<D>(tau) <= 1.5 && u <= 1.5) {
    // g = sin(tau th) cot(th/2) = 2 tau sinc(tau th)/sinc(th/2) cos(th/2); sinc decreasing on [0, pi]
    auto sinc_range = [](const I& x) {
      auto L = mpfloat<D>(lower(x)), U = mpfloat<D>(upper(x));
      I sl = (L == 0) ? I(1) : sin(I(L)) / I(L);
      I su = (U == 0) ? I(1) : sin(I(U)) / I(U);
      return hull(sl, su);
    };
    g = I(2) * taui * sinc_range(taui * th) / sinc_range(th / I(2)) * cos(th / I(2));
  } else {
    g = sin(taui * th) * cos(th / I(2)) / sin(th / I(2));
  }
  I num = (Rv - (one + c) * Qv) * cos(taui * th) + ((one - c) * Qv + Rv) * g;
  return ival<D>(T / 2, T / 2) * num / Bv;
}

/// Value and derivative (forward mode) over intervals: the mean-value form F(m) + F'(X)(X - m)
/// removes the cluster effect of branch-and-bound near an interior maximum.
template <unsigned D>
struct DI {
  interval<D> v, d;
};
template <unsigned D> DI<D> operator+(const DI<D>& a, const DI<D>& b) { return {a.v + b.v, a.d + b.d}; }
template <unsigned D> DI<D> operator-(const DI<D>& a, const DI<D>& b) { return {a.v - b.v, a.d - b.d}; }
template <unsigned D> DI<D> operator*(const DI<D>& a, const DI<D>& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
template <unsigned D> DI<D> operator/(const DI<D>& a, const DI<D>& b) {
  return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
}
template <unsigned D> DI<D> dcos(const DI<D>& a) { return {cos(a.v), -sin(a.v) * a.d}; }
template <unsigned D> DI<D> dsin(const DI<D>& a) { return {sin(a.v), cos(a.v) * a.d}; }
template <unsigned D> DI<D> dpoly(const P& p, const DI<D>& x) {
  DI<D> r{interval<D>(0), interval<D>(0)};
  for (size_t i = p.coeffs().size(); i-- > 0;) {
    r = r * x;
    r.v += scalar_cast<interval<D>>(p.coeffs()[i]);
  }
  return r;
}

/// Derivative of the frac objective over the box th (a > 0 required: uses cot(th/2) directly).
template <unsigned D>
interval<D> frac_derivative(const Objective& o, const rational& T, const rational& tau, const interval<D>& th) {
  using I = interval<D>;
  DI<D> t{th, I(1)};
  DI<D> c = dcos(t);
  DI<D> one{I(1), I(0)};
  DI<D> taui{ival<D>(tau, tau), I(0)};
  DI<D> half{I(1) / I(2), I(0)};
  DI<D> g = dsin(taui * t) * dcos(half * t) / dsin(half * t);
  DI<D> num = (dpoly<D>(o.R, c) - (one + c) * dpoly<D>(o.Q, c)) * dcos(taui * t) +
              ((one - c) * dpoly<D>(o.Q, c) + dpoly<D>(o.R, c)) * g;
  DI<D> f = DI<D>{ival<D>(T / 2, T / 2), I(0)} * num / dpoly<D>(o.B, c);
  return f.d;
}

/// The fractional delay t_d = (p/q) T (q >= 2) made exact. With w = e^{j phi}, theta = wT = q phi,
/// z = w^q, e^{-j w t_d} = w^{-p} and T/(1 - w^q) = T/((1 - w) S(w)), S = 1 + w + ... + w^{q-1}, so
///   Re{T H(z) z^-n e^{-j w t_d}/(1 - z)} = Re{T Ht(w) w^-(nq+p)/(1 - w)},  Ht(w) = H(w^q)/S(w):
/// the integer-delay objective of Ht in c = cos(phi), on c in [cos(pi/q), 1] (w in [0, pi/T]).
/// S's roots (w^q = 1, w != 1) lie at phi >= 2 pi/q, outside the domain. Returns false when the
/// objective's degree exceeds `max_degree` (the branch-and-bound then takes over).
template <unsigned D>
bool certified_frac_exact(const BoundProblem& pb, int digits, int max_degree, Bound& out) {
  const rational tau = *pb.frac_delay / pb.T;
  const long q = den(tau).convert_to<long>(), p = num(tau).convert_to<long>();
  const long degree = q * (std::max(pb.H.den().degree(), pb.H.num().degree()) + pb.delay) + p + q;
  if (q < 2 || degree > max_degree) return false;
  auto spread = [q](const P& a) {  // a(w^q)
    std::vector<rational> c(static_cast<size_t>(a.degree() * q + 1), rational(0));
    for (int k = 0; k <= a.degree(); ++k) c[static_cast<size_t>(k * q)] = a.coeffs()[static_cast<size_t>(k)];
    return P(std::move(c));
  };
  BoundProblem pt = pb;
  pt.frac_delay.reset();
  pt.H = RF(spread(pb.H.num()), spread(pb.H.den()) * P(std::vector<rational>(static_cast<size_t>(q), rational(1))));
  pt.delay = static_cast<int>(pb.delay * q + p);
  Domain dom;
  dom.q = static_cast<int>(q);
  if (q == 2) dom.end_lo = dom.end_hi = 0;
  else if (q == 3) dom.end_lo = dom.end_hi = rational(1, 2);
  else {
    interval<D> ce = cos(ipi<D>() / interval<D>(static_cast<double>(q)));
    dom.end_lo = lower_rational(ce);
    dom.end_hi = upper_rational(ce);
  }
  Objective o = objective(pt.H, pt.T, pt.delay);
  if (!certified_rational<D>(o.f, pt, digits, out, dom)) return false;
  out.method = "certified: t_d = " + to_decimal(tau, 12) + " T made exact by w = e^{j wT/" + std::to_string(q) +
               "} (objective rational in cos(wT/" + std::to_string(q) + "), degree " +
               std::to_string(o.f.den().degree()) + "), Descartes root isolation, MPFR Newton, MPFI enclosure (" +
               std::to_string(digits) + " digits)";
  return true;
}

template <unsigned D>
Bound certified_frac(const Objective& o, const BoundProblem& pb, int digits) {
  using I = interval<D>;
  using R = mpfloat<D>;
  Bound out;
  const rational tau = *pb.frac_delay / pb.T;
  bool decided = false;
  int div = divergence_at_pi(o, pb.T, tau, decided);
  if (decided && div > 0) {
    out.infinite = true;
    out.status = Status::exact;
    out.value = "inf";
    out.where = "w -> pi/T: a pole of H z^-n at z = -1 meets e^{-j w t_d} (Tustin-like): Re -> +inf";
    out.method = "exact divergence test at wT = pi (leading terms in pi - wT)";
    I w = ipi<D>() / ival<D>(pb.T, pb.T);
    out.omega_lo = lower_rational(w);
    out.omega_hi = upper_rational(w);
    out.omega = enclosure_decimal(out.omega_lo, out.omega_hi, 17);
    return out;
  }
  // t_d = (p/q) T with a small q: exact, raising the working precision as the integer-delay path
  // does (a degree-100 objective in cos(wT/q) can need more than 50 digits to isolate its roots)
  if (certified_frac_exact<D>(pb, digits, 96, out)) return out;
  if (D < 100 && digits <= 80 && certified_frac_exact<100>(pb, digits, 96, out)) return out;
  if (certified_frac_exact<300>(pb, digits, 96, out)) return out;
  // branch-and-bound (t_d/T with a large denominator): poles on the unit circle are outside it
  for (const auto& r : isolate_real_roots(o.B, rational(-1), rational(1)))
    if (!(r.is_exact() && r.lo == -1))
      throw NumericalError("fractional delay t_d = " + to_decimal(tau, 12) + " T with a pole of H on the unit circle: "
                           "decided exactly only when t_d/T has a denominator q with q (order + n + 1) <= 96; "
                           "round t_d to such a fraction of T");
  const int dig = std::min(digits, 20);  // branch-and-bound: at most 20 digits
  const R tol = pow(R(10), -dig - 1);
  struct Box { R a, b; R ub; };
  const R pi = R(mpfloat<D>(median(ipi<D>())));
  const R pimax = R(mpfloat<D>(upper(ipi<D>())));
  auto eval_box = [&](const R& a, const R& b) {
    R ub = R(mpfloat<D>(upper(frac_objective<D>(o, pb.T, tau, I(a, b)))));
    if (isnan(ub)) ub = std::numeric_limits<R>::infinity();  // an undefined bound is no bound
    if (a > 0) {  // mean-value form, intersected with the natural one
      R m = (a + b) / 2;
      I X(a, b), Mi(m, m);
      I mv = frac_objective<D>(o, pb.T, tau, Mi) + frac_derivative<D>(o, pb.T, tau, X) * (X - Mi);
      R u2 = R(mpfloat<D>(upper(mv)));
      if (!isnan(u2) && u2 < ub) ub = u2;
    }
    return ub;
  };
  R best = -std::numeric_limits<double>::infinity(), best_at = 0;
  auto point = [&](const R& x) {
    I v = frac_objective<D>(o, pb.T, tau, I(x, x));
    R lv = R(mpfloat<D>(lower(v)));
    if (lv > best) { best = lv; best_at = x; }
  };
  // the right end is pi (enclosed): evaluate both ends and split
  std::vector<Box> work;
  const int N0 = 64;
  for (int i = 0; i < N0; ++i) {
    R a = pi * i / N0, b = (i == N0 - 1) ? pimax : pi * (i + 1) / N0;
    point((a + b) / 2);
    work.push_back({a, b, eval_box(a, b)});
  }
  point(R(0));
  point(pi);
  long evals = 0;
  const long budget = 200000;
  R maxub = best;
  R unresolved = -std::numeric_limits<R>::infinity();  // upper bounds of boxes too narrow to split
  bool converged = false;
  while (evals < budget) {
    // drop dominated boxes, find the largest upper bound
    R thresh = best + tol * std::max(R(1), abs(best));
    std::vector<Box> keep;
    maxub = std::max(best, unresolved);
    for (auto& bx : work)
      if (!(bx.ub <= thresh)) { keep.push_back(bx); maxub = std::max(maxub, bx.ub); }
    if (keep.empty()) { converged = unresolved <= thresh; break; }
    std::sort(keep.begin(), keep.end(), [](const Box& x, const Box& y) { return x.ub > y.ub; });
    std::vector<Box> next;
    size_t nsplit = std::min<size_t>(keep.size(), 16);
    for (size_t i = 0; i < keep.size(); ++i) {
      if (i >= nsplit) { next.push_back(keep[i]); continue; }
      R mid = (keep[i].a + keep[i].b) / 2;
      if (keep[i].b - keep[i].a < pow(R(10), -static_cast<int>(D) + 5)) {  // too narrow to split: its
        unresolved = std::max(unresolved, keep[i].ub);                        // bound stays in the answer
        continue;
      }
      point(mid);
      next.push_back({keep[i].a, mid, eval_box(keep[i].a, mid)});
      next.push_back({mid, keep[i].b, eval_box(mid, keep[i].b)});
      evals += 3;
    }
    work = std::move(next);
  }
  if (!converged) {
    if (!isfinite(maxub))
      throw NumericalError("fractional delay t_d = " + to_decimal(tau, 12) + " T: the branch-and-bound found b* >= " +
                           to_decimal(exact_rational(mpfloat<D>(best)) + pb.eta, 12) +
                           " but could not bound it from above within its budget; round t_d to a fraction p/q of T "
                           "with a small q (decided exactly)");
  }
  rational lo = exact_rational(mpfloat<D>(best)) + pb.eta;
  const R thresh = best + tol * std::max(R(1), abs(best));  // every dropped box lies below it
  rational hi = exact_rational(mpfloat<D>(converged ? thresh : std::max(maxub, thresh))) + pb.eta;
  out.lo = lo;
  out.hi = std::max(lo, hi);
  // not converged: [best point value, largest remaining box bound] is still a proven enclosure
  out.status = Status::certified;
  out.value = enclosure_decimal(out.lo, out.hi, dig);
  out.method = "certified: interval branch-and-bound over w (MPFI, " + std::to_string(D) +
               "-digit arithmetic, enclosure to " + std::to_string(dig) + " digits)";
  if (digits > dig) out.note = std::to_string(digits) + " digits asked; the branch-and-bound for a fractional delay stops at 20";
  if (!converged) out.note = "branch-and-bound budget exhausted: the enclosure is the proven bracket it reached";
  R w = best_at / mpfloat<D>(to_real<R>(pb.T));
  out.omega_lo = out.omega_hi = exact_rational(mpfloat<D>(w));
  out.omega = to_decimal(out.omega_lo, std::min(dig, 12));
  out.where = best_at == 0 ? "w = 0" : (best_at >= pi ? "w = pi/T" : "interior");
  return out;
}

}  // namespace

namespace {
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
  out.value = "inf";
  out.omega = "0";
  out.omega_lo = out.omega_hi = 0;
  out.where = "pole of H at z = 1 (w = 0) not cancelled: an integrator; no finite b makes the loop passive";
  out.method = "exact: H(z) has a simple pole at z = 1 (the denominator vanishes at 1 after cancellation)";
  return out;
}
}  // namespace

Bound bound_certified(const BoundProblem& p, int digits) {
  check_assumptions(p);
  if (digits < 10 || digits > 280) throw InputError("--digits must be in [10, 280] (got " + std::to_string(digits) + ")");
  if (auto inf = integrator_pole(p)) return *inf;
  const BoundProblem q = with_integer_delay(p);
  Objective o = objective(q.H, q.T, q.delay);
  if (q.frac_delay) {
    if (digits <= 30) return certified_frac<50>(o, q, digits);
    return certified_frac<100>(o, q, digits);
  }
  Bound b;
  if (digits <= 30 && certified_rational<50>(o.f, q, digits, b)) return b;
  if (digits <= 80 && certified_rational<100>(o.f, q, digits, b)) return b;
  if (certified_rational<300>(o.f, q, digits, b)) return b;
  throw NumericalError("could not decide " + std::to_string(digits) + " digits of the bound");
}

// ---------------------------------------------------------------------------------------------
// grid and fast paths
namespace {
/// Monomial coefficients of T_m and U_m (m <= 63), exact integers in double for m < 50.
struct ChebTables {
  std::vector<std::vector<double>> T, U;
  ChebTables() {
    T = {{1.0}, {0.0, 1.0}};
    U = {{1.0}, {0.0, 2.0}};
    for (int m = 2; m < 48; ++m) {
      for (auto* tab : {&T, &U}) {
        const auto& a = (*tab)[m - 1];
        const auto& b = (*tab)[m - 2];
        std::vector<double> c(m + 1, 0.0);
        for (size_t i = 0; i < a.size(); ++i) c[i + 1] += 2 * a[i];
        for (size_t i = 0; i < b.size(); ++i) c[i] -= b[i];
        tab->push_back(std::move(c));
      }
    }
  }
};
const ChebTables& cheb_tables() {
  static const ChebTables t;
  return t;
}
inline double horner_d(const std::vector<double>& c, double x) {
  double r = 0;
  for (size_t i = c.size(); i-- > 0;) r = r * x + c[i];
  return r;
}
std::vector<double> deriv(const std::vector<double>& c) {
  std::vector<double> r;
  for (size_t i = 1; i < c.size(); ++i) r.push_back(c[i] * static_cast<double>(i));
  return r;
}
/// Real roots of the polynomial c in [a, b] (double), by recursion on the derivative: between
/// consecutive critical points the polynomial is monotone, so one safeguarded bisection/Newton each.
void roots_in(const std::vector<double>& c, double a, double b, std::vector<double>& out) {
  std::vector<double> p = c;
  while (!p.empty() && p.back() == 0) p.pop_back();
  out.clear();
  if (p.size() <= 1) return;
  if (p.size() == 2) {
    double r = -p[0] / p[1];
    if (r >= a && r <= b) out.push_back(r);
    return;
  }
  std::vector<double> crit;
  roots_in(deriv(p), a, b, crit);
  std::vector<double> pts;
  pts.push_back(a);
  for (double x : crit) pts.push_back(x);
  pts.push_back(b);
  auto dp = deriv(p);
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    double x0 = pts[i], x1 = pts[i + 1];
    double f0 = horner_d(p, x0), f1 = horner_d(p, x1);
    if (f0 == 0) { if (out.empty() || out.back() != x0) out.push_back(x0); continue; }
    if (f1 == 0) continue;
    if ((f0 > 0) == (f1 > 0)) continue;
    double lo = x0, hi = x1, x = 0.5 * (x0 + x1);
    for (int it = 0; it < 100; ++it) {
      double fx = horner_d(p, x);
      if (fx == 0) break;
      if ((fx > 0) == (f0 > 0)) lo = x; else hi = x;
      double d = horner_d(dp, x);
      double xn = d != 0 ? x - fx / d : 0.5 * (lo + hi);
      if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
      if (std::abs(xn - x) <= 1e-17 * std::max(1.0, std::abs(x))) { x = xn; break; }
      x = xn;
      if (hi - lo <= 4e-16 * std::max(1.0, std::abs(x))) break;
    }
    out.push_back(x);
  }
}
}  // namespace

FastBound::FastBound(const BoundProblem& p) {
  if (with_integer_delay(p).frac_delay) { ok_ = false; return; }
  const int n = with_integer_delay(p).delay;
  T_ = to_real<double>(p.T);
  eta_ = to_real<double>(p.eta);
  // the c-form in double-double from double-double coefficients of N and D z^n
  const auto& nc = p.H.num().coeffs();
  const auto& dc0 = p.H.den().coeffs();
  std::vector<dd> N, Dp(static_cast<size_t>(n), dd{0, 0});
  for (auto& x : nc) N.push_back(to_dd(x));
  for (auto& x : dc0) Dp.push_back(to_dd(x));
  // H's denominator is monic after reduction; scale-free inputs keep dd products exact enough
  const int nn = static_cast<int>(N.size()), nd = static_cast<int>(Dp.size());
  const int M = std::max(nn, nd);
  std::vector<dd> a(M + 1), cs(M + 1), e(M + 1);
  for (int k = 0; k < nn; ++k)
    for (int l = 0; l < nd; ++l) {
      dd pr = N[k] * Dp[l];
      int m = k - l;
      if (m == 0) a[0] = a[0] + pr;
      else if (m > 0) { a[m] = a[m] + pr; cs[m] = cs[m] + pr; }
      else { a[-m] = a[-m] + pr; cs[-m] = cs[-m] - pr; }
    }
  for (int l = 0; l < nd; ++l)
    for (int l2 = l; l2 < nd; ++l2) {
      dd pr = Dp[l] * Dp[l2];
      if (l2 == l) e[0] = e[0] + pr;
      else e[l2 - l] = e[l2 - l] + pr + pr;
    }
  // Chebyshev -> monomial (integer coefficients, exact in double)
  if (M >= 48) { ok_ = false; return; }
  const ChebTables& ct = cheb_tables();
  auto add_cheb = [](std::vector<dd>& acc, const std::vector<double>& basis, dd coef) {
    if (coef.hi == 0) return;
    if (acc.size() < basis.size()) acc.resize(basis.size());
    for (size_t i = 0; i < basis.size(); ++i)
      if (basis[i] != 0) acc[i] = acc[i] + coef * dd{basis[i], 0};
  };
  std::vector<dd> R, Q, B;
  for (int m = 0; m <= M; ++m) {
    add_cheb(R, ct.T[m], a[m]);
    if (m >= 1) add_cheb(Q, ct.U[m - 1], cs[m]);
    add_cheb(B, ct.T[m], e[m]);
  }
  // A = (T/2)(R - (1+c) Q)
  std::vector<dd> A(std::max(R.size(), Q.size() + 1));
  for (size_t i = 0; i < R.size(); ++i) A[i] = A[i] + R[i];
  for (size_t i = 0; i < Q.size(); ++i) { A[i] = A[i] - Q[i]; A[i + 1] = A[i + 1] - Q[i]; }
  dd half_T = to_dd(p.T / 2);
  if (A.empty()) A.push_back(dd{0, 0});
  if (B.empty()) { ok_ = false; return; }
  for (auto& x : A) x = x * half_T;
  for (auto& x : A) { Ahi_.push_back(x.hi); Alo_.push_back(x.lo); }
  for (auto& x : B) { Bhi_.push_back(x.hi); Blo_.push_back(x.lo); }
}

std::optional<std::pair<double, double>> FastBound::evaluate() const {
  if (!ok_) return std::nullopt;
  // B = |D'|^2 > 0 on [-1, 1] unless a pole lies on the unit circle: check at its critical points
  double bscale = 0;
  for (double x : Bhi_) bscale = std::max(bscale, std::abs(x));
  std::vector<double> rb;
  roots_in(deriv(Bhi_), -1.0, 1.0, rb);
  rb.push_back(-1.0);
  rb.push_back(1.0);
  // A resonance so narrow that min B < 1e-11 max|B_k| (pole radius above ~1 - 3e-6): the critical
  // points of f are located in double from coefficients that cancel down to min B, and the maximiser
  // is lost (radius 1 - 1e-8 gave -2.8e-4 for a true 66666.7; 1 - 1e-7 an error of 3e-12). Such
  // cases go to the certified path, which is exact about them (~0.1-0.3 ms).
  for (double x : rb)
    if (horner_dd(Bhi_, Blo_, x).hi <= 1e-11 * bscale) return std::nullopt;
  // P = A'B - AB' in double-double
  const size_t na = Ahi_.size(), nb = Bhi_.size();
  std::vector<dd> Pd(na + nb, dd{0, 0});
  // (k * hi rounds in double: scale by k in double-double, or P keeps only double accuracy and its
  // root -- the maximiser -- moves by ~1e-16 / P': 5e-11 at radius 0.99999 with a 2-sample delay)
  for (size_t i = 1; i < na; ++i)
    for (size_t j = 0; j < nb; ++j)
      Pd[i - 1 + j] = Pd[i - 1 + j] + dd{Ahi_[i], Alo_[i]} * dd{static_cast<double>(i), 0} * dd{Bhi_[j], Blo_[j]};
  for (size_t i = 0; i < na; ++i)
    for (size_t j = 1; j < nb; ++j)
      Pd[i + j - 1] = Pd[i + j - 1] - dd{Ahi_[i], Alo_[i]} * dd{static_cast<double>(j), 0} * dd{Bhi_[j], Blo_[j]};
  std::vector<double> Ph, Pl;
  for (auto& x : Pd) { Ph.push_back(x.hi); Pl.push_back(x.lo); }
  std::vector<double> roots;
  roots_in(Ph, -1.0, 1.0, roots);
  // Newton on P with P and P' both in double-double. A root located in double from P's cancelling
  // coefficients must converge here, else the case goes to the certified path; the minima of B (the
  // resonance centres, rb) seed extra starts, so a narrow peak is never missed by the double scan.
  std::vector<double> dPh, dPl;
  for (size_t k = 1; k < Ph.size(); ++k) {
    dd c = dd{Ph[k], Pl[k]} * dd{static_cast<double>(k), 0};
    dPh.push_back(c.hi);
    dPl.push_back(c.lo);
  }
  auto polish = [&](double& x) {
    for (int it = 0; it < 12; ++it) {
      dd d = horner_dd(dPh, dPl, x);
      if (d.hi == 0) return false;
      const double step = (horner_dd(Ph, Pl, x) / d).hi;
      if (!std::isfinite(step) || x - step < -1 || x - step > 1) return false;
      x -= step;
      if (std::abs(step) <= 2e-16 * std::max(1.0, std::abs(x))) return true;
    }
    return false;
  };
  std::vector<double> crit;
  for (double x : roots) {
    if (!polish(x)) return std::nullopt;
    crit.push_back(x);
  }
  for (double x : rb)
    if (x > -1 && x < 1 && polish(x)) crit.push_back(x);
  crit.push_back(1.0);
  crit.push_back(-1.0);
  double best = -std::numeric_limits<double>::infinity(), bc = 1;
  for (double x : crit) {
    dd v = horner_dd(Ahi_, Alo_, x) / horner_dd(Bhi_, Blo_, x);
    double vv = (v + dd{eta_, 0}).hi;
    if (vv > best) { best = vv; bc = x; }
  }
  return std::make_pair(best, std::acos(std::clamp(bc, -1.0, 1.0)) / T_);
}

// The objective at theta = wT > 0 evaluated on the unit circle itself, in the scalar R:
//   Re{T W/(1 - z)} = (T/2) (Re W - cot(theta/2) Im W),  W = H(z) z^-n e^{-j theta t_d/T},
// since 1/(1 - e^{j theta}) = 1/2 + (j/2) cot(theta/2). Horner on |z| = 1 keeps the relative
// accuracy of R whatever the degree; the c-form A(c)/B(c) does not: its monomial coefficients
// grow like 2^degree, and in double it returned 0.34 for z^-50 (b* = 0.0505) and 1e171 for
// z^-500. At theta = 0 the limit is the exact c-form value at c = 1.
template <class R>
R objective_on_circle(const BoundProblem& p, const R& th) {
  const R zr = cos(th), zi = sin(th);
  auto horner = [&](const P& poly, R& re, R& im) {
    re = 0, im = 0;
    for (size_t i = poly.coeffs().size(); i-- > 0;) {
      const R nr = re * zr - im * zi + to_real<R>(poly.coeffs()[i]);
      im = re * zi + im * zr;
      re = nr;
    }
  };
  R nr, ni, dr, di;
  horner(p.H.num(), nr, ni);
  horner(p.H.den(), dr, di);
  const R d2 = dr * dr + di * di;
  const R hr = (nr * dr + ni * di) / d2, hi = (ni * dr - nr * di) / d2;
  R lag = th * R(p.delay);
  if (p.frac_delay) lag += th * to_real<R>(*p.frac_delay / p.T);
  const R cr = cos(lag), ci = -sin(lag);
  const R wr = hr * cr - hi * ci, wi = hr * ci + hi * cr;
  return to_real<R>(p.T) / 2 * (wr - wi * cos(th / 2) / sin(th / 2)) + to_real<R>(p.eta);
}

// The limit at theta = 0 (exact: the c-form at c = 1, plus the fractional delay's term).
double objective_at_zero(const BoundProblem& p) {
  using R = mp50;
  Objective o = objective(p.H, p.T, p.delay);
  const R one(1);
  if (!p.frac_delay) return static_cast<double>(to_real<R>(o.f.num()(rational(1)) / o.f.den()(rational(1))) + to_real<R>(p.eta));
  const R tau = to_real<R>(*p.frac_delay / p.T);
  const R num = (to_real<R>(o.R(rational(1))) - 2 * to_real<R>(o.Q(rational(1)))) + to_real<R>(o.R(rational(1))) * 2 * tau;
  return static_cast<double>(to_real<R>(p.T) / 2 * num / to_real<R>(o.B(rational(1))) + to_real<R>(p.eta));
}

Bound bound_grid(const BoundProblem& p, long N) {
  check_assumptions(p);
  if (N < 2) throw InputError("grid: N must be >= 2");
  if (auto inf = integrator_pole(p)) return *inf;
  Bound out;
  out.status = Status::numeric;
  out.method = "grid (" + std::to_string(N) + " points, double, evaluated on the unit circle)";
  const double T = to_real<double>(p.T);
  const double pi = 3.14159265358979323846;
  double best = objective_at_zero(p), bw = 0;
  for (long k = 1; k < N; ++k) {
    const double th = pi * static_cast<double>(k) / static_cast<double>(N - 1);
    const double v = objective_on_circle<double>(p, th);
    if (v > best) best = v, bw = th / T;
  }
  if (std::isinf(best) && best > 0) { out.infinite = true; out.value = "inf"; return out; }
  out.lo = out.hi = exact_rational(best);
  out.value = to_decimal(out.lo, 17);
  out.omega = to_decimal(exact_rational(bw), 17);
  out.omega_lo = out.omega_hi = exact_rational(bw);
  out.where = "grid point";
  return out;
}

Bound bound(const BoundProblem& p, Method m, int digits, long grid_points) {
  if (m == Method::grid) return bound_grid(p, grid_points);
  if (m == Method::fast) {
    check_assumptions(p);
    if (auto r = FastBound::run(p)) {
      Bound out;
      out.status = Status::numeric;
      out.method = "fast: double-double coefficients, root finding in double, Newton polish";
      out.lo = out.hi = exact_rational(r->first);
      out.value = to_decimal(out.lo, 16);
      out.omega = to_decimal(exact_rational(r->second), 16);
      out.omega_lo = out.omega_hi = exact_rational(r->second);
      out.where = "numeric maximiser";
      return out;
    }
  }
  return bound_certified(p, digits);
}

// ---------------------------------------------------------------------------------------------
NecessaryCheck necessary_condition(const RF& H, const rational& T, const rational& b, const rational& omega) {
  using R = mp50;
  if (omega <= 0) throw InputError("necessary_condition: omega must be > 0 (r(jw) has a pole at w = 0)");
  R th = to_real<R>(omega * T);
  R zr = cos(th), zi = sin(th);
  auto eval = [&](const P& p, R& re, R& im) {
    re = 0; im = 0;
    for (size_t i = p.coeffs().size(); i-- > 0;) {
      R nr = re * zr - im * zi + to_real<R>(p.coeffs()[i]);
      R ni = re * zi + im * zr;
      re = nr; im = ni;
    }
  };
  R nr, ni, dr, di;
  eval(H.num(), nr, ni);
  eval(H.den(), dr, di);
  R dd2 = dr * dr + di * di;
  R hr = (nr * dr + ni * di) / dd2, hi = (ni * dr - nr * di) / dd2;
  // r = T/(z - 1)
  R ar = zr - 1, ai = zi, a2 = ar * ar + ai * ai;
  R Tr = to_real<R>(T);
  R rr = Tr * ar / a2, ri = -Tr * ai / a2;
  R xr = rr * hr - ri * hi, xi = rr * hi + ri * hr;  // r H
  R br = to_real<R>(b);
  R lhs = sqrt(xr * xr + xi * xi) / sqrt((2 * br + xr) * (2 * br + xr) + xi * xi);
  NecessaryCheck c;
  c.lhs14 = static_cast<double>(lhs);
  c.rhs15 = static_cast<double>(-xr);
  c.holds14 = lhs < 1;
  c.holds15 = br > -xr;
  return c;
}

double objective_at(const BoundProblem& p, double omega) {
  if (omega == 0) return objective_at_zero(p);
  return static_cast<double>(objective_on_circle<mp50>(p, mp50(omega) * to_real<mp50>(p.T)));
}

}  // namespace hapstab::passivity
