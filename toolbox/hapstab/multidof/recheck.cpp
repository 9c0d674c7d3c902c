// hapstab/multidof/recheck.cpp -- the ONE exact re-check of a Theorem 5 point (planner.hpp): every
// path's candidate (P11, X, Q_E, Q_V) becomes a proof only here, in rational arithmetic on the
// exact data (15): P > 0, -M1 >= 0 with kernel exactly the facial directions [v_b; 0], the facial
// equalities M1 [v_b; 0] = 0, the scaled (14) > 0, Q_V > 0 and g_i >= 1 (analysis.hpp).
//
// Implements: paper 000 (14), (16) (Theorem 5), checked exactly.
#include <string>
#include <vector>

#include "hapstab/multidof/detail.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

namespace hapstab::multidof::detail {

MatQ storage_of(const Problem& pb, const EhatSplit& sp, const ExactEnv& x) {
  const int m = pb.structure.m();
  const int n = static_cast<int>(pb.E.states());
  const rational T = pb.T();
  // P = Pi0^-T blockdiag(P11, X E(1)/(2T)) Pi0^-1
  MatQ Pt = MatQ::Zero(n + m, n + m);
  if (n) Pt.topLeftCorner(n, n) = x.P11;
  Pt.bottomRightCorner(m, m) = exact_product(x.X, sp.E1) / (2 * T);
  // Pi0 = [[I, Va], [0, I]] has the exact inverse [[I, -Va], [0, I]] (no elimination needed)
  MatQ Pi0i = MatQ::Identity(n + m, n + m);
  if (n) Pi0i.topRightCorner(n, m) = -sp.Va;
  return exact_product(exact_product(MatQ(Pi0i.transpose()), Pt), Pi0i);
}

bool exact_recheck(const Problem& pb, const EhatSplit& sp, const ExactEnv& x, const MatQ& QV, std::string& why) {
  const int m = pb.structure.m();
  const int n = static_cast<int>(pb.E.states());
  const rational T = pb.T();
  const StateSpace<rational> H = ehat(pb.E);
  const MatQ P = storage_of(pb, sp, x);
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

}  // namespace hapstab::multidof::detail

namespace hapstab::multidof {

ExactStorage exact_storage(const Problem& pb, const ExactPoint& x) {
  detail::ExactEnv env;
  env.P11 = x.P11;
  env.X = x.X;
  env.QE = x.QE;
  return {ehat(pb.E), detail::storage_of(pb, ehat_split(pb.E), env)};
}

}  // namespace hapstab::multidof
