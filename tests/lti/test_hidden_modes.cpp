// The modes a realisation hides (lti/realization.hpp, hidden_modes), exactly. Random Kalman
// forms with known parts -- a controllable-observable part (A1, B1, C1), an uncontrollable but
// observable part A2 (B2 = 0, C2 random), an unobservable but controllable part A3 (C3 = 0, B3
// random), coupled as the Kalman form allows (A12, A13 ...) -- disguised by a random rational
// similarity, must give uncontrollable = det(xI - A2) and unobservable = det(xI - A3) exactly,
// and a minimal realisation of order dim A1 with the same transfer matrix. 300 cases.
#include <gtest/gtest.h>

#include <random>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

using namespace hapstab;

namespace {
MatQ random(std::mt19937_64& g, int r, int c, int range = 6) {
  std::uniform_int_distribution<int> num(-range, range), den(1, 5);
  MatQ M(r, c);
  for (int i = 0; i < M.size(); ++i) M.data()[i] = rational(num(g), den(g));
  return M;
}
}  // namespace

TEST(HiddenModes, RandomKalmanFormsGiveTheKnownFactors) {
  std::mt19937_64 g(2008);
  std::uniform_int_distribution<int> dim(0, 3), io(1, 2);
  int with_uc = 0, with_uo = 0;
  for (int c = 0; c < 300; ++c) {
    const int n1 = 1 + dim(g), n2 = dim(g), n3 = dim(g), m = io(g), p = io(g), n = n1 + n2 + n3;
    // x = [x1; x2; x3]: x2 not reached (rows of B zero, no coupling into x2 from x1/x3),
    // x3 not seen (C3 = 0, x3 drives neither x1 nor x2)
    MatQ A = MatQ::Zero(n, n), B = MatQ::Zero(n, m), C = MatQ::Zero(p, n);
    A.block(0, 0, n1, n1) = random(g, n1, n1);
    A.block(0, n1, n1, n2) = random(g, n1, n2);          // x2 drives x1 (observable through x1)
    A.block(n1, n1, n2, n2) = random(g, n2, n2);
    A.block(n1 + n2, 0, n3, n1) = random(g, n3, n1);     // x1 drives x3 (reachable)
    A.block(n1 + n2, n1 + n2, n3, n3) = random(g, n3, n3);
    B.topRows(n1) = random(g, n1, m);
    B.bottomRows(n3) = random(g, n3, m);
    C.leftCols(n1) = random(g, p, n1);
    C.block(0, n1, p, n2) = random(g, p, n2);
    const MatQ S = MatQ::Identity(n, n) + random(g, n, n, 1) / rational(2 * n + 2);
    const MatQ Si = exact_solve(S, MatQ::Identity(n, n), "S");
    const StateSpace<rational> sys{exact_product(exact_product(S, A), Si), exact_product(S, B), exact_product(C, Si),
                                   random(g, p, m), rational(1, 100)};
    const HiddenModes h = hidden_modes(sys);
    // The generic random blocks are controllable/observable where they should be; a degenerate
    // draw (e.g. a zero column) can hide more, so compare with the minimal order first.
    const StateSpace<rational> m1 = minreal(sys);
    EXPECT_EQ(h.minimal.states(), m1.states());
    if (m1.states() != n1) continue;  // a degenerate draw: nothing more to assert exactly
    EXPECT_EQ(h.uncontrollable.expanded(), charpoly(MatQ(A.block(n1, n1, n2, n2)))) << "case " << c;
    EXPECT_EQ(h.unobservable.expanded(), charpoly(MatQ(A.block(n1 + n2, n1 + n2, n3, n3)))) << "case " << c;
    EXPECT_EQ(h.any(), n2 + n3 > 0);
    with_uc += n2 > 0;
    with_uo += n3 > 0;
  }
  EXPECT_GE(with_uc, 150);
  EXPECT_GE(with_uo, 150);
}

TEST(HiddenModes, TheIssueEnvironmentHidesZEqualsTwo) {
  // issue 38: A = diag(1/2, 2), B = [1; 1], C = [1, 0], D = 20000: x2 is unobservable
  MatQ A(2, 2), B(2, 1), C(1, 2), D(1, 1);
  A << rational(1, 2), 0, 0, 2;
  B << 1, 1;
  C << 1, 0;
  D << 20000;
  const HiddenModes h = hidden_modes({A, B, C, D, rational(1, 1000)});
  EXPECT_EQ(h.uncontrollable.expanded(), Polynomial<rational>(rational(1)));
  EXPECT_EQ(h.unobservable.expanded(), Polynomial<rational>(std::vector<rational>{-2, 1}));
  EXPECT_EQ(h.minimal.states(), 1);
  // nothing hidden, and a static block
  EXPECT_FALSE(hidden_modes({MatQ(0, 0), MatQ(0, 1), MatQ(1, 0), D, rational(1, 1000)}).any());
}

TEST(HiddenModes, KalmanSplitBlock) {
  // the uncontrollable block's eigenvalues are the uncontrollable factor's roots
  MatQ A(3, 3), B(3, 1), C(1, 3), D(1, 1);
  A << 0, 1, 5, -2, -3, 7, 0, 0, 4;
  B << 0, 1, 0;
  C << 1, 0, 1;
  D << 0;
  const KalmanSplit k = controllable_split({A, B, C, D, 0});
  EXPECT_EQ(k.controllable.states(), 2);
  ASSERT_EQ(k.uncontrollable_A.rows(), 1);
  EXPECT_EQ(k.uncontrollable_A(0, 0), 4);
}
