// Tests of hapstab/poly/polynomial.hpp and rational_function.hpp. Expected values are exact
// rationals computed by hand or by an independent route (expanded products, exact complex
// rational arithmetic); floating evaluations are compared with 100-digit references and the
// tolerances are stated in units of the evaluation type's epsilon.
#include <gtest/gtest.h>

#include <complex>
#include <cstdint>
#include <random>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/poly/polynomial.hpp"
#include "hapstab/poly/rational_function.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_polynomial {

using namespace hapstab;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

namespace {
P X() { return P::monomial(1); }
P lin(rational a) { return X() - P(a); }  // x - a
rational q(const char* s) { return parse_rational(s); }
}  // namespace

TEST(Polynomial, ZeroAndConstants) {
  P z;
  EXPECT_EQ(z.degree(), -1);
  EXPECT_TRUE(z.is_zero());
  EXPECT_THROW(z.leading(), InputError);
  EXPECT_EQ(z.coeff(3), 0);
  EXPECT_EQ(P(rational(0)).degree(), -1);  // a zero constant is the zero polynomial
  P c(rational(7, 3));
  EXPECT_EQ(c.degree(), 0);
  EXPECT_EQ(c(rational(123)), rational(7, 3));
  EXPECT_EQ(P(std::vector<rational>{1, 2, 0, 0}).degree(), 1);  // trailing zeros trimmed
  EXPECT_EQ(z(rational(5)), 0);
  EXPECT_EQ(z.derivative(), z);
  EXPECT_EQ(c.derivative(), z);
  EXPECT_THROW(P::monomial(-1), InputError);
}

TEST(Polynomial, Arithmetic) {
  P p = (X() + P(1)).pow(3);
  EXPECT_EQ(p, P(std::vector<rational>{1, 3, 3, 1}));
  EXPECT_EQ(p.derivative(), P(std::vector<rational>{3, 6, 3}));
  EXPECT_EQ(p - p, P());
  EXPECT_EQ(-p + p, P());
  EXPECT_EQ(P(2) * p, p + p);
  EXPECT_EQ(p * rational(2), p + p);
  // compose: p(x^2 - 1) = x^6 exactly
  EXPECT_EQ(p.compose(X() * X() - P(1)), P::monomial(6));
  EXPECT_EQ(p.monic(), p);
  EXPECT_EQ((p * rational(-4)).monic(), p);
  EXPECT_EQ(P::monomial(3, rational(5)).coeff(3), 5);
  EXPECT_EQ(to_string(P(std::vector<rational>{1, rational(-1, 2), 3})), "3*x^2 - 1/2*x + 1");
  EXPECT_EQ(to_string(-X(), "t"), "-t");
  EXPECT_EQ(to_string(P()), "0");
}

TEST(Polynomial, DivmodAndGcd) {
  P a = lin(1).pow(2) * lin(-2) * (X() * X() + P(1));
  P b = lin(1) * lin(-3) * P(rational(5, 7));
  auto [qq, r] = divmod(a, b);
  EXPECT_LT(r.degree(), b.degree());
  EXPECT_EQ(qq * b + r, a);  // exact identity
  EXPECT_EQ(gcd(a, b), lin(1));
  EXPECT_EQ(gcd(b, a), lin(1));
  EXPECT_EQ(gcd(a, a * rational(3)), a.monic());
  EXPECT_EQ(gcd(a, P()), a.monic());
  EXPECT_EQ(gcd(P(), P()), P());
  EXPECT_EQ(gcd(a, P(rational(3))), P(1));  // coprime to a constant
  EXPECT_THROW(divmod(a, P()), InputError);
  // huge / tiny coefficients stay exact
  P h = P(std::vector<rational>{q("1e-300"), rational(0), q("1e300")});
  P hd = h.derivative();
  EXPECT_EQ(gcd(h * lin(q("1e-200")), hd * lin(q("1e-200"))), lin(q("1e-200")));
  // coefficient growth does not break exactness: gcd of two degree-12 products
  P f = P(1), g = P(1);
  for (int k = 1; k <= 6; ++k) {
    f = f * lin(rational(k, k + 1));
    g = g * lin(rational(k + 3, k + 4));
  }
  // common roots: k/(k+1) = j/(j+1) with k = j+3 ... none equal except by value: 4/5,5/6,6/7
  P expect = lin(rational(4, 5)) * lin(rational(5, 6)) * lin(rational(6, 7));
  EXPECT_EQ(gcd(f, g), expect);
}

TEST(Polynomial, FlintKernelsAgreeWithSchoolbookAndEuclid) {
  // The FLINT kernels (products of >= 64 coefficient pairs, powers, division, gcd) against
  // independent exact routes: the convolution sum, exact evaluation at rational points,
  // a = q b + r with deg r < deg b, and the generic Euclid gcd. Random rational coefficients
  // with numerators and denominators up to 2^40, some zero, degrees 0..40 (0..12 against Euclid).
  std::mt19937_64 rng(20261124);
  auto random_poly = [&](int deg) {
    std::vector<rational> c(size_t(deg) + 1);
    for (auto& x : c)
      x = rng() % 5 == 0 ? rational(0) : rational(integer(std::int64_t(rng() % (1ULL << 40)) - (1LL << 39)), integer(rng() % (1ULL << 40) + 1));
    if (c.back() == 0) c.back() = 1;
    return P(std::move(c));
  };
  for (int trial = 0; trial < 40; ++trial) {
    const P a = random_poly(int(rng() % 41)), b = random_poly(int(rng() % 41)), g = random_poly(int(rng() % 6) + 1);
    std::vector<rational> conv(a.coeffs().size() + b.coeffs().size() - 1, rational(0));
    for (size_t i = 0; i < a.coeffs().size(); ++i)
      for (size_t j = 0; j < b.coeffs().size(); ++j) conv[i + j] += a.coeffs()[i] * b.coeffs()[j];
    EXPECT_EQ(a * b, P(conv)) << trial;
    const rational x0(integer(std::int64_t(rng() % 1000) - 500), 7);
    const rational v = a(x0);
    EXPECT_EQ(a.pow(5)(x0), v * v * v * v * v) << trial;
    const auto [q, r] = divmod(a, b);
    EXPECT_EQ(q * b + r, a) << trial;
    EXPECT_LT(r.degree(), b.degree()) << trial;
    EXPECT_EQ(gcd(a * g, b * g), gcd(a, b) * g.monic()) << trial;
    // Euclid's coefficients explode (why FLINT is used): the reference only at low degree
    const P as = random_poly(int(rng() % 8)), bs = random_poly(int(rng() % 8));
    EXPECT_EQ(gcd(as * g, bs * g), detail::euclid_gcd(as * g, bs * g)) << trial;
  }
  EXPECT_EQ(gcd(P(), P()), P());
  EXPECT_EQ(gcd(lin(3), P()), lin(3));
}

TEST(Polynomial, GcdSpecialCases) {
  const integer p1(2147483647), p2(2147483629);
  P a = P(std::vector<rational>{rational(1), rational(0), rational(p1)});  // p1 x^2 + 1
  P b = lin(3) * P(rational(p1));
  EXPECT_EQ(gcd(a, b), P(1));
  P c = lin(rational(1, p1 * p2)) * lin(2), d = lin(rational(1, p1 * p2)) * lin(5);
  EXPECT_EQ(gcd(c, d), lin(rational(1, p1 * p2)));
  EXPECT_EQ(gcd(lin(rational(p1)), X()), P(1));
  EXPECT_EQ(gcd(lin(rational(p1)) * lin(7), X() * lin(7)), lin(7));
  // random products with and without a shared quadratic factor
  P s = X() * X() - P(2);
  for (int k = 1; k <= 20; ++k) {
    P f = lin(rational(k, 3)) * P(std::vector<rational>{rational(k), rational(-1), rational(1, k)});
    P g = lin(rational(-k, 7)) * lin(rational(2 * k + 1, 5));
    EXPECT_EQ(gcd(f, g), P(1)) << k;
    EXPECT_EQ(gcd(f * s, g * s), s) << k;
    EXPECT_EQ(gcd(f * s * rational(k, 11), g * s.pow(2)), s) << k;
  }
}

TEST(Polynomial, EvaluateInManyScalars) {
  // p(x) = 1/3 x^3 - 7/5 x + 1e-20 (coefficients not representable in binary)
  P p(std::vector<rational>{q("1e-20"), rational(-7, 5), rational(0), rational(1, 3)});
  const rational x0(5, 7);
  const rational exact = p(x0);
  // rational: exact by hand
  EXPECT_EQ(exact, q("1e-20") - rational(7, 5) * x0 + rational(1, 3) * x0 * x0 * x0);
  // mp100: within a few ulps (Horner, 3 steps, coefficient and argument rounding)
  mp100 v100 = p(mp100(x0));
  mp100 e100 = mp100(exact);
  EXPECT_LE(abs(v100 - e100) / abs(e100), 20 * std::numeric_limits<mp100>::epsilon());
  // double: Horner error <= ~ (2n+2) eps * sum|a_i x^i| / |p(x)|; here cond ~ 2, so 20 eps
  double vd = p(static_cast<double>(x0));
  EXPECT_NEAR(vd, static_cast<double>(e100), 20 * 2.3e-16 * std::abs(static_cast<double>(e100)));
  // interval: must contain the exact value, and be narrow
  ival100 vi = p(scalar_cast<ival100>(x0));
  mp100 lo = lower(vi), hi = upper(vi);
  EXPECT_TRUE(exact_rational(lo) <= exact && exact <= exact_rational(hi));
  EXPECT_LT(hi - lo, 1e-95);
  // complex<double> at z = 0.3 + 0.4 j against exact Gaussian-rational Horner
  rational zr(3, 10), zi(2, 5), ar = 0, ai = 0;
  for (int k = p.degree(); k >= 0; --k) {
    rational nr = ar * zr - ai * zi + p.coeff(k);
    ai = ar * zi + ai * zr;
    ar = nr;
  }
  std::complex<double> vc = p(std::complex<double>(0.3, 0.4));
  // 0.3, 0.4 are rounded on input (1/2 ulp each): the error is dominated by cond * eps, cond <= 10
  EXPECT_NEAR(vc.real(), static_cast<double>(mp100(ar)), 50 * 2.3e-16);
  EXPECT_NEAR(vc.imag(), static_cast<double>(mp100(ai)), 50 * 2.3e-16);
  // complex<mp100>
  std::complex<mp100> vcm = p(std::complex<mp100>(mp100(zr), mp100(zi)));
  EXPECT_LT(abs(vcm.real() - mp100(ar)), 1e-98);
  EXPECT_LT(abs(vcm.imag() - mp100(ai)), 1e-98);
  // cast to double coefficients
  Polynomial<double> pd = p.cast<double>();
  EXPECT_EQ(pd.degree(), 3);
  EXPECT_EQ(pd.coeff(1), -1.4);
  Polynomial<mp50> pm = p.cast<mp50>();
  EXPECT_EQ(pm.coeff(3), mp50(1) / 3);
}

TEST(Polynomial, FloatingFieldGcd) {
  // gcd over double with exactly representable data: (x-1)(x-2) and (x-1)(x+4)
  Polynomial<double> a(std::vector<double>{2, -3, 1}), b(std::vector<double>{-4, 3, 1});
  Polynomial<double> g = gcd(a, b);
  ASSERT_EQ(g.degree(), 1);
  EXPECT_EQ(g.coeff(0), -1.0);
  EXPECT_EQ(g.coeff(1), 1.0);
}

TEST(RationalFunction, CanonicalForm) {
  RF f(X() * X() - P(1), P(rational(2)) * lin(1));  // (x^2-1)/(2(x-1)) = (x+1)/2
  EXPECT_EQ(f.den(), P(1));
  EXPECT_EQ(f.num(), (X() + P(1)) * rational(1, 2));
  EXPECT_THROW(RF(X(), P()), InputError);
  RF zero(P(), lin(3));
  EXPECT_TRUE(zero.is_zero());
  EXPECT_EQ(zero.den(), P(1));
  EXPECT_THROW(zero.pow(-1), InputError);
  EXPECT_THROW(f / zero, InputError);
  // den is monic
  RF g(P(1), P(std::vector<rational>{1, 3}));
  EXPECT_EQ(g.den().leading(), 1);
  EXPECT_EQ(g(rational(1)), rational(1, 4));
}

TEST(RationalFunction, Algebra) {
  RF a(P(1), lin(1)), b(P(1), lin(-1));
  // 1/(x-1) - 1/(x+1) = 2/(x^2-1)
  EXPECT_EQ(a - b, RF(P(2), X() * X() - P(1)));
  EXPECT_EQ((a - b).num(), P(2));
  EXPECT_EQ(a * b, RF(P(1), X() * X() - P(1)));
  EXPECT_EQ(a / b, RF(lin(-1), lin(1)));
  EXPECT_EQ(a.pow(-2), RF(lin(1).pow(2)));
  EXPECT_EQ(a.pow(0), RF(P(1)));
  // d/dx 1/x = -1/x^2
  EXPECT_EQ(RF(P(1), X()).derivative(), RF(P(-1), X() * X()));
  // quotient rule against product form: d/dx (x^2+1)/(x-2)
  RF h(X() * X() + P(1), lin(2));
  EXPECT_EQ(h.derivative(), RF(X() * X() - X() * rational(4) - P(1), lin(2).pow(2)));
  RF s = a + b;  // 2x/(x^2-1)
  EXPECT_EQ(s(rational(3)), rational(6, 8));
  EXPECT_NEAR(s(3.0), 0.75, 1e-16);
  EXPECT_EQ(-s + s, RF(P()));
  RF c = 5;  // constants convert
  EXPECT_EQ(c(rational(9)), 5);
}

// A sum, product or quotient with a constant skips the gcd (rational_function.hpp): the result
// must be the canonical form the general path gives. The reference builds num/den over a common
// denominator and lets the constructor reduce them (the gcd path), on random functions with
// common factors, zero results and negative constants.
TEST(RationalFunction, ConstantShortcutsGiveTheCanonicalForm) {
  std::mt19937 g(17);
  std::uniform_int_distribution<int> d(-4, 4);
  const auto poly = [&](int deg) {
    std::vector<rational> c;
    for (int i = 0; i <= deg; ++i) c.emplace_back(d(g), 1 + std::abs(d(g)));
    return P(std::move(c));
  };
  for (int n = 0; n < 300; ++n) {
    P num = poly(n % 4), den = poly(1 + n % 3);
    if (den.is_zero()) continue;
    const RF f(num, den);
    const rational c(d(g), 1 + std::abs(d(g)));
    const RF k{P(c)};
    const auto same = [](const RF& a, const RF& b) { return a.num() == b.num() && a.den() == b.den(); };
    EXPECT_TRUE(same(f + k, RF(f.num() + f.den() * P(c), f.den())));
    EXPECT_TRUE(same(k + f, RF(f.num() + f.den() * P(c), f.den())));
    EXPECT_TRUE(same(f * k, RF(f.num() * P(c), f.den())));
    EXPECT_TRUE(same(k * f, RF(f.num() * P(c), f.den())));
    if (c != 0) { EXPECT_TRUE(same(f / k, RF(f.num(), f.den() * P(c)))); }
    EXPECT_TRUE(same(f - f + k, k));  // zero plus a constant, and a zero result on the way
    EXPECT_TRUE((f + RF(P(-c)) + k) == f);
  }
}

}  // namespace test_polynomial
