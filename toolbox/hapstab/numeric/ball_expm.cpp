// Arb-backed enclosures of matrix exponentials (see ball_expm.hpp).
#include "hapstab/numeric/ball_expm.hpp"

#include <cmath>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"

namespace hapstab {

namespace {

constexpr long kExpmPrec = 128;

void load(flint::BallMat& out, const MatQ& A, const rational& scale) {
  flint::QMat q(static_cast<long>(A.rows()), static_cast<long>(A.cols()));
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) flint::set(q.at(static_cast<long>(i), static_cast<long>(j)), A(i, j) * scale);
  arb_mat_set_fmpq_mat(out.get(), q.get(), kExpmPrec);
}

// Rows [r0, r0 + nr) x columns [c0, c0 + nc) of B, as a double midpoint with a radius that
// also covers the rounding to double.
DoubleEnclosure extract(flint::BallMat& B, long r0, long c0, long nr, long nc) {
  DoubleEnclosure e;
  e.mid.resize(nr, nc);
  for (long i = 0; i < nr; ++i)
    for (long j = 0; j < nc; ++j) {
      double r = 0;
      if (!flint::to_double_ball(B.at(r0 + i, c0 + j), e.mid(i, j), r))
        throw NumericalError("matrix exponential: Arb lost the enclosure (non-finite ball)");
      e.radius = std::max(e.radius, r);
    }
  return e;
}

void check_square(const MatQ& A, const char* what) {
  if (A.rows() != A.cols()) throw InputError(std::string(what) + ": the matrix must be square");
}

}  // namespace

DoubleEnclosure expm_enclosure(const MatQ& A, const rational& t) {
  check_square(A, "expm_enclosure");
  const long n = static_cast<long>(A.rows());
  flint::BallMat X(n, n), E(n, n);
  load(X, A, t);
  arb_mat_exp(E.get(), X.get(), kExpmPrec);
  return extract(E, 0, 0, n, n);
}

ZohEnclosure zoh_enclosure(const MatQ& A, const MatQ& B, const rational& t) {
  check_square(A, "zoh_enclosure");
  if (B.rows() != A.rows()) throw InputError("zoh_enclosure: B must have A's rows");
  if (t < 0) throw InputError("zoh_enclosure: negative time step");
  const long n = static_cast<long>(A.rows()), m = static_cast<long>(B.cols());
  MatQ M = MatQ::Zero(n + m, n + m);
  M.topLeftCorner(n, n) = A;
  M.topRightCorner(n, m) = B;
  flint::BallMat X(n + m, n + m), E(n + m, n + m);
  load(X, M, t);
  arb_mat_exp(E.get(), X.get(), kExpmPrec);
  return {extract(E, 0, 0, n, n), extract(E, 0, n, n, m)};
}

DoubleEnclosure gram_enclosure(const MatQ& M, const MatQ& Q, const rational& t) {
  check_square(M, "gram_enclosure");
  if (Q.rows() != M.rows() || Q.cols() != M.cols()) throw InputError("gram_enclosure: Q must have M's size");
  if (t < 0) throw InputError("gram_enclosure: negative time step");
  const long n = static_cast<long>(M.rows());
  // h = t / 2^k with ||M||_inf h <= 1/2
  rational nrm = 0;
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    rational row = 0;
    for (Eigen::Index j = 0; j < M.cols(); ++j) row += abs(M(i, j));
    nrm = std::max(nrm, row);
  }
  int k = 0;
  rational h = t;
  while (nrm * h > rational(1, 2)) {
    h /= 2;
    ++k;
  }
  MatQ V = MatQ::Zero(2 * n, 2 * n);
  V.topLeftCorner(n, n) = -M.transpose();
  V.topRightCorner(n, n) = Q;
  V.bottomRightCorner(n, n) = M;
  flint::BallMat X(2 * n, 2 * n), E(2 * n, 2 * n);
  load(X, V, h);
  arb_mat_exp(E.get(), X.get(), kExpmPrec);
  flint::BallMat F12(n, n), Ph(n, n), PhT(n, n), W(n, n), T1(n, n), T2(n, n);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) {
      arb_set(F12.at(i, j), E.at(i, n + j));
      arb_set(Ph.at(i, j), E.at(n + i, n + j));
    }
  arb_mat_transpose(PhT.get(), Ph.get());
  arb_mat_mul(W.get(), PhT.get(), F12.get(), kExpmPrec);
  for (int i = 0; i < k; ++i) {  // W(2h) = W(h) + e^{M^T h} W(h) e^{M h};  e^{2Mh} = (e^{Mh})^2
    arb_mat_mul(T1.get(), PhT.get(), W.get(), kExpmPrec);
    arb_mat_mul(T2.get(), T1.get(), Ph.get(), kExpmPrec);
    arb_mat_add(W.get(), W.get(), T2.get(), kExpmPrec);
    arb_mat_sqr(T1.get(), Ph.get(), kExpmPrec);
    arb_mat_swap(Ph.get(), T1.get());
    arb_mat_transpose(PhT.get(), Ph.get());
  }
  // symmetrise: the exact W is symmetric, so (W + W^T)/2 encloses it too
  arb_mat_transpose(T1.get(), W.get());
  arb_mat_add(W.get(), W.get(), T1.get(), kExpmPrec);
  arb_mat_scalar_mul_2exp_si(W.get(), W.get(), -1);
  return extract(W, 0, 0, n, n);
}

}  // namespace hapstab
