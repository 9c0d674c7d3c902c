// Where an eigenvalue of M0 + p M1 can meet the unit circle (lti/circle_crossing.hpp): R(p) = Res_z(c, z^n c(1/z))
// on families whose crossings are known by hand.
#include <gtest/gtest.h>

#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/sturm.hpp"

using namespace hapstab;

namespace {
Mat<rational> mat(std::initializer_list<std::initializer_list<rational>> rows) {
  Mat<rational> M(static_cast<long>(rows.size()), static_cast<long>(rows.begin()->size()));
  long i = 0;
  for (const auto& r : rows) {
    long j = 0;
    for (const auto& x : r) M(i, j++) = x;
    ++i;
  }
  return M;
}
}  // namespace

// lambda = 1 - p: on the circle at p = 0 and p = 2 only. R = (1 - lambda^2) up to a constant = p (2 - p).
TEST(CircleCrossing, ScalarFamily) {
  const auto M0 = mat({{rational(1)}}), M1 = mat({{rational(-1)}});
  const CircleCrossing c = circle_crossing(M0, M1);
  ASSERT_FALSE(c.identically_zero);
  EXPECT_EQ(c.zero_order, 1);
  EXPECT_EQ(c.R.degree(), 1);
  EXPECT_EQ(c.R(rational(2)), rational(0));
  EXPECT_EQ(no_circle_crossing(M0, M1, rational(1)), "");
  EXPECT_EQ(no_circle_crossing(M0, M1, rational(199, 100)), "");
  EXPECT_NE(no_circle_crossing(M0, M1, rational(2)), "");  // (0, 2] holds the crossing at 2 itself
  EXPECT_NE(no_circle_crossing(M0, M1, rational(0)), "");
}

// A pure mass's Jordan block at z = 1 under a damped spring scaled by p: M(p) = [[1, 1], [-p, 1 - 2p]], det = 1 - p,
// trace = 2 - 2p. By Jury's conditions it is Schur stable exactly for 0 < p < 4/3 (1 + trace + det = 4 - 3p), the
// eigenvalues leaving z = 1 like 1 +- j sqrt(p): no root of R in (0, 4/3), one at 4/3 (z = -1).
TEST(CircleCrossing, JordanBlockLeavesTheCircle) {
  const auto M0 = mat({{rational(1), rational(1)}, {rational(0), rational(1)}});
  const auto M1 = mat({{rational(0), rational(0)}, {rational(-1), rational(-2)}});
  const CircleCrossing c = circle_crossing(M0, M1);
  ASSERT_FALSE(c.identically_zero);
  EXPECT_GE(c.zero_order, 1);
  EXPECT_EQ(c.R(rational(4, 3)), rational(0));
  EXPECT_EQ(count_real_roots(c.R, rational(0), rational(4, 3) - rational(1, 1000000)), 0);
  EXPECT_EQ(no_circle_crossing(M0, M1, rational(13, 10)), "");
  EXPECT_NE(no_circle_crossing(M0, M1, rational(3, 2)), "");
}

// det = 1 + p/2 > 1: unstable for every p > 0, yet no eigenvalue on the circle on (0, 1] -- the resultant shows the
// inertia constant, not stability (the caller proves M(a) stable).
TEST(CircleCrossing, ConstantInertiaIsNotStability) {
  const auto M0 = mat({{rational(1), rational(1)}, {rational(0), rational(1)}});
  const auto M1 = mat({{rational(0), rational(0)}, {rational(-1), rational(-1, 2)}});
  EXPECT_EQ(no_circle_crossing(M0, M1, rational(1)), "");
}

// A rotation by pi/2 that p does not move: eigenvalues +-j on the circle at every p, R = 0 identically.
TEST(CircleCrossing, IdenticallyZeroShowsNothing) {
  const auto M0 = mat({{rational(0), rational(-1)}, {rational(1), rational(0)}});
  const auto M1 = mat({{rational(0), rational(0)}, {rational(0), rational(0)}});
  EXPECT_TRUE(circle_crossing(M0, M1).identically_zero);
  EXPECT_NE(no_circle_crossing(M0, M1, rational(1)), "");
}

TEST(CircleCrossing, RefusesWhatItCannotTake) {
  const auto M0 = mat({{rational(1), rational(0)}}), M1 = mat({{rational(1), rational(0)}});
  EXPECT_THROW(circle_crossing(M0, M1), InputError);
}
