// hapstab/check/multidof_feasible_check.hpp -- the checker of a `multidof-feasible` certificate
// (`hapstab multidof analyze --scene S --certificate FILE` where (16) was proven feasible): paper
// 000's Theorem 5 program (16) has the point (P, X, Q_E, Q_V) on the realisation (A, B, C, D) of
// E-hat that the evidence gives, and that realisation is the model's E-hat as written.
//
// The model is the multidof-witness kind's (check/multidof_model.hpp): T, the delay n, E's entries
// as written with domain, method and gain, the parameters, the devices' levels Delta_D, the
// operators. The evidence: A (N x N), B (N x m), C (m x N), D (m x m), P (N x N), X, Q_E, Q_V
// (m x m), every entry a "p/q" string. Verified, in rational arithmetic:
//   (r) C (zI - A)^-1 B + D = T z/(z - 1) z^-n g E(z) entry by entry, as rational functions: both
//       sides are quotients of degree at most N + 1 and n + d + 1 (d: an entry's degree as written,
//       s-entries homogenised), so their cross-multiplied difference has degree <= N + n + d + 1
//       and vanishes identically when it vanishes at N + n + d + 2 points; the checker uses
//       z = 2, 3, ... (skipping z where zI - A is singular or E has a pole);
//   (16) P = P^T > 0; M1 = [[A^T P A - P, A^T P B - C^T X/2], [., B^T P B - (X D + D^T X)/2 - Q_E]]
//       <= 0; (14) [[Delta_D X - Q_E, -Q_E], [-Q_E, Q_V - Q_E]] > 0; Q_V > 0; X = diag(g_o(i)), one
//       g_o >= 1 per operator (9). Definiteness by symmetric elimination without pivoting: > 0 iff
//       every pivot is > 0 (Sylvester); >= 0 iff no pivot is < 0 and a zero pivot has its whole
//       remaining row 0 (a PSD matrix with a zero diagonal entry has that row 0; Schur complements
//       of PSD matrices are PSD).
// So the claim "(16) is feasible" holds for E-hat as the model writes it, on that realisation;
// what Theorem 5 concludes from it (Assumption 1, the loop's hidden modes) is not part of the claim.
// Size: N + m <= 160 (exact elimination on matrices of order N + m).
//
// Implements: paper 000 (9), (11), (14), (16), Theorem 5.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/multidof_model.hpp"

namespace hapstab::check {

Verdict check_multidof_feasible(const nlohmann::json& certificate);

namespace detail {

/// The claim {status: "exact", KEY: a boolean} of a multi-DOF certificate, its model and evidence
/// holding only the fields named (InputError naming the field otherwise): the boolean.
bool exact_boolean_claim(const Parts& p, const std::string& key, std::initializer_list<const char*> model_fields,
                         std::initializer_list<const char*> evidence_fields);

/// The model of the multi-DOF kinds (check/multidof_model.hpp): T and the delay, E's entries as
/// written, the levels Delta_D and each DOF's operator (InputError naming the field).
struct WholeModel {
  PeriodDelay pd;
  multidof_model::Environment env;
  std::vector<rational> delta;
  std::vector<size_t> owner;
};
WholeModel read_whole_model(const Parts& p);

/// The evidence of one point: the realisation (A, B, C, D) and (P, X, Q_E, Q_V), exact.
struct FeasiblePoint {
  std::vector<std::vector<rational>> A, B, C, D, P, X, QE, QV;
};
/// `ev` (named `where` in errors) as a FeasiblePoint of an m-DOF environment; InputError naming the
/// field (a missing or extra key, a size, an order N + m beyond 160).
FeasiblePoint read_feasible_point(const nlohmann::json& ev, const std::string& where, size_t m);
/// "" when (r) and (16) above hold at `pt` for `env`, the levels `delta` and the operators `owner`;
/// else what fails. g_at_least_one: X's g >= 1 ((9), a whole scene); else g > 0 (a block of the
/// symmetric kind, which the lift scales: check/multidof_symmetric_check.hpp). `points`: how many
/// points (r) compared.
std::string feasible_point_fails(const multidof_model::Environment& env, const std::vector<rational>& delta,
                                 const std::vector<size_t>& owner, const FeasiblePoint& pt, bool g_at_least_one, long& points);

}  // namespace detail

}  // namespace hapstab::check
