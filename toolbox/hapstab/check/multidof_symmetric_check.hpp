// hapstab/check/multidof_symmetric_check.hpp -- the checker of a `multidof-feasible-symmetric`
// certificate (`hapstab multidof analyze --scene S --certificate FILE` where (16) was proven feasible
// by the split of identical DOFs, multidof/symmetry.hpp): paper 000's Theorem 5 program (16) of the
// whole scene is feasible, shown by one point per block of the split instead of one point of the
// whole (whose order grows with the number of DOFs: 258 states at 128 contacts).
//
// The model is the multidof-feasible kind's (check/multidof_model.hpp), without perturb_C. The
// evidence: `classes` (a partition of the m DOFs), `fixed` (a point of the fixed space's block, one
// DOF per class in the order of `classes`) and `zero_sum` (one {class, point} per class of two DOFs
// or more, in class order); a point is the multidof-feasible kind's evidence (A, B, C, D, P, X, Q_E,
// Q_V). The theorem (multidof/symmetry.hpp, where the producer states and uses it):
//   Hypotheses, each verified here from the model as written, exactly:
//   (h1) every operator has one DOF, so X = diag(g) with one free g per DOF;
//   (h2) the OSP level Delta is the same on every DOF of a class;
//   (h3) E is invariant under every permutation within the classes: E(i, i) = E(a0, a0) for i in
//        class a, and for i != k in classes a, c, E(i, k) = E(a0, a1) (a = c) or E(a0, c0) (a != c),
//        a0, a1 the class's first two DOFs -- compared as reduced rational functions, all m^2 entries.
//   Then E S = S blockdiag(E_f, e_a I_{k_a - 1}) with S the rational basis of class indicators and
//   Helmert vectors, E_f(a, c) = sum_{j in C_c} E(a0, j) and e_a = E(a0, a0) - E(a0, a1): E-hat
//   has a realisation made of the blocks' (A = blockdiag, one copy of e-hat_a's per Helmert vector),
//   on which the congruences blockdiag(I, S) and blockdiag(S, S) turn (16) into the blocks' own
//   programs with X_b = S^T X S, Q_b = S^T Q S (Delta X commutes with S by (h2)). (16) is homogeneous
//   in (P, X, Q_E, Q_V) apart from g >= 1, so points of the blocks with g > 0, scaled (the fixed
//   block's by sigma = max(1, max_c k_c / gamma_c), class a's j-th copy by g_a j (j + 1) / gamma_a),
//   lift to a point of the whole with every g >= 1.
//   Verified: (h1)-(h3); E_f and e_a computed here from the entries as written (not read from the
//   certificate); each block's point by the multidof-feasible kind's test
//   (check/multidof_feasible_check.hpp: its realisation is the block's E-hat = T z/(z - 1) z^-n g
//   E_b(z), P > 0, M1 <= 0, (14) > 0, Q_V > 0, X diagonal) with g > 0 in place of g >= 1.
// So the claim "(16) is feasible" holds for E-hat as the model writes it, on the lifted realisation.
// Size: m <= 512 DOFs (model.environment.E), each block's N + m <= 160.
//
// The split: Gatermann & Parrilo (2004), as in multidof/symmetry.hpp.
//
// Implements: paper 000 (9), (11), (14), (16), Theorem 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

#include <string>
#include <vector>

#include "hapstab/check/multidof_model.hpp"

namespace hapstab::check {

Verdict check_multidof_feasible_symmetric(const nlohmann::json& certificate);

namespace detail {

/// What both split kinds read first: T and the delay, E's entries as written, the levels (every DOF
/// in one operator) and evidence.classes, a partition of the m DOFs (InputError naming the field).
struct SplitModel {
  PeriodDelay pd;
  multidof_model::Environment env;
  std::vector<rational> delta;
  std::vector<std::vector<size_t>> classes;
};
SplitModel read_split_model(const Parts& p);
/// The whole's invariant diagonal multipliers, one value per class: X = diag(g), Q_E, Q_V.
struct SplitMultipliers {
  std::vector<rational> g, qe, qv;
};
/// The theorem above on p's model (env, its levels `delta`) and evidence (`fixed`, `zero_sum`): ""
/// when (h1)-(h3) hold and every block's point holds its (16), else the refutation; InputError when
/// malformed. With `invariant`, each block's X, Q_E, Q_V must moreover be one positive multiple of the
/// image of the whole's (S^T diag S: k_c times on the fixed space; any multiple on a zero-sum block), so
/// the lifted point has exactly these multipliers (check/multidof_coupling_symmetric_check.hpp).
/// `said`: the blocks' account; `blocks`: how many blocks the lifted realisation has.
std::string split_16_fails(const Parts& p, const multidof_model::Environment& env, const std::vector<rational>& delta,
                           const std::vector<std::vector<size_t>>& classes, const SplitMultipliers* invariant,
                           std::string& said, size_t& blocks);

}  // namespace detail

}  // namespace hapstab::check
