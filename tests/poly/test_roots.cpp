// Certified root enclosures (poly/roots.hpp), the FLINT way: thousands of random polynomials
// built from known roots -- rational ones with multiplicities, complex pairs a +- j b with
// rational a, b, roots on the unit circle (z = +-1, +-j) -- and every true root must lie in
// exactly one returned enclosure, with its exact multiplicity, and no enclosure may be left
// without a root. Containment is checked in exact rational arithmetic on the outward-rounded
// double bounds (|z| against the squared modulus, exactly).
#include <gtest/gtest.h>

#include <random>

#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/roots.hpp"

using namespace hapstab;

namespace {

struct TrueRoot {
  rational re, im;
  int mult;
};

Polynomial<rational> from_roots(const std::vector<TrueRoot>& roots) {
  Polynomial<rational> p(rational(1));
  for (const auto& r : roots)
    for (int k = 0; k < r.mult; ++k) {
      if (r.im == 0)
        p = p * Polynomial<rational>(std::vector<rational>{-r.re, rational(1)});
      else  // (z - a - jb)(z - a + jb) = z^2 - 2a z + a^2 + b^2
        p = p * Polynomial<rational>(std::vector<rational>{r.re * r.re + r.im * r.im, -2 * r.re, rational(1)});
    }
  return p;
}

bool inside(const RootEnclosure& e, const rational& re, const rational& im) {
  const rational a2 = re * re + im * im;
  return rational(e.re_lo) <= re && re <= rational(e.re_hi) && rational(e.im_lo) <= im && im <= rational(e.im_hi) &&
         rational(e.abs_lo) * rational(e.abs_lo) <= a2 && a2 <= rational(e.abs_hi) * rational(e.abs_hi);
}

}  // namespace

TEST(Roots, RandomPolynomialsEveryRootEnclosedOnceWithItsMultiplicity) {
  std::mt19937_64 g(38);
  std::uniform_int_distribution<int> num(-40, 40), den(1, 9), mult(1, 3), count(1, 4), kind(0, 5);
  int cases = 0, complex_roots = 0, multiple = 0, circle = 0;
  for (int c = 0; c < 2000; ++c) {
    std::vector<TrueRoot> roots;
    const int n = count(g);
    for (int i = 0; i < n; ++i) {
      TrueRoot r{rational(num(g), den(g)), rational(0), mult(g) == 3 ? 2 : 1};
      const int k = kind(g);
      const int im = num(g);
      if (k == 0) r.im = rational(im == 0 ? 1 : im, den(g));  // a complex pair
      if (k == 1) r = {rational(g() % 2 ? 1 : -1), rational(0), r.mult};  // z = +-1
      if (k == 2) r = {rational(0), rational(1), 1};                     // z = +-j
      bool dup = false;
      for (const auto& q : roots) dup = dup || (q.re == r.re && (q.im == r.im || q.im == -r.im));
      if (dup) continue;
      if (r.im < 0) r.im = -r.im;
      roots.push_back(r);
    }
    const int lead = num(g);
    const Polynomial<rational> p = from_roots(roots) * rational(lead == 0 ? 3 : lead, den(g));
    const std::vector<RootEnclosure> enc = enclose_roots(p);
    // every true root (both members of a pair) in exactly one enclosure, with its multiplicity
    size_t expected = 0;
    for (const auto& r : roots) {
      for (int sign : {1, -1}) {
        if (r.im == 0 && sign < 0) continue;
        ++expected;
        int hits = 0;
        for (const auto& e : enc)
          if (inside(e, r.re, sign * r.im)) {
            ++hits;
            EXPECT_EQ(e.multiplicity, r.mult) << "case " << c;
          }
        EXPECT_EQ(hits, 1) << "case " << c << ": root " << r.re << " + j " << sign * r.im;
      }
      complex_roots += r.im != 0;
      multiple += r.mult > 1;
      circle += r.re * r.re + r.im * r.im == 1;
    }
    EXPECT_EQ(enc.size(), expected) << "case " << c;
    ++cases;
  }
  // the families actually occurred (a generator that stopped producing them would pass vacuously)
  EXPECT_GE(complex_roots, 300);
  EXPECT_GE(multiple, 300);
  EXPECT_GE(circle, 300);
}

TEST(Roots, TextIsAnOutwardEnclosure) {
  // z^2 - 2 = 0: sqrt(2) printed as an interval that contains it; z = 2 printed exactly
  const auto e = enclose_roots(Polynomial<rational>(std::vector<rational>{-2, 0, 1}));
  ASSERT_EQ(e.size(), 2u);
  for (const auto& r : e) {
    const std::string t = r.text();
    EXPECT_NE(t.find('['), std::string::npos) << t;
  }
  const auto two = enclose_roots(Polynomial<rational>(std::vector<rational>{-2, 1}));
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(two[0].text(), "z = 2");
  EXPECT_THROW(enclose_roots(Polynomial<rational>()), InputError);
  EXPECT_TRUE(enclose_roots(Polynomial<rational>(rational(5))).empty());
}
