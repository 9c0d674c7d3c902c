#include "hapstab/multidof/environment.hpp"

#include "hapstab/numeric/lyapunov.hpp"

#include <algorithm>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

namespace hapstab::multidof {


void MechanicalEnvironment::validate() const {
  if (kc.empty()) throw InputError("environment: no contact point (give k_i, B_i for each DOF)");
  if (kc.size() != Bc.size())
    throw InputError("environment: " + std::to_string(kc.size()) + " contact springs but " +
                     std::to_string(Bc.size()) + " contact dampers");
  if (M <= 0) throw InputError("environment: mass M must be > 0");
  if (k < 0 || B < 0) throw InputError("environment: k and B must be >= 0");
  for (size_t i = 0; i < kc.size(); ++i)
    if (kc[i] < 0 || Bc[i] < 0)
      throw InputError("environment: contact " + std::to_string(i + 1) + " has a negative spring or damper");
}

TransferMatrix mechanical_impedance(const MechanicalEnvironment& env) {
  env.validate();
  const size_t m = env.kc.size();
  rational Bs = env.B, ks = env.k;
  for (size_t i = 0; i < m; ++i) {
    Bs += env.Bc[i];
    ks += env.kc[i];
  }
  const QPoly den(std::vector<rational>{ks, Bs, env.M});
  std::vector<QPoly> Z(m);
  for (size_t i = 0; i < m; ++i) Z[i] = QPoly(std::vector<rational>{env.kc[i], env.Bc[i]});
  TransferMatrix E;
  E.domain = Domain::s;
  E.T = 0;
  E.entries.assign(m, std::vector<TransferFunction>(m));
  for (size_t i = 0; i < m; ++i)
    for (size_t j = 0; j < m; ++j) {
      QPoly num = -(Z[i] * Z[j]);
      if (i == j) num += Z[i] * den;
      E.entries[i][j] = tf(num, den, 0);
    }
  return E;
}

namespace {
// p(s) with s = a(z)/b(z), times b(z)^d: sum_k p_k a^k b^(d-k).
QPoly substitute(const QPoly& p, const QPoly& a, const QPoly& b, int d) {
  QPoly r;
  for (int k = 0; k <= p.degree(); ++k) r += p.coeff(k) * (a.pow(static_cast<unsigned>(k)) * b.pow(static_cast<unsigned>(d - k)));
  return r;
}
}  // namespace

TransferMatrix c2d(const TransferMatrix& Hs, const rational& T, C2dMethod method) {
  if (Hs.domain != Domain::s) throw InputError("c2d: the transfer matrix is already discrete");
  if (T <= 0) throw InputError("c2d: sample period T must be > 0");
  QPoly a, b;
  if (method == C2dMethod::backward_euler) {
    a = QPoly(std::vector<rational>{rational(-1), rational(1)});  // z - 1
    b = QPoly(std::vector<rational>{rational(0), T});             // T z
  } else if (method == C2dMethod::tustin) {
    a = QPoly(std::vector<rational>{rational(-2) / T, rational(2) / T});  // (2/T)(z - 1)
    b = QPoly(std::vector<rational>{rational(1), rational(1)});           // z + 1
  } else {
    throw InputError("c2d: ZOH of a transfer matrix in s is refused here: the contact dampers make E(s) improper "
                     "(B_i s); give a proper continuous state space, or use backward_euler or tustin");
  }
  TransferMatrix Hz;
  Hz.domain = Domain::z;
  Hz.T = T;
  Hz.entries.assign(Hs.outputs(), std::vector<TransferFunction>(Hs.inputs()));
  for (size_t i = 0; i < Hs.outputs(); ++i)
    for (size_t j = 0; j < Hs.inputs(); ++j) {
      const auto& e = Hs.entries[i][j];
      const int d = std::max(e.num().degree(), e.den().degree());
      QPoly n = substitute(e.num(), a, b, d), q = substitute(e.den(), a, b, d);
      if (q.is_zero()) throw InputError("c2d: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") has a pole at the substitution's singular point");
      Hz.entries[i][j] = tf(n, q, T);
      if (!Hz.entries[i][j].is_proper())
        throw InputError("c2d: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ") is not causal after discretisation");
    }
  return Hz;
}

StateSpace<rational> minimal_ss(const TransferMatrix& Hz) { return minreal(tf2ss(Hz)); }

StateSpace<rational> mechanical_environment(const MechanicalEnvironment& env, const rational& T, C2dMethod method) {
  return minimal_ss(c2d(mechanical_impedance(env), T, method));
}

StateSpace<rational> mechanical_environment_be_ss(const MechanicalEnvironment& env, const rational& T) {
  env.validate();
  if (T <= 0) throw InputError("environment: sample period T must be > 0");
  const int m = static_cast<int>(env.kc.size());
  rational Ks = env.k, Bs = env.B;
  for (int i = 0; i < m; ++i) {
    Ks += env.kc[static_cast<size_t>(i)];
    Bs += env.Bc[static_cast<size_t>(i)];
  }
  // backward Euler: y_k = y_{k-1} + T v_k,
  // M (v_k - v_{k-1})/T = -K_s y_k - B_s v_k + sum_i (k_i + B_i/T) x_{i,k} - (B_i/T) x_{i,k-1}
  const rational alpha = env.M / T + Ks * T + Bs;
  MatQ A = MatQ::Zero(m + 2, m + 2), B = MatQ::Zero(m + 2, m), C = MatQ::Zero(m, m + 2), D = MatQ::Zero(m, m);
  // v_k = ay y + av v + ax' x_prev + cu' u
  const rational ay = -Ks / alpha, av = env.M / T / alpha;
  std::vector<rational> ax(static_cast<size_t>(m)), cu(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    ax[static_cast<size_t>(i)] = -(env.Bc[static_cast<size_t>(i)] / T) / alpha;
    cu[static_cast<size_t>(i)] = (env.kc[static_cast<size_t>(i)] + env.Bc[static_cast<size_t>(i)] / T) / alpha;
  }
  // row 1: v_k
  A(1, 0) = ay;
  A(1, 1) = av;
  for (int i = 0; i < m; ++i) {
    A(1, 2 + i) = ax[static_cast<size_t>(i)];
    B(1, i) = cu[static_cast<size_t>(i)];
  }
  // row 0: y_k = y + T v_k
  A.row(0) = T * A.row(1);
  A(0, 0) += 1;
  B.row(0) = T * B.row(1);
  // x_k = u
  for (int i = 0; i < m; ++i) B(2 + i, i) = 1;
  // f_i = (k_i + B_i/T) u_i - k_i y - (k_i T + B_i) v_k - (B_i/T) x_prev_i
  for (int i = 0; i < m; ++i) {
    const rational ki = env.kc[static_cast<size_t>(i)], bi = env.Bc[static_cast<size_t>(i)];
    C.row(i) = -(ki * T + bi) * A.row(1);
    D.row(i) = -(ki * T + bi) * B.row(1);
    C(i, 0) -= ki;
    C(i, 2 + i) -= bi / T;
    D(i, i) += ki + bi / T;
  }
  return {A, B, C, D, T};
}

bool schur_stable(const MatQ& A, std::string* method) {
  if (A.rows() >= kLyapunovFromStates && lyapunov_proves_schur_stable(A)) {
    if (method) *method = "Lyapunov certificate: P > 0, P - A^T P A > 0 by ball Cholesky on the exact A";
    return true;
  }
  if (method) *method = "Schur-Cohn on the exact det(zI - A)";
  return A.rows() == 0 || hapstab::schur_stable(charpoly(A));
}

MatQ dc_gain(const StateSpace<rational>& E) {
  const auto n = E.states();
  if (n == 0) return E.D;
  const MatQ Va = exact_solve(MatQ(MatQ::Identity(n, n) - E.A), E.B, "I - A_E (E has a pole at z = 1)");
  return MatQ(exact_product(E.C, Va) + E.D);
}

StateSpace<rational> ehat(const StateSpace<rational>& E) {
  E.validate("environment E");
  if (E.inputs() != E.outputs())
    throw InputError("environment E must be square (m inputs, m outputs), got " + std::to_string(E.outputs()) + "x" +
                     std::to_string(E.inputs()));
  if (!E.is_discrete()) throw InputError("environment E must be discrete (T > 0) for (15)");
  const auto n = E.states(), m = E.inputs();
  const rational& T = E.T;
  StateSpace<rational> H;
  H.T = T;
  H.A = MatQ::Zero(n + m, n + m);
  H.A.topLeftCorner(n, n) = E.A;
  H.A.topRightCorner(n, m) = E.B;
  H.A.bottomRightCorner(m, m) = MatQ::Identity(m, m);
  H.B = MatQ::Zero(n + m, m);
  H.B.topRows(n) = E.B * T;
  H.B.bottomRows(m) = MatQ::Identity(m, m) * T;
  H.C = MatQ::Zero(m, n + m);
  H.C.leftCols(n) = E.C;
  H.C.rightCols(m) = E.D;
  H.D = E.D * T;
  return H;
}

StateSpace<rational> scale_gamma(const StateSpace<rational>& s, const MatQ& G) {
  const MatQ Gi = inverse(G, "Gamma");
  return {s.A, s.B * Gi, G * s.C, G * s.D * Gi, s.T};
}

StateSpace<rational> vhat(const StateSpace<rational>& V, const MatQ& K) {
  V.validate("coupling V");
  if (!V.is_discrete()) throw InputError("coupling V must be discrete (T > 0) for (17)");
  if (V.inputs() != V.outputs()) throw InputError("coupling V must be square");
  const auto n = V.states(), m = V.inputs();
  if (K.rows() != m || K.cols() != m)
    throw InputError("coupling V has " + std::to_string(m) + " ports but K is " + std::to_string(K.rows()) + "x" +
                     std::to_string(K.cols()));
  const rational& T = V.T;
  StateSpace<rational> H;
  H.T = T;
  H.A = MatQ::Zero(n + m, n + m);
  H.A.topLeftCorner(n, n) = V.A;
  H.A.topRightCorner(n, m) = -V.B / T;
  H.B = MatQ::Zero(n + m, m);
  H.B.topRows(n) = V.B / T;
  H.B.bottomRows(m) = MatQ::Identity(m, m);
  H.C = MatQ::Zero(m, n + m);
  H.C.leftCols(n) = V.C;
  H.C.rightCols(m) = (K - V.D) / T;
  H.D = (V.D - K) / T;
  return H;
}

StateSpace<rational> coupling_from_gamma(const StateSpace<rational>& VG, const MatQ& G) {
  const MatQ Gi = inverse(G, "Gamma");
  return {VG.A, VG.B * G, Gi * VG.C, Gi * VG.D * G, VG.T};
}

EhatSplit ehat_split(const StateSpace<rational>& E) {
  const StateSpace<rational> H = ehat(E);
  const auto n = E.states(), m = E.inputs();
  EhatSplit s;
  s.Va = n ? exact_solve(MatQ(MatQ::Identity(n, n) - E.A), E.B, "I - A_E (E has a pole at z = 1)") : MatQ(0, m);
  s.Pi0 = MatQ::Identity(n + m, n + m);
  if (n) s.Pi0.topRightCorner(n, m) = s.Va;
  // Pi0^-1 H Pi0 by blocks (Pi0 = [[I, Va], [0, I]], Pi0^-1 = [[I, -Va], [0, I]]): with
  // H.A = [[A_E, B_E], [0, I]], H.B = [B_E T; T I], H.C = [C_E, D_E] the transformed system is
  //   A = [[A_E, A_E Va + B_E - Va], [0, I]],  B = [(B_E - Va) T; T I],  C = [C_E, C_E Va + D_E],
  // the same exact entries as the dense triple product in O(n^2 m) instead of O((n + m)^3). The
  // top-right block of A is (A_E - I) Va + B_E = 0 by the definition of Va (computed, not assumed);
  // C_E Va + D_E is E(1).
  const MatQ AVa = exact_product(E.A, s.Va), CVa = exact_product(E.C, s.Va);
  s.E1 = n ? MatQ(CVa + E.D) : E.D;
  s.t = H;
  if (n) {
    s.t.A.topRightCorner(n, m) = AVa + E.B - s.Va;
    s.t.B.topRows(n) = (E.B - s.Va) * E.T;
  }
  s.t.C.rightCols(m) = s.E1;
  return s;
}

StateSpace<rational> blockdiag(const std::vector<StateSpace<rational>>& bl) {
  Eigen::Index n = 0, p = 0, q = 0;
  for (const auto& b : bl) {
    n += b.states();
    p += b.outputs();
    q += b.inputs();
  }
  StateSpace<rational> s{MatQ::Zero(n, n), MatQ::Zero(n, q), MatQ::Zero(p, n), MatQ::Zero(p, q),
                         bl.empty() ? rational(0) : bl[0].T};
  Eigen::Index a = 0, o = 0, i = 0;
  for (const auto& b : bl) {
    s.A.block(a, a, b.states(), b.states()) = b.A;
    s.B.block(a, i, b.states(), b.inputs()) = b.B;
    s.C.block(o, a, b.outputs(), b.states()) = b.C;
    s.D.block(o, i, b.outputs(), b.inputs()) = b.D;
    a += b.states();
    o += b.outputs();
    i += b.inputs();
  }
  return s;
}

}  // namespace hapstab::multidof
