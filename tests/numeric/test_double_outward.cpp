// double_outward (numeric/decimal.hpp): a rational rounded to a double on the side asked, the
// ends of every enclosure the Python module hands out as floats (lo/hi). Checked exactly, in
// rational arithmetic, on a campaign of random rationals of every magnitude (normal, subnormal,
// beyond the double range) and on doubles themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstring>
#include <random>

#include "hapstab/numeric/decimal.hpp"

using namespace hapstab;

namespace {

rational random_rational(std::mt19937_64& g) {
  std::uniform_int_distribution<int> digits(1, 40), sign(0, 1);
  std::uniform_int_distribution<long> e(-340, 340);
  auto big = [&](int n) {
    integer x = 0;
    for (int k = 0; k < n; ++k) x = x * 10 + integer(int(g() % 10));
    return x + 1;
  };
  rational q(big(digits(g)), big(digits(g)));
  const long ex = e(g);
  q *= ex >= 0 ? pow10(ex) : 1 / pow10(-ex);
  return sign(g) ? rational(-q) : q;
}

}  // namespace

TEST(DoubleOutward, EnclosesEveryRationalWithAdjacentDoubles) {
  // lo = double_outward(q, -1) <= q <= hi = double_outward(q, +1), exactly; lo and hi are q when
  // q is a double, else adjacent doubles (nothing is lost beyond one rounding); nearest is one of
  // them. MIN compared cases of each kind (inside the normal range, subnormal, beyond it).
  constexpr int kCases = 20000, MIN = 200;
  std::mt19937_64 g(41);
  const double max = std::numeric_limits<double>::max();
  int normal = 0, tiny = 0, huge = 0;
  for (int i = 0; i < kCases; ++i) {
    const rational q = random_rational(g);
    const double lo = double_outward(q, -1), hi = double_outward(q, +1), near = double_outward(q, 0);
    ASSERT_TRUE(near == lo || near == hi) << q;
    if (std::isinf(lo) || std::isinf(hi) || std::fabs(lo) == max || std::fabs(hi) == max) {
      ++huge;  // beyond the range: the outward side is infinite, the inward side the largest double
      ASSERT_TRUE(q > 0 ? (hi == INFINITY && lo == max) : (lo == -INFINITY && hi == -max)) << q;
      continue;
    }
    ASSERT_LE(exact_rational(lo), q) << q;
    ASSERT_GE(exact_rational(hi), q) << q;
    ASSERT_TRUE(lo == hi ? exact_rational(lo) == q : std::nextafter(lo, INFINITY) == hi) << q;
    if (std::fabs(lo) < std::numeric_limits<double>::min() || std::fabs(hi) < std::numeric_limits<double>::min())
      ++tiny;
    else
      ++normal;
  }
  EXPECT_GE(normal, MIN);
  EXPECT_GE(tiny, MIN);
  EXPECT_GE(huge, MIN);
}

TEST(DoubleOutward, ADoubleIsItselfOnBothSides) {
  std::mt19937_64 g(7);
  for (int i = 0; i < 10000; ++i) {
    double x;
    do {
      const uint64_t bits = g();
      std::memcpy(&x, &bits, sizeof x);
    } while (!std::isfinite(x));
    const rational q = exact_rational(x);
    ASSERT_EQ(double_outward(q, -1), x);
    ASSERT_EQ(double_outward(q, +1), x);
    ASSERT_EQ(double_outward(q, 0), x);
  }
  EXPECT_LT(exact_rational(double_outward(rational(1, 3), -1)), rational(1, 3));
  EXPECT_GT(exact_rational(double_outward(rational(1, 3), +1)), rational(1, 3));
  EXPECT_EQ(double_outward(rational(0), -1), 0.0);
}
