// hapstab/check/interpolate.hpp -- the checkers' exact polynomial interpolation (Newton's divided
// differences over Q), for polynomials known by their values: det(zI - A) and P_nu of
// check/passivity_level_mimo_check.hpp, det(tI - J) of check/limit_cycle_check.hpp.
#pragma once

#include <vector>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::check {

/// The polynomial of degree < x.size() through (x_k, y_k), the x_k distinct.
Polynomial<rational> interpolate(const std::vector<rational>& x, std::vector<rational> y);

}  // namespace hapstab::check
