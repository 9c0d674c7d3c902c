// hapstab/contact/wedge.hpp -- the wedge criterion (25) and Tsypkin's condition (21) of
// Tsai & Colgate (paper 002), decided over the WHOLE interval theta in [0, pi], not on a grid.
//
// With t = tan(theta/2) (z = (1+jt)/(1-jt)), m(theta) = sin(theta)/(1-cos(theta)) = cot(theta/2) = 1/t,
// R(t) = Re H(e^{j theta}) (even in t) and J(t) = Im H(e^{j theta}) / t (even in t: Im H is odd)
// are exact rational functions of t, so the two branches of (25),
//     f+(t) = R + J,   f-(t) = R - J,        w(theta) = max(f+, f-) + 1 = R + |J| + 1,
// and Tsypkin's left side R are exact too. Both are functions of u = t^2 in [0, inf]
// (u = inf is theta = pi, where J -> 0 and both branches equal H(-1)).
//
//  * holds (exact): exact isolation of the real roots of the numerators on [0, inf), the sign
//    of every branch between and at the roots; a common root of both branches (the margin
//    touching 0) is found by a gcd. So "holds" is proven, never sampled.
//  * margin (certified): min over theta of w, as an enclosure: the minimum of a max of smooth
//    branches lies at an end point, at a critical point of a branch, or where branches cross;
//    all these are isolated exactly (Descartes), refined on dyadic points with exact integer
//    sign tests (poly/sturm.hpp), and the branches evaluated there in Arb ball arithmetic
//    (poly/ball_range.hpp) until `digits` decimals are decided; a candidate whose coarse
//    enclosure lies above another's is dropped before the fine refinement.
//  * max gain (certified): k* = -1/min_theta max(f+, f-) when the minimum is negative, else +inf
//    (decided exactly); Tsypkin: the same with R. k*H satisfies the criterion for 0 < k < k*.
//  * grid_margin: the same quantity on an N-point theta grid in double, kept for comparison.
// Assumptions of the paper (Sec. 2) are checked exactly (Schur-Cohn-Jury test over Q) and
// reported, never thrown: H stable, (1+kH)^{-1} stable, H(1) >= 0. r_k > 0 is a property of the
// bias input, not of H (the limit-cycle simulation takes rho > 0 and checks it).
//
// Implements: paper 002 (21), (25).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/tf.hpp"
#include "hapstab/numeric/result.hpp"
#include "hapstab/poly/rational_function.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::contact {

using RatFun = RationalFunction<rational>;

/// Re H and Im H / t on the unit circle as exact functions of u = t^2 = tan^2(theta/2).
struct WedgeBranches {
  RatFun re;         ///< R(u)  = Re H(e^{j theta})
  RatFun im_over_t;  ///< J(u)  = Im H(e^{j theta}) / tan(theta/2)
};
WedgeBranches wedge_branches(const TransferFunction& H);

/// The exact verdict of (25) alone: w(theta) > 0 for every theta in [0, pi]. First a certified
/// fast path (outward-rounded double intervals, branch and bound over u in [0, 1] and 1/u in
/// [0, 1]: every box proven positive, or a box where both branches are negative); when that
/// is undecided within its budget (margin touching 0), Sturm decides. H must have no pole on
/// the unit circle.
bool wedge_holds(const TransferFunction& H);

/// Exact: max_i f_i(u) > 0 (strict) or >= 0 (non-strict) for every u in [0, inf]. The f_i must
/// have no pole on [0, inf] (InputError otherwise).
/// `fast` = false skips the interval fast path (pure Sturm; for cross-checks).
bool max_positive(const std::vector<RatFun>& fs, bool strict, bool fast = true);

/// Certified enclosure of min over u in [0, inf] of max_i f_i(u), and where it is attained.
struct MinOfMax {
  Enclosure<rational> value;  ///< certified
  Enclosure<rational> u;      ///< an enclosure of a minimiser u* (u = tan^2(theta/2)); hi may be "inf"
  bool at_infinity = false;   ///< the minimum is the limit u -> inf (theta = pi)
  bool decided = true;        ///< `digits` decimals of the value are decided by the enclosure
};
MinOfMax min_of_max(const std::vector<RatFun>& fs, int digits);

/// theta in [0, pi] (radians, double) for u = tan^2(theta/2).
double theta_of_u(const rational& u);

/// The Sec. 2 assumptions for the loop gain k*H.
struct Assumptions {
  bool h_stable = false;            ///< every pole of H strictly inside the unit circle (exact)
  bool closed_loop_stable = false;  ///< (1 + kH)^{-1} stable (exact)
  bool dc_gain_nonnegative = false; ///< H(1) >= 0 (exact; false when H has a pole at z = 1)
  bool pole_on_unit_circle = false; ///< H has a pole with |z| = 1 (a criterion is evaluated only where its branch stays bounded)
  std::optional<rational> h1;       ///< H(1) when finite
  std::vector<std::string> violated;  ///< human-readable list, empty when all hold
};
Assumptions check_assumptions(const TransferFunction& H, const rational& k = 1);

/// One criterion's verdict for H.
struct CriterionReport {
  std::string name;                 ///< "wedge (25)" or "Tsypkin (21)"
  /// holds / fails, exact: left side + 1 > 0 for every theta in [0, pi]. Undecided (status
  /// failed) when the criterion was not evaluated: a branch is unbounded (a pole of H on the
  /// unit circle); then margin and max_gain are unset.
  Verdict verdict{Outcome::undecided, Status::failed, "not evaluated: a pole of H on the unit circle"};
  bool evaluated() const { return verdict.decided(); }
  Certified<rational> margin;          ///< min over theta of left side + 1 (certified enclosure)
  double theta_at_min = 0;          ///< radians (numeric, from the certified enclosure of u*)
  Enclosure<rational> u_at_min;     ///< the certified enclosure of u* = tan^2(theta*/2) (unset at theta = pi)
  bool min_at_pi = false;           ///< the minimum is at theta = pi (u -> inf)
  bool gain_infinite = false;       ///< exact: k*H satisfies the criterion for every k > 0
  Certified<rational> max_gain;        ///< k* when finite (certified enclosure)
};

struct ContactAnalysis {
  TransferFunction H;
  Assumptions assumptions;
  CriterionReport wedge, tsypkin;
  bool applies() const { return assumptions.violated.empty(); }
};

/// Both criteria, certified, for H (discrete, rational coefficients).
ContactAnalysis analyze_contact(const TransferFunction& H, int digits = 20);

/// Grid check in double: min over theta_i = pi i/(n-1) of the wedge (or Tsypkin) left side + 1.
struct GridMin {
  double value, theta;
};
GridMin grid_margin(const TransferFunction& H, int n, bool wedge);

/// Double-precision evaluation of the wedge left side + 1 at theta in (0, pi] (for plots).
double wedge_margin_at(const TransferFunction& H, double theta);

}  // namespace hapstab::contact
