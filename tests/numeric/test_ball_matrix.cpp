// Midpoint-radius matrices and the certified Schur decision (numeric/ball_matrix.hpp).
//  - Products enclose the exact rational product (checked exactly, entry by entry).
//  - schur_decide on matrices whose spectrum is known exactly: M = S L S^-1 with L built from
//    chosen real eigenvalues and 2x2 rotation-scaling blocks r [[cos, -sin], [sin, cos]] (cos,
//    sin rational from Pythagorean triples, so |eigenvalue| = r exactly), made block upper
//    triangular by random entries above and permuted: M = P (L + U) P^T has L's spectrum exactly. A decided verdict must be right every time; it must decide almost all
//    cases whose spectral radius is not within 1e-6 of 1; at 1 +- 1e-13 it may only be right
//    or undecided. 1000+ cases, orders 1-24.
//  - positive_definite: SPD and indefinite matrices, with radii that do or do not cover the
//    smallest eigenvalue.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

using namespace hapstab;

namespace {

// A spectrum with spectral radius exactly rho: eigenvalues of modulus <= rho, one of modulus rho.
MatQ known_spectrum(std::mt19937_64& g, int n, const rational& rho) {
  static const std::vector<std::pair<int, int>> triples = {{3, 5}, {4, 5}, {5, 13}, {12, 13}, {8, 17}, {15, 17}, {7, 25}};
  std::uniform_int_distribution<int> pick(0, 6), frac(1, 9), sgn(0, 1);
  MatQ L = MatQ::Zero(n, n);
  for (int i = 0; i < n;) {
    const rational r = i == 0 ? rho : rho * rational(frac(g), 10);
    if (i + 1 < n && sgn(g)) {
      const auto [a, c] = triples[static_cast<size_t>(pick(g))];
      const int b = static_cast<int>(std::lround(std::sqrt(double(c) * c - double(a) * a)));
      const rational co(a, c), si(b, c);
      L(i, i) = r * co, L(i, i + 1) = -r * si, L(i + 1, i) = r * si, L(i + 1, i + 1) = r * co;
      i += 2;
    } else {
      L(i, i) = sgn(g) ? r : rational(-r);
      i += 1;
    }
  }
  // M = P (L + U) P^T: U strictly upper triangular outside L's 2x2 blocks (so the spectrum is L's,
  // exactly), small (modest non-normality), P a random permutation that hides the triangle
  std::uniform_int_distribution<int> e(-3, 3);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (L(j, i) == 0 && !(j == i + 1 && L(i, j) != 0)) L(i, j) += rational(e(g), 4 * n);
  std::vector<int> perm(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) perm[static_cast<size_t>(i)] = i;
  std::shuffle(perm.begin(), perm.end(), g);
  MatQ M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(perm[static_cast<size_t>(i)], perm[static_cast<size_t>(j)]) = L(i, j);
  return M;
}

}  // namespace

TEST(BallMatrix, ProductEnclosesTheExactProduct) {
  std::mt19937_64 g(7);
  std::uniform_int_distribution<int> num(-50, 50), den(1, 30), dim(1, 7);
  for (int c = 0; c < 400; ++c) {
    const int r = dim(g), k = dim(g), q = dim(g);
    MatQ A(r, k), B(k, q);
    for (int i = 0; i < A.size(); ++i) A.data()[i] = rational(num(g), den(g));
    for (int i = 0; i < B.size(); ++i) B.data()[i] = rational(num(g), den(g));
    const BallMatrix P = BallMatrix::exact(A) * BallMatrix::exact(B);
    const MatQ E = exact_product(A, B);
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < q; ++j) {
        EXPECT_LE(abs(rational(P.mid(i, j)) - E(i, j)), rational(P.rad(i, j))) << "case " << c;
        // a few roundings of the terms: relative to sum_k |a_ik||b_kj| (the scale the products round at;
        // |mid| can be far smaller by cancellation), 100 u
        double scale = 0;
        for (int l = 0; l < k; ++l) scale += std::abs(to_real<double>(A(i, l))) * std::abs(to_real<double>(B(l, j)));
        EXPECT_LE(P.rad(i, j), 1e-14 * (1 + scale)) << "case " << c;
      }
  }
}

TEST(BallMatrix, SchurDecisionIsNeverWrongAndDecidesAwayFromTheCircle) {
  std::mt19937_64 g(38);
  std::uniform_int_distribution<int> dim(1, 24);
  int stable = 0, unstable = 0, decided_far = 0, far = 0, near = 0;
  for (int c = 0; c < 1200; ++c) {
    const int n = dim(g);
    const int which = c % 6;
    // rho: well inside, well outside, 1 - 1e-6 .. 1 + 1e-6 (decidable), 1 -+ 1e-13 (near)
    const rational rho = which == 0 ? rational(1, 2) : which == 1 ? rational(3, 2) : which == 2 ? rational(999999, 1000000)
                         : which == 3 ? rational(1000001, 1000000) : which == 4 ? 1 - rational(1, 10000000000000LL)
                                                                                : 1 + rational(1, 10000000000000LL);
    const MatQ M = known_spectrum(g, n, rho);
    const SchurDecision d = schur_decide(BallMatrix::exact(M));
    const bool truth = rho < 1;
    if (d.stable) {
      EXPECT_EQ(*d.stable, truth) << "case " << c << ", n = " << n << ", rho = " << rho << ": " << d.why;
      (*d.stable ? stable : unstable)++;
    }
    if (which < 4) {
      ++far;
      decided_far += d.stable.has_value();
    } else {
      ++near;
    }
  }
  EXPECT_GE(decided_far, far * 98 / 100) << "decided " << decided_far << " of " << far;
  EXPECT_GE(stable, 350);
  EXPECT_GE(unstable, 350);
  EXPECT_GT(near, 0);
}

TEST(BallMatrix, RadiiAreHonoured) {
  // diag(0.9, 0.5) is stable, but a ball of radius 0.2 around it holds diag(1.1, 0.5): not decided stable
  BallMatrix M = BallMatrix::exact(Eigen::MatrixXd(Eigen::Vector2d(0.9, 0.5).asDiagonal()));
  EXPECT_EQ(schur_decide(M).stable, std::optional<bool>(true));
  M.rad.setConstant(0.2);
  EXPECT_NE(schur_decide(M).stable, std::optional<bool>(true));
  // positive definiteness: [[1, 0], [0, 1e-3]] is PD; with radius 1e-2 on every entry it is not certain
  BallMatrix S = BallMatrix::exact(Eigen::MatrixXd(Eigen::Vector2d(1, 1e-3).asDiagonal()));
  EXPECT_TRUE(positive_definite(S));
  S.rad.setConstant(1e-2);
  EXPECT_FALSE(positive_definite(S));
  // indefinite
  EXPECT_FALSE(positive_definite(BallMatrix::exact(Eigen::MatrixXd(Eigen::Vector2d(1, -1).asDiagonal()))));
}

TEST(BallMatrix, LargeOrderIsDecided) {
  // order 300: a stable and an unstable matrix of known radius 0.99 / 1.01 (the contact scenes'
  // closed loops are of this order)
  std::mt19937_64 g(300);
  for (const rational& rho : {rational(99, 100), rational(101, 100)}) {
    const SchurDecision d = schur_decide(BallMatrix::exact(known_spectrum(g, 300, rho)));
    ASSERT_TRUE(d.stable.has_value()) << d.why;
    EXPECT_EQ(*d.stable, rho < 1) << d.why;
  }
}

TEST(BallMatrix, PositiveDefiniteIsNeverWrongNearSingular) {
  // S = L D L^T exactly (rationals), L unit lower triangular, D diagonal with one entry +-eps:
  // the inertia is D's (Sylvester), so S is PD iff every D_ii > 0 -- known exactly, whatever
  // rounding S's entries go through (BallMatrix::exact keeps it as radius). positive_definite
  // (the double-bound Cholesky first, the Arb congruence second) must never say PD for an
  // indefinite S; it must decide the PD cases whose eps is far above n u ||S|| (1e-6 at
  // ||S|| ~ 10, orders up to 120: ~1e6 times the double path's slack).
  std::mt19937_64 g(11);
  std::uniform_int_distribution<int> e(-4, 4), pick(0, 1);
  const std::vector<rational> eps = {rational(1, 1000000), rational(1, 10000000000LL), rational(1, 100000000000000LL)};
  int decided_far = 0, far = 0, pd_said = 0;
  for (int c = 0; c < 60; ++c) {
    const int n = c < 40 ? 4 + c : 120;
    MatQ L = MatQ::Identity(n, n), D = MatQ::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j) L(i, j) = rational(e(g), 8 * n);
    for (int i = 0; i < n; ++i) D(i, i) = rational(1 + (i % 5), 2);
    const rational ep = eps[static_cast<size_t>(c % 3)];
    const bool pd = pick(g) == 1;
    D(n / 2, n / 2) = pd ? ep : rational(-ep);
    const MatQ S = exact_product(exact_product(L, D), MatQ(L.transpose()));
    const bool said = positive_definite(BallMatrix::exact(S));
    if (!pd) {
      EXPECT_FALSE(said) << "case " << c << ": an indefinite matrix called positive definite";
    } else {
      pd_said += said;
      if (ep == eps[0]) {
        ++far;
        decided_far += said;
      }
    }
  }
  EXPECT_EQ(decided_far, far);
  EXPECT_GT(pd_said, 0);
}

TEST(BallMatrix, BadInput) {
  EXPECT_THROW(schur_decide(BallMatrix(2, 3)), InputError);
  EXPECT_THROW(BallMatrix(2, 3) * BallMatrix(2, 3), InputError);
  BallMatrix nan = BallMatrix::exact(Eigen::MatrixXd(Eigen::MatrixXd::Constant(2, 2, std::nan(""))));
  EXPECT_THROW(schur_decide(nan), NumericalError);
  EXPECT_EQ(schur_decide(BallMatrix(0, 0)).stable, std::optional<bool>(true));
}
