// The checker of a stability-loop-verdicts certificate (header).
#include "hapstab/check/stability_loop_verdicts_check.hpp"

#include <set>
#include <string>

#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

constexpr size_t kMaxVerdicts = 64;  // the bisection asks at most 2 x 10 + 40 values; 64 leaves room

// The part's model must be the scene as written with p set to `at` and nothing else moved.
void require_part_model(const nlohmann::json& part, const nlohmann::json& model, const std::string& name, const nlohmann::json& at,
                        const std::string& where) {
  const nlohmann::json& pm = detail::object_field(part, "model", where);
  nlohmann::json want = {{"scene", model.at("scene")}, {"set", model.at("set")}};
  want["set"][name] = at;
  if (pm != want)
    throw InputError(where + ".model: not the scene as written with its set and " + name + " = " + at.get<std::string>() +
                     " (each verdict must be about the model of this certificate)");
}

}  // namespace

Verdict check_stability_loop_verdicts(const nlohmann::json& c) {
  const auto [model, claim, evidence] = detail::certificate_parts(c);
  detail::only_fields(model, {"scene", "set", "name"}, "model");
  detail::only_fields(claim, {"quantity", "status", "verdicts"}, "claim");
  detail::only_fields(evidence, {"verdicts"}, "evidence");
  if (!model.contains("scene") || !model.at("scene").is_string()) throw InputError("model.scene: missing or not a string");
  if (!model.contains("name") || !model.at("name").is_string() || model.at("name").get<std::string>().empty())
    throw InputError("model.name: missing or not a parameter's name");
  const std::string name = model.at("name").get<std::string>();
  const nlohmann::json& set = detail::object_field(model, "set", "model");
  if (set.contains(name)) throw InputError("model.set: gives " + name + " a value (the parameter whose verdicts are claimed)");
  if (!claim.contains("status") || claim.at("status") != "certified") throw InputError("claim.status: missing or not \"certified\"");
  if (!claim.contains("verdicts") || !claim.at("verdicts").is_array() || claim.at("verdicts").empty() ||
      claim.at("verdicts").size() > kMaxVerdicts)
    throw InputError("claim.verdicts: not an array of 1.." + std::to_string(kMaxVerdicts) + " verdicts");
  const nlohmann::json& verdicts = claim.at("verdicts");
  if (!evidence.contains("verdicts") || !evidence.at("verdicts").is_array() || evidence.at("verdicts").size() != verdicts.size())
    throw InputError("evidence.verdicts: not an array of one certificate per claimed verdict");
  std::set<rational> seen;
  std::string reason;
  long stable = 0;
  for (size_t i = 0; i < verdicts.size(); ++i) {
    const std::string at = "claim.verdicts[" + std::to_string(i) + "]", ev = "evidence.verdicts[" + std::to_string(i) + "]";
    const nlohmann::json& v = verdicts[i];
    if (!v.is_object()) throw InputError(at + ": not an object {at, stable}");
    detail::only_fields(v, {"at", "stable"}, at);
    const rational value = detail::exact_field(v, "at", at);
    if (!seen.insert(value).second) throw InputError(at + ".at: " + value.str() + " twice");
    if (!v.contains("stable") || !v.at("stable").is_boolean()) throw InputError(at + ".stable: missing or not true/false");
    const nlohmann::json& part = evidence.at("verdicts")[i];
    if (!part.is_object() || !part.contains("kind") || !part.at("kind").is_string())
      throw InputError(ev + ": not a certificate object with a kind");
    const std::string kind = part.at("kind").get<std::string>();
    if (kind != "stability-loop" && kind != "stability-loop-symmetric")
      throw InputError(ev + ".kind: '" + kind + "', not stability-loop or stability-loop-symmetric");
    if (!part.contains("certificate") || part.at("certificate") != "hapstab" || !part.contains("version") || part.at("version") != 1)
      throw InputError(ev + ": not a hapstab certificate of version 1");
    require_part_model(part, model, name, v.at("at"), ev);
    const nlohmann::json& pc = detail::object_field(part, "claim", ev);
    if (!pc.contains("stable") || pc.at("stable") != v.at("stable"))
      throw InputError(ev + ".claim.stable: not the verdict claimed at " + name + " = " + value.str());
    Verdict pv;
    try {
      pv = kind == "stability-loop" ? check_stability_loop(part) : check_stability_loop_symmetric(part);
    } catch (const InputError& e) {
      throw InputError(ev + ": " + e.what());
    }
    if (!pv.verified) return {false, ev + " (" + name + " = " + value.str() + "): " + pv.reason};
    stable += v.at("stable").get<bool>() ? 1 : 0;
  }
  return {true, std::to_string(verdicts.size()) + " verdicts of the scene's loop along " + name + " (" + std::to_string(stable) +
                    " stable, " + std::to_string(static_cast<long>(verdicts.size()) - stable) +
                    " NOT stable), each a stability-loop certificate verified on the scene with " + name + " set"};
}

}  // namespace hapstab::check
