// hapstab/check/bound_cells.cpp -- see bound_cells.hpp.
#include "hapstab/check/bound_cells.hpp"

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/jet.hpp"

namespace hapstab::check::detail {

namespace {

using flint::Ball;
using jet::Jet;
using P = Polynomial<rational>;

std::vector<Ball> balls(const P& p) {
  std::vector<Ball> v;
  for (int k = 0; k <= p.degree(); ++k) v.push_back(Ball(p.coeff(k)));
  if (v.empty()) v.push_back(Ball(0L));
  return v;
}

// f, f', f'' over the ball theta (bound_cells.hpp): B, A, E in c = cos theta by Horner on jets.
// singular = false leaves out the part -(T/2)(rho/2) sin(nu theta) tan(theta/2) of a pole at z = -1
// met by a fractional delay (unbounded at pi: tail_below).
Jet<Ball> objective(const KernelForm& f, const Ball& theta, bool singular = true) {
  Ball sh, ch, snu, cnu;
  const Ball nu(f.nu);
  flint::sin_cos(theta * Ball(rational(1, 2)), sh, ch);
  flint::sin_cos(nu * theta, snu, cnu);
  const Ball s1 = Ball(2L) * (sh * ch), c1 = Ball(1L) - Ball(2L) * (sh * sh);
  const Jet<Ball> th = jet::variable(theta);
  const Jet<Ball> c{c1, Ball(0L) - s1, Ball(0L) - c1};
  const Jet<Ball> b = jet::horner(balls(f.B), c);
  const Jet<Ball> cos_nu{cnu, Ball(0L) - nu * snu, Ball(0L) - nu * nu * cnu};
  const Jet<Ball> s_nu = jet::kernel_S(th, nu, snu, cnu, sh, ch);
  const Jet<Ball> num = jet::horner(balls(f.A), c) * cos_nu + jet::horner(balls(f.E), c) * s_nu;
  Jet<Ball> r = num / b;
  if (f.rho != 0 && f.m > 0) {  // H's simple pole at z = -1, integer nu: rho K_{nu + 1}(theta) (bound_cells.hpp)
    Ball sm, cm;
    flint::sin_cos(Ball(f.m) * theta, sm, cm);
    r = r + Ball(f.rho) * jet::kernel_K(th, f.m, sm, cm, s1, c1);
  } else if (f.rho != 0) {  // fractional nu: rho [cos(nu theta) + S_nu/2 - sin(nu theta) tan(theta/2)/2] (bound_cells.hpp)
    const Ball rho(f.rho), half(rational(1, 2));
    r = r + rho * cos_nu + (rho * half) * s_nu;
    if (singular) {
      const Jet<Ball> sin_nu{snu, nu * cnu, Ball(0L) - nu * nu * snu};
      const Jet<Ball> sin_half{sh, half * ch, Ball(0L) - sh * Ball(rational(1, 4))};
      const Jet<Ball> cos_half{ch, Ball(0L) - half * sh, Ball(0L) - ch * Ball(rational(1, 4))};
      r = r - (rho * half) * (sin_nu * (sin_half / cos_half));
    }
  }
  Jet<Ball> out = Ball(f.T / 2) * r;
  out.v = out.v + Ball(f.eta);
  return out;
}

}  // namespace

KernelForm kernel_form(const RationalFunction<rational>& H0, const rational& T, const rational& nu, const rational& eta) {
  using namespace circle;
  KernelForm f;
  RationalFunction<rational> H = H0;
  const rational m1(-1);
  if (H.den()(m1) == 0 && H.den().derivative()(m1) != 0) {  // rho/(z + 1) apart (m = 0: nu not whole)
    f.rho = H.num()(m1) / H.den().derivative()(m1);
    if (denominator(nu) == 1) f.m = numerator(nu).convert_to<long>() + 1;
    H = H - RationalFunction<rational>(P(f.rho), P{rational(1), rational(1)});
  }
  const OnCircle n = at_circle(H.num()), d = at_circle(H.den());
  const OnCircle xy = mul(n, OnCircle{d.a, P() - d.b});  // N conj(D) = X + j s Y
  const P one_plus_c{rational(1), rational(1)}, one_minus_c{rational(1), rational(-1)};
  f.A = xy.a - one_plus_c * xy.b;
  f.E = xy.a + one_minus_c * xy.b;
  f.B = d.a * d.a + one_minus_c2() * d.b * d.b;
  f.T = T;
  f.nu = nu;
  f.eta = eta;
  return f;
}

namespace {
// The cell [a, b] around pi of a pole at z = -1 met by a fractional delay (bound_cells.hpp): on [a, pi),
// f = g - (T/4) rho sin(nu theta) tan(theta/2), g the rest (bounded): g <= g(a) + sup(g' [a, pi]) (pi - a),
// and where rho sin(nu theta) > 0 on [a, pi], tan(theta/2) >= tan(a/2) > 0 (a > 0): f < hi when
// g(a) + g'([a, pi]) [0, pi - a] - (T/4) inf(rho sin(nu theta)) tan(a/2) < hi. f at pi itself is -inf.
bool tail_below(const KernelForm& f, const rational& a, const rational& hi) {
  if (!(a > 0)) return false;
  const Ball X = flint::hull(Ball(a), Ball::pi()), width = Ball::pi() - Ball(a);
  const Ball g = objective(f, Ball(a), false).v + objective(f, X, false).d * flint::hull(Ball(0L), width);
  Ball snu, cnu, sa, ca;
  flint::sin_cos(Ball(f.nu) * X, snu, cnu);
  flint::sin_cos(Ball(a / 2), sa, ca);
  const Ball weight = (Ball(f.rho) * snu).lower_end(), t = (sa / ca).lower_end();
  if (!weight.positive() || !t.positive()) return false;
  const Ball bound = g - Ball(f.T / 4) * weight * t;
  return bound.finite() && bound.below(Ball(hi));
}
}  // namespace

bool cell_below(const KernelForm& f, const rational& a, const rational& b, const rational& hi) {
  if (f.rho != 0 && f.m == 0 && !beyond_pi(a) && !Ball(b).below(Ball::pi())) {  // the cell reaches pi: the pole's
    return Ball(a).below(Ball::pi()) && beyond_pi(b) && tail_below(f, a, hi);  // -inf side, or not shown
  }
  const rational m = (a + b) / 2, r = (b - a) / 2;
  const Ball at_m = objective(f, Ball(m)).v;
  const Jet<Ball> over = objective(f, Ball::hull(a, b));
  const Ball bound = at_m + over.d * Ball::hull(-r, r);
  return bound.finite() && bound.below(Ball(hi));
}

bool point_above(const KernelForm& f, const rational& theta0, const rational& lo) {
  const Ball v = objective(f, Ball(theta0)).v;
  return v.finite() && Ball(lo).below(v);
}

PointJet objective_at(const KernelForm& f, const rational& theta) {
  const Jet<Ball> j = objective(f, Ball(theta));
  return {j.v.to_double(), j.d.to_double(), j.dd.to_double()};
}

bool beyond_pi(const rational& theta) { return Ball::pi().below(Ball(theta)); }

std::optional<std::string> cells_below_fail(const KernelForm& f, const std::vector<rational>& ends, const rational& hi) {
  if (ends.empty() || !beyond_pi(ends.back())) return "the cells end at or below pi (they must cover [0, pi])";
  rational a(0);
  for (size_t i = 0; i < ends.size(); ++i) {
    if (!(a < ends[i])) return "cell " + std::to_string(i + 1) + "'s end " + ends[i].str() + " is not above the one before";
    if (!cell_below(f, a, ends[i], hi))
      return "f < " + decimal(hi) + " not shown on cell " + std::to_string(i + 1) + " [" + decimal(a) + ", " + decimal(ends[i]) + "]";
    a = ends[i];
  }
  return std::nullopt;
}

std::optional<std::string> witness_fails(const KernelForm& f, const rational& theta0, const rational& lo) {
  if (theta0 < 0 || !Ball(theta0).below(Ball::pi())) return "the witness theta0 = " + theta0.str() + " is not in [0, pi]";
  if (!point_above(f, theta0, lo)) return "f(theta0) > " + decimal(lo) + " not shown at theta0 = " + decimal(theta0);
  return std::nullopt;
}

std::vector<rational> read_cells(const nlohmann::json& evidence, const std::string& key) {
  const std::string where = "evidence." + key;
  if (!evidence.contains(key) || !evidence.at(key).is_array() || evidence.at(key).empty())
    throw InputError(where + ": must be a non-empty array of \"p/q\" strings");
  const nlohmann::json& c = evidence.at(key);
  if (c.size() > max_bound_cells)
    throw InputError(where + ": " + std::to_string(c.size()) + " cells, beyond the checker's limit of " + std::to_string(max_bound_cells));
  std::vector<rational> ends;
  for (size_t i = 0; i < c.size(); ++i) ends.push_back(exact_string(c[i], where + "[" + std::to_string(i) + "]"));
  return ends;
}

}  // namespace hapstab::check::detail
