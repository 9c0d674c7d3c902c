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
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <map>

#include "hapstab/lmi/backend.hpp"

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

}  // namespace

BackendResult solve_ipm(const StandardForm& sf) {
  validate(sf);
  const int m = sf.m;
  const size_t J = sf.blocks.size();
  std::vector<DenseBlock> blk(J);
  int N = 0;
  double cnorm = 0, amax = 0;
  for (size_t j = 0; j < J; ++j) {
    const auto& B = sf.blocks[j];
    auto& D = blk[j];
    D.n = static_cast<int>(B.C.rows());
    N += D.n;
    D.C = B.C;
    cnorm = std::max(cnorm, B.C.norm());
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
      amax = std::max(amax, B.terms[t].A.norm());
    }
    D.V.resize(static_cast<Eigen::Index>(D.n) * D.n, static_cast<Eigen::Index>(B.terms.size()));
    D.V.setFromTriplets(vt.begin(), vt.end());
    setup_low_rank(B, D);
  }
  BackendResult r;
  r.y = VectorXd::Zero(m);
  for (const auto& D : blk)  // the dense path's n^2 x q work matrices must fit: else decline at once
    if (!D.low_rank && !D.all_sparse &&
        static_cast<double>(D.n) * D.n * static_cast<double>(D.vars.size()) > static_cast<double>(1 << 26)) {
      r.status = SolveStatus::numerical_trouble;
      r.detail = "hapstab IPM: a " + std::to_string(D.n) + "x" + std::to_string(D.n) + " block with " +
                 std::to_string(D.vars.size()) + " dense terms is too large for its dense Schur complement";
      r.X.resize(J);
      return r;
    }
  r.X.resize(J);
  // CSDP's starting point (initsoln): X = 10 alpha I, S = 10 beta I
  double alpha = 0;
  for (int k = 0; k < m; ++k) alpha = std::max(alpha, (1 + std::abs(sf.b(k))) / (1 + amax));
  alpha *= N;
  const double beta = (1 + std::max(amax, cnorm)) / std::sqrt(static_cast<double>(N));
  std::vector<MatrixXd> X(J), S(J), Sinv(J), Rd(J), R(J), dX(J), dS(J), dXa(J), dSa(J);
  for (size_t j = 0; j < J; ++j) {
    X[j] = 10 * alpha * MatrixXd::Identity(blk[j].n, blk[j].n);
    S[j] = 10 * beta * MatrixXd::Identity(blk[j].n, blk[j].n);
  }
  VectorXd& y = r.y;
  const double bnorm = sf.b.norm();
  auto apply_A = [&](size_t j, const VectorXd& v) {  // sum_k v_k A_jk
    VectorXd w(blk[j].vars.size());
    for (size_t t = 0; t < blk[j].vars.size(); ++t) w(static_cast<Eigen::Index>(t)) = v(blk[j].vars[t]);
    VectorXd a = blk[j].V * w;
    return MatrixXd(Eigen::Map<MatrixXd>(a.data(), blk[j].n, blk[j].n));
  };
  auto trace_A = [&](const std::vector<MatrixXd>& Mj) {  // (tr(A_k M))_k
    VectorXd out = VectorXd::Zero(m);
    for (size_t j = 0; j < J; ++j) {
      VectorXd t = blk[j].V.transpose() * Eigen::Map<const VectorXd>(Mj[j].data(), Mj[j].size());
      for (size_t i = 0; i < blk[j].vars.size(); ++i) out(blk[j].vars[i]) += t(static_cast<Eigen::Index>(i));
    }
    return out;
  };
  struct Work {
    MatrixXd Abig, U, Uv, Gv, G, Mj;
  };
  std::vector<Work> work(J);
  MatrixXd M;               // Schur complement, reused across iterations
  Eigen::LLT<MatrixXd> LL;
  Eigen::LDLT<MatrixXd> LM;
  const int max_iter = 60;
  double mu0 = 0;
  int it = 0;
  r.status = SolveStatus::numerical_trouble;
  r.detail = "hapstab IPM: iteration limit";
  double last_err = INFINITY;  // max(pinf, dinf, gap) at the last iterate measured
  for (; it < max_iter; ++it) {
    std::vector<Eigen::LLT<MatrixXd>> LX(J), LS(J);
    double trXS = 0, rdnorm2 = 0;
    bool lost = false;
    for (size_t j = 0; j < J && !lost; ++j) {
      LX[j].compute(X[j]);
      LS[j].compute(S[j]);
      if (LX[j].info() != Eigen::Success || LS[j].info() != Eigen::Success) {
        r.detail = "hapstab IPM: lost positive definiteness";
        lost = true;
        break;
      }
      Sinv[j] = LS[j].solve(MatrixXd::Identity(blk[j].n, blk[j].n));
      Rd[j] = blk[j].C + apply_A(j, y) - S[j];
      rdnorm2 += Rd[j].squaredNorm();
      trXS += X[j].cwiseProduct(S[j]).sum();
    }
    if (lost) break;
    const VectorXd rp = -sf.b - trace_A(X);
    const double mu = trXS / N;
    double pobj = 0;
    for (size_t j = 0; j < J; ++j) pobj += blk[j].C.cwiseProduct(X[j]).sum();
    const double dobj = sf.b.dot(y);
    const double pinf = rp.norm() / (1 + bnorm), dinf = std::sqrt(rdnorm2) / (1 + cnorm);
    const double gap = std::abs(pobj - dobj) / (1 + std::abs(pobj) + std::abs(dobj));
    last_err = std::max({pinf, dinf, gap});
    if (pinf < 1e-8 && dinf < 1e-8 && gap < 1e-8) {  // CSDP's axtol, atytol, objtol
      r.status = SolveStatus::optimal;
      r.detail = "hapstab IPM: optimal";
      break;
    }
    if (it == 0) mu0 = mu;
    if (!std::isfinite(mu) || !std::isfinite(y.norm()) || mu > 1e8 * mu0) {
      r.detail = "hapstab IPM: diverging iterates (infeasible or unbounded?)";
      break;
    }
    // Schur complement M_kl = tr(A_k X A_l S^-1). A block of sparse terms (a Lyapunov P > 0,
    // 1x1 bounds): sum over the non-zeros, nnz_k nnz_l products a pair. Otherwise <G_k, G_l>
    // with G_k = Ls^T A_k Lx (X = Lx Lx^T, S^-1 = Ls Ls^T): G of the dense terms by two GEMMs,
    // of the sparse ones by outer products of rows of Ls and Lx, then one symmetric rank-q
    // update -- PSD by construction.
    M.setZero(m, m);
    for (size_t j = 0; j < J; ++j) {
      const auto& D = blk[j];
      const Eigen::Index q = static_cast<Eigen::Index>(D.vars.size()), n = D.n;
      if (q == 0) continue;
      MatrixXd& Mj = work[j].Mj;
      Mj.setZero(q, q);
      if (D.low_rank) {
        // M_kl = sum_{f in k, g in l} s_f s_g Xt(v_f, u_g) Zt(v_g, u_f), Xt = B^T X B, Zt = B^T S^-1 B
        const MatrixXd XB = X[j] * D.Bm, ZB = Sinv[j] * D.Bm;
        const MatrixXd Xt = D.Bm.transpose() * XB, Zt = D.Bm.transpose() * ZB;
        for (Eigen::Index k = 0; k < q; ++k)
          for (Eigen::Index l = 0; l <= k; ++l) {
            double acc = 0;
            for (const Factor& f : D.factors[static_cast<size_t>(k)])
              for (const Factor& g : D.factors[static_cast<size_t>(l)]) acc += f.s * g.s * Xt(f.v, g.u) * Zt(g.v, f.u);
            Mj(k, l) = Mj(l, k) = acc;
          }
      } else if (D.all_sparse) {
        for (Eigen::Index k = 0; k < q; ++k)
          for (Eigen::Index l = 0; l <= k; ++l) {
            double acc = 0;
            for (const auto& e : D.entries[static_cast<size_t>(k)])
              for (const auto& f : D.entries[static_cast<size_t>(l)]) acc += e.v * f.v * X[j](e.b, f.a) * Sinv[j](f.b, e.a);
            Mj(k, l) = Mj(l, k) = acc;
          }
      } else {
        const MatrixXd Lx = LX[j].matrixL();
        const MatrixXd Ls = Eigen::LLT<MatrixXd>(Sinv[j]).matrixL();
        std::vector<Eigen::Index> dense;
        for (Eigen::Index t = 0; t < q; ++t)
          if (!D.sparse[static_cast<size_t>(t)]) dense.push_back(t);
        const Eigen::Index qd = static_cast<Eigen::Index>(dense.size());
        // Work buffers live across iterations: n^2 x q doubles each, allocated and freed every
        // iteration they made glibc trim and regrow the heap (page faults), 4x the time of a
        // 54-variable solve in a fresh process (9.3 ms against 2.3 ms).
        MatrixXd& Abig = work[j].Abig;  // [A_t ...] of the dense terms
        MatrixXd& Uv = work[j].Uv;      // [Ls^T A_t; ...] stacked vertically
        MatrixXd& G = work[j].G;
        Abig.resize(n, n * qd);
        for (Eigen::Index i = 0; i < qd; ++i) {
          const VectorXd a = D.V.col(dense[static_cast<size_t>(i)]);
          Abig.middleCols(i * n, n) = Eigen::Map<const MatrixXd>(a.data(), n, n);
        }
        work[j].U.noalias() = Ls.transpose() * Abig;  // [Ls^T A_t ...]
        Uv.resize(n * qd, n);
        for (Eigen::Index i = 0; i < qd; ++i) Uv.middleRows(i * n, n) = work[j].U.middleCols(i * n, n);
        work[j].Gv.noalias() = Uv * Lx;  // [G_t; ...]
        const MatrixXd& Gv = work[j].Gv;
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
      for (Eigen::Index a = 0; a < q; ++a)
        for (Eigen::Index b = 0; b < q; ++b) M(D.vars[static_cast<size_t>(a)], D.vars[static_cast<size_t>(b)]) += Mj(a, b);
    }
    // M is symmetric positive definite in exact arithmetic: Cholesky (blocked, 3-5x Eigen's
    // unblocked LDL^T at m ~ 1000); LDL^T with a shift only when it fails.
    LL.compute(M);
    const bool cholesky = LL.info() == Eigen::Success;
    if (!cholesky) LM.compute(M);
    if (!cholesky && (LM.info() != Eigen::Success || !(LM.vectorD().minCoeff() > 0))) {
      // Near a degenerate optimum (a face of non-unique solutions, e.g. the m = 8 bench
      // program) M loses rank in floating point: a relative 1e-12 diagonal shift keeps the
      // Newton step (inexact by that much) instead of stopping.
      LM.compute(sym(M) + 1e-12 * M.diagonal().cwiseAbs().maxCoeff() * MatrixXd::Identity(m, m));
      if (LM.info() != Eigen::Success || !(LM.vectorD().minCoeff() > 0)) {
        r.detail = "hapstab IPM: singular Schur complement";
        break;
      }
    }
    auto direction = [&](VectorXd& dy) {  // from R: dy, dS, dX
      dy = cholesky ? VectorXd(LL.solve(trace_A(R) - rp)) : VectorXd(LM.solve(trace_A(R) - rp));
      for (size_t j = 0; j < J; ++j) {
        MatrixXd Ady = apply_A(j, dy);
        dS[j] = Ady + Rd[j];
        dX[j] = sym(R[j] - X[j] * Ady * Sinv[j]);
      }
    };
    auto steps = [&](double& ap, double& ad, double enough) {
      ap = ad = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < J; ++j) {
        ap = std::min(ap, max_step(X[j], LX[j], dX[j], enough));
        ad = std::min(ad, max_step(S[j], LS[j], dS[j], enough));
      }
    };
    // predictor (sigma = 0)
    for (size_t j = 0; j < J; ++j) R[j] = -X[j] - X[j] * Rd[j] * Sinv[j];
    VectorXd dy;
    direction(dy);
    double ap = 0, ad = 0;
    steps(ap, ad, 1.0);
    ap = std::min(1.0, ap);
    ad = std::min(1.0, ad);
    double mua = 0;
    for (size_t j = 0; j < J; ++j) {
      mua += (X[j] + ap * dX[j]).cwiseProduct(S[j] + ad * dS[j]).sum();
      dXa[j] = dX[j];
      dSa[j] = dS[j];
    }
    mua /= N;
    const double sigma = std::min(1.0, std::pow(std::max(0.0, mua) / mu, 3));
    // corrector
    for (size_t j = 0; j < J; ++j)
      R[j] = sigma * mu * Sinv[j] - X[j] - X[j] * Rd[j] * Sinv[j] - dXa[j] * dSa[j] * Sinv[j];
    direction(dy);
    steps(ap, ad, 1.0 / 0.98);
    ap = std::min(1.0, 0.98 * ap);
    ad = std::min(1.0, 0.98 * ad);
    for (size_t j = 0; j < J; ++j) {
      X[j] = sym(X[j] + ap * dX[j]);
      S[j] = sym(S[j] + ad * dS[j]);
    }
    y += ad * dy;
  }
  // stopped (Schur complement, steps) next to the optimum: accepted at reduced accuracy, as
  // DSDP's short steps are (backend.cpp); the exact certificate still decides feasibility
  if (r.status != SolveStatus::optimal && last_err <= 1e-6) {
    r.status = SolveStatus::optimal;
    r.detail += " (accepted: infeasibilities and relative gap <= 1e-6)";
  }
  r.iterations = it;
  for (size_t j = 0; j < J; ++j) r.X[j] = X[j];
  r.primal_objective = sf.b.dot(y);
  double trCX = 0;
  for (size_t j = 0; j < J; ++j) trCX += sf.blocks[j].C.cwiseProduct(X[j]).sum();
  r.dual_objective = trCX;
  r.dimacs = dimacs_errors(sf, y, r.X);
  r.detail += " after " + std::to_string(it) + " iterations";
  return r;
}

}  // namespace hapstab::lmi
