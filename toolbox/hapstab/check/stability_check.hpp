// hapstab/check/stability_check.hpp -- the checker of a `stability` certificate: the Schur
// stability of the one-DOF sampled-data loop of `hapstab stability --plant --H [--operator]
// [--delay]` as written (issue 19's loop; paper 001's device, zero-order hold, wall z^-n H(z)):
//   device  P_eff(s) = P/(1 + s Z_op P) = N(s)/s^k (every pole at s = 0: exact data only)
//   sample  P_d(z) = (1 - z^-1) Z{P_eff(s)/s} = Nd(z)/(z - 1)^k
//   loop    c(z) = z^n L(z) (z - 1)^k + A(z) Nd(z),   H = A/L reduced    (no other cancellation)
// Claim: "stable" (every root of c in |z| < 1) or "NOT stable".
//
// Derivation of P_d: the checker's own (check/loop_model.hpp: the z-transforms of l^m; not the
// producer's Van Loan exponential); Nd = P_d (z - 1)^k must be a polynomial (checked).
//
// Theorem (Schur 1917, Cohn 1922): a real polynomial p of degree d >= 1 has every root in |z| < 1
// iff |p_0| < |p_d| and q(z) = (p_d p(z) - p_0 z^d p(1/z))/z, of degree d - 1, has too (a
// constant has no roots). Decided exactly, in rationals, by check/schur_cohn.hpp.
// Evidence: evidence.charpoly, c's coefficients (ascending, "p/q"): it must be a non-zero
// multiple of the checker's own c -- a producer that built another loop is refuted there, before
// any root test.
// One pole off s = 0 (a mass-damper, check/loop_model.hpp): c(z; E) = c0 + E c1 with E = e^{pT}
// transcendental, so there is no charpoly to hand over (evidence empty; status "certified"). The
// checker encloses E (Arb, 128 .. 8192 bits) until D(E) = Res_{d,d}(c, c*) (check/reciprocal.hpp,
// a polynomial in E) has no root in the enclosure [lo, hi] (Sturm): then no c(.; E) there has a
// root on the unit circle (a root there is a pair b, 1/b of c and c*), deg c1 < deg c0 keeps the
// number of roots inside fixed, and Schur-Cohn on the exact c(.; lo) decides for the true E.
// D = 0 identically: NOT stable for every E. E is never a root of D (Lindemann), so only the
// precision can run out: exit 2 ("too close to its boundary").
// Two poles off s = 0 (a spring, check/loop_model.hpp): c's coefficients are polynomials in the
// entries of Phi = e^{A_c T}, which Arb's arb_mat_exp encloses (128 .. 8192 bits); c is built in
// ball arithmetic and Schur-Cohn run over the whole box: each step's |p_0| < |p_d| (or >) must hold
// for every polynomial in it (each step's balls hold the exact transform of each point), else more
// bits. A decided run holds for every polynomial in the box, the true one among them; a root on
// the circle is never decided (exit 2, "too close to its boundary").
// evidence.argument_principle (long delays; the producer writes it beyond degree 2000, 150 with a
// pole off s = 0): c(z) = z^n P1(z) + P0(z) with z^n never expanded (P1, P0 exact with every pole at
// s = 0, in balls holding E or Phi otherwise). Theorem (argument principle): with no root on the
// unit circle, the roots inside number the winding of c(e^{j theta}) around 0, i.e. (the change of
// arg c over theta in [0, pi])/pi for real coefficients. Verified: c(+-1) != 0 (exactly, or in
// balls), then [0, pi] cut into arcs whose ball image excludes 0, each in one open half-plane of the
// four Re > 0, Im > 0, Re < 0, Im < 0; the arg is followed in whole quarter turns between adjacent
// arcs (never opposite half-planes: they share a point). Stable iff the count is deg c.
// Hypotheses verified: T > 0, n an integer in [0, 100000], the device strictly proper with every
// pole at s = 0, one simple rational pole off it or two poles off it (else the certificate is
// refused as beyond this checker: exit 2), z^-n H causal, degree of c <= 2000 (150 with poles off
// s = 0).
// Implements: paper 001 Fig. 1.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_stability(const nlohmann::json& certificate);

}  // namespace hapstab::check
