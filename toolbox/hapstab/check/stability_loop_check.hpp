// hapstab/check/stability_loop_check.hpp -- the checker of a `stability-loop` certificate: the Schur
// stability of a multi-DOF scene's sampled-data loop as written (`hapstab stability --scene S
// --certificate FILE` beyond one DOF; paper 000 Sec. VI's loop, paper 001 Fig. 1 per DOF), from the
// scene's text (check/scene_model.hpp's read_scene_loop), with the loop built here:
//
//   plant    per DOF i the state (v_i, x_i): m_i v_i' = -b_i v_i - k_i x_i + u_i - (Z v)_i, x_i' = v_i;
//            each tf operator Z(s) on its ports realised column by column (column j: the monic lcm
//            d_j of its denominators, a controllable companion form of the strictly proper part,
//            D_j the direct part), an ss operator as written (velocities of its ports in, forces
//            out), their states after the DOFs' in operator order. Outputs y = x.
//   hold     s_{k+1} = Phi s_k + Gamma u, [Phi Gamma; 0 I] = exp([A B; 0 0] T) (Arb's arb_mat_exp).
//   wall     E(z) N x N realised column by column the same way (an ss block as written): xi+ =
//            A_E xi + B_E x_e; a [coupling] V(z) likewise, eta+ = A_V eta + B_V u, in parallel with
//            the device (paper 000 (11)): x_e = y + C_V eta + D_V u, u = -(C_E xi + D_E x_e), solved
//            exactly: u = -W (D_E C_x s + C_E xi + D_E C_V eta), W = (I + D_E D_V)^-1 (singular:
//            malformed). The force u_k computed from the samples at kT is applied from kT + t_d on,
//            t_d = n T + f (0 <= f < T): s+ = Phi_T s + Phi_{T-f} Gamma_f u_{k-n-1} + Gamma_{T-f} u_{k-n},
//            the state X = [s; xi; eta; u_{k-1}; ...; u_{k-L}] (L = n, or n + 1 when f > 0), X+ = M X.
//
// Theorem (Stein; the inertia form, e.g. Ostrowski & Schneider 1962): if Q = P - M^T P M > 0 for a
// symmetric P, M has no eigenvalue on |z| = 1 (M v = z v gives v* Q v = (1 - |z|^2) v* P v), and
// M is Schur stable iff P > 0 (if M were stable, P = sum (M^T)^k Q M^k > 0). Evidence: P (exact,
// symmetric) and, for NOT stable, w with w^T P w < 0. Verified: P symmetric; P > 0 (proven: the test below on
// P's exact balls, or exact elimination up to order 24 where that does not pass) or w^T P w < 0 (exactly, in
// rationals); Q > 0 for every M in the enclosure: Q's entries in balls (128, 256, 512 bits),
// S := D (Q + Q^T)/2 D in balls (a symmetric A in Q has A_ij = (A_ij + A_ji)/2, so D A D lies in S; D =
// diag(2^-k_i), 2^k_i ~ sqrt(mid Q_ii): a congruence, exact), and every matrix in S positive definite:
// X ~ L^-T from a double Cholesky of S's midpoints (upper triangular, non-zero diagonal: non-singular; its
// doubles taken as exact), G = X^T S X in balls (it holds X^T A X for every A in S), and
// min_i (G_ii - sum_{j != i} |G_ij|) > 0 (Gershgorin). (The exact elimination took 34 s at order 115; this
// takes 0.2 s; the ball products by arb_mat_mul from order 32 on. Until stop 85 S was formed in rationals from
// the balls' midpoints, the radii bounded apart by their largest row sum r and added as ||X||_F^2 r (Weyl):
// the same test, twice as slow from the rational conversions.)
// Size: M's order <= 1024, a scene of <= 64 DOFs (order 448: 5.6 s). A P that does not pass refutes the claim
// (exit 1): the evidence does not prove it.
// Conserved quantities: l with l^T [A B] = 0 exactly (A, B the continuous plant above, rationals) keeps
// l^T s constant in the loop whatever the controller does: l^T A^k = 0 for k >= 1, so l^T Phi_h = l^T
// and l^T Gamma_h = 0 for every h, and l (zero beyond the plant's states) is a left eigenvector of M,
// eigenvalue 1. An operator's spring written as k/s, or in an ss operator's states, integrates the
// velocity the position x does, and a device written with its own position state does the same: each
// gives one. The checker computes their basis itself (exact elimination; l_i = 1 at index c_i, 0 at
// the other c_j), and M is decided on the quotient: with T = [rows of I but the c_i; L], T M T^-1 =
// [M11 M12; 0 I_k], M11 = M[kept, kept] - M[kept, c] L[:, kept]. The claim states k (claim.conserved;
// absent: 0), and must be the checker's k (else refuted: with k > 0, M itself has the eigenvalue 1).
// "stable" with k > 0 means: M11 Schur stable, so the eigenvalue 1 is semisimple and every solution
// settles to the equilibrium its conserved quantities select (not asymptotically stable: say so);
// "NOT stable": M11 has an eigenvalue with |z| > 1. P (and w) are of M11's order.
// A `--plant` P without a pole at s = 0 is realised as G = s P with its position integrated: that
// adds one conserved quantity of the checker's own (x - K xi, K A_G = C_G, K B_G = 0, as G(0) = 0),
// and its quotient sets x = K xi, P's own output: the loop as written. It is set aside and not
// counted in claim.conserved.
// The wall's and the coupling's uncontrollable z = 1 (a constant the block hides: l^T (A - I) = 0, l^T B =
// 0 in its states, as realised here) is one too: (l^T xi)+ = l^T A xi + l^T B x_e = l^T xi, so L = [0 l 0
// ...] has L M = L, a left eigenvector of M like the plant's; each is counted in claim.conserved and set
// aside by the same quotient (a semisimple z = 1 that settles, as `stability` says). An unobservable one
// (r with (A - I) r = 0, C r = 0; a fully hidden mode is both, paired below) is a right eigenvector of M
// (C r = 0 keeps the force and x_e at 0, so the block's states stay r): after the left quotient, M11 is
// taken on the quotient by them too -- in reduced echelon form (r_j 1 at its own c_j, 0 at the others'),
// M[a][b] - sum_j r_j[a] M[c_j][b] on the other coordinates -- and counted the same way. So is the plant's
// unseen s = 0 (A r = 0, no position in r: y = x never sees it; an ss device's own position).
// Left beside right ones (k and m of them): G = L R^T of rank g pairs them; the m - g combinations N R, G N = 0,
// lie in ker L. If g = k, R^n = span(R_paired) + ker L with M = I on the first; if g = m, no right one lies
// in ker L; either way z = 1 is semisimple of multiplicity k + m - g when M on ker L modulo N R is Schur
// stable (a block triangular M whose other block has no eigenvalue 1 is similar to the block diagonal one).
// g < k and g < m together (a constant no sum pairs beside a sum no constant pairs: a possible Jordan block)
// is refused; an N R with a part in the plant (it could move with a plant parameter) is refused by the --max kinds.
// The loop is otherwise the scene's loop as written: hidden modes of the column realisations are
// eigenvalues of M here; a Stein certificate exists only where they are off the circle (other than the
// conserved quantities), and then they are part of M.
// NOT stable by a hidden mode (claim status "exact", evidence.hidden {block: environment | coupling,
// kind: unobservable | uncontrollable, basis, A_h}, in place of P and w): for an ss block as written
// (C, D times gain), unobservable C V = 0, A V = V A_h (V = basis, n x r), or uncontrollable W B = 0, W
// A = A_h W (W = basis, r x n); the basis of full rank (Gram matrix regular); det(zI - A_h) = (z -
// 1)^k q, q(1) != 0, q not Schur stable. Theorem: X = [0; V alpha; 0 ...] in the block's rows gives
// the block's output 0, so u = 0 and nothing else moves: M X = [0; V A_h alpha; 0 ...]; uncontrollable,
// L = [0 W 0 ...] has L M = A_h L (W B = 0 cuts the block's input). So eig(A_h) is in eig(M), and a root
// lambda != 1 of q with |lambda| >= 1 is an eigenvalue of M no conserved quantity (eigenvalue 1)
// accounts for: NOT stable, on the circle too, where Stein cannot certify. No M in balls is needed.
// Continuous blocks (block "device" or "operator" with its name, written as ss): the same conditions on
// (A, B, C) as written; det(sI - A_h) = s^k q, q(0) != 0, q not Hurwitz (Cayley map onto the disc, then
// Schur-Cohn): a root lambda != 0, Re lambda >= 0, is the eigenvalue e^{lambda T} of M after the hold,
// |.| >= 1 and != 1 (lambda T = 2 pi j m is impossible for algebraic lambda and rational T).
// Implements: paper 000 Sec. VI; paper 001 Fig. 1.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/rational_matrix.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::check {

namespace detail {
// The pieces check/stability_loop_max_check.hpp shares (its certificates are about the same loop).
using BallRows = std::vector<std::vector<flint::Ball>>;
struct LoopMatrix {
  BallRows M;            ///< on the quotient by the conserved quantities (all of M when there are none)
  size_t conserved = 0;  ///< k, the model's (the checker's own, SceneLoop::own_conserved, not counted)
  size_t order = 0;      ///< M's order before the quotient
  /// the controller's realisations as built here: A_E, B_E, C_E, D_E, A_V, B_V, C_V, D_V (V empty without a coupling)
  std::vector<rational_matrix::Mat> controller;
  bool feedthrough_loop = false;  ///< D_E D_V != 0 or D_V D_E != 0: u and x_e solved through W = (I + D_E D_V)^-1
  /// the quotient by the conserved rows l (l^T M = l^T): x = E y on {l^T x = 0}, y M's coordinates (empty
  /// when there are none); right_quotient: then also by a block's unobservable z = 1 (right eigenvectors)
  rational_matrix::Mat embedding;
  bool right_quotient = false;
  /// a right eigenvector of that quotient has a part in the plant (its unseen s = 0): it could move with a plant
  /// parameter, which the --max kinds refuse
  bool plant_right = false;
};
/// M of the loop L as above, e^{AT} in balls at `bits`.
LoopMatrix loop_matrix(const SceneLoop& L, long bits);
/// M of the loop L exactly (the whole, no quotient), where the plant's A is nilpotent (pure masses: e^{Ah} and
/// Gamma_h finite sums); else nullopt.
std::optional<rational_matrix::Mat> exact_loop_matrix(const SceneLoop& L);
/// Q = P - M^T P M > 0 for every M in the balls (the header's test); else false, `why` set.
bool stein_holds(const rational_matrix::Mat& P, const BallRows& M, std::string& why);
/// With P and M linear in t on [0, 1] (Pa, Ma at 0; Pb, Mb at 1): the four Bernstein coefficients of the cubic
/// P(t) - M(t)^T P(t) M(t) positive definite in balls (so it is on [0, 1]); else false, `why` set.
bool bernstein_stein_holds(const rational_matrix::Mat& Pa, const rational_matrix::Mat& Pb, const BallRows& Ma, const BallRows& Mb,
                           std::string& why);
/// Every symmetric matrix in the balls Q is positive definite (the header's test of Q); else false, `why` set.
bool ball_positive_definite(const BallRows& Q, std::string& why);
/// The rows r^T of the loop's slow modes at p = 0 of the family read at p = 1 (L1) and 2 (L2), on the
/// coordinates of m1.M (the quotient by the conserved quantities, m1 the loop at p = 1), in reduced row
/// echelon form: r^T M(0) = r^T exactly (l_p^T A = 0: the positions that nothing holds at p = 0; the exact
/// slow matrix, stability_loop_check.cpp; on a quotient, r = l^T E). Empty when none. InputError on a
/// quotient by right eigenvectors (beyond).
rational_matrix::Mat slow_rows(const SceneLoop& L1, const SceneLoop& L2, const LoopMatrix& m1);
/// M on ker L (L M = L, L in reduced echelon form, invariant: x_pivot = -L[:, kept] y, M_r = M[kept, :] E):
/// its eigenvalues are M's but for the slow ones L carries.
BallRows restricted(const BallRows& M, const rational_matrix::Mat& L);
/// Every symmetric matrix within r of S is positive definite (a double Cholesky's inverse as congruence).
bool positive_definite_within(const rational_matrix::Mat& S, const rational& r);
/// P > 0 (exact, symmetric P): the congruence test on P's exact balls (sufficient), else (order <= 24) exact
/// elimination decides.
bool positive_definite(const rational_matrix::Mat& P);
/// NOT stable by evidence.hidden (the header): verified, or refuted with what fails.
Verdict hidden_mode_verdict(const SceneLoop& L, const nlohmann::json& hidden);
/// The header's theorem on the loop L from `evidence` = {P[, w]} (named `where` in messages): M built here,
/// its k conserved quantities compared with `conserved`, Q = P - M^T P M > 0 in balls, P > 0 (stable) or
/// w^T P w < 0 (NOT stable). InputError for evidence of the wrong shape.
Verdict stein_verdict(const SceneLoop& L, const nlohmann::json& evidence, bool stable, long conserved, const std::string& where);
/// The monic lcm of each column's denominators: the order of the column's companion block above.
std::vector<Polynomial<rational>> column_lcms(const std::vector<std::vector<RationalFunction<rational>>>& G);
/// G realised column by column as above, column j over over[j] (monic, a multiple of every denominator of the
/// column), as an ss block: a block of a split loop keeps the whole's column blocks (stability_loop_symmetric_check.hpp).
SceneLoop::Discrete column_realisation(const std::vector<std::vector<RationalFunction<rational>>>& G,
                                       const std::vector<Polynomial<rational>>& over);
}  // namespace detail

/// M of the scene's loop as above (model: {"scene", "set"}), on the quotient by the conserved
/// quantities: each entry's enclosure [lo, hi], exact rationals, computed in balls at `bits` (for the
/// producer, which solves P from its midpoint), and their number k.
struct SceneLoopMatrix {
  std::vector<std::vector<std::pair<rational, rational>>> M;
  size_t conserved = 0;
};
SceneLoopMatrix scene_loop_matrix(const nlohmann::json& model, long bits);

Verdict check_stability_loop(const nlohmann::json& certificate);

}  // namespace hapstab::check
