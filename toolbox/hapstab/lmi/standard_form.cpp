// hapstab/lmi/standard_form.cpp -- exact equality elimination, reduction, equilibration, the
// StandardForm, and the map back to the program's coordinates (see standard_form.hpp).
#include "hapstab/lmi/standard_form.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/lmi/sparse_ops.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

std::vector<Block> collect_blocks(const Program& prog) {
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
        Expr e = ei * c.lhs * ej - Expr::scalar(c.rhs(i, j));
        blocks.push_back({c.name + "(" + std::to_string(i) + "," + std::to_string(j) + ")", e, false, true, true, -1});
      }
  }
  bool any_posed = false;
  for (const auto& b : blocks) any_posed |= b.posed;
  if (!any_posed) throw InputError("lmi program: no LMI or inequality constraint to solve");
  return blocks;
}

// ---- (1) exact elimination of equalities ----
namespace {

// The augmented rows [a | rhs - lhs constant] of every entry of the linear equalities, in
// exact rationals (entries 0 = 0 left out), and the name of each row's constraint.
void equality_rows(const Program& prog, std::vector<std::vector<rational>>& rows, std::vector<std::string>& names) {
  const int n = prog.num_scalars();
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
}

// x = x0 + N z from the reduced rows: the free columns are z, the pivot ones follow.
void affine_from_rows(const std::vector<std::vector<rational>>& rows, const std::vector<int>& pivcol, int n, Affine& af) {
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
}

}  // namespace

std::vector<int> row_reduce(std::vector<std::vector<rational>>& rows, int n, std::vector<std::string>* names) {
  std::vector<int> pivcol;
  size_t prow = 0;
  for (int col = 0; col < n && prow < rows.size(); ++col) {
    size_t p = prow;
    while (p < rows.size() && rows[p][static_cast<size_t>(col)] == 0) ++p;
    if (p == rows.size()) continue;
    std::swap(rows[p], rows[prow]);
    if (names) std::swap((*names)[p], (*names)[prow]);
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
  return pivcol;
}

bool eliminate(const Program& prog, Affine& af, std::string& why) {
  const int n = prog.num_scalars();
  std::vector<std::vector<rational>> rows;
  std::vector<std::string> names;
  equality_rows(prog, rows, names);
  af.identity = rows.empty();
  if (af.identity) {
    af.nz = n;
    return true;
  }
  const std::vector<int> pivcol = row_reduce(rows, n, &names);
  for (size_t r = pivcol.size(); r < rows.size(); ++r)
    if (rows[r][static_cast<size_t>(n)] != 0) {
      why = "the linear equalities are inconsistent (exact elimination; first failing: '" + names[r] + "')";
      return false;
    }
  affine_from_rows(rows, pivcol, n, af);
  return true;
}

std::vector<rational> exact_point(const Affine& af, std::vector<rational> zq, int n) {
  if (af.identity) return zq;
  std::vector<rational> xq(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    rational v = af.x0[static_cast<size_t>(i)];
    for (int f = 0; f < af.nz; ++f)
      if (af.N(i, f) != 0 && zq[static_cast<size_t>(f)] != 0) v += af.N(i, f) * zq[static_cast<size_t>(f)];
    xq[static_cast<size_t>(i)] = v;
  }
  return xq;
}

// ---- (2) reduction: G0 + sum_k z_k G_k per posed block ----
namespace {

SpMat sym_sparse(const SpMat& M) {
  SpMat S = 0.5 * (M + SpMat(M.transpose()));
  S.prune([](Eigen::Index, Eigen::Index, double v) { return v != 0.0; });
  S.makeCompressed();
  return S;
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

// The linear objective in z: c'x + c0 = (N'c)'z + c'x0 + c0 (zero for the margin objective).
void reduce_objective(const Program& prog, Reduction& rd) {
  const Affine& af = rd.af;
  rd.cz = Eigen::VectorXd::Zero(af.nz);
  rd.cconst = 0;
  if (prog.objective_kind() != ObjectiveKind::minimize) return;
  const Expr& c = prog.objective();
  Eigen::VectorXd cx = Eigen::VectorXd::Zero(prog.num_scalars());
  for (const auto& [k, m] : c.terms()) cx(k) = m.coeff(0, 0);
  rd.cconst = c.constant()(0, 0);
  if (af.identity) rd.cz = cx;
  else {
    rd.cz = af.Nd.transpose() * cx;
    rd.cconst += cx.dot(af.x0d);
  }
}

}  // namespace

bool reduce_program(const Program& prog, Reduction& rd) {
  for (size_t b = 0; b < rd.blocks.size(); ++b)
    if (rd.blocks[b].posed) {
      rd.posed.push_back(static_cast<int>(b));
      rd.red.push_back(reduce(rd.blocks[b].F, rd.af));
    }
  reduce_objective(prog, rd);
  const int nz = rd.af.nz;
  // variables used by posed blocks
  std::vector<int> used(static_cast<size_t>(nz), 0);
  for (const auto& r : rd.red)
    for (const auto& [k, m] : r.G)
      if (max_abs(m) > 0) used[static_cast<size_t>(k)] = 1;
  for (int k = 0; k < nz; ++k)
    if (!used[static_cast<size_t>(k)] && rd.cz(k) != 0.0) return false;
  rd.zmap.assign(static_cast<size_t>(nz), -1);
  for (int k = 0; k < nz; ++k)
    if (used[static_cast<size_t>(k)]) {
      rd.zmap[static_cast<size_t>(k)] = static_cast<int>(rd.ymap.size());
      rd.ymap.push_back(k);
    }
  return true;
}

// ---- (3) equilibration ----
namespace {

double pow2_near(double v) {  // 2^round(log2 v), v > 0
  return std::ldexp(1.0, static_cast<int>(std::lround(std::log2(v))));
}

// One sweep over the block rows: d_r /= sqrt of the row's largest |d_r d_c s_k G_jk(r,c)|
// (the constant G_j0 with weight 1).
void equilibrate_rows(const std::vector<Reduced>& red, std::vector<Eigen::VectorXd>& D, const Eigen::VectorXd& s) {
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
}

// One sweep over the variables: s_k /= sqrt of the largest |d_r d_c s_k G_jk(r,c)|.
void equilibrate_variables(const std::vector<Reduced>& red, const std::vector<Eigen::VectorXd>& D, Eigen::VectorXd& s) {
  const auto nz = s.size();
  Eigen::VectorXd sig = Eigen::VectorXd::Zero(nz);
  for (size_t j = 0; j < red.size(); ++j)
    for (const auto& [k, m] : red[j].G)
      sig(k) = std::max(sig(k), max_abs(congruence(m, D[j], s(k))));
  for (Eigen::Index k = 0; k < nz; ++k)
    if (sig(k) > 0) s(k) /= std::sqrt(sig(k));
}

}  // namespace

// Equilibration (Ruiz-type, 20 sweeps): block rows d_r and variables s_k alternately so that
// the largest |d_r d_c s_k G_jk(r,c)| in every row and for every variable is ~1 (constants
// G_j0 take part with weight 1). Finally every d_r, s_k is rounded to a power of two.
void equilibrate(Reduction& rd, bool scale) {
  rd.D.assign(rd.red.size(), Eigen::VectorXd());
  for (size_t j = 0; j < rd.red.size(); ++j) rd.D[j] = Eigen::VectorXd::Ones(rd.red[j].G0.rows());
  rd.s = Eigen::VectorXd::Ones(rd.af.nz);
  if (!scale) return;
  for (int sweep = 0; sweep < 20; ++sweep) {
    equilibrate_rows(rd.red, rd.D, rd.s);
    equilibrate_variables(rd.red, rd.D, rd.s);
  }
  for (auto& d : rd.D)
    for (Eigen::Index r = 0; r < d.size(); ++r) d(r) = pow2_near(d(r));
  for (int k = 0; k < rd.af.nz; ++k) rd.s(k) = pow2_near(rd.s(k));
}

// ---- the StandardForm ----
namespace {

// Posed block j: C = D G0 D (minus strict_threshold I for a strict LMI under a linear
// objective), terms D G_k D s_k with their low-rank pieces, and -t I on a strict block.
SdpBlock standard_block(const Program& prog, const Options& opt, const Reduction& rd, size_t j) {
  const Reduced& red = rd.red[j];
  const bool strict = rd.blocks[static_cast<size_t>(rd.posed[j])].strict;
  SdpBlock B;
  const auto Dj = rd.D[j].asDiagonal();
  B.C = Dj * red.G0 * Dj;
  if (strict && prog.objective_kind() == ObjectiveKind::minimize)
    B.C -= opt.strict_threshold * Eigen::MatrixXd::Identity(B.C.rows(), B.C.cols());
  B.basis = Dj * red.basis;
  for (const auto& [k, m] : red.G) {
    if (rd.zmap[static_cast<size_t>(k)] < 0) continue;
    SpMat A = congruence(m, rd.D[j], rd.s(k));  // exact: powers of two
    if (max_abs(A) == 0) continue;
    std::vector<Factor> f;
    if (auto it = red.factors.find(k); it != red.factors.end()) {
      f = it->second;
      for (Factor& x : f) x.s *= rd.s(k);
    }
    B.terms.push_back({rd.zmap[static_cast<size_t>(k)], std::move(A), std::move(f)});
  }
  if (strict && rd.use_t) {
    SpMat I(B.C.rows(), B.C.cols());
    I.setIdentity();
    B.terms.push_back({rd.t_index, -I});
  }
  return B;
}

}  // namespace

void build_standard_form(const Program& prog, const Options& opt, Reduction& rd) {
  rd.any_strict = false;
  for (int b : rd.posed) rd.any_strict |= rd.blocks[static_cast<size_t>(b)].strict;
  rd.use_t = prog.objective_kind() == ObjectiveKind::margin && rd.any_strict;
  StandardForm& sf = rd.sf;
  sf.m = static_cast<int>(rd.ymap.size()) + (rd.use_t ? 1 : 0);
  rd.t_index = rd.use_t ? sf.m - 1 : -1;
  if (sf.m == 0) throw InputError("lmi program: no decision variable appears in a posed constraint");
  sf.b = Eigen::VectorXd::Zero(sf.m);
  if (rd.use_t) sf.b(rd.t_index) = 1.0;
  if (prog.objective_kind() == ObjectiveKind::minimize)
    for (size_t y = 0; y < rd.ymap.size(); ++y) sf.b(static_cast<Eigen::Index>(y)) = -rd.s(rd.ymap[y]) * rd.cz(rd.ymap[y]);
  for (size_t j = 0; j < rd.red.size(); ++j) sf.blocks.push_back(standard_block(prog, opt, rd, j));
  if (rd.use_t) {  // t <= margin_cap
    SdpBlock cap;
    cap.C = Eigen::MatrixXd::Constant(1, 1, prog.margin_cap());
    SpMat one(1, 1);
    one.insert(0, 0) = -1.0;
    cap.terms.push_back({rd.t_index, one});
    sf.blocks.push_back(std::move(cap));
  }
}

// ---- back to the program's coordinates ----

Eigen::VectorXd map_back(const Program& prog, const Reduction& rd, const BackendResult& br, SolveResult& res) {
  const Affine& af = rd.af;
  const int n = prog.num_scalars();
  res.status = br.status;
  res.detail = br.detail;
  res.dimacs = br.dimacs;
  res.iterations = br.iterations;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(af.nz);
  for (size_t y = 0; y < rd.ymap.size(); ++y) z(rd.ymap[y]) = rd.s(rd.ymap[y]) * br.y(static_cast<Eigen::Index>(y));
  Eigen::VectorXd xd = af.identity ? z : Eigen::VectorXd(af.x0d + af.Nd * z);
  res.x.assign(xd.data(), xd.data() + n);
  res.margin = rd.use_t ? br.y(rd.t_index) : std::numeric_limits<double>::quiet_NaN();
  res.objective = rd.cconst + rd.cz.dot(z);
  for (const auto& c : prog.lmis()) {
    Eigen::MatrixXd F = c.F.value(res.x);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (F + F.transpose()), Eigen::EigenvaluesOnly);
    res.min_eigenvalue.push_back(es.eigenvalues()(0));
  }
  for (size_t j = 0; j < rd.red.size(); ++j) {
    const auto Dj = rd.D[j].asDiagonal();
    res.multipliers.push_back(Dj * br.X[j] * Dj);
  }
  return z;
}

double strict_margin_at(const Reduction& rd, const Eigen::VectorXd& z) {
  double actual = INFINITY;
  for (size_t j = 0; j < rd.red.size(); ++j) {
    if (!rd.blocks[static_cast<size_t>(rd.posed[j])].strict) continue;
    const auto Dj = rd.D[j].asDiagonal();
    Eigen::MatrixXd S = Dj * rd.red[j].G0 * Dj;
    for (const auto& [k, m] : rd.red[j].G)
      if (rd.zmap[static_cast<size_t>(k)] >= 0) add_to(S, z(k), congruence(m, rd.D[j], 1.0));
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
    actual = std::min(actual, es.eigenvalues()(0));
  }
  return actual;
}

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

}  // namespace hapstab::lmi
