// hapstab/check/multidof_witness_check.hpp -- the checker of a `multidof-witness` certificate
// (`hapstab multidof analyze --scene S --certificate FILE` where a frequency-domain witness decided):
// paper 000's Theorem 5 program (16) is infeasible for the scene's environment, delay and device
// levels as written, for EVERY admissible multiplier X.
//
// The model: T, the delay n (z^-n), the environment E as written -- an m x m matrix of expressions
// in z, or in s with method backward_euler (s = (z - 1)/(T z)) or tustin (s = 2(z - 1)/(T(z + 1))),
// times its gain g -- the parameters (model.set), the devices in DOF order (a mass-damper 1/(m s +
// b), whose OSP level is b exactly: Re(1/G(jw)) = Re(m jw + b) = b; or a declared level `osp`, part
// of the scene as written) giving Delta_D = diag(delta_i), and the operators (the DOFs each acts
// on; X = diag(g_o(i)) with one multiplier g_o > 0 per operator). E-hat(z) = T z/(z - 1) z^-n g E(z)
// (paper 000 (11)).
//
// Theorem (the easy direction of the KYP lemma; path_witness.cpp proves it in the producer's
// terms, restated here). Let (A, B, C, D) be any realisation of E-hat, P, X, Q_E, Q_V a point of
// (16): M1 <= 0 (its first LMI) and (14) > 0, so Delta_D X - Q_E > 0. For z on the unit circle not
// an eigenvalue of A, u != 0 complex and x = (zI - A)^-1 B u, z x = A x + B u makes the P terms of
// [x; u]^* M1 [x; u] cancel (|z| = 1), leaving -Re(u^* X E-hat(z) u) - u^* Q_E u <= 0; with
// u^* Q_E u < u^* Delta_D X u:
//     phi_X(z, u) = Re(u^* X E-hat(z) u) + u^* Delta_D X u > 0.
// (a) Every admissible X has X E(1) symmetric: E-hat(e^{jt}) = (T/2)(1 - j cot(t/2)) (g E(1) + O(t))
//     as t -> 0+ (E analytic at z = 1, verified: no entry has a pole there), so with u = a + jb,
//     phi_X = (T/2) cot(t/2) a^T (M - M^T) b + O(1), M = g X E(1); if M != M^T some a, b make it
//     -> -inf. With g != 0, X E(1) symmetric is g_o E(1)_ij = g_o' E(1)_ji for i in operator o,
//     j in o': where both entries are 0 nothing; where one is, or their signs differ, or the ratios
//     g_o'/g_o = E(1)_ij / E(1)_ji disagree around a cycle (o = o' included), no X > 0 is admissible
//     (the facial conditions decide: refused here, exit 2). Otherwise the admissible X are
//     X = sum_c g_c X_c, g_c > 0, over the connected components c of the graph of nonzero pairs,
//     X_c carrying the ratio r_o > 0 (relative to c's first operator) on the DOFs of each operator
//     o of c -- r_o = 1 throughout when E(1) is symmetric.
// (b) phi_X = sum_c g_c phi_c, phi_c = phi_{X_c}. The evidence: one point z = z_re + j z_im
//     (rational, z_re^2 + z_im^2 = 1 exactly, z != 1, not a pole of any entry of E) with u = u +
//     j u_im (Gaussian rational, not 0; u_im absent: 0), or several `points` z_j, u_j with weights
//     w_j >= 0 (the several-frequency witness of multidof/path_kyp_search.cpp, where X has several
//     free directions). With S_c = sum_j w_j phi_c(z_j, u_j), it is verified when every S_c <= 0
//     and one is < 0: then sum_j w_j phi_X(z_j, u_j) = sum_c g_c S_c < 0 for every admissible X,
//     so phi_X(z_j, u_j) < 0 at some j; phi_X is continuous at z_j, so it is < 0 at points z' near
//     z_j that are not eigenvalues of the realisation's A (finitely many) -- no point of (16).
// Everything is decided in exact rational arithmetic over Q(j) (check/gaussian_rational.hpp); the
// entries are parsed by lti/parse.hpp and evaluated at z (an s-domain entry N(s)/D(s) as
// sum n_k sigma^k tau^(d-k) / sum d_k sigma^k tau^(d-k), s = sigma/tau, d = max degree: exact at
// s = infinity too). Hypotheses verified: T > 0, n in [0, 100000], 1 <= m <= 512, E(1) finite and
// some X > 0 admissible (a), every device level given, every DOF in exactly one operator.
//
// Implements: paper 000 (11), (14), (16), Theorem 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_multidof_witness(const nlohmann::json& certificate);

}  // namespace hapstab::check
