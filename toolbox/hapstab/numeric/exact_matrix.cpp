// Exact dense products and solves on FLINT (see exact_matrix.hpp).
#include "hapstab/numeric/exact_matrix.hpp"

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"

namespace hapstab {

MatQ exact_product(const MatQ& A, const MatQ& B) {
  if (A.cols() != B.rows())
    throw InputError("exact_product: inner dimensions differ (" + std::to_string(A.cols()) + " and " +
                     std::to_string(B.rows()) + ")");
  if (A.rows() == 0 || B.cols() == 0) return MatQ(A.rows(), B.cols());
  if (A.cols() == 0) return MatQ::Zero(A.rows(), B.cols());
  flint::QMat a = flint::to_qmat(A), b = flint::to_qmat(B), c(static_cast<long>(A.rows()), static_cast<long>(B.cols()));
  fmpq_mat_mul(c.get(), a.get(), b.get());
  return flint::from_qmat(c, static_cast<long>(A.rows()), static_cast<long>(B.cols()));
}

long exact_rank(const MatQ& A) {
  if (A.rows() == 0 || A.cols() == 0) return 0;
  flint::QMat a = flint::to_qmat(A), r(static_cast<long>(A.rows()), static_cast<long>(A.cols()));
  return fmpq_mat_rref(r.get(), a.get());
}

rational exact_determinant(const MatQ& A) {
  if (A.rows() != A.cols()) throw InputError("exact_determinant: the matrix is not square");
  if (A.rows() == 0) return rational(1);
  flint::QMat a = flint::to_qmat(A);
  fmpq_t d;
  fmpq_init(d);
  fmpq_mat_det(d, a.get());
  const rational out = flint::to_rational(d);
  fmpq_clear(d);
  return out;
}

MatQ exact_solve(const MatQ& A, const MatQ& B, const std::string& what) {
  if (A.rows() != A.cols()) throw InputError(what + " is not square");
  if (A.rows() != B.rows())
    throw InputError(what + ": " + std::to_string(A.rows()) + " rows but the right-hand side has " +
                     std::to_string(B.rows()));
  const long n = static_cast<long>(A.rows()), k = static_cast<long>(B.cols());
  if (n == 0) return MatQ(0, k);
  flint::QMat a = flint::to_qmat(A), b = flint::to_qmat(B), x(n, k);
  if (k == 0) {
    // no columns to solve for; still refuse a singular A, as the caller asked
    flint::QMat r(n, n);
    if (fmpq_mat_rref(r.get(), a.get()) < n) throw InputError(what + " is singular");
    return MatQ(n, 0);
  }
  if (!fmpq_mat_solve(x.get(), a.get(), b.get())) throw InputError(what + " is singular");
  return flint::from_qmat(x, n, k);
}

}  // namespace hapstab
