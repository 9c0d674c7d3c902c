// The grid method for the passivity bound (45): N equally spaced w in [0, pi/T], the objective
// evaluated on the unit circle in double (comparison only; status numeric).
#include <cmath>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound_detail.hpp"

namespace hapstab::passivity {

Bound bound_grid(const BoundProblem& p, long N) {
  check_assumptions(p);
  if (N < 2) throw InputError("grid: N must be >= 2");
  if (auto inf = detail::integrator_pole(p)) return *inf;
  Bound out;
  out.status = Status::numeric;
  out.kind = Method::grid;
  out.method = "grid (" + std::to_string(N) + " points, double, evaluated on the unit circle)";
  const double T = to_real<double>(p.T);
  const double pi = 3.14159265358979323846;
  double best = detail::objective_at_zero(p), bw = 0;
  const detail::CircleObjective<double> f(p);
  for (long k = 1; k < N; ++k) {
    const double th = pi * static_cast<double>(k) / static_cast<double>(N - 1);
    const double v = f(th);
    if (v > best) best = v, bw = th / T;
  }
  if (std::isinf(best) && best > 0) { out.infinite = true; out.decimal = "inf"; return out; }
  const rational max = exact_rational(best), w = exact_rational(bw);
  out.enclose(max, max);
  out.decimal = to_decimal(max, 17);
  out.omega = to_decimal(w, 17);
  out.omega_enclosure = Enclosure<rational>{w, w};
  out.where = "grid point";
  return out;
}

}  // namespace hapstab::passivity
