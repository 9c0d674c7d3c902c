// hapstab/numeric/lyapunov.hpp -- a rigorous proof that a matrix is Schur stable (every
// eigenvalue in |z| < 1) by a discrete Lyapunov inequality, for matrices too large for the exact
// Schur-Cohn test to be cheap.
//
//   1. Solve A^T P A - P = -I in double (Smith doubling: P = sum_k (A^T)^k A^k, with A squared
//      each step) for the double rounding of A.
//   2. Take the symmetrised double P as an EXACT dyadic matrix (no claim is made about how well it
//      solves the equation), and check with Arb balls on the EXACT rational A that
//        P > 0   and   P - A^T P A > 0
//      (ball Cholesky, arb_mat_cho: nonzero only when every symmetric matrix inside the balls is
//      positive definite; the exact P - A^T P A lies inside them).
//   3. Then A is Schur stable: for A v = lambda v, v != 0, v^* (P - A^T P A) v = (1 - |lambda|^2)
//      v^* P v > 0 with v^* P v > 0, so |lambda| < 1 (proofs/schur_lyapunov.cpp).
// A `false` is NOT "unstable": it means no proof was found (the matrix is unstable, or too close
// to the circle for double precision, e.g. a Jordan block at radius 1 - 1e-6), and the caller
// decides with the exact test (poly/stability.hpp). The verdict is never weaker than the exact one.
#pragma once

#include <string>

#include "hapstab/numeric/eigen_traits.hpp"

namespace hapstab {

/// True iff the Lyapunov certificate above proves every eigenvalue of A (square, exact) inside
/// the open unit disc. `why` receives what failed when false (for the record, not a verdict).
bool lyapunov_proves_schur_stable(const MatQ& A, std::string* why = nullptr);

}  // namespace hapstab
