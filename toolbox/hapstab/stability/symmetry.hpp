// hapstab/stability/symmetry.hpp -- the loop as written split by the permutations of its
// identical DOFs (issue 48 item 2), for loop_as_written.cpp; multidof/symmetry.hpp splits
// Theorem 5's (16) by the same classes and blocks.
//
// A loop of N one-DOF devices under an environment E (N x N, discrete) whose DOFs fall into
// classes C_1 .. C_r of identical ones -- the same device, the same one-port operator (or none),
// the same column of E's realisation as written (A_j, B_j, and the entries of E's row i and
// column j depend only on the classes of i and j and on whether i = j) -- is invariant under
// every permutation within the classes, the group S_{k_1} x ... x S_{k_r} (k_a = |C_a|). Every
// check is an exact comparison of the realisations' rational entries: the invariance is proven,
// not sampled. Its closed-loop matrix M (as written, every state of every block) then leaves
// invariant
//  * the fixed space (each block's states equal across a class): M there is the loop of r DOFs,
//    one representative device and operator per class, under E_triv with states the r
//    representative column blocks and C_triv(a, b) = sum over j in C_b of C_j(i_a, :),
//    D_triv(a, b) = sum over j in C_b of D(i_a, j) -- E's row sums by class;
//  * for each class a with k_a >= 2, the k_a - 1 dimensional space of zero-sum vectors over its
//    DOFs: on each, the one-DOF loop of the class's device and operator under E_a with the
//    column block (A_a, B_a) and C_a = C_i(i, :) - C_j(i, :), D_a = D(i, i) - D(i, j) (i != j in
//    C_a): the diagonal entry minus the off-diagonal one.
// These spaces span the whole state space (dimension sum_a n_a + sum_a (k_a - 1) n_a), so the
// spectrum of M is that of the r-DOF loop and of each one-DOF loop with multiplicity k_a - 1
// (the isotypic decomposition: Gatermann & Parrilo 2004, Sec. 5; ctest
// LoopSymmetry.CharacteristicPolynomialFactors checks det(zI - M) = det(zI - M_triv) prod_a
// det(zI - M_a)^(k_a - 1) exactly). The loop is stable iff every one of these small loops is.
// A coupling V (when the scene has one) is treated as E is, with its own column blocks, and must
// be invariant too. Applies to loops with one-DOF devices and one-port operators, and blocks whose
// realisations are one block of states per input column (tf2ss of a transfer matrix,
// lti/realization.hpp) -- states no input reaches, isolated, are set aside: the loop is block
// triangular over them and they are hidden modes, which the caller (decide_loop's step 1) has
// proven stable. Elsewhere nullopt with the reason named.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/realization.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::stability::detail {

struct LoopSymmetry {
  std::vector<std::vector<int>> classes;  ///< the DOFs of each class (0-based), in order of their first DOF
  sim::LoopSpec fixed;                    ///< the r-DOF loop on the fixed space
  std::vector<sim::LoopSpec> standard;    ///< per class with k_a >= 2 (in class order): its one-DOF loop
  std::vector<int> standard_class;        ///< the class each of `standard` belongs to
  std::vector<Eigen::Index> isolated;     ///< the environment's states no input reaches (set aside above)
  /// "S_32^4 (4 classes of 32 DOFs)": the group in words
  std::string group() const;
};

/// The split above, or nullopt: `why_not` says why ("" when no two DOFs are alike).
std::optional<LoopSymmetry> split_by_symmetry(const sim::LoopSpec& spec, std::string& why_not);

/// The blocks put back together: the direct sum of a fixed-space realisation (r inputs and
/// outputs) and, per class a of k_a >= 2 DOFs, k_a - 1 copies of its zero-sum one (standard[a];
/// null for a class of one), on the whole's m inputs and outputs through the basis S of
/// multidof/symmetry.hpp (ones-vectors and Helmert vectors): (A_b, B_b S^-1, S C_b, S D_b S^-1).
/// A realisation of the whole's transfer matrix (E S = S blockdiag(E_f, e_a I)); minimal when the
/// blocks' are (its McMillan degree is theirs, added).
StateSpace<rational> lift_realisation(const std::vector<std::vector<int>>& classes, const StateSpace<rational>& fixed,
                                      const std::vector<const StateSpace<rational>*>& standard, int m);

/// lti::hidden_modes of the environment as written (spec.environment), by the split: under the
/// state basis (S_a (x) I) of each class its realisation is the direct sum of the blocks' and of
/// the isolated states, on inputs and outputs changed by S, which hides nothing and shows
/// nothing new. So the hidden factors are the blocks' (a class's to the power k_a - 1) times
/// the isolated states' characteristic polynomial (uncontrollable), and the minimal realisation
/// is lift_realisation of the blocks' minimal ones. Kalman decompositions of order n_f and n_a
/// instead of the whole's (ctest LoopSymmetry.EnvironmentHiddenModesAsTheWholes).
HiddenModes environment_hidden_modes(const LoopSymmetry& s, const StateSpace<rational>& E);

}  // namespace hapstab::stability::detail
