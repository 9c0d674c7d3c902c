// hapstab/check/limit_cycle_check.hpp -- the checker of a `limit-cycle` certificate: the periodic
// orbit that `hapstab limit-cycle --exact` proves for the loop of paper 002, Fig. 5 / (4):
//   y_k = -k H(z) x_k,   x_k = max(y_k, -rho)   (the unilateral nonlinearity, shifted by rho > 0).
// Derivation (the checker's own; not contact::certify_orbit, which solves a fixed point in the
// controllable realisation of k H): with H = N/D reduced, D monic of degree n >= 1, deg N <= n,
// every output sequence of the loop satisfies the difference equation
//   sum_{i=0..n} d_i y_{j+i} = -k sum_{i=0..n} n_i x_{j+i}   (every j),
// and conversely: n consecutive outputs y_j..y_{j+n-1} (the *window*) determine y_{j+n} uniquely
// when 1 + beta > 0, beta = k n_n (= k H(inf)): with a = -sum_{i<n} (d_i y_{j+i} + k n_i x_{j+i}),
// y = a - beta x and x = max(y, -rho) give y = a/(1 + beta) when that is >= -rho ("contact"), else
// y = a + beta rho (< -rho, "free"): exactly one holds. (A minimal realisation's state and the
// window determine each other, the input being a function of the output, so the window is the
// orbit's state in coordinates that every realisation shares.)
// Theorem. If the recursion started from the window evidence.y = (y_0..y_{n-1}) gives
// y_{P+i} = y_i for i < n, the loop has the P-periodic solution y (by induction: the window at P is
// the window at 0). Its least period is P iff for every prime p | P some y_{i + P/p} != y_i, i < P.
// Claims checked, exactly: the period P, the amplitude (max - min)/2 of y_0..y_{P-1}, its printed
// decimal (within half a unit of its last digit), the samples out of contact #{i < P : y_i < -rho},
// and, when claimed, attracting true/false:
//   if no y_i (i < P) equals -rho, every mode is locally constant near the orbit, so the P-step
//   window map is affine there with the linear part J = the product of the steps' Jacobians,
//   (1 + beta chi_{j+n}) dy_{j+n} = -sum_{i<n} (d_i + k n_i chi_{j+i}) dy_{j+i},  chi = [y > -rho];
//   the orbit attracts (is locally asymptotically stable) iff J is Schur stable (every eigenvalue
//   in |z| < 1). J: the recursion above run from the n unit windows; det(tI - J) from its values at
//   t = 0..n (exact determinants, numeric/exact_matrix.hpp) by interpolation; Schur-Cohn
//   (check/schur_cohn.hpp). A sample on y = -rho: the map is only piecewise affine there, and a
//   claim "attracting" is refused (exit 2: beyond this checker).
// Hypotheses verified: H causal, n >= 1 after reduction, k >= 0, rho > 0, 1 + k H(inf) > 0.
// Size: P <= 100000, n <= 200 (exit 2 beyond).
// Implements: paper 002 (3), (4), Fig. 5.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_limit_cycle(const nlohmann::json& certificate);

}  // namespace hapstab::check
