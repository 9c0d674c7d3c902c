// hapstab/numeric/lyapunov_ball.hpp -- numeric/lyapunov.hpp's proof for a whole segment of ball
// matrices: every A(t) = (1 - t) A0 + t A1, t in [0, 1] (a closed loop affine in a parameter,
// M(p) = M0 + p M1 on an interval of p), Schur stable by one P.
//   1. P solves A^T P A - P = -I in double for the midpoint of the two balls' centres (Smith
//      doubling, as numeric/lyapunov.hpp; a choice, not part of the proof), symmetrised and taken
//      as an EXACT dyadic matrix.
//   2. P > 0 and P - Ai^T P Ai > 0 for i = 0, 1, each for every matrix inside the ball Ai (ball
//      Cholesky, arb_mat_cho), so at the segment's true ends.
//   3. With P > 0, P - A^T P A > 0 is the Schur complement of [[P, A^T P], [P A, P]] > 0, a matrix
//      affine in A: at A(t) it is (1 - t) times the first end's plus t times the second's, positive
//      definite, so every A(t) is Schur stable (numeric/lyapunov.hpp, step 3).
// A `false` says only that no proof was found.
//
// Like numeric/flint.hpp (which it includes), only .cpp files include this header.
#pragma once

#include "hapstab/numeric/flint.hpp"

namespace hapstab {

/// True iff one Lyapunov P proves every matrix of the segment between A0 and A1 (square, one size)
/// Schur stable, for every choice of the ends inside the two balls.
bool lyapunov_proves_segment_stable(const flint::BallMat& A0, const flint::BallMat& A1);

}  // namespace hapstab
