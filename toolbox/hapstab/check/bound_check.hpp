// hapstab/check/bound_check.hpp -- the checker of a `bound` certificate: b* of paper 001,
//   b* = sup_{0 <= w <= pi/T} Re{ T H(z) z^-n e^{-j w t_d} / (1 - z) } + eta,  z = e^{jwT}   (45), (54)
// for an exact H(z) (the expression as written, its --set values), T > 0, an integer delay
// n >= 0, a delay t_d >= 0 in seconds (model.frac_delay; 0 when absent) and eta >= 0.
//
// Derivation (the checker's own, check/bound_objective.hpp; not passivity::objective, nor the
// fractional-delay path's H(w^q)/S(w)): with tau = n + t_d/T = P/q and c = cos(wT/q), the
// objective is f(c) = A(c)/B(c) + eta with B >= 0 on [-1, 1], on the domain c in [cos(pi/q), 1]
// (w in [0, pi/T] one to one; [-1, 1] for an integer delay, q = 1). B = 0 only at the finitely
// many poles of H on the unit circle: b* is the sup over the rest.
//
// Theorem checked (claim "b* in [lo, hi]", or "b* = v" with lo = hi = v):
//   (upper) b* <= hi  if  P = (hi - eta) B - A >= 0 on [c_lo, 1], a rational interval containing
//           the domain (c_lo = evidence.domain_c_lo, -1 when absent, shown <= cos(pi/q) by
//           bound_objective.hpp's Chebyshev test) -- iff for c_lo = cos(pi/q), since B > 0 off
//           finitely many points and P, B are continuous; or if P U_{q-1} >= 0 on [c_lo, 1]
//           (U_{q-1} > 0 on (cos(pi/q), 1]: the test across an irrational end where f -> -inf);
//           decided exactly by check/nonnegative.hpp (Yun + Sturm);
//   (lower) b* >= lo  if the witness c0 (a rational in the domain, evidence.witness_c, shown so by
//           the Chebyshev test) has Ar(c0)/Br(c0) + eta >= lo, exactly, with Ar/Br = A/B reduced
//           (g = gcd(A, B)) and Br(c0) != 0: Ar/Br is continuous at c0 and equals f off the finitely
//           many zeros of B, so it is f's value or limit at c0, and the supremum is at least that.
// A pole of H at z = -1 meeting a fractional delay (the Tustin wall with t_d = 1.5 T: f -> -inf at
// wT = pi, issue 46 item 1) needs the second test only when the end is irrational (q >= 4): A has
// a simple, B a double zero there, so P changes sign at the end.
//   (+inf)  b* = +inf (claim "infinite": true, status exact) if the objective tends to +inf at the
//           rational pole c_p = evidence.pole_c from the side evidence.side = +1 (c > c_p) or -1
//           (c < c_p), the side inside the band: with A/B reduced to Ar/Br and Br = (c - c_p)^m R,
//           sign Ar(c_p) * side^m * sign R(c_p) > 0 (bound_objective.hpp, unbounded_above_fails).
//           The Tustin wall with t_d = T/2 (sin(pi tau) > 0) tends to +inf at wT = pi; with
//           t_d = 1.5 T to -inf (issue 46 item 1's false +inf): the sign decides, exactly.
//           An irrational pole inside the band (H's pole on the circle at theta_p seen through
//           t_d/T = p/q: c_p = cos(theta_p/q)) is given by an interval (evidence.pole_lo, pole_hi)
//           isolating it and the side (unbounded_inside_fails); the band's irrational end
//           cos(pi/q) by (end_lo, end_hi] (unbounded_at_end_fails).
//   (+inf, the local form: evidence.pole_at_z = "-1", nothing expanded, no size limit) H's simple pole at
//           z = -1 met by a fractional delay nu = n + t_d/T = P/q, q >= 2. With H = H~ + rho/(z + 1),
//           rho = N(-1)/D'(-1) (D(-1) = 0, D'(-1) != 0; N(-1) != 0 as H is read in lowest terms), H~ has
//           no pole at -1, so T Re{H~ e^{-j nu theta}/(1 - z)} stays bounded near theta = wT = pi; and
//           since (1 + z)(1 - z) = 1 - z^2 = -2j sin(theta) e^{j theta},
//             T Re{rho e^{-j nu theta}/((1 + z)(1 - z))} = T rho sin((nu + 1) theta)/(2 sin theta),
//           whose numerator tends to -rho sin(nu pi) != 0 while sin theta -> 0+ (theta -> pi-): the
//           objective tends to +inf iff rho sin(nu pi) < 0, and sign sin(nu pi) = (-1)^floor(nu) (nu not
//           an integer). Exact: rho is rational, floor(nu) = P div q. The Tustin wall with t_d = 1500.5 T
//           (+inf) against 1501.5 T (-inf: this form refutes it).
//   (+inf, the circle form: evidence.pole_on_circle = {q, c_lo, c_hi}, status certified, nothing expanded, no
//           size limit) a simple pole z0 = e^{j theta0}, 0 < theta0 < pi, of H: H = R/(z - z0) + O(1), R =
//           N(z0)/D'(z0), and e^{j theta} - z0 = j z0 (theta - theta0)(1 + O(theta - theta0)), so
//             f(theta) = Im(c)/(theta - theta0) + O(1),  c = T R e^{-j nu theta0}/((1 - z0) z0),
//           -> +inf on one side of theta0 when Im(c) != 0. Verified: q (exact, in c = cos theta) has a root
//           c0 in [c_lo, c_hi] inside (-1, 1) (a sign change, or q(c_lo) = 0 at c_lo = c_hi); Z(z) = z^m
//           q((z + 1/z)/2), expanded by the binomial theorem, divides D exactly: at z0 = c0 + j sqrt(1 - c0^2),
//           (z0 + 1/z0)/2 = c0 on |z| = 1, so Z(z0) = z0^m q(c0) = 0 and D(z0) = 0; D'(z0) != 0 and Im(c) != 0 in Arb
//           balls over all of [c_lo, c_hi]. (z - 1)/(z^2 + 1) at an even delay has Im(c) = 0: refuted.
// Size limit: q (max(deg N, deg D) + 1) + P <= 1000 (the check expands the delay; degree 300
// takes ~7 s), else the certificate is refused (InputError) rather than checked for hours --
// unless its evidence is the local form above (b* = +inf at z = -1), the circle form, or the cells' form (evidence.cells,
// evidence.witness_theta; a finite claim): f < hi cell by cell and f(theta0) > lo in balls, the delay never
// expanded (check/bound_cells.hpp).
// Hypotheses verified on the data: T > 0, n >= 0 an integer (at most 100000), t_d >= 0,
// eta >= 0, lo <= hi, the printed decimals (claim.printed_lo/hi, claim.printed) are the numbers
// claimed, exactly.
// Not verified here: that H is stable (the premise under which b* is the passivity bound of
// paper 001, not part of the value of the sup).
//
// Implements: paper 001 (45), (54).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/certificate.hpp"
#include "hapstab/lti/tf.hpp"

namespace hapstab::check {

/// The size limit above: q (max(deg N, deg D) + 1) + P, for every form that expands the delay.
inline constexpr long bound_max_size = 1000;

Verdict check_bound(const nlohmann::json& certificate);

/// b* = +inf for H under the delay model dm by `evidence`, one of the forms above (pole_c/side,
/// pole_lo/pole_hi/side, end_lo/end_hi, the local form pole_at_z, the circle form pole_on_circle;
/// not the integrator). `status` is the claim's: "exact", or "certified" for the circle form
/// (InputError otherwise). `where` names the evidence's field in messages. check/bound_max_check.cpp
/// reads K_max = 0 by b*(0) = +inf with it (evidence.at_zero_infinite).
Verdict check_bound_infinite(const nlohmann::json& evidence, const TransferFunction& H, const detail::DelayModel& dm,
                             const std::string& status, const std::string& where);

}  // namespace hapstab::check
