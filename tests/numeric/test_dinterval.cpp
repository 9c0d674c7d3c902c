// Dint (numeric/dinterval.hpp): double intervals with rounding bounds. Each operation's result
// contains the exact result (checked in rational arithmetic on random doubles of every
// magnitude, subnormal and near overflow included), sin_cos_pi contains Arb's sin and cos of
// pi k/D at 256 bits for k up to 2^100 (the exact integer reduction), and the constants its
// header's bounds rest on hold (checked in rationals).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/dinterval.hpp"

using namespace hapstab;
using flint::Ball;

namespace {

double random_double(std::mt19937_64& g) {
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<int> e(-1080, 1020), kind(0, 9);
  if (kind(g) == 0) return std::ldexp(static_cast<double>(g() % 1000), -1074);  // subnormal
  return std::ldexp(m(g), kind(g) < 5 ? e(g) / 16 : e(g));
}

bool contains(const Dint& x, const rational& q) {
  return (x.lo == -std::numeric_limits<double>::infinity() || exact_rational(x.lo) <= q) &&
         (x.hi == std::numeric_limits<double>::infinity() || q <= exact_rational(x.hi));
}

integer big(__int128 x) {
  const bool neg = x < 0;
  unsigned __int128 u = neg ? static_cast<unsigned __int128>(-x) : static_cast<unsigned __int128>(x);
  const integer hi(static_cast<unsigned long long>(u >> 64)), lo(static_cast<unsigned long long>(u));
  const integer r = (hi << 64) + lo;
  return neg ? integer(-r) : r;
}

/// x meets Arb's ball b, whose radius is below 1e-40: x holds the true value up to 1e-40 (an exact
/// value such as sin(pi/2) = 1 is an end of x and inside b, which may reach past it)
bool contains_ball(const Dint& x, const Ball& b) {
  const Enclosure<rational> e = b.bounds();
  return b.radius() < 1e-40 && (std::isinf(x.lo) || exact_rational(x.lo) <= e.hi) && (std::isinf(x.hi) || e.lo <= exact_rational(x.hi));
}

}  // namespace

TEST(Dint, OperationsContainTheExactResult) {
  std::mt19937_64 g(48);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    const double a1 = random_double(g), a2 = random_double(g), b1 = random_double(g), b2 = random_double(g);
    const Dint a(std::min(a1, a2), std::max(a1, a2)), b(std::min(b1, b2), std::max(b1, b2));
    // the extreme points' exact results (the ends of the exact interval result are among them)
    for (double x : {a.lo, a.hi})
      for (double y : {b.lo, b.hi}) {
        const rational X = exact_rational(x), Y = exact_rational(y);
        EXPECT_TRUE(contains(a + b, X + Y)) << x << " + " << y;
        EXPECT_TRUE(contains(a - b, X - Y)) << x << " - " << y;
        EXPECT_TRUE(contains(a * b, X * Y)) << x << " * " << y;
        if (!b.contains_zero()) {
          EXPECT_TRUE(contains(a / b, X / Y)) << x << " / " << y;
        } else {
          EXPECT_FALSE((a / b).finite());  // a quotient by an interval holding 0 decides nothing
        }
        ++compared;
      }
  }
  EXPECT_EQ(compared, 16000);
  // overflow gives the whole line, never a finite interval that misses the result
  const Dint huge(1e308, 1e308);
  EXPECT_FALSE((huge * huge).finite());
  EXPECT_FALSE((huge + huge).finite());
  // rationals and 128-bit integers are enclosed
  for (const rational& q : {rational(1, 3), rational(-2, 7), pow10(-400), pow10(20) / 3}) EXPECT_TRUE(contains(Dint::from_rational(q), q));
  EXPECT_FALSE(Dint::from_rational(pow10(400)).finite());
  const __int128 k = (static_cast<__int128>(1) << 100) + 12345;
  EXPECT_TRUE(contains(Dint::from_i128(k), rational(big(k))));
  EXPECT_TRUE(contains(dint_pi(), Ball::pi().bounds().lo));
  EXPECT_TRUE(contains(dint_pi(), Ball::pi().bounds().hi));
}

TEST(Dint, SinCosPiContainsArb) {
  // theta = pi k/D with D = M 2^level as the branch-and-bounds use it, k = nu i up to 2^100; every
  // octant and its edges (k/D near 0, 1/4, 1/2, 1, 3/2, negative k); widths checked near 1e-14
  flint::BallPrecision scope(256);
  std::mt19937_64 g(4848);
  int compared = 0, wide = 0;
  for (int i = 0; i < 3000; ++i) {
    __int128 D = static_cast<__int128>(4 * (g() % 100000) + 64) << (g() % 40);
    __int128 k;
    switch (i % 5) {
      case 0: k = static_cast<__int128>(g() % 100001) * (static_cast<__int128>(g() >> 4) % (D * 4)); break;  // nu i
      case 1: k = D * static_cast<long>(g() % 8) / 4 + static_cast<long>(g() % 5) - 2; break;  // octant edges
      case 2: k = static_cast<long>(g() % 7) - 3; break;                                         // theta ~ 0
      case 3: k = -static_cast<__int128>(g() % 1000000007) * static_cast<__int128>(g() % 1000000007); break;
      default: k = (static_cast<__int128>(g()) << 36) + static_cast<__int128>(g() % 1000); D = 2 * D + 1; break;
    }
    Dint s, c;
    ASSERT_TRUE(sin_cos_pi(k, D, s, c));
    Ball bs, bc;
    flint::sin_cos(Ball(rational(big(k), big(D))) * Ball::pi(), bs, bc);
    ASSERT_LT(bs.radius(), 1e-40);
    EXPECT_TRUE(contains_ball(s, bs)) << "sin(pi " << big(k) << "/" << big(D) << ") = " << bs.to_double() << " not in [" << s.lo << ", " << s.hi << "]";
    EXPECT_TRUE(contains_ball(c, bc)) << "cos(pi " << big(k) << "/" << big(D) << ") = " << bc.to_double() << " not in [" << c.lo << ", " << c.hi << "]";
    wide += s.hi - s.lo > 2e-14 || c.hi - c.lo > 2e-14;
    ++compared;
  }
  EXPECT_EQ(compared, 3000);
  EXPECT_EQ(wide, 0);
  Dint s, c;
  EXPECT_FALSE(sin_cos_pi(1, static_cast<__int128>(1) << 124, s, c));  // beyond its range: refused, not wrong
}

TEST(Dint, TheConstantsOfTheBoundsHold) {
  // pi/4 < 0.786; the series' first terms left out; sinh(0.786) <= 1.11 * 0.786, cosh <= 1.33
  // (the series summed to 30 terms and the rest bounded by twice the last: ratios below 1/2)
  const rational y(786, 1000);
  EXPECT_LT(Ball::pi().bounds().hi / 4, y);
  rational f = 1, p = 1, sh = 0, ch = 0, last = 0;  // f = j!, p = y^j
  for (int j = 0; j <= 60; ++j) {
    if (j > 0) f *= j, p *= y;
    last = p / f;
    (j % 2 == 0 ? ch : sh) += last;
    if (j == 21) { EXPECT_LE(p / y / f, rational(16, 10) * pow10(-22)); }  // y^21/21! <= 1.6e-22 y
    if (j == 22) { EXPECT_LE(p / f, rational(45, 10) * pow10(-24)); }      // y^22/22! <= 4.5e-24
  }
  EXPECT_LE(sh + 2 * last, rational(111, 100) * y);
  EXPECT_LE(ch + 2 * last, rational(133, 100));
  // the remainders the code adds cover those bounds: 48 u y >= 40 u y + 1.6e-22 y, 52 u >= 47 u + 4.5e-24
  const rational u = rational(1) / rational(integer(1) << 53);
  EXPECT_GE(8 * u, rational(16, 10) * pow10(-22));
  EXPECT_GE(5 * u, rational(45, 10) * pow10(-24));
  // atan: tan(pi/16) < 0.19892 (the argument after two halvings) and 0.19892^24/25 <= 6e-19
  flint::BallPrecision scope(128);
  Ball s, c;
  flint::sin_cos(Ball::pi() / Ball(16L), s, c);
  EXPECT_LT((s / c).bounds().hi, rational(19892, 100000));
  rational t = 1;
  for (int j = 0; j < 24; ++j) t *= rational(19892, 100000);
  EXPECT_LE(t / 25, rational(6) * pow10(-19));
}

TEST(Dint, AtanAndArgContainArb) {
  flint::BallPrecision scope(256);
  std::mt19937_64 g(480);
  for (int i = 0; i < 2000; ++i) {
    // moderate magnitudes for arg (its quotient of parts overflows beyond, then it decides nothing)
    std::uniform_real_distribution<double> m(-1, 1);
    auto draw = [&] { return i % 3 ? std::ldexp(m(g), static_cast<int>(g() % 60) - 30) : random_double(g); };
    const double x = draw(), y = draw();
    const Dint a = atan(Dint(x));
    Ball b;
    arb_atan(b.get(), Ball(x).get(), 256);
    EXPECT_TRUE(contains_ball(a, b)) << "atan " << x;
    EXPECT_LT(a.hi - a.lo, 1e-14 * std::max(1.0, std::abs(x)));
    const Dint arg_d = arg(CDint{Dint(x), Dint(y)});
    const bool moderate = [](double a, double b) {
      return std::abs(a) < 1e100 && std::abs(b) < 1e100 && (a == 0 || std::abs(a) > 1e-100) && (b == 0 || std::abs(b) > 1e-100);
    }(x, y);
    if (x > 0 || y != 0) {
      if (moderate) { EXPECT_TRUE(arg_d.finite()) << x << " " << y; }
      EXPECT_TRUE(contains_ball(arg_d, flint::atan2(Ball(y), Ball(x)))) << "arg " << x << " + j " << y;
    }
  }
}
