// hapstab/numeric/ball_matrix.hpp -- real matrices known to within a proven radius per entry
// (midpoint-radius form), the data of a sampled-data loop once exponentials enter: e^{AT} of
// exact A is enclosed (numeric/ball_expm.hpp), not known exactly. Every exact value lies within
// rad(i, j) of mid(i, j). Products are taken in Arb ball arithmetic at 128 bits and rounded back
// to double outward (the rounding of the midpoint is added to the radius), so the enclosure
// property survives every operation here.
//
// And the certified decisions made on such matrices (the Stein inertia theorem, proven in
// proofs/schur_lyapunov.cpp):
//   positive_definite(S):  every symmetric matrix inside the balls of S is positive definite.
//                          First in double: Cholesky of mid S - c I runs to completion, c
//                          covering the radii and the rounding of the Cholesky itself (the a
//                          priori bound of Higham's Thm 10.3; Rump's idea), O(n^3/3). Else:
//                          congruence by an exact upper-triangular X ~ L^-T (L the double Cholesky
//                          factor of mid S), then Gershgorin on X^T S X ~ I in balls: O(n^3), and
//                          robust where ball Cholesky loses its radii (n ~ 500).
//   schur_decide(M):       stable (every eigenvalue of every matrix in M inside |z| < 1) or not
//                          stable (an eigenvalue with |z| > 1), certified, or undecided with the
//                          numeric spectral radius as the margin. A P (exact dyadic, symmetric) is
//                          solved from P - M^T P M = I in double (complex Schur form, O(n^3)),
//                          P - M^T P M enclosed by double products with a priori rounding
//                          bounds (Higham Thm 3.5: gamma_n |A||B|), in Arb when those fail; then
//                            P - M^T P M > 0 in balls   and   P > 0      =>  Schur stable
//                            P - M^T P M > 0 in balls   and   w^T P w < 0 =>  an eigenvalue |z| > 1
//                          (if M were Schur stable, P would be the unique solution sum (M^T)^k Q M^k
//                          > 0 of the Stein equation with Q = P - M^T P M; and |z| = 1 is excluded
//                          since v^*(P - M^T P M)v = (1 - |z|^2) v^* P v = 0 for M v = z v).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab {

struct BallMatrix {
  Eigen::MatrixXd mid, rad;  ///< rad >= 0 entrywise; rad = 0 where the entry is exactly mid

  BallMatrix() = default;
  BallMatrix(Eigen::Index rows, Eigen::Index cols)
      : mid(Eigen::MatrixXd::Zero(rows, cols)), rad(Eigen::MatrixXd::Zero(rows, cols)) {}
  Eigen::Index rows() const { return mid.rows(); }
  Eigen::Index cols() const { return mid.cols(); }
  /// An exact matrix: each entry rounded to nearest, the rounding as its radius (0 for dyadics).
  static BallMatrix exact(const MatQ& A);
  /// A double matrix taken as exact.
  static BallMatrix exact(const Eigen::MatrixXd& A);
  /// mid with the same radius r on every entry.
  static BallMatrix uniform(const Eigen::MatrixXd& mid, double r);
  /// The block at (r0, c0) of size (other's size) := other.
  void set_block(Eigen::Index r0, Eigen::Index c0, const BallMatrix& other);
  double max_radius() const;
};

/// A B, enclosed (Arb, 128 bits; rounded outward to double).
BallMatrix operator*(const BallMatrix& A, const BallMatrix& B);
/// A + B, enclosed.
BallMatrix operator+(const BallMatrix& A, const BallMatrix& B);

/// True when every symmetric matrix inside S's balls is positive definite (see the header). S
/// must be square; a non-symmetric midpoint is treated through its symmetric part plus the
/// asymmetry as radius.
bool positive_definite(const BallMatrix& S, std::string* why = nullptr);

struct SchurDecision {
  std::optional<bool> stable;   ///< nullopt: undecided (why says so, with the margin)
  double spectral_radius = 0;   ///< of mid M, in double (numeric; the verdict does not rest on it)
  std::string why;              ///< the certificate in words, or why there is none
  Eigen::MatrixXd P;            ///< when decided: the Stein P (its doubles are the exact dyadic P)
  Eigen::VectorXd w;            ///< when NOT stable: w with w^T P w < 0 (exact dyadics)
};
SchurDecision schur_decide(const BallMatrix& M);

/// The exponents e of D = diag(2^e_i) that balance |A|'s off-diagonal row and column norms (Parlett and
/// Reinsch's iteration, as LAPACK's gebal).
std::vector<long> balancing_exponents(Eigen::MatrixXd A);
/// D^-1 M D for those exponents of M's midpoint: the same eigenvalues for every matrix in the balls (a similarity
/// by powers of two, exact on midpoints and radii); nullopt where a scaled entry would leave the normal doubles
/// (then it would not be exact). A Stein solve on M with entries over many decades (an environment ~10^4 beside a
/// device ~10^-3) can fail where the balanced ball is decided.
std::optional<BallMatrix> balanced(const BallMatrix& M);

}  // namespace hapstab
