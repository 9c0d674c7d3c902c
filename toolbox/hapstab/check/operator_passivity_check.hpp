// hapstab/check/operator_passivity_check.hpp -- the checker of an `operator-passivity` certificate:
// Assumption 1(b) of paper 000 (every operator Z_O(s) passive, i.e. positive real) fails for the
// operator the claim names, in the scene as written (`hapstab multidof analyze --scene S
// --certificate FILE` where (16) is feasible but that premise fails, so Theorem 5 concludes nothing;
// paper 000 Sec. VI case i: the 2x2 operator H1).
//
// Model: {scene, set}, read by check/scene_model.hpp's read_scene_loop (the `stability-loop`
// reading: what it does not model is refused by name); the operator is the [[operator]] table whose
// `name` is claim.operator, given by `tf` (a matrix in s, parameters expanded) or by `ss` as written
// (Z(jw) = C (jwI - A)^-1 B + D solved over Q(j); jwI - A singular there: refuted, nothing shown). Claim: {quantity, status "exact", operator, passive: false}. Evidence: w (a rational)
// and minor (the 0-based rows, increasing, of a principal minor).
// Theorem: a positive real Z has He Z(jw) = (Z(jw) + Z(jw)^H)/2 >= 0 at every real w that is not a
// pole, so every principal minor of He Z(jw) is >= 0 there. Verified exactly in Q(j): no entry of Z
// has a pole at s = jw (each denominator non-zero there), and the determinant of He Z(jw)'s
// principal submatrix on `minor` (Hermitian: real; Gaussian elimination over Q(j)) is < 0. Then Z is
// not positive real: Assumption 1(b) fails, and Theorem 5 draws no conclusion for the scene.
// Or evidence {pole: w0} (a rational w0 >= 0), or {pole_squared: q} (w0 = sqrt(q), q > 0 rational: an irrational
// w0 such as sqrt(2) too): the residue at the axis pole s = j w0. Theorem (e.g.
// Anderson & Vongpanitlerd, Network Analysis and Synthesis, Thm 2.7.2): a positive real Z has only
// simple poles on the imaginary axis, each with a Hermitian positive semidefinite residue. Verified
// exactly: Z entry by entry as rational functions (an ss operator's by chi = det(sI - A) and
// chi (Z - D) = C adj(sI - A) B interpolated at integers, exactly), each in lowest terms (gcd); the
// pole's order = the multiplicity of s (q = 0) or s^2 + q in its denominator d: >= 2 fails; for a simple
// pole R_ij = n(j w0)/d'(j w0) = X + j w0 Y with X, Y rational (p(j w0) = E_p(-q) + j w0 O_p(-q), p's even and
// odd parts); R not Hermitian (X symmetric, Y antisymmetric), or [[X, -Y], [Y, X/q]] -- congruent to the
// real [[X, -w0 Y], [w0 Y, X]] by diag(I, I/w0), Sylvester's law of inertia -- not positive semidefinite
// (symmetric elimination; X alone at q = 0), fails. A negative spring
// -k/s (He Z(jw) = b >= 0 everywhere: no minor shows it) and a resonance -k s/(s^2 + w0^2) are the cases.
// (The converse, "passive", has no certificate here: it needs every minor >= 0 on the whole axis.)
// Implements: paper 000 Assumption 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_operator_passivity(const nlohmann::json& certificate);

}  // namespace hapstab::check
