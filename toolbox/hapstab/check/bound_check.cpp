// hapstab/check/bound_check.cpp -- see bound_check.hpp.
#include "hapstab/check/bound_check.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "hapstab/check/bound_cells.hpp"
#include "hapstab/check/bound_objective.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"
#if HAPSTAB_FLINT3
#include <flint/acb.h>
#else
#include <acb.h>
#endif

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

// b* = +inf (claim.infinite, status exact): the objective tends to +inf at evidence.pole_c from
// evidence.side (check/bound_objective.hpp, unbounded_above_fails), at an irrational pole the
// interval (pole_lo, pole_hi) isolates, from side (unbounded_inside_fails), or at the band's
// irrational end (end_lo, end_hi] (unbounded_at_end_fails).
Verdict check_infinite(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm,
                       const std::string& status) {
  if (status != "exact") throw InputError("claim.status: b* = +inf is claimed \"exact\"");
  if (evidence.contains("end_lo") || evidence.contains("end_hi")) {  // the pole at the band's irrational end
    if (evidence.contains("pole_c") || evidence.contains("side")) throw InputError("evidence: end_lo/end_hi beside pole_c/side (one pole)");
    const rational s = detail::exact_field(evidence, "end_lo", "evidence"), b = detail::exact_field(evidence, "end_hi", "evidence");
    const detail::ObjectivePolys f = detail::bound_objective(H.H, dm.T, dm.P, dm.q);
    if (auto why = detail::unbounded_at_end_fails(f, s, b, dm.q)) return {false, "b* = +inf not shown: " + *why};
    return {true, "b* = +inf: the objective tends to +inf as c = cos(wT/" + std::to_string(dm.q) + ") -> cos(pi/" +
                      std::to_string(dm.q) + ") from above (wT -> pi; isolated in (" + detail::shortened(s) + ", " +
                      detail::shortened(b) + "])"};
  }
  // the side of the pole the objective is approached from: +1 or -1
  const long side = detail::integer_field(evidence, "side", "evidence", -1, 1);
  if (side == 0) throw InputError("evidence.side: 0 is not +1 or -1 (the side of the pole the objective is approached from)");
  if (evidence.contains("pole_lo") || evidence.contains("pole_hi")) {  // an irrational pole inside the band, isolated
    if (evidence.contains("pole_c")) throw InputError("evidence: pole_lo/pole_hi beside pole_c (one pole)");
    const rational s = detail::exact_field(evidence, "pole_lo", "evidence"), b = detail::exact_field(evidence, "pole_hi", "evidence");
    const detail::ObjectivePolys f = detail::bound_objective(H.H, dm.T, dm.P, dm.q);
    if (auto why = detail::unbounded_inside_fails(f, s, b, side, dm.q)) return {false, "b* = +inf not shown: " + *why};
    return {true, "b* = +inf: the objective tends to +inf as c = cos(wT/" + std::to_string(dm.q) + ") -> its pole isolated in (" +
                      detail::shortened(s) + ", " + detail::shortened(b) + ")" + (side > 0 ? " from above" : " from below")};
  }
  const rational c_p = detail::exact_field(evidence, "pole_c", "evidence");
  const detail::ObjectivePolys f = detail::bound_objective(H.H, dm.T, dm.P, dm.q);
  if (auto why = detail::unbounded_above_fails(f, c_p, side, dm.q)) return {false, "b* = +inf not shown: " + *why};
  return {true, "b* = +inf: the objective tends to +inf as c = cos(wT/" + std::to_string(dm.q) + ") -> " +
                    detail::shortened(c_p) + (side > 0 ? " from above" : " from below") + " (a pole of H on the unit circle)"};
}

// b* = +inf at the band's end wT = pi from H's simple pole at z = -1 met by a fractional delay
// (evidence.pole_at_z = "-1"; bound_check.hpp, the local form): H = H~ + rho/(z + 1), rho = N(-1)/D'(-1),
// the objective's pole term T rho sin((nu + 1) theta)/(2 sin theta) -> +inf iff rho sin(nu pi) < 0,
// sign sin(nu pi) = (-1)^floor(nu) for nu = P/q not an integer.
Verdict check_infinite_at_minus_one(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm) {
  if (!evidence.at("pole_at_z").is_string() || evidence.at("pole_at_z").get<std::string>() != "-1")
    throw InputError("evidence.pole_at_z: only \"-1\" (the band's end wT = pi) is a pole this form takes");
  if (dm.q == 1)
    return {false, "b* = +inf not shown: the delay nu = " + std::to_string(dm.P) +
                       " is a whole number of samples, so sin(nu pi) = 0 and the pole term stays finite at wT = pi"};
  const P& N = H.num();
  const P& D = H.den();
  const rational m1(-1);
  if (D(m1) != 0) return {false, "b* = +inf not shown: z = -1 is not a pole of H (D(-1) != 0)"};
  const rational dD = D.derivative()(m1);
  if (dD == 0) return {false, "b* = +inf not shown: the pole of H at z = -1 is not simple (D'(-1) = 0)"};
  const rational rho = N(m1) / dD;  // N(-1) != 0: H is read in lowest terms
  if (rho == 0) return {false, "b* = +inf not shown: N(-1) = 0 (no pole at z = -1)"};
  const long floor_nu = dm.P / dm.q;  // P >= 0
  const int sin_sign = floor_nu % 2 == 0 ? 1 : -1;
  if ((rho > 0 ? 1 : -1) * sin_sign > 0)
    return {false, "b* = +inf not shown: rho sin(nu pi) > 0 (rho = " + detail::shortened(rho) + ", nu = " + std::to_string(dm.P) + "/" +
                       std::to_string(dm.q) + "): the objective tends to -inf as wT -> pi"};
  return {true, "b* = +inf: H's simple pole at z = -1 (rho = N(-1)/D'(-1) = " + detail::shortened(rho) +
                    ") gives the objective the term T rho sin((nu + 1) wT)/(2 sin wT), and rho sin(nu pi) < 0 (nu = " +
                    std::to_string(dm.P) + "/" + std::to_string(dm.q) + "): it tends to +inf as wT -> pi"};
}

// A complex ball, freed on scope exit (check_infinite_on_circle's arithmetic).
struct ComplexBall {
  acb_t v;
  ComplexBall() { acb_init(v); }
  ~ComplexBall() { acb_clear(v); }
  ComplexBall(const ComplexBall&) = delete;
  ComplexBall& operator=(const ComplexBall&) = delete;
};

// p at the complex ball z (rational coefficients, Horner).
void horner(acb_t out, const P& p, const acb_t z, long prec) {
  arb_t a;
  arb_init(a);
  acb_zero(out);
  for (int k = p.degree(); k >= 0; --k) {
    acb_mul(out, out, z, prec);
    flint::set(a, p.coeff(k), prec);
    acb_add_arb(out, out, a, prec);
  }
  arb_clear(a);
}

// b* = +inf at a simple pole z0 = e^{j theta0} of H inside the band (evidence.pole_on_circle = {q, c_lo,
// c_hi}; bound_check.hpp, the circle form). The pole: q changes sign on [c_lo, c_hi] inside (-1, 1), or
// vanishes at c_lo = c_hi, so it has a root c0 there, and Z(z) = z^m q((z + 1/z)/2), expanded by the binomial theorem, divides D exactly:
// Z(z0) = z0^m q(c0) = 0 at z0 = c0 + j sqrt(1 - c0^2) (|z0| = 1, so (z0 + 1/z0)/2 = Re z0 = c0), so D(z0) = 0.
// The divergence: D'(z0) != 0 (simple) and Im(c) != 0 for c = T R e^{-j nu theta0}/((1 - z0) z0), R =
// N(z0)/D'(z0), both in balls over all of [c_lo, c_hi]; then f = Im(c)/(theta - theta0) + O(1) -> +inf on one
// side of theta0 in (0, pi).
Verdict check_infinite_on_circle(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm) {
  const nlohmann::json& e = evidence.at("pole_on_circle");
  if (!e.is_object()) throw InputError("evidence.pole_on_circle: must be an object {q, c_lo, c_hi}");
  detail::only_fields(e, {"q", "c_lo", "c_hi"}, "evidence.pole_on_circle");
  if (!e.contains("q") || !e.at("q").is_array() || e.at("q").size() < 2 || e.at("q").size() > 1001)
    throw InputError("evidence.pole_on_circle.q: must be an array of 2 to 1001 \"p/q\" strings (ascending powers of c)");
  std::vector<rational> qc;
  for (size_t i = 0; i < e.at("q").size(); ++i)
    qc.push_back(detail::exact_string(e.at("q")[i], "evidence.pole_on_circle.q[" + std::to_string(i) + "]"));
  const P q(qc);
  if (q.degree() < 1) throw InputError("evidence.pole_on_circle.q: a constant has no root");
  const rational lo = detail::exact_field(e, "c_lo", "evidence.pole_on_circle"), hi = detail::exact_field(e, "c_hi", "evidence.pole_on_circle");
  const std::string fails = "b* = +inf not shown: ";
  if (!(rational(-1) < lo && lo <= hi && hi < rational(1)))
    return {false, fails + "[c_lo, c_hi] is not an interval inside (-1, 1) (the band's inside, 0 < wT < pi)"};
  if (lo == hi ? q(lo) != 0 : q(lo) * q(hi) >= 0)
    return {false, fails + "q does not change sign on [c_lo, c_hi], nor vanish at c_lo = c_hi (no root of it shown there)"};
  const int m = q.degree();
  std::vector<rational> z(static_cast<size_t>(2 * m + 1), rational(0));
  for (int k = 0; k <= m; ++k) {  // z^m ((z + 1/z)/2)^k = 2^-k sum_i C(k, i) z^(m + k - 2i)
    rational binom(1);
    for (int i = 0; i <= k; ++i) {
      z[static_cast<size_t>(m + k - 2 * i)] += q.coeff(k) * binom / rational(integer(1) << k);
      binom = binom * rational(k - i) / rational(i + 1);
    }
  }
  if (!divmod(H.den(), P(z)).second.is_zero())
    return {false, fails + "z^m q((z + 1/z)/2) does not divide H's denominator (no pole of H shown on the circle there)"};
  const rational nu = rational(dm.n) + dm.td / dm.T;
  const long prec = 256;
  arb_t c0, x, s0, theta;
  arb_init(c0), arb_init(x), arb_init(s0), arb_init(theta);
  flint::set(c0, lo, prec);
  flint::set(x, hi, prec);
  arb_union(c0, c0, x, prec);
  arb_mul(s0, c0, c0, prec);
  arb_neg(s0, s0);
  arb_add_ui(s0, s0, 1, prec);
  arb_sqrt(s0, s0, prec);
  arb_acos(theta, c0, prec);
  ComplexBall z0, num, slope, w, k;
  acb_set_arb_arb(z0.v, c0, s0);
  horner(num.v, H.num(), z0.v, prec);
  horner(slope.v, H.den().derivative(), z0.v, prec);
  const bool simple = !acb_contains_zero(slope.v);
  flint::set(x, nu, prec);
  arb_mul(x, x, theta, prec);
  acb_set_arb(k.v, x);
  acb_mul_onei(k.v, k.v);
  acb_neg(k.v, k.v);
  acb_exp(k.v, k.v, prec);  // e^{-j nu theta0}
  acb_mul(k.v, k.v, num.v, prec);
  acb_div(k.v, k.v, slope.v, prec);
  acb_one(w.v);
  acb_sub(w.v, w.v, z0.v, prec);
  acb_mul(w.v, w.v, z0.v, prec);
  acb_div(k.v, k.v, w.v, prec);
  flint::set(x, dm.T, prec);
  acb_mul_arb(k.v, k.v, x, prec);
  const int sign = arb_is_positive(acb_imagref(k.v)) ? 1 : arb_is_negative(acb_imagref(k.v)) ? -1 : 0;
  arb_clear(c0), arb_clear(x), arb_clear(s0), arb_clear(theta);
  if (!simple) return {false, fails + "D'(z0) may be 0 (the pole is not shown simple)"};
  if (sign == 0) return {false, fails + "Im(c) of the pole's term is not shown nonzero (c = T R e^{-j nu theta0}/((1 - z0) z0))"};
  return {true, "b* = +inf: H's simple pole z0 = e^{j theta0}, cos(theta0) in [" + detail::shortened(lo) + ", " +
                    detail::shortened(hi) + "] a root of q, z^m q((z + 1/z)/2) dividing D; f = Im(c)/(theta - theta0) + O(1) with Im(c) " +
                    (sign > 0 ? "> 0" : "< 0") + ": +inf as theta -> theta0 from " + (sign > 0 ? "above" : "below")};
}

// An uncancelled pole of H at z = 1 (an integrator; H is read in lowest terms, so N(1) != 0): `bound`
// defines b* = +inf there whatever the residue's sign (passivity/certified.cpp, integrator_pole, and
// docs/commands.md: for rho > 0 the objective -> +inf at w = 0; for rho < 0 (45) alone is finite but its
// sufficiency needs H stable, and a passive spring operator k_o/s makes the low-frequency loop
// m s^3 + b s^2 + k_o s + rho/T, unstable for every b). Before stop 88 both checkers read (45) alone and
// verified a finite b* (and K_max = +inf) that `bound` says is +inf.
bool has_integrator(const TransferFunction& H) { return H.den()(rational(1)) == 0; }

// b* = +inf (claim.infinite, status exact) by evidence.integrator = true: H's simple pole at z = 1.
Verdict check_integrator(const nlohmann::json& evidence, const TransferFunction& H, const std::string& status) {
  if (status != "exact") throw InputError("claim.status: b* = +inf is claimed \"exact\"");
  if (!evidence.at("integrator").is_boolean() || !evidence.at("integrator").get<bool>())
    throw InputError("evidence.integrator: must be true (H's uncancelled pole at z = 1)");
  if (!has_integrator(H)) return {false, "b* = +inf not shown: z = 1 is not a pole of H (D(1) != 0)"};
  const rational dD = H.den().derivative()(rational(1));
  if (dD == 0) return {false, "b* = +inf not shown: the pole of H at z = 1 is not simple (`bound` refuses a repeated pole on the circle)"};
  return {true, "b* = +inf: H has a simple uncancelled pole at z = 1 (an integrator, residue N(1)/D'(1) = " +
                    detail::shortened(H.num()(rational(1)) / dD) + "): no finite b makes the loop passive (docs/commands.md)"};
}

// b* in [lo, hi] by cells (check/bound_cells.hpp): evidence.cells the cells' right ends, evidence.witness_theta.
Verdict check_cells(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm, const rational& lo,
                    const rational& hi) {
  const std::vector<rational> ends = detail::read_cells(evidence, "cells");
  const rational theta0 = detail::exact_field(evidence, "witness_theta", "evidence");
  const rational nu = rational(dm.n) + dm.td / dm.T;
  const detail::KernelForm f = detail::kernel_form(H.H, dm.T, nu, dm.eta);
  if (auto why = detail::cells_below_fail(f, ends, hi)) return {false, "b* <= " + detail::decimal(hi) + " not shown: " + *why};
  if (auto why = detail::witness_fails(f, theta0, lo)) return {false, "b* >= " + detail::decimal(lo) + " not shown: " + *why};
  return {true, "b* in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "] (upper bound: f < hi on " + std::to_string(ends.size()) +
                    " cells of [0, pi], each by the mean value theorem in balls, the delay never expanded; lower bound: f at theta0 = " +
                    detail::shortened(theta0) + ")"};
}

}  // namespace

Verdict check_bound_infinite(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm,
                             const std::string& status, const std::string& where) {
  if (evidence.contains("pole_at_z")) {  // the local form: nothing expanded
    detail::only_fields(evidence, {"pole_at_z"}, where);
    if (status != "exact") throw InputError("claim.status: b* = +inf at z = -1 is claimed \"exact\"");
    return check_infinite_at_minus_one(evidence, H, dm);
  }
  if (evidence.contains("pole_on_circle")) {  // the circle form: nothing expanded
    detail::only_fields(evidence, {"pole_on_circle"}, where);
    if (status != "certified") throw InputError("claim.status: b* = +inf at a pole on the circle is claimed \"certified\" (shown in balls)");
    return check_infinite_on_circle(evidence, H, dm);
  }
  detail::only_fields(evidence, {"pole_c", "side", "end_lo", "end_hi", "pole_lo", "pole_hi"}, where);
  detail::check_size(dm, H.num().degree(), H.den().degree(), bound_max_size);  // these forms expand the delay
  return check_infinite(evidence, H, dm, status);
}

Verdict check_bound(const nlohmann::json& cert) {
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);

  // ---- the model as written (a field this checker does not read would be a model it does not check)
  detail::only_fields(model, {"H", "set", "num", "den", "T", "delay", "frac_delay", "eta"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi", "infinite"}, "claim");
  const bool infinite = claim.contains("infinite");  // its value is read by claim_range below
  const bool cells = !infinite && evidence.contains("cells");  // the long-delay form (check/bound_cells.hpp)
  const bool integrator = infinite && evidence.contains("integrator");  // H's pole at z = 1: nothing expanded
  if (integrator) detail::only_fields(evidence, {"integrator"}, "evidence");
  else if (cells) detail::only_fields(evidence, {"cells", "witness_theta"}, "evidence");
  else if (!infinite) detail::only_fields(evidence, {"witness_c", "domain_c_lo"}, "evidence");
  const detail::DelayModel dm = detail::read_delay_model(model);
  const rational& eta = dm.eta;
  const TransferFunction H = detail::model_tf(model, dm.T, HiddenPoles::allow_marginal);  // as `bound` reads it
  // the checker expands the delay: its polynomials in c have degree about q (deg H + 1) + P
  // (b* = +inf: check_bound_infinite checks the size for the forms that expand it)
  if (!cells && !infinite) detail::check_size(dm, H.num().degree(), H.den().degree(), bound_max_size);

  // ---- the claim (the printed decimals, when given, are the numbers claimed)
  const detail::ClaimRange range = detail::claim_range(claim, /*may_be_infinite=*/true);
  if (range.refuted) return {false, *range.refuted};
  if (infinite && !range.infinite) throw InputError("claim.infinite: false (a finite claim has no such field)");
  if (range.infinite && integrator) return check_integrator(evidence, H, range.status);
  if (!range.infinite && has_integrator(H))
    return {false, "b* finite fails: H has an uncancelled pole at z = 1 (an integrator), where b* = +inf whatever the residue's sign "
                   "(docs/commands.md)"};
  if (range.infinite) return check_bound_infinite(evidence, H, dm, range.status, "evidence");
  const std::string& status = range.status;
  const rational &lo = range.lo, &hi = range.hi;
  if (cells) return check_cells(evidence, H, dm, lo, hi);

  // ---- f(c) = A/B + eta in c = cos(wT/q), the checker's own derivation (check/bound_objective.hpp)
  const detail::ObjectivePolys f = detail::bound_objective(H.H, dm.T, dm.P, dm.q);
  // the band c in [cos(pi/q), 1] ([-1, 1] for an integer delay) lies in [c_lo, 1]
  const rational c_lo = evidence.contains("domain_c_lo") ? exact_field(evidence, "domain_c_lo", "evidence") : rational(-1);
  const rational c0 = exact_field(evidence, "witness_c", "evidence");

  // ---- upper: (hi - eta) B - A >= 0 on [c_lo, 1]
  std::string how;
  if (auto why = detail::upper_bound_fails(f, hi - eta, "(hi - eta)", c_lo, dm.q, how))
    return {false, "b* <= " + hi.str() + " (" + detail::decimal(hi) + ") fails: " + *why};

  // ---- lower: the witness
  if (auto why = detail::lower_bound_fails(f, lo - eta, c0, dm.q))
    return {false, "b* >= " + lo.str() + " (" + detail::decimal(lo) + ") not shown: " + *why};

  std::string what = status == "exact" ? "b* = " + lo.str() : "b* in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]";
  return {true, what + " (upper bound: " + how + "; lower bound: the objective at c0 = " + detail::shortened(c0) + ")"};
}

}  // namespace hapstab::check
