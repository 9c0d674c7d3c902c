// hapstab/check/wedge_check.cpp -- see wedge_check.hpp.
#include "hapstab/check/wedge_check.hpp"

#include <map>
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
  detail::only_fields(model, {"H", "set", "T"}, "model");
  if (!model.contains("H") || !model.at("H").is_string()) throw InputError("model.H: missing or not a string (the expression of H(z))");
  const rational T = detail::exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  const TransferFunction H = detail::model_tf(model, model.at("H").get<std::string>(), T);
  if (H.num().degree() > H.den().degree()) throw InputError("model.H: not causal (deg num > deg den)");
  return H;
}

bool claimed(const nlohmann::json& claim, const char* key) {
  if (!claim.contains(key) || !claim.at(key).is_boolean()) throw InputError(std::string("claim.") + key + ": missing or not true/false");
  return claim.at(key).get<bool>();
}

}  // namespace

Verdict check_wedge(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(evidence, {}, "evidence");
  detail::only_fields(claim, {"quantity", "status", "wedge", "tsypkin", "h_stable", "closed_loop_stable", "dc_gain_nonnegative"}, "claim");
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

  std::vector<std::pair<const char*, std::pair<bool, std::string>>> facts;
  const auto wedge = max_positive_on(Pp, Pm, m1, p1);
  facts.push_back({"wedge", {!wedge, wedge ? "(25) fails: max(P+, P-) on [-1, 1]: " + *wedge : "(25) holds: max(P+, P-) > 0 on [-1, 1]"}});
  const auto tsypkin = max_positive_on(S, S, m1, p1);
  facts.push_back({"tsypkin", {!tsypkin, tsypkin ? "(21) fails: X + |D|^2 on [-1, 1]: " + *tsypkin : "(21) holds: X + |D|^2 > 0 on [-1, 1]"}});
  const SchurCohn hs = schur_cohn(D);
  facts.push_back({"h_stable", {hs.stable, "H stable: " + hs.why}});
  const P cl = D + N;
  const SchurCohn cs = cl.is_zero() ? SchurCohn{false, "D + N = 0"} : schur_cohn(cl);
  facts.push_back({"closed_loop_stable", {cs.stable, "(1 + H)^-1 stable: " + cs.why}});
  const rational d1 = D(p1);
  const bool dc = d1 != 0 && N(p1) / d1 >= 0;
  facts.push_back({"dc_gain_nonnegative", {dc, d1 == 0 ? "H(1) is infinite" : "H(1) = " + rational(N(p1) / d1).str()}});

  std::string shown;
  for (const auto& [key, fact] : facts) {
    if (claimed(claim, key) != fact.first)
      return {false, std::string("claim.") + key + " = " + (fact.first ? "false" : "true") + ", but " + fact.second};
    shown += (shown.empty() ? "" : "; ") + fact.second;
  }
  return {true, shown};
}

}  // namespace hapstab::check
