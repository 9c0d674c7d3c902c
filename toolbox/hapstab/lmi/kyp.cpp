// hapstab/lmi/kyp.cpp -- the KYP LMI's interior point by a DARE and doubling (kyp.hpp).
#include "hapstab/lmi/kyp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "hapstab/numeric/interrupt.hpp"

namespace hapstab::lmi {

namespace {
using Eigen::MatrixXd;
MatrixXd symmetric_part(const MatrixXd& M) { return 0.5 * (M + M.transpose()); }
}  // namespace

double kyp_min_eigenvalue(const KypData& d, const MatrixXd& P) {
  const Eigen::Index n = d.A.rows(), p = d.B.cols();
  MatrixXd F(n + p, n + p);
  const MatrixXd AtP = d.A.transpose() * P;
  F.topLeftCorner(n, n) = AtP * d.A - P;
  F.topRightCorner(n, p) = AtP * d.B - d.S;
  F.bottomLeftCorner(p, n) = F.topRightCorner(n, p).transpose();
  F.bottomRightCorner(p, p) = d.B.transpose() * P * d.B + d.R;
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(-symmetric_part(F), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

KypPoint kyp_riccati_point(const KypData& d, double delta) {
  interruption_point();  // a caller's stop request, before each Riccati solve (numeric/interrupt.hpp)
  KypPoint kp;
  kp.delta = delta;
  kp.riccati_solves = 1;
  const Eigen::Index n = d.A.rows(), p = d.B.cols();
  const MatrixXd R0 = symmetric_part(-d.R) - delta * MatrixXd::Identity(p, p);
  const Eigen::LLT<MatrixXd> L(R0);
  if (L.info() != Eigen::Success) {
    kp.detail = "R0 = -R - delta I is not positive definite";
    return kp;
  }
  // (no state: empty solves; Eigen's triangular solve of an empty right-hand side touches a null pointer)
  const MatrixXd RiSt = n > 0 ? MatrixXd(L.solve(MatrixXd(d.S.transpose()))) : MatrixXd(p, 0);
  const MatrixXd RiBt = n > 0 ? MatrixXd(L.solve(MatrixXd(d.B.transpose()))) : MatrixXd(p, 0);
  MatrixXd Ak = d.A - d.B * RiSt;
  MatrixXd Gk = symmetric_part(d.B * RiBt);
  MatrixXd Hk = symmetric_part(-delta * MatrixXd::Identity(n, n) - d.S * RiSt);
  const MatrixXd I = MatrixXd::Identity(n, n);
  bool converged = false, stalled = false;
  int it = 0;
  // Where the DARE has no stabilising solution (the shift or the level beyond the frequency
  // condition) the doubling cannot converge, and ran its 80 steps (most of a bisection's time: half
  // its probes are infeasible). It shows early: A_k = (something bounded) Phi^(2^k) decays once
  // 2^k passes the closed loop's transient, each step making a new least ||A_k|| (seen: halving
  // near the boundary, then squaring), where without a solution ||A_k|| stops decreasing and
  // wanders. So: stalled when 8 steps (a 256-fold horizon) pass without a new least ||A_k|| after
  // the decrease began, or ||A_k|| never fell below ||A_0|| in 24 steps (a transient growth of
  // ||Phi^j|| lasting 2^24 powers). A stall proves nothing (found = false, like a non-convergence).
  double least = Ak.norm();
  int since_least = 0;
  bool decreasing = false;
  for (; it < 80 && !converged && !stalled; ++it) {
    const Eigen::PartialPivLU<MatrixXd> W(I + Gk * Hk);
    const MatrixXd WA = W.solve(Ak), WG = W.solve(Gk);
    if (!WA.allFinite() || !WG.allFinite()) break;
    const MatrixXd Hn = symmetric_part(Hk + Ak.transpose() * Hk * WA);
    Gk = symmetric_part(Gk + Ak * WG * Ak.transpose());
    Ak = Ak * WA;
    const double change = (Hn - Hk).norm(), size = Hn.norm();
    Hk = Hn;
    if (!std::isfinite(size)) break;
    const double an = Ak.norm();
    converged = change <= 1e-14 * size || an <= 1e-300;
    if (an < least) least = an, since_least = 0, decreasing = true;
    else ++since_least;
    stalled = !converged && (decreasing ? since_least >= 8 : it + 1 >= 24);
  }
  std::ostringstream o;
  o << "doubling " << (converged ? "converged" : stalled ? "stalled (no decrease of A_k in 8 steps)" : "did not converge")
    << " in " << it << " steps";
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
    Eigen::SelfAdjointEigenSolver<MatrixXd> es(symmetric_part(-d.R), Eigen::EigenvaluesOnly);
    hi = es.eigenvalues()(0);
  }
  if (!(hi > 0)) {
    none.detail = "-R is not positive definite: B^T P B + R < 0 has no solution P >= 0";
    return none;
  }
  // The ladder's rungs above the frequency side's bound fail (no DARE solution exists there, and a
  // doubling that cannot converge runs its 80 steps): they are skipped, so the first rung solved is
  // the one the full ladder would have found (the bound is an upper one; 1e-3 is rounding room).
  double start = hi / 4;
  std::string skipped;
  if (kyp_sweep_pays(d)) {
    const ShiftBound sb = kyp_shift_bound(d);
    const double cap = sb.delta * (1 + 1e-3);
    std::ostringstream o;
    o << "the frequency condition Phi + delta (I + G^* G) < 0 at theta = " << sb.theta << " rad needs delta < "
      << sb.delta;
    if (!(cap >= hi * floor_rel)) {  // no rung below it (the condition fails outright when sb.delta <= 0)
      o << ", below every delta of the ladder (its floor " << hi * floor_rel << ")";  // (to_string printed 0.000000)
      none.detail = o.str();
      return none;
    }
    int k = 0;
    for (; start > cap; start /= 4) ++k;
    if (k > 0) skipped = "; " + std::to_string(k) + " larger delta(s) skipped: " + o.str();
  }
  int solves = 0;
  for (double delta = start; delta >= hi * floor_rel; delta /= 4) {
    KypPoint kp = kyp_riccati_point(d, delta);
    solves += 1;
    kp.riccati_solves = solves;
    kp.detail += skipped;
    if (kp.found) return kp;
    none.detail = kp.detail;
  }
  none.riccati_solves = solves;
  std::ostringstream range;  // (std::to_string printed both ends as 0.000000)
  range << "no delta in [" << hi * floor_rel << ", " << start << "] works; last: ";
  none.detail = range.str() + none.detail;
  return none;
}

// ---- the frequency-domain side ----

Eigen::MatrixXcd hessenberg_resolvent(const MatrixXd& H, std::complex<double> z, Eigen::MatrixXcd R) {
  using cd = std::complex<double>;
  const Eigen::Index n = H.rows();
  // row-major: the elimination and the back substitution walk rows (contiguous here; a column-major
  // copy made every access a stride of n and the sweep's cost memory-bound)
  Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> M = -H.cast<cd>();
  M.diagonal().array() += z;
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    if (std::abs(M(k + 1, k)) > std::abs(M(k, k))) {
      M.row(k).tail(n - k).swap(M.row(k + 1).tail(n - k));  // left of k both rows are already 0
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
  Eigen::ComplexSchur<MatrixXd> cs(A);
  if (cs.info() != Eigen::Success) {  // (QR iterations that do not converge: the Hessenberg form)
    Eigen::HessenbergDecomposition<MatrixXd> hd(A);
    H_ = hd.matrixH();
    const MatrixXd Q = hd.matrixQ();
    QtB_ = (Q.transpose() * B).cast<std::complex<double>>();
    CQ_ = (C * Q).cast<std::complex<double>>();
    return;
  }
  T_ = cs.matrixT();
  const Eigen::MatrixXcd& U = cs.matrixU();
  QtB_ = U.adjoint() * B.cast<std::complex<double>>();
  CQ_ = C.cast<std::complex<double>>() * U;
}

Eigen::MatrixXcd CircleResponse::at(double theta) const {
  using cd = std::complex<double>;
  Eigen::MatrixXcd G = D_.cast<cd>();
  const cd z = std::polar(1.0, theta);
  if (T_.rows() > 0) {
    // (zI - T)^-1 U^* B by back substitution, column by column of T (contiguous; nothing copied)
    Eigen::MatrixXcd X = QtB_;
    const Eigen::Index n = T_.rows();
    for (Eigen::Index k = n - 1; k >= 0; --k) {
      X.row(k) /= z - T_(k, k);
      if (k > 0) X.topRows(k).noalias() += T_.col(k).head(k) * X.row(k);
    }
    G += CQ_ * X;
  } else if (H_.rows() > 0) G += CQ_ * hessenberg_resolvent(H_, z, QtB_);
  return G;
}

namespace {

// The KYP lemma's frequency side at z = e^{j theta}: G = (zI - A)^-1 B (one Hessenberg form of A),
// Phi = R - S^T G - G^* S and W = I + G^* G.
struct KypCircle {
  const KypData& d;
  CircleResponse G;
  explicit KypCircle(const KypData& kd)
      : d(kd), G(kd.A, kd.B, MatrixXd::Identity(kd.A.rows(), kd.A.rows()), MatrixXd::Zero(kd.A.rows(), kd.B.cols())) {}
  void at(double theta, Eigen::MatrixXcd& Phi, Eigen::MatrixXcd* W) const {
    const Eigen::MatrixXcd Gz = G.at(theta);
    const Eigen::MatrixXcd SG = d.S.transpose().cast<std::complex<double>>() * Gz;
    Phi = d.R.cast<std::complex<double>>() - SG - SG.adjoint();
    if (W) *W = Eigen::MatrixXcd::Identity(Gz.cols(), Gz.cols()) + Gz.adjoint() * Gz;
  }
};

double lambda_max(const Eigen::MatrixXcd& M) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(0.5 * (M + M.adjoint()), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(M.rows() - 1);
}

}  // namespace

int kyp_sweep_grid(Eigen::Index n, int grid) {
  return grid > 0 ? grid : static_cast<int>(std::max<Eigen::Index>(1024, 16 * n));
}

CircleMax circle_max(const std::function<double(double)>& value, int grid, int keep) {
  std::vector<std::pair<double, double>> pts;  // (theta, value), theta increasing
  pts.reserve(static_cast<size_t>(grid) + 60);
  for (int k = 60; k >= 1; --k) pts.emplace_back(M_PI / grid * std::pow(10.0, -k / 10.0), 0.0);
  for (int k = 1; k <= grid; ++k) pts.emplace_back(M_PI * k / grid, 0.0);
  for (auto& pt : pts) pt.second = value(pt.first);
  CircleMax best{-INFINITY, M_PI, static_cast<int>(pts.size())};
  std::vector<size_t> peaks;  // the grid's local maxima, largest first
  for (size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].second > best.value) best.value = pts[i].second, best.theta = pts[i].first;
    const bool left = i == 0 || pts[i].second >= pts[i - 1].second;
    const bool right = i + 1 == pts.size() || pts[i].second >= pts[i + 1].second;
    if (left && right) peaks.push_back(i);
  }
  std::sort(peaks.begin(), peaks.end(), [&](size_t a, size_t b) { return pts[a].second > pts[b].second; });
  if (peaks.size() > static_cast<size_t>(keep)) peaks.resize(static_cast<size_t>(keep));
  for (size_t i : peaks) {  // golden section between the grid neighbours
    double lo = i == 0 ? 0.5 * pts[0].first : pts[i - 1].first, hi = i + 1 == pts.size() ? M_PI : pts[i + 1].first;
    for (int it = 0; it < 40; ++it) {
      const double a = hi - 0.618033988749895 * (hi - lo), b = lo + 0.618033988749895 * (hi - lo);
      if (value(a) > value(b)) hi = b;
      else lo = a;
    }
    const double th = 0.5 * (lo + hi), v = value(th);
    best.evaluations += 81;
    if (v > best.value) best.value = v, best.theta = th;
  }
  return best;
}

bool kyp_sweep_pays(const KypData& d) { return d.B.cols() <= 8; }

double kyp_frequency_bound(const KypData& d, const Eigen::VectorXd& g, int grid) {
  const KypCircle c(d);
  Eigen::MatrixXcd Phi;
  return circle_max(
             [&](double th) {
               c.at(th, Phi, nullptr);
               return lambda_max(g.asDiagonal() * Phi * g.asDiagonal());
             },
             kyp_sweep_grid(d.A.rows(), grid))
      .value;
}

ShiftBound kyp_shift_bound(const KypData& d, int grid) {
  const KypCircle c(d);
  Eigen::MatrixXcd Phi, W;
  // lambda_max(L^-1 Phi L^-*), W = L L^*: the largest delta with Phi + delta W < 0 at theta is its negative
  const CircleMax m = circle_max(
      [&](double th) {
        c.at(th, Phi, &W);
        const Eigen::LLT<Eigen::MatrixXcd> L(W);
        const Eigen::MatrixXcd LiPhi = L.matrixL().solve(Phi);
        return lambda_max(L.matrixL().solve(Eigen::MatrixXcd(LiPhi.adjoint())).adjoint());
      },
      kyp_sweep_grid(d.A.rows(), grid));
  return {-m.value, m.theta};
}

}  // namespace hapstab::lmi
