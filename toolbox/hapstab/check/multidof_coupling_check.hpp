// hapstab/check/multidof_coupling_check.hpp -- the checker of a `multidof-coupling` certificate
// (`hapstab multidof design --scene S --certificate FILE`): the coupling V the model gives (the
// designed one, exactly) meets Theorem 4 of paper 000 through Theorem 5.
//
// The model: the multidof-feasible kind's (check/multidof_model.hpp: T, the delay n, E's entries as
// written, the devices' levels Delta_D, the operators) and `coupling` {A, B, C, D}, V's realisation
// (nV states, m x m). The evidence: the multidof-feasible kind's point (A, B, C, D of E-hat, P, X,
// Q_E, Q_V) and P_V ((nV + m) x (nV + m)). The theorem:
//   Theorem 5 (paper 000): if (16) holds at (P, X, Q_E, Q_V), then with Gamma = sqrt(X) the haptic
//   loop is stable (under Assumption 1) for every V whose V-hat^Gamma is Delta-OSP with Delta >=
//   Gamma^-1 Q_V Gamma^-1 -- Theorem 4's conditions 1)-3).
//   Lemma 1 for V-hat^Gamma at Delta = Gamma^-1 Q_V Gamma^-1, after the congruence diag(I, Gamma)
//   (X = Gamma^2; Gamma itself may be irrational, X is not): a storage P_V > 0 with
//     F = [[A^T P_V A - P_V + C^T Q_V C, A^T P_V B - C^T X/2 + C^T Q_V D],
//          [.,                          B^T P_V B - (X D + D^T X)/2 + D^T Q_V D]] <= 0
//   on V-hat's realisation (17) with Gamma = I:
//     A = [[A_V, -B_V/T], [0, 0]], B = [[B_V/T], [I]], C = [C_V, (K - D_V)/T], D = (D_V - K)/T,
//   K = (T/2) Delta_D^-1 (12). (V-hat(1) = 0, so F is singular: Lemma 1 holds non-strictly, the
//   dissipation inequality sum y^T X u >= sum y^T Q_V y - P_V's storage at the start.)
// Verified, in rational arithmetic: (16) at the point by the multidof-feasible kind's test
// (check/multidof_feasible_check.hpp: the realisation is the model's E-hat, P > 0, M1 <= 0, (14) > 0,
// Q_V > 0, X = diag(g) with g >= 1 per operator); every device level > 0 (K defined); V-hat built
// here from V and K; P_V = P_V^T > 0 and F <= 0 (check/rational_matrix.hpp).
// So the claim "V meets Theorem 4's conditions" holds for the model as written. Theorem 4 then
// concludes the loop's stability under Assumption 1 (the devices' OSP levels, the operators'
// passivity), which is not part of the claim; nor is the loop as written's own decision.
// Size: E-hat's N + m <= 160 and nV + m <= 160.
//
// Implements: paper 000 (12), (14), (16), (17), Lemma 1, Theorem 4, Theorem 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

#include <string>
#include <vector>

#include "hapstab/check/rational_matrix.hpp"

namespace hapstab::check {

Verdict check_multidof_coupling(const nlohmann::json& certificate);

namespace detail {

/// Lemma 1 for V-hat above: V-hat (17) built from V = (AV, BV, CV, DV) (m x m, nV states) and K =
/// (T/2) diag(delta)^-1, then P_V = P_V^T > 0 and F <= 0 at X, Q_V (m x m). "" when it holds, else
/// what fails; InputError when a level is <= 0 or P_V (named `where`) is not (nV + m) square.
std::string vhat_lemma1_fails(const rational_matrix::Mat& AV, const rational_matrix::Mat& BV, const rational_matrix::Mat& CV,
                              const rational_matrix::Mat& DV, const std::vector<rational>& delta, const rational& T,
                              const rational_matrix::Mat& X, const rational_matrix::Mat& QV, const rational_matrix::Mat& PV,
                              const std::string& where);

}  // namespace detail

}  // namespace hapstab::check
