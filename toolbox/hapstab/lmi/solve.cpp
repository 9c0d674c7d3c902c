// hapstab/lmi/solve.cpp -- solve() (solve.hpp): the standard form of standard_form.hpp, the
// back-end call, then (5) decide_verdict and the exact certificates, certify_feasible (a
// rounded point) and certify_infeasible (a Farkas ray); the equilibrated retry, the CSDP
// fallback and the built-in IPM first (Options::backend).
#include "hapstab/lmi/solve.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "hapstab/lmi/standard_form.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interrupt.hpp"

namespace hapstab::lmi {

const char* to_string(Feasibility f) {
  return f == Feasibility::feasible ? "feasible" : f == Feasibility::infeasible ? "infeasible" : "undecided";
}
const char* to_string(Certificate c) {
  switch (c) {
    case Certificate::none: return "none";
    case Certificate::feasible_exact: return "feasible (exact)";
    case Certificate::infeasible_exact: return "infeasible (exact)";
    case Certificate::rounding_failed: return "rounding failed the exact check";
    case Certificate::numeric_only: return "numeric only";
  }
  return "none";
}

Eigen::MatrixXd SolveResult::solution(const MatrixVariable& v) const {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(v.rows, v.cols);
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i)
      if (int k = v.at(i, j); k >= 0) M(i, j) = x.at(static_cast<size_t>(k));
  return M;
}

MatQ SolveResult::exact_solution(const MatrixVariable& v) const {
  if (!certified()) throw NumericalError("exact_solution: the solution of variable '" + v.name + "' is not certified");
  MatQ M = MatQ::Zero(v.rows, v.cols);
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i)
      if (int k = v.at(i, j); k >= 0) M(i, j) = x_exact.at(static_cast<size_t>(k));
  return M;
}

namespace {

// A double for a message: 3 significant digits ("-2.1e-09", not to_string's "-0.000000").
std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// ---- (5) verdict ----

// Sets res.verdict from the back-end's answer (and res.status when its "optimal" point violates
// the LMIs). Returns whether a strict-form Farkas certificate is worth trying (the margin is
// within +-strict_threshold).
bool decide_verdict(const Program& prog, const Options& opt, const Reduction& rd, const BackendResult& br,
                    const Eigen::VectorXd& z, SolveResult& res) {
  // A back-end's "optimal" is trusted only if S(y) is PSD to 1e-6 (DIMACS err4): DSDP's
  // penalty method can stop "converged" on an infeasible problem.
  if (br.status == SolveStatus::optimal && !(br.dimacs[3] <= 1e-6)) {
    res.status = SolveStatus::numerical_trouble;
    res.detail += "; the back-end's point violates the LMIs (DIMACS err4 = " + g3(br.dimacs[3]) + ")";
  }
  // The point's own margin: smallest eigenvalue of the strict posed blocks at y (equilibrated,
  // without the t term and the strict_threshold shift). Solver tolerances (~1e-8) must not turn
  // an infeasible strict LMI into "feasible".
  const double actual = strict_margin_at(rd, z);
  const bool minimize = prog.objective_kind() == ObjectiveKind::minimize;
  const bool use_t = rd.use_t;
  bool try_strict_farkas = false;
  if (br.status == SolveStatus::infeasible) res.verdict = Feasibility::infeasible;
  else if (res.status == SolveStatus::optimal) {
    if (!use_t && !(minimize && actual <= 0.5 * opt.strict_threshold)) res.verdict = Feasibility::feasible;
    else if (!use_t) {
      res.verdict = Feasibility::undecided;
      res.detail += "; the strict LMIs hold only with margin " + g3(actual) + " at the solver's point";
    } else if (std::min(res.margin, actual) > opt.strict_threshold) res.verdict = Feasibility::feasible;
    else if (res.margin < -opt.strict_threshold) res.verdict = Feasibility::infeasible;
    else {
      res.verdict = Feasibility::undecided;
      try_strict_farkas = true;
      res.detail += "; margin " + g3(res.margin) + " within +-" + g3(opt.strict_threshold) +
                    ": strictness not decided numerically";
    }
  } else if (res.status == SolveStatus::numerical_trouble && br.y.allFinite() && br.dimacs[3] == 0.0 &&
             (!rd.any_strict || actual > opt.strict_threshold)) {
    // Feasibility needs a feasible point, not optimality: DSDP stopping early (-9, short steps)
    // at a point where every LMI holds has found one (seen on min tr P s.t. A'PA - P + I <= 0:
    // relative gap 4e-5 left). The status stays numerical_trouble: the objective is not optimal.
    res.verdict = Feasibility::feasible;
    res.detail += "; the solver stopped early at a point where every LMI holds: feasible, objective not optimal";
  } else {
    res.verdict = Feasibility::undecided;
  }
  return try_strict_farkas;
}

// ---- exact certificate of a feasible point ----

// Whether every equality and every exact block holds at the exact point xq; else `failed`
// names the first constraint that does not.
bool holds_exactly(const Program& prog, const std::vector<Block>& blocks, const std::vector<rational>& xq,
                   std::string& failed) {
  for (const auto& c : prog.linear()) {
    if (!c.equality) continue;
    MatQ L = exact_value(c.lhs, xq), R = to_rational(c.rhs);
    if (L != R) {
      failed = c.name;
      return false;
    }
  }
  for (const Block& b : blocks) {
    if (!b.exact) continue;
    if (!exact_lmi_holds(b.F, xq, b.strict)) {
      failed = b.name;
      return false;
    }
  }
  return true;
}

// Round z (the scaled y, so the relative grid is uniform), rebuild exactly, check all.
void certify_feasible(const Program& prog, const Reduction& rd, const BackendResult& br, SolveResult& res) {
  res.certificate = Certificate::rounding_failed;
  for (int bits : {20, 30, 40, 53}) {
    std::vector<rational> zq(static_cast<size_t>(rd.af.nz), rational(0));
    for (size_t y = 0; y < rd.ymap.size(); ++y)
      zq[static_cast<size_t>(rd.ymap[y])] =
          round_dyadic(br.y(static_cast<Eigen::Index>(y)), bits) * exact_rational(rd.s(rd.ymap[y]));
    std::vector<rational> xq = exact_point(rd.af, std::move(zq), prog.num_scalars());
    std::string failed;
    if (holds_exactly(prog, rd.blocks, xq, failed)) {
      res.certificate = Certificate::feasible_exact;
      res.rounding_bits = bits;
      res.x_exact = std::move(xq);
      return;
    }
    if (bits == 53) res.detail += "; exact check failed at constraint '" + failed + "'";
  }
}

// ---- exact certificate of infeasibility (a Farkas ray) ----

rational inner(const MatQ& A, const MatQ& B) {
  rational t = 0;
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      if (A(i, j) != 0 && B(i, j) != 0) t += A(i, j) * B(i, j);
  return t;
}

// Exact data of the posed blocks, and the Gram matrix M of the coefficient "vectors"
// (blockwise): M_kl = sum_j <G_jk, G_jl>.
struct FarkasSystem {
  std::vector<MatQ> G0;
  std::vector<std::vector<std::pair<int, MatQ>>> Gk;  // (y index, exact reduced coefficient)
  int K = 0;
  MatQ M;
};

FarkasSystem farkas_data(const Reduction& rd) {
  FarkasSystem fs;
  const size_t J = rd.posed.size();
  fs.G0.resize(J);
  fs.Gk.resize(J);
  for (size_t j = 0; j < J; ++j) {
    const Expr& F = rd.blocks[static_cast<size_t>(rd.posed[j])].F;
    fs.G0[j] = exact_reduced(F, rd.af, -1);
    for (const auto& [k, m] : rd.red[j].G)
      if (rd.zmap[static_cast<size_t>(k)] >= 0) fs.Gk[j].push_back({rd.zmap[static_cast<size_t>(k)], exact_reduced(F, rd.af, k)});
  }
  fs.K = static_cast<int>(rd.ymap.size());
  fs.M = MatQ::Zero(fs.K, fs.K);
  for (size_t j = 0; j < J; ++j)
    for (size_t a = 0; a < fs.Gk[j].size(); ++a)
      for (size_t c = 0; c <= a; ++c) {
        rational v = inner(fs.Gk[j][a].second, fs.Gk[j][c].second);
        fs.M(fs.Gk[j][a].first, fs.Gk[j][c].first) += v;
        if (a != c) fs.M(fs.Gk[j][c].first, fs.Gk[j][a].first) += v;
      }
  return fs;
}

// residuals r_k = sum_j <G_jk, Z_j>
std::vector<rational> ray_residuals(const FarkasSystem& fs, const std::vector<MatQ>& Z) {
  std::vector<rational> r(static_cast<size_t>(fs.K), rational(0));
  for (size_t j = 0; j < Z.size(); ++j)
    for (const auto& [k, G] : fs.Gk[j]) r[static_cast<size_t>(k)] += inner(G, Z[j]);
  return r;
}

// Attempts: the multipliers as returned, then with eigenvalues below tol * max dropped
// (a Farkas ray usually lies on a face of the PSD cone: its tiny eigenvalues are noise that
// the exact projection would turn negative), then shifted by delta I.
struct Attempt { double drop, delta; };

std::vector<MatQ> rounded_ray(const std::vector<Eigen::MatrixXd>& multipliers, double xscale, Attempt at) {
  std::vector<MatQ> Z(multipliers.size());
  for (size_t j = 0; j < Z.size(); ++j) {
    Eigen::MatrixXd Zd = multipliers[j] / xscale;
    Zd = 0.5 * (Zd + Zd.transpose());
    if (at.drop > 0) {
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Zd);
      Eigen::VectorXd l = es.eigenvalues();
      for (Eigen::Index q = 0; q < l.size(); ++q)
        if (l(q) < at.drop) l(q) = 0;
      Zd = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
      Zd = 0.5 * (Zd + Zd.transpose());
    }
    Zd += at.delta * Eigen::MatrixXd::Identity(Zd.rows(), Zd.cols());
    Z[j] = MatQ(Zd.rows(), Zd.cols());
    // absolute grid 2^-30 (the largest multiplier entry is 1): noise below it becomes 0
    for (Eigen::Index a = 0; a < Zd.rows(); ++a)
      for (Eigen::Index c = 0; c <= a; ++c)
        Z[j](a, c) = Z[j](c, a) = exact_rational(std::ldexp(std::nearbyint(std::ldexp(Zd(a, c), 30)), -30));
  }
  return Z;
}

// Z <- Z - sum mu_k G_k with M mu = r (exact; M is a Gram matrix: r lies in its range), then
// the exact check: every Z_j PSD, sum tr(F_j0 Z_j) = obj < 0 (or = 0 with Z != 0 on a strict
// block in strict mode), and the residuals zero.
bool projected_ray_holds(const FarkasSystem& fs, const Reduction& rd, std::vector<MatQ>& Z, bool strict_mode,
                         rational& obj) {
  const int K = fs.K;
  const std::vector<rational> r = ray_residuals(fs, Z);
  // [M | r] in reduced row echelon form by FLINT (fraction-free, multimodular): Gauss-Jordan on
  // Boost rationals spent minutes here (consistency case 2652, K ~ 200: entries of thousands of bits)
  flint::QMat aug(K, K + 1);
  for (int k = 0; k < K; ++k) {
    for (int c = 0; c < K; ++c) flint::set(aug.at(k, c), fs.M(k, c));
    flint::set(aug.at(k, K), r[static_cast<size_t>(k)]);
  }
  flint::QMat R(K, K + 1);
  const long rank = fmpq_mat_rref(R.get(), aug.get());
  std::vector<rational> mu(static_cast<size_t>(K), rational(0));
  for (long i = 0, j = 0; i < rank; ++i) {
    while (j <= K && fmpq_is_zero(R.at(i, j))) ++j;
    if (j >= K) return false;  // r is not in the range of M: no projection (cannot happen for a Gram matrix)
    mu[static_cast<size_t>(j++)] = flint::to_rational(R.at(i, K));
  }
  bool ok = true, strict_nonzero = false;
  obj = 0;
  for (size_t j = 0; j < Z.size() && ok; ++j) {
    for (const auto& [k, G] : fs.Gk[j])
      if (mu[static_cast<size_t>(k)] != 0) Z[j] -= mu[static_cast<size_t>(k)] * G;
    ok = exact_definiteness(Z[j]).psd;
    obj += inner(fs.G0[j], Z[j]);
    if (rd.blocks[static_cast<size_t>(rd.posed[j])].strict && !Z[j].isZero()) strict_nonzero = true;
  }
  if (!ok) return false;
  if (!(obj < 0 || (strict_mode && obj == 0 && strict_nonzero))) return false;
  // re-check the equalities exactly
  bool zero = true;
  for (const auto& v : ray_residuals(fs, Z)) zero &= v == 0;
  return zero;
}

// A Farkas ray can be irrational (A'PA - P + I <= 0 with an unstable real eigenvalue of A:
// every ray is supported on its eigenvector), so no rational rounding passes. A back-end in
// trouble whose ray Z (scaled to max entry 1) is PSD to -1e-9 with sum tr(F_j0 Z_j) = obj < 0
// and residuals r_k = sum tr(F_jk Z_j) proves, in floating point, that no z with
// max |z_k| < R = |obj| / sum |r_k| is feasible (0 <= sum tr(F_j(z) Z_j) = obj + r'z).
// R >= 1e4 is called infeasible, numerically only (as a back-end's own "infeasible" is).
void check_ray_in_floating_point(const Reduction& rd, double xscale, SolveResult& res) {
  const int K = static_cast<int>(rd.ymap.size());
  Eigen::VectorXd rk = Eigen::VectorXd::Zero(K);
  double obj = 0, min_eig = INFINITY;
  for (size_t j = 0; j < rd.red.size(); ++j) {
    Eigen::MatrixXd Zd = res.multipliers[j] / xscale;
    Zd = 0.5 * (Zd + Zd.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Zd, Eigen::EigenvaluesOnly);
    min_eig = std::min(min_eig, es.eigenvalues()(0));
    obj += rd.red[j].G0.cwiseProduct(Zd).sum();
    for (const auto& [k, m] : rd.red[j].G) {
      const int y = rd.zmap[static_cast<size_t>(k)];
      if (y < 0) continue;
      for (int o = 0; o < m.outerSize(); ++o)
        for (SpMat::InnerIterator it(m, o); it; ++it) rk(y) += it.value() * Zd(it.row(), it.col());
    }
  }
  const double R = obj < 0 ? -obj / rk.cwiseAbs().sum() : 0;
  const std::string what = "residual " + g3(rk.cwiseAbs().sum()) + ", min eig " + g3(min_eig) +
                           ", sum tr(F_j0 Z_j) = " + g3(obj);
  if (min_eig >= -1e-9 && obj <= -1e-6 && R >= 1e4) {
    res.verdict = Feasibility::infeasible;
    res.status = SolveStatus::infeasible;
    res.certificate = Certificate::numeric_only;
    res.detail += "; the back-end's Farkas ray holds in floating point (" + what + "): no solution with max |x| < " +
                  g3(R) + ", infeasible numerically only";
  } else {
    res.detail += "; nor in floating point (" + what + ")";
  }
}

// strict mode: Z != 0 on a strict block and sum tr(F_j0 Z_j) <= 0 proves that the STRICT
// system has no solution (homogeneous LMIs such as Lyapunov's have margin exactly 0 when
// infeasible); otherwise sum tr(F_j0 Z_j) < 0 proves that even F_j >= 0 is infeasible.
// `trouble`: the back-end is in numerical trouble; its ray may still pass.
void certify_infeasible(const Reduction& rd, bool strict_mode, bool trouble, SolveResult& res) {
  if (res.verdict == Feasibility::infeasible) res.certificate = Certificate::numeric_only;
  bool aux = false;
  for (int b : rd.posed) aux |= !rd.blocks[static_cast<size_t>(b)].exact;
  if (aux) {
    res.detail += "; Farkas check skipped: a facially reduced block is rounded data";
    return;
  }
  const FarkasSystem fs = farkas_data(rd);
  double xscale = 0;
  for (size_t j = 0; j < rd.posed.size(); ++j) xscale = std::max(xscale, res.multipliers[j].cwiseAbs().maxCoeff());
  if (!(xscale > 0)) {
    res.detail += "; the back-end returned no multipliers";
    return;
  }
  for (Attempt at : {Attempt{0, 0}, Attempt{1e-7, 0}, Attempt{1e-5, 0}, Attempt{0, 1e-7}, Attempt{1e-7, 1e-5},
                     Attempt{1e-7, 1e-3}}) {
    std::vector<MatQ> Z = rounded_ray(res.multipliers, xscale, at);
    rational obj;
    if (!projected_ray_holds(fs, rd, Z, strict_mode, obj)) continue;
    res.certificate = Certificate::infeasible_exact;
    res.verdict = Feasibility::infeasible;
    res.status = SolveStatus::infeasible;
    res.detail += std::string("; Farkas certificate checked exactly") + (obj < 0 ? "" : " (strict form)") +
                  ": sum tr(F_j0 Z_j) = " + to_decimal(obj, 6);
    return;
  }
  res.detail += "; no rounding of the multipliers passed the exact Farkas check";
  if (trouble && !strict_mode) check_ray_in_floating_point(rd, xscale, res);
}

SolveResult inconsistent_equalities(SolveResult res, const std::string& why) {
  res.status = SolveStatus::infeasible;
  res.verdict = Feasibility::infeasible;
  res.certificate = Certificate::infeasible_exact;
  res.detail = why;
  res.margin = std::numeric_limits<double>::quiet_NaN();
  return res;
}

SolveResult unbounded_objective(SolveResult res) {
  res.status = SolveStatus::unbounded;
  res.verdict = Feasibility::undecided;
  res.detail = "the objective depends on a variable that no constraint bounds";
  res.margin = std::numeric_limits<double>::quiet_NaN();
  return res;
}

}  // namespace

// One solve on the data as given (scale = false) or equilibrated: the pipeline of solve.hpp.
SolveResult solve_once(const Program& prog, const Options& opt, bool scale) {
  SolveResult res;
  res.solver = to_string(opt.backend);
  if (prog.num_scalars() == 0) throw InputError("lmi program: no decision variables");
  if (!(opt.strict_threshold > 0)) throw InputError("lmi options: strict_threshold must be positive");

  // ---- (1)-(3): the reduced, equilibrated standard form ----
  Reduction rd;
  rd.blocks = collect_blocks(prog);
  std::string why;
  if (!eliminate(prog, rd.af, why)) return inconsistent_equalities(std::move(res), why);
  if (!reduce_program(prog, rd)) return unbounded_objective(std::move(res));
  equilibrate(rd, scale);
  build_standard_form(prog, opt, rd);

  // ---- (4) back-end ----
  const double csdp_limit = opt.csdp_time_limit > 0 ? opt.csdp_time_limit : 5.0 + 0.02 * rd.sf.m;
  const BackendResult br = solve_standard(rd.sf, opt.backend, csdp_limit);
  const Eigen::VectorXd z = map_back(prog, rd, br, res);

  // ---- (5) verdict and exact certificates ----
  bool try_strict_farkas = decide_verdict(prog, opt, rd, br, z, res);
  if (!opt.certify) return res;
  if (res.status == SolveStatus::numerical_trouble && res.verdict == Feasibility::undecided) try_strict_farkas = false;
  // The exact projection solves a K x K Gram system in mpq whose entries grow to thousands of
  // bits: for an undecided margin (not a numeric infeasibility) it is attempted only for
  // K <= 20 variables; larger programs report the margin and "undecided" (measured: K = 43
  // took minutes).
  if (try_strict_farkas && rd.ymap.size() > 20) {
    try_strict_farkas = false;
    res.detail += "; exact Farkas check skipped (more than 20 variables)";
  }
  if (res.verdict == Feasibility::feasible) {
    certify_feasible(prog, rd, br, res);
    return res;
  }
  // A back-end in numerical trouble (DSDP's "optimal" point that violates the LMIs, its short
  // steps on an infeasible program) may still hold a usable Farkas ray: the exact check
  // decides, so trying costs time only.
  // (the cost bound of the strict check above, except for DSDP's "optimal" at an infeasible point,
  // which was always checked)
  const bool trouble = res.status == SolveStatus::numerical_trouble && res.verdict == Feasibility::undecided &&
                       (rd.ymap.size() <= 20 || br.status == SolveStatus::optimal);
  if (res.verdict == Feasibility::infeasible || try_strict_farkas || trouble)
    certify_infeasible(rd, try_strict_farkas, trouble, res);
  return res;
}

SolveResult solve_scaled(const Program& prog, const Options& opt) {
  if (opt.scale == Scaling::never) return solve_once(prog, opt, false);
  if (opt.scale == Scaling::always) {
    SolveResult r = solve_once(prog, opt, true);
    r.detail += " [equilibrated]";
    return r;
  }
  SolveResult raw = solve_once(prog, opt, false);
  // a CSDP run stopped at its time limit is not retried on equilibrated data (seen: both loop)
  const bool timed_out = raw.detail.find(kCsdpTimedOut) != std::string::npos;
  if (timed_out ||
      (raw.verdict != Feasibility::undecided && raw.status != SolveStatus::numerical_trouble &&
       raw.certificate != Certificate::rounding_failed)) {
    raw.detail += " [data as given]";
    return raw;
  }
  SolveResult eq = solve_once(prog, opt, true);
  if (eq.verdict != Feasibility::undecided && eq.certificate != Certificate::rounding_failed) {
    eq.detail += " [equilibrated; as given: " + std::string(to_string(raw.verdict)) + "]";
    return eq;
  }
  raw.detail += " [data as given; equilibrated retry: " + std::string(to_string(eq.verdict)) + "]";
  return raw;
}

namespace {
SolveResult solve_with_fallback(const Program& prog, const Options& opt) {
  SolveResult r = solve_scaled(prog, opt);
  if (!opt.fallback || opt.backend != Backend::dsdp) return r;
  if (r.verdict != Feasibility::undecided && r.status != SolveStatus::numerical_trouble) return r;
  Options o = opt;
  o.backend = Backend::csdp;
  SolveResult c = solve_scaled(prog, o);
  if (c.verdict == Feasibility::undecided && c.status == SolveStatus::numerical_trouble) {
    r.detail += "; CSDP fallback also undecided (" + c.detail + ")";
    return r;
  }
  c.solver = "CSDP (DSDP fallback)";
  c.detail = "DSDP: " + r.detail + "; CSDP: " + c.detail;
  return c;
}
}  // namespace

SolveResult solve(const Program& prog, const Options& opt) {
  interruption_point();  // a caller's stop request, before each solve (numeric/interrupt.hpp)
  if (!(opt.csdp_time_limit >= 0) || !std::isfinite(opt.csdp_time_limit))
    throw InputError("lmi options: csdp_time_limit must be a finite number of seconds >= 0 (0 = automatic)");
  if (opt.backend != Backend::automatic) return solve_with_fallback(prog, opt);
  Options o = opt;
  std::string note;
  int rows = 0;
  for (const auto& c : prog.lmis()) rows += c.F.rows();
  if (opt.certify && rows <= opt.ipm_max_rows) {
    // one attempt on the data as given (equilibration is DSDP's retry, not the IPM's)
    o.backend = Backend::ipm;
    if (o.scale == Scaling::automatic) o.scale = Scaling::never;
    SolveResult r = solve_scaled(prog, o);
    // kept only when certified and finished (a certified point where the IPM stopped early has
    // a non-optimal objective: DSDP then solves)
    if ((r.certificate == Certificate::feasible_exact || r.certificate == Certificate::infeasible_exact) &&
        r.status != SolveStatus::numerical_trouble)
      return r;
    note = "hapstab IPM first: " + std::string(to_string(r.verdict)) + ", " +
           (r.certified() ? "certified but not finished" : "not certified") + " (" + r.detail + "); ";
    o.scale = opt.scale;
  }
  o.backend = Backend::dsdp;
  SolveResult r = solve_with_fallback(prog, o);
  r.detail = note + r.detail;
  return r;
}

}  // namespace hapstab::lmi
