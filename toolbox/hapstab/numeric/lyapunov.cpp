// Certified Schur stability by a Lyapunov inequality (see lyapunov.hpp; a segment of ball
// matrices: lyapunov_ball.hpp).
#include "hapstab/numeric/lyapunov.hpp"

#include <cmath>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/numeric/lyapunov_ball.hpp"

namespace hapstab {

namespace {

constexpr long kLyapunovPrec = 128;

// P = sum_k (A^T)^k A^k (the solution of A^T P A - P = -I) by doubling; false when the series
// does not converge in double (spectral radius not clearly below 1).
bool smith_doubling(Eigen::MatrixXd Ak, Eigen::MatrixXd& P) {
  const auto n = Ak.rows();
  P = Eigen::MatrixXd::Identity(n, n);
  for (int k = 0; k < 64; ++k) {
    P += Ak.transpose() * P * Ak;
    Ak = Ak * Ak;
    const double a = Ak.norm();
    if (!std::isfinite(a) || !P.allFinite() || a > 1e100) return false;
    if (a < 1e-20) return true;  // the remaining terms are below 1e-40 |P|: P is converged
  }
  return false;
}

// M = P - A^T P A in balls (P exact; A a ball matrix holding the true one).
void lyapunov_residual(flint::BallMat& M, flint::BallMat& P, const flint::BallMat& Ab) {
  const long n = Ab.rows();
  flint::BallMat AT(n, n), PA(n, n);
  arb_mat_transpose(AT.get(), Ab.get());
  arb_mat_mul(PA.get(), P.get(), Ab.get(), kLyapunovPrec);
  arb_mat_mul(M.get(), AT.get(), PA.get(), kLyapunovPrec);
  arb_mat_sub(M.get(), P.get(), M.get(), kLyapunovPrec);
}

// P (double, symmetrised: an exact dyadic matrix) as balls of radius 0; false when P is not
// certainly positive definite.
bool exact_positive_definite(flint::BallMat& P, const Eigen::MatrixXd& Pd) {
  const long n = P.rows();
  const Eigen::MatrixXd Ps = 0.5 * (Pd + Pd.transpose());  // exactly symmetric doubles
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) arb_set_d(P.at(i, j), Ps(i, j));  // exact: P is this dyadic matrix
  flint::BallMat L(n, n);
  return arb_mat_cho(L.get(), P.get(), kLyapunovPrec) != 0;
}

// P - A^T P A certainly positive definite for every A in the ball.
bool residual_positive_definite(flint::BallMat& P, const flint::BallMat& A) {
  const long n = P.rows();
  flint::BallMat M(n, n), L(n, n);
  lyapunov_residual(M, P, A);
  return arb_mat_cho(L.get(), M.get(), kLyapunovPrec) != 0;
}

}  // namespace

bool lyapunov_proves_schur_stable(const MatQ& A, std::string* why) {
  if (A.rows() != A.cols()) throw InputError("lyapunov_proves_schur_stable: the matrix must be square");
  const long n = static_cast<long>(A.rows());
  if (n == 0) return true;
  Eigen::MatrixXd Ad(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) Ad(i, j) = static_cast<double>(A(i, j));
  Eigen::MatrixXd Pd;
  if (!smith_doubling(Ad, Pd)) {
    if (why) *why = "the Lyapunov series does not converge in double (spectral radius not clearly below 1)";
    return false;
  }
  flint::BallMat P(n, n);
  if (!exact_positive_definite(P, Pd)) {
    if (why) *why = "the rounded Lyapunov matrix P is not certainly positive definite";
    return false;
  }
  flint::QMat q(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) flint::set(q.at(i, j), A(i, j));
  flint::BallMat Ab(n, n);
  arb_mat_set_fmpq_mat(Ab.get(), q.get(), kLyapunovPrec);  // A exact up to 2^-128 relative
  if (!residual_positive_definite(P, Ab)) {
    if (why) *why = "P - A^T P A is not certainly positive definite (ball Cholesky)";
    return false;
  }
  return true;
}

bool lyapunov_proves_segment_stable(const flint::BallMat& A0, const flint::BallMat& A1) {
  const long n = A0.rows();
  if (n != A0.cols() || A1.rows() != n || A1.cols() != n)
    throw InputError("lyapunov_proves_segment_stable: the two ends must be square matrices of one size");
  if (n == 0) return true;
  Eigen::MatrixXd Am(n, n);  // the midpoint, in double (P is a choice; the proof is the checks below)
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j)
      Am(i, j) = 0.5 * (arf_get_d(arb_midref(arb_mat_entry(A0.get(), i, j)), ARF_RND_NEAR) +
                        arf_get_d(arb_midref(arb_mat_entry(A1.get(), i, j)), ARF_RND_NEAR));
  Eigen::MatrixXd Pd;
  if (!smith_doubling(Am, Pd)) return false;
  flint::BallMat P(n, n);
  return exact_positive_definite(P, Pd) && residual_positive_definite(P, A0) && residual_positive_definite(P, A1);
}

}  // namespace hapstab
