// hapstab/multidof/design.hpp -- Theorem 6 of paper 000: a structured virtual coupling
// V = blockdiag(V_1..V_Nbar) (R2) that stabilises the haptic loop, by the reconstructed LMIs
// (DESIGN.md; (19)-(20) are missing from the transcription):
//   (19) = the LMIs (16) of Theorem 5 in P, X, Q_E, Q_V (with the facial reduction of analysis.hpp),
//          Q_V in BD(m; m_1..m_N) and in BD(m; mbar_1..) (Remark 3 and (18));
//   (20) = Q > 0 and [[Y, R^T], [R, S]] >= 0, R = [C/2; A; C], S = [[(D + D^T)/2, B^T, D^T],
//          [B, Q, 0], [D, 0, Sigma]] of V-hat_Gamma (17) -- Lemma 2 (with its S typo fixed:
//          -Phi, here Phi = 0), affine in (A_V^G, B_V^G, C_V^G, D_V^G);
//   (22) Sigma = Q_V^-1, Y = Q^-1 (non-convex), by cone complementarity linearisation
//          (El Ghaoui-Oustry-AitRami 1997): minimise tr(Y_k Q + Q_k Y + Sigma_k Q_V + Q_V,k Sigma)
//          s.t. the LMIs and [[Y, I], [I, Q]] >= 0, [[Sigma, I], [I, Q_V]] >= 0, until the trace
//          reaches 2 (n + m) + 2 m (n = dim Q) within tolerance.
// (20) is posed NON-strictly: V-hat(1) = 0 makes Lemma 1/2 for V-hat infeasible as a strict LMI
// for every V (analysis.hpp). The designed V is then returned by (23), (24) and verified
// independently (never trusted from the design LMIs): V-hat's OSP level by Lemma 1 against
// Gamma^-1 Q_V Gamma^-1, and Theorem 4 with levels computed afresh (check_theorem4).
//
//
// Two routes (DesignPath); the independent checks decide either way:
//   generic_sdp  the above as one program per CCL step, Q and Y full (nbar + m square): its
//                Schur complement grows like N^6 (N = 16 took 23 s, N = 32 did not finish in 15 min).
//   blockwise    when the structured analysis path applies (analysis.hpp, kyp_riccati: X pinned,
//                Delta_D X diagonal) and K is block diagonal in V's blocks: Q_V is fixed at the
//                certified point of that path's bisection along Q_E = r I (Q_V = q I, the least
//                dissipative, when Delta_D X = d I) or along Q_E = s Delta_D X (Q_V = diag(s d_i /
//                (1 - s)) otherwise), which satisfies (14) with that point's X and Q_E. (20) and
//                (22) then separate: with Q, Y block diagonal in V's blocks and Sigma =
//                ((1 + 1/16) Q_V)^-1 fixed, the CCL of the whole is one small CCL per block (each block's LMIs are principal submatrices
//                of the whole's). The checks are block-wise too (Lemma 1 for V-hat holds iff it
//                holds for each block, P_V = blockdiag(P_V,b)); Theorem 4 is certified by the
//                environment side's exact certificate at that point and the blocks' storage
//                functions. Fixing Q_V and the block-diagonal Q, Y restrict the search: a block
//                that finds no point, or a certificate that fails, falls back to generic_sdp
//                (never a weaker verdict).
//   automatic    one planner (planner.hpp, run_plan, the rules of analyze's): blockwise whenever
//                its premises hold (the automatic back-end, K block diagonal in V's blocks, X
//                pinned), whatever the number of DOF; generic_sdp when blockwise is skipped, finds
//                nothing or its coupling is not verified (and fits the size limit).
//                DesignResult::path and ::plan say which path decided and why the others did not.
//
// Implements: paper 000 (18), (19), (20), (22), (23), (24), Theorem 6.
#pragma once

#include <string>
#include <vector>

#include "hapstab/multidof/analysis.hpp"

namespace hapstab::multidof {

enum class DesignPath { automatic, generic_sdp, blockwise };

struct DesignOptions {
  int max_iterations = 40;
  DesignPath path = DesignPath::automatic;
  double tolerance = 1e-6;  ///< relative gap of the CCL trace to 2(n + m) + 2m
  lmi::Options lmi;
};

/// One independent check of a coupling: holds = pass; proven() = certified exactly.
struct Verification {
  std::string name;
  Verdict verdict;
  std::optional<CouplingWitness> witness = std::nullopt;  ///< Theorem 4's check proven infeasible by the two-frequency witness
};

struct DesignResult {
  /// holds: a V was produced that passes every independent check (status exact: with exact
  /// certificates); fails: the convex part (19)-(20) without (22) has no solution (status
  /// exact: certified); undecided otherwise. evidence: what happened, in words.
  Verdict verdict;
  bool converged = false;      ///< CCL reached the trace target
  int iterations = 0;
  double trace_gap = 0;        ///< final tr(...) - 2(n + m) - 2m
  std::vector<double> trace_history;
  StateSpace<rational> V;      ///< (23), dyadic-rounded doubles (exact as given)
  std::vector<double> gamma_sqrt;
  Eigen::MatrixXd Q_V, delta_V;  ///< design's Q_V and Gamma^-1 Q_V Gamma^-1
  std::vector<Verification> verification;
  FacialConditions facial;     ///< the facial conditions of (16) (the same X set analyze reports)
  std::string path;            ///< the path that decided (planner.hpp), "" when none did
  std::vector<PlanStep> plan;  ///< every path's fate, in the planner's order
  /// The exact evidence of a block-wise design's Theorem 4 certificate (design_blockwise_at), what
  /// `multidof design --certificate` writes (cli/multidof_certificate.hpp): the point's X, Q_E, Q_V
  /// (diagonal) and, designed on the whole, the point itself; V-hat's storage per block of V, in V's
  /// order (a copy shares its representative's); designed on the split of identical DOFs
  /// (design_symmetry.cpp), its classes and each block's exact point, the fixed space first (the
  /// direct sum of its components' where it went by them).
  struct BlockwiseEvidence {
    MatQ X, QE, QV;
    std::optional<ExactPoint> whole;  ///< the structured path's exact point of the whole's (16); none on the split
    std::vector<MatQ> P_V;
    std::vector<std::vector<int>> classes;
    std::vector<StoredPoint> split_points;
    std::vector<int> split_class;  ///< per split point: -1 the fixed space, else its class
  };
  std::optional<BlockwiseEvidence> blockwise;
};

DesignResult design(const Problem& pb, const DesignOptions& opt = {});

/// Independent checks of any coupling V (also used for the paper's (27)): Lemma 1 for V-hat^Gamma
/// at the exact X = Gamma^2 and Q_V, V-hat's scalar OSP level, Theorem 4 with every level free,
/// V Schur stable.
std::vector<Verification> verify_coupling(const Problem& pb, const StateSpace<rational>& V, const MatQ& X,
                                          const MatQ& Q_V, const lmi::Options& opt = {});

}  // namespace hapstab::multidof
