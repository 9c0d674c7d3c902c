// hapstab/check/multidof_facial_check.hpp -- the checker of a `multidof-facial` certificate
// (`hapstab multidof analyze --scene S --certificate FILE` where the facial conditions decided):
// paper 000's Theorem 5 program (16) is infeasible because NO admissible multiplier X makes
// X E(1) symmetric. The model is the `multidof-witness` kind's (check/multidof_witness_check.hpp:
// T, the delay, the environment E as written with its gain g and perturb_C, the devices, the
// operators); the evidence is empty: the claim follows from the model alone.
//
// Theorem ((a) of the witness kind). For every point of (16) with multiplier X and every z = e^{jt},
// u = a + jb, phi_X(z, u) = Re(u^* X E-hat(z) u) + u^* Delta_D X u > 0, and as t -> 0+
//     phi_X = (T/2) cot(t/2) a^T (M - M^T) b + O(1),  M = g X E(1)
// (E analytic at z = 1). If M != M^T, some a, b make phi_X -> -inf: X is no point of (16). With
// X = diag(g_o(i)), one g_o per operator, X E(1) symmetric is the linear system
//     g_o(i) E(1)_ij = g_o(j) E(1)_ji   for all i < j   (and E(1)_ij = E(1)_ji within an operator);
// when its only solution is g = 0, every admissible X (g_o >= 1) has M != M^T (g != 0), so (16)
// has no point. Verified: E(1) finite (no entry has a pole at z = 1), g != 0, and the system's
// rank equals the number of operators (Gaussian elimination over Q, exactly); a solution g != 0 of
// the system refutes the certificate (the facial conditions do not exclude (16) there).
//
// Implements: paper 000 (11), (16), Theorem 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

/// A `multidof-facial` certificate: verified, refuted (why) or InputError (malformed).
Verdict check_multidof_facial(const nlohmann::json& certificate);

}  // namespace hapstab::check
