// Exact decimal parsing and correctly rounded decimal output (numeric/decimal.hpp).
#include <gtest/gtest.h>

#include "hapstab/numeric/decimal.hpp"
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
}

TEST(Decimal, CommonDecimalDecidesOnlyWhenBothEndsAgree) {
  EXPECT_EQ(common_decimal(rational(33332, 100000), rational(33334, 100000), 3).value(), "0.333");
  EXPECT_FALSE(common_decimal(rational(3344, 10000), rational(3356, 10000), 3).has_value());
}
