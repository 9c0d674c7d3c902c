// hapstab/check/stability_loop_max_symmetric_check.hpp -- the checker of a `stability-loop-max-symmetric`
// certificate: the largest gain p for which a scene's loop of identical DOFs is stable (`hapstab stability
// --scene S --max p --certificate FILE` where hapstab maximised on the split, stability/loop_max_symmetric.hpp),
//   sup p = sup{ p0 > 0 : the loop is stable for every p in (0, p0) }   (0 when no p0 > 0 qualifies),
// claimed in [lo, hi] (claim.status "certified") or sup = 0 (lo = hi = 0), shown on the small loops of the split
// by the permutations of identical DOFs, which this checker derives itself from the scene as written.
//
// Theorem. Let p be the whole gain of [environment], named in no other string of the scene (stability-loop-max's
// reading, check/stability_loop_max_check.hpp): the scene at p is the scene at 1 with E times p, E(p) = p E(1).
// Let evidence.classes be a partition under which the loop read at p = 1 is invariant (check/
// stability_loop_symmetric_check.hpp's split_loop: identical devices and operators, E's entries equal by class,
// all N^2 compared exactly). Then E(p) = p E(1) is invariant for every p, and at every p the closed loop's
// spectrum is that of the fixed space's loop M_F(p) (r DOFs under E_F(p)) and of each class's zero-sum loop
// M_a(p), k_a - 1 times (stability-loop-symmetric's theorem at that p), the conserved quantities adding as
// k_F + sum_a (k_a - 1) k_a'. Each block's environment is built from E(p)'s entries by sums fixed by the classes,
// so it is p times the block's at 1: the checker reads each block at p = 1 and 2 from the splits of the loops read
// there, and stability-loop-max's gain test on the block's realisations (A, B equal, C, D doubled) shows M_b(p) =
// (2 - p) M_b(1) + (p - 1) M_b(2) for every p. So:
//   * every block stable on [0, lo] (each block's cover to lo, after its first-order start where its M_b(0) is
//     only marginally stable; stability-loop-max's tests, check_max_part) => the loop is stable on (0, lo]: sup >= lo;
//   * one block NOT stable at hi (its unstable_at: Stein inertia) => the loop is NOT stable at hi: sup <= hi;
//     hi = 0: that block's M_b(0) has an eigenvalue outside the circle, so has M_b(p), hence M(p), for every small
//     p > 0: sup = 0.
// Evidence: classes, blocks [{space: "fixed" | "zero-sum", class (zero-sum), conserved (absent: 0), cover,
// first_order, unstable_at}]. hi > 0: every block (the fixed one and one per class of two DOFs or more), each with
// a cover exactly when lo > 0, exactly one with unstable_at (at hi), claim.conserved = k_F + sum_a (k_a - 1) k_a'.
// hi = 0: one block, its unstable_at at 0, no cover; claim.conserved absent.
// Refused by name (InputError): p inside a tf or the gain of [coupling], what stability-loop-symmetric refuses (a
// [coupling], an ss environment, a block on more than one DOF), more than 256 DOFs, a block beyond stability-loop-
// max's limits (order 160, 4096 intervals). A partition under which the scene is not invariant refutes the claim.
// Implements: paper 000 Sec. VI; paper 001 Fig. 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_stability_loop_max_symmetric(const nlohmann::json& certificate);

}  // namespace hapstab::check
