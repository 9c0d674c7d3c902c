// hapstab/check/multidof_coupling_symmetric_check.hpp -- the checker of a
// `multidof-coupling-symmetric` certificate (`hapstab multidof design --scene S --certificate FILE`
// where V was designed on the split of identical DOFs and the lifted order is above 40): the
// designed, decentralised V meets Theorem 4 of paper 000 through Theorem 5, shown block by block.
//
// The model: the multidof-feasible-symmetric kind's and `coupling_blocks`, one {A, B, C, D} per DOF
// in DOF order (V = blockdiag(V_i), each V_i of one input and one output, n_i states). The evidence:
// `classes`; the whole's invariant diagonal multipliers, one value per class: `g` (X = diag(g)),
// `q_E`, `q_V`; `fixed` and `zero_sum` (the split's points, as multidof-feasible-symmetric); `P_V`,
// one storage per DOF block. The theorem:
//   (16) by the split (check/multidof_symmetric_check.hpp, its hypotheses (h1)-(h3) verified): with
//   each block's X, Q_E, Q_V one positive multiple of the image S^T diag(.) S of the whole's
//   (k_c times on the fixed space; a zero-sum block's Helmert images are multiples too), the lift's
//   scalings make the block points one point of the whole's (16) with exactly X = diag(g), Q_E =
//   diag(q_E), Q_V = diag(q_V); g >= 1 and q_V > 0 are verified on the whole's values.
//   Lemma 1 for V-hat at that X and Q_V: V, K = (T/2) Delta_D^-1, X and Q_V are block diagonal by
//   DOF, so V-hat's Lemma 1 matrix F(blockdiag(P_V,i)) is blockdiag(F_i(P_V,i)) after a permutation
//   of V-hat's states (paper 000's claim 000.thm6.blockwise_lemma1): it holds iff it holds for every
//   DOF's V-hat_i at (g_c, q_V,c), c that DOF's class -- each checked by check/multidof_coupling_check.hpp's
//   Lemma 1 test. V itself need not be symmetric.
//   Then Theorem 5 gives Theorem 4's conditions for V, as for multidof-coupling.
// Not part of the claim: Assumption 1, and the loop as written with V.
// Size: m <= 512 DOFs; each split block's N + m <= 160; each V_i's n_i + 1 <= 160.
//
// Implements: paper 000 (12), (14), (16), (17), Lemma 1, Theorem 4, Theorem 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_multidof_coupling_symmetric(const nlohmann::json& certificate);

}  // namespace hapstab::check
