// Tests of exact root counting/isolation (hapstab/poly/sturm.hpp). Every expected root is known
// exactly (rational) or as the root of a simple equation (sqrt 2, cos((2k-1)pi/20)) that is
// checked by exact sign evaluation or against a 100-digit MPFR value.
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/poly/sturm.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_sturm {

using namespace hapstab;
using P = Polynomial<rational>;

namespace {
P X() { return P::monomial(1); }
P lin(rational a) { return X() - P(a); }
bool in(const RootInterval& r, const rational& x) { return r.lo <= x && x <= r.hi; }
void expect_disjoint_sorted(const std::vector<RootInterval>& v) {
  for (size_t i = 0; i < v.size(); ++i) {
    EXPECT_LE(v[i].lo, v[i].hi);
    // neighbours may share an endpoint, which is then not a root (it was a bisection point)
    if (i) { EXPECT_LE(v[i - 1].hi, v[i].lo); }
    if (i && v[i - 1].hi == v[i].lo) { EXPECT_FALSE(v[i].is_exact() || v[i - 1].is_exact()); }
  }
}
}  // namespace

TEST(Sturm, ZeroAndConstant) {
  EXPECT_THROW(isolate_real_roots(P()), InputError);
  EXPECT_THROW(count_real_roots(P(), 0, 1), InputError);
  EXPECT_THROW(sturm_sequence(P()), InputError);
  EXPECT_TRUE(isolate_real_roots(P(rational(-3))).empty());
  EXPECT_EQ(count_real_roots(P(rational(5)), -10, 10), 0);
  EXPECT_THROW(isolate_real_roots(X(), 1, 0), InputError);
}

TEST(Sturm, HalfOpenCounting) {
  P p = X() * X() - P(1);
  EXPECT_EQ(count_real_roots(p, -1, 1), 1);  // (−1, 1] holds only 1
  EXPECT_EQ(count_real_roots(p, -2, 1), 2);
  EXPECT_EQ(count_real_roots(p, -1, 0), 0);
  EXPECT_EQ(count_real_roots(p, 1, 1), 0);
  EXPECT_EQ(count_real_roots(X() * X() + P(1), -100, 100), 0);
}

TEST(Sturm, RepeatedRoots) {
  P p = lin(1).pow(3) * lin(-2).pow(2) * (X() * X() - P(2));
  EXPECT_EQ(count_real_roots(p, -10, 10), 4);  // distinct: -2, -sqrt2, 1, sqrt2
  auto v = isolate_real_roots(p);
  ASSERT_EQ(v.size(), 4u);
  expect_disjoint_sorted(v);
  EXPECT_TRUE(in(v[0], -2));
  EXPECT_TRUE(in(v[2], 1));
  // sqrt 2: refine to 1e-60 and check x^2 - 2 changes sign exactly across the interval
  RootInterval r = refine_root(p, v[3], parse_rational("1e-60"));
  EXPECT_LE(r.hi - r.lo, parse_rational("1e-60"));
  EXPECT_LT(r.lo * r.lo, 2);
  EXPECT_GT(r.hi * r.hi, 2);
  // compare with MPFR sqrt(2) at 100 digits
  mp100 s = sqrt(mp100(2));
  EXPECT_TRUE(exact_rational(s) > r.lo - parse_rational("1e-99") && exact_rational(s) < r.hi + parse_rational("1e-99"));
}

TEST(Sturm, ExtremelyCloseRoots) {
  const rational e = parse_rational("1e-30");
  P p = lin(1) * lin(1 + e);
  auto v = isolate_real_roots(p);
  ASSERT_EQ(v.size(), 2u);
  expect_disjoint_sorted(v);
  EXPECT_TRUE(in(v[0], 1) && !in(v[0], 1 + e));
  EXPECT_TRUE(in(v[1], 1 + e) && !in(v[1], 1));
  // and three roots within 1e-40 of each other, one of them rational at a dyadic point
  const rational d = parse_rational("1e-40");
  P p3 = lin(rational(1, 2)) * lin(rational(1, 2) + d) * lin(rational(1, 2) - d);
  auto v3 = isolate_real_roots(p3);
  ASSERT_EQ(v3.size(), 3u);
  expect_disjoint_sorted(v3);
  EXPECT_TRUE(in(v3[0], rational(1, 2) - d));
  EXPECT_TRUE(in(v3[1], rational(1, 2)));
  EXPECT_TRUE(in(v3[2], rational(1, 2) + d));
}

TEST(Sturm, RationalRootsAreFoundExactly) {
  // 0 and 1/2 are dyadic: bisection of the Cauchy interval (-B, B) reaches them exactly
  P p = X() * lin(rational(1, 2)) * lin(rational(-1, 3));
  auto v = isolate_real_roots(p);
  ASSERT_EQ(v.size(), 3u);
  expect_disjoint_sorted(v);
  EXPECT_TRUE(in(v[0], rational(-1, 3)));
  EXPECT_TRUE(in(v[1], 0));
  EXPECT_TRUE(in(v[2], rational(1, 2)));
  // refining the non-dyadic rational root -1/3 keeps it inside (secant steps may hit it exactly)
  RootInterval r = refine_root(p, v[0], parse_rational("1e-80"));
  EXPECT_TRUE(in(r, rational(-1, 3)));
  EXPECT_LE(r.hi - r.lo, parse_rational("1e-80"));
  // the secant step of refine_root hits a root of a linear factor exactly
  RootInterval lr = refine_root(lin(rational(2, 7)), {0, 1}, parse_rational("1e-30"));
  EXPECT_TRUE(lr.is_exact());
  EXPECT_EQ(lr.lo, rational(2, 7));
  EXPECT_THROW(refine_root(p, {rational(1), rational(2)}, rational(1, 10)), InputError);
  EXPECT_THROW(refine_root(p, {rational(1, 7), rational(1, 7)}, rational(1, 10)), InputError);
  EXPECT_THROW(refine_root(p, v[0], rational(0)), InputError);
}

TEST(Sturm, HugeAndTinyCoefficients) {
  // 1e300 x^2 - 1e-300: roots +-1e-300 (exactly rational)
  P p(std::vector<rational>{parse_rational("-1e-300"), rational(0), parse_rational("1e300")});
  auto v = isolate_real_roots(p);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(in(v[0], parse_rational("-1e-300")));
  EXPECT_TRUE(in(v[1], parse_rational("1e-300")));
  RootInterval r = refine_root(p, v[1], parse_rational("1e-320"));
  EXPECT_TRUE(in(r, parse_rational("1e-300")));
  EXPECT_LE(r.hi - r.lo, parse_rational("1e-320"));
  // x - 1e300
  auto w = isolate_real_roots(lin(parse_rational("1e300")));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(in(w[0], parse_rational("1e300")));
}

TEST(Sturm, WilkinsonAndChebyshev) {
  P w(1);
  for (int k = 1; k <= 20; ++k) w = w * lin(k);
  auto v = isolate_real_roots(w);
  ASSERT_EQ(v.size(), 20u);
  expect_disjoint_sorted(v);
  for (int k = 1; k <= 20; ++k) EXPECT_TRUE(in(v[k - 1], k)) << k;
  // T_10 (Chebyshev): roots cos((2k-1) pi / 20)
  P t0(1), t1 = X();
  for (int n = 2; n <= 10; ++n) {
    P t2 = X() * rational(2) * t1 - t0;
    t0 = t1;
    t1 = t2;
  }
  auto c = isolate_real_roots(t1);
  ASSERT_EQ(c.size(), 10u);
  expect_disjoint_sorted(c);
  const mp100 pi = boost::math::constants::pi<mp100>();
  for (int k = 1; k <= 10; ++k) {
    mp100 x = cos((2 * k - 1) * pi / 20);
    RootInterval r = refine_root(t1, c[10 - k], parse_rational("1e-70"));
    rational xr = exact_rational(x);  // within 1e-99 of the root
    EXPECT_TRUE(xr > r.lo - parse_rational("1e-98") && xr < r.hi + parse_rational("1e-98")) << k;
  }
}

TEST(Sturm, IsolateInInterval) {
  P p = lin(-1) * lin(0) * lin(1) * lin(rational(1, 3));
  auto v = isolate_real_roots(p, 0, 1);  // closed: 0, 1/3, 1
  ASSERT_EQ(v.size(), 3u);
  EXPECT_TRUE(in(v[0], 0));
  EXPECT_TRUE(in(v[1], rational(1, 3)));
  EXPECT_TRUE(in(v[2], 1));
  for (auto& r : v) EXPECT_TRUE(r.lo >= 0 && r.hi <= 1);
  EXPECT_EQ(isolate_real_roots(p, rational(1, 10), rational(3, 10)).size(), 0u);
  EXPECT_EQ(isolate_real_roots(p, rational(1, 3), rational(1, 3)).size(), 1u);
  // roots at both endpoints and irrational roots just inside them are all separated
  const rational eps(1, 1000000007);
  P r = lin(0) * lin(1) * (X() * X() - P(eps * eps * 2)) * (lin(1) * lin(1) - P(eps * eps * 2));
  auto w = isolate_real_roots(r, 0, 1);  // 0, eps*sqrt2, 1 - eps*sqrt2, 1
  ASSERT_EQ(w.size(), 4u);
  expect_disjoint_sorted(w);
  EXPECT_TRUE(w[0].is_exact() && w[0].lo == 0);
  EXPECT_TRUE(w[3].is_exact() && w[3].lo == 1);
  EXPECT_TRUE(w[1].lo > 0 && w[2].hi < 1);
  for (auto& x : w) EXPECT_TRUE(x.lo >= 0 && x.hi <= 1);
  EXPECT_EQ(isolate_real_roots(r, -1, 2).size(), 6u);  // and -eps*sqrt2, 1 + eps*sqrt2
  // the sequence is a Sturm sequence of the square-free part
  auto s = sturm_sequence(lin(2).pow(3));
  EXPECT_EQ(s.front(), lin(2));
}

}  // namespace test_sturm
