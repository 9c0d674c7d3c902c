// hapstab/numeric/ball_matrix_arb.hpp -- internal, like numeric/flint.hpp (only .cpp files include
// it): a BallMatrix (numeric/ball_matrix.hpp) to and from an Arb matrix, the enclosure kept both
// ways (from_arb adds the rounding of each midpoint to double to its radius).
#pragma once

#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/numeric/flint.hpp"

namespace hapstab {

/// out := A (out has A's size); every ball of out holds the entry's ball of A.
void to_arb(flint::BallMat& out, const BallMatrix& A);
/// The Arb matrix as double midpoints and radii (outward); NumericalError on a non-finite ball.
BallMatrix from_arb(flint::BallMat& B);

}  // namespace hapstab
