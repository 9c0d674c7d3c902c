// hapstab/check/passivity_level_check.hpp -- the checker of a `passivity-level` certificate of a
// SISO G(z) given by --H (paper 000, Definition 2 and Lemma 1; docs/passivity-levels.md):
//   ISP level  phi*   = min_{theta in [0, pi]} Re G(e^{j theta}),
//   OSP level  delta* = min_{theta in [0, pi]} Re(1/G(e^{j theta})),
// the claim "level in [lo, hi]" (or "= v").
//
// Derivation (the checker's own; not the producer's route through -b* of (z - 1) W): with
// c = cos(theta), G = N/D and N conj(D) = X + js Y on the circle (check/on_circle.hpp),
// Re G = X/|D|^2 and Re(1/G) = Re(D conj(N))/|N|^2 = X/|N|^2: one polynomial X over
// Q = |D|^2 (ISP) or |N|^2 (OSP), Q = a^2 + (1 - c^2) b^2 > 0 on [-1, 1] (hypothesis below).
// theta in [0, pi] <-> c in [-1, 1] one to one (the values on (pi, 2 pi) mirror them).
// Theorem checked:
//   level >= lo  iff  X - lo Q >= 0 on [-1, 1]            (check/nonnegative.hpp, Yun + Sturm);
//   level <= hi  if   X(c0) - hi Q(c0) <= 0 at the witness c0 in [-1, 1] (evidence.witness_c).
// Hypotheses, verified: G causal (deg N <= deg D); G Schur stable (check/schur_cohn.hpp on D):
// then the ISP value is Lemma 1's level by the strict discrete KYP lemma (docs/passivity-levels.md);
// no pole of G on the circle follows. OSP: no zero of G on the circle (|N|^2 > 0 on [-1, 1], by
// check/max_positive.hpp) and delta* > 0 (lo > 0): the conditions under which delta* is Lemma 1's
// level. An OSP value <= 0 (Lemma 1 also needs P > 0, which the frequency inequality does not
// impose), or one of a G with a zero on the circle, is an upper bound of the level only: the claim
// is then status "upper_bound" and "hi" (level <= hi), proven by the witness alone: Re W(c0) <= hi
// with Q(c0) > 0, so for every nu > hi the frequency inequality He G - nu G^* G >= 0 (OSP; He G - nu
// >= 0, ISP), necessary for a nu-passive stable G, fails at z0 (none of the hypotheses above is needed). The KYP lemma itself is cited, not checked: the certificate proves the frequency-
// domain minimum; that it is the level of Definition 2 for G's minimal realisation is that theorem.
// A lower bound by Lemma 1 (status "lower_bound" {lo}, or "bounds" {lo, hi} with the witness above;
// the LMI's level is the printed result): evidence A, B, C, D (a realisation, one input, n states)
// and P. Verified: (A, B, C, D) realises G as written -- D + C (tI - A)^-1 B (by the matrix
// determinant lemma, (det(tI - A + BC) - det(tI - A))/det(tI - A) + D) equals N/D at n + deg D + 1
// points t = 2, 3, ... where both are defined; the difference of the cross products has degree <=
// n + deg D, so it is 0 --; then Lemma 1 at lo with P (rational_matrix::lemma1_level_fails: P = P' >
// 0 and (2) < 0; its "if" is (1) with V = x'Px, check/passivity_level_mimo_check.hpp): G's
// input-output map from rest is lo-OSP (ISP), so the level is >= lo. No frequency hypothesis.
//
// Implements: paper 000 Definition 2, Lemma 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_passivity_level(const nlohmann::json& certificate);

}  // namespace hapstab::check
