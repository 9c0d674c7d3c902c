// hapstab/check/stability_check.cpp -- see stability_check.hpp.
#include "hapstab/check/stability_check.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "hapstab/check/loop_model.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
constexpr long max_charpoly_degree = 2000;

struct LoopCharpoly {
  P c;               // the characteristic polynomial, the checker's own
  std::string text;  // what was checked
};

LoopCharpoly characteristic(const nlohmann::json& model) {
  detail::only_fields(model, {"plant", "H", "operator", "set", "T", "delay"}, "model");
  const detail::LoopDevice d = detail::read_loop_device(model);
  const RF H = detail::parse_model_field(model, "H", 'z', d.T, d.params);
  if (H.num().degree() > H.den().degree() + d.n) throw InputError("model.H: z^-n H(z) is not causal");
  if (H.den().degree() + d.n + d.k > max_charpoly_degree)
    throw InputError("model: the characteristic polynomial has degree " + std::to_string(H.den().degree() + d.n + d.k) +
                     ", beyond this checker's limit of " + std::to_string(max_charpoly_degree));
  return {detail::loop_polynomial(d, H.num(), H.den()),
          "degree " + std::to_string(d.k) + " device, delay " + std::to_string(d.n)};
}

/// nullopt when `given` (ascending) is a non-zero multiple of c, else what differs.
std::optional<std::string> differs(const nlohmann::json& given, const P& c) {
  if (!given.is_array() || given.empty()) throw InputError("evidence.charpoly: not a non-empty array of \"p/q\"");
  std::vector<rational> g;
  for (size_t i = 0; i < given.size(); ++i) g.push_back(detail::exact_string(given[i], "evidence.charpoly[" + std::to_string(i) + "]"));
  const P gp(g);
  if (gp.degree() != c.degree())
    return "evidence.charpoly has degree " + std::to_string(gp.degree()) + ", the loop as written " + std::to_string(c.degree());
  const rational ratio = gp.leading() / c.leading();
  for (int i = 0; i <= c.degree(); ++i)
    if (gp.coeff(i) != ratio * c.coeff(i))
      return "evidence.charpoly is not the characteristic polynomial of the loop as written (coefficient of z^" +
             std::to_string(i) + ": " + gp.coeff(i).str() + ", expected " + rational(ratio * c.coeff(i)).str() + ")";
  return std::nullopt;
}

}  // namespace

Verdict check_stability(const nlohmann::json& cert) {
  const auto [model, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(claim, {"quantity", "status", "stable"}, "claim");
  detail::only_fields(evidence, {"charpoly"}, "evidence");
  if (!claim.contains("status") || !claim.at("status").is_string() ||
      (claim.at("status") != "exact" && claim.at("status") != "certified"))
    throw InputError("claim.status: missing or neither \"exact\" nor \"certified\"");
  if (!claim.contains("stable") || !claim.at("stable").is_boolean()) throw InputError("claim.stable: missing or not true/false");
  const bool stable = claim.at("stable").get<bool>();
  if (!evidence.contains("charpoly")) throw InputError("evidence.charpoly: missing");
  const LoopCharpoly m = characteristic(model);
  if (auto why = differs(evidence.at("charpoly"), m.c)) return {false, *why};
  const SchurCohn sc = schur_cohn(m.c);
  const std::string what = "the characteristic polynomial (degree " + std::to_string(m.c.degree()) + ", " + m.text + ")";
  if (sc.stable != stable)
    return {false, std::string("claim: ") + (stable ? "stable" : "NOT stable") + ", but on " + what + ": " + sc.why};
  return {true, std::string(stable ? "stable" : "NOT stable") + ": " + what + " rebuilt from the model; " + sc.why};
}

}  // namespace hapstab::check
