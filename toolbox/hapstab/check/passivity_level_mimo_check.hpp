// hapstab/check/passivity_level_mimo_check.hpp -- the checker of a `passivity-level-mimo`
// certificate: the ISP or OSP level of a square MIMO state space G(z) = C (zI - A)^-1 B + D as
// written (`hapstab passivity-level --ss FILE --kind isp|osp`; paper 000, Definition 2 and Lemma 1;
// docs/passivity-levels.md):
//   phi*   = min_{theta in [0, pi]} lambda_min(He G(e^{j theta})),   He G = (G + G^H)/2      (ISP)
//   delta* = sup {nu : He G - nu G^H G >= 0 on the circle} = min_theta lambda_min(He G^-1)  (OSP)
// the claim "level in [lo, hi]" (or "= v"). OSP is ISP's argument with the pencil
// He G - nu G^H G in place of He G - nu I (below, "ISP -> OSP").  (The values on (pi, 2 pi) mirror those on (0, pi):
// A, B, C, D real give He G(e^{-j theta}) = conj He G(e^{j theta}), the same eigenvalues.)
//
// Derivation (the checker's own; not the producer's det over Q[c][j sin theta] by Faddeev-LeVerrier
// on ss2tf's entries): d(z) = det(zI - A), by exact determinants at z = 0..n and interpolation.
// For a rational nu, Phi(z) = d(z) d(1/z) (G(z) + G(1/z)^T - 2 nu I) has Laurent-polynomial entries
// (exponents -n..n: d G is a polynomial matrix of degree <= n) and Phi(1/z) = Phi(z)^T, so det Phi
// is a symmetric Laurent polynomial of exponents -mn..mn, i.e. a polynomial
//   P_nu(c) in c = (z + 1/z)/2 of degree <= mn.
// On the circle z = e^{j theta}: 1/z = conj z, d(1/z) = conj d(z), G(1/z)^T = G(z)^H, so
//   P_nu(cos theta) = 2^m |d|^{2m} det(He G(e^{j theta}) - nu I)                        (*)
// and |d| > 0 there (A Schur stable): P_nu's roots in [-1, 1] are exactly the theta where nu is an
// eigenvalue of He G. P_nu is interpolated from mn + 1 values at real z = t = 2, 3, ... (c = (t +
// 1/t)/2 distinct; t skipped where d(1/t) = 0), each d(t) d(1/t) times det(G(t) + G(1/t)^T - 2 nu I)
// with G(t) = C (tI - A)^-1 B + D solved exactly.
//
// Theorem checked:
//   (lower) phi* >= lo  iff  He G - lo I >= 0 on the circle, iff (P_lo not identically 0) it is
//     positive definite at one point of every arc between consecutive distinct roots of P_lo in
//     [-1, 1] (the ends c = +-1 belong to the first and last arc when they are not roots). Proof:
//     the eigenvalues of He G(e^{j theta}) - lo I are continuous in theta; on an arc where P_lo != 0
//     none is 0, so none changes sign; at a root each is a limit of values on the neighbouring arcs.
//     The roots are isolated exactly (Sturm counts, check/nonnegative.hpp: sturm_count, on the
//     square-free part; a rational root met by bisection is divided out); each arc is sampled at
//     c = +-1 (when not a root) or at a rational point of the circle z = (1 - t^2 + 2jt)/(1 + t^2),
//     t rational, strictly inside it; positive definiteness there by exact Hermitian Gaussian
//     elimination over Q(j) without pivoting (Sylvester: every pivot > 0), He G(z) from the state
//     space directly (C (zI - A)^-1 B + D in Q(j)). P_lo = 0 identically: not decided (refuted).
//     For lo < phi*, P_lo has no root in [-1, 1] and the test is one sample per end.
//   (upper, certified claim) phi* <= hi  if  He G(z0) - hi I is not positive definite at the
//     witness z0 = c0 + j s0 (evidence.witness_c, witness_s rationals, c0^2 + s0^2 = 1 exactly):
//     then lambda_min(He G(z0)) <= hi.
//   (exact claim "= v") phi* >= v by (lower) with lo = v, and P_v has a root c_r in [-1, 1]: there
//     He G - v I is singular and >= 0, so lambda_min = v at c_r and phi* <= v. No witness.
// ISP -> OSP: d(z) d(1/z) G(1/z)^T G(z) = (d G)(1/z)^T (d G)(z) is a Laurent polynomial matrix of
//   exponents -n..n too, so P_nu(c) = det(d(z) d(1/z) (G(z) + G(1/z)^T - 2 nu G(1/z)^T G(z))) is a
//   polynomial of degree <= mn in c and equals 2^m |d|^{2m} det(He G - nu G^H G) on the circle.
//   He G - nu G^H G is non-increasing in nu (G^H G >= 0), so (lower) holds as stated. Where G is
//   regular, He G - nu G^H G = G^H (He G^-1 - nu I) G (a congruence), so the witness's "not > 0"
//   gives lambda_min(He G^-1(z0)) <= hi, and the exact claim's singular point gives lambda_min = v.
//   Hence the OSP hypotheses: det G != 0 on the circle -- Z(c) = (d(z) d(1/z))^m det G(z) det G(1/z)
//   (degree <= mn, interpolated as P_nu) has no root in [-1, 1] (Z(+-1) != 0, Sturm count 0) --
//   and lo > 0 (an OSP value <= 0 bounds Lemma 1's level only from above, as the SISO kind says).
//   (upper bound only, claim status "upper_bound", {hi[, printed_hi]}: an OSP value <= 0 is written so)
//     level <= hi  if  the pencil at hi is not > 0 at the witness z0 (evidence.witness_c, witness_s on
//     the circle exactly) and, for OSP, det G(z0) != 0 (exact, in Q(j)): then He G^-1(z0) - hi I is
//     not > 0 (a congruence), so for every nu > hi He G - nu G^H G = G^H (He G^-1 - nu I) G is not
//     >= 0 at z0, and the frequency inequality of every level above hi fails (it is necessary for a
//     stable G to be nu-passive). No hypothesis on the rest of the circle; ISP likewise (He G - nu I).
//   (lower bound by Lemma 1, claim status "lower_bound" {lo[, printed_lo]}, or "bounds" with {hi[,
//     printed_hi]} and the witness above beside it; evidence.P, n x n: the LMI's level is the printed
//     result, the frequency value <= 0 not the level) level >= lo  if  P = P' > 0 and paper 000's (2) < 0
//     at Delta = lo I (OSP) or Phi = lo I (ISP) with this P, both by exact symmetric elimination
//     (rational_matrix::lemma1_matrix, every pivot > 0). Proof (the "if" of Lemma 1, in one line): for
//     [x; u] != 0, [x; u]'(2)[x; u] = V(x+) - V(x) - y'u + lo y'y (OSP; + lo u'u for ISP) < 0 with V =
//     x'Px > 0, which is Definition 2's (1) at Delta = lo I; so the system is lo-OSP (ISP) and Lemma 1's
//     level, the supremum of such lo, is >= lo. (2) is non-decreasing in lo (lo times a PSD matrix), so a printed lo
//     rounded down still holds. No frequency hypothesis is used for this part (a zero of G on the circle is
//     allowed).
// Hypotheses, verified: T > 0; model.kind "isp" or "osp"; A
// n x n with n >= 1, B n x m, C m x n, D m x m (square G) with every entry a "p/q" string; A Schur
// stable (check/schur_cohn.hpp on d; then d(t) != 0 for |t| >= 1 and He G is continuous on the
// circle); mn <= 64, m <= 16 (the degree of P; beyond it exit 2). The KYP lemma is cited, not
// checked: the certificate proves the frequency-domain minimum; that it is Lemma 1's ISP level
// (A Schur stable: A'PA - P < 0 forces P > 0) is that theorem.
//
// Implements: paper 000 Definition 2, Lemma 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_passivity_level_mimo(const nlohmann::json& certificate);

}  // namespace hapstab::check
