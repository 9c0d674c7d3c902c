// hapstab/lmi/kyp.hpp -- a strictly feasible point of a discrete-time KYP LMI in O(n^3), by a
// Riccati equation instead of an interior-point method (which forms a Schur complement over
// all n(n+1)/2 entries of P: O(n^6) per iteration). Numeric only: the caller rounds the point
// and decides by its exact check.
//
// The LMI, in P = P^T (n x n), for given A (n x n, Schur stable), B, S (n x p), R (p x p):
//   F(P) = -[[A^T P A - P, A^T P B - S], [B^T P A - S^T, B^T P B + R]]  >=  delta I.
// With Y = -P, R0 = -R - delta I (> 0) and Q = -delta I, F(P) - delta I is the LQR matrix
//   [[A^T Y A - Y + Q, A^T Y B + S], [B^T Y A + S^T, R0 + B^T Y B]],
// which is positive semidefinite (rank p) at the stabilising solution of the DARE
//   Y = A^T Y A + Q - (A^T Y B + S)(R0 + B^T Y B)^-1 (B^T Y A + S^T)
// (Kalman-Yakubovich-Popov: it exists iff the delta-shifted frequency condition holds, A being
// Schur stable). The DARE is solved by the structure-preserving doubling algorithm (Chu, Fan,
// Lin 2005) on  Y = Ab^T Y (I + G Y)^-1 Ab + H,  Ab = A - B R0^-1 S^T, G = B R0^-1 B^T,
// H = Q - S R0^-1 S^T: only products and solves of n x n matrices, quadratically convergent.
// Every returned point is checked numerically: lambda_min(F(P)) >= delta / 2.
//
// Reference: Vandenberghe, Balakrishnan, Wallin, Hansson, Roh (2005) on the KYP structure; the
// Riccati route is the classical one (Willems 1971; Rantzer 1996).
#pragma once

#include <Eigen/Core>
#include <complex>
#include <string>

namespace hapstab::lmi {

struct KypData {
  Eigen::MatrixXd A, B, S, R;
};

struct KypPoint {
  bool found = false;
  Eigen::MatrixXd P;
  double delta = 0;       ///< the Riccati's shift: lambda_min(F(P)) >= delta / 2 (checked)
  double min_eig = 0;     ///< lambda_min(F(P)) at P (double)
  int riccati_solves = 0;
  std::string detail;
};

/// lambda_min(F(P)) in double.
double kyp_min_eigenvalue(const KypData& d, const Eigen::MatrixXd& P);

/// P with F(P) >= delta I for one shift delta (the stabilising DARE solution); found = false when
/// R0 is not positive definite, the doubling breaks down or does not converge, or the check fails.
KypPoint kyp_riccati_point(const KypData& d, double delta);

/// A well-interior point: kyp_riccati_point at delta = delta_hi 4^-k (delta_hi = lambda_min(-R))
/// for k = 1, 2, ... down to delta_hi * floor_rel, and the first delta that works is returned (so
/// its shift is within a factor 4 of the largest on that ladder; riccati_solves counts the
/// tries). found = false when none does (-R not positive definite, or no delta on the ladder).
KypPoint kyp_interior_point(const KypData& d, double floor_rel = 1e-12);

// ---- the frequency-domain side (the KYP lemma's other half), numeric ----
// With A Schur stable, F(P) > 0 is feasible iff Phi(z) = R - S^T G(z) - G(z)^* S < 0 on the whole
// unit circle, G(z) = (zI - A)^-1 B: a sweep of Phi costs O(n^2 p) per frequency after one O(n^3)
// Hessenberg form, where each DARE solve costs O(n^3) per doubling step.

/// (zI - H)^-1 R for an upper Hessenberg H (Gaussian elimination with partial pivoting between
/// adjacent rows, O(n^2 p)). A delay's shift chain is a defective eigenvalue, which an
/// eigendecomposition would not survive; a Hessenberg form does.
Eigen::MatrixXcd hessenberg_resolvent(const Eigen::MatrixXd& H, std::complex<double> z, Eigen::MatrixXcd R);

/// (C (zI - A)^-1 B + D) on the unit circle by one Hessenberg form of A.
struct CircleResponse {
  CircleResponse(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C, const Eigen::MatrixXd& D);
  Eigen::MatrixXcd at(double theta) const;  ///< at z = e^{j theta}
 private:
  Eigen::MatrixXd H_, D_;
  Eigen::MatrixXcd QtB_, CQ_;
};

/// The least t with F(P) > 0 feasible for R - t diag(g)^-2 ... precisely: max over the sweep of
/// lambda_max(diag(g) Phi(e^{j theta}) diag(g)), theta on a grid of (0, pi] (denser near 0) refined by
/// golden section. A LOWER bound of the true least t (a grid misses nothing it samples; it may
/// miss a narrow peak): the caller confirms by a DARE solve above it.
double kyp_frequency_bound(const KypData& d, const Eigen::VectorXd& g, int grid = 1024);

}  // namespace hapstab::lmi
