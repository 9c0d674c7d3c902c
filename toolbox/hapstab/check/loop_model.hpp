// hapstab/check/loop_model.hpp -- the one-DOF sampled loop of `stability` and `stability-max`
// certificates as the checkers read it from the model (issue 19's loop; paper 001's device,
// zero-order hold, wall z^-n H(z)):
//   device  P_eff(s) = P/(1 + s Z_op P) = N(s)/s^k (every pole at s = 0: exact data only)
//   sample  P_d(z) = (1 - z^-1) Z{P_eff(s)/s} = Nd(z)/(z - 1)^k
//   loop    c(z) = z^n L(z) (z - 1)^k + A(z) Nd(z),   H = A/L                (nothing cancelled)
// Derivation of P_d (the checker's own; not the producer's Van Loan exponential): with
// P_eff/s = sum_i b_i / s^(k-i+1), the step response sampled at t = lT is
// y(l) = sum_i b_i (lT)^m / m!, m = k - i >= 1, and Z{l^m} = S_m(z) with S_0 = z/(z - 1),
// S_m = -z dS_{m-1}/dz (differentiating sum_l l^(m-1) z^-l); so P_d = ((z - 1)/z) sum_i b_i
// T^m/m! S_m(z), and Nd = P_d (z - 1)^k must be a polynomial (checked).
// Hypotheses verified: T > 0, n an integer in [0, 100000], the device strictly proper with every
// pole at s = 0 (else InputError: beyond the checkers).
//
// One pole off s = 0 (the `stability` kind only; a mass-damper 1/(m s^2 + b s), p = -b/m): P_eff =
// N(s)/(s^k (s - p)), p rational, simple. Partial fractions P_eff/s = Q(s)/s^(k+1) + r/(s - p),
// r = N(p)/p^(k+1), Q = (N - r s^(k+1))/(s - p) (exact division, checked); the step response
// y(l) = sum_{m >= 1} q_(k-m) (lT)^m/m! + r (E^l - 1), E = e^{pT} (the constant terms cancel: y(0) = 0
// for a strictly proper P_eff), so
//   P_d(z) = Ndp(z)/(z - 1)^k + r (E - 1)/(z - E),   Ndp the hold of Q/s^k as above,
// and the loop's c(z; E) = z^n L (z - 1)^k (z - E) + A (Ndp (z - E) + r (E - 1)(z - 1)^k) = c0 + E c1:
//   c0 = z^(n+1) L (z - 1)^k + A (z Ndp - r (z - 1)^k),   c1 = -z^n L (z - 1)^k - A Ndp + r A (z - 1)^k.
// E is transcendental (Lindemann: e^q for rational q != 0), so it is known by an enclosure only
// (exp_enclosure, Arb); stability_check.hpp decides c(.; E) for every E in it.
//
// Two poles off s = 0 (the `stability` kind only; a spring 1/(m s^2 + b s + k), poles real or
// complex): P_eff = N(s)/(s^k q(s)), q = s^2 + a1 s + a0 monic, a0 != 0. Partial fractions over Q:
// P_eff/s = Q(s)/s^(k+1) + R(s)/q(s), R = R0 + R1 s = N s^-(k+1) mod q (s^-1 = -(s + a1)/a0 mod q),
// Q = (N - R s^(k+1))/q (exact division, checked; Q_k + R1 = 0: y(0) = 0). R/q = C (sI - A_c)^-1 B,
// A_c = [[0, 1], [-a0, -a1]], B = [0; 1], C = [R0, R1], so y(lT) = (the hold of Q/s^k) + C Phi^l B - CB,
// Phi = e^{A_c T}, and
//   P_d(z) = Ndp(z)/(z - 1)^k + Nq(z)/Delta(z),  Delta = det(zI - Phi) = z^2 - tr(Phi) z + det(Phi),
//   Nq = (z - 1) C adj(zI - Phi) B - R1 Delta = (R0 phi12 - R1 + R1 phi22) z - R0 phi12 + R1 phi11 - R1 det(Phi),
//   c(z) = z^n L (z - 1)^k Delta + A (Ndp Delta + (z - 1)^k Nq),
// whose coefficients are polynomials in Phi's entries: stability_check.cpp encloses Phi (Arb's
// arb_mat_exp) and decides Schur-Cohn over the whole enclosure.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

struct LoopDevice {
  rational T = 1;                          ///< model.T > 0
  long n = 0;                              ///< model.delay, z^-n
  int k = 0;                               ///< P_eff = N(s)/s^k (times 1/(s - p) with a pole)
  Polynomial<rational> Nd;                 ///< P_d = Nd/(z - 1)^k (every pole at s = 0)
  std::optional<rational> pole;            ///< p, the one pole off s = 0 (only when allowed)
  Polynomial<rational> Ndp;                ///< with a pole: P_d = Ndp/(z - 1)^k + r (E - 1)/(z - E)
  rational r = 0;                          ///< with a pole: the residue of P_eff/s at p
  std::optional<std::pair<rational, rational>> spring;  ///< (a1, a0): two poles off s = 0, q = s^2 + a1 s + a0
  rational R0 = 0, R1 = 0;                 ///< with a spring: R = R0 + R1 s (the header); Ndp as with a pole
  std::map<std::string, rational> params;  ///< model.set
};

/// model.T, model.delay, model.set, model.plant and model.operator (the device, above); InputError
/// naming the field that is missing, malformed or beyond the checkers (a pole off s = 0, unless
/// `one_pole` allows one simple rational pole p != 0 or two poles off s = 0, a spring).
/// `scene_device`: model.plant is scene_loop_model's "(G)/s" of a device given by its velocity tf G,
/// whose cancelled s (the position offset, a conserved quantity) is the checker's own.
LoopDevice read_loop_device(const nlohmann::json& model, bool one_pole = false, bool scene_device = false);

/// c(z; E) = c0 + E c1 of the loop with one pole off s = 0 (the header), H = A/L.
std::pair<Polynomial<rational>, Polynomial<rational>> loop_family_in_E(const LoopDevice& d, const Polynomial<rational>& A,
                                                                       const Polynomial<rational>& L);

/// [lo, hi], exact rationals, holding e^x (Arb at `bits`).
std::pair<rational, rational> exp_enclosure(const rational& x, long bits);

/// model[key], an expression in `variable` ('s' or 'z') with sample period T and the parameters;
/// InputError naming model.KEY (also for a pole it cancels on or outside the stable region, but as
/// `hidden_poles` allows: lti/parse.hpp).
RationalFunction<rational> parse_model_field(const nlohmann::json& model, const char* key, char variable, const rational& T,
                                             const std::map<std::string, rational>& params,
                                             HiddenPoles hidden_poles = HiddenPoles::refuse);

/// c(z) = z^n L(z) (z - 1)^k + A(z) Nd(z) of the loop with the wall H = A/L.
Polynomial<rational> loop_polynomial(const LoopDevice& d, const Polynomial<rational>& A, const Polynomial<rational>& L);

}  // namespace hapstab::check::detail
