// hapstab/check/stability_loop_max_symmetric_check.hpp -- the checker of a `stability-loop-max-symmetric`
// certificate: the largest gain p for which a scene's loop of identical DOFs is stable (`hapstab stability
// --scene S --max p --certificate FILE` where hapstab maximised on the split, stability/loop_max_symmetric.hpp),
//   sup p = sup{ p0 > 0 : the loop is stable for every p in (0, p0) }   (0 when no p0 > 0 qualifies),
// claimed in [lo, hi] (claim.status "certified") or sup = 0 (lo = hi = 0), shown on the small loops of the split
// by the permutations of identical DOFs, which this checker derives itself from the scene as written.
//
// Theorem. Let p enter [environment] only, as stability-loop-max reads it (check/stability_loop_max_check.hpp): its
// whole gain, named in no other string (the scene at p is the scene at 1 with E times p, E(p) = p E(1)); or inside
// its tf (a compact scene's diagonal / off_diagonal are its entries), each entry naming p proven affine, E(p) = E0 +
// p E1. Let evidence.classes be a partition under which the loops read at p = 1 and 2 are invariant (check/
// stability_loop_symmetric_check.hpp's split_loop: identical devices and operators, E's entries equal by class, all
// N^2 compared exactly). Each entry being affine in p, equal at p = 1 and 2 means equal at every p: E(p) is
// invariant for every p, and at every p the closed loop's spectrum is that of the fixed space's loop M_F(p) (r
// DOFs under E_F(p)) and of each class's zero-sum loop M_a(p), k_a - 1 times (stability-loop-symmetric's theorem
// at that p), the conserved quantities adding as k_F + sum_a (k_a - 1) k_a'. Each block's environment is built
// from E(p)'s entries by sums fixed by the classes, so it is affine in p too, and its column b is realised over the
// whole's column f_b's lcm: the checker reads each block from the splits of the loops read at p = 1, 2 (and hi),
// and stability-loop-max's test on the block's realisations -- the gain: A, B equal, C, D doubled; inside: A, B
// equal at 1, 2 and hi, of the block's largest order (the sum of its columns' deg L_{f_b}, L_j the lcm of column
// j's den E0, den E1: a pole cancelled at one of them is beyond), C, D at hi on the line -- shows M_b(p) = (2 - p)
// M_b(1) + (p - 1) M_b(2) for every p (inside: R_b(p), whose eigenvalues hold the block's as read). So:
//   * every block stable on [0, lo] (each block's cover to lo, after its first-order start where its M_b(0) is
//     only marginally stable; stability-loop-max's tests, check_max_part) => the loop is stable on (0, lo]: sup >= lo;
//   * one block NOT stable at hi (its unstable_at: Stein inertia) => the loop is NOT stable at hi: sup <= hi;
//     hi = 0: that block's M_b(0) has an eigenvalue outside the circle, so has M_b(p), hence M(p), for every small
//     p > 0 (or its first_order_unstable: M_b(p) NOT stable on (0, eps], stability-loop-max's mirror): sup = 0.
// Evidence: classes, blocks [{space: "fixed" | "zero-sum", class (zero-sum), conserved (absent: 0), cover,
// first_order, unstable_at, first_order_unstable}]. hi > 0: every block (the fixed one and one per class of two DOFs or more), each with
// a cover exactly when lo > 0, exactly one with unstable_at (at hi), claim.conserved = k_F + sum_a (k_a - 1) k_a'.
// hi = 0: one block, its unstable_at at 0 or its first_order_unstable, no cover; claim.conserved absent.
// Refused by name (InputError): p the gain of [coupling] or named elsewhere, what stability-loop-symmetric refuses (an
// ss environment or coupling, a block on more than one DOF), more than 256 DOFs, a block beyond stability-loop-
// max's limits (order 160, 4096 intervals). A partition under which the scene is not invariant refutes the claim.
// Implements: paper 000 Sec. VI; paper 001 Fig. 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_stability_loop_max_symmetric(const nlohmann::json& certificate);

}  // namespace hapstab::check
