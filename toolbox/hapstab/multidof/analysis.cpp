#include "hapstab/multidof/analysis.hpp"

#include <chrono>
#include <functional>
#include <optional>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "hapstab/lmi/kyp.hpp"
#include "hapstab/multidof/detail.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::multidof {

using namespace detail;

Eigen::MatrixXd to_double(const MatQ& M) {
  MatrixXd D(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) D(i, j) = to_real<double>(M(i, j));
  return D;
}

Expr scalar_times(const Expr& se, const MatrixXd& M) {
  // M = sum_i col_i e_i^T  ->  s M = sum_i col_i * s * e_i^T
  Expr r = Expr::zero(static_cast<int>(M.rows()), static_cast<int>(M.cols()));
  for (Eigen::Index j = 0; j < M.cols(); ++j) {
    if (M.col(j).isZero(0.0)) continue;
    MatrixXd e = MatrixXd::Zero(1, M.cols());
    e(0, j) = 1;
    r += MatrixXd(M.col(j)) * se * e;
  }
  return r;
}

void Problem::validate(bool with_coupling) const {
  structure.validate();
  E.validate("environment E");
  if (!E.is_discrete()) throw InputError("environment E must be discrete (sample period T > 0)");
  if (E.inputs() != E.outputs())
    throw InputError("environment E is not square: " + std::to_string(E.outputs()) + " outputs, " +
                     std::to_string(E.inputs()) + " inputs (a square m x m E is required)");
  if (E.inputs() != structure.m())
    throw InputError("block sizes do not add up: the operators have sum m_i = " + std::to_string(structure.m()) +
                     " DOF but the environment E has m = " + std::to_string(E.inputs()));
  if (!schur_stable(E.A))
    throw InputError("environment E is not stable: A_E has an eigenvalue on or outside the unit circle "
                     "(exact Schur-Cohn test); Theorem 5 needs a stable E");
  if (with_coupling) coupling.validate(structure.m());
}

namespace {

// The rational basis of {g in Q^N : X(g) G symmetric for every G in `gains`}, X(g) the block
// diagonal with g_b I on operator b's block (blk[i] = the operator of DOF i). Each condition
// (X G)_ij = (X G)_ji (i < j) reads g_p G_ij - g_q G_ji = 0, p = blk[i], q = blk[j]: at most two
// unknowns. So the conditions are a graph on the operators: an edge a g_p = b g_q (a, b != 0)
// fixes the ratio g_q / g_p; a condition with one nonzero coefficient (or p = q with
// G_ij != G_ji) forces g_p = 0, and so does a cycle whose ratios do not multiply to 1. Each
// connected component without such a contradiction contributes one basis vector w (the ratios,
// w = 1 at its largest column); the others contribute nothing. O(m^2) work where the rational
// RREF of the m(m-1)/2 x N condition matrix took O(m^2 N^2).
//
// The basis is the one the RREF gives, vector for vector (tests/multidof compares both): the
// RREF of a component's rows (rank = size - 1) has its largest column free, so its null vector
// is w with w = 1 there; vectors come in the order of their free columns, and each is signed so
// that its first nonzero entry is positive (g >= 1 wants positive directions).
std::vector<std::vector<rational>> symmetric_gain_basis(const std::vector<int>& blk, int N,
                                                        const std::vector<MatQ>& gains) {
  struct Edge {
    int to;
    rational a, b;  // a g_from = b g_to
  };
  std::vector<std::vector<Edge>> adj(static_cast<size_t>(N));
  std::vector<char> forced_zero(static_cast<size_t>(N), 0);
  const int m = static_cast<int>(blk.size());
  for (const auto& G : gains)
    for (int i = 0; i < m; ++i)
      for (int j = i + 1; j < m; ++j) {
        const int p = blk[static_cast<size_t>(i)], q = blk[static_cast<size_t>(j)];
        const rational &a = G(i, j), &b = G(j, i);
        if (p == q) {
          if (a != b) forced_zero[static_cast<size_t>(p)] = 1;
        } else if (a == 0 || b == 0) {
          if (a != 0) forced_zero[static_cast<size_t>(p)] = 1;
          if (b != 0) forced_zero[static_cast<size_t>(q)] = 1;
        } else {
          adj[static_cast<size_t>(p)].push_back({q, a, b});
          adj[static_cast<size_t>(q)].push_back({p, b, a});
        }
      }
  std::vector<std::vector<rational>> basis;
  std::vector<rational> w(static_cast<size_t>(N));
  std::vector<char> seen(static_cast<size_t>(N), 0);
  // From the largest column down: an unseen column is the largest of its component.
  for (int f = N - 1; f >= 0; --f) {
    if (seen[static_cast<size_t>(f)]) continue;
    std::vector<int> comp{f};
    seen[static_cast<size_t>(f)] = 1;
    w[static_cast<size_t>(f)] = 1;
    bool zero = false;
    for (size_t k = 0; k < comp.size(); ++k) {
      const int u = comp[k];
      zero = zero || forced_zero[static_cast<size_t>(u)];
      for (const Edge& e : adj[static_cast<size_t>(u)]) {
        const size_t v = static_cast<size_t>(e.to);
        if (!seen[v]) {
          seen[v] = 1;
          w[v] = e.a * w[static_cast<size_t>(u)] / e.b;
          comp.push_back(e.to);
        } else if (!zero && e.a * w[static_cast<size_t>(u)] != e.b * w[v]) {
          zero = true;  // the ratios around a cycle do not multiply to 1
        }
      }
    }
    if (zero) continue;
    std::vector<rational> v(static_cast<size_t>(N), rational(0));
    const int first = *std::min_element(comp.begin(), comp.end());
    const bool flip = w[static_cast<size_t>(first)] < 0;
    for (int c : comp) v[static_cast<size_t>(c)] = flip ? rational(-w[static_cast<size_t>(c)]) : w[static_cast<size_t>(c)];
    basis.push_back(std::move(v));
  }
  std::reverse(basis.begin(), basis.end());  // in the order of their largest (free) columns
  return basis;
}

std::string str(const rational& q, int digits = 6) {
  std::ostringstream o;
  o.precision(digits);
  o << to_real<double>(q);
  return o.str();
}

}  // namespace

FacialConditions facial_conditions(const Problem& pb, const std::vector<MatQ>& extra) {
  FacialConditions fc;
  fc.E1 = dc_gain(pb.E);
  const int m = pb.structure.m();
  const auto sizes = pb.structure.operator_sizes();
  const int N = static_cast<int>(sizes.size());
  std::vector<int> blk;
  for (int i = 0; i < N; ++i)
    for (int k = 0; k < sizes[static_cast<size_t>(i)]; ++k) blk.push_back(i);
  std::vector<MatQ> gains{fc.E1};
  for (const auto& g : extra) gains.push_back(g);
  fc.gamma_basis = symmetric_gain_basis(blk, N, gains);
  fc.symmetric_possible = !fc.gamma_basis.empty();
  std::ostringstream o;
  o << "Facial reduction of (16)'s first LMI: E-hat has " << m << " eigenvalues at z = 1, so (16) needs "
    << "(A^T - I) P v = 0 and (B^T P - X C/2) v = 0 for each eigenvector v; these hold iff "
    << "P = Pi0^-T blockdiag(P11, X E(1)/(2T)) Pi0^-1, which requires X E(1) symmetric and positive definite. "
    << "E(1) (static stiffness) = ";
  if (m <= 4) {  // in full; a larger one summarised (one line of text, not m^2 numbers)
    o << "[";
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) o << (j ? ", " : "") << str(fc.E1(i, j));
      o << (i + 1 < m ? "; " : "]");
    }
  } else {
    rational lo = fc.E1(0, 0), hi = lo;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) lo = std::min(lo, fc.E1(i, j)), hi = std::max(hi, fc.E1(i, j));
    o << "(" << m << " x " << m << ", entries in [" << str(lo) << ", " << str(hi) << "])";
  }
  if (fc.E1 == MatQ(fc.E1.transpose()) && static_cast<int>(fc.gamma_basis.size()) == N)
    o << " is symmetric, so every X in G(m; ...) keeps X E(1) symmetric";
  else if (fc.E1 == MatQ(fc.E1.transpose()))
    o << " is symmetric; X E(1) is symmetric only on a " << fc.gamma_basis.size()
      << "-dimensional set of X (g_i = g_j wherever E(1) couples operators i and j)";
  else if (!fc.symmetric_possible)
    o << " is not symmetric and no X in G(m; m_1..m_N) makes X E(1) symmetric: (16) has NO solution for this "
         "structure (exact; no SDP needed)";
  else
    o << " is not symmetric; X E(1) is symmetric only on a " << fc.gamma_basis.size()
      << "-dimensional set of X (the ratios of the g_i are pinned by E(1)_ij / E(1)_ji)";
  fc.explanation = o.str();
  return fc;
}

namespace detail {

EnvVars add_environment(Program& prog, const Problem& pb, const EhatSplit& sp, const FacialConditions& fc,
                        bool qe_is_delta_x) {
  EnvVars ev;
  const int m = pb.structure.m();
  const int n = static_cast<int>(pb.E.states());
  const rational T = pb.T();
  const double Td = to_real<double>(T);
  ev.basis = fc.gamma_basis;
  const int N = static_cast<int>(pb.structure.operators.size());
  ev.X = Expr::zero(m, m);
  ev.g = Expr::zero(N, 1);
  for (size_t k = 0; k < ev.basis.size(); ++k) {
    ev.theta.push_back(prog.new_scalar("theta" + std::to_string(k + 1)));
    std::vector<rational> gk = ev.basis[k];
    MatQ Xk = pb.structure.scalar_blocks(gk);
    ev.Xk.push_back(Xk);
    ev.X += scalar_times(ev.theta.back(), to_double(Xk));
    MatrixXd gv(N, 1);
    for (int i = 0; i < N; ++i) gv(i, 0) = to_real<double>(gk[static_cast<size_t>(i)]);
    ev.g += scalar_times(ev.theta.back(), gv);
  }
  // g_i >= 1 (9)
  prog.add_linear_inequality("gamma_i >= 1 (9)", ev.g, MatrixXd::Ones(N, 1));
  if (!qe_is_delta_x) ev.QE = prog.new_symmetric(m, "Q_E");
  const MatrixXd E1 = to_double(sp.E1);
  const MatrixXd DE = to_double(pb.E.D);
  // XE1s = (X E(1) + E(1)^T X)/2 (= X E(1) exactly for the exact basis)
  const Expr XE1s = 0.5 * (ev.X * E1 + E1.transpose() * ev.X);
  // W = X E(1)/(2T) > 0  (the P22 block in the split coordinates)
  prog.add_lmi("P > 0: X E(1)/(2T) block", (0.5 / Td) * XE1s, Strictness::strict);
  const Expr QEe = qe_is_delta_x ? to_double(pb.structure.delta_D()) * ev.X : Expr(ev.QE);
  Expr F22 = (Td / 2) * XE1s - (Td / 2) * (ev.X * DE + DE.transpose() * ev.X) - QEe;
  if (n > 0) {
    ev.P11 = prog.new_symmetric(n, "P11");
    const Expr P(ev.P11);
    prog.add_lmi("P > 0: P11 block", P, Strictness::strict);
    const MatrixXd AE = to_double(MatQ(sp.t.A.topLeftCorner(n, n)));
    const MatrixXd Bt = to_double(MatQ(sp.t.B.topRows(n)));
    const MatrixXd CE = to_double(MatQ(sp.t.C.leftCols(n)));
    // [[AE^T P AE - P, AE^T P Bt - CE^T X/2], [., Bt^T P Bt + F22]] written as
    // W^T P W - J^T P J + [[0, -CE^T X/2], [., F22]], W = [AE, Bt], J = [I, 0]: the same
    // entries, and each P_ij term keeps its 4 rank-one pieces (w_i w_j^T + w_j w_i^T - e_i e_j^T
    // - e_j e_i^T), which the IPM's Schur complement uses (lmi/program.hpp, LowRank).
    MatrixXd W(n, n + m), J = MatrixXd::Zero(n, n + m);
    W << AE, Bt;
    J.leftCols(n).setIdentity();
    const Expr rest = lmi::blocks({{Expr::zero(n, n), -0.5 * (CE.transpose() * ev.X)}, {Expr(), F22}});
    prog.add_lmi("(16) first LMI, reduced (facial reduction)",
                -1.0 * (W.transpose() * P * W - J.transpose() * P * J + rest), Strictness::strict);
  } else {
    prog.add_lmi("(16) first LMI, reduced (facial reduction)", -1.0 * F22, Strictness::strict);
  }
  return ev;
}

void add_condition14(Program& prog, const Problem& pb, const EnvVars& ev, const Expr& QV) {
  const MatrixXd DD = to_double(pb.structure.delta_D());
  const Expr QE(ev.QE);
  prog.add_lmi("(16) second LMI (scaled (14))", lmi::blocks({{DD * ev.X - QE, -1.0 * QE}, {Expr(), QV - QE}}),
              Strictness::strict);
}

ExactEnv exact_env(const lmi::CertifiedSolve& cs, const EnvVars& ev) {
  auto get = [&](const MatrixVariable& v) { return cs.point(v); };
  ExactEnv x;
  const int m = ev.X.rows();
  x.X = MatQ::Zero(m, m);
  for (size_t k = 0; k < ev.theta.size(); ++k) {
    const rational th = get(ev.theta[k])(0, 0);
    x.X += th * ev.Xk[k];
    x.theta.push_back(th);
  }
  if (ev.QE.rows > 0) x.QE = get(ev.QE);
  if (ev.P11.rows > 0) x.P11 = get(ev.P11);
  return x;
}

bool exact_recheck(const Problem& pb, const EhatSplit& sp, const ExactEnv& x, const MatQ& QV, std::string& why) {
  const int m = pb.structure.m();
  const int n = static_cast<int>(pb.E.states());
  const rational T = pb.T();
  const StateSpace<rational> H = ehat(pb.E);
  // P = Pi0^-T blockdiag(P11, X E(1)/(2T)) Pi0^-1
  MatQ Pt = MatQ::Zero(n + m, n + m);
  if (n) Pt.topLeftCorner(n, n) = x.P11;
  Pt.bottomRightCorner(m, m) = exact_product(x.X, sp.E1) / (2 * T);
  // Pi0 = [[I, Va], [0, I]] has the exact inverse [[I, -Va], [0, I]] (no elimination needed)
  MatQ Pi0i = MatQ::Identity(n + m, n + m);
  if (n) Pi0i.topRightCorner(n, m) = -sp.Va;
  const MatQ P = exact_product(exact_product(MatQ(Pi0i.transpose()), Pt), Pi0i);
  if (P != MatQ(P.transpose())) {
    why = "X E(1) is not exactly symmetric at the rounded point";
    return false;
  }
  if (!lmi::exact_pd_bareiss(P)) {
    why = "P > 0 fails exactly";
    return false;
  }
  const MatQ& A = H.A;
  const MatQ& B = H.B;
  const MatQ& C = H.C;
  const MatQ& D = H.D;
  MatQ M1(n + 2 * m, n + 2 * m);
  const MatQ AtP = exact_product(MatQ(A.transpose()), P);
  M1.topLeftCorner(n + m, n + m) = exact_product(AtP, A) - P;
  M1.topRightCorner(n + m, m) = exact_product(AtP, B) - exact_product(MatQ(C.transpose()), x.X) / 2;
  M1.bottomLeftCorner(m, n + m) = M1.topRightCorner(n + m, m).transpose();
  M1.bottomRightCorner(m, m) = exact_product(exact_product(MatQ(B.transpose()), P), B) -
                               (exact_product(x.X, D) + exact_product(MatQ(D.transpose()), x.X)) / 2 - x.QE;
  // facial equalities M1 [v_b; 0] = 0 for v_b = [Va b; b]
  MatQ Vk = MatQ::Zero(n + 2 * m, m);
  if (n) Vk.topRows(n) = sp.Va;
  Vk.block(n, 0, m, m) = MatQ::Identity(m, m);
  if (!exact_product(M1, Vk).isZero(0)) {
    why = "facial equality M1 v = 0 fails exactly";
    return false;
  }
  // With M1 Vk = 0 exactly and Vk = [Va; I; 0] (identity in rows n..n+m-1), the congruence by
  // the nonsingular T = [W, Vk], W = the unit vectors of the other rows, gives
  // T^T (-M1) T = blockdiag(W^T (-M1) W, 0). So "-M1 >= 0 with kernel exactly span(Vk) (rank
  // n+m)" holds iff the principal submatrix of -M1 without rows/columns n..n+m-1 is positive
  // definite: an exact fraction-free Bareiss test with exit at the first failing minor.
  MatQ Wm(n + m, n + m);
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < n; ++i) keep.push_back(i);
  for (Eigen::Index i = n + m; i < n + 2 * m; ++i) keep.push_back(i);
  for (size_t i = 0; i < keep.size(); ++i)
    for (size_t j = 0; j < keep.size(); ++j)
      Wm(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = -M1(keep[i], keep[j]);
  if (!lmi::exact_pd_bareiss(Wm)) {
    why = "-M1 >= 0 with kernel exactly the facial directions (rank n + m = " + std::to_string(n + m) +
          ") fails exactly: its block off the facial rows is not positive definite";
    return false;
  }
  const MatQ DD = pb.structure.delta_D();
  MatQ S(2 * m, 2 * m);
  S << exact_product(DD, x.X) - x.QE, -x.QE, -x.QE, QV - x.QE;
  if (!lmi::exact_pd_bareiss(S)) {
    why = "the scaled (14) > 0 fails exactly";
    return false;
  }
  if (!lmi::exact_pd_bareiss(QV)) {
    why = "Q_V > 0 fails exactly";
    return false;
  }
  for (int i = 0; i < m; ++i)
    if (x.X(i, i) < 1) {
      why = "g_i >= 1 fails exactly";
      return false;
    }
  why = "exact: P > 0, -M1 >= 0 with kernel exactly {[v_b; 0]} (rank n+m), the facial equalities, (14) > 0, "
        "Q_V > 0 and g_i >= 1 checked in rational arithmetic on the exact data (15)";
  return true;
}

MatrixXd gamma_inv_scale(const MatrixXd& Q, const MatrixXd& X) {
  MatrixXd Gi = MatrixXd::Zero(X.rows(), X.cols());
  for (Eigen::Index i = 0; i < X.rows(); ++i) Gi(i, i) = 1.0 / std::sqrt(X(i, i));
  return Gi * Q * Gi;
}

std::vector<double> gamma_sqrt(const Problem& pb, const MatrixXd& X) {
  std::vector<double> g;
  int off = 0;
  for (int s : pb.structure.operator_sizes()) {
    g.push_back(std::sqrt(X(off, off)));
    off += s;
  }
  return g;
}

VhatVars add_vhat(Program& prog, const StateSpace<rational>& V, const MatQ& K, const std::vector<MatQ>& Xk,
                  const std::vector<Expr>& theta, const Expr& QV) {
  VhatVars vv;
  vv.Vh = vhat(V, K);
  const int nb = static_cast<int>(V.states()), m = static_cast<int>(V.inputs());
  const rational T = V.T;
  const MatQ G = dc_gain(V) - K;  // V(1) - K
  MatQ Minv;
  if (nb) Minv = inverse(MatQ(V.A.transpose() - MatQ::Identity(nb, nb)), "A_V^T - I (V has a pole at z = 1)");
  Expr p1 = Expr::zero(nb, m), P22 = Expr::zero(m, m);
  for (size_t k = 0; k < Xk.size(); ++k) {
    const MatQ p1k = nb ? MatQ(Minv * V.C.transpose() * Xk[k] / 2) : MatQ(0, m);
    const MatQ P22k = G.transpose() * Xk[k] / (2 * T);
    vv.p1k.push_back(p1k);
    vv.P22k.push_back(P22k);
    const MatrixXd P22d = to_double(P22k);
    if (nb) p1 += scalar_times(theta[k], to_double(p1k));
    P22 += scalar_times(theta[k], MatrixXd(0.5 * (P22d + P22d.transpose())));
  }
  if (nb) {
    vv.P11 = prog.new_symmetric(nb, "P_V11");
    vv.PV = lmi::blocks({{Expr(vv.P11), p1}, {Expr(), P22}});
  } else {
    vv.PV = P22;
  }
  prog.add_lmi("P_V > 0 (storage of Vhat^Gamma)", vv.PV, Strictness::strict);
  // reduced Lemma 1 (state block): -(A^T P A - P + C^T Q_V C) > 0; the input rows follow from
  // the pinned blocks (the full matrix times [0; I; I] is exactly 0).
  const MatrixXd A = to_double(vv.Vh.A), C = to_double(vv.Vh.C);
  prog.add_lmi("Vhat^Gamma OSP (Lemma 1), reduced (facial reduction)",
              -1.0 * (A.transpose() * vv.PV * A - vv.PV + C.transpose() * QV * C), Strictness::strict);
  return vv;
}

MatQ lemma1_matrix(const StateSpace<rational>& Vh, const MatQ& P, const MatQ& X, const MatQ& QV) {
  const Eigen::Index nn = Vh.states(), m = Vh.inputs();
  const MatQ &A = Vh.A, &B = Vh.B, &C = Vh.C, &D = Vh.D;
  MatQ F(nn + m, nn + m);
  F.topLeftCorner(nn, nn) = A.transpose() * P * A - P + C.transpose() * QV * C;
  F.topRightCorner(nn, m) = A.transpose() * P * B - C.transpose() * X / 2 + C.transpose() * QV * D;
  F.bottomLeftCorner(m, nn) = F.topRightCorner(nn, m).transpose();
  F.bottomRightCorner(m, m) = B.transpose() * P * B - (X * D + D.transpose() * X) / 2 + D.transpose() * QV * D;
  return F;
}

bool exact_recheck_vhat(const VhatVars& vv, const std::vector<MatQ>& Xk, const std::vector<rational>& theta,
                        const MatQ& QV, const MatQ& P11, std::string& why) {
  const auto& Vh = vv.Vh;
  const Eigen::Index m = Vh.inputs(), nn = Vh.states(), nb = nn - m;
  MatQ X = MatQ::Zero(m, m), P = MatQ::Zero(nn, nn);
  for (size_t k = 0; k < Xk.size(); ++k) {
    X += theta[k] * Xk[k];
    if (nb) P.topRightCorner(nb, m) += theta[k] * vv.p1k[k];
    P.bottomRightCorner(m, m) += theta[k] * vv.P22k[k];
  }
  if (nb) {
    P.topLeftCorner(nb, nb) = P11;
    P.bottomLeftCorner(m, nb) = P.topRightCorner(nb, m).transpose();
  }
  if (P != MatQ(P.transpose())) {
    why = "X (V(1) - K) is not exactly symmetric";
    return false;
  }
  if (!lmi::exact_definiteness(P).pd) {
    why = "P_V > 0 fails exactly";
    return false;
  }
  const MatQ F = lemma1_matrix(Vh, P, X, QV);
  MatQ W = MatQ::Zero(nn + m, m);
  W.block(nb, 0, m, m) = MatQ::Identity(m, m);
  W.block(nn, 0, m, m) = MatQ::Identity(m, m);
  if (!MatQ(F * W).isZero(0)) {
    why = "Lemma 1 for Vhat: the facial equalities F [0; u; u] = 0 fail exactly";
    return false;
  }
  const auto d = lmi::exact_definiteness(MatQ(-F));
  if (!d.psd) {
    why = "Lemma 1 for Vhat: -F >= 0 fails exactly";
    return false;
  }
  why = "exact: P_V > 0 and Lemma 1 for Vhat^Gamma (-F >= 0, F [0; u; u] = 0, rank " + std::to_string(d.rank) +
        ") in rational arithmetic";
  return true;
}

}  // namespace detail

namespace {
// Scales an exact Theorem 5 point so that min g_i = 1 (the LMIs are homogeneous in
// (P, X, Q_E, Q_V); g_i >= 1 is the only inhomogeneous constraint, Remark 2).
rational normaliser(const MatQ& X) {
  rational mn = X(0, 0);
  for (Eigen::Index i = 1; i < X.rows(); ++i) mn = std::min(mn, X(i, i));
  return mn > 1 ? rational(1) / mn : rational(1);
}

// The solver's point of (16) -- environment side and Q_V -- in exact rationals, scaled by
// normaliser (min g_i = 1).
struct ScaledPoint {
  ExactEnv env;
  MatQ QV;
  rational scale;
};
ScaledPoint scaled_point(const lmi::CertifiedSolve& cs, const EnvVars& ev, const MatrixVariable& QV) {
  ScaledPoint p{exact_env(cs, ev), cs.point(QV), rational(1)};
  p.scale = normaliser(p.env.X);
  p.env.X *= p.scale;
  p.env.QE *= p.scale;
  p.env.P11 *= p.scale;
  for (auto& t : p.env.theta) t *= p.scale;
  p.QV *= p.scale;
  return p;
}

// The verdict of (16) before any point is re-checked: infeasible with solve()'s exact Farkas
// certificate (evidence `farkas`) or numerically ("numeric only"); otherwise the solver's
// outcome, numeric, no evidence yet.
Verdict unchecked_verdict(const lmi::CertifiedSolve& cs, const std::string& farkas) {
  if (cs.verdict.fails()) return {Outcome::fails, cs.verdict.status, cs.verdict.proven() ? farkas : "numeric only"};
  return {cs.verdict.outcome, Status::numeric, ""};
}

// The reported feasible point: X, Q_E, Q_V, Gamma and the coupling requirement delta_V.
void store_point(AnalysisResult& res, const Problem& pb, const MatQ& X, const MatQ& QE, const MatQ& QV) {
  res.X = to_double(X);
  res.Q_E = to_double(QE);
  res.Q_V = to_double(QV);
  res.gamma_sqrt = gamma_sqrt(pb, res.X);
  for (double g : res.gamma_sqrt) res.gamma.push_back(g * g);
  res.delta_V = gamma_inv_scale(res.Q_V, res.X);
}

// (16) in (P, X, Q_E, Q_V): the environment side, Q_V > 0 and the scaled (14).
void pose_16(Program& prog, const Problem& pb, const EhatSplit& sp, const FacialConditions& fc, EnvVars& ev,
             MatrixVariable& QV) {
  ev = add_environment(prog, pb, sp, fc);
  QV = pb.qv_block_diagonal ? prog.new_block_diagonal(pb.structure.operator_sizes(), "Q_V")
                            : prog.new_symmetric(pb.structure.m(), "Q_V");
  prog.add_lmi("Q_V > 0", Expr(QV), Strictness::strict);
  add_condition14(prog, pb, ev, Expr(QV));
}

// Stability-only mode (analysis.hpp): Q_E := Delta_D X eliminated; only P11, X (theta) remain.
void analyze_stability_only(const Problem& pb, const EhatSplit& sp, const lmi::Options& opt, AnalysisResult& res) {
  const int m = pb.structure.m();
  Program prog;
  const EnvVars ev = add_environment(prog, pb, sp, res.facial, true);
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, opt);
  res.sdp_seconds += cs.seconds;
  res.margin = cs.margin();
  res.solver_detail = cs.solver_text();
  res.verdict = unchecked_verdict(cs, "exact Farkas certificate of the posed (reduced) LMI with Q_E = Delta_D X "
                                      "(infeasible there implies (16) infeasible)");
  if (cs.verdict.fails() || !cs.has_point()) return;
  // mu: smallest eigenvalue of the reduced first LMI at the solver's point (original scale)
  double mu = INFINITY;
  for (size_t i = 0; i < prog.lmis().size(); ++i)
    if (prog.lmis()[i].name.rfind("(16) first LMI", 0) == 0) mu = std::min(mu, cs.result.min_eigenvalue[i]);
  ExactEnv x = exact_env(cs, ev);
  const rational s = normaliser(x.X);
  x.X *= s;
  x.P11 *= s;
  const MatQ DX = exact_product(pb.structure.delta_D(), x.X);
  std::string why = "the first LMI with Q_E = Delta_D X has no margin at the solver's point";
  bool ok = false;
  MatQ QV;
  for (double f : {0.5, 0.0625}) {
    if (!(mu > 0)) break;
    const rational eps = lmi::round_dyadic(f * mu * to_real<double>(s), 20);
    if (!(eps > 0)) break;
    x.QE = DX - eps * MatQ::Identity(m, m);
    QV = x.QE + exact_product(x.QE, x.QE) / eps + eps * MatQ::Identity(m, m);
    ok = exact_recheck(pb, sp, x, QV, why);
    if (ok) break;
  }
  if (ok && cs.margin() > 0)  // the exact check is the proof
    why += "; Q_E = Delta_D X - eps I and Q_V = Q_E + Q_E^2/eps + eps I constructed exactly (stability-only mode)";
  res.verdict = cs.recheck(ok, why);
  if (ok) store_point(res, pb, x.X, x.QE, QV);
}

// Full mode: (16) with margin, its point re-checked exactly on the rational data (15).
void analyze_margin(const Problem& pb, const EhatSplit& sp, const lmi::Options& opt, AnalysisResult& res) {
  Program prog;
  EnvVars ev;
  MatrixVariable QV;
  pose_16(prog, pb, sp, res.facial, ev, QV);
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, opt);
  res.sdp_seconds += cs.seconds;
  res.margin = cs.margin();
  res.solver_detail = cs.solver_text();
  res.verdict = unchecked_verdict(cs, "exact Farkas certificate of the posed (reduced) LMIs");
  if (cs.verdict.fails() || !cs.has_point()) return;
  const ScaledPoint p = scaled_point(cs, ev, QV);
  std::string why;
  const bool ok = exact_recheck(pb, sp, p.env, p.QV, why);
  res.verdict = cs.recheck(ok, why);
  store_point(res, pb, p.env.X, p.env.QE, p.QV);
}

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

// ---- the structured path (analysis.hpp, AnalysisPath::kyp_riccati) ----

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// X pinned by the facial conditions to one direction, scaled so that min g_i = 1, and the first
// LMI of (16) as the KYP data of lmi/kyp.hpp for Q_E = 0: A = A_E, B = B_t, S = C_E^T X / 2,
// R = F22 (a Q_E then enters as R - Q_E).
struct Pinned {
  MatQ X;
  rational theta;  // X = theta X_1 (X_1 = scalar_blocks(gamma_basis[0]))
  lmi::KypData kyp;
};

std::optional<Pinned> pinned_x(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc) {
  if (fc.gamma_basis.size() != 1) return std::nullopt;
  const MatQ X1 = pb.structure.scalar_blocks(fc.gamma_basis[0]);
  rational mn = X1(0, 0);
  for (Eigen::Index i = 0; i < X1.rows(); ++i) mn = std::min(mn, X1(i, i));
  if (!(mn > 0)) return std::nullopt;  // X > 0 impossible along this direction
  Pinned px;
  px.theta = rational(1) / mn;
  px.X = px.theta * X1;
  const int n = static_cast<int>(pb.E.states());
  const double Td = to_real<double>(pb.T());
  const MatrixXd X = to_double(px.X), E1 = to_double(sp.E1), DE = to_double(pb.E.D);
  px.kyp.A = to_double(MatQ(sp.t.A.topLeftCorner(n, n)));
  px.kyp.B = to_double(MatQ(sp.t.B.topRows(n)));
  px.kyp.S = 0.5 * to_double(MatQ(sp.t.C.leftCols(n))).transpose() * X;
  const MatrixXd XE1s = 0.5 * (X * E1 + E1.transpose() * X);
  px.kyp.R = (Td / 2) * XE1s - (Td / 2) * (X * DE + DE.transpose() * X);
  return px;
}

// The Riccati point P11 rounded to dyadic rationals: the fewest bits (24, 32, 44, 52) whose
// rounding moves lambda_min of the first LMI by at most a tenth of its margin (double check;
// the exact re-check decides).
MatQ rounded_p11(const lmi::KypData& d, const lmi::KypPoint& kp) {
  const Eigen::Index n = kp.P.rows();
  MatQ R(n, n);
  for (int bits : {24, 32, 44, 52}) {
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = 0; i <= j; ++i) R(i, j) = R(j, i) = lmi::round_dyadic(kp.P(i, j), bits);
    if (std::abs(lmi::kyp_min_eigenvalue(d, to_double(R)) - kp.min_eig) <= 0.1 * kp.min_eig) break;
  }
  return R;
}

// Theorem 5's verdict by the structured path: the stability-only elimination (Q_E := Delta_D X,
// analysis.hpp) with P11 from the Riccati equation of lmi/kyp.hpp, then Q_E = Delta_D X - eps I,
// Q_V = Q_E + Q_E^2/eps + eps I and the exact re-check. False (res untouched) when the path
// finds no point that passes: the caller falls back to the generic SDP.
bool kyp_verdict(const Problem& pb, const EhatSplit& sp, const Pinned& px, AnalysisResult& res) {
  const int m = pb.structure.m();
  const MatQ DX = exact_product(pb.structure.delta_D(), px.X);
  lmi::KypData d = px.kyp;
  d.R -= to_double(DX);
  const auto t0 = std::chrono::steady_clock::now();
  const lmi::KypPoint kp = lmi::kyp_interior_point(d);
  const double numeric = since(t0);
  res.sdp_seconds += numeric;
  if (!kp.found) return false;
  ExactEnv x;
  x.X = px.X;
  x.theta = {px.theta};
  x.P11 = rounded_p11(d, kp);
  std::string why;
  MatQ QV;
  bool ok = false;
  for (double f : {0.5, 0.0625}) {
    const rational eps = lmi::round_dyadic(f * kp.min_eig, 20);
    if (!(eps > 0)) break;
    x.QE = DX - eps * MatQ::Identity(m, m);
    QV = x.QE + exact_product(x.QE, x.QE) / eps + eps * MatQ::Identity(m, m);
    ok = exact_recheck(pb, sp, x, QV, why);
    if (ok) {
      res.margin = kp.min_eig - to_real<double>(eps);
      break;
    }
  }
  if (!ok) return false;
  std::ostringstream o;
  o << "structured KYP path (X pinned to one direction by the facial conditions, min g_i = 1): P11 from the "
       "Riccati equation of (16)'s first LMI with Q_E = Delta_D X (lmi/kyp.hpp: "
    << kp.riccati_solves << " DARE solve(s), " << kp.detail << "), " << numeric << " s";
  res.solver_detail = o.str();
  res.verdict = {Outcome::holds, Status::exact,
                 why + "; Q_E = Delta_D X - eps I and Q_V = Q_E + Q_E^2/eps + eps I constructed exactly, P11 from a "
                       "Riccati equation (structured path)"};
  store_point(res, pb, x.X, x.QE, QV);
  return true;
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
std::optional<KypMinPoint> least_dissipative_point(const Problem& pb, const EhatSplit& sp, const Pinned& px,
                                                   bool diagonal) {
  const int m = pb.structure.m();
  const MatQ DX = exact_product(pb.structure.delta_D(), px.X);
  const bool scalar = DX == MatQ(DX(0, 0) * MatQ::Identity(m, m));
  if (!scalar && !(diagonal && DX.isDiagonal(0))) return std::nullopt;
  // Q_E = t G: G = I and t = r in (lo, d) when Delta_D X = d I; G = Delta_D X and t = s in (lo, 1)
  // otherwise. lo: -(R - t G) must be > 0, i.e. t > lambda_max(G^-1/2 R G^-1/2); the upper end is
  // feasible (the verdict).
  const MatQ G = scalar ? MatQ(MatQ::Identity(m, m)) : DX;
  const rational t_end = scalar ? DX(0, 0) : rational(1);
  const double d = to_real<double>(t_end);
  const MatrixXd Gd = to_double(G);
  const Eigen::VectorXd gi = Gd.diagonal().cwiseSqrt().cwiseInverse();
  auto data = [&](double t) {
    lmi::KypData k = px.kyp;
    k.R -= t * Gd;
    return k;
  };
  const MatrixXd Rs = gi.asDiagonal() * (0.5 * (px.kyp.R + px.kyp.R.transpose())) * gi.asDiagonal();
  Eigen::SelfAdjointEigenSolver<MatrixXd> es(Rs, Eigen::EigenvaluesOnly);
  double lo = es.eigenvalues()(m - 1), hi = d;
  const double width = hi - lo;
  if (!(width > 0)) return std::nullopt;
  const auto t0 = std::chrono::steady_clock::now();
  int solves = 0;
  while (hi - lo > 1e-7 * width && solves < 60) {
    const double mid = 0.5 * (lo + hi);
    ++solves;
    (lmi::kyp_riccati_point(data(mid), 1e-9 * width).found ? hi : lo) = mid;
  }
  // the point: t_c a little above the least t, where the LMI has room for a rounded point
  const rational tc = lmi::round_dyadic(std::min(d, hi + 1e-6 * width), 30);
  if (!(tc < t_end)) return std::nullopt;  // (14) needs Delta_D X - Q_E > 0
  const lmi::KypData k = data(to_real<double>(tc));
  const lmi::KypPoint kp = lmi::kyp_interior_point(k);
  if (!kp.found) return std::nullopt;
  KypMinPoint p;
  p.numeric_seconds = since(t0);
  p.r = tc;
  p.env.X = px.X;
  p.env.theta = {px.theta};
  p.env.P11 = rounded_p11(k, kp);
  p.env.QE = tc * G;
  const rational e = lmi::round_dyadic(1e-9 * std::max(1.0, to_real<double>(DX(0, 0))), 20);
  p.QV = MatQ::Zero(m, m);
  for (int i = 0; i < m; ++i) {
    const rational q = p.env.QE(i, i);
    const rational f = q * DX(i, i) / (DX(i, i) - q);  // Q_E + Q_E (Delta_D X - Q_E)^-1 Q_E, channel i
    p.QV(i, i) = (f > 0 ? f : rational(0)) + e;
  }
  p.certified = exact_recheck(pb, sp, p.env, p.QV, p.why);
  p.riccati_solves = solves + kp.riccati_solves;
  return p;
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

bool use_kyp(const Problem& pb, const lmi::Options& opt, AnalysisPath path) {
  if (path == AnalysisPath::generic_sdp || pb.qv_block_diagonal) return false;
  if (path == AnalysisPath::kyp_riccati) return true;
  return opt.backend == lmi::Backend::automatic && pb.structure.m() >= kKypMinDof;
}

}  // namespace

std::optional<detail::KypMinPoint> detail::kyp_min_point(const Problem& pb, const EhatSplit& sp, const FacialConditions& fc) {
  const std::optional<Pinned> px = pinned_x(pb, sp, fc);
  if (!px) return std::nullopt;
  return least_dissipative_point(pb, sp, *px, true);
}

void check_generic_size(const Problem& pb, long extra_unknowns, const std::string& what) {
  const long n = static_cast<long>(pb.E.states());
  const double v = static_cast<double>(n) * (n + 1) / 2 + static_cast<double>(extra_unknowns);
  const double bytes = 8 * v * v;
  if (bytes > limits::generic_sdp_bytes) {
    std::ostringstream o;
    o.precision(3);
    o << what << " for an environment realisation of order " << n
      << " (with any [delay] folded in) has about " << v << " scalar unknowns: its Schur complement would need "
      << bytes / 1e9 << " GB, more than the limit of " << limits::generic_sdp_bytes / 1e9
      << " GB. The structured path (X pinned to one direction by the facial conditions, from " << kKypMinDof
      << " DOF) avoids it; a shorter [delay] or a smaller environment fits";
    throw InputError(o.str());
  }
}

AnalysisResult analyze(const Problem& pb, const lmi::Options& opt, AnalysisMode mode, AnalysisPath path) {
  pb.validate(false);
  AnalysisResult res;
  const auto start = std::chrono::steady_clock::now();
  struct Stamp {  // res.seconds on every return
    AnalysisResult& r;
    std::chrono::steady_clock::time_point t0;
    ~Stamp() { r.seconds = since(t0); }
  } stamp{res, start};
  res.facial = facial_conditions(pb);
  if (!res.facial.symmetric_possible) {
    res.verdict = {Outcome::fails, Status::exact, "exact: " + res.facial.explanation};
    return res;
  }
  const EhatSplit sp = ehat_split(pb.E);
  if (use_kyp(pb, opt, path)) {
    const std::optional<Pinned> px = pinned_x(pb, sp, res.facial);
    if (px && kyp_verdict(pb, sp, *px, res)) {
      if (mode == AnalysisMode::full && !kyp_least_dissipative(pb, sp, *px, res)) {
        try {
          check_generic_size(pb, 2L * pb.structure.m() * (pb.structure.m() + 1), "the least dissipative coupling's SDP");
          least_dissipative(pb, sp, opt, res);
        } catch (const InputError& e) {  // the verdict stands; only the optional minimisation is skipped
          res.solver_detail += std::string("; least dissipative coupling not searched: ") + e.what();
        }
      }
      return res;
    }
  }
  check_generic_size(pb, pb.structure.m() * (pb.structure.m() + 1), "Theorem 5's generic SDP (16)");
  if (mode == AnalysisMode::stability_only && !pb.qv_block_diagonal) {
    analyze_stability_only(pb, sp, opt, res);
    return res;
  }
  analyze_margin(pb, sp, opt, res);
  if (!res.verdict.holds() || mode == AnalysisMode::stability_only) return res;
  least_dissipative(pb, sp, opt, res);
  return res;
}

CouplingCheck check_theorem4(const Problem& pb, const StateSpace<rational>& V, const lmi::Options& opt) {
  pb.validate(false);
  CouplingCheck cc;
  const int m = pb.structure.m();
  if (V.inputs() != m || V.outputs() != m)
    throw InputError("coupling V must be " + std::to_string(m) + "x" + std::to_string(m) + " (the environment's m)");
  if (V.T != pb.T()) throw InputError("coupling V and environment E have different sample periods");
  const MatQ K = pb.structure.K(pb.T());
  const FacialConditions fc = facial_conditions(pb, {MatQ(dc_gain(V) - K)});
  if (!fc.symmetric_possible) {
    cc.verdict = {Outcome::fails, Status::exact, "exact: " + fc.explanation};
    return cc;
  }
  check_generic_size(pb, m * (m + 1) + static_cast<long>(V.states() + m) * (V.states() + m + 1) / 2,
                     "Theorem 4's program for the coupling");
  const EhatSplit sp = ehat_split(pb.E);
  Program prog;
  EnvVars ev = add_environment(prog, pb, sp, fc);
  const MatrixVariable QV = prog.new_symmetric(m, "Q_V");
  prog.add_lmi("Q_V > 0 (Delta_V > 0)", Expr(QV), Strictness::strict);
  add_condition14(prog, pb, ev, Expr(QV));
  std::vector<Expr> th;
  for (const auto& t : ev.theta) th.emplace_back(t);
  const VhatVars vv = add_vhat(prog, V, K, ev.Xk, th, Expr(QV));
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, opt);
  cc.verdict = cs.verdict;
  cc.margin = cs.margin();
  if (cs.verdict.fails() || !cs.has_point()) return cc;
  const ScaledPoint p = scaled_point(cs, ev, QV);
  MatQ P11v = vv.P11.rows > 0 ? cs.point(vv.P11) : MatQ(0, 0);
  P11v *= p.scale;
  std::string why1, why2;
  const bool ok1 = exact_recheck(pb, sp, p.env, p.QV, why1);
  const bool ok2 = ok1 && exact_recheck_vhat(vv, ev.Xk, p.env.theta, p.QV, P11v, why2);
  cc.verdict = cs.recheck(ok1 && ok2, cs.solver_text() + " | environment side: " + why1 +
                                          (ok1 ? " | coupling side: " + why2 : ""));
  const MatrixXd X = to_double(p.env.X);
  cc.gamma_sqrt = gamma_sqrt(pb, X);
  cc.Q_V = to_double(p.QV);
  cc.delta_V = gamma_inv_scale(cc.Q_V, X);
  return cc;
}

OspCheck detail::check_vhat_lemma1(const StateSpace<rational>& V, const MatQ& K, const MatQ& X, const MatQ& Q,
                                   const lmi::Options& opt) {
  OspCheck oc;
  const MatQ S = X * MatQ(dc_gain(V) - K);
  if (S != MatQ(S.transpose())) {
    oc.verdict = {Outcome::fails, Status::exact,
                  "exact: X (V(1) - K) is not symmetric, so no storage function can satisfy Lemma 1's facial equalities"};
    return oc;
  }
  Program prog;
  const MatrixVariable one = prog.new_scalar("unit");
  prog.add_linear_equality("unit = 1", Expr(one), MatrixXd::Ones(1, 1));
  const VhatVars vv = add_vhat(prog, V, K, {X}, {Expr(one)}, Expr(to_double(Q)));
  prog.set_margin_objective(1.0);
  const lmi::CertifiedSolve cs = lmi::certify_lmi(prog, opt);
  oc.verdict = cs.verdict;
  oc.margin = cs.margin();
  if (cs.verdict.fails() || !cs.has_point()) return oc;
  const MatQ P11 = vv.P11.rows > 0 ? cs.point(vv.P11) : MatQ(0, 0);
  std::string why;
  const bool ok = exact_recheck_vhat(vv, {X}, {rational(1)}, Q, P11, why);
  oc.verdict = cs.recheck(ok, cs.solver_text() + " | " + why);
  return oc;
}

OspCheck check_vhat_osp(const StateSpace<rational>& V, const MatQ& K, const MatQ& Gamma, const MatQ& Delta,
                        const lmi::Options& opt) {
  return check_vhat_lemma1(V, K, MatQ(Gamma * Gamma), MatQ(Gamma * Delta * Gamma), opt);
}

OspLevel detail::osp_level_bisection(const std::function<bool(double)>& certified_at) {
  OspLevel l;
  auto ok = [&](double d) { return certified_at(to_real<double>(lmi::round_dyadic(d, 30))); };
  double lo = 0, hi = 1;
  if (!ok(0)) {
    l.verdict = {Outcome::undecided, Status::numeric, "Vhat is not certified passive (delta = 0 fails): no positive OSP level"};
    return l;
  }
  int guard = 0;
  while (ok(hi) && guard++ < 40) {
    lo = hi;
    hi *= 4;
  }
  for (int it = 0; it < 30 && (hi - lo) > 1e-7 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ok(mid) ? lo : hi) = mid;
  }
  l.delta = to_real<double>(lmi::round_dyadic(lo, 30));
  l.upper = hi;
  l.verdict = {Outcome::holds, Status::exact,
               "bisection on Lemma 1 (non-strict, facial reduction): level >= delta certified exactly"};
  return l;
}

OspLevel vhat_osp_level(const StateSpace<rational>& V, const MatQ& K, const lmi::Options& opt) {
  const Eigen::Index m = V.inputs();
  const MatQ I = MatQ::Identity(m, m);
  return detail::osp_level_bisection([&](double d) {
    const OspCheck c = check_vhat_osp(V, K, I, rational(d) * I, opt);
    return c.verdict.holds() && c.verdict.proven();
  });
}

}  // namespace hapstab::multidof
