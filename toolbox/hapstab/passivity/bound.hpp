// hapstab/passivity/bound.hpp -- the passivity bound b* of paper 001 for any virtual environment.
//
//   b* = sup_{0 <= w <= pi/T} Re{ T H(e^{jwT}) z^{-n} e^{-j w t_d} / (1 - e^{jwT}) } + eta     (45), (54)
//
// The system of Fig. 1 is passive iff b > b* (Secs. III-V, VII). Exact objective: with
// c = cos(wT) and W = H z^{-n} = N/D', write N(z)conj(D'(z)) = sum_m (a_m cos m wT + j c_m sin m wT),
// |D'|^2 = sum_m e_m cos m wT. Because T/(1-z) = T/2 + j T/(2t), t = tan(wT/2), and
// sin(m wT)/t = (1 + c) U_{m-1}(c) (Chebyshev U), the objective without delay is the exact rational
// function of c
//   f(c) = (T/2) [ R(c) - (1 + c) Q(c) ] / B(c),  R = sum a_m T_m(c), Q = sum c_m U_{m-1}(c), B = sum e_m T_m(c)
// on c in [-1, 1] (c = 1 <-> w = 0, c = -1 <-> w = pi/T). No 1/t is ever formed, so w -> 0 does not
// cancel (Re{T/(1-z)} = T/2 exactly), and a pole of H at z = +-1 cancels or not exactly (gcd).
//
// Methods: certified (default), fast (status numeric), grid (N samples, comparison only). The
// certified method has two paths, chosen by cost (plan_bound):
//   exact       the rational f(c) above, exact isolation of its critical points by Descartes' rule
//               of signs, Newton polish in MPFR, MPFI mean-value enclosure; exact where the maximiser
//               is rational. Its polynomials have degree max(deg N, deg D + n): cost ~ degree^4.
//   long_delay  never expands z^-n: f(theta) = (T/2)[(A/B + rho) cos(nu theta) + (E/B + rho/2)
//               S_nu(theta) + ...] (bound_detail.hpp) with low-order A, B, E, evaluated with its
//               derivatives in Arb balls; interval branch-and-bound over w with Newton on f'.
//               Cost ~ nu (the delay in samples), any integer or fractional delay.
// fast: double-double coefficients, derivative-recursion root finding and Newton polish on f(c)
// where the exact path would run; the long-delay f in double, sampled and polished, where it is
// long. A fractional delay t_d = (p/q) T with a small q is exact in cos(wT/q); a Tustin-like pole
// at z = -1 meeting a fractional delay is decided by an exact divergence test at wT = pi.
//
// Implements: paper 001 (45), (54).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/result.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::passivity {

/// One passivity-bound problem. H is a rational function of z with exact coefficients.
struct BoundProblem {
  RationalFunction<rational> H{Polynomial<rational>(rational(0))};
  rational T = 0;                     ///< sample period, > 0
  int delay = 0;                      ///< n in z^{-n}, >= 0
  std::optional<rational> frac_delay; ///< t_d > 0 in e^{-j w t_d} (seconds), not a multiple of T
  rational eta = 0;                   ///< operator shortage of passivity (54), >= 0
  bool allow_noncausal = false;       ///< evaluate (45) for a non-causal H (the FIR form (47) as written)
};

/// Checks the assumptions of (45)/(54): T > 0, n >= 0, eta >= 0, t_d >= 0, H z^{-n} causal (deg num
/// <= deg den + n, unless allow_noncausal), non-zero denominator, H stable (no pole with |z| > 1; decided exactly by Schur-Cohn
/// on the part of the denominator without unit-circle roots, and by exact root isolation on the unit circle for
/// the rest). A simple pole ON the unit circle is allowed (a repeated one is unstable); an uncancelled
/// pole at z = 1 makes b* = +inf (see bound_certified). Throws InputError naming the failed assumption.
void check_assumptions(const BoundProblem& p);
/// Throws InputError when the work of every path is beyond its limit (numeric/limits.hpp): H's
/// degree above limits::model_degree, or the delay n + t_d/T above limits::criterion_delay samples
/// (the long-delay path's work grows like the delay). check_assumptions and catalogue::match call
/// it first, before anything is allocated.
void check_problem_size(const BoundProblem& p);

/// p with a fractional delay that is a whole multiple kT moved into the integer delay (n + k): the
/// form every method and the closed-form matcher work on.
BoundProblem with_integer_delay(BoundProblem p);

/// The exact objective as a function of c = cos(wT), without eta (see the header comment).
struct Objective {
  RationalFunction<rational> f{Polynomial<rational>(rational(0))};  ///< reduced A/B
  Polynomial<rational> R, Q, B;  ///< unreduced pieces: Re W * B = R, Im W * B = sin(wT) Q, B = |D'|^2
};
Objective objective(const RationalFunction<rational>& H, const rational& T, int delay);

enum class Method { certified, fast, grid };

/// The two algorithms of the certified method (see the header comment).
/// at_pole: b* = +inf decided at a pole of H on the circle inside the band, nothing expanded (circle_pole.cpp).
enum class BoundPath { exact, long_delay, at_pole };
inline const char* to_string(BoundPath p) {
  return p == BoundPath::exact ? "exact" : p == BoundPath::long_delay ? "long_delay" : "at_pole";
}

/// Which path computes b* and why: the exact path where its polynomial (degree max(deg N,
/// deg D + n), or q (order + n) + p + q for t_d = (p/q) T) is small enough that it is no slower
/// than about the long-delay path (or below 20 ms), the long-delay path otherwise and wherever the
/// exact polynomial would exceed limits::model_degree. Both costs are estimates in seconds on one
/// core of the reference machine (bench/delay.cpp measures them: BM_bound).
struct BoundPlan {
  BoundPath path = BoundPath::exact;
  long exact_degree = 0;       ///< the degree the exact path would expand to
  double exact_seconds = 0;    ///< estimated cost of the exact path (inf beyond its limit)
  double long_seconds = 0;     ///< estimated cost of the long-delay path (inf when it does not apply)
  std::string why;             ///< the choice in words
};
BoundPlan plan_bound(const BoundProblem& p);
inline const char* to_string(Method m) {
  return m == Method::certified ? "certified" : m == Method::fast ? "fast" : "grid";
}

/// b* as a Certified<rational>: `value` the midpoint of `enclosure` (b* itself when `status` is
/// exact), `enclosure` [lo, hi] always set when b* is finite (exact: [b*, b*]; certified: proven;
/// fast: the value -+ its stated error, not a proof; grid: [max, max], the grid maximum, which
/// only estimates b* from below), `method` the algorithm in words, `note` caveats. What only b*
/// has: `infinite` (no finite b makes the system passive; value 0 and no enclosure then), the
/// method family `kind`, the decimal to report, and the maximiser.
struct Bound : Certified<rational> {
  bool infinite = false;
  Method kind = Method::certified;                 ///< the family that produced it (fast hands hard cases to certified)
  std::string decimal;                             ///< b* to the requested digits, or "inf"
  std::optional<std::string> omega;                ///< maximiser in rad/s (decimal), nullopt when none
  std::optional<Enclosure<rational>> omega_enclosure;  ///< enclosure of the maximiser (rad/s), when known
  std::string where;                               ///< "w = 0", "w = pi/T", "interior", "constant", "pole ..."
  BoundPath path = BoundPath::exact;               ///< the certified path that ran (or that fast/grid stand in for)
  std::string plan;                                ///< the planner's reason, when it chose
  double value_double() const;                     ///< nearest double of `value` (+inf when infinite)
  void enclose(rational lo, rational hi);          ///< enclosure = [lo, hi], value = its midpoint
};

/// The error the fast path states (not a proof): relative 10^-fast_error_digits, checked against
/// the certified path on narrow resonances (tests/passivity, FastPathNeverWrongOnVeryNarrowResonances).
constexpr int fast_error_digits = 13;

/// The enclosure every output of b* states, as decimal strings: [lo, hi] rounded outward to
/// digits + 5 for exact and certified results (rigorous); the fast path's stated error band to 17
/// digits (not a proof); [grid maximum, inf) for the grid, whose maximum only estimates b* from
/// below. {"inf", "inf"} when b* is infinite.
Enclosure<std::string> reported_enclosure(const Bound& b, int digits);
/// True when reported_enclosure is proven to contain b* (exact, certified or infinite).
bool enclosure_rigorous(const Bound& b);

/// Certified bound to `digits` significant digits (10 <= digits <= 280; default 30), by the path
/// plan_bound chooses.
Bound bound_certified(const BoundProblem& p, int digits = 30);
/// The same by a given path (comparisons, benchmarks): InputError when the exact path's degree
/// exceeds limits::model_degree, NumericalError when the long-delay path does not apply.
Bound bound_certified(const BoundProblem& p, int digits, BoundPath path);

/// Grid method with N equally spaced w in [0, pi/T] (comparison only; status numeric).
Bound bound_grid(const BoundProblem& p, long N);

/// Double-precision fast path for a prepared case. Prepare once (exact -> double-double
/// coefficients), then `evaluate` (the timed part). Returns nullopt from evaluate when the
/// case needs the certified path (a pole on the unit circle, a fractional delay).
class FastBound {
 public:
  explicit FastBound(const BoundProblem& p);
  /// b* (with eta) and the maximising w; nullopt when the case is outside the fast path.
  std::optional<std::pair<double, double>> evaluate() const;
  /// Builds the coefficients from the exact H and evaluates: the whole fast path.
  static std::optional<std::pair<double, double>> run(const BoundProblem& p) { return FastBound(p).evaluate(); }

 private:
  std::vector<double> Ahi_, Alo_, Bhi_, Blo_;  // f = A/B in c, double-double coefficients
  double T_ = 0, eta_ = 0;
  bool ok_ = true;
};

/// The fast path for a long delay (the long-delay objective in double, sampled on 4 nu + 64
/// points, its best local maxima polished by Newton): b* (with eta), its maximiser w and the
/// relative error it states -- a first-order rounding estimate at the maximiser (the condition of
/// the Horner sums A, E, B in cos(wT), and the argument nu wT), times 16; not a proof, checked
/// against the certified path (tests/passivity, LongDelay.FastAgreesWithCertified). nullopt when
/// the long-delay path does not apply.
struct FastLongDelay {
  double value = 0, omega = 0, relative_error = 0;
};
std::optional<FastLongDelay> fast_long_delay(const BoundProblem& p);

/// Dispatcher: certified / fast (falls back to certified when out of scope) / grid.
Bound bound(const BoundProblem& p, Method m = Method::certified, int digits = 30, long grid_points = 100000);

/// The necessary condition of Sec. III at one frequency: (14) |rH/(2b + rH)| < 1 and (15)
/// b > Re{-r H}, r = T/(e^{jwT} - 1) (44), evaluated in 50-digit arithmetic. They agree.
struct NecessaryCheck {
  bool holds14 = false, holds15 = false;
  double lhs14 = 0, rhs15 = 0;  ///< |rH/(2b+rH)| and Re{-rH}
};
NecessaryCheck necessary_condition(const RationalFunction<rational>& H, const rational& T, const rational& b,
                                   const rational& omega);

/// Re{T H(e^{jwT}) z^{-n} e^{-j w t_d}/(1 - e^{jwT})} + eta at one w, in 50-digit arithmetic
/// through the c-form (no cancellation at w -> 0). Used by figures and the grid method.
double objective_at(const BoundProblem& p, double omega);

}  // namespace hapstab::passivity
