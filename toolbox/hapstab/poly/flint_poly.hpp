// hapstab/poly/flint_poly.hpp -- exact conversions between Polynomial<rational> and FLINT's
// fmpq_poly (one common denominator). For the .cpp files that hand exact algebra to FLINT
// (numeric/flint.hpp says which); no public header includes it.
#pragma once

#include "hapstab/numeric/flint.hpp"
#include "hapstab/poly/polynomial.hpp"

namespace hapstab::flint {

void to_flint(const Polynomial<rational>& a, FmpqPoly& out);
Polynomial<rational> from_flint(const FmpqPoly& p);

}  // namespace hapstab::flint
