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
#pragma once

#include <string>

#include "hapstab/poly/polynomial.hpp"

namespace hapstab {

/// True iff every root of p satisfies |z| < 1. `why`, if given, receives the reason when false.
/// Throws InputError for the zero polynomial; a nonzero constant is stable.
bool schur_stable(const Polynomial<rational>& p, std::string* why = nullptr);

/// True iff every root of p satisfies Re s < 0 (false for the zero polynomial).
bool hurwitz_stable(const Polynomial<rational>& p);

}  // namespace hapstab
