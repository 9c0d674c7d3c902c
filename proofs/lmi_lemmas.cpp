// proofs/lmi_lemmas.cpp -- paper 000, Lemmas 1 and 2 (discrete-time KYP, OSP/ISP levels).
//
// Schur steps (exact, rational data): with W = [[P, C'/2], [C/2, (D+D')/2 - Phi]] and
// N = [[A, B], [C, D]],
//   (i)   -M(P) = W - N' blockdiag(P, Delta) N            (M = Lemma 1's matrix (2)),
//   (ii)  W - N' diag(P, Delta) N > 0  <=>  [[W, N'], [N, diag(P^{-1}, Delta^{-1})]] > 0
//         (Schur complement on the positive definite lower-right block),
//   (iii) the latter is Lemma 2's [[Q^{-1}, R'], [R, S]] > 0 with Q = P^{-1}, R = [C/2; A; C],
//         S = [[(D+D')/2 - Phi, B', D'], [B, Q, 0], [D, 0, Delta^{-1}]] (a permutation), and
//   (iv)  that is equivalent to S - R Q R' > 0 (Schur complement on Q^{-1} > 0), the LMI in Q
//         that lmi/passivity_level.cpp solves.
// Hence S's top-left block is (D+D')/2 - Phi: the transcription's "+Phi" is a typo, refuted
// below on a system that is not ISP but passes the transcribed test.
//
// For every value (issue 40): (i) and the block form of (iii) -- Lemma 2's [[P, R'], [R, S]] is
// [[W, N'], [N, diag(Q, Delta^{-1})]] entry for entry -- are polynomial identities in the entries
// of A, B, C, D, P, Delta, Phi, Q and Delta^{-1} (the last two as free symbols), checked as such
// (proofs/symbolic.hpp) for every n, m = 1..3. (ii) and (iv) are then the Schur complement lemma
// (a symmetric [[X, Y'], [Y, Z]] with Z > 0 is > 0 iff X - Y' Z^{-1} Y > 0) on the pivots
// diag(P^{-1}, Delta^{-1}) and P, which is cited, not re-derived. The random instances check the
// definiteness verdicts agree (exact LDL^T) on both sides of the equivalence.
#include <random>
#include <sstream>

#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lmi/passivity_level.hpp"
#include "proofs/proof.hpp"
#include "proofs/symbolic.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::lmi;

MatQ inverse_exact(MatQ A) {
  const auto n = A.rows();
  MatQ I = MatQ::Identity(n, n);
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::Index p = c;
    while (p < n && A(p, c) == 0) ++p;
    if (p == n) throw hapstab::NumericalError("inverse_exact: singular");
    A.row(p).swap(A.row(c));
    I.row(p).swap(I.row(c));
    const rational inv = 1 / A(c, c);
    A.row(c) *= inv;
    I.row(c) *= inv;
    for (Eigen::Index r = 0; r < n; ++r)
      if (r != c && A(r, c) != 0) {
        const rational f = A(r, c);
        A.row(r) -= f * A.row(c);
        I.row(r) -= f * I.row(c);
      }
  }
  return I;
}

MatQ rand_q(std::mt19937& g, Eigen::Index r, Eigen::Index c, int range = 5, int den = 4) {
  std::uniform_int_distribution<int> d(-range, range);
  MatQ M(r, c);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) M(i, j) = rational(d(g), den);
  return M;
}

MatQ vcat(std::initializer_list<MatQ> parts) {
  Eigen::Index rows = 0, cols = parts.begin()->cols();
  for (const auto& p : parts) rows += p.rows();
  MatQ M(rows, cols);
  Eigen::Index r = 0;
  for (const auto& p : parts) {
    M.block(r, 0, p.rows(), cols) = p;
    r += p.rows();
  }
  return M;
}

}  // namespace

// (i) and the block form of (iii) as polynomial identities in the symbols, at sizes n x m: true
// when both hold; `monomials` counts the terms compared (the evidence that they are not empty).
bool lemma_identities_symbolic(size_t n, size_t m, size_t& monomials) {
  using namespace hapstab::proofs;
  Symbols x;
  const SymMat A = x.matrix(n, n), B = x.matrix(n, m), C = x.matrix(m, n), D = x.matrix(m, m);
  const SymMat P = x.symmetric(n), Delta = x.symmetric(m), Phi = x.symmetric(m), Q = x.symmetric(n), Dinv = x.symmetric(m);
  const rational half(1, 2);
  const SymMat HeD = half * (D + transpose(D));
  // Lemma 1's M(P)
  const SymMat M = blocks({{transpose(A) * P * A - P + transpose(C) * Delta * C,
                            transpose(A) * P * B - half * transpose(C) + transpose(C) * Delta * D},
                           {transpose(B) * P * A - half * C + transpose(D) * Delta * C,
                            transpose(B) * P * B - HeD + transpose(D) * Delta * D + Phi}});
  const SymMat W = blocks({{P, half * transpose(C)}, {half * C, HeD - Phi}});
  const SymMat N = blocks({{A, B}, {C, D}});
  const SymMat PD = blocks({{P, zeros(n, m)}, {zeros(m, n), Delta}});
  const SymMat lhs = -M, rhs = W - transpose(N) * PD * N;
  // Lemma 2's matrix, with Q^{-1} = P in its corner, and the Schur form [[W, N'], [N, diag(Q, Delta^{-1})]]
  const SymMat R = blocks({{half * C}, {A}, {C}});
  const SymMat S = blocks({{HeD - Phi, transpose(B), transpose(D)},
                           {B, Q, zeros(n, m)},
                           {D, zeros(m, n), Dinv}});
  const SymMat big = blocks({{P, transpose(R)}, {R, S}});
  const SymMat schur_form = blocks({{W, transpose(N)}, {N, blocks({{Q, zeros(n, m)}, {zeros(m, n), Dinv}})}});
  for (const SymMat* X : {&lhs, &big})
    for (const auto& row : *X)
      for (const auto& e : row) monomials += e.size();
  return lhs == rhs && big == schur_form;
}

HAPSTAB_PROOF(lmi_lemma1_lemma2_schur, "000", "Lemma 1 <=> Lemma 2: the Schur complement steps in exact arithmetic") {
  bool symbolic = true;
  size_t monomials = 0;
  for (size_t n = 1; n <= 3; ++n)
    for (size_t m = 1; m <= 3; ++m) symbolic = lemma_identities_symbolic(n, m, monomials) && symbolic;
  std::mt19937 g(20260522);
  int identity_ok = 0, equiv_ok = 0, pd_count = 0, total = 0;
  // non-trivial (proof.hpp): the equivalence must be met from both sides, on feasible
  // instances (Lemma 1 holds) and on infeasible ones (it fails)
  proofs::Instances feasible{"instances where Lemma 1's (2) < 0 holds", 10},
      infeasible{"instances where it fails", 10}, instances{"random (A, B, C, D, P, Delta, Phi), each identity between non-zero matrices", 60};
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Index n = 1 + trial % 3, m = 1 + (trial / 3) % 2;
    MatQ A = rand_q(g, n, n, 1, static_cast<int>(3 * n)), B = rand_q(g, n, m), C = rand_q(g, m, n), D = rand_q(g, m, m);
    MatQ L = rand_q(g, n, n);
    MatQ P = L * L.transpose() + MatQ::Identity(n, n);  // P > 0
    MatQ Q = inverse_exact(P);
    MatQ Delta = MatQ::Identity(m, m) * rational(1 + trial % 4, 30);
    MatQ Phi = MatQ::Identity(m, m) * rational(-(trial % 9) * 3, 1);  // 0 .. -24: both verdicts occur
    MatQ HeD = (D + D.transpose()) / rational(2);
    // Lemma 1's M(P)
    MatQ M(n + m, n + m);
    M.topLeftCorner(n, n) = A.transpose() * P * A - P + C.transpose() * Delta * C;
    M.topRightCorner(n, m) = A.transpose() * P * B - C.transpose() / rational(2) + C.transpose() * Delta * D;
    M.bottomLeftCorner(m, n) = M.topRightCorner(n, m).transpose();
    M.bottomRightCorner(m, m) = B.transpose() * P * B - HeD + D.transpose() * Delta * D + Phi;
    // (i)
    MatQ W(n + m, n + m);
    W << P, C.transpose() / rational(2), C / rational(2), HeD - Phi;
    MatQ N(n + m, n + m);
    N << A, B, C, D;
    MatQ PD = MatQ::Zero(n + m, n + m);
    PD.topLeftCorner(n, n) = P;
    PD.bottomRightCorner(m, m) = Delta;
    identity_ok += MatQ(-M) == MatQ(W - N.transpose() * PD * N);
    // (iii) Lemma 2's big matrix and (iv) its Schur form
    MatQ R = vcat({MatQ(C / rational(2)), A, C});
    MatQ S = MatQ::Zero(2 * m + n, 2 * m + n);
    S.topLeftCorner(m, m) = HeD - Phi;
    S.block(0, m, m, n) = B.transpose();
    S.block(0, m + n, m, m) = D.transpose();
    S.block(m, 0, n, m) = B;
    S.block(m, m, n, n) = Q;
    S.block(m + n, 0, m, m) = D;
    S.block(m + n, m + n, m, m) = inverse_exact(Delta);
    MatQ Big(n + 2 * m + n, n + 2 * m + n);
    Big << P, R.transpose(), R, S;  // Q^{-1} = P
    const bool l1 = exact_definiteness(MatQ(-M)).pd;
    const bool l2 = exact_definiteness(Big).pd;
    const bool l2s = exact_definiteness(MatQ(S - R * Q * R.transpose())).pd;
    equiv_ok += (l1 == l2) && (l2 == l2s);
    pd_count += l1;
    feasible.count(l1);
    infeasible.count(!l1);
    instances.count(true);
    ++total;
  }
  std::ostringstream ev;
  ev << "symbolic: -M = W - N' diag(P,Delta) N and [[P, R'], [R, S]] = [[W, N'], [N, diag(Q, Delta^-1)]] hold as "
        "polynomial identities in the entries for n, m = 1..3 (" << monomials << " monomials compared): "
     << (symbolic ? "yes" : "NO") << "; instances: " << identity_ok << "/" << total
     << " exact identities -M = W - N' diag(P,Delta) N; " << equiv_ok << "/" << total
     << " instances where Lemma 1 (2) < 0, Lemma 2 > 0 and S - RQR' > 0 agree (exact LDL^T; " << pd_count
     << " feasible, " << total - pd_count << " infeasible instances)";
  check.claim("000.lemma1.schur_identity", "(2)",
              "-M(P) = W - N' blockdiag(P, Delta) N, the first Schur step, for every A, B, C, D, P, Delta, Phi with n, m "
              "<= 3 (a polynomial identity in their entries)",
              hapstab::Status::exact, symbolic && identity_ok == total, ev.str(), {instances});
  check.claim("000.lemma2.equivalence", "Lemma 2",
              "Lemma 1's (2) < 0 <=> [[Q^{-1}, R'], [R, S]] > 0 <=> S - R Q R' > 0 at Q = P^{-1}, for every A, B, C, D, "
              "P > 0, Delta > 0, Phi with n, m <= 3: Lemma 2's matrix is [[W, N'], [N, diag(Q, Delta^{-1})]] "
              "(a polynomial identity), so both equivalences are the Schur complement lemma",
              hapstab::Status::exact, symbolic && equiv_ok == total, ev.str(), {feasible, infeasible});
}

HAPSTAB_PROOF(lmi_lemma2_typo, "000", "Lemma 2's S: (D+D')/2 - Phi, not + Phi") {
  // G(z) = 1/2 + 1/(z - 1/2): ISP level phi* = 1/2 - 1/(1 + 1/2) = -1/6 < 0 (not ISP).
  Eigen::MatrixXd A(1, 1), B(1, 1), C(1, 1), D(1, 1);
  A << 0.5;
  B << 1;
  C << 1;
  D << 0.5;
  auto sys = ss<double>(A, B, C, D, rational(1, 100));
  const double phi = 0.3;  // above phi* = -1/6 and above -phi* = 1/6 (where +Phi flips)
  const double m1 = lemma_margin(sys, 1, 0, phi, false);
  const double m2 = lemma_margin(sys, 2, 0, phi, false);
  const double m2typo = lemma_margin(sys, 2, 0, phi, true);
  const double fq = passivity_level_freq(sys, PassivityKind::isp).level;
  std::ostringstream ev;
  ev.precision(6);
  ev << "G = 1/2 + 1/(z-1/2), phi = 0.3 > phi* = " << fq << " (frequency domain; exact -1/6): margins Lemma 1 " << m1
     << ", Lemma 2 with -Phi " << m2 << ", Lemma 2 with +Phi " << m2typo << " (> 0 means 'is 0.3-ISP'; with +Phi the test is the correct one at -Phi)";
  check.claim("000.lemma2.typo", "Lemma 2 S", "the transcribed +Phi accepts a non-ISP system; (D+D')/2 - Phi agrees with Lemma 1",
              hapstab::Status::numeric, m1 < -1e-6 && m2 < -1e-6 && m2typo > 1e-6 && std::abs(fq + 1.0 / 6) < 1e-12,
              ev.str());
}
