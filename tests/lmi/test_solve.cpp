// Known-answer SDPs on both back-ends (same verdict required), infeasible programs with
// exact Farkas certificates, exact feasibility certificates, malformed programs, badly scaled
// data. Expected values are derived by hand in exact arithmetic (comments give the algebra).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <random>

#include "hapstab/lmi/ccl.hpp"
#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lmi/solve.hpp"
#include "hapstab/numeric/error.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_solve {

using namespace hapstab;
using namespace hapstab::lmi;
using Eigen::MatrixXd;

namespace {

const Backend kBoth[] = {Backend::dsdp, Backend::csdp};
// feasible known answers: the built-in IPM too (it has no infeasibility detection of its own)
const Backend kAll[] = {Backend::dsdp, Backend::csdp, Backend::ipm};

// One back-end, no DSDP -> CSDP fallback: each back-end's verdict must stand on its own.
Options only(Backend b) {
  Options o;
  o.backend = b;
  o.fallback = false;
  return o;
}

MatrixXd M2(double a, double b, double c, double d) {
  MatrixXd m(2, 2);
  m << a, b, c, d;
  return m;
}

// Lyapunov program: P > 0, A^T P A - P < 0 (margin objective).
Program lyapunov(const MatrixXd& A, MatrixVariable* Pout = nullptr) {
  Program prog;
  auto P = prog.new_symmetric(static_cast<int>(A.rows()), "P");
  prog.add_lmi("P > 0", Expr(P));
  prog.add_lmi("Lyapunov", -(A.transpose() * Expr(P) * A - Expr(P)));
  if (Pout) *Pout = P;
  return prog;
}

}  // namespace

// min x s.t. [[x, 1], [1, x]] >= 0: eigenvalues x +- 1, so x* = 1 exactly.
TEST(LmiSolve, KnownMinimumBothBackends) {
  for (Backend b : kAll) {
    Program prog;
    auto x = prog.new_scalar("x");
    prog.add_lmi("[[x,1],[1,x]]", {{Expr(x), Expr::scalar(1)}, {Expr(), Expr(x)}}, Strictness::nonstrict);
    prog.set_minimize(Expr(x));
    SolveResult r = solve(prog, only(b));
    ASSERT_EQ(r.status, SolveStatus::optimal) << to_string(b) << " " << r.detail;
    EXPECT_TRUE(r.is_success());
    // Interior-point accuracy: gap tolerance 1e-9 (DSDP, IPM) / 1e-8 (CSDP) relative; 1e-6 absolute is
    // ample and still excludes any other value.
    EXPECT_NEAR(r.objective, 1.0, 1e-6) << to_string(b);
    // The exact check of [[x,1],[1,x]] >= 0 needs x >= 1 exactly. The optimum sits on the
    // boundary, so a rounding may land below 1 and fail: then the certificate must say
    // rounding_failed, never feasible_exact; when it passed, the exact x is in [1, 1 + 1e-6].
    ASSERT_TRUE(r.certificate == Certificate::feasible_exact || r.certificate == Certificate::rounding_failed)
        << to_string(b) << " " << to_string(r.certificate);
    if (r.certified()) {
      EXPECT_GE(r.x_exact[0], 1);
      EXPECT_LE(r.x_exact[0], rational(1000001, 1000000));
    }
    for (double e : r.dimacs) EXPECT_LT(std::abs(e), 1e-6) << to_string(b);
  }
}

// max t s.t. diag(x1, x2) >= t I with x1 + x2 = 1, x1 <= 0.3 (as 0.3 - x1 >= 0):
// t* = min(x1, x2) maximised: x1 = 0.3, x2 = 0.7 -> t* = 0.3 (but the margin is measured after
// equilibration; the original-coordinate min eigenvalue must be 0.3).
TEST(LmiSolve, EqualitiesAndInequalitiesBothBackends) {
  for (Backend b : kAll) {
    Program prog;
    auto X = prog.new_diagonal(2, "X");
    prog.add_lmi("X > 0", Expr(X));
    MatrixXd e1 = MatrixXd::Zero(1, 2), e2 = MatrixXd::Zero(2, 1);
    e1(0, 0) = 1;
    e2(0, 0) = 1;
    MatrixXd ones = MatrixXd::Ones(1, 2), onesc = MatrixXd::Ones(2, 1);
    prog.add_linear_equality("x1 + x2 = 1", ones * Expr(X) * onesc, MatrixXd::Ones(1, 1));
    prog.add_linear_inequality("x1 <= 0.3", -(e1 * Expr(X) * e2), MatrixXd::Constant(1, 1, -0.3));
    Options o = only(b);
    o.scale = Scaling::never;  // keep t in original units for this known answer
    SolveResult r = solve(prog, o);
    ASSERT_TRUE(r.is_success()) << to_string(b) << " " << r.detail;
    EXPECT_NEAR(r.margin, 0.3, 1e-6) << to_string(b);
    MatrixXd Xv = r.solution(X);
    EXPECT_NEAR(Xv(0, 0), 0.3, 1e-6);
    EXPECT_NEAR(Xv(1, 1), 0.7, 1e-6);
    ASSERT_TRUE(r.certified()) << r.detail;
    // The equality holds EXACTLY at the certified point (exact elimination).
    EXPECT_EQ(r.x_exact[0] + r.x_exact[1], rational(1));
    EXPECT_LE(r.x_exact[0], rational(3, 10));
  }
}

TEST(LmiSolve, LyapunovFeasibleCertifiedBothBackends) {
  MatrixXd A = M2(0.9, 0.5, -0.2, 0.7);  // eigenvalues 0.8 +- 0.3i, |.| = 0.854 < 1
  for (Backend b : kAll) {
    MatrixVariable P;
    Program prog = lyapunov(A, &P);
    SolveResult r = solve(prog, only(b));
    ASSERT_TRUE(r.is_success()) << to_string(b) << " " << r.detail;
    EXPECT_GT(r.margin, 1e-3);
    ASSERT_TRUE(r.certified()) << to_string(b) << " " << r.detail;
    // Independent exact re-check of the returned certificate.
    MatQ Pq = r.exact_solution(P);
    MatQ Aq = to_rational(A);
    EXPECT_TRUE(exact_definiteness(Pq).pd);
    EXPECT_TRUE(exact_definiteness(MatQ(Pq - Aq.transpose() * Pq * Aq)).pd);
  }
}

// The low-rank form (program.hpp LowRank) through congruences, sums, transposes, scaling and
// block assembly: for every variable, the sum of its pieces equals its sparse term to rounding.
// Then a Lyapunov program that takes the IPM's low-rank Schur complement (a dense 20-state A:
// 210 variables with 4 pieces each against up to n^2 = 400 entries) is solved and certified by
// the IPM, and by DSDP.
TEST(LmiModel, LowRankPiecesMatchTheTerms) {
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 20;
  MatrixXd A(n, n), B(n, 1);
  for (int i = 0; i < A.size(); ++i) A.data()[i] = u(g);
  for (int i = 0; i < n; ++i) B(i, 0) = u(g);
  A *= 0.9 / Eigen::EigenSolver<MatrixXd>(A).eigenvalues().cwiseAbs().maxCoeff();  // Schur stable
  MatrixXd W(n, n + 1), J = MatrixXd::Zero(n, n + 1);
  W << A, B;
  J.leftCols(n).setIdentity();
  Program prog;
  auto P = prog.new_symmetric(n, "P");
  auto t = prog.new_scalar("t");
  const Expr F = -1.0 * (W.transpose() * Expr(P) * W - J.transpose() * Expr(P) * J) +
                 blocks({{Expr::zero(n, n), Expr::zero(n, 1)}, {Expr(), kron(MatrixXd::Identity(1, 1), Expr(t))}});
  const LowRank& lr = F.low_rank();
  for (const auto& [k, m] : F.terms()) {
    auto it = lr.factors.find(k);
    if (k == t.index[0]) {  // kron: no pieces
      EXPECT_EQ(it, lr.factors.end());
      continue;
    }
    ASSERT_NE(it, lr.factors.end()) << "variable " << k;
    MatrixXd rec = MatrixXd::Zero(F.rows(), F.cols());
    for (const Factor& f : it->second) rec += f.s * lr.L.col(f.u) * lr.R.col(f.v).transpose();
    EXPECT_LE((rec - MatrixXd(m)).cwiseAbs().maxCoeff(), 1e-13) << "variable " << k;
  }
  // the transpose keeps them too
  const Expr Ft = F.transpose();
  for (const auto& [k, f] : Ft.low_rank().factors) {
    MatrixXd rec = MatrixXd::Zero(Ft.rows(), Ft.cols());
    for (const Factor& x : f) rec += x.s * Ft.low_rank().L.col(x.u) * Ft.low_rank().R.col(x.v).transpose();
    EXPECT_LE((rec - MatrixXd(Ft.terms().at(k))).cwiseAbs().maxCoeff(), 1e-13);
  }
  MatrixVariable Pv;
  Program lyap = lyapunov(A, &Pv);
  for (Backend b : {Backend::ipm, Backend::dsdp}) {
    const SolveResult r = solve(lyap, only(b));
    ASSERT_TRUE(r.certified()) << to_string(b) << " " << r.detail;
    EXPECT_EQ(r.verdict, Feasibility::feasible);
  }
}

// A = diag(1.2, 0.5) is not Schur: no P > 0 with A^T P A - P < 0. Farkas: Z = e1 e1^T on the
// Lyapunov block and 0.44 e1 e1^T on P: tr((P - A^T P A) Z) + 0.44... -> the back-end's Z is
// checked exactly.
TEST(LmiSolve, LyapunovInfeasibleBothBackendsExactFarkas) {
  MatrixXd A = M2(1.2, 0.0, 0.0, 0.5);
  for (Backend b : kBoth) {
    Program prog = lyapunov(A);
    SolveResult r = solve(prog, only(b));
    EXPECT_EQ(r.verdict, Feasibility::infeasible) << to_string(b) << " " << r.detail;
    EXPECT_FALSE(r.is_success());
    EXPECT_EQ(r.certificate, Certificate::infeasible_exact) << to_string(b) << " " << r.detail;
  }
}

// The built-in IPM alone on an infeasible program: never "feasible" (it cannot prove
// infeasibility itself); Solve's default (automatic) then lets DSDP decide, exactly, and says so.
TEST(LmiSolve, AutomaticKeepsTheIpmOnlyWhenCertified) {
  Program bad = lyapunov(M2(1.2, 0.0, 0.0, 0.5));
  SolveResult ri = solve(bad, only(Backend::ipm));
  EXPECT_NE(ri.verdict, Feasibility::feasible) << ri.detail;
  EXPECT_FALSE(ri.certified());
  SolveResult ra = solve(bad, Options{});
  EXPECT_EQ(ra.verdict, Feasibility::infeasible) << ra.detail;
  EXPECT_EQ(ra.certificate, Certificate::infeasible_exact) << ra.detail;
  if (ra.solver == "hapstab IPM") { EXPECT_EQ(ra.certificate, Certificate::infeasible_exact); }
  else EXPECT_NE(ra.detail.find("hapstab IPM first"), std::string::npos) << ra.detail;
  // a feasible small program: the IPM's certified answer is the one returned
  Program good = lyapunov(M2(0.9, 0.5, -0.2, 0.7));
  SolveResult rg = solve(good, Options{});
  EXPECT_EQ(rg.solver, "hapstab IPM") << rg.detail;
  EXPECT_EQ(rg.certificate, Certificate::feasible_exact) << rg.detail;
  // without certification automatic means DSDP
  Options nc;
  nc.certify = false;
  EXPECT_EQ(solve(good, nc).solver, "DSDP");
  // a program above ipm_max_rows goes to DSDP directly
  Options tiny;
  tiny.ipm_max_rows = 3;
  SolveResult rd = solve(good, tiny);
  EXPECT_EQ(rd.solver, "DSDP");
  EXPECT_EQ(rd.certificate, Certificate::feasible_exact);
}

// x >= 1 and x <= -1: DSDP/CSDP report infeasibility directly (non-strict, no margin).
TEST(LmiSolve, ContradictoryBoundsInfeasibleBothBackends) {
  for (Backend b : kBoth) {
    Program prog;
    auto x = prog.new_scalar("x");
    prog.add_lmi("x >= 1", Expr(x) - Expr::scalar(1), Strictness::nonstrict);
    prog.add_lmi("x <= -1", -Expr(x) - Expr::scalar(1), Strictness::nonstrict);
    prog.set_minimize(Expr(x));
    SolveResult r = solve(prog, only(b));
    EXPECT_EQ(r.verdict, Feasibility::infeasible) << to_string(b) << " " << r.detail;
    EXPECT_EQ(r.certificate, Certificate::infeasible_exact) << to_string(b) << " " << r.detail;
  }
}

// min -x s.t. x >= 1 (as a 1x1 LMI, and as a linear inequality): unbounded below. DSDP
// bounds |y| by 1e7 internally and used to stop there "converged" with objective -1e7.
TEST(LmiSolve, UnboundedBelowAllBackends) {
  for (bool as_lmi : {true, false})
    for (Backend b : kBoth) {
      Program prog;
      auto x = prog.new_scalar("x");
      if (as_lmi) prog.add_lmi("x >= 1", Expr(x) - Expr::scalar(1), Strictness::nonstrict);
      else prog.add_linear_inequality("x >= 1", Expr(x), MatrixXd::Ones(1, 1));
      prog.set_minimize(-Expr(x));
      SolveResult r = solve(prog, only(b));
      EXPECT_EQ(r.status, SolveStatus::unbounded) << to_string(b) << " " << r.detail;
      EXPECT_FALSE(r.is_success()) << to_string(b);
      EXPECT_FALSE(r.certified()) << to_string(b);
    }
  // min -(y + z) s.t. [[y, 1], [1, z]] >= 0: unbounded along y = z -> inf. (Not [[1, y], [y, z]]
  // with min -y: that one is only weakly unbounded -- no multiplier ray exists -- and CSDP
  // stops with code 7.)
  for (Backend b : kBoth) {
    Program prog;
    auto y = prog.new_scalar("y");
    auto z = prog.new_scalar("z");
    prog.add_lmi("[[y,1],[1,z]]", {{Expr(y), Expr::scalar(1)}, {Expr(), Expr(z)}}, Strictness::nonstrict);
    prog.set_minimize(-Expr(y) - Expr(z));
    SolveResult r = solve(prog, only(b));
    EXPECT_EQ(r.status, SolveStatus::unbounded) << to_string(b) << " " << r.detail;
  }
}

// CSDP's easy_sdp loops without end on the OSP-level LMI (Lemma 1) of (z^2 + 1)/(z^2 - 1/4),
// whose zeros +-j lie on the unit circle (the strict LMI has no interior: the frequency
// inequality is an equality at theta = pi/2 for every delta). The child is stopped at the
// time limit, reported as numerical trouble, and its private folder is removed.
TEST(LmiSolve, CsdpTimeLimitStopsAHangingSolve) {
  // (z^2 + 1)/(z^2 - 1/4) = 1 + (5/4)/(z^2 - 1/4), controllable canonical form
  MatrixXd A = M2(0, 1, 0.25, 0), B(2, 1), C(1, 2), D(1, 1);
  B << 0, 1;
  C << 1.25, 0;
  D << 1;
  Program prog;
  auto P = prog.new_symmetric(2, "P");
  auto d = prog.new_scalar("delta");
  Expr Pe(P), de(d);
  Expr M11 = A.transpose() * Pe * A - Pe + kron(MatrixXd(C.transpose() * C), de);
  Expr M12 = A.transpose() * Pe * B - Expr(MatrixXd(0.5 * C.transpose())) + kron(MatrixXd(C.transpose() * D), de);
  Expr M22 = B.transpose() * Pe * B - Expr(MatrixXd(D)) + kron(MatrixXd(D.transpose() * D), de);
  prog.add_lmi("P > 0", Pe);
  prog.add_lmi("Lemma 1 (2) < 0", -blocks({{M11, M12}, {Expr(), M22}}));
  prog.set_minimize(-de);
  Options o = only(Backend::csdp);
  o.scale = Scaling::never;
  o.csdp_time_limit = 1.0;
  // a private TMPDIR, so that CSDP runs of tests in parallel processes do not count
  char tmpl[] = "/tmp/hapstab-test-XXXXXX";
  ASSERT_NE(::mkdtemp(tmpl), nullptr);
  const char* old_tmp = std::getenv("TMPDIR");
  const std::string saved = old_tmp ? old_tmp : "";
  ::setenv("TMPDIR", tmpl, 1);
  SolveResult r = solve(prog, o);
  if (old_tmp) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  EXPECT_EQ(::rmdir(tmpl), 0) << "the CSDP folder was left in " << tmpl;  // rmdir fails unless empty
  EXPECT_FALSE(r.is_success());
  EXPECT_FALSE(r.certified());
  // Either CSDP was stopped at the limit (the detail says so; no wall-clock assertion here:
  // timing lives in bench/), or a CSDP build that does not loop here answered -- which must
  // still not call this program feasible.
  if (r.detail.find(kCsdpTimedOut) != std::string::npos) { EXPECT_EQ(r.status, SolveStatus::numerical_trouble); }
  else EXPECT_NE(r.verdict, Feasibility::feasible) << r.detail;
  EXPECT_THROW(
      {
        Options bad = o;
        bad.csdp_time_limit = -1;
        solve(prog, bad);
      },
      InputError);
}

// The same random programs on DSDP and CSDP (no fallback): the verdicts must agree, and the
// optimal values of the minimisation agree to the solvers' tolerance. Family: min tr(W P)
// s.t. P >= 0, A'PA - P + I <= 0 (a Lyapunov bound, feasible iff rho(A) < 1, optimum =
// tr(W X) with X the Lyapunov solution, W = I), A random 3x3 scaled to spectral radius
// 0.6 (feasible) or 1.3 (infeasible). DSDP stops on short steps on some infeasible ones; its
// multipliers then still hold a Farkas ray, which Solve checks (solve.cpp).
TEST(LmiSolve, BackendsAgreeOnRandomPrograms) {
  std::mt19937 g(2026);
  std::normal_distribution<double> N(0, 1);
  for (int trial = 0; trial < 12; ++trial) {
    MatrixXd A(3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j) = N(g);
    const double rho = trial % 3 == 2 ? 1.3 : 0.6;
    A *= rho / Eigen::EigenSolver<MatrixXd>(A, false).eigenvalues().cwiseAbs().maxCoeff();
    // exact optimum: X = sum_k (A')^k A^k, the minimal solution of A'XA - X + I = 0
    MatrixXd X = MatrixXd::Identity(3, 3), T = MatrixXd::Identity(3, 3);
    for (int k = 0; k < 4000; ++k) {
      T = A.transpose() * T * A;
      X += T;
    }
    Program prog;
    auto P = prog.new_symmetric(3, "P");
    prog.add_lmi("P >= 0", Expr(P), Strictness::nonstrict);
    prog.add_lmi("A'PA - P + I <= 0", -(A.transpose() * Expr(P) * A - Expr(P) + Expr::identity(3)), Strictness::nonstrict);
    prog.set_minimize(trace(Expr(P)));
    SolveResult rd = solve(prog, only(Backend::dsdp)), rc = solve(prog, only(Backend::csdp));
    ASSERT_EQ(rd.verdict, rc.verdict) << "trial " << trial << ": DSDP " << rd.detail << " | CSDP " << rc.detail;
    if (rho < 1) {
      ASSERT_EQ(rd.verdict, Feasibility::feasible) << rd.detail;
      // relative 1e-6: both solvers stop at relative gaps <= 1e-8..1e-9; the Lyapunov
      // conditioning (|A| up to ~5 after scaling) costs at most two more digits.
      // A solver that stopped early at a feasible point (status numerical_trouble, verdict
      // feasible) gives an upper bound only.
      for (const SolveResult* r : {&rd, &rc}) {
        if (r->status == SolveStatus::optimal) { EXPECT_NEAR(r->objective, X.trace(), 1e-6 * X.trace()) << "trial " << trial; }
        else EXPECT_GE(r->objective, X.trace() * (1 - 1e-9)) << "trial " << trial << " " << r->detail;
      }
    } else {
      // Every Farkas ray of this family is supported on A's unstable eigenvectors (a ray needs
      // Z >= 0 with A Z A' >= Z), irrational for a random A: no rational certificate exists
      // and numeric_only is the honest answer; never "none" or a feasible claim.
      EXPECT_EQ(rd.verdict, Feasibility::infeasible) << rd.detail;
      for (const SolveResult* r : {&rd, &rc})
        EXPECT_TRUE(r->certificate == Certificate::infeasible_exact || r->certificate == Certificate::numeric_only)
            << r->detail;
    }
  }
}

TEST(LmiSolve, InconsistentEqualitiesAreExactlyInfeasible) {
  Program prog;
  auto x = prog.new_scalar("x");
  prog.add_lmi("x > 0", Expr(x));
  prog.add_linear_equality("x = 1", Expr(x), MatrixXd::Ones(1, 1));
  prog.add_linear_equality("2x = 3", 2.0 * Expr(x), MatrixXd::Constant(1, 1, 3));
  SolveResult r = solve(prog);
  EXPECT_EQ(r.verdict, Feasibility::infeasible);
  EXPECT_EQ(r.certificate, Certificate::infeasible_exact);
  EXPECT_NE(r.detail.find("2x = 3"), std::string::npos) << r.detail;
}

TEST(LmiModel, MalformedProgramsNameTheConstraint) {
  Program prog;
  auto P = prog.new_symmetric(2, "P");
  auto x = prog.new_scalar("x");
  // (1,2) block is 2x1 but (2,2) is 3x3: the second block row has inconsistent heights.
  try {
    prog.add_lmi("coupling", {{Expr(P), Expr(MatrixXd::Ones(2, 1))}, {Expr(), Expr::identity(3)}});
    FAIL() << "dimension mismatch accepted";
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("coupling"), std::string::npos) << m;
    EXPECT_NE(m.find("block (2,2)"), std::string::npos) << m;
  }
  try {
    prog.add_lmi("skew", {{Expr(x), Expr::scalar(1)}, {Expr::scalar(2), Expr(x)}});
    FAIL() << "non-symmetric LMI accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("skew"), std::string::npos);
  }
  try {
    prog.add_lmi("rect", Expr(MatrixXd::Ones(2, 3)));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rect"), std::string::npos);
  }
  // A mismatch inside an expression built before the constraint (C++ evaluates it first) is
  // reported by the constraint that receives it, with the block and the operation.
  Expr bad_sum = Expr(P) + Expr(MatrixXd::Ones(3, 3));  // no throw here
  EXPECT_FALSE(bad_sum.ok());
  Expr chained = 2.0 * bad_sum.transpose() + Expr(P);  // the first error survives
  try {
    prog.add_lmi("(16) first", {{Expr(P), Expr(MatrixXd::Zero(2, 2))}, {Expr(), chained}});
    FAIL() << "invalid block accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("(16) first"), std::string::npos) << m;
    EXPECT_NE(m.find("block (2,2)"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot add a 2x2 and a 3x3"), std::string::npos) << m;
  }
  try {
    prog.add_linear_inequality("L x >= 0", MatrixXd::Ones(1, 3) * Expr(P), MatrixXd::Zero(1, 2));
    FAIL() << "bad product accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("L x >= 0"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot multiply a 1x3 constant by a 2x2 expression"), std::string::npos) << m;
  }
  try {
    prog.set_minimize(kron(MatrixXd::Ones(1, 1), Expr(P)));
    FAIL() << "kron with a 2x2 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("objective"), std::string::npos) << e.what();
  }
  EXPECT_THROW(bad_sum.value({0, 0, 0, 0}), InputError);
  prog.add_lmi("ok", Expr(P));
  EXPECT_THROW(prog.add_lmi("ok", Expr(P)), InputError);  // duplicate name
  EXPECT_THROW(prog.add_lmi("nan", Expr(MatrixXd::Constant(1, 1, NAN)) + Expr(x)), InputError);
  Program other;
  auto y = other.new_scalar("y");
  (void)y;
  EXPECT_THROW(other.add_lmi("foreign", Expr(P)), InputError);  // P belongs to prog
}

TEST(LmiModel, StructuredVariables) {
  Program prog;
  auto BD = prog.new_block_diagonal(std::vector<int>{2, 1}, "Q");
  EXPECT_EQ(prog.num_scalars(), 3 + 1);
  auto G = prog.new_scalar_identity_blocks({2, 3}, "X");
  EXPECT_EQ(prog.num_scalars(), 6);
  EXPECT_EQ(G.at(0, 0), G.at(1, 1));
  EXPECT_EQ(G.at(2, 2), G.at(4, 4));
  EXPECT_EQ(G.at(0, 2), -1);
  auto NS = prog.new_block_diagonal(std::vector<std::pair<int, int>>{{2, 1}, {1, 3}}, "B");
  EXPECT_EQ(NS.rows, 3);
  EXPECT_EQ(NS.cols, 4);
  EXPECT_EQ(NS.at(2, 0), -1);
  EXPECT_GE(NS.at(2, 3), 0);
  EXPECT_EQ(BD.at(0, 2), -1);
  EXPECT_EQ(BD.at(0, 1), BD.at(1, 0));
}

// Badly scaled data: A has entries from 1e-7 to 1e6 (eigenvalues 0.4 +- 0.3i, |.| = 0.5).
// Scaling::automatic (raw data, then an equilibrated retry) must make both back-ends find and
// certify P; forcing equilibration may leave the verdict undecided but never infeasible.
TEST(LmiSolve, BadlyScaledFeasible) {
  MatrixXd A = M2(0.5, 1e6, -1e-7, 0.3);
  // the built-in IPM (no scaling safeguards of its own) diverges on these data; Solve's default
  // must still certify, through DSDP
  {
    SolveResult r = solve(lyapunov(A), Options{});
    EXPECT_TRUE(r.certified()) << r.solver << " " << r.detail;
    EXPECT_NE(solve(lyapunov(A), only(Backend::ipm)).verdict, Feasibility::infeasible);
  }
  for (Backend b : kBoth) {
    Program prog = lyapunov(A);
    SolveResult r = solve(prog, only(b));
    ASSERT_TRUE(r.is_success()) << to_string(b) << " " << r.detail << " margin " << r.margin << " its "
                                << r.iterations << " err4 " << r.dimacs[3] << " err5 " << r.dimacs[4];
    EXPECT_TRUE(r.certified()) << to_string(b) << " " << r.detail;
    Options eq = only(b);
    eq.scale = Scaling::always;
    EXPECT_NE(solve(prog, eq).verdict, Feasibility::infeasible) << to_string(b);
  }
}

// Same magnitudes but det = 0.15 + 2 > 1: not Schur, so infeasible on both back-ends.
TEST(LmiSolve, BadlyScaledInfeasible) {
  MatrixXd A = M2(0.5, 1e6, -2e-6, 0.3);
  for (Backend b : kBoth) {
    Program prog = lyapunov(A);
    SolveResult r = solve(prog, only(b));
    EXPECT_EQ(r.verdict, Feasibility::infeasible) << to_string(b) << " " << r.detail;
    EXPECT_FALSE(r.certified());
    // the infeasibility is either proven (an exact Farkas ray) or explicitly numeric
    EXPECT_TRUE(r.certificate == Certificate::infeasible_exact || r.certificate == Certificate::numeric_only)
        << to_string(b) << " " << to_string(r.certificate) << " " << r.detail;
  }
}

TEST(LmiCertificate, ExactDefiniteness) {
  MatQ M(3, 3);
  // [[1,1,0],[1,1,0],[0,0,2]] is PSD with a zero pivot whose row is zero after step 1.
  M << 1, 1, 0, 1, 1, 0, 0, 0, 2;
  auto d = exact_definiteness(M);
  EXPECT_TRUE(d.psd);
  EXPECT_FALSE(d.pd);
  EXPECT_EQ(d.rank, 2);
  // [[0,1],[1,0]]: zero pivot with a non-zero rest of row -> indefinite.
  MatQ N(2, 2);
  N << 0, 1, 1, 0;
  EXPECT_FALSE(exact_definiteness(N).psd);
  // [[1, 1/2],[1/2, 1/4 + 1e-30]] is PD but its double rounding is singular.
  MatQ P(2, 2);
  rational tiny = rational(1) / rational(integer(10) * integer(pow(integer(10), 29)));
  P << 1, rational(1, 2), rational(1, 2), rational(1, 4) + tiny;
  EXPECT_TRUE(exact_definiteness(P).pd);
  EXPECT_TRUE(exact_pd_bareiss(P));
  P(1, 1) = rational(1, 4);
  EXPECT_FALSE(exact_pd_bareiss(P));
  EXPECT_TRUE(exact_definiteness(P).psd);
  P(1, 1) = rational(1, 4) - tiny;
  EXPECT_FALSE(exact_definiteness(P).psd);
}

TEST(LmiCertificate, BareissAgreesWithLdlOnRandomMatrices) {
  std::srand(7);
  // n >= 8 goes through Arb's ball Cholesky first (it may only prove "yes"); the shifts put the
  // smallest eigenvalue near 0 (positive, zero, negative) and a rank-deficient R R^T (n - 1
  // columns) is singular: each verdict must be LDL^T's
  for (int trial = 0; trial < 80; ++trial) {
    const int n = 1 + trial % 14;
    MatrixXd R = MatrixXd::Random(n, trial % 5 == 4 ? std::max(1, n - 1) : n);
    MatrixXd S = R * R.transpose();
    const double lmin = Eigen::SelfAdjointEigenSolver<MatrixXd>(S).eigenvalues()(0);
    S -= (trial % 4 == 0 ? lmin * (1 - 1e-9) : (trial % 3) * 0.2) * MatrixXd::Identity(n, n);
    MatQ Q = to_rational(S);
    EXPECT_EQ(exact_pd_bareiss(Q), exact_definiteness(Q).pd) << trial;
  }
}

// Facial reduction: F(P) = [[p11 - 1, 0], [0, 0]] + ... a non-strict LMI singular along e2 for
// every P: F = diag(p - 1, 0) with p scalar; F >= 0 non-strict has no interior. Posed with
// facial_reduce on v = e2 it becomes p - 1 > 0 (margin), and F >= 0 is certified exactly with a
// zero pivot.
TEST(LmiCertificate, FacialReductionCertifiesSingularLmi) {
  for (Backend b : kBoth) {
    Program prog;
    auto p = prog.new_scalar("p");
    prog.add_lmi("singular", {{Expr(p) - Expr::scalar(1), Expr::zero(1, 1)}, {Expr(), Expr::zero(1, 1)}},
                Strictness::nonstrict);
    prog.add_linear_inequality("p <= 3", -Expr(p), MatrixXd::Constant(1, 1, -3));
    // Without reduction: margin objective has no strict LMI, feasibility only; posed directly.
    MatrixXd V = MatrixXd::Zero(2, 1);
    V(1, 0) = 1;
    facial_reduce(prog, "singular", V);
    SolveResult r = solve(prog, only(b));
    ASSERT_TRUE(r.is_success()) << to_string(b) << " " << r.detail;
    EXPECT_TRUE(r.certified()) << r.detail;
  }
}

// exact_lmi_holds (integer products and shifts on a common binary exponent) must give the verdict
// of the rational route exact_value + exact_pd_bareiss / exact_definiteness. Cases: random
// 5x5 symmetric data with entries spread over 2^-40..2^40 (exponent alignment), dyadic and
// non-dyadic x (1/3, 5/7: common denominator 21), x on the PSD boundary (exactly singular:
// strict fails, non-strict holds), and one just beyond it (both fail).
TEST(ExactCertificate, IntegerRouteAgreesWithRationalRoute) {
  Program p;
  auto a = p.new_scalar("a"), b = p.new_scalar("b");
  std::mt19937 g(7);
  std::uniform_int_distribution<int> e(-40, 40), v(-9, 9);
  auto rnd_sym = [&](int n) {
    MatrixXd M(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) M(i, j) = M(j, i) = std::ldexp(v(g), e(g));
    return M;
  };
  int agreed = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const MatrixXd C = rnd_sym(5), A = rnd_sym(5), B = rnd_sym(5);
    Expr F = Expr(C) + kron(A, Expr(a)) + kron(B, Expr(b));
    for (auto xs : {std::vector<rational>{rational(1, 3), rational(5, 7)}, std::vector<rational>{rational(3, 1024), rational(-7)},
                    std::vector<rational>{rational(0), rational(0)}}) {
      const MatQ Fq = exact_value(F, xs);
      EXPECT_EQ(exact_lmi_holds(F, xs, true), exact_pd_bareiss(Fq)) << trial;
      EXPECT_EQ(exact_lmi_holds(F, xs, false), exact_definiteness(Fq).psd) << trial;
      ++agreed;
    }
  }
  EXPECT_EQ(agreed, 120);
  // boundary: F = [[1, a], [a, 1]] at a = 1 is singular PSD; at a = 1 + 2^-50 indefinite
  Expr F2 = Expr(MatrixXd::Identity(2, 2)) + kron(M2(0, 1, 1, 0), Expr(a));
  const std::vector<rational> on{rational(1), rational(0)}, beyond{rational(1) + rational(1) / (integer(1) << 50), rational(0)};
  EXPECT_FALSE(exact_lmi_holds(F2, on, true));
  EXPECT_TRUE(exact_lmi_holds(F2, on, false));
  EXPECT_FALSE(exact_lmi_holds(F2, beyond, true));
  EXPECT_FALSE(exact_lmi_holds(F2, beyond, false));
}

}  // namespace test_solve
