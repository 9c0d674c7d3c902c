// hapstab/check/stability_loop_symmetric_check.hpp -- the checker of a `stability-loop-symmetric` certificate:
// the Schur stability of a scene's loop of many identical DOFs (`hapstab stability --scene S --certificate FILE`
// beyond 64 DOFs), shown on the small loops of the split by the permutations of identical DOFs, which this
// checker derives itself from the scene as written (stability_loop_check.hpp's reading, up to 256 DOFs).
//
// Theorem (the isotypic decomposition of stability/symmetry.hpp's header, re-derived for this reading). Let the
// DOFs fall into classes C_1 .. C_r (evidence.classes, a partition, 0-based) such that, exactly:
//   * the DOFs of a class are identical: the same device (m, b, or a one-DOF block as written), the same
//     operators on them, in order (m, b, k summed into the DOF; tf and ss one-port impedances);
//   * E(z) (tf, N x N) is invariant: E_ii = E_{f_a f_a} for i in C_a (f_a the class's first DOF), E_ij =
//     E_{f_a s_a} for i != j both in C_a (s_a its second), E_ij = E_{f_a f_b} for i in C_a, j in C_b, a != b.
// Then every column of E in a class has the same multiset of entries, so the same monic lcm d_b, and the loop
// as built here (stability_loop_check.hpp: column j over d_j) commutes with each permutation within the classes
// acting on the DOFs' blocks of states (plant, operators, E's column, delay buffer). Its closed-loop matrix M
// leaves invariant
//   * the fixed space (each block of states equal across a class): M there is the loop of r DOFs, one per
//     class (its first DOF's device and operators), under E_F with column b over d_b and entries
//     E_F[a][a] = E_{f_a f_a} + (k_a - 1) E_{f_a s_a},  E_F[a][b] = k_b E_{f_a f_b}  (a != b):
//     the force on f_a when every DOF of a class moves alike (the numerators over d_b add);
//   * per class a with k_a >= 2, the zero-sum vectors over its DOFs (k_a - 1 dimensions; blocks of states
//     outside C_a zero): M there is k_a - 1 copies of the one-DOF loop of f_a under e_a = E_{f_a f_a} -
//     E_{f_a s_a}, over d_a (the force on i in C_a is e_a's on its own states; on j outside, E_{j f_a} times a
//     sum that is zero).
// These spaces span the state space (sum_a n_a + sum_a (k_a - 1) n_a = sum_a k_a n_a), so det(zI - M) =
// det(zI - M_F) prod_a det(zI - M_a)^(k_a - 1), and each block's conserved quantities (l^T [A B] = 0, a wall's
// z = 1: invariant subspaces) add the same way: k = k_F + sum_a (k_a - 1) k_a'.
// Evidence: classes, and blocks [{space: "fixed" | "zero-sum", class: a (zero-sum), conserved: k_b (absent:
// 0), P[, w]}], each verified by stability_loop_check.hpp's Stein inertia test on the block's loop built here
// (detail::stein_verdict). Stable: every block (the fixed one and one per class of two DOFs or more), each
// stable, and claim.conserved = k_F + sum_a (k_a - 1) k_a'. NOT stable: one block, NOT stable (its eigenvalue
// outside the circle is one of M's, multiplicity >= 1); claim.conserved absent.
// A [coupling] V (tf, since stop 76) is split the same way: V invariant under the classes (all N^2 entries), the
// fixed space's V_F and each class's zero-sum V as E's, each column over the whole's column lcm of V (the loop
// commutes with the permutations with V in it: the argument is unchanged).
// Refused by name (InputError: beyond this kind): an ss coupling, an ss environment, a device or an operator on
// more than one DOF, more than 256 DOFs. A partition under which the scene is not invariant refutes the
// claim (exit 1, naming the first entry that differs).
// Implements: paper 000 Sec. VI; paper 001 Fig. 1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/scene_model.hpp"

namespace hapstab::check {

namespace detail {
/// The small loops of the header.
struct SymmetricSplit {
  SceneLoop fixed;                  ///< r DOFs, one per class
  std::vector<SceneLoop> zero_sum;  ///< per class (class order); a class of one DOF: an empty loop (unused)
  std::vector<size_t> sizes;        ///< k_a
  /// slot 0: the fixed loop; a + 1: class a's zero-sum loop
  const SceneLoop& block(size_t slot) const { return slot == 0 ? fixed : zero_sum[slot - 1]; }
};
/// evidence.classes: arrays of DOF indices (0-based, each range-checked before it is narrowed); InputError when
/// malformed (split_loop then checks the partition).
std::vector<std::vector<int>> read_classes(const nlohmann::json& evidence, size_t dofs);
/// A block's {space: "fixed" | "zero-sum", class}: its slot (SymmetricSplit::block), its multiplicity (1, or k_a - 1)
/// and its space; InputError when malformed (a class of one DOF has no zero-sum space).
struct BlockSlot {
  size_t slot = 0, copies = 1;
  std::string space;
};
BlockSlot block_slot(const nlohmann::json& blk, const SymmetricSplit& split, const std::string& where);
/// The split of L by `classes`: InputError for what this kind does not take or a malformed partition; nullopt
/// with `why` when L is not invariant under the classes' permutations.
std::optional<SymmetricSplit> split_loop(const SceneLoop& L, const std::vector<std::vector<int>>& classes, std::string& why);
/// The producer's classes: DOFs with the same device, operators and E's diagonal entry, in order of their first
/// DOF (split_loop then says whether E is invariant under them).
std::vector<std::vector<int>> identical_dofs(const SceneLoop& L);
constexpr size_t kMaxSymmetricDofs = 256;  ///< DOFs read (N^2 entries of E expanded and compared: ~N^3, 1.6 s at 256, 9.5 s at 512)
}  // namespace detail

Verdict check_stability_loop_symmetric(const nlohmann::json& certificate);

}  // namespace hapstab::check
