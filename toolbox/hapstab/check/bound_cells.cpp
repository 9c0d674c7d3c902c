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
Jet<Ball> objective(const KernelForm& f, const Ball& theta) {
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
  if (f.rho != 0) {  // H's simple pole at z = -1, integer nu: rho K_{nu + 1}(theta) (bound_cells.hpp)
    Ball sm, cm;
    flint::sin_cos(Ball(f.m) * theta, sm, cm);
    r = r + Ball(f.rho) * jet::kernel_K(th, f.m, sm, cm, s1, c1);
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
  if (denominator(nu) == 1 && H.den()(m1) == 0 && H.den().derivative()(m1) != 0) {  // rho/(z + 1) apart
    f.rho = H.num()(m1) / H.den().derivative()(m1);
    f.m = numerator(nu).convert_to<long>() + 1;
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

bool cell_below(const KernelForm& f, const rational& a, const rational& b, const rational& hi) {
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
