// hapstab/check/bound_max_check.hpp -- the checker of a `bound-max` certificate
// (`hapstab bound --max K --damping b`): for H = H0 + K H1 (affine in the parameter K, as
// written), b*(K) the passivity bound of paper 001 (45)/(54) of H (check/bound_check.hpp) and the
// device's damping b > 0, the claim is about
//   K_max = sup{ K0 >= 0 : b*(K) < b for every K in [0, K0) }       (the CLI's --max, max_gain.hpp)
// either "K_max in [lo, hi]" (0 <= lo <= hi; "= v" with lo = hi = v) or "K_max = +inf".
//
// Theorem (convexity): b*(K) = sup_w [f0(w) + K f1(w)] + eta is a supremum of functions affine in
// K, so it is convex in K. Hence, with rationals from the certificate:
//   (lo)  K_max >= lo > 0  if  b*(0) <= b0 < b  (evidence.b0_hi = b0)  and  b*(lo) <= b:
//         for K in [0, lo), K = (1 - l) 0 + l lo with l < 1, so b*(K) <= (1 - l) b0 + l b < b;
//   (hi)  K_max <= hi      if  b*(hi) >= b  (K = hi lies in [0, K0) for every K0 > hi);
//         shown by a witness c1 (evidence.witness_c) with f_hi(c1) + eta >= b;
//   (inf) K_max = +inf     if  b*(0) <= b0 < b  and  f1 <= 0 on the band (b*(K) <= b*(0) for K >= 0);
//   (0)   K_max = 0        if  b*(0) = +inf (evidence.at_zero_infinite: bound_check.hpp's evidence of
//         b* = +inf, one of check_bound_infinite's forms, for H0 -- a pole on the circle, or H's pole at
//         z = -1 met by a fractional delay; the claim's status that form's), or H's pole at z = 1
//         (evidence.integrator); b* = +inf above hi by the residue at z = -1 (evidence.jump_at_z) in
//         place of the witness. Each is derived where it is checked (bound_max_check.cpp).
// Each "b*(K) <= x" and "f(c1) >= y" is the test of check/bound_check.hpp on the objective of
// H0 + K H1 (check/bound_objective.hpp: its own derivation, the band [cos(pi/q), 1] in c =
// cos(wT/q), evidence.domain_c_lo); f1 <= 0 is that test on the objective of H1 with bound 0.
//
// Long delays (evidence.witness_theta; beyond the expanded form's size): the same three tests by
// check/bound_cells.hpp's cells, the delay never expanded -- f at K = 0 below b0 on evidence.cells_at_0,
// f at K = lo below b on evidence.cells_at_lo (lo > 0), and f at K = hi above b at witness_theta
// (strict: the claim is widened to leave the cells a margin); K_max = +inf has no such form.
//
// Affinity, proven (never sampled): check/affine.hpp -- the parser's degree bound D of H in K and
// H(k) = H0 + k H1 exactly at D + 1 values of K (the checker's own loop, not split_affine).
//
// Hypotheses verified on the data: b > 0, T > 0, the delay and eta as in bound_check.hpp, K not
// in model.set, H depends on K, 0 <= lo <= hi, the printed decimals are the numbers claimed.
// Not verified: that H0 + K H1 is stable (the premise under which b* is the passivity bound).
//
// Implements: paper 001 (45), (54), Sec. VI, Sec. VII.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_bound_max(const nlohmann::json& certificate);

}  // namespace hapstab::check
