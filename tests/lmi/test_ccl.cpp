// Cone complementarity linearisation on static-output-feedback stabilisation (discrete time).
//
// A = [[1.2, 1], [0, 0.4]], B = [0; 1], C = [1, 0]: A + BKC = [[1.2, 1], [K, 0.4]] has
// characteristic polynomial p(l) = l^2 - 1.6 l + 0.48 - K. Jury: p(1) = -0.12 - K > 0,
// p(-1) = 3.08 - K > 0, |0.48 - K| < 1  <=>  K in (-0.52, -0.12) (the known answer).
// Formulation: [[Y, A + BKC], [(A + BKC)^T, P]] > 0 with Y = P^{-1} is P - Acl^T P Acl > 0.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "hapstab/lmi/ccl.hpp"

using namespace hapstab;
using namespace hapstab::lmi;
using Eigen::MatrixXd;

namespace {

struct Sof {
  Program prog;
  MatrixVariable P, Y, K;
};

Sof sof_program(const MatrixXd& A, const MatrixXd& B, const MatrixXd& C) {
  Sof s;
  const int n = static_cast<int>(A.rows());
  s.P = s.prog.new_symmetric(n, "P");
  s.Y = s.prog.new_symmetric(n, "Y");
  s.K = s.prog.new_full(static_cast<int>(B.cols()), static_cast<int>(C.rows()), "K");
  Expr Acl = Expr(A) + B * Expr(s.K) * C;
  s.prog.add_lmi("closed loop", {{Expr(s.Y), Acl}, {Expr(), Expr(s.P)}});
  s.prog.add_lmi("P > 0", Expr(s.P));
  // keep the search bounded: P <= 100 I
  s.prog.add_lmi("P < 100 I", Expr(MatrixXd(100 * MatrixXd::Identity(n, n))) - Expr(s.P));
  return s;
}

double rho(const MatrixXd& M) { return Eigen::EigenSolver<MatrixXd>(M, false).eigenvalues().cwiseAbs().maxCoeff(); }

}  // namespace

TEST(Ccl, StaticOutputFeedbackKnownAnswer) {
  MatrixXd A(2, 2), B(2, 1), C(1, 2);
  A << 1.2, 1, 0, 0.4;
  B << 0, 1;
  C << 1, 0;
  for (Backend b : {Backend::dsdp, Backend::csdp}) {
    Sof s = sof_program(A, B, C);
    CclOptions o;
    o.solver.backend = b;
    auto res = ccl_solve(s.prog, {{s.Y, s.P}}, o);
    ASSERT_TRUE(res.success) << to_string(b) << ": " << res.reason;
    ASSERT_FALSE(res.log.empty());
    const double K = res.last.solution(s.K)(0, 0);
    EXPECT_GT(K, -0.52) << to_string(b);
    EXPECT_LT(K, -0.12) << to_string(b);
    EXPECT_LT(rho(A + B * res.last.solution(s.K) * C), 1.0);
    // The objective must have come down to 2n = 4 (tolerance 1e-6 relative, ccl.hpp).
    EXPECT_LE(res.log.back().objective, 4.0 * (1 + 1e-6));
  }
}

// A = diag(1.5, 0.5), B = [1; 1], C = [0, 1]: A + BKC = [[1.5, K], [0, 0.5 + K]] keeps the
// eigenvalue 1.5 for every K. CCL must end in failure, never in success.
TEST(Ccl, UnstabilisableReportsFailure) {
  MatrixXd A(2, 2), B(2, 1), C(1, 2);
  A << 1.5, 0, 0, 0.5;
  B << 1, 1;
  C << 0, 1;
  Sof s = sof_program(A, B, C);
  CclOptions o;
  o.max_iter = 25;
  o.accept = [&](const SolveResult& r) { return rho(A + B * r.solution(s.K) * C) < 1; };
  auto res = ccl_solve(s.prog, {{s.Y, s.P}}, o);
  EXPECT_FALSE(res.success) << res.reason;
  EXPECT_FALSE(res.reason.empty());
}

// The same unstabilisable plant without the `accept` shortcut: only CCL's own stop rules
// decide. tr(Y Q) = n would make Y = P^{-1}, i.e. a Lyapunov certificate for a closed loop that
// keeps the eigenvalue 1.5, so the linearised objective cannot reach 2n = 4: the run must stop
// on a stall, the iteration limit or a failed sub-problem, with the log showing the objective
// above the target -- on every back-end.
TEST(Ccl, UnstabilisableStallsAboveTarget) {
  MatrixXd A(2, 2), B(2, 1), C(1, 2);
  A << 1.5, 0, 0, 0.5;
  B << 1, 1;
  C << 0, 1;
  for (Backend b : {Backend::automatic, Backend::dsdp, Backend::csdp}) {
    Sof s = sof_program(A, B, C);
    CclOptions o;
    o.max_iter = 30;
    o.solver.backend = b;
    auto res = ccl_solve(s.prog, {{s.Y, s.P}}, o);
    EXPECT_FALSE(res.success) << to_string(b) << ": " << res.reason;
    EXPECT_FALSE(res.reason.empty()) << to_string(b);
    EXPECT_EQ(res.target, 4.0);
    ASSERT_FALSE(res.log.empty()) << to_string(b) << ": " << res.reason;
    EXPECT_LE(static_cast<int>(res.log.size()), o.max_iter);
    // the last finite objective stays clearly above 2n (never within the success tolerance)
    double last = NAN;
    for (const auto& st : res.log)
      if (std::isfinite(st.objective)) last = st.objective;
    if (std::isfinite(last)) { EXPECT_GT(last, 4.0 * (1 + o.tol)) << to_string(b) << ": " << res.reason; }
  }
}
