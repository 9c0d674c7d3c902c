// hapstab/check/bound_check.cpp -- see bound_check.hpp.
#include "hapstab/check/bound_check.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

std::string decimal(const rational& x) { return to_decimal(x, 12); }

}  // namespace

Verdict check_bound(const nlohmann::json& cert) {
  constexpr long max_size = 1000;
  using detail::exact_field;
  using detail::object_field;
  const nlohmann::json& model = object_field(cert, "model", "certificate");
  const nlohmann::json& claim = object_field(cert, "claim", "certificate");
  const nlohmann::json& evidence = object_field(cert, "evidence", "certificate");

  // ---- the model as written (a field this checker does not read would be a model it does not check)
  detail::only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  detail::only_fields(model, {"H", "set", "T", "delay", "frac_delay", "eta"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  detail::only_fields(evidence, {"witness_c", "domain_c_lo"}, "evidence");
  if (!model.contains("H") || !model.at("H").is_string()) throw InputError("model.H: missing or not a string (the expression of H(z))");
  const std::string text = model.at("H").get<std::string>();
  const detail::DelayModel dm = detail::read_delay_model(model);
  const rational& eta = dm.eta;
  const TransferFunction H = detail::model_tf(model, text, dm.T);
  // the checker expands the delay: its polynomials in c have degree about q (deg H + 1) + P
  detail::check_size(dm, H.num().degree(), H.den().degree(), max_size);

  // ---- the claim
  if (!claim.contains("status") || !claim.at("status").is_string())
    throw InputError("claim.status: missing or not a string (\"exact\" or \"certified\")");
  const std::string status = claim.at("status").get<std::string>();
  rational lo, hi;
  if (status == "exact") {
    lo = hi = exact_field(claim, "value", "claim");
  } else if (status == "certified") {
    lo = exact_field(claim, "lo", "claim");
    hi = exact_field(claim, "hi", "claim");
    if (lo > hi) return {false, "claim: lo = " + lo.str() + " > hi = " + hi.str()};
  } else {
    throw InputError("claim.status: \"" + status + "\" is neither \"exact\" nor \"certified\"");
  }
  // the printed decimals, when given, are the numbers claimed (what a reader sees is what is proven)
  for (const char* key : {"printed_lo", "printed_hi", "printed"}) {
    if (!claim.contains(key)) continue;
    const auto& v = claim.at(key);
    if (!v.is_string()) throw InputError(std::string("claim.") + key + ": not a string");
    const auto q = try_parse_rational(v.get<std::string>());
    if (!q) throw InputError(std::string("claim.") + key + ": '" + v.get<std::string>() + "' is not a number");
    const rational& want = std::string(key) == "printed_hi" ? hi : lo;
    if (*q != want)
      return {false, std::string("claim.") + key + " = " + v.get<std::string>() + " is not the claimed " + want.str()};
  }

  // ---- f(c) = A/B + eta in c = cos(wT/q), the checker's own derivation (check/bound_objective.hpp)
  const detail::ObjectivePolys f = detail::bound_objective(H.H, dm.T, dm.P, dm.q);
  // the band c in [cos(pi/q), 1] ([-1, 1] for an integer delay) lies in [c_lo, 1]
  const rational c_lo = evidence.contains("domain_c_lo") ? exact_field(evidence, "domain_c_lo", "evidence") : rational(-1);
  const rational c0 = exact_field(evidence, "witness_c", "evidence");

  // ---- upper: (hi - eta) B - A >= 0 on [c_lo, 1]
  std::string how;
  if (auto why = detail::upper_bound_fails(f, hi - eta, "(hi - eta)", c_lo, dm.q, how))
    return {false, "b* <= " + hi.str() + " (" + decimal(hi) + ") fails: " + *why};

  // ---- lower: the witness
  if (auto why = detail::lower_bound_fails(f, lo - eta, c0, dm.q))
    return {false, "b* >= " + lo.str() + " (" + decimal(lo) + ") not shown: " + *why};

  std::string what = status == "exact" ? "b* = " + lo.str() : "b* in [" + decimal(lo) + ", " + decimal(hi) + "]";
  return {true, what + " (upper bound: " + how + "; lower bound: the objective at c0 = " + detail::shortened(c0) + ")"};
}

}  // namespace hapstab::check
