// hapstab/numeric/exact_matrix.hpp -- exact dense products and solves of rational matrices on
// FLINT's fmpq_mat (denominators cleared row/column-wise, then integer multiplication,
// multimodular for large entries), for the matrices of the exact pipeline (realisations, (15),
// the exact re-check of (16)) whose size grows with the number of DOF.
//
// Eigen's own product on Boost rationals canonicalises (a gcd) at every multiply-add and
// allocates a temporary per operation: at the 128-DOF contact scene's 258 x 258 matrices one
// product took seconds. The results here are the same exact rationals, only computed faster.
#pragma once

#include <string>

#include "hapstab/numeric/eigen_traits.hpp"

namespace hapstab {

/// A B, exact. InputError when the inner dimensions differ.
MatQ exact_product(const MatQ& A, const MatQ& B);

/// The rank of A, exact (FLINT's fraction-free reduction).
long exact_rank(const MatQ& A);

/// det A, exact (A square; FLINT's fraction-free elimination). InputError when A is not square.
rational exact_determinant(const MatQ& A);

/// The X with A X = B, exact (A square). InputError naming `what` when A is singular.
MatQ exact_solve(const MatQ& A, const MatQ& B, const std::string& what);

}  // namespace hapstab
