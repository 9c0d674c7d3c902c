// hapstab/passivity/catalogue.hpp -- the closed-form passivity bounds of paper 001, Secs. VI-VII,
// each as a function of its parameters with its exact class conditions, and a matcher that
// recognises which closed form applies to a given H(z) (for `hapstab bound --explain`).
//
//   backward differences H_m = ((z-1)/(Tz))^m: b* = (2/T)^{m-1}; sum alpha_m H_m, alpha >= 0: (46)
//   virtual wall K + B (z-1)/(Tz): KT/2 + B
//   FIR (47) H = (1-z) sum alpha_k z^-k: b* <= T sum |alpha_k| (49), tight for alpha >= 0 (w = 0) or
//     alternating signs alpha_0 >= 0, alpha_1 <= 0, ... (wT = pi); (z-1) sum_0^N z^-k (50):
//     b* ~ (C N - D) T (Dirichlet kernel), C = -min sin(y)/y, D = (1 - C)/2
//   IIR (z-1)/(z+a): T/(1-a); (1-z)/(z+a): T/(1+a) (|a| < 1); a = 1: -T/2 (52)
//   Tustin wall K + (2B/T)(z-1)/(z+1): KT/2 - B; with 0 < t_d < T: not passive for any b (B > 0)
//   delays t_d = nT (Example 4): H_0 z^-n: (2n+1) T/2; H_m z^-n: (2/T)^{m-1} (tight for even n or m = 1);
//     wall (53): n = 1: KT/2 + B + (KT - 2B) if KT >= 4B, KT/2 + B + K^2T^2/(8B) if KT < 4B;
//     conservative (2n+1)KT/2 + B; Tustin wall n = 1: KT/2 + B + |KT - 2B|
//   non-passive operator (54): add eta
//
// Implements: paper 001 (46), (47), (49), (50), (52), (53), Sec. VI, Sec. VII.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/passivity/bound.hpp"

namespace hapstab::passivity::catalogue {

// ---- the closed forms (exact rationals; InputError when the class condition fails) ----------
rational backward_difference(int m, const rational& T);                                 ///< (2/T)^{m-1}
rational backward_difference_sum(const std::vector<rational>& alpha, const rational& T);  ///< (46)
rational virtual_wall(const rational& K, const rational& B, const rational& T);         ///< KT/2 + B
/// FIR (49): T sum |alpha|; `tight` says whether a sign structure of Sec. VI makes it exact.
rational fir_bound(const std::vector<rational>& alpha, const rational& T, bool* tight = nullptr);
rational iir_zero_at_one(const rational& a, const rational& T);      ///< (z-1)/(z+a): T/(1-a), |a|<1; a=1: -T/2
rational iir_zero_at_one_neg(const rational& a, const rational& T);  ///< (1-z)/(z+a): T/(1+a), |a|<1
rational tustin_wall(const rational& K, const rational& B, const rational& T);             ///< KT/2 - B
rational delayed_constant(int n, const rational& T);                                        ///< (2n+1)T/2
rational delayed_backward_difference(int m, int n, const rational& T, bool* tight = nullptr);  ///< (2/T)^{m-1}
rational delayed_wall_n1(const rational& K, const rational& B, const rational& T);          ///< (53), n = 1
rational delayed_wall_conservative(int n, const rational& K, const rational& B, const rational& T);
rational delayed_tustin_n1(const rational& K, const rational& B, const rational& T);        ///< KT/2+B+|KT-2B|

/// C = -min_{y>0} sin(y)/y = -cos(y*), y* the root of tan y = y in (pi, 3pi/2), as a certified
/// enclosure [lo, hi] of width < 10^-digits (MPFR Newton, sign change checked with MPFI).
Enclosure<rational> dirichlet_C(int digits);
/// D = (1 - C)/2.
Enclosure<rational> dirichlet_D(int digits);
/// The approximation (C N - D) T of (50) (a number, not a bound: exact b* comes from the generic method).
double dirichlet_approx(int N, const rational& T);
/// Exact min over x of sum_{k=0}^{N} cos(kx), certified (via the generic bound of (50)).
/// H = sum_m alpha_m ((z-1)/(Tz))^m exactly (the denominator a power of z, degree of H <= 0)? alpha_0,
/// alpha_1, ... or nullopt. The classes (46), (53) and Example 4 are read off it.
std::optional<std::vector<rational>> backward_difference_coefficients(const RationalFunction<rational>& H,
                                                                       const rational& T);

/// ---- the matcher ------------------------------------------------------------------------------
struct Match {
  std::string name;        ///< e.g. "virtual wall (backward difference)"
  std::string equation;    ///< e.g. "(46)"
  std::string formula;     ///< e.g. "KT/2 + B with K = 1000, B = 5, T = 1/1000"
  std::optional<rational> value;  ///< the closed-form value of b* (with eta), when exact
  std::optional<double> approx;   ///< for approximations (Dirichlet)
  bool infinite = false;   ///< closed form says "not passive for any b"
  bool tight = true;       ///< false when the closed form is only an upper bound
};
/// Recognises the closed form that applies to the problem, or nullopt.
std::optional<Match> match(const BoundProblem& p);

/// Does the generic bound b agree with the closed form m? Infinite with infinite; a tight value
/// inside b's enclosure; an upper bound (not tight) at or above b's lower end. nullopt for an
/// approximation (Dirichlet's C N - D), which is shown beside b, not judged.
std::optional<bool> agrees(const Match& m, const Bound& b);

}  // namespace hapstab::passivity::catalogue
