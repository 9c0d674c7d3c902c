// The passivity bound b* of paper 001, (45) and (54) (bound.hpp): the assumptions of (45), the
// dispatcher over the methods, and the necessary condition (14), (15) of Sec. III. The methods
// live beside it (bound_detail.hpp lists them): objective.cpp, certified.cpp,
// fractional_delay.cpp, fast.cpp, grid.cpp.
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/bound_detail.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::passivity {


double Bound::value_double() const {
  if (infinite) return std::numeric_limits<double>::infinity();
  return to_real<double>(value);
}

void Bound::enclose(rational lo, rational hi) {
  value = (lo + hi) / 2;
  enclosure = Enclosure<rational>{std::move(lo), std::move(hi)};
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
  const long degree = std::max<long>(p.H.num().degree(), p.H.den().degree());
  if (degree > limits::model_degree)
    throw InputError("H has degree " + std::to_string(degree) + ", more than the limit of " +
                     std::to_string(limits::model_degree) + " for a model");
  // the delay in samples, n + t_d/T, compared before any use (t_d/T may be a huge rational)
  rational samples(p.delay);
  if (p.frac_delay && p.T > 0) samples += *p.frac_delay / p.T;
  if (samples > limits::criterion_delay)
    throw InputError("the delay n + t_d/T = " + to_decimal(samples, 12) + " samples is more than the limit of " +
                     std::to_string(limits::criterion_delay) +
                     " (numeric/limits.hpp: the long-delay path's work grows like the delay)");
}

// ---------------------------------------------------------------------------------------------
// the planner: exact path (degree^4) or long-delay path (~ nu), by estimated cost
namespace {
// Costs on one core of the reference machine, fitted to bench/delay.cpp (BM_bound, the wall
// 10 + 5 (z - 1)/(T z); refitted 3 December 2026): the exact path 0.46 ms at degree 11, 3.0 ms at
// 31, 30 ms at 61, 0.19 s at 101 (~ degree^4); the long-delay path (boxes in double intervals
// first, issue 48) 0.33 ms at n = 10, 1.0 ms at 100, 4.2 ms at 10^3, 39 ms at 10^4 (~ its
// 4 nu + 64 boxes). The exact path runs while it costs at most twice the long-delay path or 20 ms:
// up to n ~ 55 for a low-order wall (it can prove an interior maximum exact).
double exact_cost(long degree) {
  const double d = static_cast<double>(degree) / 100;
  return 5e-4 + 0.2 * d * d * d * d;
}
double long_cost(const rational& nu, long order) {
  const double boxes = 4 * to_real<double>(nu) + 64;
  return 2e-4 + boxes * 9e-7 * (1 + 0.1 * static_cast<double>(order));
}
// the exact objective's degree as the planner states it (fractional_exact_degree saturates at LONG_MAX)
std::string degree_text(long d) { return d == std::numeric_limits<long>::max() ? "beyond 2^63" : std::to_string(d); }
std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 0.01 ? "%.1g s" : "%.2g s", s);
  return buf;
}
}  // namespace

BoundPlan plan_bound(const BoundProblem& raw) {
  const BoundProblem p = with_integer_delay(raw);
  BoundPlan plan;
  const long order = std::max<long>(p.H.num().degree(), p.H.den().degree());
  plan.exact_degree = p.frac_delay ? detail::fractional_exact_degree(p)
                                   : std::max<long>(p.H.num().degree(), long(p.H.den().degree()) + p.delay);
  const long exact_limit = p.frac_delay ? detail::fractional_exact_limit(p) : limits::model_degree;
  const bool exact_ok = plan.exact_degree <= exact_limit;
  plan.exact_seconds = exact_ok ? exact_cost(plan.exact_degree) : std::numeric_limits<double>::infinity();
  std::string why_not;
  const bool long_ok = detail::long_delay_applies(p, &why_not).has_value();
  const rational nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  plan.long_seconds = long_ok ? long_cost(nu, order) : std::numeric_limits<double>::infinity();
  const std::string costs = (exact_ok ? "exact path ~" + seconds(plan.exact_seconds) : std::string("exact path beyond its limit")) +
                            (long_ok ? ", long-delay path ~" + seconds(plan.long_seconds) : std::string(", no long-delay path"));
  if (exact_ok && (!long_ok || plan.exact_seconds <= std::max(2 * plan.long_seconds, 0.02))) {
    plan.path = BoundPath::exact;
    plan.why = "exact path: its objective has degree " + std::to_string(plan.exact_degree) + " (" + costs + ")";
  } else if (long_ok) {
    plan.path = BoundPath::long_delay;
    plan.why = "long-delay path: the exact objective would have degree " + degree_text(plan.exact_degree) + " (" +
               costs + ")";
  } else {
    plan.path = BoundPath::exact;  // neither: the exact path refuses by its limit (bound_certified)
    plan.why = "exact path only: the long-delay path does not apply (" + why_not + ")";
  }
  return plan;
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

Bound bound_certified(const BoundProblem& p, int digits) {
  check_assumptions(p);
  if (auto inf = detail::integrator_pole(p)) return *inf;
  if (auto inf = detail::fractional_divergence(with_integer_delay(p))) return *inf;  // before any path: cheap, exact
  const BoundPlan plan = plan_bound(p);
  if (!std::isfinite(plan.exact_seconds) && !std::isfinite(plan.long_seconds)) {
    // a simple pole on the circle inside the band (which the long-delay path does not take) decided
    // locally, at any delay (circle_pole.cpp); where its term vanishes, the case is refused below
    if (auto inf = detail::circle_pole_divergence(with_integer_delay(p))) {
      inf->plan = "a pole on the unit circle inside the band, decided where it is (" + plan.why + ")";
      return *inf;
    }
    std::string why;
    detail::long_delay_applies(with_integer_delay(p), &why);
    throw InputError("no path takes this case: the exact objective would have degree " +
                     degree_text(plan.exact_degree) + ", more than the exact path's limit of " +
                     std::to_string(p.frac_delay ? detail::fractional_exact_limit(with_integer_delay(p)) : limits::model_degree) +
                     ", and the long-delay path does not apply: " + why +
                     (why.find("pole on the unit circle") != std::string::npos
                          ? "; nor is b* = +inf shown at that pole: its term Im(c)/(theta - theta0), c = T R e^{-j nu theta0}/((1 - z0) z0), "
                            "is not shown nonzero (it vanishes, e.g. H = (z - 1)/(z^2 + 1) at an even delay)"
                          : ""));
  }
  Bound b;
  try {
    if (plan.path == BoundPath::long_delay && std::isfinite(plan.exact_seconds) && digits >= 10 && digits <= 280) {
      // the exact path stands behind: the long-delay search gets about the exact path's estimated cost (an
      // Arb evaluation ~6 us per degree: 0.4 ms at degree 64), at least 1000 evaluations (the cases it
      // settles take a few hundred), and hands over when it does not settle (1/(z + 1/3)^64 at stop 87's
      // review: three attempts of 200,000 evaluations, 61 s, then exit 3; the exact path answers it)
      const double per_evaluation = 6e-6 * static_cast<double>(std::max<long>(plan.exact_degree, 1));
      const long budget = std::max(1000L, static_cast<long>(std::min(1e8, plan.exact_seconds / per_evaluation)));
      b = detail::certified_long_delay(with_integer_delay(p), digits, true, budget);
    } else {
      b = bound_certified(p, digits, plan.path);
    }
  } catch (const NumericalError&) {  // one path could not decide its digits: the other may
    if (plan.path == BoundPath::exact && std::isfinite(plan.long_seconds))
      b = bound_certified(p, digits, BoundPath::long_delay);
    else if (plan.path == BoundPath::long_delay && std::isfinite(plan.exact_seconds))
      b = bound_certified(p, digits, BoundPath::exact);
    else
      throw;
  }
  b.plan = plan.why;
  return b;
}

Bound bound_certified(const BoundProblem& p, int digits, BoundPath path) {
  check_assumptions(p);
  if (digits < 10 || digits > 280) throw InputError("--digits must be in [10, 280] (got " + std::to_string(digits) + ")");
  if (auto inf = detail::integrator_pole(p)) return *inf;
  const BoundProblem q = with_integer_delay(p);
  if (path == BoundPath::long_delay) return detail::certified_long_delay(q, digits);
  const BoundPlan plan = plan_bound(q);
  const long exact_limit = q.frac_delay ? detail::fractional_exact_limit(q) : limits::model_degree;
  if (plan.exact_degree > exact_limit)
    throw InputError("the exact objective of (45) would have degree " + degree_text(plan.exact_degree) +
                     ", more than the limit of " + std::to_string(exact_limit) +
                     " for the exact path (the long-delay path takes any delay)");
  Bound b = detail::certified_exact(q, digits);
  b.path = BoundPath::exact;
  return b;
}

namespace {
// the stated error of the fast paths (not a proof): relative 10^-fast_error_digits for f(c) in
// double-double; the long-delay double path states its own (fast_long_delay)
Bound fast_result(double value, double omega, double relative_error, const std::string& how, BoundPath path) {
  Bound out;
  out.status = Status::numeric;
  out.kind = Method::fast;
  out.path = path;
  out.method = how;
  const rational v = exact_rational(value), e = abs(v) * exact_rational(relative_error);
  out.enclose(v - e, v + e);
  out.decimal = to_decimal(v, 16);
  const rational w = exact_rational(omega);
  out.omega = to_decimal(w, 16);
  out.omega_enclosure = Enclosure<rational>{w, w};
  out.where = "numeric maximiser";
  return out;
}
}  // namespace

Bound bound(const BoundProblem& p, Method m, int digits, long grid_points) {
  if (m == Method::grid) return bound_grid(p, grid_points);
  if (m == Method::fast) {
    check_assumptions(p);
    if (auto inf = detail::integrator_pole(p)) return *inf;
    const BoundPlan plan = plan_bound(p);
    if (plan.path == BoundPath::exact) {
      if (auto r = FastBound::run(p)) {
        Bound b = fast_result(r->first, r->second, std::pow(10.0, -fast_error_digits),
                              "fast: double-double coefficients, root finding in double, Newton polish", BoundPath::exact);
        b.plan = plan.why;
        return b;
      }
    } else if (auto r = fast_long_delay(with_integer_delay(p));
               r && std::isfinite(r->value) && std::isfinite(r->omega) && std::isfinite(r->relative_error)) {
      // (not finite: a value the doubles overflowed, e.g. a pole at 1 - 1e-12 with delay 60 -- certified answers)
      Bound b = fast_result(r->value, r->omega, r->relative_error,
                            "fast: the long-delay objective in double, sampled every pi/(4 nu + 64), its best local "
                            "maxima polished by Newton",
                            BoundPath::long_delay);
      b.plan = plan.why;
      return b;
    }
  }
  return bound_certified(p, digits);
}

bool enclosure_rigorous(const Bound& b) {
  return b.infinite || b.status == Status::exact || b.status == Status::certified;
}

Enclosure<std::string> reported_enclosure(const Bound& b, int digits) {
  if (b.infinite) return {"inf", "inf"};
  const auto& [lo, hi] = *b.enclosure;
  if (b.kind == Method::grid && b.status == Status::numeric) return {decimal_outward(lo, 17, -1), "inf"};
  if (b.status == Status::numeric) return {decimal_outward(lo, 17, -1), decimal_outward(hi, 17, +1)};
  return {decimal_outward(lo, digits + 5, -1), decimal_outward(hi, digits + 5, +1)};
}

// ---------------------------------------------------------------------------------------------
NecessaryCheck necessary_condition(const QRatFun& H, const rational& T, const rational& b, const rational& omega) {
  using R = mp50;
  if (omega <= 0) throw InputError("necessary_condition: omega must be > 0 (r(jw) has a pole at w = 0)");
  R th = to_real<R>(omega * T);
  R zr = cos(th), zi = sin(th);
  auto eval = [&](const QPoly& p, R& re, R& im) {
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

}  // namespace hapstab::passivity
