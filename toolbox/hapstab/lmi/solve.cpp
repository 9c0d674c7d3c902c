// hapstab/lmi/solve.cpp -- exact equality elimination, equilibration, back-end call, verdict,
// exact certificates (see solve.hpp).
#include "hapstab/lmi/solve.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

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

Eigen::MatrixXd Result::GetSolution(const MatrixVariable& v) const {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(v.rows, v.cols);
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i)
      if (int k = v.at(i, j); k >= 0) M(i, j) = x.at(static_cast<size_t>(k));
  return M;
}

MatQ Result::GetExactSolution(const MatrixVariable& v) const {
  if (!certified()) throw NumericalError("GetExactSolution: the solution of variable '" + v.name + "' is not certified");
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

struct Block {
  std::string name;
  Expr F;          ///< original-space expression (symmetrised on use)
  bool strict;
  bool posed;
  bool exact;      ///< part of the exact certificate
  int lmi = -1;    ///< index into prog.lmis(), -1 for a linear inequality entry
};

// x = x0 + N z, exact; `identity` when there are no equalities (N = I, x0 = 0).
struct Affine {
  bool identity = true;
  int nz = 0;
  std::vector<rational> x0;
  MatQ N;
  Eigen::VectorXd x0d;
  Eigen::MatrixXd Nd;
};

// Gauss-Jordan elimination of the linear equalities in exact arithmetic. Returns false when
// they are inconsistent (sets `why`).
bool eliminate(const Program& prog, Affine& af, std::string& why) {
  const int n = prog.num_scalars();
  std::vector<std::vector<rational>> rows;
  std::vector<std::string> names;
  for (const auto& c : prog.linear()) {
    if (!c.equality) continue;
    for (int j = 0; j < c.lhs.cols(); ++j)
      for (int i = 0; i < c.lhs.rows(); ++i) {
        std::vector<rational> r(static_cast<size_t>(n + 1));
        bool any = false;
        for (const auto& [k, m] : c.lhs.terms()) {
          double v = m.coeff(i, j);
          if (v != 0.0) {
            r[static_cast<size_t>(k)] = exact_rational(v);
            any = true;
          }
        }
        r[static_cast<size_t>(n)] = exact_rational(c.rhs(i, j)) - exact_rational(c.lhs.constant()(i, j));
        if (!any && r[static_cast<size_t>(n)] == 0) continue;
        rows.push_back(std::move(r));
        names.push_back(c.name);
      }
  }
  af.identity = rows.empty();
  if (af.identity) {
    af.nz = n;
    return true;
  }
  std::vector<int> pivcol;
  size_t prow = 0;
  for (int col = 0; col < n && prow < rows.size(); ++col) {
    size_t p = prow;
    while (p < rows.size() && rows[p][static_cast<size_t>(col)] == 0) ++p;
    if (p == rows.size()) continue;
    std::swap(rows[p], rows[prow]);
    std::swap(names[p], names[prow]);
    const rational inv = 1 / rows[prow][static_cast<size_t>(col)];
    for (auto& v : rows[prow]) v *= inv;
    for (size_t r = 0; r < rows.size(); ++r) {
      if (r == prow || rows[r][static_cast<size_t>(col)] == 0) continue;
      const rational f = rows[r][static_cast<size_t>(col)];
      for (int c = col; c <= n; ++c) rows[r][static_cast<size_t>(c)] -= f * rows[prow][static_cast<size_t>(c)];
    }
    pivcol.push_back(col);
    ++prow;
  }
  for (size_t r = prow; r < rows.size(); ++r)
    if (rows[r][static_cast<size_t>(n)] != 0) {
      why = "the linear equalities are inconsistent (exact elimination; first failing: '" + names[r] + "')";
      return false;
    }
  std::vector<int> is_piv(static_cast<size_t>(n), -1);
  for (size_t r = 0; r < pivcol.size(); ++r) is_piv[static_cast<size_t>(pivcol[r])] = static_cast<int>(r);
  std::vector<int> freecols;
  for (int c = 0; c < n; ++c)
    if (is_piv[static_cast<size_t>(c)] < 0) freecols.push_back(c);
  af.nz = static_cast<int>(freecols.size());
  af.x0.assign(static_cast<size_t>(n), rational(0));
  af.N = MatQ::Zero(n, af.nz);
  for (size_t r = 0; r < pivcol.size(); ++r) af.x0[static_cast<size_t>(pivcol[r])] = rows[r][static_cast<size_t>(n)];
  for (int f = 0; f < af.nz; ++f) {
    const int c = freecols[static_cast<size_t>(f)];
    af.N(c, f) = 1;
    for (size_t r = 0; r < pivcol.size(); ++r) af.N(pivcol[r], f) = -rows[r][static_cast<size_t>(c)];
  }
  af.x0d.resize(n);
  af.Nd.resize(n, af.nz);
  for (int i = 0; i < n; ++i) {
    af.x0d(i) = to_real<double>(af.x0[static_cast<size_t>(i)]);
    for (int f = 0; f < af.nz; ++f) af.Nd(i, f) = to_real<double>(af.N(i, f));
  }
  return true;
}

// Reduced block data in double: G0 + sum_k z_k G_k (symmetrised). The coefficients stay sparse:
// at m = 32 DOF a dense copy per variable and block is hundreds of MB.
struct Reduced {
  Eigen::MatrixXd G0;
  std::map<int, SpMat> G;
  Eigen::MatrixXd basis;                       ///< G[k] = sum over factors[k] of s b_u b_v^T
  std::map<int, std::vector<Factor>> factors;  ///< (symmetrised; see LowRank in program.hpp)
};
SpMat sym_sparse(const SpMat& M) {
  SpMat S = 0.5 * (M + SpMat(M.transpose()));
  S.prune([](Eigen::Index, Eigen::Index, double v) { return v != 0.0; });
  S.makeCompressed();
  return S;
}
double max_abs(const SpMat& m) {
  double v = 0;
  for (Eigen::Index i = 0; i < m.nonZeros(); ++i) v = std::max(v, std::abs(m.valuePtr()[i]));
  return v;
}
void add_to(Eigen::MatrixXd& D, double c, const SpMat& m) {
  for (int o = 0; o < m.outerSize(); ++o)
    for (SpMat::InnerIterator it(m, o); it; ++it) D(it.row(), it.col()) += c * it.value();
}
// d_r d_c m_rc (D diagonal), sparse
SpMat congruence(const SpMat& m, const Eigen::VectorXd& d, double s) {
  SpMat r = m;
  for (int o = 0; o < r.outerSize(); ++o)
    for (SpMat::InnerIterator it(r, o); it; ++it) it.valueRef() = s * d(it.row()) * it.value() * d(it.col());
  return r;
}
// The low-rank form of the reduced, symmetrised terms: one basis [L, R]; each piece s u v^T
// of F_i becomes s/2 (u v^T + v u^T), weighted by the elimination's N_ik.
void reduce_low_rank(const Expr& F, const Affine& af, Reduced& r) {
  const LowRank& lr = F.low_rank();
  const int p = static_cast<int>(lr.L.cols());
  r.basis.resize(F.rows(), lr.L.cols() + lr.R.cols());
  r.basis << lr.L, lr.R;
  auto add = [&](std::vector<Factor>& out, const std::vector<Factor>& f, double c) {
    for (const Factor& x : f) {
      out.push_back({x.u, p + x.v, 0.5 * c * x.s});
      out.push_back({p + x.v, x.u, 0.5 * c * x.s});
    }
  };
  if (af.identity) {
    for (const auto& [k, f] : lr.factors) add(r.factors[k], f, 1.0);
    return;
  }
  for (const auto& [k, m] : r.G) {
    std::vector<Factor> out;
    bool ok = true;
    for (const auto& [i, mi] : F.terms()) {
      const double c = af.Nd(i, k);
      if (c == 0.0) continue;
      auto it = lr.factors.find(i);
      if (it == lr.factors.end()) {
        ok = false;
        break;
      }
      add(out, it->second, c);
    }
    if (ok) r.factors.emplace(k, std::move(out));
  }
}

Reduced reduce(const Expr& F, const Affine& af) {
  Reduced r;
  auto sym = [](const Eigen::MatrixXd& M) -> Eigen::MatrixXd { return 0.5 * (M + M.transpose()); };
  if (af.identity) {
    r.G0 = sym(F.constant());
    for (const auto& [k, m] : F.terms()) r.G[k] = sym_sparse(m);
    reduce_low_rank(F, af, r);
    return r;
  }
  Eigen::MatrixXd G0 = F.constant();
  for (const auto& [k, m] : F.terms()) {
    if (af.x0d(k) != 0.0) add_to(G0, af.x0d(k), m);
    for (int f = 0; f < af.nz; ++f) {
      const double c = af.Nd(k, f);
      if (c == 0.0) continue;
      auto it = r.G.find(f);
      if (it == r.G.end()) r.G[f] = c * m;
      else it->second += c * m;
    }
  }
  r.G0 = sym(G0);
  for (auto& [k, m] : r.G) m = sym_sparse(m);
  reduce_low_rank(F, af, r);
  return r;
}

// Exact reduced coefficient (for the Farkas check): G_k = sum_i N_ik F_i, G_0 = F_0 + sum x0_i F_i.
MatQ exact_reduced(const Expr& F, const Affine& af, int k /* -1: constant */) {
  const int n = F.rows();
  MatQ G = MatQ::Zero(n, n);
  auto addsp = [&](const SpMat& m, const rational& c) {
    for (int o = 0; o < m.outerSize(); ++o)
      for (SpMat::InnerIterator it(m, o); it; ++it) G(it.row(), it.col()) += c * exact_rational(it.value());
  };
  if (k < 0) {
    G = to_rational(F.constant());
    if (!af.identity)
      for (const auto& [i, m] : F.terms())
        if (af.x0[static_cast<size_t>(i)] != 0) addsp(m, af.x0[static_cast<size_t>(i)]);
  } else if (af.identity) {
    auto it = F.terms().find(k);
    if (it != F.terms().end()) addsp(it->second, rational(1));
  } else {
    for (const auto& [i, m] : F.terms())
      if (af.N(i, k) != 0) addsp(m, af.N(i, k));
  }
  MatQ S = G;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) S(i, j) = (G(i, j) + G(j, i)) / 2;
  return S;
}

double pow2_near(double v) {  // 2^round(log2 v), v > 0
  return std::ldexp(1.0, static_cast<int>(std::lround(std::log2(v))));
}

}  // namespace

Result solve_once(const Program& prog, const Options& opt, bool scale) {
  Result res;
  res.solver = to_string(opt.backend);
  const int n = prog.num_scalars();
  if (n == 0) throw InputError("lmi program: no decision variables");
  if (!(opt.strict_threshold > 0)) throw InputError("lmi options: strict_threshold must be positive");

  // ---- blocks: LMIs, then the entries of linear inequalities ----
  std::vector<Block> blocks;
  for (size_t i = 0; i < prog.lmis().size(); ++i) {
    const auto& c = prog.lmis()[i];
    blocks.push_back({c.name, c.F, c.strictness == Strictness::strict, c.posed, !c.auxiliary, static_cast<int>(i)});
  }
  for (const auto& c : prog.linear()) {
    if (c.equality) continue;
    for (int j = 0; j < c.lhs.cols(); ++j)
      for (int i = 0; i < c.lhs.rows(); ++i) {
        Eigen::MatrixXd ei = Eigen::MatrixXd::Zero(1, c.lhs.rows()), ej = Eigen::MatrixXd::Zero(c.lhs.cols(), 1);
        ei(0, i) = 1;
        ej(0 + j, 0) = 1;
        Expr e = ei * c.lhs * ej - Expr::Scalar(c.rhs(i, j));
        blocks.push_back({c.name + "(" + std::to_string(i) + "," + std::to_string(j) + ")", e, false, true, true, -1});
      }
  }
  bool any_posed = false;
  for (const auto& b : blocks) any_posed |= b.posed;
  if (!any_posed) throw InputError("lmi program: no LMI or inequality constraint to solve");

  // ---- (1) exact elimination of equalities ----
  Affine af;
  std::string why;
  if (!eliminate(prog, af, why)) {
    res.status = SolveStatus::infeasible;
    res.verdict = Feasibility::infeasible;
    res.certificate = Certificate::infeasible_exact;
    res.detail = why;
    res.margin = std::numeric_limits<double>::quiet_NaN();
    return res;
  }

  // ---- (2)+(3) reduced, equilibrated standard form ----
  std::vector<int> posed;  // indices into blocks
  std::vector<Reduced> red;
  for (size_t b = 0; b < blocks.size(); ++b)
    if (blocks[b].posed) {
      posed.push_back(static_cast<int>(b));
      red.push_back(reduce(blocks[b].F, af));
    }
  Eigen::VectorXd cz = Eigen::VectorXd::Zero(af.nz);
  double cconst = 0;
  if (prog.objective_kind() == ObjectiveKind::minimize) {
    const Expr& c = prog.objective();
    Eigen::VectorXd cx = Eigen::VectorXd::Zero(n);
    for (const auto& [k, m] : c.terms()) cx(k) = m.coeff(0, 0);
    cconst = c.constant()(0, 0);
    if (af.identity) cz = cx;
    else {
      cz = af.Nd.transpose() * cx;
      cconst += cx.dot(af.x0d);
    }
  }
  // variables used by posed blocks
  std::vector<int> used(static_cast<size_t>(af.nz), 0);
  for (const auto& r : red)
    for (const auto& [k, m] : r.G)
      if (max_abs(m) > 0) used[static_cast<size_t>(k)] = 1;
  for (int k = 0; k < af.nz; ++k)
    if (!used[static_cast<size_t>(k)] && cz(k) != 0.0) {
      res.status = SolveStatus::unbounded;
      res.verdict = Feasibility::undecided;
      res.detail = "the objective depends on a variable that no constraint bounds";
      res.margin = std::numeric_limits<double>::quiet_NaN();
      return res;
    }
  std::vector<int> ymap;  // y index -> z index
  std::vector<int> zmap(static_cast<size_t>(af.nz), -1);
  for (int k = 0; k < af.nz; ++k)
    if (used[static_cast<size_t>(k)]) {
      zmap[static_cast<size_t>(k)] = static_cast<int>(ymap.size());
      ymap.push_back(k);
    }
  // Equilibration (Ruiz-type, 20 sweeps): block rows d_r and variables s_k alternately so that
  // the largest |d_r d_c s_k G_jk(r,c)| in every row and for every variable is ~1 (constants
  // G_j0 take part with weight 1). Finally every d_r, s_k is rounded to a power of two.
  std::vector<Eigen::VectorXd> D(red.size());
  for (size_t j = 0; j < red.size(); ++j) D[j] = Eigen::VectorXd::Ones(red[j].G0.rows());
  Eigen::VectorXd s = Eigen::VectorXd::Ones(af.nz);
  if (scale) {
    for (int sweep = 0; sweep < 20; ++sweep) {
      for (size_t j = 0; j < red.size(); ++j) {
        const auto nb = red[j].G0.rows();
        Eigen::VectorXd rho = (D[j].asDiagonal() * red[j].G0.cwiseAbs() * D[j].asDiagonal()).rowwise().maxCoeff();
        for (const auto& [k, m] : red[j].G)
          for (int o = 0; o < m.outerSize(); ++o)
            for (SpMat::InnerIterator it(m, o); it; ++it)
              rho(it.row()) = std::max(rho(it.row()), s(k) * std::abs(D[j](it.row()) * it.value() * D[j](it.col())));
        for (Eigen::Index r = 0; r < nb; ++r)
          if (rho(r) > 0) D[j](r) /= std::sqrt(rho(r));
      }
      Eigen::VectorXd sig = Eigen::VectorXd::Zero(af.nz);
      for (size_t j = 0; j < red.size(); ++j)
        for (const auto& [k, m] : red[j].G)
          sig(k) = std::max(sig(k), max_abs(congruence(m, D[j], s(k))));
      for (int k = 0; k < af.nz; ++k)
        if (sig(k) > 0) s(k) /= std::sqrt(sig(k));
    }
    for (auto& d : D)
      for (Eigen::Index r = 0; r < d.size(); ++r) d(r) = pow2_near(d(r));
    for (int k = 0; k < af.nz; ++k) s(k) = pow2_near(s(k));
  }
  bool any_strict = false;
  for (int b : posed) any_strict |= blocks[static_cast<size_t>(b)].strict;
  const bool use_t = prog.objective_kind() == ObjectiveKind::margin && any_strict;
  StandardForm sf;
  sf.m = static_cast<int>(ymap.size()) + (use_t ? 1 : 0);
  const int it_ = use_t ? sf.m - 1 : -1;
  if (sf.m == 0) throw InputError("lmi program: no decision variable appears in a posed constraint");
  sf.b = Eigen::VectorXd::Zero(sf.m);
  if (use_t) sf.b(it_) = 1.0;
  if (prog.objective_kind() == ObjectiveKind::minimize)
    for (size_t y = 0; y < ymap.size(); ++y) sf.b(static_cast<Eigen::Index>(y)) = -s(ymap[y]) * cz(ymap[y]);
  for (size_t j = 0; j < red.size(); ++j) {
    const bool strict = blocks[static_cast<size_t>(posed[j])].strict;
    SdpBlock B;
    const auto Dj = D[j].asDiagonal();
    B.C = Dj * red[j].G0 * Dj;
    if (strict && prog.objective_kind() == ObjectiveKind::minimize)
      B.C -= opt.strict_threshold * Eigen::MatrixXd::Identity(B.C.rows(), B.C.cols());
    B.basis = Dj * red[j].basis;
    for (const auto& [k, m] : red[j].G) {
      if (zmap[static_cast<size_t>(k)] < 0) continue;
      SpMat A = congruence(m, D[j], s(k));  // exact: powers of two
      if (max_abs(A) == 0) continue;
      std::vector<Factor> f;
      if (auto it = red[j].factors.find(k); it != red[j].factors.end()) {
        f = it->second;
        for (Factor& x : f) x.s *= s(k);
      }
      B.terms.push_back({zmap[static_cast<size_t>(k)], std::move(A), std::move(f)});
    }
    if (strict && use_t) {
      SpMat I(B.C.rows(), B.C.cols());
      I.setIdentity();
      B.terms.push_back({it_, -I});
    }
    sf.blocks.push_back(std::move(B));
  }
  if (use_t) {
    SdpBlock cap;
    cap.C = Eigen::MatrixXd::Constant(1, 1, prog.margin_cap());
    SpMat one(1, 1);
    one.insert(0, 0) = -1.0;
    cap.terms.push_back({it_, one});
    sf.blocks.push_back(std::move(cap));
  }

  // ---- (4) back-end ----
  const double csdp_limit = opt.csdp_time_limit > 0 ? opt.csdp_time_limit : 5.0 + 0.02 * sf.m;
  BackendResult br = solve_standard(sf, opt.backend, csdp_limit);
  res.status = br.status;
  res.detail = br.detail;
  res.dimacs = br.dimacs;
  res.iterations = br.iterations;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(af.nz);
  for (size_t y = 0; y < ymap.size(); ++y) z(ymap[y]) = s(ymap[y]) * br.y(static_cast<Eigen::Index>(y));
  Eigen::VectorXd xd = af.identity ? z : Eigen::VectorXd(af.x0d + af.Nd * z);
  res.x.assign(xd.data(), xd.data() + n);
  res.margin = use_t ? br.y(it_) : std::numeric_limits<double>::quiet_NaN();
  res.objective = cconst + cz.dot(z);
  for (const auto& c : prog.lmis()) {
    Eigen::MatrixXd F = c.F.value(res.x);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (F + F.transpose()), Eigen::EigenvaluesOnly);
    res.min_eigenvalue.push_back(es.eigenvalues()(0));
  }
  for (size_t j = 0; j < red.size(); ++j) {
    const auto Dj = D[j].asDiagonal();
    res.multipliers.push_back(Dj * br.X[j] * Dj);
  }

  // ---- (5) verdict ----
  // A back-end's "optimal" is trusted only if S(y) is PSD to 1e-6 (DIMACS err4): DSDP's
  // penalty method can stop "converged" on an infeasible problem.
  if (br.status == SolveStatus::optimal && !(br.dimacs[3] <= 1e-6)) {
    res.status = SolveStatus::numerical_trouble;
    res.detail += "; the back-end's point violates the LMIs (DIMACS err4 = " + g3(br.dimacs[3]) + ")";
  }
  // The point's own margin: smallest eigenvalue of the strict posed blocks at y (equilibrated,
  // without the t term and the strict_threshold shift). Solver tolerances (~1e-8) must not turn
  // an infeasible strict LMI into "feasible".
  double actual = INFINITY;
  for (size_t j = 0; j < red.size(); ++j) {
    if (!blocks[static_cast<size_t>(posed[j])].strict) continue;
    const auto Dj = D[j].asDiagonal();
    Eigen::MatrixXd S = Dj * red[j].G0 * Dj;
    for (const auto& [k, m] : red[j].G)
      if (zmap[static_cast<size_t>(k)] >= 0) add_to(S, z(k), congruence(m, D[j], 1.0));
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
    actual = std::min(actual, es.eigenvalues()(0));
  }
  const bool minimize = prog.objective_kind() == ObjectiveKind::minimize;
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
             (!any_strict || actual > opt.strict_threshold)) {
    // Feasibility needs a feasible point, not optimality: DSDP stopping early (-9, short steps)
    // at a point where every LMI holds has found one (seen on min tr P s.t. A'PA - P + I <= 0:
    // relative gap 4e-5 left). The status stays numerical_trouble: the objective is not optimal.
    res.verdict = Feasibility::feasible;
    res.detail += "; the solver stopped early at a point where every LMI holds: feasible, objective not optimal";
  } else {
    res.verdict = Feasibility::undecided;
  }
  if (!opt.certify) return res;
  if (res.status == SolveStatus::numerical_trouble && res.verdict == Feasibility::undecided) try_strict_farkas = false;
  // The exact projection solves a K x K Gram system in mpq whose entries grow to thousands of
  // bits: for an undecided margin (not a numeric infeasibility) it is attempted only for
  // K <= 20 variables; larger programs report the margin and "undecided" (measured: K = 43
  // took minutes).
  if (try_strict_farkas && ymap.size() > 20) {
    try_strict_farkas = false;
    res.detail += "; exact Farkas check skipped (more than 20 variables)";
  }

  if (res.verdict == Feasibility::feasible) {
    // Round z (the scaled y, so the relative grid is uniform), rebuild exactly, check all.
    res.certificate = Certificate::rounding_failed;
    for (int bits : {20, 30, 40, 53}) {
      std::vector<rational> zq(static_cast<size_t>(af.nz), rational(0));
      for (size_t y = 0; y < ymap.size(); ++y)
        zq[static_cast<size_t>(ymap[y])] = round_dyadic(br.y(static_cast<Eigen::Index>(y)), bits) * exact_rational(s(ymap[y]));
      std::vector<rational> xq(static_cast<size_t>(n));
      if (af.identity) xq = zq;
      else
        for (int i = 0; i < n; ++i) {
          rational v = af.x0[static_cast<size_t>(i)];
          for (int f = 0; f < af.nz; ++f)
            if (af.N(i, f) != 0 && zq[static_cast<size_t>(f)] != 0) v += af.N(i, f) * zq[static_cast<size_t>(f)];
          xq[static_cast<size_t>(i)] = v;
        }
      bool ok = true;
      std::string failed;
      for (const auto& c : prog.linear()) {
        if (!c.equality) continue;
        MatQ L = exact_value(c.lhs, xq), R = to_rational(c.rhs);
        if (L != R) {
          ok = false;
          failed = c.name;
          break;
        }
      }
      for (size_t b = 0; b < blocks.size() && ok; ++b) {
        if (!blocks[b].exact) continue;
        const bool pass = exact_lmi_holds(blocks[b].F, xq, blocks[b].strict);
        if (!pass) {
          ok = false;
          failed = blocks[b].name;
        }
      }
      if (ok) {
        res.certificate = Certificate::feasible_exact;
        res.rounding_bits = bits;
        res.x_exact = std::move(xq);
        break;
      }
      if (bits == 53) res.detail += "; exact check failed at constraint '" + failed + "'";
    }
    return res;
  }

  // A back-end in numerical trouble (DSDP's "optimal" point that violates the LMIs, its short
  // steps on an infeasible program) may still hold a usable Farkas ray: the exact check below
  // decides, so trying costs time only.
  // (the cost bound of the strict check above, except for DSDP's "optimal" at an infeasible point,
  // which was always checked)
  const bool trouble = res.status == SolveStatus::numerical_trouble && res.verdict == Feasibility::undecided &&
                       (ymap.size() <= 20 || br.status == SolveStatus::optimal);
  if (res.verdict == Feasibility::infeasible || try_strict_farkas || trouble) {
    // strict mode: Z != 0 on a strict block and sum tr(F_j0 Z_j) <= 0 proves that the STRICT
    // system has no solution (homogeneous LMIs such as Lyapunov's have margin exactly 0 when
    // infeasible); otherwise sum tr(F_j0 Z_j) < 0 proves that even F_j >= 0 is infeasible.
    const bool strict_mode = try_strict_farkas;
    if (res.verdict == Feasibility::infeasible) res.certificate = Certificate::numeric_only;
    bool aux = false;
    for (int b : posed) aux |= !blocks[static_cast<size_t>(b)].exact;
    if (aux) {
      res.detail += "; Farkas check skipped: a facially reduced block is rounded data";
      return res;
    }
    // Exact data of the posed blocks.
    const size_t J = posed.size();
    std::vector<MatQ> G0(J);
    std::vector<std::vector<std::pair<int, MatQ>>> Gk(J);  // (y index, exact reduced coefficient)
    for (size_t j = 0; j < J; ++j) {
      const Expr& F = blocks[static_cast<size_t>(posed[j])].F;
      G0[j] = exact_reduced(F, af, -1);
      for (const auto& [k, m] : red[j].G)
        if (zmap[static_cast<size_t>(k)] >= 0) Gk[j].push_back({zmap[static_cast<size_t>(k)], exact_reduced(F, af, k)});
    }
    const int K = static_cast<int>(ymap.size());
    auto inner = [](const MatQ& A, const MatQ& B) {
      rational t = 0;
      for (Eigen::Index i = 0; i < A.rows(); ++i)
        for (Eigen::Index j = 0; j < A.cols(); ++j)
          if (A(i, j) != 0 && B(i, j) != 0) t += A(i, j) * B(i, j);
      return t;
    };
    // Gram matrix of the coefficient "vectors" (blockwise), exact.
    MatQ M = MatQ::Zero(K, K);
    for (size_t j = 0; j < J; ++j)
      for (size_t a = 0; a < Gk[j].size(); ++a)
        for (size_t c = 0; c <= a; ++c) {
          rational v = inner(Gk[j][a].second, Gk[j][c].second);
          M(Gk[j][a].first, Gk[j][c].first) += v;
          if (a != c) M(Gk[j][c].first, Gk[j][a].first) += v;
        }
    double xscale = 0;
    for (size_t j = 0; j < J; ++j) xscale = std::max(xscale, res.multipliers[j].cwiseAbs().maxCoeff());
    if (!(xscale > 0)) {
      res.detail += "; the back-end returned no multipliers";
      return res;
    }
    // Attempts: the multipliers as returned, then with eigenvalues below tol * max dropped
    // (a Farkas ray usually lies on a face of the PSD cone: its tiny eigenvalues are noise that
    // the exact projection would turn negative), then shifted by delta I.
    struct Attempt { double drop, delta; };
    for (Attempt at : {Attempt{0, 0}, Attempt{1e-7, 0}, Attempt{1e-5, 0}, Attempt{0, 1e-7}, Attempt{1e-7, 1e-5},
                       Attempt{1e-7, 1e-3}}) {
      std::vector<MatQ> Z(J);
      for (size_t j = 0; j < J; ++j) {
        Eigen::MatrixXd Zd = res.multipliers[j] / xscale;
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
      // residuals r_k = sum_j <G_jk, Z_j>, then Z <- Z - sum mu_k G_k with M mu = r.
      std::vector<rational> r(static_cast<size_t>(K), rational(0));
      for (size_t j = 0; j < J; ++j)
        for (const auto& [k, G] : Gk[j]) r[static_cast<size_t>(k)] += inner(G, Z[j]);
      // exact Gauss-Jordan on [M | r] (M is a Gram matrix: r lies in its range)
      MatQ Aug(K, K + 1);
      Aug.leftCols(K) = M;
      for (int k = 0; k < K; ++k) Aug(k, K) = r[static_cast<size_t>(k)];
      std::vector<int> piv;
      int pr = 0;
      for (int col = 0; col < K && pr < K; ++col) {
        int p = pr;
        while (p < K && Aug(p, col) == 0) ++p;
        if (p == K) continue;
        Aug.row(p).swap(Aug.row(pr));
        rational inv = 1 / Aug(pr, col);
        for (int c = 0; c <= K; ++c) Aug(pr, c) *= inv;
        for (int q = 0; q < K; ++q)
          if (q != pr && Aug(q, col) != 0) {
            rational f = Aug(q, col);
            for (int c = 0; c <= K; ++c) Aug(q, c) -= f * Aug(pr, c);
          }
        piv.push_back(col);
        ++pr;
      }
      std::vector<rational> mu(static_cast<size_t>(K), rational(0));
      for (int q = 0; q < pr; ++q) mu[static_cast<size_t>(piv[static_cast<size_t>(q)])] = Aug(q, K);
      bool ok = true, strict_nonzero = false;
      rational obj = 0;
      for (size_t j = 0; j < J && ok; ++j) {
        for (const auto& [k, G] : Gk[j])
          if (mu[static_cast<size_t>(k)] != 0) Z[j] -= mu[static_cast<size_t>(k)] * G;
        ok = exact_definiteness(Z[j]).psd;
        obj += inner(G0[j], Z[j]);
        if (blocks[static_cast<size_t>(posed[j])].strict && !Z[j].isZero()) strict_nonzero = true;
      }
      if (!ok) continue;
      if (!(obj < 0 || (strict_mode && obj == 0 && strict_nonzero))) continue;
      // re-check the equalities exactly
      std::vector<rational> rr(static_cast<size_t>(K), rational(0));
      for (size_t j = 0; j < J; ++j)
        for (const auto& [k, G] : Gk[j]) rr[static_cast<size_t>(k)] += inner(G, Z[j]);
      bool zero = true;
      for (const auto& v : rr) zero &= v == 0;
      if (!zero) continue;
      res.certificate = Certificate::infeasible_exact;
      res.verdict = Feasibility::infeasible;
      res.status = SolveStatus::infeasible;
      res.detail += std::string("; Farkas certificate checked exactly") + (obj < 0 ? "" : " (strict form)") +
                    ": sum tr(F_j0 Z_j) = " + to_decimal(obj, 6);
      return res;
    }
    res.detail += "; no rounding of the multipliers passed the exact Farkas check";
    // A Farkas ray can be irrational (A'PA - P + I <= 0 with an unstable real eigenvalue of A:
    // every ray is supported on its eigenvector), so no rational rounding passes. A back-end in
    // trouble whose ray Z (scaled to max entry 1) is PSD to -1e-9 with sum tr(F_j0 Z_j) = obj < 0
    // and residuals r_k = sum tr(F_jk Z_j) proves, in floating point, that no z with
    // max |z_k| < R = |obj| / sum |r_k| is feasible (0 <= sum tr(F_j(z) Z_j) = obj + r'z).
    // R >= 1e4 is called infeasible, numerically only (as a back-end's own "infeasible" is).
    if (trouble && !strict_mode) {
      Eigen::VectorXd rk = Eigen::VectorXd::Zero(K);
      double obj = 0, min_eig = INFINITY;
      for (size_t j = 0; j < J; ++j) {
        Eigen::MatrixXd Zd = res.multipliers[j] / xscale;
        Zd = 0.5 * (Zd + Zd.transpose());
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Zd, Eigen::EigenvaluesOnly);
        min_eig = std::min(min_eig, es.eigenvalues()(0));
        obj += red[j].G0.cwiseProduct(Zd).sum();
        for (const auto& [k, m] : red[j].G) {
          const int y = zmap[static_cast<size_t>(k)];
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
  }
  return res;
}

Result solve_scaled(const Program& prog, const Options& opt) {
  if (opt.scale == Scaling::never) return solve_once(prog, opt, false);
  if (opt.scale == Scaling::always) {
    Result r = solve_once(prog, opt, true);
    r.detail += " [equilibrated]";
    return r;
  }
  Result raw = solve_once(prog, opt, false);
  // a CSDP run stopped at its time limit is not retried on equilibrated data (seen: both loop)
  const bool timed_out = raw.detail.find(kCsdpTimedOut) != std::string::npos;
  if (timed_out ||
      (raw.verdict != Feasibility::undecided && raw.status != SolveStatus::numerical_trouble &&
       raw.certificate != Certificate::rounding_failed)) {
    raw.detail += " [data as given]";
    return raw;
  }
  Result eq = solve_once(prog, opt, true);
  if (eq.verdict != Feasibility::undecided && eq.certificate != Certificate::rounding_failed) {
    eq.detail += " [equilibrated; as given: " + std::string(to_string(raw.verdict)) + "]";
    return eq;
  }
  raw.detail += " [data as given; equilibrated retry: " + std::string(to_string(eq.verdict)) + "]";
  return raw;
}

namespace {
Result solve_with_fallback(const Program& prog, const Options& opt) {
  Result r = solve_scaled(prog, opt);
  if (!opt.fallback || opt.backend != Backend::dsdp) return r;
  if (r.verdict != Feasibility::undecided && r.status != SolveStatus::numerical_trouble) return r;
  Options o = opt;
  o.backend = Backend::csdp;
  Result c = solve_scaled(prog, o);
  if (c.verdict == Feasibility::undecided && c.status == SolveStatus::numerical_trouble) {
    r.detail += "; CSDP fallback also undecided (" + c.detail + ")";
    return r;
  }
  c.solver = "CSDP (DSDP fallback)";
  c.detail = "DSDP: " + r.detail + "; CSDP: " + c.detail;
  return c;
}
}  // namespace

Result Solve(const Program& prog, const Options& opt) {
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
    Result r = solve_scaled(prog, o);
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
  Result r = solve_with_fallback(prog, o);
  r.detail = note + r.detail;
  return r;
}

}  // namespace hapstab::lmi
