// hapstab/check/certificate.hpp -- verifying a certificate (issue 47; DESIGN.md "Producers and
// checkers"): a JSON file that holds the model as written, a claim about it, and the evidence.
// The checker trusts only numeric/, poly/ and lti/ (exact rationals, polynomials, the expression
// parser); it never calls the code that produced the claim. One small checker per kind:
//   bound   b* of paper 001 (45)/(54), any delay          check/bound_check.hpp
//   bound-max  the largest K with b*(K) < b (bound --max) check/bound_max_check.hpp
//   limit-cycle  a periodic orbit of paper 002's loop (4) check/limit_cycle_check.hpp
//   multidof-coupling  a designed V meets Theorem 4 (16 + Lemma 1 for V-hat)  check/multidof_coupling_check.hpp
//   multidof-coupling-symmetric  the same on the split of identical DOFs  check/multidof_coupling_symmetric_check.hpp
//   multidof-facial  (16) infeasible: no X makes X E(1) symmetric  check/multidof_facial_check.hpp
//   multidof-feasible  Theorem 5's (16) has a point, paper 000  check/multidof_feasible_check.hpp
//   multidof-feasible-symmetric  the same by the split of identical DOFs  check/multidof_symmetric_check.hpp
//   multidof-witness  Theorem 5's (16) infeasible, paper 000  check/multidof_witness_check.hpp
//   passivity-level  SISO ISP/OSP level (paper 000)       check/passivity_level_check.hpp
//   passivity-level-mimo  MIMO ISP level of A, B, C, D    check/passivity_level_mimo_check.hpp
//   r       r(jw) = T/(e^{jwT} - 1) of paper 001 (44)     check/r_check.hpp
//   stability  the one-DOF sampled loop, Schur-Cohn       check/stability_check.hpp
//   stability-max  its largest stable gain (stability --max)  check/stability_max_check.hpp
//   wedge   paper 002 (25), (21) and its assumptions      check/wedge_check.hpp
// Outcomes: Verdict{verified, what was shown} or Verdict{refuted, what failed}; a certificate that
// is not well formed (a missing or malformed field, an unknown kind) is an InputError naming the
// field -- `hapstab check` exits 0, 1, 2 for the three. docs/certificates.md has the format.
#pragma once

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/tf.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::check {

struct Verdict {
  bool verified = false;
  std::string reason;  ///< what was verified, or what failed
};

/// The certificate's kind decides the checker. InputError (naming the field) when malformed.
Verdict check_certificate(const nlohmann::json& certificate);

/// Reads FILE (a regular file of at most 64 MB of JSON: a 512-DOF model written out is 23 MB) and checks it; InputError when it cannot
/// be read or parsed.
Verdict check_file(const std::string& path);

namespace detail {
/// The exact rational of field `key` of `obj`: a string "p/q" or "p" (integers in decimal, q > 0)
/// and nothing else; InputError naming `where`.`key` otherwise (missing, not a string, malformed).
rational exact_field(const nlohmann::json& obj, const std::string& key, const std::string& where);
/// The string "p/q" or "p" as an exact rational, or InputError naming `what`.
rational exact_string(const nlohmann::json& v, const std::string& what);
/// obj[key] as an integer in [lo, hi] (a JSON integer; one above the range of long, which
/// nlohmann::json would wrap to a negative number, is outside it); InputError naming where.key.
long integer_field(const nlohmann::json& obj, const std::string& key, const std::string& where, long lo, long hi);
/// obj[key] as a matrix of exact rationals (an array of rows of "p/q" strings, equal lengths, at most
/// max_dim rows and columns); InputError naming where.key[i][j] otherwise.
std::vector<std::vector<rational>> exact_matrix(const nlohmann::json& obj, const std::string& key, const std::string& where,
                                                size_t max_dim);
/// obj[key] as an object; InputError naming where.key when missing or not an object.
const nlohmann::json& object_field(const nlohmann::json& obj, const std::string& key, const std::string& where);
/// InputError naming where.KEY when obj has a key outside `known`: a field a checker does not read
/// (a fractional delay, say) would make it verify another model than the one written.
void only_fields(const nlohmann::json& obj, std::initializer_list<const char*> known, const std::string& where);
/// A certificate's three parts, each an object (InputError naming the one that is missing or not
/// an object); the top-level fields must be the known ones (certificate, version, kind, model,
/// claim, evidence, produced_by).
struct Parts {
  const nlohmann::json& model;
  const nlohmann::json& claim;
  const nlohmann::json& evidence;
};
Parts certificate_parts(const nlohmann::json& certificate);
/// A claimed range of one number: claim.status "exact" with claim.value (lo = hi) or "certified"
/// with claim.lo, claim.hi; with may_be_infinite also "infinite": true (then no value, lo, hi or
/// printed number beside it). The printed decimals (claim.printed_lo, printed_hi, printed) must be
/// the numbers claimed (what a reader sees is what is proven). InputError when malformed; `refuted`
/// says why the claim is false on its face (lo > hi, a printed number that is not the one claimed).
struct ClaimRange {
  std::string status;
  rational lo = 0, hi = 0;
  bool infinite = false;
  std::optional<std::string> refuted;
};
ClaimRange claim_range(const nlohmann::json& claim, bool may_be_infinite = false);
/// A claim of status "upper_bound" (a level <= hi only): {quantity, status, hi[, printed_hi]}, its
/// printed decimal the number claimed; status "upper_bound" and lo unused (ClaimRange's refuted set
/// when printed_hi is not hi). InputError when malformed.
ClaimRange upper_bound_claim(const nlohmann::json& claim);
/// A claim of status "lower_bound" ({lo[, printed_lo]}: a level >= lo only) or "bounds" (the same
/// and {hi[, printed_hi]}: lo <= level <= hi), each printed decimal the number claimed (refuted
/// when not). hi is set only for "bounds" (`has_hi`). InputError when malformed.
ClaimRange lower_bound_claim(const nlohmann::json& claim, bool& has_hi);
/// x to 12 significant digits (the checkers' reasons).
std::string decimal(const rational& x);
/// |printed - x| <= half a unit in the last digit of `printed` (a decimal "-?D+(.D+)?(e[+-]?D+)?",
/// |exponent| < 10^4): x rounds to the printed decimal. nullopt when `printed` is not such a decimal.
std::optional<bool> rounds_to(const std::string& printed, const rational& x);
/// model.T (> 0) and model.delay (an integer n in [0, 100000]); InputError naming the field.
struct PeriodDelay {
  rational T = 1;
  long n = 0;
};
PeriodDelay read_period_delay(const nlohmann::json& model);
/// model.set's exact parameters ({NAME: "p/q"}; none when absent); InputError naming model.set.
std::map<std::string, rational> model_parameters(const nlohmann::json& model);
/// The model's H(z) as written, one of two ways: model.H, an expression parsed in z with sample
/// period T and model.set's exact parameters ({NAME: "p/q"}); or model.num and model.den, its
/// coefficients in descending powers of z ("p/q" each; `--num/--den`, a .mat's num and den), with
/// no H and no set beside them. InputError naming the field (also when H is not in z, and when H
/// as written cancels a pole on or outside the circle: refused, or for `bound` (allow_marginal)
/// refused unless H as written is marginally stable, as the producer does; lti/parse.hpp).
TransferFunction model_tf(const nlohmann::json& model, const rational& T, HiddenPoles hidden_poles = HiddenPoles::refuse);
}  // namespace detail

}  // namespace hapstab::check
