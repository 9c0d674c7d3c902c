// Exact decimal parsing and correctly rounded decimal output (numeric/decimal.hpp).
#include <gtest/gtest.h>

#include <limits>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/numeric/error.hpp"

using namespace hapstab;

TEST(Decimal, SameRationalWhateverTheSpelling) {
  const rational milli(1, 1000);
  for (const char* s : {"0.001", "1e-3", "1/1000", "+.001", "1E-3", " 0.0010 ", "10e-4", "0.5/500", "1e-3/1"})
    EXPECT_EQ(parse_rational(s), milli) << s;
  EXPECT_EQ(parse_rational("-2.5e+3"), rational(-2500));
  EXPECT_EQ(parse_rational("3/4"), rational(3, 4));
  EXPECT_EQ(parse_rational("7"), rational(7));
  // leading zeros are decimal, not octal; long mantissas are exact
  EXPECT_EQ(parse_rational("007"), rational(7));
  EXPECT_EQ(parse_rational("0.09"), rational(9, 100));
  EXPECT_EQ(parse_rational("00.5e1"), rational(5));
  EXPECT_EQ(parse_rational("-000"), rational(0));
  EXPECT_EQ(parse_rational("123456789012345678901234567890.5"), rational(integer("246913578024691357802469135781"), 2));
}

TEST(Decimal, MalformedIsRefusedByName) {
  for (const char* s : {"", "abc", "1e", "1.2.3", "--1", "1/0", "1/", "/2", "e5", "1e1234567", "0x10", "1,5"}) {
    try {
      parse_rational(s, "--T");
      ADD_FAILURE() << "accepted '" << s << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--T"), std::string::npos) << e.what();
    }
  }
  try {
    parse_rational("1/0", "--T");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("divides by zero"), std::string::npos);
  }
}

TEST(Decimal, CorrectlyRoundedHalfEven) {
  EXPECT_EQ(to_decimal(rational(1, 3), 5), "0.33333");
  EXPECT_EQ(to_decimal(rational(2, 3), 5), "0.66667");
  EXPECT_EQ(to_decimal(rational(-1, 2000), 50), "-0.0005");
  EXPECT_EQ(to_decimal(rational(125, 1000), 2), "0.12");   // tie -> even
  EXPECT_EQ(to_decimal(rational(135, 1000), 2), "0.14");   // tie -> even
  EXPECT_EQ(to_decimal(rational(9995, 1000), 3), "10");    // carry into a new digit
  EXPECT_EQ(to_decimal(rational(123456789), 3), "1.23e+08");
  EXPECT_EQ(to_decimal(rational(1, 10000000), 3), "1e-07");
  EXPECT_EQ(to_decimal(rational(0), 3), "0");
  EXPECT_EQ(to_decimal(rational(1234), 10), "1234");
}

TEST(Decimal, ExactRationalOfBinaryFloats) {
  EXPECT_EQ(exact_rational(0.5), rational(1, 2));
  EXPECT_EQ(exact_rational(-3.0), rational(-3));
  EXPECT_NE(exact_rational(0.1), rational(1, 10));  // 0.1 is not a double
  EXPECT_EQ(exact_rational(mp50(0.1)), exact_rational(0.1));
  EXPECT_EQ(exact_rational(1e300) * exact_rational(1e-300) > 0, true);
  EXPECT_EQ(exact_rational(0.1), rational(integer(3602879701896397), integer(1) << 55));
  EXPECT_EQ(exact_rational(5e-324), rational(integer(1), integer(1) << 1074));  // the least subnormal
  EXPECT_EQ(exact_rational(-std::numeric_limits<double>::max()), -rational((integer(1) << 1024) - (integer(1) << 971)));
  EXPECT_EQ(exact_rational(-0.0), rational(0));
  EXPECT_THROW(exact_rational(std::numeric_limits<double>::quiet_NaN()), InputError);
}

TEST(Decimal, CommonDecimalDecidesOnlyWhenBothEndsAgree) {
  EXPECT_EQ(common_decimal(rational(33332, 100000), rational(33334, 100000), 3).value(), "0.333");
  EXPECT_FALSE(common_decimal(rational(3344, 10000), rational(3356, 10000), 3).has_value());
}

// What `stability --max`, `wedge` and `bound` print of an enclosure that did not narrow to the
// asked digits: only the digits both ends share, and how many (issue 30; before, the midpoint
// was printed to all the asked digits).
TEST(Decimal, SharedDecimalKeepsOnlyTheDigitsBothEndsShare) {
  auto s = shared_decimal(rational(123441, 100000), rational(123444, 100000), 20);  // [1.23441, 1.23444]
  EXPECT_EQ(s.text, "1.2344");
  EXPECT_EQ(s.digits, 5);
  s = shared_decimal(rational(1, 3), rational(1, 3), 12);  // exact: every asked digit
  EXPECT_EQ(s.text, "0.333333333333");
  EXPECT_EQ(s.digits, 12);
  s = shared_decimal(rational(14, 10), rational(16, 10), 20);  // no first digit in common
  EXPECT_EQ(s.text, "");
  EXPECT_EQ(s.digits, 0);
  s = shared_decimal(rational(-2001, 1000), rational(-1999, 1000), 20);  // both round to -2.00 ... -2
  EXPECT_EQ(s.digits, 3);
  EXPECT_EQ(s.text, "-2");
}

// The decimal exponent e (10^e <= |x| < 10^(e+1)) is estimated in double and fixed exactly: at
// and next to every power of ten from 10^-40 to 10^40 (|x| 10^k (1 -+ 2^-200): the double estimate
// cannot tell them apart), each output must hold x between its outward ends one unit apart, and
// a power of ten must come back as itself.
TEST(Decimal, ExponentFixedExactlyAtPowersOfTen) {
  const rational tiny = rational(integer(1), integer(1) << 200);
  int compared = 0;
  for (int k = -40; k <= 40; ++k) {
    const rational p = pow10(k);
    for (int side : {-1, 0, +1})
      for (int sign : {-1, +1}) {
        const rational x = sign * p * (1 + side * tiny);
        const int e = side < 0 ? k - 1 : k;  // floor(log10 |x|), exactly
        for (int digits : {1, 5, 17, 30}) {
          const rational lo = parse_rational(decimal_outward(x, digits, -1));
          const rational hi = parse_rational(decimal_outward(x, digits, +1));
          EXPECT_LE(lo, x);
          EXPECT_GE(hi, x);
          EXPECT_LE(hi - lo, pow10(e - digits + 1)) << k << " " << side << " " << digits;
          if (side == 0) { EXPECT_EQ(parse_rational(to_decimal(x, digits)), x) << k << " " << digits; }
          ++compared;
        }
      }
  }
  EXPECT_EQ(compared, 81 * 6 * 4);
}

// decimal_outward is the nearest decimal of `digits` digits on the asked side: an enclosure
// printed with it still contains the value, and is no wider than one unit in the last digit.
TEST(Decimal, OutwardIsTheNearestDecimalOnTheAskedSide) {
  EXPECT_EQ(decimal_outward(rational(1, 3), 5, -1), "0.33333");
  EXPECT_EQ(decimal_outward(rational(1, 3), 5, +1), "0.33334");
  EXPECT_EQ(decimal_outward(rational(-1, 3), 5, -1), "-0.33334");
  EXPECT_EQ(decimal_outward(rational(-1, 3), 5, +1), "-0.33333");
  EXPECT_EQ(decimal_outward(rational(2, 3), 5, -1), "0.66666");  // not to nearest
  for (int dir : {-1, +1}) {
    EXPECT_EQ(decimal_outward(rational(1, 8), 5, dir), "0.125");  // exact: itself
    EXPECT_EQ(decimal_outward(rational(-1234), 4, dir), "-1234");
    EXPECT_EQ(decimal_outward(rational(0), 5, dir), "0");
  }
  EXPECT_EQ(decimal_outward(rational(999999, 100000), 5, +1), "10");  // carry into a new digit
  EXPECT_EQ(decimal_outward(rational(999999, 100000), 5, -1), "9.9999");
  EXPECT_EQ(decimal_outward(rational(123456789), 3, +1), "1.24e+08");
  EXPECT_EQ(decimal_outward(rational(123456789), 3, -1), "1.23e+08");
  // containment and width on many values: lo <= q <= hi, hi - lo <= one unit of the last digit
  for (long p = -997; p <= 997; p += 13)
    for (long q : {7L, 1000L, 999983L}) {
      const rational x(p, q);
      const rational lo = parse_rational(decimal_outward(x, 6, -1)), hi = parse_rational(decimal_outward(x, 6, +1));
      EXPECT_LE(lo, x);
      EXPECT_GE(hi, x);
      EXPECT_LE(hi - lo, abs(x) * rational(1, 10000)) << p << "/" << q;  // 10^-5 relative >= one unit of 6 digits
    }
}
