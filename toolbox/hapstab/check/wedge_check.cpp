// hapstab/check/wedge_check.cpp -- see wedge_check.hpp.
#include "hapstab/check/wedge_check.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/check/max_positive.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;

TransferFunction parse_model(const nlohmann::json& model) {
  detail::only_fields(model, {"H", "set", "num", "den", "T"}, "model");
  const rational T = detail::exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  const TransferFunction H = detail::model_tf(model, T);
  if (H.num().degree() > H.den().degree()) throw InputError("model.H: not causal (deg num > deg den)");
  return H;
}

// The margin mu = min over c in [-1, 1] of max(p1, p2)/D2 (D2 > 0 there): mu >= lo iff
// max(p1 - lo D2, p2 - lo D2) >= 0 on [-1, 1] (non-strict); mu <= hi if max(p1, p2) <= hi D2 at a
// rational witness c0 in [-1, 1]. nullopt when both hold, else what failed.
std::optional<std::string> margin_in(const P& p1, const P& p2, const P& D2, const std::optional<rational>& lo,
                                     const std::optional<rational>& hi, const std::optional<rational>& c0) {
  if (lo)
    if (auto why = max_positive_on(p1 - P(*lo) * D2, p2 - P(*lo) * D2, rational(-1), rational(1), /*strict=*/false))
      return "min >= " + detail::decimal(*lo) + " fails: " + *why;
  if (!hi) return std::nullopt;
  if (*c0 < -1 || *c0 > 1) return "the witness c0 = " + c0->str() + " is outside [-1, 1]";
  const rational d = D2(*c0), v1 = p1(*c0), v2 = p2(*c0);
  const rational v = (v1 > v2 ? v1 : v2) / d;
  if (v > *hi) return "min <= " + detail::decimal(*hi) + " not shown: the left side + 1 at the witness c0 = " + c0->str() + " is " + detail::decimal(v);
  return std::nullopt;
}

// claim.<key>_margin {lo, hi, printed} and claim.<key>_gain {lo, hi, printed} or {infinite: true}
// (k* = -1/(mu - 1): k H meets the criterion iff k (mu - 1) + 1 > 0 for every theta, so
// k* >= lo iff mu >= 1 - 1/lo, k* <= hi iff mu <= 1 - 1/hi, k* = +inf iff mu >= 1); the witness
// evidence.<key>_witness_c. nullopt when every claim present holds, else what failed; `shown` gets
// what was shown.
struct Bounds {
  rational lo, hi;
  bool infinite = false;
};
Bounds read_bounds(const nlohmann::json& claim, const std::string& field, bool may_be_infinite, std::optional<std::string>& refuted) {
  const nlohmann::json& o = detail::object_field(claim, field, "claim");
  Bounds b;
  if (may_be_infinite && o.contains("infinite")) {
    detail::only_fields(o, {"infinite"}, "claim." + field);
    if (o.at("infinite") != true) throw InputError("claim." + field + ".infinite: not true (a finite gain has lo and hi)");
    b.infinite = true;
    return b;
  }
  detail::only_fields(o, {"lo", "hi", "printed"}, "claim." + field);
  b.lo = detail::exact_field(o, "lo", "claim." + field);
  b.hi = detail::exact_field(o, "hi", "claim." + field);
  if (may_be_infinite && b.lo <= 0) throw InputError("claim." + field + ".lo: a gain k* is > 0");
  if (b.lo > b.hi) refuted = "claim." + field + ": lo = " + b.lo.str() + " > hi = " + b.hi.str();
  if (!refuted && o.contains("printed")) {
    if (!o.at("printed").is_string()) throw InputError("claim." + field + ".printed: not a string");
    const std::string t = o.at("printed").get<std::string>();
    const auto a = detail::rounds_to(t, b.lo), c = detail::rounds_to(t, b.hi);
    if (!a || !c) throw InputError("claim." + field + ".printed: '" + t.substr(0, 60) + "' is not a decimal");
    if (!*a || !*c) refuted = "claim." + field + ".printed = " + t + " is not what both ends of [lo, hi] round to";
  }
  return b;
}

// What the margins and gains shown say about mu itself: lo <= mu (when set), mu <= hi (when set).
struct MuShown {
  std::optional<rational> lo, hi;
  void at_least(const rational& v) { if (!lo || v > *lo) lo = v; }
  void at_most(const rational& v) { if (!hi || v < *hi) hi = v; }
};

std::optional<std::string> check_margins(const nlohmann::json& claim, const nlohmann::json& evidence, const std::string& key,
                                         const P& p1, const P& p2, const P& D2, std::string& shown, MuShown& mu) {
  const bool has_margin = claim.contains(key + "_margin"), has_gain = claim.contains(key + "_gain");
  std::optional<std::string> refuted;
  std::optional<rational> c0;
  if (evidence.contains(key + "_witness_c")) c0 = detail::exact_field(evidence, key + "_witness_c", "evidence");
  auto witness = [&]() -> std::optional<rational> {
    if (!c0) throw InputError("evidence." + key + "_witness_c: missing (the witness of the upper bounds)");
    return c0;
  };
  if (has_margin) {
    const Bounds m = read_bounds(claim, key + "_margin", false, refuted);
    if (refuted) return refuted;
    if (auto why = margin_in(p1, p2, D2, m.lo, m.hi, witness())) return "claim." + key + "_margin: " + *why;
    shown += "; " + key + " margin in [" + detail::decimal(m.lo) + ", " + detail::decimal(m.hi) + "]";
    mu.at_least(m.lo);
    mu.at_most(m.hi);
  }
  if (has_gain) {
    const Bounds g = read_bounds(claim, key + "_gain", true, refuted);
    if (refuted) return refuted;
    if (g.infinite) {
      if (auto why = margin_in(p1, p2, D2, rational(1), std::nullopt, std::nullopt))
        return "claim." + key + "_gain = +inf: " + *why + " (k* = +inf needs the left side >= 0)";
      shown += "; " + key + " k* = +inf (left side >= 0)";
      mu.at_least(rational(1));
    } else {
      // mu >= 1 - 1/lo follows from the margin's mu >= lo_m when 1 - 1/lo <= lo_m: the Sturm test is
      // needed only when it does not (the upper end is one evaluation at the witness either way)
      const rational need_lo = 1 - 1 / g.lo, need_hi = 1 - 1 / g.hi;
      std::optional<rational> test_lo;
      if (!mu.lo || need_lo > *mu.lo) test_lo = need_lo;
      if (auto why = margin_in(p1, p2, D2, test_lo, need_hi, witness()))
        return "claim." + key + "_gain in [" + detail::decimal(g.lo) + ", " + detail::decimal(g.hi) + "] (k* = 1/(1 - min)): " + *why;
      shown += "; " + key + " k* in [" + detail::decimal(g.lo) + ", " + detail::decimal(g.hi) + "]";
      mu.at_least(need_lo);
      mu.at_most(need_hi);
    }
  }
  if (c0 && !has_margin && !(has_gain && !claim.at(key + "_gain").contains("infinite")))
    throw InputError("evidence." + key + "_witness_c: no claim reads it");
  return std::nullopt;
}

bool claimed(const nlohmann::json& claim, const char* key) {
  if (!claim.contains(key) || !claim.at(key).is_boolean()) throw InputError(std::string("claim.") + key + ": missing or not true/false");
  return claim.at(key).get<bool>();
}

}  // namespace

Verdict check_wedge(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(evidence, {"wedge_witness_c", "tsypkin_witness_c"}, "evidence");
  detail::only_fields(claim, {"quantity", "status", "wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative",
                              "wedge_margin", "tsypkin_margin", "wedge_gain", "tsypkin_gain"},
                      "claim");
  if (!claim.contains("status") || claim.at("status") != "exact") throw InputError("claim.status: missing or not \"exact\"");
  const TransferFunction H = parse_model(model);
  const P &N = H.num(), &D = H.den();
  const circle::OnCircle n = circle::at_circle(N), d = circle::at_circle(D);
  const P one_minus_c2 = circle::one_minus_c2();
  const P X = n.a * d.a + one_minus_c2 * n.b * d.b, Y = n.b * d.a - n.a * d.b;
  const P D2 = d.a * d.a + one_minus_c2 * d.b * d.b;
  const rational m1(-1), p1(1);
  if (max_positive_on(D2, D2, m1, p1))
    throw InputError("model.H: H has a pole on the unit circle (|D|^2 vanishes on [-1, 1]): the criteria are not evaluated");
  const P one_plus_c{rational(1), rational(1)};
  const P S = X + D2, Pp = S + one_plus_c * Y, Pm = S - one_plus_c * Y;

  // Every boolean is read first (one missing: malformed), then the margins and gains: once shown, an
  // interval for mu on one side of 0 decides (25) or (21) itself (the criterion holds iff mu > 0), and
  // the Sturm test of the criterion is run only when it does not.
  const char* const keys[] = {"wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative"};
  std::map<std::string, bool> said;
  for (const char* key : keys) said[key] = claimed(claim, key);
  std::string ranges;
  MuShown wedge_mu, tsypkin_mu;
  if (auto why = check_margins(claim, evidence, "wedge", Pp, Pm, D2, ranges, wedge_mu)) return {false, *why};
  if (auto why = check_margins(claim, evidence, "tsypkin", S, S, D2, ranges, tsypkin_mu)) return {false, *why};
  auto criterion = [&](const MuShown& mu, const P& a, const P& b, const std::string& eq, const std::string& what) {
    if (mu.lo && *mu.lo > 0)
      return std::pair{true, eq + " holds: " + what + " >= " + detail::decimal(*mu.lo) + " |D|^2 > 0 on [-1, 1] (by the margin shown)"};
    if (mu.hi && *mu.hi <= 0)
      return std::pair{false, eq + " fails: " + what + " <= " + detail::decimal(*mu.hi) + " |D|^2 <= 0 at the witness (by the margin shown)"};
    const auto why = max_positive_on(a, b, m1, p1);
    return std::pair{!why, why ? eq + " fails: " + what + " on [-1, 1]: " + *why : eq + " holds: " + what + " > 0 on [-1, 1]"};
  };
  std::map<std::string, std::pair<bool, std::string>> facts;
  facts["wedge"] = criterion(wedge_mu, Pp, Pm, "(25)", "max(P+, P-)");
  facts["tsypkin"] = criterion(tsypkin_mu, S, S, "(21)", "X + |D|^2");
  const SchurCohn hs = schur_cohn(D);
  facts["h_stable"] = {hs.stable, "H stable: " + hs.why};
  const P cl = D + N;
  const SchurCohn cs = cl.is_zero() ? SchurCohn{false, "D + N = 0"} : schur_cohn(cl);
  facts["closed_loop_stable"] = {cs.stable, "(1 + H)^-1 stable: " + cs.why};
  const rational d1 = D(p1);
  const bool dc = d1 != 0 && N(p1) / d1 >= 0;
  facts["dc_gain_nonnegative"] = {dc, d1 == 0 ? "H(1) is infinite" : "H(1) = " + rational(N(p1) / d1).str()};

  std::string shown;
  for (const char* key : keys) {
    const auto& [holds, why] = facts.at(key);
    if (said.at(key) != holds) return {false, std::string("claim.") + key + " = " + (holds ? "false" : "true") + ", but " + why};
    shown += (shown.empty() ? "" : "; ") + why;
  }
  shown += ranges;
  return {true, shown};
}

}  // namespace hapstab::check
