// hapstab/passivity/max_gain.hpp -- the passivity boundary as a number: the largest value of a
// parameter K of the virtual environment that the device's damping b keeps passive
// (`hapstab bound --max K --damping b`).
//
//   H(z) = H0(z) + K H1(z)            (affine in K: a stiffness, a damping, any gain of H)
//   b*(K) = sup_w [ f0(w) + K f1(w) ] + eta,   f_i(w) = Re{T H_i(z) z^-n e^{-j w t_d}/(1 - e^{jwT})}   (45), (54)
//
// b*(K) is a supremum of functions affine in K, so it is CONVEX in K (it need not be monotone:
// with a delay, b* of K + B(z-1)/(Tz) first falls, then rises in B). So {K : b*(K) < b} is an
// interval, and when b*(0) < b the answer
//   K_max = sup{K0 >= 0 : b*(K) < b for every K in [0, K0)}
//         = min over w with f1(w) > 0 of (b - eta - f0(w))/f1(w) = 1 / max_w psi(w),
//   psi = f1/(b - eta - f0)   (its denominator >= b - b*(0) > 0 on the whole domain),
// with b*(K_max) = b, attained at the maximiser of psi. psi is a rational function of c = cos(wT)
// (of cos(wT/q) for t_d = (p/q) T), maximised by the certified path of b* itself (certified.cpp:
// Descartes isolation, MPFR Newton, MPFI): exact when the maximiser is rational. Otherwise (t_d/T
// with a large denominator) K_max is bracketed by certified b* evaluations: by convexity b*(L) < b
// proves [0, L] passive and b*(U) >= b proves K_max <= U. b*(0) >= b gives K_max = 0 (fails).
// The closed forms of Secs. VI-VII inverted (max_gain_closed_form) are shown beside it:
//   backward-difference wall K + B(z-1)/(Tz) (46): K <= 2(b - eta - B)/T, B <= b - eta - KT/2;
//   K z^-n (Example 4): K <= 2(b - eta)/((2n + 1)T); wall with n = 1 (53): K <= 2(b - eta + B)/(3T)
//   when b - eta >= 5B, else KT = 2 sqrt(B(2(b - eta) - B)) - 2B; Tustin walls (Example 3, 4);
//   n >= 2: the conservative (2n+1)KT/2 + B gives a lower bound of K_max.
//
// (Sec. VI-VII and Examples 3-4 solved for a parameter.)
// Implements: paper 001 (45), (46), (53), (54), Sec. VI, Sec. VII.
#pragma once

#include <optional>
#include <string>

#include "hapstab/passivity/bound.hpp"

namespace hapstab::passivity {

/// b*(K) of H = H0 + K H1: the problem at K = 0 and the direction H1 = dH/dK.
struct GainProblem {
  BoundProblem base;                                              ///< H = H0, T, n, t_d, eta
  RationalFunction<rational> H1{Polynomial<rational>(rational(1))};  ///< H = H0 + K H1, H1 != 0
  rational b = 0;                                                 ///< the device's damping, > 0
  std::string name = "K";                                         ///< the parameter, in formulas and notes
};

/// The bound problem at one value of the parameter (H = H0 + K H1).
BoundProblem at_gain(const GainProblem& p, const rational& K);

/// K_max as a Certified<rational>: `value` the midpoint of `enclosure` (K_max itself when `status`
/// is exact), `enclosure` always set when finite; `outcome` holds when K_max > 0 (finite or
/// infinite), fails when K_max = 0 (b*(0) >= b, or b*(K) = +inf for every K > 0).
struct MaxGain : Certified<rational> {
  Outcome outcome = Outcome::undecided;
  bool infinite = false;                        ///< b*(K) < b for every K >= 0
  Bound at_zero;                                ///< b*(0)
  std::optional<Enclosure<rational>> omega;     ///< where b*(K_max) = b is attained (rad/s), when known
  std::string where;                            ///< "w = 0", "w = pi/T", "interior", ...
  std::string decimal;                          ///< the digits both ends of `enclosure` share ("inf", "0")
  int digits = 0;                               ///< how many significant digits `decimal` has
  BoundPath path = BoundPath::exact;            ///< exact: psi maximised exactly; long_delay: bracketed by long-delay b*
  /// b* jumps at the sup: b*(K_max) <= b (`at_sup`) and b* = +inf for every K > K_max. H's simple pole
  /// at z = -1 met by a fractional delay (nu = n + t_d/T not whole) gives the objective the term
  /// T rho(K) sin((nu + 1) wT)/(2 sin wT), +inf at wT = pi iff rho(K) sin(nu pi) < 0; the residue
  /// rho(K) = rho0 + K rho1 changes sign at K_max (jump_at_minus_one).
  bool jump = false;
  std::optional<Bound> at_sup;                  ///< b*(K_max) when `jump`
};

/// The K > 0 above which H0 + K H1 has b* = +inf by its pole at z = -1 (the local form of `jump`):
/// -rho0/rho1 when nu = n + t_d/T is not whole, rho1 sin(nu pi) < 0 and -rho0/rho1 > 0; else nullopt
/// (also when a part has a repeated pole at z = -1).
std::optional<rational> jump_at_minus_one(const GainProblem& p);

/// K_max to `digits` significant digits (10..280). InputError for b <= 0, H1 = 0, an unstable or
/// non-causal H0 or H1 (then H = H0 + K H1 is, for almost every K), or digits out of range.
MaxGain max_gain(const GainProblem& p, int digits = 30);

/// The independent check of a finite K_max > 0 by b* itself (bound_certified at the ends of its
/// enclosure): holds when b*(lo) <= b <= b*(hi) within their enclosures, i.e. b* = b within the
/// enclosure of K_max (for an exact K_max: b*(K_max) = b exactly).
struct BoundaryCheck {
  Bound at_lo, at_hi;
  bool holds = false;
};
BoundaryCheck check_boundary(const GainProblem& p, const MaxGain& m, int digits = 30);

/// A closed form of Secs. VI-VII solved for the parameter. K_max is `value` (rational), or the
/// root of `root_of` in `root_in` (algebraic), or infinite; with tight = false only a lower bound
/// of K_max (the conservative (53) for n >= 2).
struct MaxGainClosedForm {
  std::string name;      ///< e.g. "virtual wall (backward difference)"
  std::string equation;  ///< e.g. "(46)"
  std::string formula;   ///< e.g. "K <= 2(b - B)/T with b = 1, B = 0.5, T = 0.001"
  std::optional<rational> value;
  std::optional<Polynomial<rational>> root_of;
  std::optional<Enclosure<rational>> root_in;
  bool infinite = false;
  bool tight = true;
};
/// The closed form that applies to the problem, or nullopt (also when b*(0) >= b).
std::optional<MaxGainClosedForm> max_gain_closed_form(const GainProblem& p);
/// The closed form's value as a decimal of `digits` digits ("inf"; an algebraic root refined).
std::string closed_form_decimal(const MaxGainClosedForm& c, int digits);
/// Does K_max agree with the closed form? A tight value (rational or algebraic) inside K_max's
/// enclosure, infinite with infinite, a lower bound at or below its upper end.
bool agrees(const MaxGainClosedForm& c, const MaxGain& m);

/// `bound --max K --damping b` (the command and hapstab.bound_max in Python): K_max, the closed
/// form that applies (when K_max > 0) and, with check = true, b* itself at the ends of a finite
/// K_max's enclosure (check_boundary).
struct BoundMax {
  GainProblem problem;
  MaxGain max;
  std::optional<MaxGainClosedForm> closed_form;
  std::optional<BoundaryCheck> check;  ///< with check = true
};
BoundMax bound_max(GainProblem g, int digits, bool check);

}  // namespace hapstab::passivity
