// hapstab/check/stability_check.cpp -- see stability_check.hpp.
#include "hapstab/check/stability_check.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
constexpr long max_degree = 2000;

RF parse_field(const nlohmann::json& model, const char* key, char variable, const rational& T,
               const std::map<std::string, rational>& params) {
  const std::string where = std::string("model.") + key;
  if (!model.at(key).is_string()) throw InputError(where + ": not a string (an expression)");
  ParseOptions po;
  po.variable = variable;
  po.T = T;
  po.parameters = params;
  try {
    const TransferFunction t = parse_tf(model.at(key).get<std::string>(), po);
    if (t.is_discrete() != (variable == 'z'))
      throw InputError(std::string("expected a transfer function in ") + variable);
    return t.H;
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

/// Nd with P_d = Nd/(z - 1)^k for P_eff = N(s)/s^k (header: Z{l^m} by S_m = -z S'_{m-1}).
P sampled_numerator(const P& N, int k, const rational& T) {
  const RF z(P{rational(0), rational(1)});
  RF S = z / RF(P{rational(-1), rational(1)});  // S_0 = z/(z - 1)
  RF Y(rational(0));
  rational Tm(1), fact(1);
  std::vector<RF> Sm{S};
  for (int m = 1; m <= k; ++m) Sm.push_back(-(z * Sm.back().derivative()));
  for (int m = 1; m <= k; ++m) {
    Tm *= T;
    fact *= m;
    const rational b = N.coeff(k - m);  // the coefficient of s^(k-m): b / s^(m+1) in P_eff/s
    if (b != 0) Y += RF(b * Tm / fact) * Sm[static_cast<size_t>(m)];
  }
  const RF Pd = RF(P{rational(-1), rational(1)}) / z * Y;
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(k));
  const auto [q, rem] = divmod(Dk, Pd.den());
  if (!rem.is_zero()) throw InputError("model.plant: the sampled device's denominator is not (z - 1)^k (checker defect)");
  return Pd.num() * q;
}

struct Model {
  P c;               // the characteristic polynomial, the checker's own
  std::string text;  // what was checked
};

Model characteristic(const nlohmann::json& model) {
  detail::only_fields(model, {"plant", "H", "operator", "set", "T", "delay"}, "model");
  for (const char* key : {"plant", "H"})
    if (!model.contains(key)) throw InputError(std::string("model.") + key + ": missing");
  const rational T = detail::exact_field(model, "T", "model");
  if (T <= 0) throw InputError("model.T: the sample period must be > 0, got " + T.str());
  if (!model.contains("delay") || !model.at("delay").is_number_integer())
    throw InputError("model.delay: missing or not an integer (n in z^-n)");
  const long n = model.at("delay").get<long>();
  if (n < 0 || n > 100000) throw InputError("model.delay: " + std::to_string(n) + " is outside [0, 100000]");
  std::map<std::string, rational> params;
  if (model.contains("set")) {
    const auto& sets = model.at("set");
    if (!sets.is_object()) throw InputError("model.set: must be an object {NAME: \"p/q\"}");
    for (auto it = sets.begin(); it != sets.end(); ++it) params[it.key()] = detail::exact_string(it.value(), "model.set." + it.key());
  }
  RF dev = parse_field(model, "plant", 's', T, params);
  if (dev.is_zero()) throw InputError("model.plant: zero (the device does not move)");
  if (model.contains("operator")) {
    const RF s(P{rational(0), rational(1)});
    const RF one = RF(rational(1)) + s * parse_field(model, "operator", 's', T, params) * dev;
    if (one.is_zero()) throw InputError("model.operator: 1 + s Z_op P is zero");
    dev = dev / one;
  }
  if (dev.num().degree() >= dev.den().degree()) throw InputError("model.plant: the device is not strictly proper");
  const int k = dev.den().degree();
  for (int i = 0; i < k; ++i)
    if (dev.den().coeff(i) != 0)
      throw InputError("model.plant: the device has a pole off s = 0 (e^{pT} is transcendental): this checker handles "
                       "devices with every pole at s = 0 only");
  const P N = dev.num() * P(rational(1) / dev.den().leading());
  const RF H = parse_field(model, "H", 'z', T, params);
  if (H.num().degree() > H.den().degree() + n) throw InputError("model.H: z^-n H(z) is not causal");
  if (H.den().degree() + n + k > max_degree)
    throw InputError("model: the characteristic polynomial has degree " + std::to_string(H.den().degree() + n + k) +
                     ", beyond this checker's limit of " + std::to_string(max_degree));
  std::vector<rational> zn(static_cast<size_t>(n) + 1, rational(0));
  zn.back() = 1;
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(k));
  return {P(zn) * H.den() * Dk + H.num() * sampled_numerator(N, k, T), "degree " + std::to_string(k) + " device, delay " + std::to_string(n)};
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
  using detail::object_field;
  detail::only_fields(cert, {"certificate", "version", "kind", "model", "claim", "evidence", "produced_by"}, "certificate");
  const nlohmann::json& model = object_field(cert, "model", "certificate");
  const nlohmann::json& claim = object_field(cert, "claim", "certificate");
  const nlohmann::json& evidence = object_field(cert, "evidence", "certificate");
  detail::only_fields(claim, {"quantity", "status", "stable"}, "claim");
  detail::only_fields(evidence, {"charpoly"}, "evidence");
  if (!claim.contains("status") || !claim.at("status").is_string() ||
      (claim.at("status") != "exact" && claim.at("status") != "certified"))
    throw InputError("claim.status: missing or neither \"exact\" nor \"certified\"");
  if (!claim.contains("stable") || !claim.at("stable").is_boolean()) throw InputError("claim.stable: missing or not true/false");
  const bool stable = claim.at("stable").get<bool>();
  if (!evidence.contains("charpoly")) throw InputError("evidence.charpoly: missing");
  const Model m = characteristic(model);
  if (auto why = differs(evidence.at("charpoly"), m.c)) return {false, *why};
  const SchurCohn sc = schur_cohn(m.c);
  const std::string what = "the characteristic polynomial (degree " + std::to_string(m.c.degree()) + ", " + m.text + ")";
  if (sc.stable != stable)
    return {false, std::string("claim: ") + (stable ? "stable" : "NOT stable") + ", but on " + what + ": " + sc.why};
  return {true, std::string(stable ? "stable" : "NOT stable") + ": " + what + " rebuilt from the model; " + sc.why};
}

}  // namespace hapstab::check
