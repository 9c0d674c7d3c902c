// hapstab/stability/long_delay.hpp -- internal to stability/: the long-delay path of the Schur
// test and of max_gain (sampled_loop.hpp), which never forms the characteristic polynomial of
// degree n + m. With the device, wall and gain polynomials of low degree,
//   c(z, K) = z^n P(z) + Q0(z) + K Q1(z),   P = L D_d,  Q0 = A0 N_d,  Q1 = A1 N_d,
// evaluated on the unit circle in Arb balls:
//   * Schur stability by the argument principle: the zeros of c in |z| < 1 are (1/pi) times the
//     change of arg c(e^{j theta}) over theta in [0, pi] (real coefficients), counted box by box:
//     where |P| > |Q| on a box the change is n dtheta + darg P + darg(1 + Q/(z^n P)) with the last
//     term inside (-pi/2, pi/2), where |Q| > |P| it is darg Q + darg(1 + z^n P/Q), elsewhere the
//     box is small enough that c's enclosure misses 0 (claim ext.stability.winding). Stable iff
//     the count is deg c = n + deg P.
//   * The crossing gains (D-decomposition): a root on the circle at e^{j theta} for real K iff
//     K = -c0/c1 is real there, i.e. q(theta) = Im(c0 conj c1)/sin(theta) = 0, where
//     q = sum_m w_m K_m(theta) with K_m = sin(m theta)/sin(theta) (numeric/jet.hpp) and a few
//     integer m near n and near 0 (claim ext.stability.crossing_delay): no polynomial of degree n.
//     Boxes are taken in the order of their smallest possible K = Re(-c0/c1); a crossing is
//     isolated (q' of one sign, a sign change) and enclosed by interval Newton on q. Before the
//     boxes, coarse arcs are dropped by a floor that does not depend on n: at a crossing
//     |K| |Q1| = |z^n P + Q0| >= |P| - |Q0|, so no gain below the best one found lies where
//     (|P| - |Q0|)/|Q1| exceeds it (claim ext.stability.crossing_floor).
// Every arc of both searches is first tried in double intervals with rounding bounds
// (numeric/dinterval.hpp: sin, cos of theta/2 and of n theta at the arc's grid point pi k/D reduced
// exactly in integers, atan/arg enclosed), Arb only where those cannot decide it (issue 48).
// The work grows like n times the width of the frequency band where |P| and |Q| are comparable
// (the loop's crossover region; for the crossings, where the floor is below sup K), at most
// ~ 4 n + 64 boxes per pass; memory does not grow with n.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::stability::detail {

/// c(z, K) = z^n P(z) + Q0(z) + K Q1(z): real coefficients as balls, ascending; the exact ones
/// too when the data are rational (exact = true), for the values that are decided exactly.
struct DelayedLoop {
  long n = 0;
  std::vector<flint::Ball> P, Q0, Q1;
  bool exact = false;
  std::vector<rational> Pq, Q0q, Q1q;
  long degree() const { return n + static_cast<long>(P.size()) - 1; }
};

/// Both searches below first try each arc in double intervals with rounding bounds
/// (numeric/dinterval.hpp) and take Arb only where those cannot decide it. An ArbOnly scope turns
/// that off on its thread: Arb for every arc, the path before issue 48 (the benchmark's and the
/// tests' comparison).
inline thread_local bool double_pruning = true;
struct ArbOnly {
  bool saved = double_pruning;
  ArbOnly() { double_pruning = false; }
  ~ArbOnly() { double_pruning = saved; }
  ArbOnly(const ArbOnly&) = delete;
  ArbOnly& operator=(const ArbOnly&) = delete;
};

/// The Schur test of c(z, K) at one K by the argument principle (in balls at flint::ball_prec).
struct Winding {
  Outcome outcome = Outcome::undecided;  ///< holds: every zero in |z| < 1
  long inside = -1;                      ///< zeros in |z| < 1 (when decided)
  long boxes = 0;                        ///< boxes the count took
  long double_boxes = 0;                 ///< of them, those decided in double intervals
  std::string why;                       ///< when undecided
};
Winding schur_by_winding(const DelayedLoop& loop, const rational& K);

/// A crossing: a root of c(., K) on the unit circle at e^{+-j theta} for the real gain K.
struct DelayCrossing {
  flint::Ball K, theta;
};
/// The crossings with K > 0 that can be the smallest (every crossing with a smaller K is among
/// them, each enclosed), found best-first; `lowest` is a proven lower bound of every positive
/// crossing gain in (0, pi) (the smallest K lower end of the pieces left unresolved, or of the
/// crossings). nullopt (with why) when a crossing gain cannot be separated from 0 or a piece
/// cannot be decided at this precision. Crossings at theta = 0, pi (z = +-1) are not included.
struct CrossingSearch {
  std::vector<DelayCrossing> crossings;
  long boxes = 0;
  long double_boxes = 0;  ///< evaluations of an arc in double intervals (numeric/dinterval.hpp)
};
std::optional<CrossingSearch> smallest_crossings(const DelayedLoop& loop, std::string& why);

}  // namespace hapstab::stability::detail
