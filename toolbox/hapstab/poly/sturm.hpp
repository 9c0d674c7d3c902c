// hapstab/poly/sturm.hpp -- exact real-root counting (Sturm's theorem) and isolation
// (Descartes' rule of signs) over Q.
//
// Used by the proofs of paper 001 to show inequalities such as r^(w) > 0 of (9), and by the
// certified passivity bound (45) to isolate its critical points after the substitution
// c = cos(wT) or t = tan(wT/2): a rational function has constant sign on an interval iff its
// numerator and denominator have no real root there, which these tests decide exactly.
//
// Everything works on the square-free part q = p / gcd(p, p') (same distinct roots, all simple),
// scaled to a primitive integer polynomial.
// - Counting: the Sturm sequence q, q', -prem(.,.), ... (integer pseudo-remainders, each made
//   primitive), and the sign variations at the two ends.
// - Isolation: Vincent-Collins-Akritas bisection -- the sign variations of the coefficients of
//   (1 + y)^n P(1/(1 + y)), P the polynomial moved to the unit interval, bound the roots inside
//   and are exact when 0 or 1; halving and Taylor shifts are integer shifts and additions, so
//   the coefficients stay near q's size (a Sturm sequence of degree n grows to ~n times it:
//   order-6 bound objectives, degree 13, reach 1600 bits). The whole line is [-B, B] with the
//   Cauchy bound B = 1 + max|a_i/a_n|.
// A rational root met as an endpoint or a bisection midpoint is returned as an exact, degenerate
// interval [x, x]; every other interval has rational endpoints that are not roots and contains
// exactly one root, at which q changes sign.
#pragma once

#include <memory>
#include <vector>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

/// p / gcd(p, p'): the monic square-free part (same distinct roots, all simple). Throws
/// InputError for the zero polynomial.
Polynomial<rational> square_free_part(const Polynomial<rational>& p);

/// 1 + max |a_i / a_n| (Cauchy): every root x of p has |x| < bound. p must not be zero.
rational cauchy_bound(const Polynomial<rational>& p);

/// The Sturm sequence of the square-free part of p: s0 = square_free_part(p), s1 = s0',
/// s_{k+1} = -rem(s_{k-1}, s_k) (each scaled by a positive constant to keep coefficients
/// small), ending in a nonzero constant. Throws InputError for the zero polynomial.
std::vector<Polynomial<rational>> sturm_sequence(const Polynomial<rational>& p);

/// Number of sign changes of the sequence at x (zeros skipped).
int sign_variations(const std::vector<Polynomial<rational>>& seq, const rational& x);

/// Number of DISTINCT real roots of p in (a, b] (0 when a >= b). Throws InputError for p = 0.
int count_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b);

/// [lo, hi] with exactly one root of p in it; lo == hi means the root is the rational lo.
struct RootInterval {
  rational lo, hi;
  bool is_exact() const { return lo == hi; }
};

/// All distinct real roots of p, as sorted intervals (neighbours may share an endpoint, which
/// is then not a root). Degree 0: none. p = 0 throws.
std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p);

/// The distinct real roots of p in the closed interval [a, b], sorted; every returned interval
/// lies inside [a, b]. Throws InputError if a > b or p = 0.
std::vector<RootInterval> isolate_real_roots(const Polynomial<rational>& p, const rational& a, const rational& b);

/// Shrinks r (which must isolate one root of p) until hi - lo <= width (width > 0) by quadratic
/// interval refinement (Abbott): a secant guess rounded to a grid of N cells, N squared when
/// the root is in the guessed cell, else a bisection. The bracket is moved onto dyadic points
/// x = X / 2^E first, so every sign test is one integer evaluation 2^(E n) q(X / 2^E) of the
/// primitive square-free integer q (no rational arithmetic, no gcd in the loop). A root of a
/// linear q, or a dyadic root met as a grid point, is returned exactly. Throws InputError if r
/// does not bracket a root of p.
RootInterval refine_root(const Polynomial<rational>& p, RootInterval r, const rational& width);

namespace flint {
class FmpzPoly;
}

/// isolate_real_roots and refine_root for many roots of one polynomial: the square-free
/// integer part (a gcd) is computed once, not per call. isolate(a, b) ==
/// isolate_real_roots(p, a, b) and refine(r, width) == refine_root(p, r, width).
class RootRefiner {
 public:
  explicit RootRefiner(const Polynomial<rational>& p);
  std::vector<RootInterval> isolate(const rational& a, const rational& b) const;
  RootInterval refine(RootInterval r, const rational& width) const;

 private:
  std::shared_ptr<const flint::FmpzPoly> q_;  // primitive square-free integer part of p
};

}  // namespace hapstab
