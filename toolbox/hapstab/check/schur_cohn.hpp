// hapstab/check/schur_cohn.hpp -- the exact Schur-Cohn test of the checkers (written for check/
// alone; not poly/stability.hpp, which the producers use).
// Theorem (Schur 1917, Cohn 1922): a real polynomial p of degree d >= 1 has every root in the
// open unit disc iff |p_0| < |p_d| and its Schur transform q(z) = (p_d p(z) - p_0 p*(z))/z has,
// p*(z) = z^d p(1/z) (q has degree d - 1: its leading coefficient is p_d^2 - p_0^2 > 0). A
// non-zero constant has no roots (stable). Every step is exact in rationals (q made monic).
#pragma once

#include <string>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check {

struct SchurCohn {
  bool stable = false;
  std::string why;  ///< the step that failed (|p_0| >= |p_d| at degree d), or "every step passes"
};

/// p must be non-zero.
SchurCohn schur_cohn(const Polynomial<rational>& p);

}  // namespace hapstab::check
