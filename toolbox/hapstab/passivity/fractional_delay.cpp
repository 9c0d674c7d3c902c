// The passivity bound with a fractional delay t_d (54), not a multiple of T: the objective
// e^{-j w t_d} is not rational in c = cos(wT). An exact divergence test at wT = pi (Tustin-like
// poles at z = -1); t_d = (p/q) T with a small q made exact (w = e^{j wT/q}); else an interval
// branch-and-bound over w (MPFI).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::passivity::detail {


namespace {

// f_tau(theta) B(c) = (T/2)[ (R - (1+c)Q) cos(tau theta) + ((1-c)Q + R) sin(tau theta) cot(theta/2) ],
// tau = t_d/T, c = cos theta.

int multiplicity_at_minus_one(QPoly p, QPoly& rest) {
  int k = 0;
  const QPoly lin(std::vector<rational>{rational(1), rational(1)});
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
  QPoly Bm, A1, E1;
  int m = multiplicity_at_minus_one(o.B, Bm);
  if (m == 0) return 0;
  const QPoly one_plus_c(std::vector<rational>{rational(1), rational(1)});
  const QPoly one_minus_c(std::vector<rational>{rational(1), rational(-1)});
  QPoly Araw = o.R - one_plus_c * o.Q;
  QPoly E = one_minus_c * o.Q + o.R;
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
template <unsigned D> DI<D> dpoly(const QPoly& p, const DI<D>& x) {
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

/// The fractional delay t_d = (p/q) T (q >= 2) made exact (frac_exact_problem, bound_detail.hpp):
/// the integer-delay objective of Ht in c = cos(phi), maximised on c in [cos(pi/q), 1].
/// Returns false when the objective's degree exceeds `max_degree` (the branch-and-bound then takes over).
template <unsigned D>
bool certified_frac_exact(const BoundProblem& pb, int digits, int max_degree, Bound& out) {
  const std::optional<FracExact> fe = frac_exact_problem<D>(pb, max_degree);
  if (!fe) return false;
  const long q = fe->domain.q;
  const rational tau = *pb.frac_delay / pb.T;
  Objective o = objective(fe->problem.H, fe->problem.T, fe->problem.delay);
  if (!certified_rational<D>(o.f, fe->problem, digits, out, fe->domain)) return false;
  out.method = "certified: t_d = " + to_decimal(tau, 12) + " T made exact by w = e^{j wT/" + std::to_string(q) +
               "} (objective rational in cos(wT/" + std::to_string(q) + "), degree " +
               std::to_string(o.f.den().degree()) + "), Descartes root isolation, MPFR Newton, MPFI enclosure (" +
               std::to_string(digits) + " digits)";
  return true;
}

/// b* = +inf when a pole of H z^-n at z = -1 meets the fractional delay (exact divergence test).
template <unsigned D>
std::optional<Bound> frac_divergence(const Objective& o, const BoundProblem& pb, const rational& tau) {
  using I = interval<D>;
  Bound out;
  bool decided = false;
  int div = divergence_at_pi(o, pb.T, tau, decided);
  if (!(decided && div > 0)) return std::nullopt;
  out.infinite = true;
  out.status = Status::exact;
  out.decimal = "inf";
  out.where = "w -> pi/T: a pole of H z^-n at z = -1 meets e^{-j w t_d} (Tustin-like): Re -> +inf";
  out.method = "exact divergence test at wT = pi (leading terms in pi - wT)";
  I w = ipi<D>() / ival<D>(pb.T, pb.T);
  out.omega_enclosure = Enclosure<rational>{lower_rational(w), upper_rational(w)};
  out.omega = enclosure_decimal(out.omega_enclosure->lo, out.omega_enclosure->hi, 17);
  return out;
}

/// Where the interval branch-and-bound over theta = wT in [0, pi] stopped: the best proven value
/// `best` (a point value, at theta = best_at), the largest upper bound left, and the tolerance.
template <unsigned D>
struct FracSearch {
  mpfloat<D> best, best_at, maxub, tol, pi;
  bool converged = false;
};

/// Interval branch-and-bound over theta in [0, pi] to `dig` digits (mean-value form on boxes
/// away from 0), within a budget of evaluations.
template <unsigned D>
FracSearch<D> frac_branch_and_bound(const Objective& o, const BoundProblem& pb, const rational& tau, int dig) {
  using I = interval<D>;
  using R = mpfloat<D>;
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
  return {best, best_at, maxub, tol, pi, converged};
}

/// The proven enclosure [best, max(upper bounds left)] + eta as a Bound.
template <unsigned D>
Bound frac_bound(const FracSearch<D>& sr, const BoundProblem& pb, const rational& tau, int digits, int dig) {
  using R = mpfloat<D>;
  const R &best = sr.best, &best_at = sr.best_at, &maxub = sr.maxub, &tol = sr.tol, &pi = sr.pi;
  const bool converged = sr.converged;
  Bound out;
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
  out.enclose(lo, std::max(lo, hi));
  // not converged: [best point value, largest remaining box bound] is still a proven enclosure
  out.status = Status::certified;
  out.decimal = enclosure_decimal(out.enclosure->lo, out.enclosure->hi, dig);
  out.method = "certified: interval branch-and-bound over w (MPFI, " + std::to_string(D) +
               "-digit arithmetic, enclosure to " + std::to_string(dig) + " digits)";
  if (digits > dig) out.note = std::to_string(digits) + " digits asked; the branch-and-bound for a fractional delay stops at 20";
  if (!converged) out.note = "branch-and-bound budget exhausted: the enclosure is the proven bracket it reached";
  R w = best_at / mpfloat<D>(to_real<R>(pb.T));
  const rational w_exact = exact_rational(mpfloat<D>(w));
  out.omega_enclosure = Enclosure<rational>{w_exact, w_exact};
  out.omega = to_decimal(w_exact, std::min(dig, 12));
  out.where = best_at == 0 ? "w = 0" : (best_at >= pi ? "w = pi/T" : "interior");
  return out;
}

template <unsigned D>
Bound certified_frac(const Objective& o, const BoundProblem& pb, int digits) {
  Bound out;
  const rational tau = *pb.frac_delay / pb.T;
  if (auto inf = frac_divergence<D>(o, pb, tau)) return *inf;
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
  return frac_bound<D>(frac_branch_and_bound<D>(o, pb, tau, dig), pb, tau, digits, dig);
}

}  // namespace

// With w = e^{j phi}, theta = wT = q phi, z = w^q, e^{-j w t_d} = w^{-p} and T/(1 - w^q) = T/((1 - w) S(w)),
// S = 1 + w + ... + w^{q-1}, so
//   Re{T H(z) z^-n e^{-j w t_d}/(1 - z)} = Re{T Ht(w) w^-(nq+p)/(1 - w)},  Ht(w) = H(w^q)/S(w):
// the integer-delay objective of Ht in c = cos(phi), on c in [cos(pi/q), 1] (w in [0, pi/T]).
// S's roots (w^q = 1, w != 1) lie at phi >= 2 pi/q, outside the domain.
template <unsigned D>
std::optional<FracExact> frac_exact_problem(const BoundProblem& pb, int max_degree) {
  if (!pb.frac_delay) return std::nullopt;
  const rational tau = *pb.frac_delay / pb.T;
  const long q = den(tau).convert_to<long>(), p = num(tau).convert_to<long>();
  const long degree = q * (std::max(pb.H.den().degree(), pb.H.num().degree()) + pb.delay) + p + q;
  if (q < 2 || degree > max_degree) return std::nullopt;
  auto spread = [q](const QPoly& a) {  // a(w^q)
    std::vector<rational> c(static_cast<size_t>(a.degree() * q + 1), rational(0));
    for (int k = 0; k <= a.degree(); ++k) c[static_cast<size_t>(k * q)] = a.coeffs()[static_cast<size_t>(k)];
    return QPoly(std::move(c));
  };
  FracExact fe;
  fe.problem = pb;
  fe.problem.frac_delay.reset();
  fe.problem.H = QRatFun(spread(pb.H.num()), spread(pb.H.den()) * QPoly(std::vector<rational>(static_cast<size_t>(q), rational(1))));
  fe.problem.delay = static_cast<int>(pb.delay * q + p);
  fe.domain.q = static_cast<int>(q);
  if (q == 2) fe.domain.end_lo = fe.domain.end_hi = 0;
  else if (q == 3) fe.domain.end_lo = fe.domain.end_hi = rational(1, 2);
  else {
    interval<D> ce = cos(ipi<D>() / interval<D>(static_cast<double>(q)));
    fe.domain.end_lo = lower_rational(ce);
    fe.domain.end_hi = upper_rational(ce);
  }
  return fe;
}
template std::optional<FracExact> frac_exact_problem<50>(const BoundProblem&, int);
template std::optional<FracExact> frac_exact_problem<100>(const BoundProblem&, int);
template std::optional<FracExact> frac_exact_problem<300>(const BoundProblem&, int);

Bound certified_fractional_delay(const Objective& o, const BoundProblem& pb, int digits) {
  if (digits <= 30) return certified_frac<50>(o, pb, digits);
  return certified_frac<100>(o, pb, digits);
}

}  // namespace hapstab::passivity::detail
