// The passivity bound with a fractional delay t_d (54), not a multiple of T, by the exact path:
// e^{-j w t_d} is not rational in c = cos(wT), but with t_d = (p/q) T it is rational in
// cos(wT/q) (w = e^{j wT/q}); an exact divergence test at wT = pi decides Tustin-like poles at
// z = -1. A large q, or a long delay, goes to the long-delay path (long_delay.cpp).
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
}  // namespace

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
std::optional<FracExact> frac_exact_problem(const BoundProblem& pb, int max_degree) {
  if (!pb.frac_delay) return std::nullopt;
  const rational tau = *pb.frac_delay / pb.T;
  const long degree = fractional_exact_degree(pb);
  if (den(tau) < 2 || degree > max_degree) return std::nullopt;
  const long q = den(tau).convert_to<long>(), p = num(tau).convert_to<long>();  // both <= degree
  auto spread = [q](const QPoly& a) {  // a(w^q)
    if (a.is_zero()) return a;          // degree -1: (-1) q + 1 elements would be a huge size_t
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

/// The fractional delay t_d = (p/q) T (q >= 2) made exact. With w = e^{j phi}, theta = wT = q phi,
/// z = w^q, e^{-j w t_d} = w^{-p} and T/(1 - w^q) = T/((1 - w) S(w)), S = 1 + w + ... + w^{q-1}, so
///   Re{T H(z) z^-n e^{-j w t_d}/(1 - z)} = Re{T Ht(w) w^-(nq+p)/(1 - w)},  Ht(w) = H(w^q)/S(w):
/// the integer-delay objective of Ht in c = cos(phi), on c in [cos(pi/q), 1] (w in [0, pi/T]).
/// S's roots (w^q = 1, w != 1) lie at phi >= 2 pi/q, outside the domain. Returns false when the
/// objective's degree exceeds `max_degree` (the branch-and-bound then takes over).
namespace {

template <unsigned D>
bool certified_frac_exact(const BoundProblem& pb, int digits, int max_degree, Bound& out) {
  const std::optional<FracExact> fe = frac_exact_problem<D>(pb, max_degree);
  if (!fe) return false;
  const rational tau = *pb.frac_delay / pb.T;
  const int q = fe->domain.q;
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

}  // namespace

std::optional<Bound> fractional_divergence(const BoundProblem& pb) {
  if (!pb.frac_delay) return std::nullopt;
  // the delay folded into tau = n + t_d/T: the objective of H alone times e^{-j tau wT}, no z^-n expanded
  const rational tau = rational(pb.delay) + *pb.frac_delay / pb.T;
  return frac_divergence<50>(objective(pb.H, pb.T, 0), pb, tau);
}

long fractional_exact_degree(const BoundProblem& pb) {
  if (!pb.frac_delay) return 0;
  const rational tau = *pb.frac_delay / pb.T;
  // in integers: t_d = 10^-25 s makes q = 10^22, beyond a long (converted, it saturated, and the
  // product overflowed)
  const integer d = den(tau) * (std::max(pb.H.den().degree(), pb.H.num().degree()) + pb.delay) + num(tau) + den(tau);
  const integer cap(std::numeric_limits<long>::max());
  return (d > cap ? cap : d).convert_to<long>();
}

// Where the long-delay path takes the case, the exact one runs up to degree 96 (bound.cpp weighs
// their costs). Where it does not (a pole on the unit circle other than a simple one at z = -1; before
// stop 82 also that pole meeting a fractional delay), the exact path is the only one, and its Sturm
// counts grow ~degree^4: measured 1.4 s at degree 158 (a wall with 50 samples and t_d = T/6), 7.4 s
// at 207 (the Tustin wall at t_d = 101.5 T), minutes at 533 (174 samples). 240 keeps every answer within ~15 s; beyond it the case is refused
// by name, exit 2 (the limit was 1000: the 533 case ran for minutes).
long fractional_exact_limit(const BoundProblem& pb) { return long_delay_applies(pb, nullptr) ? 96 : 240; }

bool certified_fractional_exact(const BoundProblem& pb, int digits, int max_degree, Bound& out) {
  if (auto inf = fractional_divergence(pb)) {
    out = *inf;
    return true;
  }
  // raising the working precision as the integer-delay path does (a degree-100 objective in
  // cos(wT/q) can need more than 50 digits to isolate its roots)
  if (digits <= 30 && certified_frac_exact<50>(pb, digits, max_degree, out)) return true;
  if (digits <= 80 && certified_frac_exact<100>(pb, digits, max_degree, out)) return true;
  return certified_frac_exact<300>(pb, digits, max_degree, out);
}

}  // namespace hapstab::passivity::detail
