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
  // (no state: empty solves; Eigen's triangular solve of an empty right-hand side touches a null pointer)
  const MatrixXd RiSt = n > 0 ? MatrixXd(L.solve(MatrixXd(d.S.transpose()))) : MatrixXd(p, 0);
  const MatrixXd RiBt = n > 0 ? MatrixXd(L.solve(MatrixXd(d.B.transpose()))) : MatrixXd(p, 0);
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

// ---- the frequency-domain side ----

Eigen::MatrixXcd hessenberg_resolvent(const MatrixXd& H, std::complex<double> z, Eigen::MatrixXcd R) {
  using cd = std::complex<double>;
  const Eigen::Index n = H.rows();
  Eigen::MatrixXcd M = -H.cast<cd>();
  M.diagonal().array() += z;
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    if (std::abs(M(k + 1, k)) > std::abs(M(k, k))) {
      M.row(k).swap(M.row(k + 1));
      R.row(k).swap(R.row(k + 1));
    }
    if (M(k, k) == cd(0)) continue;
    const cd f = M(k + 1, k) / M(k, k);
    M.row(k + 1).tail(n - k) -= f * M.row(k).tail(n - k);
    R.row(k + 1) -= f * R.row(k);
  }
  for (Eigen::Index k = n - 1; k >= 0; --k) {  // back substitution
    R.row(k) -= M.row(k).tail(n - k - 1) * R.bottomRows(n - k - 1);
    R.row(k) /= M(k, k);
  }
  return R;
}

CircleResponse::CircleResponse(const MatrixXd& A, const MatrixXd& B, const MatrixXd& C, const MatrixXd& D) : D_(D) {
  if (A.rows() == 0) return;
  Eigen::HessenbergDecomposition<MatrixXd> hd(A);
  H_ = hd.matrixH();
  const MatrixXd Q = hd.matrixQ();
  QtB_ = (Q.transpose() * B).cast<std::complex<double>>();
  CQ_ = (C * Q).cast<std::complex<double>>();
}

Eigen::MatrixXcd CircleResponse::at(double theta) const {
  Eigen::MatrixXcd G = D_.cast<std::complex<double>>();
  if (H_.rows() > 0) G += CQ_ * hessenberg_resolvent(H_, std::polar(1.0, theta), QtB_);
  return G;
}

double kyp_frequency_bound(const KypData& d, const Eigen::VectorXd& g, int grid) {
  const Eigen::Index p = d.R.rows();
  const CircleResponse G(d.A, d.B, MatrixXd::Identity(d.A.rows(), d.A.rows()), MatrixXd::Zero(d.A.rows(), p));
  auto value = [&](double th) {
    const Eigen::MatrixXcd Gz = G.at(th);  // (zI - A)^-1 B
    const Eigen::MatrixXcd SG = d.S.transpose().cast<std::complex<double>>() * Gz;
    const Eigen::MatrixXcd Phi = d.R.cast<std::complex<double>>() - SG - SG.adjoint();
    const Eigen::MatrixXcd Ps = g.asDiagonal() * Phi * g.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(0.5 * (Ps + Ps.adjoint()), Eigen::EigenvaluesOnly);
    return es.eigenvalues()(p - 1);
  };
  double best = -INFINITY, bt = M_PI;
  auto consider = [&](double th) {
    const double v = value(th);
    if (v > best) best = v, bt = th;
  };
  for (int k = 1; k <= grid; ++k) consider(M_PI * k / grid);
  for (int k = 1; k <= 60; ++k) consider(M_PI / grid * std::pow(10.0, -k / 10.0));
  double lo = std::max(1e-12, bt - M_PI / grid), hi = std::min(M_PI, bt + M_PI / grid);
  for (int it = 0; it < 40; ++it) {
    const double a = hi - 0.618033988749895 * (hi - lo), b = lo + 0.618033988749895 * (hi - lo);
    if (value(a) > value(b)) hi = b;
    else lo = a;
  }
  consider(0.5 * (lo + hi));
  return best;
}

}  // namespace hapstab::lmi
