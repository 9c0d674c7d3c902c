// Exact tf <-> ss conversions and minimal realisations (lti/realization.hpp).
#include <gtest/gtest.h>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/exact_matrix.hpp"

using namespace hapstab;

namespace {
TransferFunction z_tf(const std::string& s) {
  ParseOptions o;
  o.T = rational(1, 100);
  return parse_tf(s, o);
}
bool same(const TransferFunction& a, const TransferFunction& b) {
  return a.num() == b.num() && a.den() == b.den() && a.T == b.T && a.domain == b.domain;
}
}  // namespace

TEST(Realization, SisoRoundTripIsExact) {
  for (const char* e : {"(6000*z - 5000)/z", "z^2/(z^2 - 1/2*z + 1/16)", "3", "(z-1)/(z+0.9999)",
                        "(2*z^3 + 1)/(z^3 - z/3 + 1/7)", "1/(z-1)"}) {
    auto G = z_tf(e);
    auto sys = tf2ss(G);
    EXPECT_EQ(sys.states(), G.den().degree()) << e;
    auto back = ss2tf(sys);
    EXPECT_TRUE(same(back(0, 0), G)) << e << " -> " << back(0, 0).to_string();
  }
}

TEST(Realization, ImproperIsRefused) { EXPECT_THROW(tf2ss(z_tf("z^2/(z-1)")), InputError); }

TEST(Realization, CharpolyMatchesKnownMatrix) {
  Mat<rational> A(2, 2);
  A << 1, 2, 3, 4;  // x^2 - 5x - 2
  EXPECT_EQ(charpoly(A), Polynomial<rational>(std::vector<rational>{-2, -5, 1}));
}

TEST(Realization, MimoRoundTripAndMinreal) {
  TransferMatrix G;
  G.domain = Domain::z;
  G.T = rational(1, 100);
  G.entries = {{z_tf("1/(z-1/2)"), z_tf("0")}, {z_tf("1/(z-1/2)"), z_tf("z/(z+1/3)")}};
  auto sys = tf2ss(G);
  auto back = ss2tf(sys);
  for (size_t i = 0; i < 2; ++i)
    for (size_t j = 0; j < 2; ++j) EXPECT_TRUE(same(back(i, j), G(i, j))) << i << "," << j;
  auto m = minreal(sys);
  EXPECT_EQ(m.states(), 2);
  auto back2 = ss2tf(m);
  for (size_t i = 0; i < 2; ++i)
    for (size_t j = 0; j < 2; ++j) EXPECT_TRUE(same(back2(i, j), G(i, j))) << i << "," << j;
}

TEST(Realization, MinrealRemovesUnobservableState) {
  // x1 driven, x2 driven but never observed: 1 state remains, same transfer function.
  Mat<rational> A(2, 2), B(2, 1), C(1, 2), D(1, 1);
  A << rational(1, 2), 0, 0, rational(1, 3);
  B << 1, 1;
  C << 1, 0;
  D << 0;
  StateSpace<rational> s{A, B, C, D, rational(1, 10)};
  auto m = minreal(s);
  EXPECT_EQ(m.states(), 1);
  EXPECT_TRUE(same(ss2tf(m)(0, 0), ss2tf(s)(0, 0)));
}

// charpoly at large order with few distinct eigenvalues goes through the minimal polynomial and
// exact nullities (lti/realization.cpp): against the known product, exactly. A = V J V^-1 with J
// block diagonal: the rotation-scaling block of q(x) = x^2 - x + 1/2 repeated, a rational
// eigenvalue 1/3 in a Jordan block of size 2 (minpoly has (x - 1/3)^2) and plain 1/3's, and
// V unimodular (integer, det 1) so A is dense.
TEST(Realization, CharpolyOfLargeOrderWithRepeatedFactors) {
  for (const int copies : {30, 40}) {
    const int n = 2 * copies + 2 + 3;
    MatQ J = MatQ::Zero(n, n);
    for (int k = 0; k < copies; ++k) {
      J(2 * k, 2 * k) = rational(1, 2), J(2 * k, 2 * k + 1) = rational(-1, 2);
      J(2 * k + 1, 2 * k) = rational(1, 2), J(2 * k + 1, 2 * k + 1) = rational(1, 2);
    }
    const int b = 2 * copies;
    for (int i = b; i < n; ++i) J(i, i) = rational(1, 3);
    J(b, b + 1) = 1;  // the Jordan block
    MatQ V = MatQ::Identity(n, n), W = MatQ::Identity(n, n);  // V = U, W = U^-1 for U = I + N, N nilpotent
    for (int i = 0; i + 1 < n; ++i) V(i, i + 1) = (i % 3) - 1;
    // (I + N)^-1 = sum (-N)^k
    MatQ Nm = V - MatQ::Identity(n, n), P = MatQ::Identity(n, n);
    for (int k = 1; k < n; ++k) {
      P = exact_product(P, MatQ(-Nm));
      W += P;
    }
    ASSERT_EQ(exact_product(V, W), MatQ(MatQ::Identity(n, n)));
    const MatQ A = exact_product(exact_product(V, J), W);
    const Polynomial<rational> q(std::vector<rational>{rational(1, 2), rational(-1), rational(1)});
    const Polynomial<rational> l(std::vector<rational>{rational(-1, 3), rational(1)});
    EXPECT_EQ(charpoly(A), q.pow(static_cast<unsigned>(copies)) * l.pow(5)) << "copies " << copies;
  }
}

// The branch where the minimal polynomial has degree n (distinct eigenvalues): never trusted as it
// is (FLINT 2.9's multimodular minpoly can stop at a wrong coefficient bound); against FLINT's
// fraction-free charpoly and against det(xI - A) at rational points (Bareiss on the matrix),
// on dense matrices with large entries and distinct eigenvalues, orders 49..60.
TEST(Realization, CharpolyOfLargeOrderWithDistinctEigenvalues) {
  for (const int n : {49, 53, 60}) {
    MatQ A(n, n);
    unsigned long x = 12345u + static_cast<unsigned long>(n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        x = x * 6364136223846793005ul + 1442695040888963407ul;
        const long num = static_cast<long>((x >> 20) % 2000001) - 1000000;  // |entry| up to 10^6
        A(i, j) = rational(num, 1 + static_cast<long>((x >> 50) % 7));
      }
    const Polynomial<rational> p = charpoly(A);
    ASSERT_EQ(p.degree(), n);
    EXPECT_EQ(p.coeff(n), 1);
    // det(x I - A) at x = 0, 1, -2 by exact elimination (exact_matrix.hpp), independent of FLINT's charpoly
    for (const rational& xv : {rational(0), rational(1), rational(-2)}) {
      MatQ M = MatQ(MatQ::Identity(n, n)) * xv - A;
      EXPECT_EQ(p(xv), exact_determinant(M)) << "n = " << n << ", x = " << xv;
    }
  }
}
