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
#include <functional>
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
/// tries). Where the frequency sweep is cheap beside a DARE (kyp_sweep_pays), the rungs above
/// kyp_shift_bound are skipped unsolved (no DARE solution exists there; a doubling that cannot
/// converge costs its 80 steps): the same rung is found with fewer solves, and where the bound is
/// below every rung (the frequency condition fails on the sweep) nothing is solved. found = false
/// when none works (-R not positive definite, or no delta on the ladder).
KypPoint kyp_interior_point(const KypData& d, double floor_rel = 1e-12);

// ---- the frequency-domain side (the KYP lemma's other half), numeric ----
// With A Schur stable, F(P) > 0 is feasible iff Phi(z) = R - S^T G(z) - G(z)^* S < 0 on the whole
// unit circle, G(z) = (zI - A)^-1 B: a sweep of Phi costs O(n^2 p) per frequency after one O(n^3)
// Schur form, where each DARE solve costs O(n^3) per doubling step.

/// (zI - H)^-1 R for an upper Hessenberg H (Gaussian elimination with partial pivoting between
/// adjacent rows, O(n^2 p)). A delay's shift chain is a defective eigenvalue, which an
/// eigendecomposition would not survive; a Hessenberg form does.
Eigen::MatrixXcd hessenberg_resolvent(const Eigen::MatrixXd& H, std::complex<double> z, Eigen::MatrixXcd R);

/// (C (zI - A)^-1 B + D) on the unit circle by one complex Schur form A = U T U^* (backward
/// stable: a delay's shift chain, a defective eigenvalue 0 that an eigendecomposition would not
/// survive, is computed as well as by the Hessenberg form -- 2e-14 relative apart at delay 200),
/// then one triangular back substitution per frequency that reads T in place (the Hessenberg
/// route copies and eliminates an n x n matrix per frequency: 3-4x the work). Where the QR
/// iteration does not converge, the Hessenberg form.
struct CircleResponse {
  CircleResponse(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C, const Eigen::MatrixXd& D);
  Eigen::MatrixXcd at(double theta) const;  ///< at z = e^{j theta}
 private:
  Eigen::MatrixXd H_, D_;
  Eigen::MatrixXcd T_, QtB_, CQ_;  ///< T_ empty: the Hessenberg form H_ is used
};

/// The maximum of value(theta) over (0, pi]: `grid` uniform frequencies and 60 log-spaced toward 0
/// (an accumulator's pole at z = 1), then golden section between the grid neighbours of the `keep`
/// largest local maxima (a delay's ripple has many near-equal peaks). Numeric: a grid misses what
/// it does not sample (a narrow peak), so the maximum found is a LOWER bound, up to rounding.
struct CircleMax {
  double value = 0, theta = 0;
  int evaluations = 0;
};
CircleMax circle_max(const std::function<double(double)>& value, int grid, int keep = 4);

/// The sweep's grid for a state dimension n: `grid` if > 0, else max(1024, 16 n) (a response of
/// order n has at most ~n ripples on the circle: ~16 samples each).
int kyp_sweep_grid(Eigen::Index n, int grid = 0);

/// A sweep costs O(n^2 p + p^3) per frequency, a DARE O(n^3) per doubling step: the sweeps below
/// are worth running before DARE solves for few inputs (p <= 8; a delayed wall has p = 1, the
/// 128-DOF contact scenes p = 128).
bool kyp_sweep_pays(const KypData& d);

/// The least t with F(P) > 0 feasible for R - t diag(g)^-2 ... precisely: max over the sweep of
/// lambda_max(diag(g) Phi(e^{j theta}) diag(g)) (circle_max). A LOWER bound of the true least t
/// (a grid misses nothing it samples; it may miss a narrow peak): the caller confirms by a DARE
/// solve above it.
double kyp_frequency_bound(const KypData& d, const Eigen::VectorXd& g, int grid = 0);

/// The largest shift delta with F(P) >= delta I feasible, from the frequency side: along
/// [(zI - A)^-1 B; I] u the P terms cancel, so it needs Phi(z) + delta (I + G^* G) < 0, i.e.
/// delta < -lambda_max(W^-1/2 Phi W^-1/2), W = I + G^* G, at every z = e^{j theta} (and, A Schur
/// stable, that suffices: KYP). By circle_max: an UPPER bound of that delta (up to rounding), and
/// the frequency where the sweep found it least. delta <= 0: the frequency condition fails there,
/// and F(P) > 0 has no solution.
struct ShiftBound {
  double delta = 0, theta = 0;
};
ShiftBound kyp_shift_bound(const KypData& d, int grid = 0);

}  // namespace hapstab::lmi
