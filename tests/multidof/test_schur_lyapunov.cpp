// Tests of hapstab/numeric/lyapunov.hpp and multidof::schur_stable: the Lyapunov certificate proves stability only of
// stable matrices (checked against the exact Schur-Cohn test of poly/stability.hpp), also at
// radius 1 - 1e-9, and gives no proof for unstable or marginal ones, nor for a Jordan block so
// close to the circle that double precision cannot hold P (where multidof::schur_stable falls
// back to the exact test and still gets the right answer).
#include <gtest/gtest.h>

#include <random>

#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/environment.hpp"
#include "hapstab/numeric/lyapunov.hpp"
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
