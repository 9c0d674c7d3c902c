// Midpoint-radius matrices and their certified Schur decision (see ball_matrix.hpp).
#include "hapstab/numeric/ball_matrix.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/numeric/numeric_decimal.hpp"

namespace hapstab {

namespace {

constexpr long kBallMatrixPrec = 128;

// A ball as a double midpoint (nearest) and a radius that also covers that rounding.
void to_double(const arb_t x, double& mid, double& rad) {
  if (!flint::to_double_ball(x, mid, rad)) throw NumericalError("ball matrix: Arb lost the enclosure (non-finite ball)");
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
  arb_mat_add(Sb.get(), Sb.get(), St.get(), kBallMatrixPrec);
  arb_mat_scalar_mul_2exp_si(Sb.get(), Sb.get(), -1);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) arb_set_d(Xb.at(i, j), X(i, j));
  arb_mat_transpose(Xt.get(), Xb.get());
  arb_mat_mul(T.get(), Sb.get(), Xb.get(), kBallMatrixPrec);
  arb_mat_mul(Y.get(), Xt.get(), T.get(), kBallMatrixPrec);
}

// Stein equation P - M^T P M = I for a real M by the complex Schur form M = U T U^*:
// X - T^* X T = I with X = U^* P U, column by column (T^* is lower triangular):
//   (I - T_jj T^*) X(:, j) = e_j + T^* sum_{l < j} X(:, l) T_lj,
// solved by forward substitution without forming the matrix (row i of T^* is column i of T,
// conjugated: contiguous). O(n^3) in all, ~2 n^3 complex flops. The eigenvalues of M (T's
// diagonal) are returned as well. false when a pivot 1 - T_jj conj(T_ii) vanishes (eigenvalues on
// the circle or a reciprocal pair).
// The complex Schur form of a real M from its real Schur form (MATLAB's rsf2csf; Golub & Van Loan
// 7.4.1): each 2 x 2 block of a complex pair is made triangular by one unitary rotation, O(n) per
// block. Eigen's ComplexSchur runs its QR iterations in complex arithmetic: about twice the work
// of the real iterations, which at order 642 (the 128-device contact loop) was a second.
bool complex_schur(const Eigen::MatrixXd& M, Eigen::MatrixXcd& T, Eigen::MatrixXcd& U) {
  using cd = std::complex<double>;
  const Eigen::RealSchur<Eigen::MatrixXd> rs(M);
  if (rs.info() != Eigen::Success) return false;
  T = rs.matrixT().cast<cd>();
  U = rs.matrixU().cast<cd>();
  const Eigen::Index n = M.rows();
  for (Eigen::Index m = n - 1; m >= 1; --m) {
    if (T(m, m - 1) == cd(0)) continue;
    // an eigenvalue of the block [[a, b], [c, d]] at (m-1, m), minus d
    const cd a = T(m - 1, m - 1), b = T(m - 1, m), c = T(m, m - 1), d = T(m, m);
    const cd half = 0.5 * (a - d), mu = half + std::sqrt(half * half + b * c);
    const double r = std::hypot(std::abs(mu), std::abs(c));
    const cd cs = mu / r, sn = c / r;
    // G = [[conj(cs), conj(sn)], [-sn, cs]] (unitary; sn real up to rounding): T := G T G^*, U := U G^*
    for (Eigen::Index j = m - 1; j < n; ++j) {
      const cd x = T(m - 1, j), y = T(m, j);
      T(m - 1, j) = std::conj(cs) * x + std::conj(sn) * y;
      T(m, j) = -sn * x + cs * y;
    }
    for (Eigen::Index i = 0; i <= m; ++i) {
      const cd x = T(i, m - 1), y = T(i, m);
      T(i, m - 1) = x * cs + y * sn;
      T(i, m) = -x * std::conj(sn) + y * std::conj(cs);
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      const cd x = U(i, m - 1), y = U(i, m);
      U(i, m - 1) = x * cs + y * sn;
      U(i, m) = -x * std::conj(sn) + y * std::conj(cs);
    }
    T(m, m - 1) = 0;
  }
  return T.allFinite() && U.allFinite();
}

bool stein(const Eigen::MatrixXd& M, Eigen::MatrixXd& P, Eigen::VectorXcd& eigenvalues) {
  const Eigen::Index n = M.rows();
  Eigen::MatrixXcd T, U;
  if (!complex_schur(M, T, U)) return false;
  eigenvalues = T.diagonal();
  Eigen::MatrixXcd X = Eigen::MatrixXcd::Zero(n, n);
  Eigen::VectorXcd r(n), rhs(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::complex<double> tjj = T(j, j);
    // rhs = e_j + T^* r, r = X(:, 0:j) T(0:j, j); (T^* r)_i = sum_{k <= i} conj(T(k, i)) r_k
    if (j > 0) {
      r.noalias() = X.leftCols(j) * T.col(j).head(j);
      for (Eigen::Index i = 0; i < n; ++i) rhs(i) = T.col(i).head(i + 1).dot(r.head(i + 1));  // dot conjugates T
    } else {
      rhs.setZero();
    }
    rhs(j) += 1.0;
    // (I - tjj T^*) x = rhs: x_i = (rhs_i + tjj sum_{k < i} conj(T(k, i)) x_k) / (1 - tjj conj(T(i, i)))
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::complex<double> pivot = 1.0 - tjj * std::conj(T(i, i));
      if (std::abs(pivot) < 1e-14) return false;
      const std::complex<double> acc = i > 0 ? T.col(i).head(i).dot(X.col(j).head(i)) : std::complex<double>(0);
      X(i, j) = (rhs(i) + tjj * acc) / pivot;
    }
  }
  const Eigen::MatrixXcd Pc = U * X * U.adjoint();
  P = 0.5 * (Pc.real() + Pc.real().transpose());
  return P.allFinite();
}

// ---- certified bounds in double arithmetic (round to nearest, no rounding-mode switch) ----
// The a priori error bounds of floating-point linear algebra (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed.: Thm 3.5 for products, Thm 10.3 for Cholesky), with u = 2^-53
// and gamma_k = k u / (1 - k u). They hold for any order of summation (blocked, FMA), so Eigen's
// products may be used. Underflow adds at most k eta per inner product (eta the least subnormal):
// covered by an absolute term. These make the large decisions (the closed loop of a 128-device
// scene has order ~900) cost a few double products instead of 128-bit Arb products; where their
// slack (a factor ~n of the true rounding) is too coarse, the Arb path decides instead.
constexpr double kU = 0x1p-53;
constexpr double kEta = std::numeric_limits<double>::denorm_min();

// gamma_k, rounded up with room to spare (the 1.01 covers the rounding of this formula).
double gamma_up(double k) { return 1.01 * k * kU / (1 - k * kU); }

// A B for ball matrices in double: mid = fl(Am Bm); rad bounds gamma_k |Am||Bm| (the rounding of
// mid) + |Am| Br + Ar (|Bm| + Br) (the members), each nonnegative product computed in fl being at
// least (1 - gamma_{k+4}) times its true value: scaling by (1 + 2 gamma_{k+5}) restores an upper
// bound. Throws NumericalError on overflow.
BallMatrix product_fp(const BallMatrix& A, const BallMatrix& B) {
  const double k = static_cast<double>(A.cols());
  const double g = gamma_up(k + 5);
  BallMatrix C;
  C.mid.noalias() = A.mid * B.mid;
  const Eigen::MatrixXd absA = A.mid.cwiseAbs(), absB = B.mid.cwiseAbs();
  Eigen::MatrixXd R = absA * absB;
  R *= g;
  if (!B.rad.isZero(0)) R.noalias() += absA * B.rad;
  if (!A.rad.isZero(0)) R.noalias() += A.rad * (absB + B.rad);
  C.rad = (R * (1 + 2 * g)).array() + (3 * k + 10) * kEta;
  if (!C.mid.allFinite() || !C.rad.allFinite()) throw NumericalError("ball matrix product (double bounds): overflow");
  return C;
}

// A - B: mid = fl(Am - Bm), |fl(x) - x| <= u |fl(x)|.
BallMatrix difference_fp(const BallMatrix& A, const BallMatrix& B) {
  BallMatrix C;
  C.mid = A.mid - B.mid;
  C.rad = ((A.rad + B.rad + kU * C.mid.cwiseAbs()) * (1 + 4 * kU)).array() + 4 * kEta;
  return C;
}

// Every symmetric matrix within S's balls is positive definite, proven in double: with
// A = fl((Sm + Sm^T)/2) and r >= ||S - A||_2 for every symmetric S in the balls (the symmetric
// part of the radii, the rounding u|A|, bounded by the largest row sum: ||.||_2 <= ||.||_inf for
// a symmetric matrix), shift c = r + (gamma_{n+1}/(1 - gamma_{n+1})) tr(A) + u max A_ii (+ an
// underflow term). If the plain Cholesky of fl(A - c I) runs to completion, R^T R = A - c I + E +
// dA with |E_ii| <= u |A_ii - c|, ||dA||_2 <= gamma_{n+1} || |R^T||R| ||_2 <= gamma_{n+1} sum_i
// ||r_i||^2 <= (gamma_{n+1}/(1 - gamma_{n+1})) tr(A - c I) (Thm 10.3 and Cauchy-Schwarz), so
// lambda_min(A) > r and every S in the balls is positive definite.
bool positive_definite_fp(const BallMatrix& S) {
  const Eigen::Index n = S.rows();
  const double nd = static_cast<double>(n);
  const Eigen::MatrixXd A = 0.5 * (S.mid + S.mid.transpose());
  const Eigen::MatrixXd Rs = 0.5 * (S.rad + S.rad.transpose()) + kU * A.cwiseAbs();
  const double g = gamma_up(nd + 3);
  const double r = Rs.rowwise().sum().maxCoeff() * (1 + 2 * g);
  const double trace = A.trace(), dmax = A.diagonal().maxCoeff();
  if (!(A.diagonal().minCoeff() > 0) || !std::isfinite(trace) || !std::isfinite(r)) return false;
  const double gn = gamma_up(nd + 1);
  const double c = (r + (gn / (1 - gn)) * trace * (1 + g) + kU * dmax) * 1.01 + nd * nd * 1e-300;
  // plain (unblocked) Cholesky A - c I = U^T U, U upper triangular, column by column (contiguous)
  Eigen::MatrixXd U = A;
  U.diagonal().array() -= c;
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < j; ++i) U(i, j) = (U(i, j) - U.col(i).head(i).dot(U.col(j).head(i))) / U(i, i);
    const double d = U(j, j) - U.col(j).head(j).squaredNorm();
    if (!(d > 0)) return false;
    U(j, j) = std::sqrt(d);
  }
  return true;
}

}  // namespace

BallMatrix BallMatrix::exact(const MatQ& A) {
  BallMatrix B(A.rows(), A.cols());
  arb_t x;
  arb_init(x);
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
      if (A(i, j) == 0) continue;
      flint::set(x, A(i, j), kBallMatrixPrec);
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
  arb_mat_mul(p.get(), a.get(), b.get(), kBallMatrixPrec);
  return unload(p);
}

BallMatrix operator+(const BallMatrix& A, const BallMatrix& B) {
  if (A.rows() != B.rows() || A.cols() != B.cols()) throw InputError("ball matrix sum: sizes differ");
  const long r = static_cast<long>(A.rows()), c = static_cast<long>(A.cols());
  flint::BallMat a(r, c), b(r, c);
  load(a, A);
  load(b, B);
  arb_mat_add(a.get(), a.get(), b.get(), kBallMatrixPrec);
  return unload(a);
}

bool positive_definite(const BallMatrix& S, std::string* why) {
  if (S.rows() != S.cols()) throw InputError("positive_definite: the matrix must be square");
  const long n = static_cast<long>(S.rows());
  if (n == 0) return true;
  check_finite(S, "positive_definite");
  if (positive_definite_fp(S)) return true;  // the cheap proof first; the Arb congruence where its slack is too coarse
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
      arb_sub(s, s, a, kBallMatrixPrec);
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

// The exponents e of D = diag(2^e_i) that balance |A|'s off-diagonal row and column norms
// (Parlett and Reinsch's iteration, as LAPACK's gebal).
std::vector<long> balancing_exponents(Eigen::MatrixXd A) {
  const long n = A.rows();
  std::vector<long> e(static_cast<size_t>(n), 0);
  A = A.cwiseAbs();
  for (int sweep = 0; sweep < 40; ++sweep) {
    bool changed = false;
    for (long i = 0; i < n; ++i) {
      double c = 0, r = 0;  // off-diagonal column and row norms of D^-1 A D
      for (long j = 0; j < n; ++j)
        if (j != i) c += A(j, i), r += A(i, j);
      if (!(c > 0 && r > 0) || !std::isfinite(c) || !std::isfinite(r)) continue;
      int f = 0;  // D_ii *= 2^f with 2^f ~ sqrt(r / c)
      while (c * std::ldexp(1.0, 2 * f) < r / 2 && f < 61) ++f;
      while (c * std::ldexp(1.0, 2 * f) > 2 * r && f > -61) --f;
      if (f == 0 || f > 60 || f < -60) continue;
      e[static_cast<size_t>(i)] += f;
      for (long j = 0; j < n; ++j)
        if (j != i) A(j, i) = std::ldexp(A(j, i), f), A(i, j) = std::ldexp(A(i, j), -f);
      changed = true;
    }
    if (!changed) break;
  }
  return e;
}

std::optional<BallMatrix> balanced(const BallMatrix& M) {
  const std::vector<long> e = balancing_exponents(M.mid);
  BallMatrix B = M;
  for (Eigen::Index i = 0; i < M.mid.rows(); ++i)
    for (Eigen::Index j = 0; j < M.mid.cols(); ++j) {
      const int s = static_cast<int>(e[size_t(j)] - e[size_t(i)]);
      for (auto [from, to] : {std::pair{&M.mid, &B.mid}, std::pair{&M.rad, &B.rad}}) {
        const double x = (*from)(i, j), y = std::ldexp(x, s);
        if (x != 0 && !std::isnormal(y)) return std::nullopt;  // a subnormal or infinite result would not be exact
        (*to)(i, j) = y;
      }
    }
  return B;
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
  Eigen::MatrixXd P;
  Eigen::VectorXcd ev;
  const bool solved = stein(M.mid, P, ev);
  d.spectral_radius = ev.size() ? ev.cwiseAbs().maxCoeff() : Eigen::EigenSolver<Eigen::MatrixXd>(M.mid, false).eigenvalues().cwiseAbs().maxCoeff();
  if (!solved) {
    d.why = "no Stein certificate: the double solve of P - M^T P M = I failed (an eigenvalue on or within ~1e-14 of the "
            "unit circle, or a pair z, 1/conj(z)); numeric spectral radius " + numeric_decimal(d.spectral_radius);
    return d;
  }
  // R = P - M^T P M in balls (P exact: the doubles it holds), by the double bounds first and in
  // Arb at 128 bits when those do not prove R > 0
  const BallMatrix Pb = BallMatrix::exact(P);
  BallMatrix Mt;
  Mt.mid = M.mid.transpose();
  Mt.rad = M.rad.transpose();
  BallMatrix R = difference_fp(Pb, product_fp(Mt, product_fp(Pb, M)));
  if (!positive_definite_fp(R)) R = difference_fp(Pb, Mt * (Pb * M));
  std::string why;
  if (!positive_definite(R, &why)) {
    d.why = "no Stein certificate: P - M^T P M is not certainly positive definite in balls (" + why +
            "); numeric spectral radius " + numeric_decimal(d.spectral_radius) + ", |1 - rho| = " + numeric_decimal(std::abs(1 - d.spectral_radius));
    return d;
  }
  const std::string stein_text = "P - M^T P M > 0 proven in ball arithmetic for an exact P (" + std::to_string(n) + " x " +
                                 std::to_string(n) + ", solved from the Stein equation)";
  if (positive_definite(Pb, &why)) {
    d.P = P;
    d.stable = true;
    d.why = "certified Schur stable: " + stein_text + " and P > 0 (Lyapunov); numeric spectral radius " + numeric_decimal(d.spectral_radius);
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
    d.P = P;
    d.w = w;
    d.stable = false;
    d.why = "certified NOT Schur stable (an eigenvalue with |z| > 1): " + stein_text +
            " and w^T P w < 0 for an exact w (Stein inertia); numeric spectral radius " + numeric_decimal(d.spectral_radius);
    return d;
  }
  d.why = "no certificate: P - M^T P M > 0 holds but P is neither certainly positive definite nor certainly indefinite; "
          "numeric spectral radius " + numeric_decimal(d.spectral_radius);
  return d;
}

}  // namespace hapstab
