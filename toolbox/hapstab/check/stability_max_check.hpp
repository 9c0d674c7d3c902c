// hapstab/check/stability_max_check.hpp -- the checker of a `stability-max` certificate
// (`hapstab stability --plant P --H H --max K`): the one-DOF sampled loop of the `stability` kind
// (check/loop_model.hpp: every device pole at s = 0, an integer delay n), with the wall
// H = H0 + K H1 affine in the parameter K (proven: check/affine.hpp), and the claim about
//   K_max = sup{ K0 > 0 : the loop is stable for every K in (0, K0) }   (docs/stability.md; 0 when
//                                                                        no K0 > 0 qualifies)
// either "K_max in [lo, hi]" (0 <= lo <= hi; "= v" with lo = hi = v; "= 0") or "K_max = +inf".
//
// The loop at K is the `stability` kind's: H(K) = H0 + K H1 reduced to A_K/L_K and
// c_K = z^n L_K (z - 1)^k + A_K Nd. The family: with L = lcm(L0, L1) (H0 = A0/L0, H1 = A1/L1),
//   c(z; K) = z^n L (z - 1)^k + (A0 L/L0 + K A1 L/L1) Nd = c0(z) + K c1(z),
// and c(.; K) = g_K c_K with g_K = gcd(A0 L/L0 + K A1 L/L1, L): a factor of L, non-constant at
// finitely many K only (a root r of L with multiplicities m0, m1 in L0, L1 is a root of
// A0 L/L0 + K A1 L/L1 for at most one K: if m0 != m1 exactly one of the two terms vanishes at r,
// if m0 = m1 neither does). So c(.; K) stable => c_K stable, and c_K = c(.; K) off finitely many K.
// deg c1 < deg c0 = d (z^-n H0, z^-n H1 causal, P_d strictly proper; checked): the leading
// coefficient of c(.; K) does not depend on K.
//
// Theorem. Roots move continuously in K while the degree and the leading coefficient stay, and a
// root leaves the open unit disc only through the circle; a root on the circle makes
// D(K) = Res_{d,d}(c, c*) vanish, and D(K) = 0 makes c(.; K) NOT stable (check/reciprocal.hpp).
// So on an interval J of K where D has no root, c(.; K) is stable at every K or at none: the
// stable K of J are open in J (roots continuous) and closed in J (a limit of stable K not stable
// has a root on the circle, D = 0). With rationals from the certificate, Schur-Cohn exact
// (check/schur_cohn.hpp) and the roots of D counted exactly (Descartes, Sturm):
//   (lo)  K_max >= lo > 0  if c(.; K0) is stable at evidence.stable_at = K0 in (0, lo) and D has no
//         root in (0, lo): then c(.; K), so the loop, is stable on (0, lo);
//   (hi)  K_max <= hi, hi > 0, if the loop at K = hi (c_hi, as the `stability` kind) is NOT stable;
//   (0)   K_max = 0  if c(.; e) is NOT stable at evidence.unstable_at = e > 0 and D has no root in
//         (0, e] or D = 0 identically (then every c(.; K) has a pair b, 1/b of roots: NOT stable):
//         c(.; K), so c_K off finitely many K, is NOT stable on (0, e], and no (0, K0) is stable;
//   (inf) K_max = +inf  if c(.; K0) is stable at K0 = evidence.stable_at > 0 and D has no root in
//         (0, inf).
// An exact claim K_max = k uses (lo) and (hi) with lo = hi = k (D may vanish at k itself).
// D also vanishes where a pair b, 1/b of roots lies off the circle: such K in (0, lo) refute the
// certificate (conservative; the producer chooses lo below them or refuses).
//
// Hypotheses verified on the data: T > 0, n an integer in [0, 100000], the device (as for
// `stability`) with every pole at s = 0 and not depending on K (K in model.set is refused: the
// parameter has no value), H affine in K and depending on it, z^-n H0 and z^-n H1 causal,
// deg c1 < deg c0 = d <= 150, 0 <= lo <= hi, the printed decimals are the numbers claimed.
// Size: D has degree <= 2d in K, interpolated from 2d + 1 exact resultants.
// Implements: paper 001 Fig. 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_stability_max(const nlohmann::json& certificate);

}  // namespace hapstab::check
