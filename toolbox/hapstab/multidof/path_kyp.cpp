// hapstab/multidof/path_kyp.cpp -- the structured KYP/Riccati path of Theorem 5 (planner.hpp).
//
// Premises: the facial conditions pin X to one direction (X = g X_1; by homogeneity min g_i = 1),
// and Q_V need not be block diagonal (Remark 3). Then (16)'s first LMI with Q_E = Delta_D X (the
// stability-only elimination of analysis.hpp) is a KYP LMI in P11 alone, whose interior point is
// the stabilising solution of a shifted DARE (lmi/kyp.hpp): O(n^3) work and O(n^2) memory where
// the generic SDP's Schur complement has n(n+1)/2 x n(n+1)/2 entries. The candidate points are
//   Q_E = Delta_D X - eps I,  Q_V = Q_E + Q_E^2/eps + eps I   (eps = mu/2, then mu/16),
// which satisfy (14) (Schur complement eps I) and Q_V > 0 exactly; the planner's exact re-check
// (recheck.cpp) decides. riccati_points builds them at any exact X (path_kyp_search.cpp calls it
// at the X its outer search chose when X is not pinned). When the realisation's basis leaves the
// doubling no accuracy (a companion form of order 12 or more: no Riccati point on the whole
// ladder), the equation is solved again in a scaled modal basis x' = S x, S rational, and the point
// mapped back exactly (P11 = S^T P' S), so the re-check still decides in the realisation as
// written. The search proves nothing by itself: no Riccati point, or a point that fails the
// re-check, hands over to the next path (the generic SDP).
//
// Implements: paper 000 (16) via the KYP lemma (Rantzer 1996); DESIGN.md "Structure to exploit".
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <chrono>
#include <cmath>
#include <sstream>

#include "hapstab/lmi/kyp.hpp"
#include "hapstab/multidof/planner.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

namespace hapstab::multidof {

using namespace detail;

lmi::KypData detail::kyp_data(const Problem& pb, const EhatSplit& sp, const MatQ& Xq) {
  const int n = static_cast<int>(pb.E.states());
  const double Td = to_real<double>(pb.T());
  const MatrixXd X = to_double(Xq), E1 = to_double(sp.E1), DE = to_double(pb.E.D);
  lmi::KypData d;
  d.A = to_double(MatQ(sp.t.A.topLeftCorner(n, n)));
  d.B = to_double(MatQ(sp.t.B.topRows(n)));
  d.S = 0.5 * to_double(MatQ(sp.t.C.leftCols(n))).transpose() * X;
  const MatrixXd XE1s = 0.5 * (X * E1 + E1.transpose() * X);
  d.R = (Td / 2) * XE1s - (Td / 2) * (X * DE + DE.transpose() * X);
  return d;
}

std::optional<Pinned> detail::pinned_x(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc, std::string* why) {
  auto unmet = [&](std::string w) {
    if (why) *why = std::move(w);
    return std::nullopt;
  };
  if (fc.gamma_basis.size() != 1)
    return unmet("the facial conditions leave X a " + std::to_string(fc.gamma_basis.size()) +
                 "-dimensional set, not one direction");
  const MatQ X1 = pb.structure.scalar_blocks(fc.gamma_basis[0]);
  rational mn = X1(0, 0);
  for (Eigen::Index i = 0; i < X1.rows(); ++i) mn = std::min(mn, X1(i, i));
  if (!(mn > 0)) return unmet("X > 0 is impossible along the one direction the facial conditions leave");
  Pinned px;
  px.theta = rational(1) / mn;
  px.X = px.theta * X1;
  px.kyp = kyp_data(pb, sp, px.X);
  return px;
}

// The Riccati point rounded to dyadic rationals: the fewest bits (24, 32, 44, 52) whose rounding
// moves lambda_min of the first LMI by at most a tenth of its margin (double check; the exact
// re-check decides), mapped back to the realisation as written exactly.
MatQ detail::rounded_p11(const Pinned& px, const lmi::KypData& d, const lmi::KypPoint& kp) {
  const Eigen::Index n = kp.P.rows();
  MatQ R(n, n);
  for (int bits : {24, 32, 44, 52}) {
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = 0; i <= j; ++i) R(i, j) = R(j, i) = lmi::round_dyadic(kp.P(i, j), bits);
    if (std::abs(lmi::kyp_min_eigenvalue(d, to_double(R)) - kp.min_eig) <= 0.1 * kp.min_eig) break;
  }
  if (px.basis.size() == 0) return R;
  return exact_product(exact_product(MatQ(px.basis.transpose()), R), px.basis);
}

// The modal basis: the real eigenvectors of A (a complex pair as its real and imaginary parts),
// each mode scaled so that its rows of B and S have equal norms (the Riccati solution then has
// entries of one size: condition number 32 against 1e7 unscaled for the order-13 chain of
// bench/contact_scene.py --chain 6). In double: any invertible S does, the exact re-check of
// S^T R S decides.
std::optional<Pinned> detail::in_modal_basis(const Pinned& px) {
  const MatrixXd& A = px.kyp.A;
  const Eigen::Index n = A.rows();
  if (n < 2) return std::nullopt;
  Eigen::EigenSolver<MatrixXd> es(A);
  if (es.info() != Eigen::Success) return std::nullopt;
  const Eigen::VectorXcd lam = es.eigenvalues();
  const Eigen::MatrixXcd V = es.eigenvectors();
  MatrixXd Vr(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const bool pair = lam(i).imag() != 0 && i + 1 < n;
    Vr.col(i) = V.col(i).real();  // (Eigen's v has norm 1; a pair's parts keep their ratio: a real Jordan block)
    if (pair) Vr.col(i + 1) = V.col(i).imag(), ++i;
  }
  const Eigen::JacobiSVD<MatrixXd> sv(Vr);
  const double cond = sv.singularValues()(0) / sv.singularValues()(n - 1);
  // near 1: the basis is modal already; beyond 1e12: a defective eigenvalue (a delay's shift chain)
  if (!std::isfinite(cond) || cond < 1e3 || cond > 1e12) return std::nullopt;
  MatrixXd S = Vr.inverse();
  const MatrixXd SB = S * px.kyp.B, SS = Vr.transpose() * px.kyp.S;  // B' = S B, S' = S^-T S_kyp
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index k = lam(i).imag() != 0 && i + 1 < n ? 2 : 1;
    const double b = SB.middleRows(i, k).norm(), s = SS.middleRows(i, k).norm();
    if (b > 0 && s > 0) S.middleRows(i, k) *= std::sqrt(s / b);
    i += k - 1;
  }
  Pinned out = px;
  // S exactly as computed (53 bits): rounded coarser, S A S^-1 would no longer be block diagonal
  // to the doubles' accuracy (S's condition number times the rounding couples the modes)
  out.basis = lmi::to_rational(S);
  const MatrixXd Si = Eigen::PartialPivLU<MatrixXd>(S).inverse();
  if (!Si.allFinite()) return std::nullopt;
  out.kyp.A = S * A * Si;
  out.kyp.B = S * px.kyp.B;
  out.kyp.S = Si.transpose() * px.kyp.S;
  return out;
}

std::optional<Premises> riccati_premises(const PathContext& c, bool backend_premise) {
  if (c.pb.qv_block_diagonal)
    return Premises::unmet("Q_V is to be block diagonal (Remark 3): the constructed Q_V = Q_E + Q_E^2/eps + eps I is not");
  if (backend_premise && c.opt.backend != lmi::Backend::automatic)
    return Premises::unmet("an SDP back-end was chosen (--backend): that is the generic SDP");
  return std::nullopt;
}

RiccatiPoints riccati_points(const Problem& pb, const MatQ& X, const std::vector<rational>& theta,
                             const lmi::KypData& d0) {
  RiccatiPoints rp;
  const int m = pb.structure.m();
  const MatQ DX = exact_product(pb.structure.delta_D(), X);
  Pinned as_written;
  as_written.X = X;
  as_written.kyp = d0;
  lmi::KypData d = d0;
  d.R -= to_double(DX);
  const auto t0 = std::chrono::steady_clock::now();
  rp.kp = lmi::kyp_interior_point(d);
  if (!rp.kp.found) {  // a badly conditioned basis (in_modal_basis) leaves the doubling no accuracy
    if (std::optional<Pinned> mp = in_modal_basis(as_written)) {
      lmi::KypData dm = mp->kyp;
      dm.R -= to_double(DX);
      lmi::KypPoint km = lmi::kyp_interior_point(dm);
      km.riccati_solves += rp.kp.riccati_solves;
      if (km.found) {
        rp.kp = std::move(km);
        d = std::move(dm);
        rp.modal = std::move(mp);
        rp.basis_note = " in a scaled modal basis x' = S x, S rational, mapped back exactly: P11 = S^T P' S";
      } else {
        rp.kp.riccati_solves = km.riccati_solves;
        rp.kp.detail += "; in a scaled modal basis: " + km.detail;
      }
    }
  }
  rp.numeric_seconds = since(t0);
  const lmi::KypPoint& kp = rp.kp;
  if (!kp.found) {
    rp.no_point = "no Riccati point of (16)'s first LMI with Q_E = Delta_D X (" + kp.detail + ")";
    return rp;
  }
  ExactEnv x;
  x.X = X;
  x.theta = theta;
  x.P11 = rounded_p11(rp.modal ? *rp.modal : as_written, d, kp);
  for (double f : {0.5, 0.0625}) {
    const rational eps = lmi::round_dyadic(f * kp.min_eig, 20);
    if (!(eps > 0)) break;
    CandidatePoint cp;
    cp.env = x;
    cp.env.QE = DX - eps * MatQ::Identity(m, m);
    cp.QV = cp.env.QE + exact_product(cp.env.QE, cp.env.QE) / eps + eps * MatQ::Identity(m, m);
    cp.margin = kp.min_eig - to_real<double>(eps);
    cp.construction = "; Q_E = Delta_D X - eps I and Q_V = Q_E + Q_E^2/eps + eps I constructed exactly, P11 from a "
                      "Riccati equation (structured path)";
    rp.points.push_back(std::move(cp));
  }
  if (rp.points.empty()) rp.no_point = "the Riccati point has no margin to round into";
  return rp;
}

SolvePath kyp_riccati_path(bool backend_premise) {
  SolvePath p;
  p.name = "structured KYP/Riccati";
  p.premises = [backend_premise](const PathContext& c) {
    if (std::optional<Premises> no = riccati_premises(c, backend_premise)) return *no;
    std::string why;
    if (!pinned_x(c.pb, c.split, c.facial, &why)) return Premises::unmet(why);
    return Premises::met();
  };
  p.search = [](const PathContext& c) {
    PathResult r;
    const Problem& pb = c.pb;
    r.pinned = pinned_x(pb, c.split, c.facial);
    const Pinned& px = *r.pinned;
    RiccatiPoints rp = riccati_points(pb, px.X, {px.theta}, px.kyp);
    r.numeric_seconds = rp.numeric_seconds;
    r.points = std::move(rp.points);
    r.no_point = rp.no_point;
    const lmi::KypPoint& kp = rp.kp;
    if (!kp.found) return r;
    if (rp.modal) {  // the least dissipative coupling then solves in this basis too
      rp.modal->theta = px.theta;
      r.pinned = std::move(rp.modal);
    }
    std::ostringstream o;
    o << "structured KYP path (X pinned to one direction by the facial conditions, min g_i = 1): P11 from the "
         "Riccati equation of (16)'s first LMI with Q_E = Delta_D X (lmi/kyp.hpp: "
      << kp.riccati_solves << " DARE solve(s)" << rp.basis_note << ", " << kp.detail << ")";  // its time: AnalysisResult::sdp_seconds
    r.solver_detail = o.str();
    return r;
  };
  return p;
}

}  // namespace hapstab::multidof
