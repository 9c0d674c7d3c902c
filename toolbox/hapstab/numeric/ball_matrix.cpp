// Midpoint-radius matrices and their certified Schur decision (see ball_matrix.hpp).
#include "hapstab/numeric/ball_matrix.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"

namespace hapstab {

namespace {

constexpr long kPrec = 128;

// A ball as a double midpoint (nearest) and a radius that also covers that rounding.
void to_double(const arb_t x, double& mid, double& rad) {
  if (!arb_is_finite(x)) throw NumericalError("ball matrix: Arb lost the enclosure (non-finite ball)");
  mid = arf_get_d(arb_midref(x), ARF_RND_NEAR);
  arf_t d;
  arf_init(d);
  arf_set_d(d, mid);
  arf_sub(d, d, arb_midref(x), 64, ARF_RND_UP);
  const double rounding = std::fabs(arf_get_d(d, ARF_RND_UP));
  arf_clear(d);
  const double r = mag_get_d(arb_radref(x)) + rounding;  // mag_get_d rounds up
  rad = r > 0 ? std::nextafter(r, INFINITY) : 0.0;
}

void load(flint::BallMat& out, const BallMatrix& A) {
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      arb_struct* x = out.at(static_cast<long>(i), static_cast<long>(j));
      arb_set_d(x, A.mid(i, j));
      mag_set_d(arb_radref(x), A.rad(i, j));  // rounds up
    }
}

BallMatrix unload(flint::BallMat& B) {
  BallMatrix A(B.rows(), B.cols());
  for (long i = 0; i < B.rows(); ++i)
    for (long j = 0; j < B.cols(); ++j) to_double(B.at(i, j), A.mid(i, j), A.rad(i, j));
  return A;
}

void check_finite(const BallMatrix& A, const char* what) {
  if (!A.mid.allFinite() || !A.rad.allFinite()) throw NumericalError(std::string(what) + ": a non-finite entry");
}

// Y = X^T S X for an exact double X, in balls (Arb), S symmetrised: (S + S^T)/2 also contains
// the exact symmetric matrix.
void congruence(flint::BallMat& Y, const BallMatrix& S, const Eigen::MatrixXd& X) {
  const long n = static_cast<long>(S.rows());
  flint::BallMat Sb(n, n), St(n, n), Xb(n, n), Xt(n, n), T(n, n);
  load(Sb, S);
  arb_mat_transpose(St.get(), Sb.get());
  arb_mat_add(Sb.get(), Sb.get(), St.get(), kPrec);
  arb_mat_scalar_mul_2exp_si(Sb.get(), Sb.get(), -1);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) arb_set_d(Xb.at(i, j), X(i, j));
  arb_mat_transpose(Xt.get(), Xb.get());
  arb_mat_mul(T.get(), Sb.get(), Xb.get(), kPrec);
  arb_mat_mul(Y.get(), Xt.get(), T.get(), kPrec);
}

// Stein equation P - M^T P M = I for a real M by the complex Schur form M = U T U^*:
// X - T^* X T = I with X = U^* P U, column by column (T^* is lower triangular):
//   (I - T_jj T^*) X(:, j) = e_j + T^* sum_{l < j} X(:, l) T_lj.
// false when a pivot 1 - T_jj conj(T_ii) vanishes (eigenvalues on the circle or a reciprocal pair).
bool stein(const Eigen::MatrixXd& M, Eigen::MatrixXd& P) {
  const Eigen::Index n = M.rows();
  Eigen::ComplexSchur<Eigen::MatrixXd> cs(M);
  if (cs.info() != Eigen::Success) return false;
  const Eigen::MatrixXcd& T = cs.matrixT();
  const Eigen::MatrixXcd& U = cs.matrixU();
  const Eigen::MatrixXcd Ts = T.adjoint();
  Eigen::MatrixXcd X = Eigen::MatrixXcd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXcd r = Eigen::VectorXcd::Zero(n);
    if (j > 0) r = X.leftCols(j) * T.col(j).head(j);
    Eigen::VectorXcd rhs = Ts.triangularView<Eigen::Lower>() * r;
    rhs(j) += 1.0;
    Eigen::MatrixXcd L = -T(j, j) * Ts;
    L.diagonal().array() += 1.0;
    for (Eigen::Index i = 0; i < n; ++i)
      if (std::abs(L(i, i)) < 1e-14) return false;
    X.col(j) = L.triangularView<Eigen::Lower>().solve(rhs);
  }
  const Eigen::MatrixXcd Pc = U * X * U.adjoint();
  P = 0.5 * (Pc.real() + Pc.real().transpose());
  return P.allFinite();
}

std::string num(double x) {
  std::ostringstream o;
  o.precision(6);
  o << x;
  return o.str();
}

}  // namespace

BallMatrix BallMatrix::exact(const MatQ& A) {
  BallMatrix B(A.rows(), A.cols());
  arb_t x;
  arb_init(x);
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      if (A(i, j) == 0) continue;
      flint::set(x, A(i, j), kPrec);
      to_double(x, B.mid(i, j), B.rad(i, j));
    }
  arb_clear(x);
  return B;
}

BallMatrix BallMatrix::exact(const Eigen::MatrixXd& A) {
  BallMatrix B;
  B.mid = A;
  B.rad = Eigen::MatrixXd::Zero(A.rows(), A.cols());
  return B;
}

BallMatrix BallMatrix::uniform(const Eigen::MatrixXd& mid, double r) {
  BallMatrix B;
  B.mid = mid;
  B.rad = Eigen::MatrixXd::Constant(mid.rows(), mid.cols(), r);
  return B;
}

void BallMatrix::set_block(Eigen::Index r0, Eigen::Index c0, const BallMatrix& other) {
  mid.block(r0, c0, other.rows(), other.cols()) = other.mid;
  rad.block(r0, c0, other.rows(), other.cols()) = other.rad;
}

double BallMatrix::max_radius() const { return rad.size() ? rad.maxCoeff() : 0.0; }

BallMatrix operator*(const BallMatrix& A, const BallMatrix& B) {
  if (A.cols() != B.rows()) throw InputError("ball matrix product: inner dimensions differ");
  check_finite(A, "ball matrix product");
  check_finite(B, "ball matrix product");
  const long r = static_cast<long>(A.rows()), k = static_cast<long>(A.cols()), c = static_cast<long>(B.cols());
  if (r == 0 || c == 0 || k == 0) return BallMatrix(A.rows(), B.cols());
  flint::BallMat a(r, k), b(k, c), p(r, c);
  load(a, A);
  load(b, B);
  arb_mat_mul(p.get(), a.get(), b.get(), kPrec);
  return unload(p);
}

BallMatrix operator+(const BallMatrix& A, const BallMatrix& B) {
  if (A.rows() != B.rows() || A.cols() != B.cols()) throw InputError("ball matrix sum: sizes differ");
  const long r = static_cast<long>(A.rows()), c = static_cast<long>(A.cols());
  flint::BallMat a(r, c), b(r, c);
  load(a, A);
  load(b, B);
  arb_mat_add(a.get(), a.get(), b.get(), kPrec);
  return unload(a);
}

bool positive_definite(const BallMatrix& S, std::string* why) {
  if (S.rows() != S.cols()) throw InputError("positive_definite: the matrix must be square");
  const long n = static_cast<long>(S.rows());
  if (n == 0) return true;
  check_finite(S, "positive_definite");
  const Eigen::MatrixXd Sm = 0.5 * (S.mid + S.mid.transpose());
  Eigen::LLT<Eigen::MatrixXd> llt(Sm);
  if (llt.info() != Eigen::Success) {
    if (why) *why = "its midpoint is not positive definite (double Cholesky)";
    return false;
  }
  // X = L^-T: upper triangular with a nonzero diagonal, so nonsingular (exactly: X is what it is)
  const Eigen::MatrixXd Linv = llt.matrixL().solve(Eigen::MatrixXd::Identity(n, n));
  Eigen::MatrixXd X = Linv.transpose().triangularView<Eigen::Upper>();
  for (long i = 0; i < n; ++i)
    if (!(std::isfinite(X(i, i)) && X(i, i) != 0)) {
      if (why) *why = "the congruence L^-T is singular in double";
      return false;
    }
  flint::BallMat Y(n, n);
  congruence(Y, S, X);
  arb_t s, a;
  arb_init(s);
  arb_init(a);
  bool ok = true;
  for (long i = 0; i < n && ok; ++i) {
    arb_set(s, Y.at(i, i));
    for (long j = 0; j < n; ++j) {
      if (j == i) continue;
      arb_abs(a, Y.at(i, j));
      arb_sub(s, s, a, kPrec);
    }
    ok = arb_is_positive(s);
    if (!ok && why) {
      std::ostringstream o;
      o << "Gershgorin on L^-1 S L^-T fails at row " << i << " (the matrix is too ill-conditioned for double precision, or "
        << "not positive definite)";
      *why = o.str();
    }
  }
  arb_clear(a);
  arb_clear(s);
  return ok;
}

SchurDecision schur_decide(const BallMatrix& M) {
  if (M.rows() != M.cols()) throw InputError("schur_decide: the matrix must be square");
  check_finite(M, "schur_decide");
  SchurDecision d;
  const Eigen::Index n = M.rows();
  if (n == 0) {
    d.stable = true;
    d.why = "no state";
    return d;
  }
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(M.mid, false).eigenvalues();
  d.spectral_radius = ev.cwiseAbs().maxCoeff();
  Eigen::MatrixXd P;
  if (!stein(M.mid, P)) {
    d.why = "no Stein certificate: the double solve of P - M^T P M = I failed (an eigenvalue on or within ~1e-14 of the "
            "unit circle, or a pair z, 1/conj(z)); numeric spectral radius " + num(d.spectral_radius);
    return d;
  }
  // R = P - M^T P M in balls (P exact: the doubles it holds)
  const BallMatrix Pb = BallMatrix::exact(P);
  BallMatrix Mt;
  Mt.mid = M.mid.transpose();
  Mt.rad = M.rad.transpose();
  BallMatrix R = Mt * (Pb * M);
  R.mid = P - R.mid;
  std::string why;
  if (!positive_definite(R, &why)) {
    d.why = "no Stein certificate: P - M^T P M is not certainly positive definite in balls (" + why +
            "); numeric spectral radius " + num(d.spectral_radius) + ", |1 - rho| = " + num(std::abs(1 - d.spectral_radius));
    return d;
  }
  const std::string stein_text = "P - M^T P M > 0 proven in ball arithmetic for an exact P (" + std::to_string(n) + " x " +
                                 std::to_string(n) + ", solved from the Stein equation)";
  if (positive_definite(Pb, &why)) {
    d.stable = true;
    d.why = "certified Schur stable: " + stein_text + " and P > 0 (Lyapunov); numeric spectral radius " + num(d.spectral_radius);
    return d;
  }
  // a direction with w^T P w < 0: an eigenvector of P for its least eigenvalue
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(P);
  const Eigen::VectorXd w = es.eigenvectors().col(0);
  arb_t acc, t, u;  // w^T P w in balls at 512 bits (each term w_i P_ij w_j is a product of doubles)
  arb_init(acc);
  arb_init(t);
  arb_init(u);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      arb_set_d(t, w(i));
      arb_set_d(u, P(i, j));
      arb_mul(t, t, u, 512);
      arb_set_d(u, w(j));
      arb_mul(t, t, u, 512);
      arb_add(acc, acc, t, 512);
    }
  const bool negative = arb_is_negative(acc);
  arb_clear(u);
  arb_clear(t);
  arb_clear(acc);
  if (negative) {
    d.stable = false;
    d.why = "certified NOT Schur stable (an eigenvalue with |z| > 1): " + stein_text +
            " and w^T P w < 0 for an exact w (Stein inertia); numeric spectral radius " + num(d.spectral_radius);
    return d;
  }
  d.why = "no certificate: P - M^T P M > 0 holds but P is neither certainly positive definite nor certainly indefinite; "
          "numeric spectral radius " + num(d.spectral_radius);
  return d;
}

}  // namespace hapstab
