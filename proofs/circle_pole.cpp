// proofs/circle_pole.cpp -- b* = +inf at a simple pole of H on the unit circle inside the band (paper 001,
// (45)/(54)), decided at the pole for delays beyond the exact path's size (passivity/circle_pole.cpp).
// Near z0 = e^{j theta0}, 0 < theta0 < pi: H = R/(z - z0) + O(1), R = N(z0)/D'(z0), and e^{j theta} - z0 =
// j z0 (theta - theta0)(1 + O(theta - theta0)), so
//   f(theta) = Re{T H(e^{j theta}) e^{-j nu theta}/(1 - e^{j theta})} = Im(c)/(theta - theta0) + O(1),
//   c = T R e^{-j nu theta0}/((1 - z0) z0),
// and f -> +inf on one side of theta0 when Im(c) != 0.
//   001.eq45.circle_pole  where `bound` prints +inf by that path, the objective AS WRITTEN (complex
//                         Horner in 100-digit MPFR on the circle, none of the path's forms) times
//                         theta - theta0 (at +-1e-16, +-1e-20) is one nonzero constant on both sides of its theta0
//                         (so f -> +inf on one side); where Im(c) = 0 (H = (z - 1)/(z^2 + 1) at an even
//                         delay: Im(c) = -(T/2) sin(nu pi/2)) that product tends to 0 and `bound` refuses
#include <sstream>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/lti/parse.hpp"
#include "proofs/certify.hpp"
#include "proofs/proof.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::passivity;
using hapstab::proofs::Instances;
using R = mp100;

struct Cx {
  R re, im;
};
Cx operator*(const Cx& a, const Cx& b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
Cx operator/(const Cx& a, const Cx& b) {
  const R d = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}

Cx horner(const Polynomial<rational>& p, const Cx& z) {
  Cx v{R(0), R(0)};
  for (int k = p.degree(); k >= 0; --k) {
    v = v * z;
    v.re += R(p.coeff(k));
  }
  return v;
}

// (45)/(54) as written at theta (100 digits): Re{T H(e^{j theta}) e^{-j nu theta}/(1 - e^{j theta})}
R objective(const BoundProblem& p, const R& theta) {
  const rational nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  const Cx z{cos(theta), sin(theta)};
  const Cx delay{cos(R(nu) * theta), -sin(R(nu) * theta)};
  const Cx g = horner(p.H.num(), z) / horner(p.H.den(), z) * delay / Cx{1 - z.re, -z.im};
  return R(p.T) * g.re;
}

HAPSTAB_PROOF(circle_pole, "001", "b* = +inf at a simple pole on the circle inside the band, at any delay") {
  const rational T(1, 1000);  // paper 001's period, as every 001 certificate's (Im(c) scales with T, its sign does not)
  struct Case {
    const char* H;
    rational T;
    int n;
    std::optional<rational> td;
    bool vanishes;
  };
  const std::vector<Case> cases = {
      {"1/(z^2+1)", T, 600, {}, false},
      {"1/(z^2+1)", T, 1201, rational(1, 3000), false},
      {"(z-1)/(z^2+1)", T, 601, {}, false},
      {"(z-1)/(z^2+1)", T, 400, rational(1, 7000), false},
      {"1/(z^4+1)", T, 900, {}, false},
      {"1/(z^4+1)", T, 2500, rational(1, 2000), false},
      {"3/(z^2-z+1) + 1/(z-1/2)", T, 333, {}, false},
      {"(z+2)/(z^2+z/3+1)", T, 5000, {}, false},
      {"(z^2-1/5)/(z^4+z^3+z^2+z+1)", T, 777, rational(3, 10000), false},
      {"(2*z+1)/((z^2+1)*(z^2-z+1))", T, 1500, {}, false},
      {"(z-1)/(z^2+1)", T, 600, {}, true},
      {"(z+1)/(z^2+1)", T, 601, {}, true},
  };
  bool ok = true;
  Instances infinite{"+inf at the pole (the product tends to a nonzero constant)", 10}, vanishing{"Im(c) = 0: refused", 2};
  std::ostringstream worst;
  R spread_max(0);
  for (const Case& k : cases) {
    ParseOptions o;
    o.variable = 'z';
    o.T = k.T;
    BoundProblem p;
    p.H = parse_tf(k.H, o).H;
    p.T = k.T;
    p.delay = k.n;
    p.frac_delay = k.td;
    if (k.vanishes) {
      bool refused = false;
      try {
        bound_certified(p, 20);
      } catch (const InputError& e) {
        refused = std::string(e.what()).find("not shown nonzero") != std::string::npos;
      }
      vanishing.count(refused);
      ok = ok && refused;
      if (!refused) worst << " " << k.H << " n = " << k.n << ": not refused;";
      continue;
    }
    const Bound b = bound_certified(p, 20);
    const bool at_pole = b.infinite && b.status == Status::certified && b.path == BoundPath::at_pole && b.omega_enclosure;
    if (!at_pole) {
      ok = false;
      worst << " " << k.H << " n = " << k.n << ": not +inf at the pole;";
      infinite.count(false);
      continue;
    }
    // theta0 to ~1e-28 (the path's enclosure, cos(theta0) to 2^-96); d well above that: s(d) = f(theta0 + d) d =
    // Im(c) (1 + O(d) + O(1e-28/d))
    const R theta0 = R((b.omega_enclosure->lo + b.omega_enclosure->hi) / 2 * p.T);
    std::vector<R> s;
    for (const char* d : {"1e-16", "-1e-16", "1e-20", "-1e-20"}) s.push_back(objective(p, theta0 + R(d)) * R(d));
    const R scale = abs(s[2]);
    R spread(0);
    for (const R& v : s) spread = std::max(spread, R(abs(v - s[2])));
    spread = spread / scale;
    spread_max = std::max(spread_max, spread);
    const bool this_ok = scale > R(1e-12) && spread < R(1e-6);
    infinite.count(this_ok);
    ok = ok && this_ok;
    if (!this_ok) worst << " " << k.H << " n = " << k.n << ": f d = " << to_decimal(exact_rational(s[2].convert_to<double>()), 6) << ";";
    proofs::BoundInstance inst{k.H, k.T};
    inst.delay = k.n;
    inst.frac_delay = k.td;
    proofs::CertificateRequest r;
    r.args = proofs::bound_args(inst);
    r.flags = {{"infinite", true}};
    check.certify("001.eq45.circle_pole", r);
  }
  check.claim("001.eq45.circle_pole", "(45), (54)",
              "a simple pole z0 = e^{j theta0} of H inside the band gives f = Im(c)/(theta - theta0) + O(1), c = T R e^{-j nu theta0}/((1 - z0) z0): "
              "where `bound` prints +inf [certified] by the path at_pole (delays 333-5000 beyond the exact path's size; poles at "
              "pi/2, pi/3, pi/4, 3pi/4, 2pi/5, 4pi/5 and an irrational angle; fractional delays), f (theta - theta0) tends to one "
              "nonzero constant from both sides; where Im(c) = 0 it is refused by name",
              Status::certified, ok,
              "f as written in 100-digit MPFR at theta0 +- 1e-16 and +- 1e-20: the four products f d agree to " +
                  to_decimal(exact_rational(spread_max.convert_to<double>()), 2) +
                  " relative (tolerance 1e-6: O(d) and theta0's enclosure, ~1e-28, over d)" +
                  worst.str(),
              {infinite, vanishing});
}

}  // namespace
