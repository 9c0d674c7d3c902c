// hapstab/multidof/symmetry.hpp -- Theorem 5's program (16) for a scene of identical DOFs, split
// by the permutations that leave it invariant (issue 48 item 2): small programs whose sizes do
// not depend on how many DOFs are alike, and their points lifted back to one point of the whole.
//
// The scene: one-DOF operators (X = diag(g), one g per DOF), DOFs in classes C_1..C_r of alike
// ones -- the same device, operator and column of E's realisation as written, E's entries
// depending only on the classes of their row and column (stability/symmetry.hpp proves this
// exactly) -- and, for (16), the same OSP level Delta within a class. E then commutes with every
// permutation within the classes. Take the rational basis S of R^m with orthogonal columns
//   1_c (the ones on class c), c = 1..r;   h_j = e_{c0} + .. + e_{c(j-1)} - j e_{cj} (Helmert,
//   j = 1..k_a - 1, over class a's DOFs c0..c(k_a-1));   S^T S = D = diag(k_c, j (j + 1)).
// E S = S blockdiag(E_f, e_a I_{k_a - 1}):  E_f(a, c) = sum_{j in C_c} E(i_a, j)  (the r-DOF
// "fixed" block: E's row sums by class) and e_a = E(i, i) - E(i, j), i != j in C_a (a one-DOF
// "standard" block per class of two or more). So E-hat = S blockdiag(E-hat_f, e-hat_a I) S^-1,
// S^-1 = D^-1 S^T, and on the realisation (A, B_b S^-1, S C_b, S D_b S^-1) built from the
// blocks' realisations (A = blockdiag, one copy of e-hat_a's per h_j) the congruence
// blockdiag(I, S) turns (16)'s first LMI into the blocks' own, with X_b = S^T X S =
// diag(k_c g_c, j (j + 1) g_a), Q_b = S^T Q S; (14) likewise under blockdiag(S, S) (Delta X
// commutes: Delta is constant on each class). (16) is homogeneous in (P, X, Q_E, Q_V) apart
// from g >= 1, so a block's point may be scaled by any s > 0 that keeps g >= 1. Hence
//   blocks feasible => whole feasible: from the fixed block's point (P_f, diag(gamma_c), Q_f)
//     and class a's (p_a, gamma_a, q_a), with sigma = max(1, max_c k_c / gamma_c),
//     g_c = sigma gamma_c / k_c >= 1 and t_aj = g_a j (j + 1) / gamma_a:
//       P = blockdiag(sigma P_f, t_aj p_a), X = diag(g),
//       Q = S^-T blockdiag(sigma Q_f, t_aj q_a) S^-1, i.e.
//       Q(i, k) = sigma Q_f(c, d) / (k_c k_d) + [i, k in C_a] (g_a / gamma_a) q_a (delta_ik - 1/k_a),
//     and every condition of (16) holds exactly on that realisation (lift_point below; the
//     lifted point is what `--certificate` writes, and both checkers verify it as any other
//     multidof-feasible certificate: ctest SceneSymmetry.*, `CertificateExamples`);
//   a block's witness => the whole infeasible, in the frequency domain (no realisation needed):
//     a point of the whole's (16) with X = diag(g) makes phi(z, u) = Re(u^* X E-hat(z) u) +
//     u^* Delta X u > 0 at every z on the circle and u != 0 (path_witness.cpp). Lift the block's
//     u: for class a's block, u (e_i - e_j) (i, j in C_a): E-hat maps it to e-hat_a(z) times
//     itself, so phi = (g_i + g_j) phi_a(z, u; 1) <= 0. For the fixed block, u_c on every DOF
//     of class c: phi = phi_f(z, u; diag(G_c)), G_c = sum of g over C_c, and diag(G_c) is an X
//     the fixed block admits (X E(1) symmetric sums, class block by class block, to diag(G_c)
//     E_f(1) symmetric), where the block's witness (one frequency, or weighted over several)
//     makes it <= 0. The facial conditions lift the same way (no X_f admissible, or e_a(1) <= 0
//     makes h^T X E(1) h <= 0 at a zero-sum h). A Farkas vector speaks of the block's realisation
//     only: such a block, or one not proven either way, hands the scene to the whole program
//     (planner.hpp), the block and its verdict named -- never a weaker verdict than the whole's.
//     `--certificate` writes the lifted witness (lift_direction), which both checkers verify on
//     the whole scene as any multidof-witness certificate.
// The blocks are realised from E as written (E_f: the classes' first column blocks, C summed over
// each class's columns; e_a: column block of i, C_i(i, :) - C_j(i, :)), reduced exactly and
// delayed as the whole is (scene_multidof.hpp), so each is a realisation of its transfer matrix.
// Not split (the reason in the plan): operators of two or more DOFs, Q_V block diagonal (Remark
// 3: a lifted Q_V is not diagonal), unequal OSP levels within a class, and whatever
// stability/symmetry.hpp declines.
//
// Implements: paper 000 (16), Theorem 5.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/multidof/design.hpp"
#include "hapstab/multidof/scene_multidof.hpp"

namespace hapstab::multidof {

/// One block of the split: its problem, how often it repeats, and (after the analysis) its result.
struct SymmetryBlock {
  std::string name;      ///< "the fixed space (4 DOF, one per class)", "class 2's zero-sum space (1 DOF)"
  int copies = 1;        ///< k_a - 1 for a class's block; 1 for the fixed space
  int cls = -1;          ///< the class of a standard block; -1 for the fixed space
  Problem problem;
  AnalysisResult result;
  bool analysed = false;  ///< false: not needed, an earlier block proved the whole infeasible
};

struct SymmetryResult {
  std::vector<std::vector<int>> classes;  ///< the DOFs of each class (0-based), by their first DOF
  std::string group;                      ///< "S_32^4 (4 classes of 32 identical DOFs)"
  std::vector<SymmetryBlock> blocks;      ///< the fixed space first, then one per class of two or more
};

/// The blocks of sp's (16), not yet analysed; nullopt with `why_not` when the scene does not
/// split ("" when no two DOFs are alike).
std::optional<SymmetryResult> split_problem(const SceneProblem& sp, std::string& why_not);

/// Theorem 5 on sp by the split: every block analysed (analyze()); the whole's result (path
/// "symmetry", `symmetry` set) when every block is proven feasible with an exact point, or one is
/// proven infeasible by a witness or its facial conditions; else nullopt and `why_not` names the
/// block that decided nothing.
std::optional<AnalysisResult> analyze_by_symmetry(const SceneProblem& sp, SymmetryResult split, const lmi::Options& opt,
                                                  std::string& why_not);

/// Theorem 6 on sp by the split (design_symmetry.cpp): one structured point shared by the blocks,
/// lifted to an invariant point of the whole's (16) (checked exactly), then the block-wise design at
/// it (one CCL per distinct block of V); or (19) infeasible, exactly, when the fixed space's facial
/// conditions admit no X > 0, or (with no shared point) analyze_by_symmetry proves (16) infeasible.
/// nullopt with `why_not` when a block's premise fails and (16) is not proven infeasible.
std::optional<DesignResult> design_by_symmetry(const SceneProblem& sp, const SymmetryResult& split,
                                               const DesignOptions& opt, std::string& why_not);

/// A block's witness direction u lifted to the whole's m DOFs (above).
std::vector<rational> lift_direction(const SymmetryResult& s, const SymmetryBlock& b, const std::vector<rational>& u, int m);

/// JSON `symmetry` of `multidof analyze` and Python's Analysis.symmetry: null, or {group, classes
/// (0-based DOFs), blocks [{name, copies, dofs, states, path, verdict (or "not needed": not
/// analysed, an earlier block proved the whole infeasible), certified, seconds}]}.
nlohmann::json symmetry_json(const AnalysisResult& r);

/// The lifted point above: a realisation of the whole's E-hat and a point of its (16), exact;
/// with multipliers_only, X, Q_E and Q_V alone (st left empty: what the verdict prints).
StoredPoint lift_point(const SymmetryResult& s, int m, bool multipliers_only = false);

}  // namespace hapstab::multidof
