// hapstab/check/passivity_level_check.cpp -- see passivity_level_check.hpp.
#include "hapstab/check/passivity_level_check.hpp"

#include <algorithm>
#include <string>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/max_positive.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {
using P = Polynomial<rational>;
}  // namespace

Verdict check_passivity_level(const nlohmann::json& cert) {
  using detail::exact_field;
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(model, {"H", "set", "num", "den", "T", "kind"}, "model");
  detail::only_fields(claim, {"quantity", "status", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  detail::only_fields(evidence, {"witness_c"}, "evidence");

  // ---- the model as written
  if (!model.contains("kind") || !model.at("kind").is_string() ||
      (model.at("kind") != "isp" && model.at("kind") != "osp"))
    throw InputError("model.kind: missing or neither \"isp\" nor \"osp\"");
  const bool osp = model.at("kind") == "osp";
  const rational T = exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  const TransferFunction G = detail::model_tf(model, T);
  if (G.num().is_zero()) throw InputError("model.H: G = 0");
  if (G.num().degree() > G.den().degree()) throw InputError("model.H: G is not causal (deg N > deg D)");
  if (G.den().degree() > 1000) throw InputError("model.H: degree above this checker's limit of 1000");
  const SchurCohn stable = schur_cohn(G.den());
  if (!stable.stable) throw InputError("model.H: G is not Schur stable (" + stable.why + "): the level is not its frequency minimum");

  // ---- Re W = X/Q on the circle, c = cos(theta)
  const circle::OnCircle N = circle::at_circle(G.num()), D = circle::at_circle(G.den());
  const P s2 = circle::one_minus_c2();
  const P X = N.a * D.a + s2 * N.b * D.b;
  const P Q = osp ? N.a * N.a + s2 * N.b * N.b : D.a * D.a + s2 * D.b * D.b;
  const rational m1(-1), p1(1);
  const std::string name = osp ? "delta*" : "phi*";

  // ---- an upper bound only (header): Re W(c0) <= hi at the witness with Q(c0) > 0
  if (claim.contains("status") && claim.at("status") == "upper_bound") {
    const detail::ClaimRange range = detail::upper_bound_claim(claim);
    if (range.refuted) return {false, *range.refuted};
    const rational& hi = range.hi;
    const rational c0 = exact_field(evidence, "witness_c", "evidence");
    if (c0 < -1 || c0 > 1) return {false, "evidence.witness_c = " + detail::shortened(c0) + " is outside [-1, 1]"};
    if (Q(c0) == 0) return {false, std::string("evidence.witness_c: ") + (osp ? "G" : "1/G") + " = 0 there (no bound from it)"};
    const rational w0 = X(c0) / Q(c0);
    if (w0 > hi)
      return {false, name + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: Re " + (osp ? "1/G" : "G") +
                         " at the witness c0 = " + detail::shortened(c0) + " is " + detail::decimal(w0) + " > hi"};
    return {true, name + " <= " + detail::decimal(hi) + " (" + (osp ? "OSP" : "ISP") + ", an upper bound only: Re " +
                      (osp ? "1/G" : "G") + " = " + detail::decimal(w0) + " at c0 = " + detail::shortened(c0) +
                      ", where the frequency inequality of every level above hi fails; G Schur stable: " + stable.why + ")"};
  }

  // ---- the claim
  const detail::ClaimRange range = detail::claim_range(claim);
  if (range.refuted) return {false, *range.refuted};
  const std::string& status = range.status;
  const rational &lo = range.lo, &hi = range.hi;
  if (osp) {
    if (auto why = max_positive_on(Q, Q, m1, p1))
      throw InputError("model.H: G has a zero on the unit circle (|N|^2 not > 0: " + *why + "): delta* is not Lemma 1's level there");
    if (lo <= 0)
      throw InputError("claim: an OSP value <= 0 (lo = " + detail::decimal(lo) + ") is an upper bound of Lemma 1's level only: no certificate");
  }
  if (auto why = nonnegative_on(X - lo * Q, m1, p1))
    return {false, name + " >= " + lo.str() + " (" + detail::decimal(lo) + ") fails: X(c) - lo Q(c) on [-1, 1]: " + *why};
  const rational c0 = exact_field(evidence, "witness_c", "evidence");
  if (c0 < -1 || c0 > 1) return {false, "evidence.witness_c = " + detail::shortened(c0) + " is outside [-1, 1]"};
  const rational w0 = X(c0) / Q(c0);  // Q > 0 on [-1, 1]
  if (w0 > hi)
    return {false, name + " <= " + hi.str() + " (" + detail::decimal(hi) + ") not shown: Re " + (osp ? "1/G" : "G") +
                       " at the witness c0 = " + detail::shortened(c0) + " is " + detail::decimal(w0) + " > hi"};
  const std::string what = status == "exact" ? name + " = " + lo.str() : name + " in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]";
  return {true, what + " (" + (osp ? "OSP" : "ISP") + "; lower bound: X - lo " + (osp ? "|N|^2" : "|D|^2") +
                    " >= 0 on [-1, 1] by Sturm, degree " + std::to_string(std::max(X.degree(), Q.degree())) +
                    "; upper bound: Re " + (osp ? "1/G" : "G") + " at c0 = " + detail::shortened(c0) + "; G Schur stable: " +
                    stable.why + ")"};
}

}  // namespace hapstab::check
