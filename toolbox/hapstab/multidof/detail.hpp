// hapstab/multidof/detail.hpp -- internal building blocks shared by the paths of Theorem 5
// (planner.hpp: path_generic.cpp, path_kyp.cpp, least_dissipative.cpp), the exact re-check
// (recheck.cpp), Theorem 4's checks (coupling_check.cpp) and design.cpp: the environment side of (16) in the split coordinates of ehat_split (facial
// reduction imposed exactly), the scaled (14), Lemma 1 for V-hat^Gamma in congruence form
//   -[[A^T P A - P + C^T Q_V C, A^T P B - C^T X/2 + C^T Q_V D],
//     [.,                       B^T P B - (X D + D^T X)/2 + D^T Q_V D]] >= 0
// (Q_V = Gamma Delta_V Gamma, X = Gamma^2: linear in P, X, Q_V), its kernel [0; u; u], and the
// exact re-check of a Theorem 5 solution on the rational data (15). Not a public API.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/lmi/certify.hpp"
#include "hapstab/lmi/kyp.hpp"
#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/design.hpp"

namespace hapstab::multidof::detail {

// The lmi names analysis.cpp and design.cpp both use (they open `using namespace detail`).
using Eigen::MatrixXd;
using lmi::Expr;
using lmi::MatrixVariable;
using lmi::Program;
using lmi::Strictness;

struct EnvVars {
  std::vector<lmi::MatrixVariable> theta;            ///< X = sum theta_k X_k
  std::vector<MatQ> Xk;                              ///< exact basis of the admissible X
  std::vector<std::vector<rational>> basis;
  lmi::MatrixVariable P11, QE;
  lmi::Expr X, g;                                    ///< X (m x m) and g (N x 1) expressions
};
/// `qe_is_delta_x`: no Q_E variable; Q_E := Delta_D X in the first LMI (the stability-only
/// elimination of analysis.hpp; EnvVars::QE then has no rows).
EnvVars add_environment(lmi::Program& prog, const Problem& pb, const EhatSplit& sp, const FacialConditions& fc,
                        bool qe_is_delta_x = false);
void add_condition14(lmi::Program& prog, const Problem& pb, const EnvVars& ev, const lmi::Expr& QV);

/// The environment side of a Theorem 5 point, exact: X = sum theta_k X_k (the facial basis),
/// Q_E, and P11, the block of P in the split coordinates of ehat_split (P's other block,
/// X E(1)/(2T), is pinned by the facial reduction).
struct ExactEnv {
  std::vector<rational> theta;
  MatQ X, QE, P11;
};
/// The solver's point of the environment side, exact (lmi::CertifiedSolve::point).
ExactEnv exact_env(const lmi::CertifiedSolve& cs, const EnvVars& ev);
/// The storage P of (16) in E-hat's coordinates (ehat(pb.E)) at the point x: Pi0^-T blockdiag(P11,
/// X E(1)/(2T)) Pi0^-1, exact (recheck.cpp; the certificate of a feasible (16) prints it).
MatQ storage_of(const Problem& pb, const EhatSplit& sp, const ExactEnv& x);
/// THE exact re-check of a Theorem 5 point (recheck.cpp): true when every condition of (16) holds
/// in rational arithmetic on the exact data (15); `why` says what was checked, or what failed.
bool exact_recheck(const Problem& pb, const EhatSplit& sp, const ExactEnv& x, const MatQ& QV, std::string& why);

/// Scales an exact Theorem 5 point so that min g_i = 1 (the LMIs are homogeneous in
/// (P, X, Q_E, Q_V); g_i >= 1 is the only inhomogeneous constraint, Remark 2).
rational normaliser(const MatQ& X);
/// The solver's point of (16) -- environment side and Q_V -- in exact rationals, scaled by
/// normaliser (min g_i = 1).
struct ScaledPoint {
  ExactEnv env;
  MatQ QV;
  rational scale;
};
ScaledPoint scaled_point(const lmi::CertifiedSolve& cs, const EnvVars& ev, const lmi::MatrixVariable& QV);
/// The reported feasible point: X, Q_E, Q_V, Gamma and the coupling requirement delta_V.
void store_point(AnalysisResult& res, const Problem& pb, const MatQ& X, const MatQ& QE, const MatQ& QV);
/// (16) in (P, X, Q_E, Q_V): the environment side, Q_V > 0 and the scaled (14).
void pose_16(lmi::Program& prog, const Problem& pb, const EhatSplit& sp, const FacialConditions& fc, EnvVars& ev,
             lmi::MatrixVariable& QV);

/// The generic SDP's size check (numeric/limits.hpp): "" when its Schur complement fits in
/// limits::generic_sdp_bytes, else the reason, naming the order and the limit.
std::string generic_size_exceeded(const Problem& pb, long extra_unknowns, const std::string& what);

/// The structured path's data: X pinned by the facial conditions to one direction, scaled so
/// that min g_i = 1, and the first LMI of (16) as the KYP data of lmi/kyp.hpp for Q_E = 0:
/// A = A_E, B = B_t, S = C_E^T X / 2, R = F22 (a Q_E then enters as R - Q_E).
struct Pinned {
  MatQ X;
  rational theta;  ///< X = theta X_1 (X_1 = scalar_blocks(gamma_basis[0]))
  lmi::KypData kyp;  ///< in the state basis x' = basis x
  MatQ basis;        ///< rational and invertible; empty: the realisation as written (x' = x)
};
/// (16)'s first LMI at an exact X as KYP data for Q_E = 0 (linear in X; a Q_E enters as R - Q_E).
lmi::KypData kyp_data(const Problem& pb, const EhatSplit& sp, const MatQ& X);
/// nullopt (with `why`) when the facial conditions leave X more than one direction, or none with X > 0.
std::optional<Pinned> pinned_x(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc,
                               std::string* why = nullptr);
/// The facial basis as matrices X_k when every operator lies in the support of exactly one basis
/// vector, with positive entries (so X = sum theta_k X_k > 0 iff every theta_k > 0, and g_i >= 1
/// forces theta_k > 0); else nullopt and `why` (path_kyp_search.cpp).
std::optional<std::vector<MatQ>> positive_facial_basis(const Problem& pb, const FacialConditions& fc, std::string& why);
/// Theorem 4's program for the coupling V (check_theorem4) proven infeasible by a frequency-domain
/// witness (path_witness.cpp): a Fails verdict, exact; nullopt when none was found (`tried` says
/// what was tried). `fc`: the facial conditions with V(1) - K; `Vh` = V-hat of (17).
/// `out`, when given, receives the witness as decided.
std::optional<Verdict> theorem4_witness(const Problem& pb, const FacialConditions& fc, const StateSpace<rational>& Vh,
                                        std::string& tried, CouplingWitness* out = nullptr);
/// (16) proven infeasible for every X = sum g_k X_k, g > 0, by a witness at several frequencies
/// (path_witness.cpp): weights w_j >= 0 (not all 0) and points (theta_j, u_j), theta_j in (0, pi],
/// with sum_j w_j phi_k(z_j, u_j) <= 0 for every direction X_k, phi_k(z, u) = Re(u^* X_k E-hat(z) u)
/// + u^* Delta_D X_k u, decided in rational arithmetic at rational points and directions; nullopt
/// (with `why`) when the rounded certificate does not hold; `out`, when given, receives it as decided.
std::optional<Verdict> multi_frequency_witness(const Problem& pb, const std::vector<MatQ>& Xk,
                                               const std::vector<double>& theta, const std::vector<Eigen::VectorXcd>& u,
                                               const std::vector<double>& w, std::string& why,
                                               WeightedWitness* out = nullptr);
/// The same KYP data in a scaled modal basis x' = S x (S rational): for a realisation whose basis
/// makes the Riccati equation badly conditioned (a companion form of order 12: eigenvectors with
/// condition number 1e8), where the doubling "converges" to a P with lambda_min(F(P)) << 0.
/// nullopt when A is not diagonalisable in double (a delay's shift chain) or already nearly modal.
std::optional<Pinned> in_modal_basis(const Pinned& px);
/// The Riccati point P' (in px's basis) rounded to dyadic rationals R (the fewest bits that keep
/// its margin), as P11 of the realisation as written: S^T R S, exact (F(S^T R S) is the congruence
/// diag(S, I)^T F'(R) diag(S, I), so the exact re-check decides as if R were checked in S's basis).
MatQ rounded_p11(const Pinned& px, const lmi::KypData& d, const lmi::KypPoint& kp);

/// The structured path's least dissipative point of (16) (analysis.hpp, AnalysisPath::kyp_riccati),
/// exact: X pinned by the facial conditions (min g_i = 1), Q_E = r I, P11 from the Riccati
/// equation, Q_V = q I; `certified` when exact_recheck passed on the rational data (15) (`why`
/// says what was checked, or what failed). Where Delta_D X = diag(d_i) is diagonal but not a
/// multiple of I, the point of the same bisection along Q_E = s Delta_D X, Q_V = diag(s d_i/(1 - s))
/// (certified, not necessarily least; `r` is then s). nullopt when X is not pinned to one
/// direction, Delta_D X is not diagonal, or no Riccati point is found.
struct KypMinPoint {
  ExactEnv env;
  MatQ QV;
  rational r;  ///< Q_E = r I (Delta_D X = d I), or Q_E = r Delta_D X
  bool certified = false;
  std::string why;
  int riccati_solves = 0;
  double numeric_seconds = 0;  ///< the Riccati bisection and point (not the exact check)
};
std::optional<KypMinPoint> kyp_min_point(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc);
/// One part of a structured bisection shared by several problems (the blocks of a symmetry
/// split: multidof/symmetry.hpp, design_by_symmetry).
struct KypPart {
  const Problem* pb;
  const EhatSplit* sp;
  Pinned px;
};
/// The structured point with one s shared by every part (two or more): Q_E = s Delta_D X and
/// Q_V = (max(s/(1 - s), 0) + eps) Delta_D X in each part (eps: 1e-9 as a dyadic), s a little above the least s at
/// which every part's Riccati equation is solvable, each part re-checked exactly (its own
/// `certified`). Every matrix of a part's point is proportional to its X. nullopt when a part's
/// Delta_D X is not diagonal, or no Riccati point is found in some part.
std::optional<std::vector<KypMinPoint>> least_dissipative_points(const std::vector<KypPart>& parts);
/// Theorem 6 block by block (design.cpp, the block-wise path of design.hpp) at a certified point of
/// (16) with X and Q_V diagonal (from kyp_min_point, or from a symmetry split's blocks): one CCL
/// per distinct block of V (blocks posing the same problem share it), then the independent checks.
/// nullopt (with `why`) when the point is not certified or a block's CCL finds nothing.
std::optional<DesignResult> design_blockwise_at(const Problem& pb, const KypMinPoint& point, const DesignOptions& opt,
                                                std::string& why);

/// The least dissipative coupling (AnalysisResult::Q_V_min ...) after a feasible verdict,
/// planned like the verdict (least_dissipative.cpp): the structured bisection when `px` is given
/// and its premises hold (Delta_D X = d I), else the generic program when it fits the size limit
/// (else a note in solver_detail: the verdict stands, only the optional minimisation is skipped).
void plan_least_dissipative(const Problem& pb, const EhatSplit& sp, const lmi::Options& opt,
                            const std::optional<Pinned>& px, AnalysisResult& res);

double since(std::chrono::steady_clock::time_point t0);
Eigen::MatrixXd gamma_inv_scale(const Eigen::MatrixXd& Q, const Eigen::MatrixXd& X);
std::vector<double> gamma_sqrt(const Problem& pb, const Eigen::MatrixXd& X);
/// Coupling side: P_V with its facial block pinned by X (basis Xk, scalars theta), reduced LMI.
struct VhatVars {
  StateSpace<rational> Vh;                 ///< (17)
  std::vector<MatQ> p1k, P22k;             ///< exact pinned blocks per basis element
  lmi::MatrixVariable P11;
  lmi::Expr PV;
};
VhatVars add_vhat(lmi::Program& prog, const StateSpace<rational>& V, const MatQ& K, const std::vector<MatQ>& Xk,
                  const std::vector<lmi::Expr>& theta, const lmi::Expr& QV);
/// Lemma 1's matrix for V-hat (the congruence form above) at a storage P, exact.
MatQ lemma1_matrix(const StateSpace<rational>& Vh, const MatQ& P, const MatQ& X, const MatQ& QV);
/// Exact re-check of the coupling side at exact theta, Q_V, P11; `storage` (when given) receives
/// the storage P_V that passed, in V-hat's coordinates (vv.Vh).
bool exact_recheck_vhat(const VhatVars& vv, const std::vector<MatQ>& Xk, const std::vector<rational>& theta,
                        const MatQ& QV, const MatQ& P11, std::string& why, MatQ* storage = nullptr);

/// Lemma 1 for V-hat (check_vhat_osp) with X = Gamma^2 and Q_V = Gamma Delta Gamma given exactly.
OspCheck check_vhat_lemma1(const StateSpace<rational>& V, const MatQ& K, const MatQ& X, const MatQ& QV,
                           const lmi::Options& opt);
/// vhat_osp_level's bisection on a predicate "Lemma 1 certified exactly at level delta" (delta a
/// dyadic double).
OspLevel osp_level_bisection(const std::function<bool(double)>& certified_at);

}  // namespace hapstab::multidof::detail
