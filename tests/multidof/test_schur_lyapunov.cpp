// Tests of hapstab/numeric/lyapunov.hpp and multidof::schur_stable: the Lyapunov certificate proves stability only of
// stable matrices (checked against the exact Schur-Cohn test of poly/stability.hpp), also at
// radius 1 - 1e-9, and gives no proof for unstable or marginal ones, nor for a Jordan block so
// close to the circle that double precision cannot hold P (where multidof::schur_stable falls
// back to the exact test and still gets the right answer). numeric/lyapunov_ball.hpp: one P for a
// segment of matrices proves only segments whose every point is stable (exact Schur-Cohn along it),
// never one whose ends are stable and whose middle is not.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/numeric/lyapunov.hpp"
#include "hapstab/numeric/lyapunov_ball.hpp"
#include "hapstab/poly/stability.hpp"
#include "proofs/known_spectrum.hpp"

using namespace hapstab;

namespace {

// a dense rational matrix with the eigenvalues and Jordan structure of D (proofs/known_spectrum.hpp)
MatQ similar(const MatQ& D, unsigned seed) {
  std::mt19937 g(seed);
  return proofs::dense_similar(D, g);
}
using proofs::rotation_blocks;

bool exact_schur(const MatQ& A) { return schur_stable(charpoly(A)); }

// the exact matrix as balls of radius 0 (up to 2^-128 relative)
void to_balls(flint::BallMat& B, const MatQ& A) {
  flint::QMat q(A.rows(), A.cols());
  for (long i = 0; i < A.rows(); ++i)
    for (long j = 0; j < A.cols(); ++j) flint::set(q.at(i, j), A(i, j));
  arb_mat_set_fmpq_mat(B.get(), q.get(), 128);
}

bool segment_proven(const MatQ& A0, const MatQ& A1) {
  flint::BallMat B0(A0.rows(), A0.cols()), B1(A1.rows(), A1.cols());
  to_balls(B0, A0);
  to_balls(B1, A1);
  return lyapunov_proves_segment_stable(B0, B1);
}

}  // namespace

TEST(Lyapunov, ProvesStableDenseMatrices) {
  for (int blocks : {2, 6, 10}) {
    const MatQ A = similar(rotation_blocks(blocks, rational(9, 10)), 7u + static_cast<unsigned>(blocks));
    ASSERT_TRUE(exact_schur(A));
    std::string why;
    EXPECT_TRUE(lyapunov_proves_schur_stable(A, &why)) << blocks << ": " << why;
  }
}

TEST(Lyapunov, ProvesEigenvaluesAtRadiusOneMinus1e9) {
  const rational r = 1 - rational(1, 1000000000);
  const MatQ A = similar(rotation_blocks(6, r), 3);  // 12 x 12, |lambda| = 1 - 1e-9
  ASSERT_TRUE(exact_schur(A));
  std::string why;
  EXPECT_TRUE(lyapunov_proves_schur_stable(A, &why)) << why;
  EXPECT_TRUE(multidof::schur_stable(A));
}

TEST(Lyapunov, NoProofForUnstableOrMarginal) {
  for (const rational& r : {rational(1), rational(1000000001, 1000000000), rational(11, 10)}) {
    const MatQ A = similar(rotation_blocks(6, r), 5);
    EXPECT_FALSE(exact_schur(A));
    std::string why;
    EXPECT_FALSE(lyapunov_proves_schur_stable(A, &why)) << r;
    EXPECT_FALSE(why.empty());
    EXPECT_FALSE(multidof::schur_stable(A)) << r;
  }
  // one eigenvalue just outside among stable ones
  MatQ D = rotation_blocks(6, rational(1, 2));
  D(11, 11) = rational(-1000001, 1000000);
  D(11, 10) = 0;
  D(10, 11) = 0;
  const MatQ A = similar(D, 9);
  EXPECT_FALSE(lyapunov_proves_schur_stable(A));
  EXPECT_FALSE(multidof::schur_stable(A));
}

TEST(Lyapunov, JordanBlockNearTheCircleFallsBackToExact) {
  // a 12 x 12 Jordan block at r = 1 - 1e-6: stable, but P ~ (1 - r)^-23 overflows double;
  // the certificate gives no proof and the exact test decides "stable"
  const int n = 12;
  const rational r = 1 - rational(1, 1000000);
  MatQ J = MatQ::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    J(i, i) = r;
    if (i + 1 < n) J(i, i + 1) = 1;
  }
  const MatQ A = similar(J, 11);
  EXPECT_FALSE(lyapunov_proves_schur_stable(A));
  std::string how;
  EXPECT_TRUE(multidof::schur_stable(A, &how));
  EXPECT_NE(how.find("Schur-Cohn"), std::string::npos) << how;
  // and the same block at r = 1 is not stable
  for (int i = 0; i < n; ++i) J(i, i) = 1;
  EXPECT_FALSE(multidof::schur_stable(similar(J, 11)));
}

TEST(LyapunovSegment, ProvesAStableSegment) {
  const MatQ A0 = similar(rotation_blocks(3, rational(9, 10)), 11u);
  MatQ A1 = A0;
  A1(0, 1) += rational(1, 100);
  EXPECT_TRUE(segment_proven(A0, A1));
}

TEST(LyapunovSegment, NoProofWhereTheEndsAreStableAndTheMiddleIsNot) {
  // two nilpotent ends (every eigenvalue 0); the midpoint [[0, 3/2], [3/2, 0]] has the eigenvalues +-3/2
  MatQ A0 = MatQ::Zero(2, 2), A1 = MatQ::Zero(2, 2);
  A0(0, 1) = 3;
  A1(1, 0) = 3;
  ASSERT_TRUE(exact_schur(A0));
  ASSERT_TRUE(exact_schur(A1));
  MatQ mid = (A0 + A1) / rational(2);
  ASSERT_FALSE(exact_schur(mid));
  EXPECT_FALSE(segment_proven(A0, A1));
  MatQ unstable = A0;  // an end outside
  unstable(0, 0) = rational(11, 10);
  EXPECT_FALSE(segment_proven(unstable, A1 / rational(10)));
}

TEST(LyapunovSegment, EveryProvenSegmentIsStableAlongIt) {
  // random pairs of dense 4 x 4 matrices, entries in [-0.55, 0.55]; each proven segment is checked exactly at
  // t = k/16 (exact Schur-Cohn on the rational A(t)), and the run must prove some and refuse some
  std::mt19937 g(81);
  std::uniform_int_distribution<int> entry(-55, 55);
  int proven = 0, refused = 0;
  for (int trial = 0; trial < 400; ++trial) {
    MatQ A[2] = {MatQ(4, 4), MatQ(4, 4)};
    for (MatQ& M : A)
      for (long i = 0; i < 4; ++i)
        for (long j = 0; j < 4; ++j) M(i, j) = rational(entry(g), 100);
    if (segment_proven(A[0], A[1])) {
      ++proven;
      for (int k = 0; k <= 16; ++k) {
        const MatQ At = A[0] * rational(16 - k, 16) + A[1] * rational(k, 16);
        EXPECT_TRUE(exact_schur(At)) << "trial " << trial << " t = " << k << "/16";
      }
    } else {
      ++refused;
    }
  }
  EXPECT_GT(proven, 10);
  EXPECT_GT(refused, 10);
  std::printf("%d proven, %d refused\n", proven, refused);
}
