// hapstab/check/bound_max_check.cpp -- see bound_max_check.hpp.
#include "hapstab/check/bound_max_check.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using RF = RationalFunction<rational>;

std::string decimal(const rational& x) { return to_decimal(x, 12); }

struct Affine {
  RF H0{Polynomial<rational>(rational(0))}, H1{Polynomial<rational>(rational(0))};
  long D = 0;  // the degree bound in K that the values proved
};

// H = H0 + K H1, proven (the header): D + 1 values of K where H(k) = H0 + k H1 exactly.
Affine prove_affine(const std::string& text, ParseOptions po, const std::string& K) {
  constexpr long max_degree = 64;
  std::pair<long, long> deg;
  try {
    deg = ParsedExpression(text, po, {K}).degree_bound();
  } catch (const InputError& e) {
    throw InputError(std::string("model.H: ") + e.what());
  }
  Affine a;
  a.D = std::max(deg.first, deg.second + 1);
  if (a.D > max_degree)
    throw InputError("model.H: its degree in " + K + " is bounded only by " + std::to_string(a.D) + " (above " +
                     std::to_string(max_degree) + "): not proven affine in " + K);
  auto at = [&](const rational& k) {
    po.parameters[K] = k;
    return parse_tf(text, po).H;
  };
  try {
    a.H0 = at(rational(0));
    a.H1 = at(rational(1)) - a.H0;
  } catch (const InputError& e) {
    throw InputError("model.H at " + K + " = 0 or 1: " + e.what());
  }
  if (a.H1.is_zero()) throw InputError("model.H: does not depend on model.name = " + K);
  long proven = 2, tried = 0;
  for (long j = 2; proven < a.D + 1; ++j) {
    const rational k = j % 2 == 0 ? rational(j, 5) : rational(-j, 11);  // distinct, never 0 or 1
    std::optional<RF> h;
    try {
      h = at(k);
    } catch (const InputError&) {  // the expression divides by zero at k: at most dd such values
      if (++tried > a.D + deg.second + 2) throw InputError("model.H: undefined at too many values of " + K);
      continue;
    }
    if (*h != a.H0 + RF(k) * a.H1)
      throw InputError("model.H: not affine in " + K + " (H(" + k.str() + ") != H(0) + " + k.str() + " (H(1) - H(0)))");
    ++proven;
  }
  return a;
}

}  // namespace

Verdict check_bound_max(const nlohmann::json& cert) {
  constexpr long max_size = 1000;
  using detail::exact_field;
  using detail::object_field;
  const nlohmann::json& model = object_field(cert, "model", "certificate");
  const nlohmann::json& claim = object_field(cert, "claim", "certificate");
  const nlohmann::json& evidence = object_field(cert, "evidence", "certificate");
  detail::only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  detail::only_fields(model, {"H", "set", "name", "T", "delay", "frac_delay", "eta", "damping"}, "model");
  detail::only_fields(claim, {"quantity", "status", "infinite", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  detail::only_fields(evidence, {"witness_c", "b0_hi", "domain_c_lo"}, "evidence");

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
  if (model.contains("set")) {
    const auto& sets = model.at("set");
    if (!sets.is_object()) throw InputError("model.set: must be an object {NAME: \"p/q\"}");
    for (auto it = sets.begin(); it != sets.end(); ++it) po.parameters[it.key()] = detail::exact_string(it.value(), "model.set." + it.key());
  }
  if (po.parameters.count(K)) throw InputError("model.set: gives the parameter model.name = " + K + " a value");
  const Affine h = prove_affine(text, po, K);
  detail::check_size(dm, std::max(h.H0.num().degree(), h.H1.num().degree()),
                     std::max(h.H0.den().degree(), h.H1.den().degree()), max_size);
  auto at = [&](const rational& k) { return detail::bound_objective(h.H0 + RF(k) * h.H1, dm.T, dm.P, dm.q); };

  // ---- the claim
  if (!claim.contains("status") || !claim.at("status").is_string())
    throw InputError("claim.status: missing or not a string (\"exact\" or \"certified\")");
  const std::string status = claim.at("status").get<std::string>();
  if (status != "exact" && status != "certified")
    throw InputError("claim.status: \"" + status + "\" is neither \"exact\" nor \"certified\"");
  bool infinite = false;
  if (claim.contains("infinite")) {
    if (!claim.at("infinite").is_boolean()) throw InputError("claim.infinite: not true/false");
    infinite = claim.at("infinite").get<bool>();
  }
  rational lo, hi;
  if (!infinite) {
    if (status == "exact") {
      lo = hi = exact_field(claim, "value", "claim");
    } else {
      lo = exact_field(claim, "lo", "claim");
      hi = exact_field(claim, "hi", "claim");
    }
    if (lo < 0) return {false, "claim: lo = " + lo.str() + " < 0 (K_max >= 0 by its definition)"};
    if (lo > hi) return {false, "claim: lo = " + lo.str() + " > hi = " + hi.str()};
  } else if (claim.contains("value") || claim.contains("lo") || claim.contains("hi")) {
    throw InputError("claim.infinite: true beside a finite value, lo or hi");
  }
  for (const char* key : {"printed_lo", "printed_hi", "printed"}) {
    if (!claim.contains(key)) continue;
    const auto& v = claim.at(key);
    if (!v.is_string()) throw InputError(std::string("claim.") + key + ": not a string");
    const auto q = try_parse_rational(v.get<std::string>());
    if (!q) throw InputError(std::string("claim.") + key + ": '" + v.get<std::string>() + "' is not a number");
    if (infinite) throw InputError(std::string("claim.") + key + ": a printed number beside an infinite claim");
    const rational& want = std::string(key) == "printed_hi" ? hi : lo;
    if (*q != want)
      return {false, std::string("claim.") + key + " = " + v.get<std::string>() + " is not the claimed " + want.str()};
  }
  const rational c_lo = evidence.contains("domain_c_lo") ? exact_field(evidence, "domain_c_lo", "evidence") : rational(-1);
  // checked whenever given, also where no upper bound reads it (K_max = 0): evidence is never ignored
  // (the campaign found a moved domain_c_lo accepted on K_max = 0 certificates)
  if (!detail::at_or_below_domain_end(c_lo, dm.q))
    return {false, "evidence.domain_c_lo = " + detail::shortened(c_lo) + " is not <= cos(pi/" + std::to_string(dm.q) + ")"};
  const std::string at_K = K + " = " + decimal(lo);
  std::vector<std::string> shown;

  // ---- b*(0) <= b0 < b: needed for K_max > 0
  if (infinite || lo > 0) {
    const rational b0 = exact_field(evidence, "b0_hi", "evidence");
    if (b0 >= b) return {false, "evidence.b0_hi = " + decimal(b0) + " is not < b = " + decimal(b) + ": K_max > 0 not shown"};
    std::string how;
    if (auto why = detail::upper_bound_fails(at(rational(0)), b0 - dm.eta, "(b0 - eta)", c_lo, dm.q, how))
      return {false, "b*(" + K + " = 0) <= b0_hi = " + decimal(b0) + " fails: " + *why};
    shown.push_back("b*(0) <= " + decimal(b0) + " < b (" + how + ")");
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
      return {false, K + "_max >= " + decimal(lo) + " fails: b*(" + at_K + ") <= b = " + decimal(b) + " not shown: " + *why};
    shown.push_back("b*(" + at_K + ") <= b (" + how + ")");
  }
  // ---- upper end: b*(hi) >= b, by the witness
  const rational c1 = exact_field(evidence, "witness_c", "evidence");
  if (auto why = detail::lower_bound_fails(at(hi), b - dm.eta, c1, dm.q))
    return {false, K + "_max <= " + decimal(hi) + " not shown: b*(" + K + " = " + decimal(hi) + ") >= b = " + decimal(b) + ": " + *why};
  shown.push_back("b*(" + K + " = " + decimal(hi) + ") >= b at c1 = " + detail::shortened(c1));
  std::string what = K + "_max " + (status == "exact" ? "= " + lo.str() : "in [" + decimal(lo) + ", " + decimal(hi) + "]");
  std::string all;
  for (const auto& s : shown) all += (all.empty() ? "" : "; ") + s;
  return {true, what + ": " + all + " (b* convex in " + K + "; H affine in " + K + ", degree bound " + std::to_string(h.D) + ")"};
}

}  // namespace hapstab::check
