// hapstab/lmi/ipm.cpp -- the small dense primal-dual interior-point method (see backend.hpp).
//
// Standard form (backend.hpp): dual  max b^T y, S = C + sum_k y_k A_k >= 0;
//                              primal min tr(C X), tr(A_k X) = -b_k, X >= 0.
// Infeasible-start path following with the HKM direction and Mehrotra's predictor-corrector
// (Helmberg-Rendl-Vanderbei-Wolkowicz 1996; Todd-Toh-Tutuncu 1998), as CSDP uses. With the
// residuals rp_k = -b_k - tr(A_k X), Rd = C + sum y_k A_k - S and a target sigma mu:
//   M dy = tr(A_k R) - rp_k,   M_kl = tr(A_k X A_l S^-1),   R = sigma mu S^-1 - X - X Rd S^-1 [- dXa dSa S^-1]
//   dS = sum dy_l A_l + Rd,    dX = sym(R - X (sum dy_l A_l) S^-1).
// The Schur complement is formed per block in one of three ways: from the terms' rank-one
// pieces over a shared basis Bm when the program supplies them (SdpTerm::factors; a Lyapunov
// term A^T E_ij A - E_ij has 4): M_kl = sum s_f s_g Xt(v_f, u_g) Zt(v_g, u_f) with
// Xt = Bm^T X Bm, Zt = Bm^T S^-1 Bm, O(pieces^2) per entry; entry by entry for blocks of sparse
// terms; else as G^T G with G = [vec Ls^T A_k Lx] (X = Lx Lx^T, S^-1 = Ls Ls^T), dense level-3
// work. The first is what makes the 32-device Theorem 5 program (1700 variables, a 66 x 66
// Lyapunov block) a matter of seconds: the dense form costs q^2 n^2 / 2 = 1.4e10 per iteration.
//
// Stages: setup_blocks (the terms' sparse, dense and low-rank forms; setup_low_rank), the
// starting point (Ipm::start), then per iteration factor_iterate (Cholesky of X and S, S^-1,
// Rd), the termination tests (Ipm::run), schur_complement and factor_schur, and
// predictor_corrector_step (direction, step_lengths); Ipm::result reports.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <map>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/numeric/interrupt.hpp"

namespace hapstab::lmi {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Entry {
  int a, b;
  double v;
};
struct DenseBlock {
  int n = 0;
  MatrixXd C;
  std::vector<int> vars;                   // k of each column of V
  Eigen::SparseMatrix<double> V;           // n^2 x |vars|: vec(A_k)
  std::vector<std::vector<Entry>> entries; // A_k's non-zeros (both triangles)
  std::vector<bool> sparse;                // nnz(A_k) <= n: outer products beat a GEMM
  bool all_sparse = true;
  // The low-rank path (SdpTerm::factors): A_k = sum s b_u b_v^T over the columns of Bm.
  bool low_rank = false;
  MatrixXd Bm;
  std::vector<std::vector<Factor>> factors;
};

// Deduplicated basis and per-term pieces for block B, when every piece checks out against its
// sparse term (relative 1e-12) and the low-rank Schur complement is cheaper than the dense
// one: R^2 n + sum_{k<=l} |f_k| |f_l| against q^2 n^2 / 2. Terms without pieces get unit
// vectors (one piece per non-zero).
void setup_low_rank(const SdpBlock& B, DenseBlock& D) {
  const int n = D.n;
  const size_t q = B.terms.size();
  bool any = false;
  for (const auto& t : B.terms) any = any || !t.factors.empty();
  if (!any || D.all_sparse) return;
  std::map<std::vector<double>, int> index;  // exact column -> position in the new basis
  std::vector<VectorXd> cols;
  auto column = [&](const VectorXd& c) {
    std::vector<double> key(c.data(), c.data() + c.size());
    auto [it, fresh] = index.emplace(std::move(key), static_cast<int>(cols.size()));
    if (fresh) cols.push_back(c);
    return it->second;
  };
  std::vector<int> remap(static_cast<size_t>(B.basis.cols()), -1);
  auto basis_col = [&](int u) {
    if (remap[static_cast<size_t>(u)] < 0) remap[static_cast<size_t>(u)] = column(B.basis.col(u));
    return remap[static_cast<size_t>(u)];
  };
  std::vector<std::vector<Factor>> f(q);
  double pairs = 0, total = 0;
  for (size_t t = 0; t < q; ++t) {
    const auto& T = B.terms[t];
    const MatrixXd A(T.A);
    if (!T.factors.empty()) {
      MatrixXd rec = MatrixXd::Zero(n, n);
      for (const Factor& x : T.factors) {
        if (x.u < 0 || x.v < 0 || x.u >= B.basis.cols() || x.v >= B.basis.cols()) return;
        rec.noalias() += x.s * B.basis.col(x.u) * B.basis.col(x.v).transpose();
      }
      if ((rec - A).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, A.cwiseAbs().maxCoeff())) {
        std::map<std::pair<int, int>, double> merged;  // pieces on the same (u, v) after dedup
        for (const Factor& x : T.factors) merged[{basis_col(x.u), basis_col(x.v)}] += x.s;
        for (const auto& [uv, c] : merged)
          if (c != 0.0) f[t].push_back({uv.first, uv.second, c});
      }
    }
    if (f[t].empty())
      for (const auto& e : D.entries[t]) f[t].push_back({column(VectorXd::Unit(n, e.a)), column(VectorXd::Unit(n, e.b)), e.v});
    total += static_cast<double>(f[t].size());
  }
  pairs = total * total / 2;  // sum over k <= l of |f_k| |f_l|, about
  const double R = static_cast<double>(cols.size()), dn = n;
  const double low = 2 * (R * R * dn + R * dn * dn) + pairs, dense = static_cast<double>(q) * q * dn * dn / 2;
  if (!(low < dense)) return;
  D.low_rank = true;
  D.Bm.resize(n, static_cast<Eigen::Index>(cols.size()));
  for (size_t c = 0; c < cols.size(); ++c) D.Bm.col(static_cast<Eigen::Index>(c)) = cols[c];
  D.factors = std::move(f);
}

// largest alpha in (0, inf] with P + alpha dP >= 0, P > 0 (L = chol(P)), or any value
// >= `enough` when P + enough dP > 0 (one Cholesky instead of an eigenvalue problem: near
// the optimum full steps are the rule)
double max_step(const MatrixXd& P, const Eigen::LLT<MatrixXd>& L, const MatrixXd& dP, double enough) {
  if (P.rows() == 1) return dP(0, 0) < 0 ? -P(0, 0) / dP(0, 0) : std::numeric_limits<double>::infinity();
  if (Eigen::LLT<MatrixXd>(P + enough * dP).info() == Eigen::Success) return enough;
  MatrixXd T = L.matrixL().solve(dP);
  T = L.matrixL().solve(T.transpose()).transpose();
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(0.5 * (T + T.transpose()), Eigen::EigenvaluesOnly);
  const double lmin = es.eigenvalues()(0);
  return lmin < 0 ? -1.0 / lmin : std::numeric_limits<double>::infinity();
}

MatrixXd sym(const MatrixXd& M) { return 0.5 * (M + M.transpose()); }

// ---- setup: the blocks' data in the forms the Schur complement uses ----

struct Setup {
  std::vector<DenseBlock> blk;
  int N = 0;                   // sum of the block orders
  double cnorm = 0, amax = 0;  // largest |C_j|_F and |A_jk|_F (the starting point's scale)
};

Setup setup_blocks(const StandardForm& sf) {
  Setup s;
  s.blk.resize(sf.blocks.size());
  for (size_t j = 0; j < sf.blocks.size(); ++j) {
    const auto& B = sf.blocks[j];
    auto& D = s.blk[j];
    D.n = static_cast<int>(B.C.rows());
    s.N += D.n;
    D.C = B.C;
    s.cnorm = std::max(s.cnorm, B.C.norm());
    std::vector<Eigen::Triplet<double>> vt;
    for (size_t t = 0; t < B.terms.size(); ++t) {
      D.vars.push_back(B.terms[t].var);
      std::vector<Entry> e;
      for (int o = 0; o < B.terms[t].A.outerSize(); ++o)
        for (Eigen::SparseMatrix<double>::InnerIterator i(B.terms[t].A, o); i; ++i) {
          e.push_back({static_cast<int>(i.row()), static_cast<int>(i.col()), i.value()});
          vt.emplace_back(static_cast<int>(i.col()) * D.n + static_cast<int>(i.row()), static_cast<int>(t), i.value());
        }
      D.sparse.push_back(static_cast<int>(e.size()) <= D.n);
      D.all_sparse = D.all_sparse && D.sparse.back();
      D.entries.push_back(std::move(e));
      s.amax = std::max(s.amax, B.terms[t].A.norm());
    }
    D.V.resize(static_cast<Eigen::Index>(D.n) * D.n, static_cast<Eigen::Index>(B.terms.size()));
    D.V.setFromTriplets(vt.begin(), vt.end());
    setup_low_rank(B, D);
  }
  return s;
}

// The dense path's n^2 x q work matrices must fit: else the IPM declines at once. Returns
// the reason, empty when every block fits.
std::string too_large(const std::vector<DenseBlock>& blk) {
  for (const auto& D : blk)
    if (!D.low_rank && !D.all_sparse &&
        static_cast<double>(D.n) * D.n * static_cast<double>(D.vars.size()) > static_cast<double>(1 << 26))
      return "hapstab IPM: a " + std::to_string(D.n) + "x" + std::to_string(D.n) + " block with " +
             std::to_string(D.vars.size()) + " dense terms is too large for its dense Schur complement";
  return "";
}

// Work buffers of the dense Schur complement, per block.
struct Work {
  MatrixXd Abig, U, Uv, Gv, G, Mj;
};

// The iterates (X, S, y) and the stages of one predictor-corrector iteration.
class Ipm {
 public:
  Ipm(const StandardForm& sf, Setup setup)
      : sf_(sf), m_(sf.m), J_(sf.blocks.size()), blk_(std::move(setup.blk)), N_(setup.N), cnorm_(setup.cnorm),
        amax_(setup.amax), X_(J_), S_(J_), Sinv_(J_), Rd_(J_), R_(J_), dX_(J_), dS_(J_), dXa_(J_), dSa_(J_), LX_(J_),
        LS_(J_), work_(J_), y_(VectorXd::Zero(m_)) {}
  BackendResult run();

 private:
  // residuals and gap of the current iterate, relative (CSDP's measures)
  struct Measures {
    double pinf, dinf, gap;
  };
  void start();
  bool factor_iterate(double& trXS, double& rdnorm2);
  Measures measure(const VectorXd& rp, double rdnorm2) const;
  void schur_complement();
  void block_schur_low_rank(size_t j);
  void block_schur_sparse(size_t j);
  void block_schur_dense(size_t j);
  bool factor_schur();
  void direction(const VectorXd& rp, VectorXd& dy);
  void step_lengths(double& ap, double& ad, double enough);
  void predictor_corrector_step(const VectorXd& rp, double mu);
  BackendResult result(BackendResult r, int it, double last_err) const;

  MatrixXd apply_A(size_t j, const VectorXd& v) const {  // sum_k v_k A_jk
    VectorXd w(blk_[j].vars.size());
    for (size_t t = 0; t < blk_[j].vars.size(); ++t) w(static_cast<Eigen::Index>(t)) = v(blk_[j].vars[t]);
    VectorXd a = blk_[j].V * w;
    return MatrixXd(Eigen::Map<MatrixXd>(a.data(), blk_[j].n, blk_[j].n));
  }
  VectorXd trace_A(const std::vector<MatrixXd>& Mj) const {  // (tr(A_k M))_k
    VectorXd out = VectorXd::Zero(m_);
    for (size_t j = 0; j < J_; ++j) {
      VectorXd t = blk_[j].V.transpose() * Eigen::Map<const VectorXd>(Mj[j].data(), Mj[j].size());
      for (size_t i = 0; i < blk_[j].vars.size(); ++i) out(blk_[j].vars[i]) += t(static_cast<Eigen::Index>(i));
    }
    return out;
  }

  const StandardForm& sf_;
  const int m_;
  const size_t J_;
  const std::vector<DenseBlock> blk_;
  const int N_;
  const double cnorm_, amax_;
  std::vector<MatrixXd> X_, S_, Sinv_, Rd_, R_, dX_, dS_, dXa_, dSa_;
  std::vector<Eigen::LLT<MatrixXd>> LX_, LS_;  // Cholesky factors of X_j and S_j
  std::vector<Work> work_;
  MatrixXd M_;  // Schur complement, reused across iterations
  Eigen::LLT<MatrixXd> LL_;
  Eigen::LDLT<MatrixXd> LM_;
  bool cholesky_ = false;  // LL_ holds M's factor, else LM_ (shifted LDL^T)
  VectorXd y_;
};

// CSDP's starting point (initsoln): X = 10 alpha I, S = 10 beta I
void Ipm::start() {
  double alpha = 0;
  for (int k = 0; k < m_; ++k) alpha = std::max(alpha, (1 + std::abs(sf_.b(k))) / (1 + amax_));
  alpha *= N_;
  const double beta = (1 + std::max(amax_, cnorm_)) / std::sqrt(static_cast<double>(N_));
  for (size_t j = 0; j < J_; ++j) {
    X_[j] = 10 * alpha * MatrixXd::Identity(blk_[j].n, blk_[j].n);
    S_[j] = 10 * beta * MatrixXd::Identity(blk_[j].n, blk_[j].n);
  }
}

// Cholesky factors of X and S, S^-1 and the dual residual Rd = C + sum y_k A_k - S; tr(XS) and
// |Rd|^2 summed over the blocks. False when X or S lost positive definiteness.
bool Ipm::factor_iterate(double& trXS, double& rdnorm2) {
  for (size_t j = 0; j < J_; ++j) {
    LX_[j].compute(X_[j]);
    LS_[j].compute(S_[j]);
    if (LX_[j].info() != Eigen::Success || LS_[j].info() != Eigen::Success) return false;
    Sinv_[j] = LS_[j].solve(MatrixXd::Identity(blk_[j].n, blk_[j].n));
    Rd_[j] = blk_[j].C + apply_A(j, y_) - S_[j];
    rdnorm2 += Rd_[j].squaredNorm();
    trXS += X_[j].cwiseProduct(S_[j]).sum();
  }
  return true;
}

Ipm::Measures Ipm::measure(const VectorXd& rp, double rdnorm2) const {
  double pobj = 0;
  for (size_t j = 0; j < J_; ++j) pobj += blk_[j].C.cwiseProduct(X_[j]).sum();
  const double dobj = sf_.b.dot(y_);
  const double pinf = rp.norm() / (1 + sf_.b.norm()), dinf = std::sqrt(rdnorm2) / (1 + cnorm_);
  const double gap = std::abs(pobj - dobj) / (1 + std::abs(pobj) + std::abs(dobj));
  return {pinf, dinf, gap};
}

// Schur complement M_kl = tr(A_k X A_l S^-1), per block, scattered into M by the blocks'
// variables.
void Ipm::schur_complement() {
  M_.setZero(m_, m_);
  for (size_t j = 0; j < J_; ++j) {
    const auto& D = blk_[j];
    const Eigen::Index q = static_cast<Eigen::Index>(D.vars.size());
    if (q == 0) continue;
    work_[j].Mj.setZero(q, q);
    if (D.low_rank) block_schur_low_rank(j);
    else if (D.all_sparse) block_schur_sparse(j);
    else block_schur_dense(j);
    const MatrixXd& Mj = work_[j].Mj;
    for (Eigen::Index a = 0; a < q; ++a)
      for (Eigen::Index b = 0; b < q; ++b) M_(D.vars[static_cast<size_t>(a)], D.vars[static_cast<size_t>(b)]) += Mj(a, b);
  }
}

// M_kl = sum_{f in k, g in l} s_f s_g Xt(v_f, u_g) Zt(v_g, u_f), Xt = B^T X B, Zt = B^T S^-1 B
void Ipm::block_schur_low_rank(size_t j) {
  const auto& D = blk_[j];
  const Eigen::Index q = static_cast<Eigen::Index>(D.vars.size());
  MatrixXd& Mj = work_[j].Mj;
  const MatrixXd XB = X_[j] * D.Bm, ZB = Sinv_[j] * D.Bm;
  const MatrixXd Xt = D.Bm.transpose() * XB, Zt = D.Bm.transpose() * ZB;
  for (Eigen::Index k = 0; k < q; ++k)
    for (Eigen::Index l = 0; l <= k; ++l) {
      double acc = 0;
      for (const Factor& f : D.factors[static_cast<size_t>(k)])
        for (const Factor& g : D.factors[static_cast<size_t>(l)]) acc += f.s * g.s * Xt(f.v, g.u) * Zt(g.v, f.u);
      Mj(k, l) = Mj(l, k) = acc;
    }
}

// A block of sparse terms (a Lyapunov P > 0, 1x1 bounds): sum over the non-zeros, nnz_k nnz_l
// products a pair.
void Ipm::block_schur_sparse(size_t j) {
  const auto& D = blk_[j];
  const Eigen::Index q = static_cast<Eigen::Index>(D.vars.size());
  MatrixXd& Mj = work_[j].Mj;
  for (Eigen::Index k = 0; k < q; ++k)
    for (Eigen::Index l = 0; l <= k; ++l) {
      double acc = 0;
      for (const auto& e : D.entries[static_cast<size_t>(k)])
        for (const auto& f : D.entries[static_cast<size_t>(l)]) acc += e.v * f.v * X_[j](e.b, f.a) * Sinv_[j](f.b, e.a);
      Mj(k, l) = Mj(l, k) = acc;
    }
}

// <G_k, G_l> with G_k = Ls^T A_k Lx (X = Lx Lx^T, S^-1 = Ls Ls^T): G of the dense terms by two
// GEMMs, of the sparse ones by outer products of rows of Ls and Lx, then one symmetric rank-q
// update -- PSD by construction.
void Ipm::block_schur_dense(size_t j) {
  const auto& D = blk_[j];
  const Eigen::Index q = static_cast<Eigen::Index>(D.vars.size()), n = D.n;
  MatrixXd& Mj = work_[j].Mj;
  const MatrixXd Lx = LX_[j].matrixL();
  const MatrixXd Ls = Eigen::LLT<MatrixXd>(Sinv_[j]).matrixL();
  std::vector<Eigen::Index> dense;
  for (Eigen::Index t = 0; t < q; ++t)
    if (!D.sparse[static_cast<size_t>(t)]) dense.push_back(t);
  const Eigen::Index qd = static_cast<Eigen::Index>(dense.size());
  // Work buffers live across iterations: n^2 x q doubles each, allocated and freed every
  // iteration they made glibc trim and regrow the heap (page faults), 4x the time of a
  // 54-variable solve in a fresh process (9.3 ms against 2.3 ms).
  MatrixXd& Abig = work_[j].Abig;  // [A_t ...] of the dense terms
  MatrixXd& Uv = work_[j].Uv;      // [Ls^T A_t; ...] stacked vertically
  MatrixXd& G = work_[j].G;
  Abig.resize(n, n * qd);
  for (Eigen::Index i = 0; i < qd; ++i) {
    const VectorXd a = D.V.col(dense[static_cast<size_t>(i)]);
    Abig.middleCols(i * n, n) = Eigen::Map<const MatrixXd>(a.data(), n, n);
  }
  work_[j].U.noalias() = Ls.transpose() * Abig;  // [Ls^T A_t ...]
  Uv.resize(n * qd, n);
  for (Eigen::Index i = 0; i < qd; ++i) Uv.middleRows(i * n, n) = work_[j].U.middleCols(i * n, n);
  work_[j].Gv.noalias() = Uv * Lx;  // [G_t; ...]
  const MatrixXd& Gv = work_[j].Gv;
  G.setZero(n * n, q);
  for (Eigen::Index i = 0; i < qd; ++i)
    Eigen::Map<MatrixXd>(G.col(dense[static_cast<size_t>(i)]).data(), n, n) = Gv.middleRows(i * n, n);
  for (Eigen::Index t = 0; t < q; ++t) {
    if (!D.sparse[static_cast<size_t>(t)]) continue;
    Eigen::Map<MatrixXd> Gt(G.col(t).data(), n, n);
    for (const auto& e : D.entries[static_cast<size_t>(t)]) Gt.noalias() += e.v * Ls.row(e.a).transpose() * Lx.row(e.b);
  }
  Mj.selfadjointView<Eigen::Lower>().rankUpdate(G.transpose());
  Mj = Mj.selfadjointView<Eigen::Lower>();
}

// M is symmetric positive definite in exact arithmetic: Cholesky (blocked, 3-5x Eigen's
// unblocked LDL^T at m ~ 1000); LDL^T with a shift only when it fails. False when M is
// singular even so.
bool Ipm::factor_schur() {
  LL_.compute(M_);
  cholesky_ = LL_.info() == Eigen::Success;
  if (!cholesky_) LM_.compute(M_);
  if (!cholesky_ && (LM_.info() != Eigen::Success || !(LM_.vectorD().minCoeff() > 0))) {
    // Near a degenerate optimum (a face of non-unique solutions, e.g. the m = 8 bench
    // program) M loses rank in floating point: a relative 1e-12 diagonal shift keeps the
    // Newton step (inexact by that much) instead of stopping.
    LM_.compute(sym(M_) + 1e-12 * M_.diagonal().cwiseAbs().maxCoeff() * MatrixXd::Identity(m_, m_));
    if (LM_.info() != Eigen::Success || !(LM_.vectorD().minCoeff() > 0)) return false;
  }
  return true;
}

// From R: M dy = tr(A_k R) - rp_k, dS = sum dy_l A_l + Rd, dX = sym(R - X (sum dy_l A_l) S^-1).
void Ipm::direction(const VectorXd& rp, VectorXd& dy) {
  dy = cholesky_ ? VectorXd(LL_.solve(trace_A(R_) - rp)) : VectorXd(LM_.solve(trace_A(R_) - rp));
  for (size_t j = 0; j < J_; ++j) {
    MatrixXd Ady = apply_A(j, dy);
    dS_[j] = Ady + Rd_[j];
    dX_[j] = sym(R_[j] - X_[j] * Ady * Sinv_[j]);
  }
}

// The largest primal and dual steps that keep X and S positive semidefinite (or `enough`).
void Ipm::step_lengths(double& ap, double& ad, double enough) {
  ap = ad = std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < J_; ++j) {
    ap = std::min(ap, max_step(X_[j], LX_[j], dX_[j], enough));
    ad = std::min(ad, max_step(S_[j], LS_[j], dS_[j], enough));
  }
}

// Mehrotra: the predictor (sigma = 0) gives the affine-scaling step and its mu; the corrector
// aims at sigma mu with sigma = (mu_aff / mu)^3 and the second-order term dXa dSa S^-1; then
// 0.98 of the longest step that keeps X, S positive definite.
void Ipm::predictor_corrector_step(const VectorXd& rp, double mu) {
  // predictor (sigma = 0)
  for (size_t j = 0; j < J_; ++j) R_[j] = -X_[j] - X_[j] * Rd_[j] * Sinv_[j];
  VectorXd dy;
  direction(rp, dy);
  double ap = 0, ad = 0;
  step_lengths(ap, ad, 1.0);
  ap = std::min(1.0, ap);
  ad = std::min(1.0, ad);
  double mua = 0;
  for (size_t j = 0; j < J_; ++j) {
    mua += (X_[j] + ap * dX_[j]).cwiseProduct(S_[j] + ad * dS_[j]).sum();
    dXa_[j] = dX_[j];
    dSa_[j] = dS_[j];
  }
  mua /= N_;
  const double sigma = std::min(1.0, std::pow(std::max(0.0, mua) / mu, 3));
  // corrector
  for (size_t j = 0; j < J_; ++j)
    R_[j] = sigma * mu * Sinv_[j] - X_[j] - X_[j] * Rd_[j] * Sinv_[j] - dXa_[j] * dSa_[j] * Sinv_[j];
  direction(rp, dy);
  step_lengths(ap, ad, 1.0 / 0.98);
  ap = std::min(1.0, 0.98 * ap);
  ad = std::min(1.0, 0.98 * ad);
  for (size_t j = 0; j < J_; ++j) {
    X_[j] = sym(X_[j] + ap * dX_[j]);
    S_[j] = sym(S_[j] + ad * dS_[j]);
  }
  y_ += ad * dy;
}

// Termination: CSDP's tolerances 1e-8 (optimal), diverging iterates, or a stage that cannot
// go on (positive definiteness lost, singular Schur complement), or the iteration limit.
BackendResult Ipm::run() {
  BackendResult r;
  r.X.resize(J_);
  start();
  const int max_iter = 60;
  double mu0 = 0;
  int it = 0;
  r.status = SolveStatus::numerical_trouble;
  r.detail = "hapstab IPM: iteration limit";
  double last_err = INFINITY;  // max(pinf, dinf, gap) at the last iterate measured
  for (; it < max_iter; ++it) {
    interruption_point();  // the caller may abandon the solve between iterations (numeric/interrupt.hpp)
    double trXS = 0, rdnorm2 = 0;
    if (!factor_iterate(trXS, rdnorm2)) {
      r.detail = "hapstab IPM: lost positive definiteness";
      break;
    }
    const VectorXd rp = -sf_.b - trace_A(X_);
    const double mu = trXS / N_;
    const Measures e = measure(rp, rdnorm2);
    last_err = std::max({e.pinf, e.dinf, e.gap});
    if (e.pinf < 1e-8 && e.dinf < 1e-8 && e.gap < 1e-8) {  // CSDP's axtol, atytol, objtol
      r.status = SolveStatus::optimal;
      r.detail = "hapstab IPM: optimal";
      break;
    }
    if (it == 0) mu0 = mu;
    if (!std::isfinite(mu) || !std::isfinite(y_.norm()) || mu > 1e8 * mu0) {
      r.detail = "hapstab IPM: diverging iterates (infeasible or unbounded?)";
      break;
    }
    schur_complement();
    if (!factor_schur()) {
      r.detail = "hapstab IPM: singular Schur complement";
      break;
    }
    predictor_corrector_step(rp, mu);
  }
  return result(std::move(r), it, last_err);
}

BackendResult Ipm::result(BackendResult r, int it, double last_err) const {
  // stopped (Schur complement, steps) next to the optimum: accepted at reduced accuracy, as
  // DSDP's short steps are (backend.cpp); the exact certificate still decides feasibility
  if (r.status != SolveStatus::optimal && last_err <= 1e-6) {
    r.status = SolveStatus::optimal;
    r.detail += " (accepted: infeasibilities and relative gap <= 1e-6)";
  }
  r.iterations = it;
  r.y = y_;
  for (size_t j = 0; j < J_; ++j) r.X[j] = X_[j];
  r.primal_objective = sf_.b.dot(y_);
  double trCX = 0;
  for (size_t j = 0; j < J_; ++j) trCX += sf_.blocks[j].C.cwiseProduct(X_[j]).sum();
  r.dual_objective = trCX;
  r.dimacs = dimacs_errors(sf_, r.y, r.X);
  r.detail += " after " + std::to_string(it) + " iterations";
  return r;
}

}  // namespace

BackendResult solve_ipm(const StandardForm& sf) {
  validate(sf);
  Setup setup = setup_blocks(sf);
  if (std::string why = too_large(setup.blk); !why.empty()) {
    BackendResult r;
    r.y = VectorXd::Zero(sf.m);
    r.status = SolveStatus::numerical_trouble;
    r.detail = why;
    r.X.resize(sf.blocks.size());
    return r;
  }
  return Ipm(sf, std::move(setup)).run();
}

}  // namespace hapstab::lmi
