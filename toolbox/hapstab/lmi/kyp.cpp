// hapstab/lmi/kyp.cpp -- the KYP LMI's interior point by a DARE and doubling (kyp.hpp).
#include "hapstab/lmi/kyp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "hapstab/numeric/interrupt.hpp"

namespace hapstab::lmi {

namespace {
using Eigen::MatrixXd;
MatrixXd sym(const MatrixXd& M) { return 0.5 * (M + M.transpose()); }
}  // namespace

double kyp_min_eigenvalue(const KypData& d, const MatrixXd& P) {
  const Eigen::Index n = d.A.rows(), p = d.B.cols();
  MatrixXd F(n + p, n + p);
  const MatrixXd AtP = d.A.transpose() * P;
  F.topLeftCorner(n, n) = AtP * d.A - P;
  F.topRightCorner(n, p) = AtP * d.B - d.S;
  F.bottomLeftCorner(p, n) = F.topRightCorner(n, p).transpose();
  F.bottomRightCorner(p, p) = d.B.transpose() * P * d.B + d.R;
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(-sym(F), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

KypPoint kyp_riccati_point(const KypData& d, double delta) {
  interruption_point();  // a caller's stop request, before each Riccati solve (numeric/interrupt.hpp)
  KypPoint kp;
  kp.delta = delta;
  kp.riccati_solves = 1;
  const Eigen::Index n = d.A.rows(), p = d.B.cols();
  const MatrixXd R0 = sym(-d.R) - delta * MatrixXd::Identity(p, p);
  const Eigen::LLT<MatrixXd> L(R0);
  if (L.info() != Eigen::Success) {
    kp.detail = "R0 = -R - delta I is not positive definite";
    return kp;
  }
  const MatrixXd RiSt = L.solve(MatrixXd(d.S.transpose())), RiBt = L.solve(MatrixXd(d.B.transpose()));
  MatrixXd Ak = d.A - d.B * RiSt;
  MatrixXd Gk = sym(d.B * RiBt);
  MatrixXd Hk = sym(-delta * MatrixXd::Identity(n, n) - d.S * RiSt);
  const MatrixXd I = MatrixXd::Identity(n, n);
  bool converged = false;
  int it = 0;
  for (; it < 80 && !converged; ++it) {
    const Eigen::PartialPivLU<MatrixXd> W(I + Gk * Hk);
    const MatrixXd WA = W.solve(Ak), WG = W.solve(Gk);
    if (!WA.allFinite() || !WG.allFinite()) break;
    const MatrixXd Hn = sym(Hk + Ak.transpose() * Hk * WA);
    Gk = sym(Gk + Ak * WG * Ak.transpose());
    Ak = Ak * WA;
    const double change = (Hn - Hk).norm(), size = Hn.norm();
    Hk = Hn;
    if (!std::isfinite(size)) break;
    converged = change <= 1e-14 * size || Ak.norm() <= 1e-300;
  }
  std::ostringstream o;
  o << "doubling " << (converged ? "converged" : "did not converge") << " in " << it << " steps";
  if (!converged) {
    kp.detail = o.str();
    return kp;
  }
  kp.P = -Hk;
  kp.min_eig = kyp_min_eigenvalue(d, kp.P);
  o << ", lambda_min(F(P)) = " << kp.min_eig << " (delta = " << delta << ")";
  kp.found = std::isfinite(kp.min_eig) && kp.min_eig >= 0.5 * delta;
  kp.detail = o.str();
  return kp;
}

KypPoint kyp_interior_point(const KypData& d, double floor_rel) {
  const Eigen::Index p = d.B.cols();
  KypPoint none;
  double hi = 0;
  if (p > 0) {
    Eigen::SelfAdjointEigenSolver<MatrixXd> es(sym(-d.R), Eigen::EigenvaluesOnly);
    hi = es.eigenvalues()(0);
  }
  if (!(hi > 0)) {
    none.detail = "-R is not positive definite: B^T P B + R < 0 has no solution P >= 0";
    return none;
  }
  int solves = 0;
  for (double delta = hi / 4; delta >= hi * floor_rel; delta /= 4) {
    KypPoint kp = kyp_riccati_point(d, delta);
    solves += 1;
    kp.riccati_solves = solves;
    if (kp.found) return kp;
    none.detail = kp.detail;
  }
  none.riccati_solves = solves;
  none.detail = "no delta in [" + std::to_string(hi * floor_rel) + ", " + std::to_string(hi / 4) + "] works; last: " + none.detail;
  return none;
}

}  // namespace hapstab::lmi
