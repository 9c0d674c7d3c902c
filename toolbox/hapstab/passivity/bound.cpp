// The passivity bound b* of paper 001, (45) and (54) (bound.hpp): the assumptions of (45), the
// dispatcher over the methods, and the necessary condition (14), (15) of Sec. III. The methods
// live beside it (bound_detail.hpp lists them): objective.cpp, certified.cpp,
// fractional_delay.cpp, fast.cpp, grid.cpp.
#include "hapstab/passivity/bound.hpp"

#include <algorithm>
#include <cmath>
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
  const long degree = std::max<long>(p.H.num().degree(), long(p.H.den().degree()) + p.delay);
  if (degree > limits::model_degree)
    throw InputError("the objective of (45) has degree " + std::to_string(degree) +
                     " (max(deg N, deg D + n)), more than the limit of " + std::to_string(limits::model_degree) +
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

Bound bound(const BoundProblem& p, Method m, int digits, long grid_points) {
  if (m == Method::grid) return bound_grid(p, grid_points);
  if (m == Method::fast) {
    check_assumptions(p);
    if (auto r = FastBound::run(p)) {
      Bound out;
      out.status = Status::numeric;
      out.kind = Method::fast;
      out.method = "fast: double-double coefficients, root finding in double, Newton polish";
      const rational v = exact_rational(r->first), e = abs(v) * pow10(-fast_error_digits);
      out.enclose(v - e, v + e);
      out.decimal = to_decimal(v, 16);
      const rational w = exact_rational(r->second);
      out.omega = to_decimal(w, 16);
      out.omega_enclosure = Enclosure<rational>{w, w};
      out.where = "numeric maximiser";
      return out;
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
