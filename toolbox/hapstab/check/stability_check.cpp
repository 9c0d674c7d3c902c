// hapstab/check/stability_check.cpp -- see stability_check.hpp.
#include "hapstab/check/stability_check.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/loop_model.hpp"
#include "hapstab/check/reciprocal.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
constexpr long max_charpoly_degree = 2000;
constexpr long max_family_degree = 150;  // D(E) from 2d + 1 exact resultants of degree d (as stability-max)

struct LoopCharpoly {
  P c;                     // the characteristic polynomial, the checker's own (every pole at s = 0)
  std::optional<P> c1;     // with a pole off s = 0: c is c0 of c(z; E) = c0 + E c1
  std::optional<rational> x;  // and E = e^x, x = p T
  std::string text;        // what was checked
};

LoopCharpoly characteristic(const nlohmann::json& model) {
  detail::only_fields(model, {"plant", "H", "operator", "set", "T", "delay"}, "model");
  const detail::LoopDevice d = detail::read_loop_device(model, true);
  const RF H = detail::parse_model_field(model, "H", 'z', d.T, d.params);
  const int extra = d.pole ? 1 : 0;
  if (H.num().degree() > H.den().degree() + d.n) throw InputError("model.H: z^-n H(z) is not causal");
  if (H.den().degree() + d.n + d.k + extra > (d.pole ? max_family_degree : max_charpoly_degree))
    throw InputError("model: the characteristic polynomial has degree " + std::to_string(H.den().degree() + d.n + d.k + extra) +
                     ", beyond this checker's limit of " + std::to_string(d.pole ? max_family_degree : max_charpoly_degree) +
                     (d.pole ? " with a device pole off s = 0" : ""));
  const std::string text = "degree " + std::to_string(d.k + extra) + " device, delay " + std::to_string(d.n);
  if (!d.pole) return {detail::loop_polynomial(d, H.num(), H.den()), std::nullopt, std::nullopt, text};
  const auto [c0, c1] = detail::loop_family_in_E(d, H.num(), H.den());
  return {c0, c1, *d.pole * d.T, text + ", pole s = " + d.pole->str() + " (E = e^{pT})"};
}

/// Schur stability of c0 + E c1 at the true E = e^x (x rational, != 0): the enclosure [lo, hi] of E
/// is narrowed (Arb, 128 to 8192 bits) until D(E) = Res(c, c*) (check/reciprocal.hpp, a polynomial
/// in E) has no root in [lo, hi]; then no c(.; E), E in [lo, hi], has a root on the unit circle, the
/// number of roots inside is the same for all of them (the degree does not move: deg c1 < deg c0),
/// and Schur-Cohn at E = lo decides every one, the true E among them. D = 0 identically: c and c*
/// share a root for every E, so NOT stable (reciprocal.hpp). E transcendental is never a root of D
/// (rational coefficients), so only the precision can run out: InputError then.
SchurCohn decide_family(const P& c0, const P& c1, const rational& x, std::string& how) {
  if (c1.degree() >= c0.degree())
    throw InputError("model: the E-part of the characteristic polynomial has degree >= c0's (checker defect)");
  const P D = detail::reciprocal_resultant(c0, c1);
  if (D.is_zero()) {
    how = "D(E) = Res(c, c*) = 0 for every E: c and c* share a root";
    return {false, "a pair of roots b, 1/b (or a root on the circle) for every E"};
  }
  for (long bits = 128; bits <= 8192; bits *= 2) {
    const auto [lo, hi] = detail::exp_enclosure(x, bits);
    if (D(lo) == 0 || D(hi) == 0 || detail::roots_between(D, lo, hi, true) != 0) continue;
    how = "E = e^(" + x.str() + ") in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "] (Arb, " + std::to_string(bits) +
          " bits), where D(E) = Res(c, c*) (degree " + std::to_string(D.degree()) + " in E) has no root (Sturm); at E = lo,";
    return schur_cohn(c0 + c1 * P(lo));
  }
  throw InputError("model: the loop is too close to its stability boundary for this checker (e^{pT}'s enclosure at 8192 bits "
                   "still holds a root of D(E))");
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
  const LoopCharpoly m = characteristic(model);
  SchurCohn sc;
  std::string what = "the characteristic polynomial (degree " + std::to_string(m.c.degree()) + ", " + m.text + ")";
  if (m.c1) {  // transcendental E: no polynomial to hand over, the checker derives c0, c1 itself
    if (evidence.contains("charpoly"))
      throw InputError("evidence.charpoly: the device has a pole off s = 0, so the polynomial's coefficients are not rational");
    if (claim.at("status") != "certified") throw InputError("claim.status: with a device pole off s = 0 the verdict is \"certified\"");
    std::string how;
    sc = decide_family(m.c, *m.c1, *m.x, how);
    what = "c(z; E) = c0 + E c1 (degree " + std::to_string(m.c.degree()) + ", " + m.text + ") rebuilt from the model; " + how;
  } else {
    if (!evidence.contains("charpoly")) throw InputError("evidence.charpoly: missing");
    if (auto why = differs(evidence.at("charpoly"), m.c)) return {false, *why};
    sc = schur_cohn(m.c);
  }
  if (sc.stable != stable)
    return {false, std::string("claim: ") + (stable ? "stable" : "NOT stable") + ", but on " + what + ": " + sc.why};
  return {true, std::string(stable ? "stable" : "NOT stable") + ": " + what + (m.c1 ? " " : " rebuilt from the model; ") + sc.why};
}

}  // namespace hapstab::check
