// hapstab/multidof/path_kyp_search.cpp -- the structured KYP/Riccati path of Theorem 5 when the
// facial conditions leave X a d-dimensional set, d > 1 (issue 39 item 3; planner.hpp), e.g. several
// operators whose environment couples them only dynamically (dampers between objects: E(1) is
// block diagonal over them, so each operator keeps its own g_i).
//
// X = sum_i g_i X_i, X_i = the facial basis (facial.cpp; disjoint supports). Premise: every
// operator lies in the support of one X_i with positive entries, so X > 0 iff g > 0. With
// Q_E := Delta_D X (the stability-only elimination of analysis.hpp), (16)'s first LMI is the KYP
// LMI F_g(P11) > 0 of lmi/kyp.hpp whose data (A, B, S_g, R_g) = (A, B, sum g_i S_i, sum g_i R_i)
// is LINEAR in g (detail::kyp_data). The outer search over g uses the KYP lemma's frequency
// form (Rantzer 1996; A is Schur stable): F_g(P11) > 0 is feasible for some P11 iff
//     Phi_g(theta) = sum_i g_i Phi_i(theta) < 0  for every theta in [0, pi],
//     Phi_i(theta) = R_i - S_i^T G(theta) - G(theta)^* S_i,  G(theta) = (e^{j theta} I - A)^-1 B.
// psi(g) = max_theta lambda_max(Phi_g(theta)) is a maximum of functions linear in g, so it is
// CONVEX and positively homogeneous: the g that work form an open convex cone, and minimising psi
// over the simplex {g >= 0, sum g_i = 1} finds an interior one when there is one. (The same
// holds in the time domain -- (X, P11) enter (16) jointly linearly, so sup_P lambda_min(F_g(P)) is
// concave in g -- but evaluating that needs a bisection of Riccati solves per g; Phi is one
// frequency sweep for all g.) The minimisation is an exchange method (Hettich & Kortanek 1993 for
// semi-infinite programs): on a grid of theta (G(theta) by one Hessenberg form of A, O(n^2 m)
// per frequency, lmi::CircleResponse), solve the small SDP
//     min t  s.t.  t I - sum_i g_i Phi_i(theta_k) >= 0 (k active),  sum g_i = 1,  g >= 0
// in d + 1 unknowns (Hermitian blocks as their real 2m x 2m embedding), add the grid's worst
// local maxima at the new g to the active set, and repeat until the grid's maximum meets the
// SDP's lower bound t (the grid's optimum is then reached; t >= 0: no g works on the grid).
//
// At the g found (pulled into the simplex's interior so that X > 0 with room, rounded to dyadic
// rationals, scaled to min g_i = 1) the structured path's Riccati point and candidate points
// (path_kyp.cpp, riccati_points) go to the planner's exact re-check, which decides. The grid may
// miss a narrow peak: the Riccati equation then has no stabilising solution at that g and the
// path hands over (no point), never a weaker verdict. Where the SDP's bound t is positive (no g
// passes the active frequencies), the top eigenvectors there and the weights of the dual matrix
// game are a candidate witness of infeasibility at several frequencies, decided exactly by
// path_witness.cpp (multi_frequency_witness): the path then proves (16) infeasible.
//
// Implements: paper 000 (16) via the KYP lemma (Rantzer 1996) with X searched over the facial
// set; DESIGN.md "Structure to exploit".
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <sstream>

#include "hapstab/lmi/kyp.hpp"
#include "hapstab/multidof/planner.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/numeric_decimal.hpp"

namespace hapstab::multidof {

using namespace detail;

namespace {

using Eigen::MatrixXcd;

// Phi_i(theta) for every basis element on a grid of theta.
struct FrequencyData {
  std::vector<double> theta;
  std::vector<std::vector<MatrixXcd>> Phi;  // [k][i]
  double scale = 1;                          // max_i,k ||Phi_i(theta_k)||_max: the tolerances' unit
  int m = 0;
};

FrequencyData sample(const std::vector<lmi::KypData>& d) {
  FrequencyData f;
  const Eigen::Index n = d[0].A.rows(), m = d[0].R.rows();
  f.m = static_cast<int>(m);
  const lmi::CircleResponse G(d[0].A, d[0].B, Eigen::MatrixXd::Identity(n, n), Eigen::MatrixXd::Zero(n, m));
  // a uniform grid of [0, pi] and a logarithmic one towards 0 (the lightly damped poles near z = 1
  // of a stiff environment), as the witness's and the least dissipative step's sweeps
  const int K = 1024;
  for (int k = 0; k <= K; ++k) f.theta.push_back(M_PI * k / K);
  for (int k = 1; k <= 60; ++k) f.theta.push_back(M_PI / K * std::pow(10.0, -k / 10.0));
  std::sort(f.theta.begin(), f.theta.end());
  f.scale = 0;
  for (double th : f.theta) {
    const MatrixXcd Gz = G.at(th);
    std::vector<MatrixXcd> row;
    for (const auto& di : d) {
      const MatrixXcd SG = di.S.transpose().cast<std::complex<double>>() * Gz;
      MatrixXcd P = di.R.cast<std::complex<double>>() - SG - SG.adjoint();
      P = 0.5 * (P + P.adjoint());
      f.scale = std::max(f.scale, P.cwiseAbs().maxCoeff());
      row.push_back(std::move(P));
    }
    f.Phi.push_back(std::move(row));
  }
  if (!(f.scale > 0)) f.scale = 1;
  return f;
}

MatrixXcd combine(const std::vector<MatrixXcd>& Phi, const Eigen::VectorXd& g) {
  MatrixXcd S = MatrixXcd::Zero(Phi[0].rows(), Phi[0].cols());
  for (size_t i = 0; i < Phi.size(); ++i) S += g(static_cast<Eigen::Index>(i)) * Phi[i];
  return S;
}

double lambda_max(const MatrixXcd& H) {
  Eigen::SelfAdjointEigenSolver<MatrixXcd> es(H, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(es.eigenvalues().size() - 1);
}

// [[Re H, -Im H], [Im H, Re H]]: real symmetric with H's eigenvalues, each twice.
Eigen::MatrixXd real_embedding(const MatrixXcd& H) {
  const Eigen::Index m = H.rows();
  Eigen::MatrixXd E(2 * m, 2 * m);
  E << H.real(), -H.imag(), H.imag(), H.real();
  return 0.5 * (E + E.transpose());
}

struct OuterResult {
  Eigen::VectorXd g;
  double psi = INFINITY;   // the grid's max of lambda_max(Phi_g) at g
  double bound = -INFINITY;  // the last SDP's t: a lower bound of min psi over the grid
  int iterations = 0, active = 0;
  std::vector<size_t> active_set;  // the frequencies (indices into the grid) of the last SDP
  std::string failure;
};

// min over the simplex of the grid's psi, by the exchange method above.
OuterResult minimise_psi(const FrequencyData& f, int d) {
  OuterResult o;
  o.g = Eigen::VectorXd::Constant(d, 1.0 / d);
  std::vector<char> active(f.theta.size(), 0);
  std::vector<size_t> act;
  const double tol = 1e-6 * f.scale;
  for (int it = 0; it < 40; ++it) {
    std::vector<double> v(f.theta.size());
    for (size_t k = 0; k < v.size(); ++k) v[k] = lambda_max(combine(f.Phi[k], o.g));
    o.psi = *std::max_element(v.begin(), v.end());
    if (it > 0 && o.psi <= o.bound + tol) break;  // the grid's optimum, to tol
    // the worst local maxima (grid neighbours) not yet active, at most 6 per round
    std::vector<size_t> peaks;
    for (size_t k = 0; k < v.size(); ++k)
      if (!active[k] && (k == 0 || v[k] >= v[k - 1]) && (k + 1 == v.size() || v[k] >= v[k + 1])) peaks.push_back(k);
    std::sort(peaks.begin(), peaks.end(), [&](size_t a, size_t b) { return v[a] > v[b]; });
    if (peaks.empty() || v[peaks[0]] <= o.bound + tol) {
      const size_t worst = static_cast<size_t>(std::max_element(v.begin(), v.end()) - v.begin());
      if (active[worst]) break;  // nothing new to add
      peaks = {worst};
    }
    for (size_t q = 0; q < std::min<size_t>(6, peaks.size()); ++q) active[peaks[q]] = 1, act.push_back(peaks[q]);
    // the SDP over the active frequencies (scaled by f.scale)
    lmi::Program prog;
    std::vector<lmi::MatrixVariable> gv;
    lmi::Expr sum = lmi::Expr::zero(1, 1);
    for (int i = 0; i < d; ++i) {
      gv.push_back(prog.new_scalar("g" + std::to_string(i + 1)));
      sum += lmi::Expr(gv.back());
      prog.add_linear_inequality("g" + std::to_string(i + 1) + " >= 0", lmi::Expr(gv.back()), Eigen::MatrixXd::Zero(1, 1));
    }
    prog.add_linear_equality("sum g = 1", sum, Eigen::MatrixXd::Ones(1, 1));
    const lmi::MatrixVariable t = prog.new_scalar("t");
    const Eigen::MatrixXd I2 = Eigen::MatrixXd::Identity(2 * f.m, 2 * f.m);
    for (size_t k : act) {
      lmi::Expr F = scalar_times(lmi::Expr(t), I2);
      for (int i = 0; i < d; ++i)
        F -= scalar_times(lmi::Expr(gv[static_cast<size_t>(i)]), real_embedding(f.Phi[k][static_cast<size_t>(i)]) / f.scale);
      prog.add_lmi("frequency " + std::to_string(k), F, lmi::Strictness::nonstrict);
    }
    prog.set_minimize(lmi::Expr(t));
    lmi::Options opt;
    opt.backend = lmi::Backend::ipm;
    opt.certify = false;
    const lmi::SolveResult sr = lmi::solve(prog, opt);
    o.iterations = it + 1;
    o.active = static_cast<int>(act.size());
    o.active_set = act;
    if (sr.verdict != lmi::Feasibility::feasible) {
      o.failure = "the outer search's SDP over " + std::to_string(act.size()) + " frequencies: " +
                  lmi::to_string(sr.verdict) + " (" + sr.detail + ")";
      return o;
    }
    Eigen::VectorXd g(d);
    for (int i = 0; i < d; ++i) g(i) = std::max(0.0, sr.solution(gv[static_cast<size_t>(i)])(0, 0));
    if (!(g.sum() > 0)) {
      o.failure = "the outer search's SDP returned g = 0";
      return o;
    }
    o.g = g / g.sum();
    o.bound = sr.solution(t)(0, 0) * f.scale;
    if (o.bound >= 0) {  // no g on the simplex passes the grid's frequencies
      o.psi = -INFINITY;
      for (size_t k = 0; k < f.Phi.size(); ++k) o.psi = std::max(o.psi, lambda_max(combine(f.Phi[k], o.g)));
      return o;
    }
  }
  return o;
}

// Where the outer search's bound is positive (no g passes the active frequencies): the weights of
// a witness (multi_frequency_witness) -- the top eigenvectors u_j of Phi_g at the active
// frequencies (theta > 0) and w from the matrix game max_w min_i sum_j w_j u_j^* Phi_i u_j (an LP,
// the dual of the outer problem restricted to those directions).
std::optional<Verdict> witness_of(const Problem& pb, const std::vector<MatQ>& Xk, const FrequencyData& f,
                                  const OuterResult& o, std::string& why, WeightedWitness& out) {
  const int d = static_cast<int>(Xk.size());
  std::vector<double> theta;
  std::vector<Eigen::VectorXcd> u;
  std::vector<Eigen::VectorXd> c;  // c[j](i) = u_j^* Phi_i(theta_j) u_j
  for (size_t k : o.active_set) {
    if (!(f.theta[k] > 0)) continue;  // E-hat has its poles at z = 1
    Eigen::SelfAdjointEigenSolver<MatrixXcd> es(combine(f.Phi[k], o.g));
    const Eigen::Index m = es.eigenvalues().size();
    for (Eigen::Index q = m - 1; q >= std::max<Eigen::Index>(0, m - 2); --q) {
      theta.push_back(f.theta[k]);
      u.push_back(es.eigenvectors().col(q));
      Eigen::VectorXd ci(d);
      for (int i = 0; i < d; ++i) ci(i) = (u.back().adjoint() * f.Phi[k][static_cast<size_t>(i)] * u.back())(0, 0).real() / f.scale;
      c.push_back(ci);
    }
  }
  if (theta.empty()) {
    why = "no active frequency in (0, pi]";
    return std::nullopt;
  }
  lmi::Program prog;
  std::vector<lmi::MatrixVariable> wv;
  lmi::Expr sum = lmi::Expr::zero(1, 1);
  std::vector<lmi::Expr> rows(static_cast<size_t>(d), lmi::Expr::zero(1, 1));
  const lmi::MatrixVariable sv = prog.new_scalar("s");
  for (size_t j = 0; j < theta.size(); ++j) {
    wv.push_back(prog.new_scalar("w" + std::to_string(j + 1)));
    prog.add_linear_inequality("w" + std::to_string(j + 1) + " >= 0", lmi::Expr(wv.back()), Eigen::MatrixXd::Zero(1, 1));
    sum += lmi::Expr(wv.back());
    for (int i = 0; i < d; ++i) rows[static_cast<size_t>(i)] += c[j](i) * lmi::Expr(wv.back());
  }
  prog.add_linear_equality("sum w = 1", sum, Eigen::MatrixXd::Ones(1, 1));
  for (int i = 0; i < d; ++i)
    prog.add_linear_inequality("direction " + std::to_string(i + 1), rows[static_cast<size_t>(i)] - lmi::Expr(sv),
                               Eigen::MatrixXd::Zero(1, 1));
  prog.set_minimize(-1.0 * lmi::Expr(sv));
  lmi::Options opt;
  opt.backend = lmi::Backend::ipm;
  opt.certify = false;
  const lmi::SolveResult sr = lmi::solve(prog, opt);
  if (sr.verdict != lmi::Feasibility::feasible || !(sr.solution(sv)(0, 0) > 0)) {
    why = "the witness weights' LP found no positive value (" + std::string(lmi::to_string(sr.verdict)) + ")";
    return std::nullopt;
  }
  std::vector<double> w;
  for (const auto& v : wv) w.push_back(std::max(0.0, sr.solution(v)(0, 0)));
  return multi_frequency_witness(pb, Xk, theta, u, w, why, &out);
}

}  // namespace

std::optional<std::vector<MatQ>> detail::positive_facial_basis(const Problem& pb, const FacialConditions& fc,
                                                               std::string& why) {
  const size_t N = pb.structure.operators.size();
  std::vector<int> covered(N, 0);
  std::vector<MatQ> Xk;
  for (const auto& b : fc.gamma_basis) {
    for (size_t i = 0; i < N; ++i) {
      if (b[i] < 0) {
        why = "a direction of the facial set has entries of both signs (X > 0 is impossible along it)";
        return std::nullopt;
      }
      covered[i] += b[i] > 0;
    }
    Xk.push_back(pb.structure.scalar_blocks(b));
  }
  for (size_t i = 0; i < N; ++i)
    if (covered[i] != 1) {
      why = "operator '" + pb.structure.operators[i].name + "' has g = 0 on every X the facial conditions allow";
      return std::nullopt;
    }
  return Xk;
}

SolvePath kyp_search_path(bool backend_premise) {
  SolvePath p;
  p.name = "structured KYP/Riccati, X searched";
  p.premises = [backend_premise](const PathContext& c) {
    if (std::optional<Premises> no = riccati_premises(c, backend_premise)) return *no;
    const size_t d = c.facial.gamma_basis.size();
    if (d < 2) return Premises::unmet("the facial conditions pin X to one direction (the structured KYP/Riccati path's case)");
    std::string why;
    if (!positive_facial_basis(c.pb, c.facial, why)) return Premises::unmet(why);
    return Premises::met();
  };
  p.search = [](const PathContext& c) {
    PathResult r;
    const Problem& pb = c.pb;
    const auto t0 = std::chrono::steady_clock::now();
    std::string why;
    const std::vector<MatQ> Xk = *positive_facial_basis(pb, c.facial, why);
    const int d = static_cast<int>(Xk.size());
    // Phi_i with Q_E := Delta_D X_i (linear in X)
    std::vector<lmi::KypData> kd;
    for (const MatQ& X : Xk) {
      lmi::KypData k = kyp_data(pb, c.split, X);
      k.R -= to_double(exact_product(pb.structure.delta_D(), X));
      kd.push_back(std::move(k));
    }
    const FrequencyData f = sample(kd);
    OuterResult o = minimise_psi(f, d);
    std::ostringstream sd;
    sd << "structured KYP path with X searched (the facial conditions leave X a " << d
       << "-dimensional set): outer exchange method over g on " << f.theta.size() << " frequencies, " << o.iterations
       << " SDP(s) of " << d + 1 << " unknowns over " << o.active << " active frequencies; max lambda(Phi_g) = "
       << numeric_decimal(o.psi / f.scale, 4) << " (relative; lower bound " << numeric_decimal(o.bound / f.scale, 4) << ")";
    if (o.failure.empty() && o.bound > 0) {  // no g passes the active frequencies: a witness?
      std::string why;
      WeightedWitness ww;
      if (std::optional<Verdict> v = witness_of(pb, Xk, f, o, why, ww)) {
        r.numeric_seconds = since(t0);
        r.solver_detail = sd.str();
        r.proven = v;
        r.weighted_witness = std::move(ww);
        return r;
      }
      sd << "; no certified witness (" << why << ")";
    }
    if (!o.failure.empty() || !(o.psi < 0)) {
      r.numeric_seconds = since(t0);
      r.solver_detail = sd.str();
      r.no_point = !o.failure.empty() ? o.failure
                                      : "no X on the facial set passes the frequency condition of (16)'s first LMI on the "
                                        "grid (max lambda(Phi_g) = " + numeric_decimal(o.psi / f.scale, 4) + " relative at the best g)";
      return r;
    }
    // pull g into the simplex's interior (psi convex: psi((1-s) g + s c) <= (1-s) psi(g) + s psi(c)),
    // keeping psi below half its value, so that X > 0 with room
    Eigen::VectorXd g = o.g;
    const Eigen::VectorXd c0 = Eigen::VectorXd::Constant(d, 1.0 / d);
    for (double s : {0.25, 0.1, 0.03, 0.01}) {
      if (g.minCoeff() >= 0.05 / d) break;
      const Eigen::VectorXd h = (1 - s) * o.g + s * c0;
      double psi = -INFINITY;
      for (const auto& Phi : f.Phi) psi = std::max(psi, lambda_max(combine(Phi, h)));
      if (psi <= 0.5 * o.psi) {
        g = h;
        break;
      }
    }
    // exact g: dyadic, scaled so that min g_i (times the basis' entries) = 1
    std::vector<rational> gq;
    MatQ X = MatQ::Zero(pb.structure.m(), pb.structure.m());
    for (int i = 0; i < d; ++i) {
      gq.push_back(lmi::round_dyadic(g(i) / g.maxCoeff(), 30));
      X += gq.back() * Xk[static_cast<size_t>(i)];
    }
    rational mn = X(0, 0);
    for (Eigen::Index i = 0; i < X.rows(); ++i) mn = std::min(mn, X(i, i));
    if (!(mn > 0)) {
      r.numeric_seconds = since(t0);
      r.solver_detail = sd.str();
      r.no_point = "the outer search's g has a zero entry (X > 0 fails)";
      return r;
    }
    for (auto& q : gq) q /= mn;
    X /= mn;
    RiccatiPoints rp = riccati_points(pb, X, gq, kyp_data(pb, c.split, X));
    r.numeric_seconds = since(t0);
    r.points = std::move(rp.points);
    r.no_point = rp.no_point;
    sd << "; at g = (";
    for (int i = 0; i < d; ++i) sd << (i ? ", " : "") << numeric_decimal(to_real<double>(gq[static_cast<size_t>(i)]), 4);
    sd << ") (min g_i = 1) P11 from the Riccati equation of (16)'s first LMI with Q_E = Delta_D X (lmi/kyp.hpp: "
       << rp.kp.riccati_solves << " DARE solve(s), " << rp.kp.detail << ")";
    r.solver_detail = sd.str();
    return r;
  };
  return p;
}

}  // namespace hapstab::multidof
