// hapstab/check/wedge_check.hpp -- the checker of a `wedge` certificate: the exact verdicts of
// `hapstab wedge --H` for H(z) as written (Tsai & Colgate, paper 002):
//   wedge (25)    Re H(e^{j theta}) + cot(theta/2) |Im H(e^{j theta})| + 1 > 0 for every theta in [0, pi]
//   Tsypkin (21)  Re H(e^{j theta}) + 1 > 0 for every theta in [0, pi]
//   assumptions (Sec. 2)  H stable, (1 + H)^{-1} stable, H(1) >= 0
// Derivation (the checker's own; not contact::wedge_branches, which works in u = tan^2(theta/2)):
// with c = cos(theta), s = sin(theta) >= 0, H = N/D and (check/on_circle.hpp) N = Nr + js Ni,
// D = Dr + js Di, N conj(D) = X + js Y, |D|^2 = Dr^2 + (1 - c^2) Di^2:
//   Re H = X/|D|^2,  Im H = s Y/|D|^2,  cot(theta/2) = (1 + c)/s,  so
//   (25) holds iff max(P+, P-) > 0 on [-1, 1],  P+- = X +- (1 + c) Y + |D|^2   (|D|^2 > 0 there),
//   (21) holds iff S = X + |D|^2 > 0 on [-1, 1]
// (theta -> 0 and theta -> pi are the values at c = 1 and c = -1: the polynomials are continuous).
// Decided exactly by check/max_positive.hpp (Sturm isolation of the roots of P+ P-). The
// assumptions by the checker's Schur-Cohn (check/schur_cohn.hpp) on D and on D + N, and H(1)
// exactly (false when D(1) = 0).
// Hypotheses verified: H causal (deg N <= deg D), no pole of H on the unit circle (|D|^2 has no
// root in [-1, 1]: else the criteria are not evaluated and the certificate is refused, exit 2).
// Claims checked: claim.wedge, claim.tsypkin, claim.h_stable, claim.closed_loop_stable,
// claim.dc_gain_nonnegative (all booleans; status "exact"); and, when present, the margins and
// largest gains the command prints, for each criterion (<key> = wedge, tsypkin):
//   claim.<key>_margin {lo, hi, printed}: mu = min over theta of the left side + 1, i.e. the min over
//     c in [-1, 1] of max(P+, P-)/|D|^2 (Tsypkin: S/|D|^2), lies in [lo, hi]:
//       mu >= lo  iff max(P+ - lo |D|^2, P- - lo |D|^2) >= 0 on [-1, 1] (max_positive_on, non-strict);
//       mu <= hi  if  max(P+, P-) <= hi |D|^2 at the rational witness c0 = evidence.<key>_witness_c;
//   claim.<key>_gain {lo, hi, printed} or {infinite: true}: k* = sup{k > 0 : k H meets the criterion}.
//     The left side of k H is k times that of H, so k H meets it iff k (mu - 1) + 1 > 0, and
//     k* = 1/(1 - mu) when mu < 1, +inf when mu >= 1: k* >= lo iff mu >= 1 - 1/lo, k* <= hi iff
//     mu <= 1 - 1/hi (the same two tests; the first is implied, and not run again, when the margin's
//     lo, already shown, is >= 1 - 1/lo), +inf iff max(P+ - |D|^2, P- - |D|^2) >= 0;
//   printed (the decimal the command printed, its shared digits): both lo and hi round to it
//     (within half a unit of its last digit), so the value does too.
// Implements: paper 002 (21), (25), Sec. 2.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_wedge(const nlohmann::json& certificate);

}  // namespace hapstab::check
