// hapstab/poly/stability.hpp -- exact root-location tests for polynomials with rational
// coefficients: the one implementation behind every "is it stable" of the toolbox (H in the
// passivity bound and the wedge criterion, the environment and the coupling of paper 000, the
// limit-cycle maps of paper 002).
//
//   schur_stable(p):   every root strictly inside the unit circle. Schur-Cohn-Jury recursion
//                      p -> (a_n p - a_0 p*)/z, which keeps the number of roots inside iff
//                      |a_0| < |a_n| at every step. The test is scale-free, so p is kept a primitive
//                      integer polynomial: the content is divided out at each step, and the
//                      coefficients stay at the size of subresultants instead of doubling each
//                      step (a raw rational recursion on a degree-40 det(zI - A) never finished).
//   hurwitz_stable(p): every root in Re s < 0 (Routh array, exact).
//   unit_circle_roots(p): the number of distinct roots on |z| = 1. Every such root is a root of
//                      g = gcd(p, z^deg p p(1/z)) (with the reciprocal pairs (r, 1/r) off the
//                      circle); the roots of g's square-free part s on the circle are z = -1 and
//                      the real roots t of gcd(Re, Im) of (1 - jt)^m s(z(t)), z = (1 + jt)/(1 - jt)
//                      (poly/unit_circle.hpp), counted by exact isolation (poly/sturm.hpp).
//   marginally_stable(d): every root in |z| <= 1, those on the circle simple: the poles the
//                      passivity bound (45) allows in H. The unit-circle and reciprocal part g is
//                      divided out and checked as above; Schur-Cohn decides the rest.
#pragma once

#include <string>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

/// True iff every root of p satisfies |z| < 1. `why`, if given, receives the reason when false.
/// Throws InputError for the zero polynomial; a nonzero constant is stable.
bool schur_stable(const Polynomial<rational>& p, std::string* why = nullptr);

/// True iff every root of p satisfies Re s < 0 (false for the zero polynomial).
bool hurwitz_stable(const Polynomial<rational>& p);

/// Number of distinct roots of p on the unit circle |z| = 1 (exact). p must not be zero.
int unit_circle_roots(const Polynomial<rational>& p);

/// True iff every root of d satisfies |z| <= 1 and those with |z| = 1 are simple (exact): the
/// poles H may have in (45). `detail` receives the reason when false. Throws InputError for d = 0.
/// The answer for the last d asked on this thread is kept (a vectorised b* over a numerator
/// parameter asks about one denominator at every point).
bool marginally_stable(const Polynomial<rational>& d, std::string* detail = nullptr);

}  // namespace hapstab
