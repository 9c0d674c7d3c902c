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

Verdict check_bound(const nlohmann::json& cert) {
  constexpr long max_size = 1000;
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);

  // ---- the model as written (a field this checker does not read would be a model it does not check)
  detail::only_fields(model, {"H", "set", "num", "den", "T", "delay", "frac_delay", "eta"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi", "infinite"}, "claim");
  const bool infinite = claim.contains("infinite");  // its value is read by claim_range below
  const bool cells = !infinite && evidence.contains("cells");  // the long-delay form (check/bound_cells.hpp)
  if (infinite) detail::only_fields(evidence, {"pole_c", "side", "end_lo", "end_hi", "pole_lo", "pole_hi"}, "evidence");
  else if (cells) detail::only_fields(evidence, {"cells", "witness_theta"}, "evidence");
  else detail::only_fields(evidence, {"witness_c", "domain_c_lo"}, "evidence");
  const detail::DelayModel dm = detail::read_delay_model(model);
  const rational& eta = dm.eta;
  const TransferFunction H = detail::model_tf(model, dm.T, HiddenPoles::allow_marginal);  // as `bound` reads it
  // the checker expands the delay: its polynomials in c have degree about q (deg H + 1) + P
  if (!cells) detail::check_size(dm, H.num().degree(), H.den().degree(), max_size);

  // ---- the claim (the printed decimals, when given, are the numbers claimed)
  const detail::ClaimRange range = detail::claim_range(claim, /*may_be_infinite=*/true);
  if (range.refuted) return {false, *range.refuted};
  if (infinite && !range.infinite) throw InputError("claim.infinite: false (a finite claim has no such field)");
  if (range.infinite) return check_infinite(evidence, H, dm, range.status);
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
