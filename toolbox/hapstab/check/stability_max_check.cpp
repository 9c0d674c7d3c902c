// hapstab/check/stability_max_check.cpp -- see stability_max_check.hpp.
#include "hapstab/check/stability_max_check.hpp"

#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/affine.hpp"
#include "hapstab/check/loop_model.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/reciprocal.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
constexpr int max_loop_degree = 150;  // of c in z; D has degree <= 2d in K

struct Family {
  std::string K;
  detail::LoopDevice device;
  detail::Affine h;
  P c0, c1;  // c(z; K) = c0 + K c1, deg c1 < deg c0
};

Family read_family(const nlohmann::json& model, bool scene_device) {
  detail::only_fields(model, {"plant", "H", "operator", "set", "name", "T", "delay"}, "model");
  if (!model.contains("name") || !model.at("name").is_string() || model.at("name").get<std::string>().empty())
    throw InputError("model.name: missing or not a string (the parameter maximised)");
  Family f;
  f.K = model.at("name").get<std::string>();
  f.device = detail::read_loop_device(model, false, scene_device);  // the device may not name K: it has no value
  if (f.device.params.count(f.K)) throw InputError("model.set: gives the parameter model.name = " + f.K + " a value");
  if (!model.contains("H") || !model.at("H").is_string()) throw InputError("model.H: missing or not a string (the expression of H(z))");
  ParseOptions po;
  po.variable = 'z';
  po.T = f.device.T;
  po.parameters = f.device.params;
  f.h = detail::prove_affine(model.at("H").get<std::string>(), po, f.K);
  const long n = f.device.n;
  for (const RF* H : {&f.h.H0, &f.h.H1})
    if (H->num().degree() > H->den().degree() + n)
      throw InputError("model.H: z^-n H" + std::string(H == &f.h.H0 ? "0" : "1") + "(z) is not causal (H = H0 + " + f.K + " H1)");
  const P &L0 = f.h.H0.den(), &L1 = f.h.H1.den();
  const P g = gcd(L0, L1), L = L0 * divmod(L1, g).first;  // lcm(L0, L1)
  if (L.degree() + n + f.device.k > max_loop_degree)
    throw InputError("model: the characteristic polynomial has degree " + std::to_string(L.degree() + n + f.device.k) +
                     ", beyond this checker's limit of " + std::to_string(max_loop_degree));
  f.c0 = detail::loop_polynomial(f.device, f.h.H0.num() * divmod(L, L0).first, L);
  f.c1 = f.h.H1.num() * divmod(L, L1).first * f.device.Nd;
  if (f.c1.degree() >= f.c0.degree())
    throw InputError("model: c1 has degree >= that of c0 (the leading coefficient would move with " + f.K + "): beyond this checker");
  return f;
}

/// c(z; k) = c0 + k c1 (the family) and c_k (the loop at k as the `stability` kind builds it).
P family_at(const Family& f, const rational& k) { return f.c0 + f.c1 * P(k); }
P loop_at(const Family& f, const rational& k) {
  const RF H = f.h.H0 + RF(k) * f.h.H1;
  return detail::loop_polynomial(f.device, H.num(), H.den());
}

/// An evidence field read for this claim, or InputError naming it; `wanted` false: it must be absent.
std::optional<rational> evidence_point(const nlohmann::json& evidence, const char* key, bool wanted) {
  if (!wanted) {
    if (evidence.contains(key)) throw InputError(std::string("evidence.") + key + ": not read for this claim (it would not be checked)");
    return std::nullopt;
  }
  return detail::exact_field(evidence, key, "evidence");
}

/// nullopt when D has no root in (0, b) (or (0, b] when closed; b = nullopt: (0, inf)), else why not.
std::optional<std::string> crossing_free(const P& D, const std::optional<rational>& b, bool closed, const std::string& K) {
  const std::string where = "(0, " + (b ? detail::decimal(*b) : std::string("inf")) + (closed ? "]" : ")");
  if (D.is_zero()) return "D(" + K + ") = Res_z(c, c*) vanishes identically: a pair b, 1/b of roots for every " + K;
  const int n = detail::roots_between(D, rational(0), b, closed);
  if (n > 0)
    return "D(" + K + ") = Res_z(c, c*) (degree " + std::to_string(D.degree()) + " in " + K + ") has " + std::to_string(n) +
           " root(s) in " + where + ": a root may meet the unit circle there";
  return std::nullopt;
}

}  // namespace

Verdict check_stability_max(const nlohmann::json& cert) {
  const auto [written, claim, evidence] = detail::certificate_parts(cert);
  detail::only_fields(claim, {"quantity", "status", "infinite", "value", "lo", "hi", "printed", "printed_lo", "printed_hi"}, "claim");
  detail::only_fields(evidence, {"stable_at", "unstable_at"}, "evidence");
  const Family f = read_family(detail::scene_loop_model(written, true), written.contains("scene"));  // a scene: its one-DOF loop, read here
  const std::string& K = f.K;
  const detail::ClaimRange range = detail::claim_range(claim, true);
  if (range.refuted) return {false, *range.refuted};
  const rational &lo = range.lo, &hi = range.hi;
  if (!range.infinite && lo < 0) return {false, "claim: lo = " + lo.str() + " < 0 (K_max >= 0 by its definition)"};
  const bool zero = !range.infinite && hi == 0;
  const std::optional<rational> K0 = evidence_point(evidence, "stable_at", range.infinite || lo > 0);
  const std::optional<rational> e = evidence_point(evidence, "unstable_at", zero);
  const P D = detail::reciprocal_resultant(f.c0, f.c1);
  std::vector<std::string> shown;
  const std::string family = "c(z; " + K + ") of degree " + std::to_string(f.c0.degree()) + ", D(" + K + ") = Res_z(c, c*) of degree " +
                             (D.is_zero() ? std::string("-inf (zero)") : std::to_string(D.degree()));

  // ---- lower end (or +inf): stable at K0, and D has no root in (0, lo) (or (0, inf))
  if (K0) {
    const std::string at = K + " = " + detail::decimal(*K0);
    if (*K0 <= 0 || (!range.infinite && *K0 >= lo))
      return {false, "evidence.stable_at = " + detail::decimal(*K0) + " is not in (0, " + (range.infinite ? std::string("inf") : detail::decimal(lo)) + ")"};
    const SchurCohn sc = schur_cohn(family_at(f, *K0));
    const std::string lower = range.infinite ? K + "_max = +inf" : K + "_max >= " + detail::decimal(lo);
    if (!sc.stable) return {false, lower + " fails: NOT stable at " + at + ": " + sc.why};
    const std::optional<rational> end = range.infinite ? std::nullopt : std::optional<rational>(lo);
    if (auto why = crossing_free(D, end, false, K)) return {false, lower + " not shown: " + *why};
    shown.push_back("stable at " + at + " (" + sc.why + ") and D has no root in (0, " + (end ? detail::decimal(*end) : std::string("inf")) +
                    "): stable on all of it");
  }
  if (range.infinite)
    return {true, K + "_max = +inf: " + shown.front() + " (" + family + "; H affine in " + K + ", degree bound " + std::to_string(f.h.D) + ")"};

  // ---- upper end: NOT stable at hi (the loop at hi), or K_max = 0 on (0, e]
  if (!zero) {
    const SchurCohn sc = schur_cohn(loop_at(f, hi));
    if (sc.stable) return {false, K + "_max <= " + detail::decimal(hi) + " not shown: the loop at " + K + " = " + detail::decimal(hi) + " is stable (" + sc.why + ")"};
    shown.push_back("NOT stable at " + K + " = " + detail::decimal(hi) + " (" + sc.why + ")");
  } else {
    if (*e <= 0) return {false, "evidence.unstable_at = " + detail::decimal(*e) + " is not > 0"};
    const SchurCohn sc = schur_cohn(family_at(f, *e));
    if (sc.stable) return {false, K + "_max = 0 not shown: c(z; " + K + " = " + detail::decimal(*e) + ") is stable (" + sc.why + ")"};
    if (!D.is_zero())
      if (auto why = crossing_free(D, *e, true, K)) return {false, K + "_max = 0 not shown: " + *why};
    shown.push_back("NOT stable at " + K + " = " + detail::decimal(*e) + " (" + sc.why + ") and " +
                    (D.is_zero() ? std::string("D = 0 identically: NOT stable for every ") + K
                                 : "D has no root in (0, " + detail::decimal(*e) + "]: NOT stable on all of it"));
  }
  std::string all;
  for (const auto& s : shown) all += (all.empty() ? "" : "; ") + s;
  const std::string what = K + "_max " + (range.status == "exact" ? "= " + lo.str() : "in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "]");
  return {true, what + ": " + all + " (" + family + "; H affine in " + K + ", degree bound " + std::to_string(f.h.D) + ")"};
}

}  // namespace hapstab::check
