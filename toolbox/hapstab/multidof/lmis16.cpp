// hapstab/multidof/lmis16.cpp -- the LMIs (16) posed in hapstab::lmi (analysis.hpp): the
// environment side in the split coordinates of ehat_split with the facial reduction imposed
// exactly, the scaled (14), and the solver's point read back in exact rationals (detail.hpp).
// The generic SDP path, the least dissipative program, Theorem 4's program and Theorem 6's
// design pose their programs with these.
#include <algorithm>

#include "hapstab/multidof/detail.hpp"

namespace hapstab::multidof::detail {

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

rational normaliser(const MatQ& X) {
  rational mn = X(0, 0);
  for (Eigen::Index i = 1; i < X.rows(); ++i) mn = std::min(mn, X(i, i));
  return mn > 1 ? rational(1) / mn : rational(1);
}


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

void store_point(AnalysisResult& res, const Problem& pb, const MatQ& X, const MatQ& QE, const MatQ& QV) {
  res.X = to_double(X);
  res.Q_E = to_double(QE);
  res.Q_V = to_double(QV);
  res.gamma_sqrt = gamma_sqrt(pb, res.X);
  for (double g : res.gamma_sqrt) res.gamma.push_back(g * g);
  res.delta_V = gamma_inv_scale(res.Q_V, res.X);
}

void pose_16(Program& prog, const Problem& pb, const EhatSplit& sp, const FacialConditions& fc, EnvVars& ev,
             MatrixVariable& QV) {
  ev = add_environment(prog, pb, sp, fc);
  QV = pb.qv_block_diagonal ? prog.new_block_diagonal(pb.structure.operator_sizes(), "Q_V")
                            : prog.new_symmetric(pb.structure.m(), "Q_V");
  prog.add_lmi("Q_V > 0", Expr(QV), Strictness::strict);
  add_condition14(prog, pb, ev, Expr(QV));
}


}  // namespace hapstab::multidof::detail
