// hapstab/stability/loop_max.hpp -- the largest value of a scene parameter p for which the loop
// as written is stable, for any number of DOF (`hapstab stability --scene S --max NAME` beyond one
// DOF), certified, when the closed-loop matrix of sim/closed_loop.hpp is affine in p:
//   M(p) = M0 + p M1,
// i.e. p enters only the controller's exact rows Ku, Kx (a gain of [environment] or [coupling]:
// `gain = "g"`, a stiffness written affinely; the plant, the delay and the controller's order do
// not change). Checked exactly at two more values; anything else is refused (InputError naming p).
//
// A crossing is a p > 0 where M(p) has an eigenvalue z = e^{j theta} on the unit circle: with
// z v = M(p) v, v = a + j b, the real system (a, b, p, theta) of 2n + 2 equations
//   (M(p) - cos(theta)) a + sin(theta) b = 0,   (M(p) - cos(theta)) b - sin(theta) a = 0,
//   Re(c^H v) = 1, Im(c^H v) = 0            (c: the numeric eigenvector, normalising v)
// (for z = +-1 the real system (M(p) -+ I) a = 0, c^T a = 1 in (a, p)). The steps:
//  1. Isolation (numeric): the spectral radius of M(p) in double on a geometric grid of p, the
//     first stable run and the first p past it where it is >= 1; bisection to the crossing.
//  2. Enclosure (certified): the Krawczyk operator of the system above in Arb balls on M0, M1
//     enclosed at `prec` bits (the exponentials by arb_mat_exp), Newton at that precision first;
//     K(X) inside X proves exactly one crossing in X. The precision is raised until the enclosure
//     of p is 10^-digits relative or narrower.
//  3. Below it (certified): every eigenvalue of every M0 + p M1 inside the unit disk, on adjacent
//     intervals of p, a walk from a point of the stable run up to within 10^-(digits+1) of the
//     crossing (at most 2000 steps) and down towards 0 (at most 4000 up to order 20, as many as cost
//     the same beyond, at least 400; each time the walk down has halved, one Lyapunov P is tried for
//     all of [0, down]: numeric/lyapunov_ball.hpp, the Stein inequality convex in M(p), so its two
//     ends suffice). Each step, at a point c: R an
//     approximate eigenbasis of M(c) (double; a cluster of close eigenvalues gets a basis of its
//     invariant subspace), exact as it is, L a ball enclosure of R^-1; then R^-1 M(p) R lies in
//     B0 + (p - c) C, B0 = L M(c) R, C = L M1 R, and Gershgorin's discs of D^-1 (B0 + t C) D
//     (D = diag(d) > 0, a Perron scaling; centres B0_ii + t C_ii, convex in t) inside the unit
//     circle prove the interval. Where no eigenbasis serves, a Stein certificate on the ball
//     matrix M0 + [a, b] M1 (numeric/ball_matrix.hpp). Should the walk stall within 10^-9 of the
//     crossing, a last step closes it by monotonicity: on [a, crossing.hi] Rump's enclosures
//     (acb_mat_eig_simple_rump) of the eigenvalues not inside the disk have d|lambda|^2/dp =
//     2 Re(conj(lambda) (L M1 R)_ii) > 0, and at the walk's target all are inside.
//  4. Confirmation: stability::decide_loop (the decider of `stability --scene`, Stein inertia) at
//     a point just below the crossing (stable) and just above it (NOT stable). Where it is
//     undecided (its Stein certificate too ill-conditioned near the crossing), the point below is
//     one step 3 certified and the point above is proven NOT stable by Rump's enclosure of an
//     eigenvalue of M(p) outside the disk (LoopMax::confirmed_by says so). Step 3's walk up, should
//     a step fail anywhere short of the crossing, tries the closing step by monotonicity from there.
// The supremum is sup{p >= 0 : stable for every p in (0, sup)} (docs/stability.md), so it is
// stated (outcome holds) only when the walk covers [0, stable_to]: M(0) Schur stable and reached.
// Where M(0) has the eigenvalue 1 on position integrators (v = [vp; vc; 0] with A vp = 0,
// Ku0 [vp; vc] = 0, Kx0 [vp; vc] = vc: then M0 v = v exactly, e^{AT} vp = vp; a device's position
// that nothing scaled by p holds, an environment's memory of it), a first-order cover at p = 0
// proves (0, eps]: V an exact (rational) basis of those v, and in a basis [V Q, R2]
// R^-1 M(t) R = [[I + t C11, B12 + t C12], [t C21, B22 + t C22]] exactly in its first block;
// Gershgorin's discs with the scaling diag(I, t K), K = diag(kappa_j) (Perron's scaling of the
// second block's discs at t = eps; R2 an eigenbasis of M(0)'s other eigenvalues, with or without
// orthonormal bases of its clusters, or a Schur basis: the largest eps of the three), are inside the circle for t in (0, eps]
// when every Re (C11)_ii plus its row's off-diagonal part is < 0 (Cover::near_zero states the
// bounds). The walk then continues down to eps, and the supremum of (0, sup) is stated with
// open_at_zero (the loop at p = 0 itself is only marginally stable). A pure mass that nothing
// damps at p = 0 (a Jordan block at z = 1) is not covered: its eigenvalues leave 1 like sqrt(p). There, where M(p) is
// rational (every plant component nilpotent: pure masses), the walk's lowest point a is joined to 0 exactly instead:
// R(p) = Res_z(det(zI - M(p)), its reciprocal) without a root in (0, a] (lti/circle_crossing.hpp) and M(a) stable; and
// a walk up stalled at b short of the crossing is joined to crossing.lo the same way (no root of R in (b, crossing.lo]).
// The mirror: where p moves a slow mode out at first order (an eigenvalue of C11 with Re > 0 beyond its row's
// off-diagonal part: a negative stiffness on a position nothing holds), the same discs show every M(p), p in
// (0, eps], with an eigenvalue outside the circle -- the outward first-block discs lie in |z| > 1, apart from the
// others, so they hold as many eigenvalues (Gershgorin) -- and sup = 0 (outcome fails, certified), before step 1.
// Where the walk towards 0 stops at stable_from > 0 otherwise (another eigenvalue on the circle, or
// an unstable window below: an open-loop unstable device that only larger gains stabilise) the
// outcome is undecided and what is proven is [stable_from, stable_to] (certified). Where M(0) has
// an eigenvalue strictly outside the circle (a Stein inertia certificate on the ball M0), so has
// M(p) for every small p > 0: sup = 0 (outcome fails, certified). The supremum then lies in
// [stable_to, crossing.hi]; when the walk ends short of its target the relative gap not covered is
// reported (`gap`) and the printed digits are only those the two ends share -- fewer than --digits where the gap
// exceeds 10^-(digits+1) but not 10^-6 (beyond: undecided, with [stable_from, stable_to]). Step 1 can miss
// nothing that steps 2-4 would then hide: a crossing below the one found stops a walk.
// Before step 1 the controller's modes that no p moves (an environment's unobservable states:
// Ku(p) V = 0, Kx(p) V in V, the V block constant) are deflated exactly and checked Schur stable
// exactly (Schur-Cohn on their characteristic polynomial): repeated, they would defeat the
// eigenbasis of step 3 (an unstable one: NOT stable for every p, exact, exit 1).
// Implements: paper 000 Sec. VI, Theorem 5.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/result.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::stability {

/// The loop with the parameter set to p (a scene loaded with NAME = p).
using LoopAt = std::function<sim::LoopSpec(const rational& p)>;

struct LoopMax {
  Outcome outcome = Outcome::undecided;  ///< holds: a crossing enclosed and [0, crossing) certified stable; fails: sup = 0
  Status status = Status::failed;        ///< certified when holds (or of stable_on alone when undecided); exact/certified when fails
  Enclosure<rational> crossing{0, 0};    ///< p* where an eigenvalue of M(p*) is on |z| = 1 (certified)
  Enclosure<rational> theta{0, 0};       ///< its angle in [0, pi] (rad; omega = theta / T)
  Enclosure<rational> sup{0, 0};         ///< [stable_to, crossing.hi]: holds the supremum (certified)
  rational stable_from = 0, stable_to = 0;  ///< stable for every p in [stable_from, stable_to] (certified)
  /// M(0) has the eigenvalue 1 (position integrators): stable_from = 0 is excluded, the loop is
  /// stable for every p in (0, stable_to], (0, first_order_to] by the first-order cover at p = 0.
  /// outcome fails with first_order_to > 0: NOT stable on (0, first_order_to] by the mirror of that cover (header).
  bool open_at_zero = false;
  rational first_order_to = 0;
  /// stable on (0, no_crossing_to] because no eigenvalue of the rational M(p) meets the circle there (lti/circle_crossing.hpp)
  /// and M(no_crossing_to) is stable (0: not used)
  rational no_crossing_to = 0;
  /// the walk stopped short at no_crossing_above and the resultant closed (no_crossing_above, crossing.lo] (0: not used)
  rational no_crossing_above = 0;
  double gap = 0;                        ///< (crossing.lo - stable_to) / crossing.lo: not covered (0: sup = crossing)
  std::optional<rational> stable_at;     ///< decide_loop: stable there (just below the crossing)
  std::optional<rational> unstable_at;   ///< decide_loop: NOT stable there (just above the crossing)
  std::string confirmed_by;              ///< "" (decide_loop decided both), else what proved stable_at / unstable_at
  std::string where;                     ///< "z = 1", "z = -1" or "complex pair"
  std::vector<double> mode;              ///< |position| of the crossing mode on each DOF, largest = 1
  rational T = 0;                        ///< the sample period (omega = theta / T)
  long states = 0;                       ///< order of M (without the fixed modes)
  long fixed_modes = 0;                  ///< deflated: eigenvalues of every M(p), proven inside (exact)
  long precision_bits = 0;               ///< of the enclosure in step 2
  long cover_intervals = 0;              ///< eigenvalue enclosures of step 3
  std::string note;                      ///< what was proven, or why nothing was
};

/// The exact data of the family (checked affine in p): M(p) is assembled as in
/// sim/closed_loop.hpp from the reduced plant (A, Bu), the delay t_d = n T + f and the
/// controller's rows Ku = Ku0 + p dKu, Kx = Kx0 + p dKx. `positions` reads the DOFs' sampled
/// positions from the state. For comparisons and the claims of proofs/.
struct LoopFamily {
  MatQ A, Bu, Ku0, dKu, Kx0, dKx, positions;
  long n = 0;
  rational f = 0, T = 0;
  long N = 0;
  /// The controller's modes no p moves (a block's hidden modes), deflated from Ku, Kx exactly:
  /// their matrix; M(p)'s spectrum is that of the family above and eig(fixed).
  MatQ fixed;
};
/// loop_family's refusal where M(p) is the same at p and 2p (p named nowhere the loop reads it): an InputError
/// that the symmetric split tells apart (a block of the split without p is not a loop that is not affine).
struct ParameterAbsent : InputError {
  using InputError::InputError;
};
/// `points`: how many distinct values of p prove the controller rows affine, from the caller's
/// ground (a scene: scene/parameter_degree.hpp's points_needed, from its text; a loop built in
/// code: the degree of its construction in p). The family is built from p = reference and
/// 2 reference and checked equal at max(points, 4) - 2 more values; an InputError when it is not.
LoopFamily loop_family(const LoopAt& at, const rational& reference, const std::string& name, long points);

/// sup of p over the stable interval (see the header); `reference` > 0 is where the grid of step 1
/// is centred (the scene's value of p; it spans reference 10^-6 .. 10^6), `digits` the width of
/// the crossing's enclosure (1 .. 60).
LoopMax max_parameter(const LoopAt& at, const rational& reference, const std::string& name, long points, int digits = 16);

}  // namespace hapstab::stability
