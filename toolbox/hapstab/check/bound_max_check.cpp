// hapstab/check/bound_max_check.cpp -- see bound_max_check.hpp.
#include "hapstab/check/bound_max_check.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/affine.hpp"
#include "hapstab/check/bound_cells.hpp"
#include "hapstab/check/bound_check.hpp"
#include "hapstab/check/bound_objective.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using RF = RationalFunction<rational>;

// b*(K) = +inf for every K > hi (evidence.jump_at_z = "-1": b* jumps at the sup). H0 and H1 each have at
// z = -1 a simple pole or none, residues rho0, rho1 (0 for none), so H0 + K H1 = G(K) + rho(K)/(z + 1) with
// G(K) regular at -1 and rho(K) = rho0 + K rho1; by bound_check.cpp's local form the objective's pole term
// T rho(K) sin((nu + 1) theta)/(2 sin theta) tends to +inf as theta -> pi iff rho(K) sin(nu pi) < 0, nu not
// whole, sin(nu pi) of sign s = (-1)^floor(nu). rho1 s < 0 and rho(hi) s <= 0 give rho(K) s < 0 for K > hi.
// The reason it fails, or nullopt (then `how` says what was shown).
std::optional<std::string> jump_fails(const nlohmann::json& evidence, const detail::Affine& h, const detail::DelayModel& dm,
                                      const rational& hi, const std::string& K, std::string& how) {
  if (!evidence.at("jump_at_z").is_string() || evidence.at("jump_at_z").get<std::string>() != "-1")
    throw InputError("evidence.jump_at_z: only \"-1\" (the band's end wT = pi) is a pole this form takes");
  if (dm.q == 1)
    return "the delay nu = " + std::to_string(dm.P) + " is a whole number of samples: sin(nu pi) = 0, the pole term stays finite at wT = pi";
  const rational m1(-1);
  rational rho[2];
  const RF* parts[2] = {&h.H0, &h.H1};
  for (int k = 0; k < 2; ++k) {
    const auto& D = parts[k]->den();
    if (D(m1) != 0) continue;
    const rational d1 = D.derivative()(m1);
    if (d1 == 0) return std::string(k == 0 ? "H0" : "H1") + " has a repeated pole at z = -1";
    rho[k] = parts[k]->num()(m1) / d1;
  }
  const int s = (dm.P / dm.q) % 2 == 0 ? 1 : -1;
  if (sgn(rho[1]) * s >= 0)
    return "rho1 sin(nu pi) < 0 fails (rho1 = " + detail::shortened(rho[1]) + ", nu = " + std::to_string(dm.P) + "/" + std::to_string(dm.q) +
           "): the pole term does not tend to +inf for every large " + K;
  if (sgn(rho[0] + hi * rho[1]) * s > 0)
    return "rho(" + K + " = hi) sin(nu pi) <= 0 fails (rho(hi) = " + detail::shortened(rho[0] + hi * rho[1]) +
           "): the objective tends to -inf at wT = pi just above hi";
  how = "b*(" + K + ") = +inf for every " + K + " > " + detail::decimal(hi) + ": the residue at z = -1, rho(" + K + ") = " +
        detail::shortened(rho[0]) + " + " + K + " (" + detail::shortened(rho[1]) + "), has rho(" + K + ") sin(nu pi) < 0 there (nu = " +
        std::to_string(dm.P) + "/" + std::to_string(dm.q) + ")";
  return std::nullopt;
}

// The cells' form (check/bound_cells.hpp), for delays beyond the expanded form: K_max in [lo, hi] with
// lo > 0 by b0_hi < b, cells_at_0 (f at K = 0 below b0) and cells_at_lo (f at K = lo below b); or
// K_max = 0 (claim.value "0"); and b*(hi) >= b by f(witness_theta) > b at K = hi.
Verdict cells_form(const nlohmann::json& evidence, const detail::Affine& h, const detail::DelayModel& dm, const rational& b,
                   const std::string& K, const detail::ClaimRange& range) {
  if (range.infinite) throw InputError("claim.infinite: K_max = +inf has no cells' form (evidence.witness_theta)");
  const rational &lo = range.lo, &hi = range.hi;
  const bool jump = evidence.contains("jump_at_z");  // b* = +inf above hi (jump_fails), in place of witness_theta
  const char* upper = jump ? "jump_at_z" : "witness_theta";
  detail::only_fields(evidence, lo > 0 ? std::initializer_list<const char*>{"b0_hi", "cells_at_0", "cells_at_lo", upper}
                                       : std::initializer_list<const char*>{upper},
                      "evidence");
  const rational nu = rational(dm.n) + dm.td / dm.T;
  auto at = [&](const rational& k) { return detail::kernel_form(h.H0 + RF(k) * h.H1, dm.T, nu, dm.eta); };
  std::vector<std::string> shown;
  if (lo > 0) {
    const rational b0 = detail::exact_field(evidence, "b0_hi", "evidence");
    if (b0 >= b) return {false, "evidence.b0_hi = " + detail::decimal(b0) + " is not < b = " + detail::decimal(b) + ": K_max > 0 not shown"};
    if (auto why = detail::cells_below_fail(at(rational(0)), detail::read_cells(evidence, "cells_at_0"), b0))
      return {false, "b*(" + K + " = 0) < b0_hi not shown: " + *why};
    if (auto why = detail::cells_below_fail(at(lo), detail::read_cells(evidence, "cells_at_lo"), b))
      return {false, K + "_max >= " + detail::decimal(lo) + " fails: b*(" + K + " = lo) < b not shown: " + *why};
    shown.push_back("b*(0) < " + detail::decimal(b0) + " < b and b*(" + K + " = " + detail::decimal(lo) + ") < b by cells");
  }
  if (jump) {
    std::string how;
    if (auto why = jump_fails(evidence, h, dm, hi, K, how)) return {false, K + "_max <= " + detail::decimal(hi) + " not shown: " + *why};
    shown.push_back(how);
  } else {
    const rational theta = detail::exact_field(evidence, "witness_theta", "evidence");
    if (auto why = detail::witness_fails(at(hi), theta, b))
      return {false, K + "_max <= " + detail::decimal(hi) + " not shown: b*(" + K + " = hi) > b: " + *why};
    shown.push_back("b*(" + K + " = " + detail::decimal(hi) + ") > b at theta = " + detail::shortened(theta));
  }
  std::string all;
  for (const auto& s : shown) all += (all.empty() ? "" : "; ") + s;
  return {true, K + "_max " + (range.status == "exact" ? "= " + lo.str() : "in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]") +
                    ": " + all + " (the delay never expanded; b* convex in " + K + ", H affine in " + K + ", degree bound " +
                    std::to_string(h.D) + ")"};
}

// H's uncancelled pole at z = 1 (an integrator: b* = +inf whatever the residue's sign, bound_check.cpp):
// in H0, b*(0) = +inf; in H1 and not H0, b*(K) = +inf for every K > 0 (H0 + K H1 keeps the pole). Either
// way K_max = 0: a claim of more is refuted, and K_max = 0 is verified by evidence.integrator = true
// alone (the pole simple, as `bound` requires). nullopt when neither part has a pole at z = 1.
std::optional<Verdict> integrator_form(const nlohmann::json& evidence, const detail::Affine& h, const std::string& K,
                                       const detail::ClaimRange& range) {
  const rational one(1);
  const bool pole0 = h.H0.den()(one) == 0, pole1 = h.H1.den()(one) == 0;
  if (!pole0 && !pole1) {
    if (evidence.contains("integrator")) return Verdict{false, "evidence.integrator: neither H0 nor H1 has a pole at z = 1"};
    return std::nullopt;
  }
  const RF& part = pole0 ? h.H0 : h.H1;
  const std::string why = pole0 ? "H(" + K + " = 0) has an uncancelled pole at z = 1 (an integrator): b*(0) = +inf"
                                : "the part of H in " + K + " has a pole at z = 1 that H(" + K + " = 0) lacks (an integrator): b*(" + K +
                                      ") = +inf for every " + K + " > 0";
  if (range.infinite || range.lo > 0) return Verdict{false, K + "_max = 0, not the claim: " + why + " (docs/commands.md)"};
  if (!evidence.contains("integrator")) return std::nullopt;  // K_max = 0 by the witness form
  detail::only_fields(evidence, {"integrator"}, "evidence");
  if (!evidence.at("integrator").is_boolean() || !evidence.at("integrator").get<bool>())
    throw InputError("evidence.integrator: must be true (a pole of H at z = 1)");
  if (part.den().derivative()(one) == 0)
    return Verdict{false, K + "_max = 0 not shown: the pole at z = 1 is not simple (`bound` refuses a repeated pole on the circle)"};
  return Verdict{true, K + "_max = 0: " + why + " (docs/commands.md; H affine in " + K + ", degree bound " + std::to_string(h.D) + ")"};
}

// K_max = 0 by b*(0) = +inf (evidence.at_zero_infinite: the evidence of a `bound` certificate that b* = +inf,
// check_bound_infinite's forms, for H0 = H(K = 0), the delay and eta of the model): b*(0) < b fails, so no
// K0 > 0 has b*(K) < b on [0, K0), and K_max = 0 (K0 = 0 qualifies, [0, 0) being empty). The claim's status
// is the form's: "exact", or "certified" for the circle form (shown in balls).
Verdict at_zero_infinite_form(const nlohmann::json& evidence, const detail::Affine& h, const detail::DelayModel& dm,
                              const std::string& K, const detail::ClaimRange& range) {
  detail::only_fields(evidence, {"at_zero_infinite"}, "evidence");
  const nlohmann::json& inner = evidence.at("at_zero_infinite");
  if (!inner.is_object()) throw InputError("evidence.at_zero_infinite: must be an object (a `bound` certificate's evidence of b* = +inf)");
  if (range.infinite || range.lo != 0 || range.hi != 0)
    return {false, K + "_max = 0, not the claim: evidence.at_zero_infinite states b*(" + K + " = 0) = +inf (>= b)"};
  const Verdict v = check_bound_infinite(inner, tf(h.H0.num(), h.H0.den(), dm.T), dm, range.status, "evidence.at_zero_infinite");
  if (!v.verified) return {false, K + "_max = 0 not shown: b*(" + K + " = 0) = +inf fails: " + v.reason};
  return {true, K + "_max = 0: b*(" + K + " = 0) = +inf >= b, " + v.reason + " (H affine in " + K + ", degree bound " + std::to_string(h.D) + ")"};
}

}  // namespace

Verdict check_bound_max(const nlohmann::json& cert) {
  constexpr long max_size = bound_max_size;
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(model, {"H", "set", "name", "T", "delay", "frac_delay", "eta", "damping"}, "model");
  detail::only_fields(claim, {"quantity", "status", "infinite", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  // the long-delay form (cells_form above): its witness, or its cells beside a jump
  const bool cells = evidence.contains("witness_theta") || evidence.contains("cells_at_0");
  const bool jump = evidence.contains("jump_at_z");  // b* = +inf above hi (jump_fails above), in place of witness_c
  const bool at_zero_infinite = evidence.contains("at_zero_infinite");  // K_max = 0 by b*(0) = +inf (at_zero_infinite_form)
  if (!cells && !evidence.contains("integrator") && !at_zero_infinite)
    detail::only_fields(evidence, jump ? std::initializer_list<const char*>{"jump_at_z", "b0_hi", "domain_c_lo"}
                                       : std::initializer_list<const char*>{"witness_c", "b0_hi", "domain_c_lo"},
                        "evidence");

  // ---- the model as written
  if (!model.contains("H") || !model.at("H").is_string()) throw InputError("model.H: missing or not a string (the expression of H(z))");
  if (!model.contains("name") || !model.at("name").is_string()) throw InputError("model.name: missing or not a string (the parameter)");
  const std::string text = model.at("H").get<std::string>(), K = model.at("name").get<std::string>();
  const detail::DelayModel dm = detail::read_delay_model(model);
  const rational b = exact_field(model, "damping", "model");
  if (b <= 0) throw InputError("model.damping: b must be > 0, got " + b.str());
  ParseOptions po;
  po.variable = 'z';
  po.T = dm.T;
  po.parameters = detail::model_parameters(model);
  po.hidden_poles = HiddenPoles::allow_marginal;  // as `bound --max` reads it
  if (po.parameters.count(K)) throw InputError("model.set: gives the parameter model.name = " + K + " a value");
  const detail::Affine h = detail::prove_affine(text, po, K);
  if (!cells && !evidence.contains("integrator") && !at_zero_infinite)
    detail::check_size(dm, std::max(h.H0.num().degree(), h.H1.num().degree()),
                       std::max(h.H0.den().degree(), h.H1.den().degree()), max_size);
  auto at = [&](const rational& k) { return detail::bound_objective(h.H0 + RF(k) * h.H1, dm.T, dm.P, dm.q); };

  // ---- the claim
  const detail::ClaimRange range = detail::claim_range(claim, true);
  if (range.refuted) return {false, *range.refuted};
  const std::string& status = range.status;
  const bool infinite = range.infinite;
  const rational &lo = range.lo, &hi = range.hi;
  if (!infinite && lo < 0) return {false, "claim: lo = " + lo.str() + " < 0 (K_max >= 0 by its definition)"};
  if (jump && infinite) throw InputError("evidence.jump_at_z: K_max = +inf has no upper end");
  if (auto v = integrator_form(evidence, h, K, range)) return *v;
  if (at_zero_infinite) return at_zero_infinite_form(evidence, h, dm, K, range);
  if (cells) return cells_form(evidence, h, dm, b, K, range);
  const rational c_lo = evidence.contains("domain_c_lo") ? exact_field(evidence, "domain_c_lo", "evidence") : rational(-1);
  // checked whenever given, also where no upper bound reads it (K_max = 0): evidence is never ignored
  // (the campaign found a moved domain_c_lo accepted on K_max = 0 certificates)
  if (!detail::at_or_below_domain_end(c_lo, dm.q))
    return {false, "evidence.domain_c_lo = " + detail::shortened(c_lo) + " is not <= cos(pi/" + std::to_string(dm.q) + ")"};
  const std::string at_K = K + " = " + detail::decimal(lo);
  std::vector<std::string> shown;

  // ---- b*(0) <= b0 < b: needed for K_max > 0
  if (infinite || lo > 0) {
    const rational b0 = exact_field(evidence, "b0_hi", "evidence");
    if (b0 >= b) return {false, "evidence.b0_hi = " + detail::decimal(b0) + " is not < b = " + detail::decimal(b) + ": K_max > 0 not shown"};
    std::string how;
    if (auto why = detail::upper_bound_fails(at(rational(0)), b0 - dm.eta, "(b0 - eta)", c_lo, dm.q, how))
      return {false, "b*(" + K + " = 0) <= b0_hi = " + detail::decimal(b0) + " fails: " + *why};
    shown.push_back("b*(0) <= " + detail::decimal(b0) + " < b (" + how + ")");
  }
  if (infinite) {
    std::string how;
    const detail::ObjectivePolys f1 = detail::bound_objective(h.H1, dm.T, dm.P, dm.q);
    if (auto why = detail::upper_bound_fails(f1, rational(0), "0", c_lo, dm.q, how))
      return {false, K + "_max = +inf fails: f1 <= 0 (the objective of dH/d" + K + ") not shown: " + *why};
    return {true, K + "_max = +inf: " + shown.front() + "; f1 <= 0 (" + how + "), so b*(" + K + ") <= b*(0) < b for every " +
                      K + " >= 0 (b* convex in " + K + "; H affine in " + K + ", degree bound " + std::to_string(h.D) + ")"};
  }
  // ---- lower end: b*(lo) <= b
  if (lo > 0) {
    std::string how;
    if (auto why = detail::upper_bound_fails(at(lo), b - dm.eta, "(b - eta)", c_lo, dm.q, how))
      return {false, K + "_max >= " + detail::decimal(lo) + " fails: b*(" + at_K + ") <= b = " + detail::decimal(b) + " not shown: " + *why};
    shown.push_back("b*(" + at_K + ") <= b (" + how + ")");
  }
  // ---- upper end: b* = +inf above hi (a jump), or b*(hi) >= b by the witness
  if (jump) {
    std::string how;
    if (auto why = jump_fails(evidence, h, dm, hi, K, how)) return {false, K + "_max <= " + detail::decimal(hi) + " not shown: " + *why};
    shown.push_back(how);
  } else {
    const rational c1 = exact_field(evidence, "witness_c", "evidence");
    if (auto why = detail::lower_bound_fails(at(hi), b - dm.eta, c1, dm.q))
      return {false, K + "_max <= " + detail::decimal(hi) + " not shown: b*(" + K + " = " + detail::decimal(hi) + ") >= b = " + detail::decimal(b) + ": " + *why};
    shown.push_back("b*(" + K + " = " + detail::decimal(hi) + ") >= b at c1 = " + detail::shortened(c1));
  }
  std::string what = K + "_max " + (status == "exact" ? "= " + lo.str() : "in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]");
  std::string all;
  for (const auto& s : shown) all += (all.empty() ? "" : "; ") + s;
  return {true, what + ": " + all + " (b* convex in " + K + "; H affine in " + K + ", degree bound " + std::to_string(h.D) + ")"};
}

}  // namespace hapstab::check
