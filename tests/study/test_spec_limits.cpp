// Sweep specs are untrusted (docs/security.md; issue 32): the number of points is counted from
// the axes' sizes before any value is generated, every exact value has a bounded size, exact
// values are written in time linear in their size, and a spec deeper than toml++ can take is
// refused before toml++ sees it.
#include <gtest/gtest.h>

#include <boost/multiprecision/gmp.hpp>
#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/study/spec.hpp"

using namespace hapstab;
using namespace hapstab::study;

namespace {

std::string error_of(const std::string& spec) {
  try {
    parse_spec(spec, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string head = "command = \"bound\"\n[args]\nH = \"K\"\nT = \"1/1000\"\n[axes]\n";

}  // namespace

// Two random axes of 10^7 values were generated in full (1.5 GB) before the product was checked.
TEST(SpecLimits, PointsAreCountedBeforeAnyValueIsGenerated) {
  const std::string msg = error_of(head + "K = { random = 10000000, from = \"0\", to = \"1\", seed = 1 }\n"
                                          "B = { random = 10000000, from = \"0\", to = \"1\", seed = 2 }\n");
  EXPECT_NE(msg.find("s.toml: axes.B: the axes up to this one make 100000000000000 points, more than the limit of "
                     "10^9 (nothing was generated)"),
            std::string::npos)
      << msg;
  // a values list, a linear and a random axis are counted alike
  EXPECT_NE(error_of(head + "K = { values = [\"1\", \"2\"] }\nB = { from = \"0\", to = \"1\", points = 10000000 }\n"
                            "C = { random = 100, from = \"0\", to = \"1\", seed = 1 }\n")
                .find("axes.C: the axes up to this one make 2000000000 points"),
            std::string::npos);
}

// "1e-200000" is 9 bytes of spec and 660,000 bits: a 150-byte spec parsed for more than 55 s.
TEST(SpecLimits, EveryExactValueHasABoundedSize) {
  for (const std::string& axis : {std::string("K = { from = \"0\", to = \"1e-200000\", points = 3 }"),
                                  std::string("K = { values = [\"1\", \"1e-200000\"] }"),
                                  std::string("K = { random = 3, from = \"1e200000\", to = \"1\", seed = 1 }")}) {
    const std::string msg = error_of(head + axis + "\n");
    EXPECT_NE(msg.find("s.toml: axes.K."), std::string::npos) << msg;
    EXPECT_NE(msg.find("bits of numerator and denominator, more than the limit of 1024"), std::string::npos) << msg;
  }
  // 300 digits pass
  const Spec s = parse_spec(head + "K = { from = \"0\", to = \"1e-300\", points = 3 }\n", "s.toml");
  EXPECT_EQ(s.axes[0].values[2], "0." + std::string(299, '0') + "1");
}

// exact_text finds the powers of 2 and 5 of the denominator by GMP's valuations and writes the
// decimal at once: the loops it replaces were quadratic in the size of the denominator.
TEST(SpecLimits, ExactTextOfLargeDenominators) {
  using boost::multiprecision::pow;
  const rational tiny(integer(3), pow(integer(10), 200000));  // 3e-200000
  const std::string t = exact_text(tiny);
  EXPECT_EQ(t.size(), 200002u);  // "0." and 200000 digits
  EXPECT_EQ(t.substr(0, 4), "0.00");
  EXPECT_EQ(t.back(), '3');
  EXPECT_EQ(exact_text(rational(integer(-7), pow(integer(2), 5000))).size(), 5003u);  // -0.<5000 digits>
  EXPECT_EQ(exact_text(rational(integer(1), pow(integer(5), 3) * pow(integer(2), 7))), "0.0000625");
  EXPECT_EQ(exact_text(rational(integer(1), pow(integer(5), 4000) * 3)).find('/'), 1u);  // not terminating: p/q
  EXPECT_EQ(exact_text(rational(-3, 40)), "-0.075");
}

TEST(SpecLimits, DeepTablesAreRefusedBeforeToml) {
  std::string deep = "a";
  for (int i = 0; i < 50000; ++i) deep += ".a";
  const std::string msg = error_of(head + "K = { values = [\"1\"] }\n[" + deep + "]\n");
  EXPECT_NE(msg.find("s.toml:7: a key or table nested 50001 levels deep"), std::string::npos) << msg;
}
