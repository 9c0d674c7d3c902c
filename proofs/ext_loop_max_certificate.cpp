// proofs/ext_loop_max_certificate.cpp -- the arguments the certificate checkers of stops 72-73 rest on
// (check/stability_loop_max_check.hpp, check/operator_passivity_check.hpp; docs/certificates.md), each
// checked on random instances against a computation that does not share its shortcut:
//
//   first-order start. M(p) = M0 + p K1 with L M0 = L (the slow rows), P(p) = P0 + L^T S L / p. Then
//     P(p) - M(p)^T P(p) M(p) = P0 - M(p)^T P0 M(p) - (K^T S L + L^T S K) - p K^T S K,  K = L K1,
//   an identity of matrix polynomials of degree <= 3 once multiplied by p: exact at four values of p
//   proves it for every p != 0. Its right side is concave in p when P0, S >= 0 (-p^2 K1^T P0 K1 and
//   -p K^T S K), so the checker's test at p = 0 and p = eps covers (0, eps]. Checked: wherever the
//   checker (detail::first_order_start) accepts, M(p) at eps/1000, eps/3 and eps is Schur stable by an
//   exact Schur-Cohn test on det(zI - M(p)); with S = 0 it never accepts (M(0) has the eigenvalue 1,
//   v^T Q(0) v = 0 for its right eigenvector).
//   P linear over an interval. With P(t) = (1 - t) Pa + t Pb and M(t) = (1 - t) Ma + t Mb, S(t) = P(t) - M(t)^T P(t)
//   M(t) is a cubic, sum_s C_s B_s(t) in the Bernstein basis with C_s = ((3 - s) Pa + s Pb)/3 - (3 choose s)^-1 sum
//   over i + j + k = s of X_i^T P_j X_k: an identity of cubics, exact at five t; and wherever the checker
//   (detail::bernstein_stein_holds) accepts, S(t) > 0 exactly and M(t) Schur stable (Schur-Cohn) at t = 1/7, 1/2, 5/6.
//   kernel of the slow rows. L M = L (L in reduced echelon form) makes ker L invariant and M the identity
//   on the quotient, so det(zI - M) = (z - 1)^k det(zI - M|ker L): the restriction the sup = 0 test
//   decides (detail::restricted), checked as an exact identity of characteristic polynomials.
//   holds on a slow row. l^T A = 0 gives l^T e^{Ah} = l^T and l^T Gamma_h = h l^T B (the power series),
//   which is why the exact slow matrix (every hold e^{Ah} -> I, Gamma_h -> h B) has the slow rows of the
//   loop's own: checked against the ball enclosure of the zero-order hold (numeric/ball_expm.hpp), with a
//   row l^T A != 0 beside it that the enclosure separates from l^T.
//   residue at an irrational axis pole. Z = (s F + G)/(s^2 + q) + Z1(s), q > 0 not a square: the residue
//   at s = j w0, w0 = sqrt(q), is F/2 - j w0 G/(2q) = X + j w0 Y with X, Y rational; the checker's route
//   (n(j w0)/d'(j w0), even powers of j w0 rational, odd ones j w0 times a rational) and the factored one
//   (n(j w0)/((2 j w0) d1(j w0)), evaluated in Q(sqrt q)(j)) give it exactly; and with D = diag(I, w0 I),
//   D [[X, -Y], [Y, X/q]] D = [[X, -w0 Y], [w0 Y, X]] (the real form of X + j w0 Y) exactly in Q(sqrt q):
//   a congruence, so one is PSD iff the other is (Sylvester), and w0 is never written.
//   first-order mirror. The start's P(p) with S of any sign: Q(p) > 0 on [0, eps] (as above) and w^T P(p) w < 0
//   there (s = (L w)^T S (L w) < 0, w^T P0 w + s/eps < 0) make M(p) NOT Schur stable on (0, eps] (Stein inertia).
//   Checked: wherever the checker (detail::first_order_unstable) accepts, exact Schur-Cohn finds M(p) unstable at
//   eps/1000, eps/3 and eps; with S negated or w = 0 it never accepts.
//   no crossing of the circle (lti/circle_crossing.hpp, evidence no_crossing). c(z, p) = det(zI - M(p)) monic, R(p) =
//   Res_z(c, z^n c(1/z)) = prod over c's roots of mu^n c(1/mu): no root of R in (0, a] keeps every eigenvalue off the
//   circle there, so M(p) has one inertia on (0, a]. Checked: R's interpolation (degree <= 2 n rank M1) equals the
//   determinant of the Sylvester matrix of c and z^n c(1/z) (exact_determinant, no FLINT resultant) at p = 1/3, 5/7, 11;
//   and wherever no_circle_crossing(M0, M1, a) holds on random families with a pure mass's Jordan block at z = 1, exact
//   Schur-Cohn gives M(p) the verdict of M(a) at a/1000, a/3 and 2a/3 (stable and NOT stable both met).
#include <random>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "hapstab/check/stability_loop_max_check.hpp"
#include "hapstab/lti/circle_crossing.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/poly/sturm.hpp"
#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/poly/stability.hpp"
#include "proofs/proof.hpp"

namespace ext_loop_max_certificate_detail {

using namespace hapstab;
using Q = rational;
namespace rm = check::rational_matrix;
using RMat = rm::Mat;

Q draw(std::mt19937& g, int lo, int hi, long den) { return Q(std::uniform_int_distribution<int>(lo, hi)(g), den); }

MatQ to_matq(const RMat& A) {
  MatQ M(static_cast<long>(A.size()), static_cast<long>(A[0].size()));
  for (size_t i = 0; i < A.size(); ++i)
    for (size_t j = 0; j < A[0].size(); ++j) M(static_cast<long>(i), static_cast<long>(j)) = A[i][j];
  return M;
}

check::detail::BallRows balls(const RMat& A) {
  check::detail::BallRows B(A.size());
  for (size_t i = 0; i < A.size(); ++i)
    for (const Q& x : A[i]) B[i].emplace_back(x);
  return B;
}

nlohmann::json json_matrix(const RMat& A) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : A) {
    nlohmann::json row = nlohmann::json::array();
    for (const Q& x : r) row.push_back(x.str());
    rows.push_back(row);
  }
  return rows;
}

// ---- the first-order start ------------------------------------------------------------------------
struct SlowLoop {
  RMat M0, K1, L, P0, S;
};

// M0 = [[I_k, 0], [C, A0]] (L = [I_k 0]: L M0 = L), K1 small but for -c I on the slow block; P0 near
// diag(alpha I_k, I_f), S = s I_k: the checker accepts a good share of them at small eps.
SlowLoop draw_slow_loop(std::mt19937& g) {
  const size_t k = 1 + g() % 2, f = 1 + g() % 3, n = k + f;
  SlowLoop d{rm::zeros(n, n), rm::zeros(n, n), rm::zeros(k, n), rm::zeros(n, n), rm::zeros(k, k)};
  const Q c = g() % 2 ? Q(1, 2) : Q(1), alpha = g() % 2 ? Q(1) : Q(2), s = std::vector<Q>{Q(1, 2), Q(1), Q(2)}[g() % 3];
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      if (i < k) d.M0[i][j] = i == j ? Q(1) : Q(0);
      else d.M0[i][j] = j < k ? draw(g, -3, 3, 10) : draw(g, -2, 2, 10);
      d.K1[i][j] = draw(g, -2, 2, 10) - (i == j && i < k ? c : Q(0));
    }
  for (size_t i = 0; i < k; ++i) d.L[i][i] = 1, d.S[i][i] = s;
  for (size_t i = 0; i < n; ++i) {
    d.P0[i][i] = i < k ? alpha : Q(1);
    for (size_t j = 0; j < i; ++j) d.P0[i][j] = d.P0[j][i] = draw(g, -1, 1, 20);
  }
  return d;
}

RMat loop_at(const SlowLoop& d, const Q& p) { return rm::add(d.M0, d.K1, p); }

// P(p) - M^T P(p) M == P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K, exactly at p.
bool stein_identity_at(const SlowLoop& d, const Q& p) {
  const RMat M = loop_at(d, p), Mt = rm::transpose(M), Lt = rm::transpose(d.L);
  const RMat LSL = rm::mul(rm::mul(Lt, d.S), d.L), P = rm::add(d.P0, LSL, Q(1) / p);
  const RMat lhs = rm::add(P, rm::mul(rm::mul(Mt, P), M), Q(-1));
  const RMat K = rm::mul(d.L, d.K1), SK = rm::mul(d.S, K), Kt = rm::transpose(K);
  RMat rhs = rm::add(d.P0, rm::mul(rm::mul(Mt, d.P0), M), Q(-1));
  rhs = rm::add(rhs, rm::add(rm::mul(Kt, rm::mul(d.S, d.L)), rm::mul(Lt, SK)), Q(-1));
  rhs = rm::add(rhs, rm::mul(Kt, SK), -p);
  return lhs == rhs;
}

std::string checker_on(const SlowLoop& d, const RMat& S, const Q& eps) {
  check::detail::LoopMatrix m1, m2;
  m1.M = balls(loop_at(d, Q(1)));
  m2.M = balls(loop_at(d, Q(2)));
  const nlohmann::json fo = {{"to", eps.str()}, {"P0", json_matrix(d.P0)}, {"S", json_matrix(S)}};
  Q from;
  return check::detail::first_order_start(fo, m1, m2, d.L, eps, from);
}

// ---- P linear over an interval ------------------------------------------------------------------------
RMat lerp(const RMat& A, const RMat& B, const Q& t) { return rm::add(rm::add(A, A, -t), B, t); }  // (1 - t) A + t B
RMat stein(const RMat& P, const RMat& M) { return rm::add(P, rm::mul(rm::mul(rm::transpose(M), P), M), Q(-1)); }

// S(t) == sum_s C_s B_s(t), the C_s from the expansion, exactly at t.
bool bernstein_identity_at(const RMat& Pa, const RMat& Pb, const RMat& Ma, const RMat& Mb, const Q& t) {
  const RMat X[2] = {Ma, Mb}, P[2] = {Pa, Pb};
  const long binomial[4] = {1, 3, 3, 1};
  RMat sum = rm::zeros(Pa.size(), Pa.size());
  for (int s = 0; s <= 3; ++s) {
    RMat C = rm::add(rm::add(Pa, Pa, Q(-s, 3)), Pb, Q(s, 3));  // ((3 - s) Pa + s Pb)/3
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          if (i + j + k == s) C = rm::add(C, rm::mul(rm::mul(rm::transpose(X[i]), P[j]), X[k]), Q(-1, binomial[s]));
    Q b = binomial[s];
    for (int e = 0; e < 3 - s; ++e) b *= 1 - t;
    for (int e = 0; e < s; ++e) b *= t;
    sum = rm::add(sum, C, b);
  }
  return sum == stein(lerp(Pa, Pb, t), lerp(Ma, Mb, t));
}

// ---- the kernel of the slow rows --------------------------------------------------------------------
// L = [I_k L2] (reduced echelon), M's last rows drawn and its first k rows L - L2 M[k:, :], so L M = L;
// dyadic entries, so the balls of detail::restricted stay exact.
bool kernel_identity(std::mt19937& g, bool& exact) {
  const size_t k = 1 + g() % 2, n = k + 1 + g() % 4;
  RMat L = rm::zeros(k, n), M = rm::zeros(n, n);
  for (size_t i = 0; i < k; ++i) {
    L[i][i] = 1;
    for (size_t j = k; j < n; ++j) L[i][j] = draw(g, -4, 4, 4);
  }
  for (size_t i = k; i < n; ++i)
    for (size_t j = 0; j < n; ++j) M[i][j] = draw(g, -8, 8, 8);
  for (size_t i = 0; i < k; ++i)
    for (size_t j = 0; j < n; ++j) {
      M[i][j] = L[i][j];
      for (size_t t = k; t < n; ++t) M[i][j] -= L[i][t] * M[t][j];
    }
  if (rm::mul(L, M) != L) return false;
  const check::detail::BallRows R = check::detail::restricted(balls(M), L);
  RMat Mr(R.size(), std::vector<Q>(R.size()));
  exact = true;
  for (size_t i = 0; i < R.size(); ++i)
    for (size_t j = 0; j < R.size(); ++j) {
      const Enclosure<Q> e = R[i][j].bounds();
      exact = exact && e.lo == e.hi;
      Mr[i][j] = e.lo;
    }
  if (!exact || Mr.size() != n - k) return false;
  QPoly slow(1);
  for (size_t i = 0; i < k; ++i) slow = slow * QPoly(std::vector<Q>{Q(-1), Q(1)});
  return charpoly(to_matq(M)) == slow * charpoly(to_matq(Mr));
}

// ---- holds on a slow row ----------------------------------------------------------------------------
// |sum_i l_i X(i, j) - target_j| <= sum_i |l_i| radius for every j, in balls: the exact row l^T X may be target.
bool row_within(const Q* l, const DoubleEnclosure& X, const std::vector<Q>& target) {
  for (long j = 0; j < X.mid.cols(); ++j) {
    flint::Ball v(0L), bound(0L);
    for (long i = 0; i < X.mid.rows(); ++i) {
      v += flint::Ball(l[i]) * flint::Ball(X.mid(i, j));
      bound += flint::Ball(abs(l[i])) * flint::Ball(X.radius);
    }
    v -= flint::Ball(target[static_cast<size_t>(j)]);
    if ((v - bound).positive() || (v + bound).negative()) return false;  // |v| > bound for certain
  }
  return true;
}

// ---- the residue at s = j w0, w0 = sqrt(q) ------------------------------------------------------------
struct Surd {  // a + b sqrt(q)
  Q a, b;
};
Surd operator+(const Surd& x, const Surd& y) { return {x.a + y.a, x.b + y.b}; }
Surd operator-(const Surd& x, const Surd& y) { return {x.a - y.a, x.b - y.b}; }
Surd times(const Surd& x, const Surd& y, const Q& q) { return {x.a * y.a + q * x.b * y.b, x.a * y.b + x.b * y.a}; }
bool operator==(const Surd& x, const Surd& y) { return x.a == y.a && x.b == y.b; }
struct Cx {  // re + j im over Q(sqrt q)
  Surd re, im;
};
Cx mul(const Cx& x, const Cx& y, const Q& q) {
  return {times(x.re, y.re, q) - times(x.im, y.im, q), times(x.re, y.im, q) + times(x.im, y.re, q)};
}
Cx divide(const Cx& x, const Cx& y, const Q& q) {
  const Surd n2 = times(y.re, y.re, q) + times(y.im, y.im, q);  // |y|^2 in Q(sqrt q)
  const Q norm = n2.a * n2.a - q * n2.b * n2.b;                    // n2 times its conjugate: rational, != 0
  const Surd inv{n2.a / norm, -n2.b / norm};
  const Cx num = mul(x, {y.re, {-y.im.a, -y.im.b}}, q);
  return {times(num.re, inv, q), times(num.im, inv, q)};
}
Cx evaluate_at_jw0(const QPoly& p, const Q& q) {  // Horner at s = j sqrt(q)
  const Cx s{{0, 0}, {0, 1}};
  Cx v{{0, 0}, {0, 0}};
  for (int i = p.degree(); i >= 0; --i) v = mul(v, s, q), v.re.a += p.coeff(i);
  return v;
}
// The checker's route: n(j w0) = A_n + j w0 B_n with A_n, B_n rational (even / odd powers), likewise d'.
std::pair<Q, Q> residue_by_derivative(const QPoly& n, const QPoly& d, const Q& q) {
  auto split = [&](const QPoly& p) {
    Q even = 0, odd = 0, power = 1;  // (-q)^floor(i/2)
    for (int i = 0; i <= p.degree(); ++i) {
      (i % 2 ? odd : even) += p.coeff(i) * power;
      if (i % 2) power *= -q;
    }
    return std::pair<Q, Q>{even, odd};
  };
  const auto [An, Bn] = split(n);
  const auto [Ad, Bd] = split(d.derivative());
  const Q den = Ad * Ad + q * Bd * Bd;
  return {(An * Ad + q * Bn * Bd) / den, (Bn * Ad - An * Bd) / den};
}

void first_order_claim(proofs::Checker& check, std::mt19937& g) {
  // ---- first-order start ----------------------------------------------------------------------------
  proofs::Instances accepted{"(loop, eps) where the checker accepts the first-order start on (0, eps]", 40},
      refused{"(loop, eps) where it does not, M(eps) unstable among them", 40};
  bool identity = true, sound = true, s_zero_refused = true;
  long unstable_refused = 0;
  for (int t = 0; t < 60; ++t) {
    const SlowLoop d = draw_slow_loop(g);
    for (const Q& p : {Q(1, 3), Q(1), Q(2), Q(5)}) identity = identity && stein_identity_at(d, p);
    for (const Q& eps : {Q(1, 10), Q(1), Q(3), Q(8)}) {
      if (!checker_on(d, d.S, eps).empty()) {
        refused.count(true);
        unstable_refused += !schur_stable(charpoly(to_matq(loop_at(d, eps))));
        continue;
      }
      accepted.count(true);
      for (const Q& p : {eps / 1000, eps / 3, eps}) sound = sound && schur_stable(charpoly(to_matq(loop_at(d, p))));
      s_zero_refused = s_zero_refused && !checker_on(d, rm::zeros(d.S.size(), d.S.size()), eps).empty();
    }
  }
  std::ostringstream e1;
  e1 << "the identity exact at p = 1/3, 1, 2, 5 on 60 loops: " << (identity ? "holds" : "FAILS") << "; each accepted (loop, eps) Schur stable "
     << "at eps/1000, eps/3, eps by Schur-Cohn: " << (sound ? "yes" : "NO") << "; S = 0 never accepted: " << (s_zero_refused ? "yes" : "NO")
     << "; " << unstable_refused << " refused where M(eps) is unstable";
  // its certificate: a mass-damper's sup K (a position integrator: the cover starts with `first_order`), the closed form
  // of ext.stability.damper_n0 at m = b = 1, T = 1/1000 (40 digits by mpmath) inside
  proofs::CertificateRequest r;
  r.args = {"stability", "--plant", "1/(m*s^2 + b*s)", "--set", "m=1", "--set", "b=1", "--H", "K", "--T", "1/1000", "--max", "K"};
  r.contains = "2000.333388892592283877130610588631144";
  check.certify("ext.loop_max.first_order_start", r);
  check.claim("ext.loop_max.first_order_start", "Stein on (0, eps], L M(0) = L",
              "with L M(0) = L and P(p) = P0 + L^T S L/p, P(p) - M(p)^T P(p) M(p) = P0 - M^T P0 M - (K^T S L + L^T S K) - p K^T S K "
              "(K = L (M(2) - M(1)); exact, a cubic identity after times p), concave in p; where the checker accepts it at 0 and eps, "
              "M(p) is Schur stable on (0, eps] (exact Schur-Cohn at eps/1000, eps/3, eps), and with S = 0 it never accepts -- on "
              "60 random loops (seed 47073) at eps = 1/10, 1, 3, 8; its certificate: a mass-damper's sup K, its cover started so",
              Status::certified, identity && sound && s_zero_refused && accepted.enough() && refused.enough() && unstable_refused > 0, e1.str(),
              {accepted, refused});
}

void bernstein_claim(proofs::Checker& check, std::mt19937& g) {
  // ---- P linear over an interval ----------------------------------------------------------------------
  proofs::Instances lin_accepted{"pairs (P, M) linear on [0, 1] the checker accepts", 30}, lin_refused{"pairs it does not", 30};
  bool bern_identity = true, bern_sound = true;
  for (int t = 0; t < 80; ++t) {
    const size_t n = 2 + g() % 4;
    const Q scale = std::vector<Q>{Q(1, 2), Q(1), Q(3, 2), Q(2)}[g() % 4];
    RMat Ma = rm::zeros(n, n), Mb = Ma, Pa = rm::identity(n), Pb = rm::identity(n);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) {
        Ma[i][j] = draw(g, -8, 8, 16) * scale;
        Mb[i][j] = Ma[i][j] + draw(g, -4, 4, 32) * scale;
        if (j < i) Pa[i][j] = Pa[j][i] = draw(g, -2, 2, 16), Pb[i][j] = Pb[j][i] = Pa[i][j] + draw(g, -1, 1, 16);
      }
    for (const Q& x : {Q(0), Q(1, 3), Q(1, 2), Q(2, 3), Q(1)}) bern_identity = bern_identity && bernstein_identity_at(Pa, Pb, Ma, Mb, x);
    std::string why;
    if (!check::detail::bernstein_stein_holds(Pa, Pb, balls(Ma), balls(Mb), why)) {
      lin_refused.count(true);
      continue;
    }
    lin_accepted.count(true);
    for (const Q& x : {Q(1, 7), Q(1, 2), Q(5, 6)})
      bern_sound = bern_sound && rm::positive_definite(stein(lerp(Pa, Pb, x), lerp(Ma, Mb, x)), true) &&
                   schur_stable(charpoly(to_matq(lerp(Ma, Mb, x))));
  }
  check.no_certificate("ext.loop_max.bernstein_cover", "the argument the stability-loop-max checkers rely on for a cover's intervals, not a verdict of a command; the suprema whose covers use it have certificates (kind stability-loop-max)");
  check.claim("ext.loop_max.bernstein_cover", "Stein with P linear in p",
              "with P and M affine in t on [0, 1], S(t) = P(t) - M(t)^T P(t) M(t) = sum_s C_s B_s(t), C_s = ((3 - s) Pa + s Pb)/3 - "
              "(3 choose s)^-1 sum_{i+j+k=s} X_i^T P_j X_k (exact at t = 0, 1/3, 1/2, 2/3, 1: a cubic identity); where the checker "
              "finds every C_s > 0, S(t) > 0 exactly and M(t) is Schur stable (Schur-Cohn) at t = 1/7, 1/2, 5/6 -- on 80 random "
              "pairs of order 2-5 (seed 47073)",
              Status::certified, bern_identity && bern_sound && lin_accepted.enough() && lin_refused.enough(),
              std::string("the identity ") + (bern_identity ? "exact" : "FAILS") + "; accepted pairs " +
                  (bern_sound ? "stable with S > 0 at every t tried" : "NOT all stable"),
              {lin_accepted, lin_refused});
}

void kernel_claim(proofs::Checker& check, std::mt19937& g) {
  // ---- kernel of the slow rows ----------------------------------------------------------------------
  proofs::Instances kernels{"random M with L M = L, exact restriction", 30};
  bool kernel_ok = true;
  for (int t = 0; t < 40; ++t) {
    bool exact = false;
    const bool holds = kernel_identity(g, exact);
    if (kernels.count(exact)) kernel_ok = kernel_ok && holds;
  }
  check.claim("ext.loop_max.kernel_restriction", "sup = 0 beside a free position",
              "L M = L (L in reduced echelon form) leaves ker L invariant and M the identity on the quotient: det(zI - M) = (z - 1)^k "
              "det(zI - M|ker L), M|ker L as the checker restricts it -- exact identity of characteristic polynomials on 40 random "
              "dyadic M of order 2-6 with k = 1, 2 (seed 47073)",
              Status::exact, kernel_ok && kernels.enough(), kernel_ok ? "every identity exact" : "an identity FAILS", {kernels});
}

void slow_hold_claim(proofs::Checker& check, std::mt19937& g) {
  // ---- holds on a slow row --------------------------------------------------------------------------
  proofs::Instances holds{"plants (A, B) with a row l^T A = 0 and one l'^T A != 0", 20};
  bool slow_ok = true, separated = true;
  for (int t = 0; t < 24; ++t) {
    const long n = 2 + static_cast<long>(g() % 3);
    MatQ A = MatQ::Zero(n, n), B(n, 1), R(n, n);
    std::vector<Q> l(static_cast<size_t>(n)), other(static_cast<size_t>(n));
    for (long i = 0; i < n; ++i) {
      l[static_cast<size_t>(i)] = draw(g, 1, 5, 1);
      other[static_cast<size_t>(i)] = i == 0 ? Q(1) : Q(0);
      B(i, 0) = draw(g, -5, 5, 2);
      for (long j = 0; j < n; ++j) R(i, j) = draw(g, -6, 6, 3);
    }
    // A = (I - e_0 l^T / l_0) R: l^T A = (l^T - l^T) R = 0
    for (long i = 0; i < n; ++i)
      for (long j = 0; j < n; ++j) {
        A(i, j) = R(i, j);
        if (i == 0)
          for (long t2 = 0; t2 < n; ++t2) A(i, j) -= l[static_cast<size_t>(t2)] / l[0] * R(t2, j);
      }
    Q lA = 0;
    for (long j = 0; j < n; ++j) lA += abs(A(0, j));
    if (!holds.count(lA != 0)) continue;
    for (const Q& h : {Q(1, 1000), Q(3, 10000), Q(1, 10)}) {
      const ZohEnclosure z = zoh_enclosure(A, B, h);
      std::vector<Q> lB(1, Q(0));
      for (long i = 0; i < n; ++i) lB[0] += l[static_cast<size_t>(i)] * B(i, 0) * h;
      slow_ok = slow_ok && row_within(l.data(), z.Phi, l) && row_within(l.data(), z.Gamma, lB);
      separated = separated && !row_within(other.data(), z.Phi, other);
    }
  }
  check.no_certificate("ext.loop_max.slow_hold", "the argument behind the checkers' exact slow matrix, not a verdict of a command; the suprema of pure masses and mass-dampers have certificates (kind stability-loop-max)");
  check.claim("ext.loop_max.slow_hold", "slow matrix, holds -> I, h B",
              "l^T A = 0 gives l^T e^{Ah} = l^T and l^T Gamma_h = h l^T B (the power series), so the exact slow matrix has the loop's "
              "slow rows: inside the zero-order hold's ball enclosure at h = 1e-3, 3e-4, 1e-1 on 24 random rational plants of order 2-4, "
              "and a row e_0 with e_0^T A != 0 is separated from e_0^T by the same enclosure (seed 47073)",
              Status::certified, slow_ok && separated && holds.enough(),
              std::string(slow_ok ? "every slow row inside" : "a slow row OUTSIDE") + "; " +
                  (separated ? "every other row separated" : "a row with l^T A != 0 NOT separated"),
              {holds});
}

void residue_claim(proofs::Checker& check, std::mt19937& g) {
  // ---- the residue at an irrational axis pole --------------------------------------------------------
  proofs::Instances psd{"residues positive semidefinite", 8}, indefinite{"residues not positive semidefinite", 8};
  bool residue_ok = true, congruent = true;
  for (int t = 0; t < 40; ++t) {
    const Q q = std::vector<Q>{Q(2), Q(3), Q(1, 2), Q(5, 3), Q(7)}[g() % 5];
    const size_t m = 1 + g() % 2;
    RMat F = rm::zeros(m, m), G = rm::zeros(m, m);
    for (size_t i = 0; i < m; ++i) {
      F[i][i] = draw(g, -2, 8, 2);
      for (size_t j = 0; j < i; ++j) {
        F[i][j] = F[j][i] = draw(g, -4, 4, 3);
        G[i][j] = draw(g, -4, 4, 1), G[j][i] = -G[i][j];
      }
    }
    // Z = (s F + G)/(s^2 + q) + Z1, Z1 = W/((s + 1)(s + 2)) entrywise; d = (s^2 + q)(s + 1)(s + 2)
    const QPoly pole2(std::vector<Q>{q, Q(0), Q(1)}), d1(std::vector<Q>{Q(2), Q(3), Q(1)}), d = pole2 * d1;
    RMat X = rm::zeros(m, m), Y = X;
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j) {
        const QPoly n = QPoly(std::vector<Q>{G[i][j], F[i][j]}) * d1 + QPoly(std::vector<Q>{draw(g, -5, 5, 1), draw(g, -5, 5, 1)}) * pole2;
        const auto [x, y] = residue_by_derivative(n, d, q);
        const Cx r = divide(evaluate_at_jw0(n, q), mul({{0, 0}, {0, 2}}, evaluate_at_jw0(d1, q), q), q);  // n/((2 j w0) d1)
        residue_ok = residue_ok && r.re == Surd{x, 0} && r.im == Surd{0, y} && x == F[i][j] / 2 && y == -G[i][j] / (2 * q);
        X[i][j] = x, Y[i][j] = y;
      }
    // D [[X, -Y], [Y, X/q]] D == [[X, -w0 Y], [w0 Y, X]], D = diag(I, w0 I): entrywise in Q(sqrt q)
    RMat N = rm::zeros(2 * m, 2 * m);
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j) N[i][j] = X[i][j], N[i][m + j] = -Y[i][j], N[m + i][j] = Y[i][j], N[m + i][m + j] = X[i][j] / q;
    Eigen::MatrixXd real_form(2 * m, 2 * m);
    for (size_t i = 0; i < 2 * m; ++i)
      for (size_t j = 0; j < 2 * m; ++j) {
        const Surd di{i < m ? Q(1) : Q(0), i < m ? Q(0) : Q(1)}, dj{j < m ? Q(1) : Q(0), j < m ? Q(0) : Q(1)};
        const Surd lhs = times(times(di, {N[i][j], 0}, q), dj, q);
        const size_t a = i % m, b = j % m;
        const Surd rhs = i < m && j < m ? Surd{X[a][b], 0} : i >= m && j >= m ? Surd{X[a][b], 0} : i < m ? Surd{0, -Y[a][b]} : Surd{0, Y[a][b]};
        congruent = congruent && lhs == rhs;
        real_form(static_cast<long>(i), static_cast<long>(j)) = static_cast<double>(rhs.a) + static_cast<double>(rhs.b) * std::sqrt(static_cast<double>(q));
      }
    const bool is_psd = rm::positive_definite(N, false);
    const double least = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(real_form).eigenvalues().minCoeff();
    if (std::abs(least) > 1e-9) residue_ok = residue_ok && (is_psd == (least > 0));  // a double cross-check off zero
    (is_psd ? psd : indefinite).count(true);
  }
  check.claim("ext.operator.irrational_residue", "Assumption 1(b), s = j sqrt(q)",
              "the residue of Z = (sF + G)/(s^2 + q) + Z1 at s = j w0, w0 = sqrt(q) irrational, is X + j w0 Y = F/2 - j w0 G/(2q) with X, Y "
              "rational, the checker's n(j w0)/d'(j w0) (even and odd powers apart) equal to n(j w0)/((2 j w0) d1(j w0)) in Q(sqrt q)(j); "
              "and diag(I, w0 I) [[X, -Y], [Y, X/q]] diag(I, w0 I) = [[X, -w0 Y], [w0 Y, X]] in Q(sqrt q), a congruence: PSD of the "
              "rational matrix decides the residue's -- on 40 random 1x1 and 2x2 Z, q in {2, 3, 1/2, 5/3, 7} (seed 47073)",
              Status::exact, residue_ok && congruent && psd.enough() && indefinite.enough(),
              std::string(residue_ok ? "both routes and the construction agree" : "the routes DISAGREE") + "; congruence " +
                  (congruent ? "exact" : "FAILS"),
              {psd, indefinite});
}

// ---- the first-order mirror (sup = 0) -----------------------------------------------------------------
// draw_slow_loop's loops with the slow block of K1 +c I (p moves the slow modes OUT), S = -s I, w = e_1 (a slow
// coordinate): the checker's first_order_unstable accepts at small eps.
std::string mirror_on(const SlowLoop& d, const RMat& S, const Q& eps, const std::vector<Q>& w) {
  check::detail::LoopMatrix m1, m2;
  m1.M = balls(loop_at(d, Q(1)));
  m2.M = balls(loop_at(d, Q(2)));
  nlohmann::json wj = nlohmann::json::array();
  for (const Q& x : w) wj.push_back(x.str());
  const nlohmann::json fo = {{"to", eps.str()}, {"P0", json_matrix(d.P0)}, {"S", json_matrix(S)}, {"w", wj}};
  bool refuted = false;
  return check::detail::first_order_unstable(fo, m1, m2, d.L, "evidence", refuted);
}

void mirror_claim(proofs::Checker& check, std::mt19937& g) {
  proofs::Instances accepted{"(loop, eps) where the checker accepts the mirror on (0, eps]", 40},
      refused{"(loop, eps) where it does not", 20};
  bool sound = true, flipped_refused = true;
  for (int t = 0; t < 60; ++t) {
    SlowLoop d = draw_slow_loop(g);
    const size_t k = d.L.size(), n = d.M0.size();
    for (size_t i = 0; i < k; ++i) d.K1[i][i] += 2 * (Q(1) - d.K1[i][i]);  // -c + x -> the slow diagonal pushed out
    RMat S = rm::zeros(k, k), Sflip = rm::zeros(k, k);
    for (size_t i = 0; i < k; ++i) S[i][i] = -d.S[i][i], Sflip[i][i] = d.S[i][i];
    std::vector<Q> w(n, Q(0));
    w[0] = 1;
    for (const Q& eps : {Q(1, 100), Q(1, 10), Q(1), Q(8)}) {
      if (!mirror_on(d, S, eps, w).empty()) {
        refused.count(true);
        continue;
      }
      accepted.count(true);
      for (const Q& p : {eps / 1000, eps / 3, eps}) sound = sound && !schur_stable(charpoly(to_matq(loop_at(d, p))));
      flipped_refused = flipped_refused && !mirror_on(d, Sflip, eps, w).empty() && !mirror_on(d, S, eps, std::vector<Q>(n, Q(0))).empty();
    }
  }
  // its certificate: two devices on linked walls of negative stiffness (tests/cli/scenes/loop_max_zero_outward.toml)
  proofs::CertificateRequest r;
  r.args = {"stability", "--scene", "{input}", "--max", "g", "--quiet"};
  r.input = "[scene]\nname = \"negative walls\"\nT = \"1/1000\"\n[parameters]\ng = \"1\"\n"
            "[[device]]\nname = \"a\"\nm = \"1/2\"\nb = \"1\"\n[[device]]\nname = \"b\"\nm = \"1\"\nb = \"2\"\n"
            "[environment]\ntf = [[\"-1000 + 2*(z-1)/(T*z)\", \"-100\"], [\"-100\", \"-500 + 2*(z-1)/(T*z)\"]]\ngain = \"g\"";
  r.contains = "0";
  check.certify("ext.loop_max.first_order_mirror", r);
  std::ostringstream e;
  e << "each accepted (loop, eps) NOT Schur stable at eps/1000, eps/3, eps by Schur-Cohn: " << (sound ? "yes" : "NO")
    << "; S of the other sign, or w = 0, never accepted: " << (flipped_refused ? "yes" : "NO");
  check.claim("ext.loop_max.first_order_mirror", "sup = 0 by the first-order mirror",
              "with L M(0) = L, P(p) = P0 + L^T S L/p (S of any sign) and Q(p) = P(p) - M(p)^T P(p) M(p) (the start's identity) > 0 at 0 "
              "and eps (concave in p), s = (L w)^T S (L w) < 0 and w^T P0 w + s/eps < 0: M(p) is NOT Schur stable on (0, eps] (Stein "
              "inertia) -- wherever the checker accepts, exact Schur-Cohn finds M(p) unstable at eps/1000, eps/3, eps; with S negated "
              "or w = 0 it never accepts -- on 60 random loops whose slow modes p moves out (seed 47073) at eps = 1/100, 1/10, 1, 8; "
              "its certificate: sup g = 0 of two devices on walls of negative stiffness (kind stability-loop-max)",
              Status::certified, sound && flipped_refused && accepted.enough() && refused.enough(), e.str(), {accepted, refused});
}

// ---- no crossing of the circle (a pure mass's Jordan block at p = 0) --------------------------------------------
// Res(f, g) for f monic of degree n and g of formal degree n as the determinant of their Sylvester matrix
// (numeric/exact_matrix.hpp): no resultant routine.
Q sylvester_resultant(const Polynomial<Q>& f, const Polynomial<Q>& g, int n) {
  MatQ S = MatQ::Zero(2 * n, 2 * n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= n; ++k) {
      S(i, i + k) = f.coeff(n - k);  // descending
      S(n + i, i + k) = g.coeff(n - k);
    }
  return exact_determinant(S);
}

void no_crossing_claim(proofs::Checker& check, std::mt19937& g) {
  proofs::Instances stable{"(family, a): no crossing on (0, a], M(a) stable", 20}, unstable{"... M(a) NOT stable", 10},
      degree{"families whose R was evaluated directly at three points", 40};
  bool sound = true, interpolated = true;
  for (int t = 0; t < 60; ++t) {
    // a pure mass's Jordan block [[1, h], [0, 1]] beside a stable 2 x 2 part, p a spring-damper on the mass (and a
    // random coupling of rank <= 2)
    const Q h = draw(g, 1, 4, 4), k = draw(g, -3, 6, 4), b = draw(g, -2, 8, 4);
    MatQ M0 = MatQ::Zero(4, 4), M1 = MatQ::Zero(4, 4);
    M0(0, 0) = 1, M0(0, 1) = h, M0(1, 1) = 1;
    for (long i = 2; i < 4; ++i)
      for (long j = 2; j < 4; ++j) M0(i, j) = draw(g, -3, 3, 10);
    M0(1, 2) = draw(g, -2, 2, 4), M0(2, 0) = draw(g, -2, 2, 4);
    M1(1, 0) = -k, M1(1, 1) = -b, M1(3, 0) = draw(g, -2, 2, 4), M1(3, 1) = draw(g, -2, 2, 4);
    const CircleCrossing cc = circle_crossing(M0, M1);
    if (cc.identically_zero) continue;
    degree.count(true);
    for (const Q& p : {Q(1, 3), Q(5, 7), Q(11)}) {
      const Polynomial<Q> c = charpoly(MatQ(M0 + M1 * p));
      std::vector<Q> rev(5);
      for (int i = 0; i <= 4; ++i) rev[size_t(i)] = c.coeff(4 - i);
      Q Rp = cc.R(p);
      for (long m = 0; m < cc.zero_order; ++m) Rp *= p;
      interpolated = interpolated && Rp == sylvester_resultant(c, Polynomial<Q>(std::move(rev)), 4);
    }
    for (const Q& a : {Q(1, 100), Q(1, 10), Q(1, 2)}) {
      if (!no_circle_crossing(M0, M1, a).empty()) continue;
      const bool at_a = schur_stable(charpoly(MatQ(M0 + M1 * a)));
      (at_a ? stable : unstable).count(true);
      for (const Q& p : {a / 1000, a / 3, a * 2 / 3}) sound = sound && schur_stable(charpoly(MatQ(M0 + M1 * p))) == at_a;
    }
  }
  // its certificate: two pure masses under linked spring-damper walls (tests/cli/scenes/loop_max_pure_masses.toml);
  // what it must contain: the first positive root of R for the scene's own loop, refined here
  proofs::CertificateRequest r;
  r.args = {"stability", "--scene", "{input}", "--max", "g", "--quiet"};
  r.input = "[scene]\nname = \"two pure masses\"\nT = \"1/1000\"\n[parameters]\ng = \"1\"\n"
            "[[device]]\nname = \"d0\"\nm = \"1/100\"\nb = \"0\"\n[[device]]\nname = \"d1\"\nm = \"1/50\"\nb = \"0\"\n"
            "[environment]\ntf = [[\"2500 + 5*(z-1)/(T*z)\", \"-500\"], [\"-500\", \"3500 + 8*(z-1)/(T*z)\"]]\ngain = \"g\"";
  r.contains = "2.363709386939923421";  // R's first positive root (the crossing), isolated below
  check.certify("ext.loop_max.no_crossing", r);
  std::ostringstream e;
  e << "R's interpolation equal to the Sylvester determinant at 1/3, 5/7, 11: " << (interpolated ? "yes" : "NO")
    << "; M(p) at a/1000, a/3, 2a/3 with M(a)'s verdict wherever no crossing on (0, a]: " << (sound ? "yes" : "NO");
  check.claim("ext.loop_max.no_crossing", "no crossing of the unit circle on (0, a]",
              "c(z, p) = det(zI - M0 - p M1) monic in z, R(p) = Res_z(c, z^n c(1/z)) vanishes wherever an eigenvalue is on |z| = 1; "
              "deg_p c <= rank M1, deg R <= 2 n rank M1, R interpolated exactly from resultants at integers equals the Sylvester "
              "determinant at other points; R without a root in (0, a] leaves M(p) one inertia there -- exact Schur-Cohn at a/1000, "
              "a/3, 2a/3 agrees with M(a) -- on 60 random families with a pure mass's Jordan block at z = 1 (seed 47073), a in {1/100, "
              "1/10, 1/2}; its certificate: sup g of two pure masses (kind stability-loop-max, evidence no_crossing)",
              Status::exact, sound && interpolated && stable.enough() && unstable.enough() && degree.enough(), e.str(),
              {stable, unstable, degree});
}

}  // namespace ext_loop_max_certificate_detail

HAPSTAB_PROOF(ext_loop_max_certificate, "ext", "the arguments of the supremum's and the axis residue's certificates") {
  using namespace ext_loop_max_certificate_detail;
  std::mt19937 g(47073);  // one stream, the claims in this order
  first_order_claim(check, g);
  bernstein_claim(check, g);
  kernel_claim(check, g);
  slow_hold_claim(check, g);
  residue_claim(check, g);
  mirror_claim(check, g);
  no_crossing_claim(check, g);
}
