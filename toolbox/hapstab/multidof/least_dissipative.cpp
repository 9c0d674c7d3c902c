// hapstab/multidof/least_dissipative.cpp -- the least dissipative coupling after a feasible
// Theorem 5 verdict (analysis.hpp: minimise ||Q_V||_2 subject to (16)), planned like the verdict
// (plan_least_dissipative): the structured Riccati bisection when X is pinned and
// Delta_D X = d I, else the generic program when it has at most limits::least_dissipative_unknowns
// unknowns (a verdict of seconds is not held minutes for this optional step). Each point is re-checked
// by the one exact re-check (recheck.cpp); its minimality is numeric, never certified.
//
// Implements: paper 000 (16) with the objective of Sec. VI (least dissipative coupling).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "hapstab/multidof/detail.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::multidof {

using namespace detail;

namespace {

// The least dissipative coupling: minimise t with Q_V <= t I subject to (16).
void least_dissipative(const Problem& pb, const EhatSplit& sp, const lmi::Options& opt, AnalysisResult& res) {
  const int m = pb.structure.m();
  Program prog;
  EnvVars ev;
  MatrixVariable QV;
  pose_16(prog, pb, sp, res.facial, ev, QV);
  const MatrixVariable t = prog.new_scalar("t");
  prog.add_lmi("Q_V <= t I", scalar_times(t, MatrixXd::Identity(m, m)) - Expr(QV), Strictness::nonstrict);
  prog.set_minimize(Expr(t));
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, opt);
  res.sdp_seconds += cs.seconds;
  if (cs.result.status != lmi::SolveStatus::optimal || !cs.has_point()) return;
  const ScaledPoint p = scaled_point(cs, ev, QV);
  std::string why;
  res.min_found = true;
  res.min_point_certified = exact_recheck(pb, sp, p.env, p.QV, why);
  res.Q_V_min = to_double(p.QV);
  const MatrixXd X = to_double(p.env.X);
  res.delta_V_min = gamma_inv_scale(res.Q_V_min, X);
  res.gamma_sqrt_min = gamma_sqrt(pb, X);
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(res.Q_V_min);
  res.Q_V_min_norm = es.eigenvalues().maxCoeff();
}


// The least dissipative coupling by the structured path. With X pinned (X = g X_1, g >= 1) and
// Delta_D X_1 = d I, (14) holds iff Q_V > Q_E + Q_E (d g I - Q_E)^-1 Q_E = f(Q_E), f matrix
// monotone, and Q_E enters the first LMI only as -Q_E: Q_E <= q I keeps it, so min ||Q_V|| is
// attained along Q_E = r g I, ||Q_V|| -> g d r / (d - r) (r >= 0; 0 when r < 0), least at g = 1 and
// the least r with the first LMI feasible. That r is found by bisection on the Riccati
// equation's solvability (lmi/kyp.hpp), the point at r slightly above it re-checked exactly.
// `diagonal`: Delta_D X = diag(d_i) need not be a multiple of I. The same bisection then runs
// along Q_E = s Delta_D X (0 < s < 1; the verdict's Q_E = Delta_D X - eps I is its end s -> 1):
// the certified point Q_V = diag(s d_i / (1 - s)) is a coupling requirement, not necessarily the
// least one (design.cpp's block-wise path uses it). nullopt when Delta_D X is not a multiple of I
// (not diagonal, with `diagonal`), or no Riccati point is found there (the caller then runs the
// generic program; design.cpp then designs by the generic CCL).
// Several parts (least_dissipative_points, the blocks of a symmetry split): one s shared by all,
// always along Q_E = s Delta_D X, feasible where every part's Riccati equation is solvable, and
// Q_V = (max(s/(1 - s), 0) + eps) Delta_D X: every matrix of the point proportional to X, so the
// parts' points are one point of the whole after the scalings of symmetry.hpp.
std::optional<std::vector<KypMinPoint>> bisection_points(const std::vector<KypPart>& parts, bool diagonal) {
  const bool shared = parts.size() > 1;
  struct Side {
    MatQ DX, G;
    MatrixXd Gd;
    Eigen::VectorXd gi;
  };
  std::vector<Side> side;
  bool scalar = !shared;
  double lo = -INFINITY;
  for (const KypPart& part : parts) {
    const int m = part.pb->structure.m();
    Side sd;
    sd.DX = exact_product(part.pb->structure.delta_D(), part.px.X);
    scalar = scalar && sd.DX == MatQ(sd.DX(0, 0) * MatQ::Identity(m, m));
    if (!scalar && !((diagonal || shared) && sd.DX.isDiagonal(0))) return std::nullopt;
    side.push_back(std::move(sd));
  }
  // Q_E = t G: G = I and t = r in (lo, d) when Delta_D X = d I; G = Delta_D X and t = s in (lo, 1)
  // otherwise. lo: -(R - t G) must be > 0, i.e. t > lambda_max(G^-1/2 R G^-1/2); the upper end is
  // feasible (the verdict).
  const rational t_end = scalar ? side[0].DX(0, 0) : rational(1);
  const double d = to_real<double>(t_end);
  for (size_t k = 0; k < parts.size(); ++k) {
    Side& sd = side[k];
    const int m = parts[k].pb->structure.m();
    sd.G = scalar ? MatQ(MatQ::Identity(m, m)) : sd.DX;
    sd.Gd = to_double(sd.G);
    sd.gi = sd.Gd.diagonal().cwiseSqrt().cwiseInverse();
    const lmi::KypData& kd = parts[k].px.kyp;
    const MatrixXd Rs = sd.gi.asDiagonal() * (0.5 * (kd.R + kd.R.transpose())) * sd.gi.asDiagonal();
    Eigen::SelfAdjointEigenSolver<MatrixXd> es(Rs, Eigen::EigenvaluesOnly);
    lo = std::max(lo, es.eigenvalues()(m - 1));
  }
  double hi = d;
  const double width = hi - lo;
  if (!(width > 0)) return std::nullopt;
  auto data = [&](size_t k, double t) {
    lmi::KypData kd = parts[k].px.kyp;
    kd.R -= t * side[k].Gd;
    return kd;
  };
  auto all_riccati = [&](double t, double tol) {
    for (size_t k = 0; k < parts.size(); ++k)
      if (!lmi::kyp_riccati_point(data(k, t), tol).found) return false;
    return true;
  };
  const auto t0 = std::chrono::steady_clock::now();
  int solves = 0;
  // The point: t_c a little above the least t (1e-6 of the bracket), where the LMI has room for a
  // rounded point; none when (14)'s Delta_D X - Q_E > 0 leaves no such t, or no Riccati point is found.
  std::optional<std::pair<rational, std::vector<lmi::KypPoint>>> at_tc;
  auto point_above = [&](double least) {
    const rational tc = lmi::round_dyadic(std::min(d, least + 1e-6 * width), 30);
    if (!(tc < t_end)) return;
    std::vector<lmi::KypPoint> kps;
    for (size_t k = 0; k < parts.size(); ++k) {
      kps.push_back(lmi::kyp_interior_point(data(k, to_real<double>(tc))));
      solves += kps.back().riccati_solves;
      if (!kps.back().found) return;
    }
    at_tc.emplace(tc, std::move(kps));
  };
  // The frequency side of the KYP lemma brackets the least t at once: t > lambda_max(G^-1/2 Phi(z)
  // G^-1/2) on the whole circle (lmi/kyp.hpp: a sweep costs O(n^2 m) per frequency where a DARE
  // costs O(n^3) per doubling step). The sweep's maximum f is a lower bound, refined to rounding:
  // the point is tried at once where the bisection below would end (f + its tolerance 1e-7), and
  // only if that fails (the grid missed a narrow peak) does the bisection run from f (issue 39
  // item 5: a delay of 200 samples took ~40 DARE solves here, most at a t or delta too close to
  // the boundary for the doubling to converge in its 80 steps).
  // Worth it when the sweep is cheap beside the DARE solves it saves: O(n^2 m + m^3) per frequency
  // against O(n^3) per doubling step -- few DOF (a delayed wall: m = 1), not the 128-DOF contact
  // scenes (there the sweep cost more than the bisection it shortened).
  double f = -INFINITY;
  for (size_t k = 0; k < parts.size(); ++k)
    if (lmi::kyp_sweep_pays(parts[k].px.kyp)) f = std::max(f, lmi::kyp_frequency_bound(parts[k].px.kyp, side[k].gi));
  const bool bracketed = f > lo && f < hi;
  if (bracketed) {
    lo = f;
    point_above(f + 1e-7 * width);
  }
  if (!at_tc) {
    if (bracketed) {  // the sweep's bound, confirmed by a DARE just above it
      const double up = std::min(hi, f + 1e-6 * width);
      ++solves;
      if (all_riccati(up, 1e-9 * width)) hi = up;
    }
    while (hi - lo > 1e-7 * width && solves < 60) {
      const double mid = 0.5 * (lo + hi);
      ++solves;
      (all_riccati(mid, 1e-9 * width) ? hi : lo) = mid;
    }
    point_above(hi);
  }
  if (!at_tc) return std::nullopt;
  const rational tc = at_tc->first;
  const double numeric_seconds = since(t0);
  // Q_V's margin over f(Q_E): absolute for one part (as always), proportional to Delta_D X for several
  const rational e = lmi::round_dyadic(1e-9 * std::max(1.0, to_real<double>(side[0].DX(0, 0))), 20);
  const rational eps = lmi::round_dyadic(1e-9, 20);
  std::vector<KypMinPoint> out;
  for (size_t k = 0; k < parts.size(); ++k) {
    const KypPart& part = parts[k];
    const int m = part.pb->structure.m();
    const MatQ& DX = side[k].DX;
    KypMinPoint p;
    p.numeric_seconds = numeric_seconds;
    p.r = tc;
    p.env.X = part.px.X;
    p.env.theta = {part.px.theta};
    p.env.P11 = rounded_p11(part.px, data(k, to_real<double>(tc)), at_tc->second[k]);
    p.env.QE = tc * side[k].G;
    p.QV = MatQ::Zero(m, m);
    for (int i = 0; i < m; ++i) {
      const rational q = p.env.QE(i, i);
      const rational fq = q * DX(i, i) / (DX(i, i) - q);  // Q_E + Q_E (Delta_D X - Q_E)^-1 Q_E, channel i
      p.QV(i, i) = (fq > 0 ? fq : rational(0)) + (shared ? eps * DX(i, i) : e);
    }
    p.certified = exact_recheck(*part.pb, *part.sp, p.env, p.QV, p.why);
    p.riccati_solves = solves;
    out.push_back(std::move(p));
  }
  return out;
}

std::optional<KypMinPoint> least_dissipative_point(const Problem& pb, const EhatSplit& sp, const Pinned& px,
                                                   bool diagonal) {
  auto pts = bisection_points({KypPart{&pb, &sp, px}}, diagonal);
  if (!pts) return std::nullopt;
  return std::move(pts->front());
}

bool kyp_least_dissipative(const Problem& pb, const EhatSplit& sp, const Pinned& px, AnalysisResult& res) {
  const std::optional<KypMinPoint> p = least_dissipative_point(pb, sp, px, false);
  if (!p) return false;  // no point to report: the generic program decides
  res.sdp_seconds += p->numeric_seconds;
  res.min_found = true;
  res.min_point_certified = p->certified;
  res.Q_V_min = to_double(p->QV);
  const MatrixXd X = to_double(p->env.X);
  res.delta_V_min = gamma_inv_scale(res.Q_V_min, X);
  res.gamma_sqrt_min = gamma_sqrt(pb, X);
  res.Q_V_min_norm = to_real<double>(p->QV(0, 0));
  res.solver_detail += "; least dissipative: Q_E = r I with r = " + std::to_string(to_real<double>(p->r)) + " (" +
                       std::to_string(p->riccati_solves) + " DARE solves)";
  return true;
}

}  // namespace

std::optional<detail::KypMinPoint> detail::kyp_min_point(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc) {
  const std::optional<Pinned> px = pinned_x(pb, sp, fc);
  if (!px) return std::nullopt;
  return least_dissipative_point(pb, sp, *px, true);
}

std::optional<std::vector<detail::KypMinPoint>> detail::least_dissipative_points(const std::vector<KypPart>& parts) {
  if (parts.size() < 2) throw std::logic_error("least_dissipative_points: two parts or more");
  return bisection_points(parts, true);
}

void detail::plan_least_dissipative(const Problem& pb, const EhatSplit& sp, const lmi::Options& opt,
                                    const std::optional<Pinned>& px, AnalysisResult& res) {
  if (px && kyp_least_dissipative(pb, sp, *px, res)) return;
  const double n = static_cast<double>(pb.E.states()), m = pb.structure.m();
  const double unknowns = n * (n + 1) / 2 + m * (m + 1);
  if (unknowns > limits::least_dissipative_unknowns) {  // the verdict stands; the optional search is bounded
    const std::string why = "its generic SDP has about " + std::to_string(static_cast<long>(unknowns)) +
                            " scalar unknowns, more than the " +
                            std::to_string(static_cast<long>(limits::least_dissipative_unknowns)) +
                            " this optional search is run for (numeric/limits.hpp)";
    res.solver_detail += "; least dissipative coupling not searched: " + why;
    return;
  }
  const std::string why =
      generic_size_exceeded(pb, 2L * pb.structure.m() * (pb.structure.m() + 1), "the least dissipative coupling's SDP");
  if (!why.empty()) {  // the verdict stands; only the optional minimisation is skipped
    res.solver_detail += "; least dissipative coupling not searched: " + why;
    return;
  }
  least_dissipative(pb, sp, opt, res);
}

}  // namespace hapstab::multidof
