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
// at the X its outer search chose when X is not pinned). The search proves nothing by itself: no Riccati point, or a point that
// fails the re-check, hands over to the next path (the generic SDP).
//
// Implements: paper 000 (16) via the KYP lemma (Rantzer 1996); DESIGN.md "Structure to exploit".
#include <chrono>
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

// The Riccati point P11 rounded to dyadic rationals: the fewest bits (24, 32, 44, 52) whose
// rounding moves lambda_min of the first LMI by at most a tenth of its margin (double check;
// the exact re-check decides).
MatQ detail::rounded_p11(const lmi::KypData& d, const lmi::KypPoint& kp) {
  const Eigen::Index n = kp.P.rows();
  MatQ R(n, n);
  for (int bits : {24, 32, 44, 52}) {
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = 0; i <= j; ++i) R(i, j) = R(j, i) = lmi::round_dyadic(kp.P(i, j), bits);
    if (std::abs(lmi::kyp_min_eigenvalue(d, to_double(R)) - kp.min_eig) <= 0.1 * kp.min_eig) break;
  }
  return R;
}

std::optional<Premises> riccati_premises(const PathContext& c, bool backend_premise) {
  if (c.pb.qv_block_diagonal)
    return Premises::unmet("Q_V is to be block diagonal (Remark 3): the constructed Q_V = Q_E + Q_E^2/eps + eps I is not");
  if (backend_premise && c.opt.backend != lmi::Backend::automatic)
    return Premises::unmet("an SDP back-end was chosen (--backend): that is the generic SDP");
  return std::nullopt;
}

RiccatiPoints riccati_points(const Problem& pb, const MatQ& X, const std::vector<rational>& theta, lmi::KypData d) {
  RiccatiPoints rp;
  const int m = pb.structure.m();
  const MatQ DX = exact_product(pb.structure.delta_D(), X);
  d.R -= to_double(DX);
  const auto t0 = std::chrono::steady_clock::now();
  rp.kp = lmi::kyp_interior_point(d);
  rp.numeric_seconds = since(t0);
  const lmi::KypPoint& kp = rp.kp;
  if (!kp.found) {
    rp.no_point = "no Riccati point of (16)'s first LMI with Q_E = Delta_D X (" + kp.detail + ")";
    return rp;
  }
  ExactEnv x;
  x.X = X;
  x.theta = theta;
  x.P11 = rounded_p11(d, kp);
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
    std::ostringstream o;
    o << "structured KYP path (X pinned to one direction by the facial conditions, min g_i = 1): P11 from the "
         "Riccati equation of (16)'s first LMI with Q_E = Delta_D X (lmi/kyp.hpp: "
      << kp.riccati_solves << " DARE solve(s), " << kp.detail << ")";  // its time: AnalysisResult::sdp_seconds
    r.solver_detail = o.str();
    return r;
  };
  return p;
}

}  // namespace hapstab::multidof
