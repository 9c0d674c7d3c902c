// hapstab/multidof/analysis.hpp -- Theorem 5 of paper 000 (the LMI stability test (16)) and
// Theorem 4 for a given coupling V, posed with hapstab::lmi.
//
// (16): P > 0, X in G(m; m_1..m_N), Q_V > 0,
//   M1 = [[A^T P A - P, A^T P B - C^T X/2], [B^T P A - X C/2, B^T P B - (X D + D^T X)/2 - Q_E]] <= 0
//   [[Delta_D X - Q_E, -Q_E], [-Q_E, Q_V - Q_E]] > 0                               ((14) scaled)
// with (A, B, C, D) = E-hat of (15). (16) comes from Theorem 4 by the congruences diag(I, Gamma)
// (Lemma 1 for E-hat^Gamma, X = Gamma^2, Q_E = Gamma Phi_E Gamma) and diag(Gamma, Gamma) ((14),
// Q_V = Gamma Delta_V Gamma); proofs/multidof_congruence.cpp checks both.
//
// M1 cannot be < 0: E-hat has m eigenvalues at 1 with eigenvectors v_b = [V_a b; b], and
// [v_b; 0]^T M1 [v_b; 0] = v^T (A^T P A - P) v = 0 for every P. So M1 <= 0 is posed
// non-strictly by facial reduction: M1 [v_b; 0] = 0, i.e. (A^T - I) P v_b = 0 and
// (B^T P - X C/2) v_b = 0. In the coordinates of ehat_split these equalities say exactly
//   P = Pi0^{-T} blockdiag(P_11, W) Pi0^{-1},   W = X E(1) / (2T),
// so they require  X E(1) = E(1)^T X  (symmetric) and, with P > 0,  X E(1) > 0: the
// environment's static stiffness E(1), weighted by X, must be symmetric positive definite.
// For case i (X = g I) E(1) itself must be symmetric; for case ii (X = diag(g1, g2)) the ratio
// g2/g1 is pinned to E(1)_12 / E(1)_21. We impose them exactly (X ranges over a rational basis
// of the X with X E(1) symmetric; no X -> certified infeasible without any SDP) and pose the
// reduced LMI (P_11, X, Q_E) strictly, with margin. The certificate is then re-checked in exact
// rational arithmetic on the original data (15): P > 0, -M1 >= 0 (exact LDL^T), M1 [v_b; 0] = 0,
// the scaled (14) > 0, Q_V > 0, g_i >= 1.
//
// On the coupling side V-hat carries (z-1)/(Tz), V-hat(1) = 0, and Lemma 1 for V-hat holds
// only non-strictly: its kernel vectors [0; u; u] (state of V zero, delayed input = input)
// are removed by lmi::facial_reduce before the rest is posed with margin.
//
// Implements: paper 000 (14), (16), Theorem 4, Theorem 5.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/multidof/structure.hpp"

namespace hapstab::multidof {

struct Problem {
  Structure structure;
  StateSpace<rational> E;          ///< discrete environment (displacement -> force)
  CouplingStructure coupling;      ///< for design (Theorem 6)
  bool qv_block_diagonal = false;  ///< Remark 3: Q_V in BD(m; m_1..m_N)
  /// InputError naming the inconsistency: E not square / not discrete / m != sum m_i /
  /// E not Schur stable (exact) / coupling sizes (when `with_coupling`).
  void validate(bool with_coupling = false) const;
  rational T() const { return E.T; }
};

/// The facial-reduction analysis of (16)'s first LMI: which X in G make X E(1) symmetric.
struct FacialConditions {
  MatQ E1;                          ///< E(1), exact
  std::vector<std::vector<rational>> gamma_basis;  ///< rational basis of {g : X(g) E(1) symmetric}
  bool symmetric_possible = false;  ///< basis non-empty
  std::string explanation;          ///< what the equalities require, in words, with numbers
};
/// `extra`: further static gains G that X G must keep symmetric (the coupling's V(1) - K).
FacialConditions facial_conditions(const Problem& pb, const std::vector<MatQ>& extra = {});

// Every verdict below is a hapstab::Verdict (numeric/result.hpp): holds = the LMIs are feasible,
// fails = infeasible (lmi::feasibility_of maps back); status exact when an exact certificate
// passed (feasible: the rounded point re-checked in rational arithmetic on the original data,
// with a positive margin; infeasible: Farkas or the facial conditions), numeric otherwise.
/// One path's fate in the planner (planner.hpp): which path, and what became of it.
struct PlanStep {
  std::string path;  ///< "structured KYP/Riccati", "generic SDP"
  std::string fate;  ///< "decided", "skipped", "no point", "point failed the exact re-check", "not needed"
  std::string why;   ///< the premise that failed, the re-check's failure, ... ("" when decided)
};

/// The exact point of (16) that decided a feasible verdict (P11 in the split coordinates of the
/// facial reduction): what `multidof analyze --certificate` writes, through exact_storage
/// (cli/multidof_certificate.hpp). Kept as the re-check had it: the storage P in E-hat's own
/// coordinates costs exact products of E-hat's order, computed only when a certificate is asked for.
struct ExactPoint {
  MatQ P11, X, QE, QV;
};

/// One independent component's outcome when the scene splits (components.hpp).
struct ComponentResult {
  std::string name;              ///< "{H1, H2} (2 DOF, 5 states)"
  std::vector<int> dofs;         ///< the whole's DOF indices
  std::string path;              ///< the path that decided it
  Verdict verdict;
  double seconds = 0;
  std::optional<ExactPoint> exact_point;  ///< its point, in its own coordinates, when it was proven feasible
};

/// The exact frequency-domain witness that proved (16) infeasible (path_witness.cpp), as it was
/// decided: a rational point z = z_re + j z_im of the unit circle and a rational direction u != 0
/// (indexed by the whole scene's DOFs: zero outside the component it came from) where
/// phi = Re(u^T X E-hat(z) u) + u^T Delta_D X u <= 0 (X the facial direction X_1). Published in
/// `multidof analyze --json` (key `witness`) so that an outside check can re-evaluate it.
struct FrequencyWitness {
  double theta = 0;         ///< the sweep's frequency (rad per sample) the rational z rounds
  rational z_re, z_im;      ///< z_re^2 + z_im^2 = 1 exactly
  std::vector<rational> u;  ///< one entry per DOF, not all 0
  rational phi;             ///< phi at (z, u), exact, <= 0
};

/// A complex vector of exact rationals (re + j im), one entry per DOF.
struct ComplexVectorQ {
  std::vector<rational> re, im;
};

/// The exact two-frequency witness that proved Theorem 4's program for a given coupling V
/// infeasible (path_witness.cpp, theorem4_witness), as decided: rational points z1, z2 of the unit
/// circle, complex rational directions p, u with [p; V-hat(z2) u] != 0, and for every direction
/// X_k of the facial set (diagonal, listed by its diagonal)
///   phi_k = p^* Delta_D X_k p + Re(u^* X_k V-hat(z2) u) + Re(w^* X_k E-hat(z1) w) <= 0,
/// w = p + V-hat(z2) u. Published in JSON (key `theorem4_witness`) so that an outside check can
/// re-evaluate it.
struct CouplingWitness {
  double theta1 = 0, theta2 = 0;     ///< the sweep's frequencies (rad per sample) z1, z2 round
  rational z1_re, z1_im, z2_re, z2_im;  ///< on the unit circle exactly
  ComplexVectorQ p, u;
  std::vector<std::vector<rational>> directions;  ///< the diagonals of X_k
  std::vector<rational> phi;                      ///< phi_k, exact, each <= 0
};

/// The exact weighted witness at several frequencies (path_witness.cpp, multi_frequency_witness)
/// that proved (16) infeasible for every X = sum g_k X_k, g > 0: points z_j of the unit circle,
/// complex rational directions u_j != 0 and weights w_j > 0 with, for every direction X_k,
///   sum_j w_j (Re(u_j^* X_k E-hat(z_j) u_j) + u_j^* Delta_D X_k u_j) <= 0.
/// Published in `multidof analyze --json` (key `weighted_witness`).
struct WeightedWitness {
  struct Point {
    double theta = 0;
    rational z_re, z_im, weight;
    ComplexVectorQ u;
  };
  std::vector<Point> points;
  std::vector<std::vector<rational>> directions;  ///< the diagonals of X_k
  std::vector<rational> sums;                     ///< the weighted sums, exact, each <= 0
};


struct SymmetryResult;  // symmetry.hpp

struct AnalysisResult {
  Verdict verdict;                  ///< (16) feasible; evidence: what was proven, in words
  double margin = 0;                ///< margin of the strict LMIs (lmi equilibrated coordinates); structured
                                    ///< path: lambda_min of (16)'s first LMI at the point (original coordinates)
  std::vector<double> gamma;        ///< g_i (Gamma = sqrt(X) has sqrt(g_i) ... see gamma_sqrt)
  std::vector<double> gamma_sqrt;   ///< the gamma_i of Gamma = sqrt(X)
  Eigen::MatrixXd X, Q_E, Q_V, delta_V;  ///< delta_V = Gamma^-1 Q_V Gamma^-1 (coupling requirement)
  FacialConditions facial;
  // least dissipative coupling: minimise ||Q_V||_2 (spectral norm) subject to (16). The point is
  // re-checked exactly (min_point_certified); its minimality is numeric (the solver's optimum, or
  // the structured path's floating-point bisection), never certified.
  bool min_found = false, min_point_certified = false;
  Eigen::MatrixXd Q_V_min, delta_V_min;
  double Q_V_min_norm = 0;
  std::vector<double> gamma_sqrt_min;
  std::string solver_detail;
  std::string path;              ///< the path that decided (planner.hpp), "" when none ran
  std::vector<PlanStep> plan;    ///< every path's fate, in the planner's order
  std::vector<ComponentResult> components;  ///< how the scene split (empty: it did not; path "decomposed")
  std::optional<FrequencyWitness> witness;  ///< set when the frequency-domain witness decided
  std::optional<WeightedWitness> weighted_witness;  ///< set when the several-frequency witness decided
  std::optional<ExactPoint> exact_point;  ///< set when a point passed the exact re-check (not decomposed)
  std::shared_ptr<const SymmetryResult> symmetry;  ///< set when the split by identical DOFs decided (path "symmetry")
  double seconds = 0;      ///< wall time of analyze()
  double sdp_seconds = 0;  ///< ... of it in the numeric searches (lmi::solve, Riccati equations; the rest: Ê,
                           ///< facial reduction, exact checks); decomposed: their share of the wall time
};

/// E-hat of (15) for pb.E and the storage P of `x` in its coordinates (recheck.cpp), exact.
struct ExactStorage {
  StateSpace<rational> Ehat;
  MatQ P;
};
ExactStorage exact_storage(const Problem& pb, const ExactPoint& x);

/// The exact point of a feasible result on a realisation of E-hat, with X, Q_E, Q_V: the point
/// itself (exact_storage), the block-diagonal assembly of the components' (components.hpp) or the
/// lift of the symmetric blocks' (symmetry.hpp); nullopt when the result holds none. What
/// `multidof analyze --certificate` writes.
struct StoredPoint {
  ExactStorage st;
  MatQ X, QE, QV;
};
std::optional<StoredPoint> stored_point(const Problem& pb, const AnalysisResult& r);

/// full: the margin program (16) in (P, X, Q_E, Q_V), then the least dissipative coupling.
/// stability_only: only Theorem 5's verdict, certified, from a smaller program (used by the
/// scaling benchmark; at m = 31 DOF the full program has ~1500 variables, this one ~600):
/// Q_E and Q_V are eliminated exactly. (14) > 0 implies Delta_D X - Q_E > 0, and Q_E enters
/// the first LMI as -Q_E, so (16) is feasible iff the first LMI with Q_E := Delta_D X is
/// strictly feasible (with margin mu) -- infeasibility of that LMI (Farkas, exact) is
/// infeasibility of (16). From its solution, with eps = mu/2 rounded to a dyadic rational,
///   Q_E = Delta_D X - eps I,   Q_V = Q_E + Q_E^2 / eps + eps I
/// satisfy (14) (Schur complement eps I) and Q_V > 0 ((Q_E + eps/2)^2/eps + 3 eps/4 I) exactly;
/// the point is then re-checked by the same exact test as `full`. Not for
/// Problem::qv_block_diagonal (a constructed Q_V is not block diagonal): that falls back to full
/// without the least-dissipative step. Q_V, delta_V of the result are the constructed ones.
enum class AnalysisMode { full, stability_only };

/// Which numeric route finds the points (the exact re-check on the rational data (15) decides
/// either way, and the verdict's evidence says which route found the point):
///   generic_sdp  the LMI programs above through lmi::solve (the built-in IPM first): its Schur
///                complement has all n(n+1)/2 entries of P11 (plus Q_E, Q_V): O(n^6) work per
///                iteration, about N^5 over the contact scenes (bench/contact_scene.py).
///   kyp_riccati  when the facial conditions pin X to one direction (X = g X_1; min g_i = 1 by
///                homogeneity), (16)'s first LMI is a KYP LMI in P11 alone: its interior point
///                is the stabilising solution of a shifted DARE (lmi/kyp.hpp, O(n^3)). The
///                verdict is the stability-only construction above on that point. The least
///                dissipative coupling, when Delta_D X_1 = d I: Q_E enters the first LMI only as
///                -Q_E and Q_V > f(Q_E) = Q_E + Q_E (Delta_D X - Q_E)^-1 Q_E is matrix monotone,
///                so the minimum is along Q_E = r I: bisection on r (DARE solvability), the point
///                re-checked exactly; otherwise that step runs the generic program. When the
///                facial conditions leave X a d-dimensional set (d > 1), the same path with X
///                searched (path_kyp_search.cpp: an outer search over X = sum g_i X_i by the KYP
///                lemma's frequency form, linear in g; the Riccati point at the X it chose).
///                Problem::qv_block_diagonal, no Riccati point or a failed exact check: the whole
///                analysis falls back to generic_sdp (never a weaker verdict).
///   automatic    the planner (planner.hpp) tries the structured paths whenever their premises
///                hold (X pinned, or X searched over d > 1 directions; Q_V not block diagonal; the
///                automatic back-end), whatever the number of DOF, then the frequency-domain
///                witness, then generic_sdp: the path is chosen by cost, not by size.
///                AnalysisResult::path and ::plan say which path decided and why the others did
///                not apply.
enum class AnalysisPath { automatic, generic_sdp, kyp_riccati };

/// InputError when a generic SDP on pb would need a Schur complement above
/// limits::generic_sdp_bytes (`extra_unknowns` beside E's storage P11), naming the order and the
/// limit: checked before the program is posed.
void check_generic_size(const Problem& pb, long extra_unknowns, const std::string& what);

AnalysisResult analyze(const Problem& pb, const lmi::Options& opt = {}, AnalysisMode mode = AnalysisMode::full,
                       AnalysisPath path = AnalysisPath::automatic);

/// Independent verification of a coupling V (given by its realisation): Theorem 4 with
/// V-hat^Gamma's OSP level by Lemma 1 (non-strict, facial reduction), E-hat^Gamma's ISP level
/// and (14), over X in G, Q_E, Q_V and both storage functions -- one LMI program.
struct CouplingCheck {
  Verdict verdict;  ///< evidence: the solver's account, then both exact re-checks
  double margin = 0;
  std::vector<double> gamma_sqrt;
  Eigen::MatrixXd Q_V, delta_V;
  std::optional<CouplingWitness> witness;  ///< set when the two-frequency witness proved the program infeasible
  /// When the verdict holds exactly: the environment's exact point (exact_storage gives E-hat's
  /// realisation and P_E) and V-hat's storage P_V in vhat(V, K)'s coordinates, at that point's X and
  /// Q_V -- what `multidof design --certificate` writes (cli/multidof_certificate.hpp).
  std::optional<ExactPoint> point;
  MatQ P_V;
};
CouplingCheck check_theorem4(const Problem& pb, const StateSpace<rational>& V, const lmi::Options& opt = {});

/// Lemma 1 for V-hat^Gamma (V-hat of (17) built from V and K): is it Delta-OSP? Non-strict
/// (V-hat(1) = 0): the kernel vectors [0; u; u] force P_V [0; I] = [p1; P22] with
///   p1 = (A_V^T - I)^{-1} C_V^T X / 2,   P22 = (V(1) - K)^T X / (2T)   (X = Gamma^2),
/// so X (V(1) - K) must be symmetric positive definite (the coupling must act as a damper at
/// DC). These are imposed exactly; the rest (P11 block) is posed with margin and the rounded
/// point re-checked exactly on the rational data.
struct OspCheck {
  Verdict verdict;  ///< evidence: the solver's account, then the exact re-check
  double margin = 0;
  MatQ P_V;         ///< the storage that passed the exact re-check (V-hat's coordinates); empty otherwise
};
OspCheck check_vhat_osp(const StateSpace<rational>& V, const MatQ& K, const MatQ& Gamma, const MatQ& Delta,
                        const lmi::Options& opt = {});

/// The largest scalar delta with V-hat delta-OSP (Delta = delta I, Gamma = I): bisection on
/// check_vhat_osp; `delta` is the largest level certified exactly (a lower bound), `upper` the
/// smallest level found infeasible numerically. `verdict` holds (exact) when the bisection ran:
/// V-hat is delta-OSP; undecided when not even delta = 0 was certified.
struct OspLevel {
  double delta = 0, upper = 0;
  Verdict verdict;
};
OspLevel vhat_osp_level(const StateSpace<rational>& V, const MatQ& K, const lmi::Options& opt = {});

/// Helpers shared with design.cpp.
Eigen::MatrixXd to_double(const MatQ& M);
lmi::Expr scalar_times(const lmi::Expr& s, const Eigen::MatrixXd& M);  ///< s * M (s a 1x1 expression)

}  // namespace hapstab::multidof
