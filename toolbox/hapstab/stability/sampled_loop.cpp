#include "hapstab/stability/sampled_loop.hpp"
#include "hapstab/stability/long_delay.hpp"
#include "hapstab/stability/max_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <type_traits>
#include <vector>

#if HAPSTAB_FLINT3
#include <flint/acb_poly.h>
#else
#include <acb_poly.h>
#endif

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::stability {
namespace {

using QP = Polynomial<rational>;

// ---- real balls (numeric/ball.hpp) at the working precision of this thread ---------------------
using flint::Ball;

bool is_zero(const rational& q) { return q == 0; }
bool is_zero(const Ball& b) { return arb_is_zero(b.get()); }

Enclosure<rational> bounds(const arb_t x) {
  if (!arb_is_finite(x)) throw NumericalError("stability: Arb lost the enclosure (non-finite ball)");
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  arb_get_lbound_arf(lo, x, flint::ball_prec);
  arb_get_ubound_arf(hi, x, flint::ball_prec);
  Enclosure<rational> e{flint::to_rational(lo), flint::to_rational(hi)};
  arf_clear(lo);
  arf_clear(hi);
  return e;
}

// ---- polynomials as ascending coefficient vectors over rational or Ball ---------------------
template <class C>
using Vec = std::vector<C>;

template <class C>
Vec<C> lift(const QP& p) {
  Vec<C> v;
  for (const rational& c : p.coeffs()) v.emplace_back(c);
  return v;
}
template <class C>
Vec<C> add(Vec<C> a, const Vec<C>& b) {
  if (a.size() < b.size()) a.resize(b.size(), C(rational(0)));
  for (size_t i = 0; i < b.size(); ++i) a[i] = a[i] + b[i];
  return a;
}
template <class C>
Vec<C> mul(const Vec<C>& a, const Vec<C>& b) {
  if (a.empty() || b.empty()) return {};
  Vec<C> r(a.size() + b.size() - 1, C(rational(0)));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) r[i + j] = r[i + j] + a[i] * b[j];
  return r;
}
template <class C>
C eval(const Vec<C>& p, const C& x) {
  C r(rational(0));
  for (size_t i = p.size(); i-- > 0;) r = r * x + p[i];
  return r;
}
template <class C>
Vec<C> shift(const Vec<C>& p, int n) {  // z^n p
  Vec<C> r(static_cast<size_t>(n), C(rational(0)));
  r.insert(r.end(), p.begin(), p.end());
  return r;
}

// ---- the sampled device: P_d = N/D, D = (z - 1)^r * (the rest) -------------------------------
template <class C>
struct Sampled {
  Vec<C> N, D;
  int r = 0;  // exact multiplicity of z = 1 in D (the device's poles at s = 0)
  bool N_zero_at_minus1 = false;  // N(-1) = 0 exactly (an even device: sample_ball)
};

Mat<rational> van_loan(const StateSpace<rational>& ss, const rational& T) {
  const Eigen::Index n = ss.A.rows();
  Mat<rational> M = Mat<rational>::Zero(n + 1, n + 1);
  M.topLeftCorner(n, n) = ss.A * T;
  M.topRightCorner(n, 1) = ss.B * T;
  return M;
}

StateSpace<rational> realize(const QP& num, const QP& den) { return tf2ss(tf(num, den)); }

/// All poles at s = 0: Van Loan's block is nilpotent, its exponential a finite sum, exact.
Sampled<rational> sample_exact(const QP& num, const QP& den, const rational& T) {
  const StateSpace<rational> ss = realize(num, den);
  const Eigen::Index n = ss.A.rows();
  const Mat<rational> M = van_loan(ss, T);
  Mat<rational> E = Mat<rational>::Identity(n + 1, n + 1), term = E;
  for (Eigen::Index k = 1; k <= n; ++k) {
    term = (term * M).eval() / rational(k);
    E += term;
  }
  const Mat<rational> Phi = E.topLeftCorner(n, n), Gamma = E.topRightCorner(n, 1);
  const QP D = charpoly(Phi), closed = charpoly((Phi - Gamma * ss.C).eval());
  Sampled<rational> s;
  s.D = D.coeffs();
  s.N = (closed - D).coeffs();
  s.r = static_cast<int>(n);
  return s;
}

void exp_ball(flint::BallMat& out, const Mat<rational>& M) {
  flint::QMat q(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) flint::set(q.at(i, j), M(i, j));
  flint::BallMat X(M.rows(), M.cols());
  arb_mat_set_fmpq_mat(X.get(), q.get(), flint::ball_prec);
  arb_mat_exp(out.get(), X.get(), flint::ball_prec);
}

Vec<Ball> charpoly_ball(const flint::BallMat& A) {
  arb_poly_t p;
  arb_poly_init(p);
  arb_mat_charpoly(p, A.get(), flint::ball_prec);
  Vec<Ball> v;
  for (slong i = 0; i < arb_poly_length(p); ++i) v.emplace_back(arb_poly_get_coeff_ptr(p, i));
  arb_poly_clear(p);
  return v;
}

/// N(-1) = 0 exactly for a device P = num/den even in s, P(-s) = P(s) (an undamped mass-spring
/// 1/(m s^2 + k), 1/s^2), when D(-1) != 0 (no sampled pole at z = -1). Proof: with (A, B, C) any
/// realisation of P, Phi = e^{AT} and Gamma = int_0^T e^{At} dt B, the ZOH gives
///   G(-1) = C (-I - Phi)^-1 Gamma = C f(A) B,  f(x) = -(e^{xT} - 1)/(x (1 + e^{xT})) = -tanh(xT/2)/x,
/// f even and analytic on A's spectrum (1 + e^{xT} != 0 there: D(-1) != 0), so f(A) = p(A^2) for a
/// polynomial p; P(s) = sum_j C A^j B s^-(j+1) even makes every C A^(2k) B = 0, so G(-1) = 0, and
/// N(-1) = D(-1) G(-1) = 0 (N = D G identically: N = det(zI - Phi + Gamma C) - det(zI - Phi)).
/// A Ball N(-1) only encloses 0; this makes c1(-1) = A1(-1) N(-1) exactly 0 for `stability --max`
/// (issue 46: "c1(+-1) not separated from 0" was 34 of stability_max's 47 undecided cases).
template <class S>
bool even_device_zero_at_minus1(const QP& num, const QP& den, const S& s) {
  const auto reflect = [](const QP& p) {  // p(-s)
    std::vector<rational> c = p.coeffs();
    for (size_t k = 1; k < c.size(); k += 2) c[k] = -c[k];
    return QP(c);
  };
  if (num * reflect(den) != reflect(num) * den) return false;
  const Ball d = eval(s.D, Ball(rational(-1)));
  return !arb_contains_zero(d.get());
}

/// Poles off s = 0: e^{p T} as Arb balls. D keeps its exact (z - 1)^r factor.
Sampled<Ball> sample_ball(const QP& num, const QP& den, const rational& T, int r) {
  const StateSpace<rational> ss = realize(num, den);
  const Eigen::Index n = ss.A.rows();
  flint::BallMat E(n + 1, n + 1), Phi(n, n), closed(n, n);
  exp_ball(E, van_loan(ss, T));
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      arb_set(Phi.at(i, j), E.at(i, j));
      const Ball g(E.at(i, n)), c(ss.C(0, j));
      arb_sub(closed.at(i, j), E.at(i, j), (g * c).get(), flint::ball_prec);
    }
  Sampled<Ball> s;
  Vec<Ball> open = charpoly_ball(Phi), shut = charpoly_ball(closed);
  s.N = add(shut, mul(open, Vec<Ball>{Ball(rational(-1))}));
  s.N.pop_back();  // the leading terms cancel exactly (both monic)
  // D = (z - 1)^r * charpoly(e^{A~ T}), A~ the companion of den / s^r (no pole at 0).
  const QP rest(std::vector<rational>(den.coeffs().begin() + r, den.coeffs().end()));
  Vec<Ball> D{Ball(rational(1))};
  if (rest.degree() > 0) {
    const StateSpace<rational> sr = realize(QP(rational(1)), rest);
    flint::BallMat Er(sr.A.rows(), sr.A.rows());
    exp_ball(Er, (sr.A * T).eval());
    D = charpoly_ball(Er);
  }
  for (int k = 0; k < r; ++k) D = mul(D, Vec<Ball>{Ball(rational(-1)), Ball(rational(1))});
  s.D = D;
  s.r = r;
  s.N_zero_at_minus1 = even_device_zero_at_minus1(num, den, s);
  return s;
}

int zero_poles(const QP& den) {
  int r = 0;
  while (r <= den.degree() && den.coeff(r) == 0) ++r;
  return r;
}

// ---- the characteristic polynomial c0 + K c1 ------------------------------------------------
struct WallPolys {
  QP L, A0, A1;  // H0 = A0/L, H1 = A1/L
};

WallPolys wall_polys(const Loop& loop) {
  const QP& d0 = loop.H.den();
  if (!loop.H_gain) return {d0, loop.H.num(), QP()};
  const QP& d1 = loop.H_gain->den();
  const QP L = divmod(d0 * d1, gcd(d0, d1)).first;
  return {L, loop.H.num() * divmod(L, d0).first, loop.H_gain->num() * divmod(L, d1).first};
}

/// c0(1), c1(1), c0(-1), c1(-1) with structural zeros exact (they decide crossings at z = +-1).
template <class C>
struct Edges {
  C at1_0, at1_1, atm1_0, atm1_1;
};

template <class C>
struct Characteristic : Edges<C> {
  Vec<C> c0, c1;
};

template <class C>
C term_at(const QP& A, const rational& x, const Vec<C>& N) {
  const rational a = A(x);
  return a == 0 ? C(rational(0)) : C(a) * eval(N, C(x));
}

template <class C>
Edges<C> edges(const WallPolys& w, const Sampled<C>& s, int n) {
  Edges<C> e;
  const C lead1 = s.r >= 1 ? C(rational(0)) : C(w.L(rational(1))) * eval(s.D, C(rational(1)));
  e.at1_0 = lead1 + term_at(w.A0, rational(1), s.N);
  e.at1_1 = term_at(w.A1, rational(1), s.N);
  const rational sign = n % 2 == 0 ? 1 : -1;
  e.atm1_0 = C(sign * w.L(rational(-1))) * eval(s.D, C(rational(-1))) +
              (s.N_zero_at_minus1 ? C(rational(0)) : term_at(w.A0, rational(-1), s.N));
  e.atm1_1 = s.N_zero_at_minus1 ? C(rational(0)) : term_at(w.A1, rational(-1), s.N);
  return e;
}

template <class C>
Characteristic<C> characteristic(const WallPolys& w, const Sampled<C>& s, int n) {
  Characteristic<C> ch;
  static_cast<Edges<C>&>(ch) = edges(w, s, n);
  ch.c0 = add(shift(mul(lift<C>(w.L), s.D), n), mul(lift<C>(w.A0), s.N));
  ch.c1 = mul(lift<C>(w.A1), s.N);
  return ch;
}

/// The long-delay form c = z^n P + Q0 + K Q1 (long_delay.hpp): P = L D_d, Q0 = A0 N_d, Q1 = A1 N_d.
Vec<Ball> to_balls(const Vec<rational>& v) {
  Vec<Ball> b;
  for (const rational& c : v) b.emplace_back(c);
  return b;
}
Vec<Ball> to_balls(const Vec<Ball>& v) { return v; }
template <class C>
detail::DelayedLoop delayed_loop(const WallPolys& w, const Sampled<C>& s, int n) {
  detail::DelayedLoop d;
  d.n = n;
  const Vec<C> P = mul(lift<C>(w.L), s.D), Q0 = mul(lift<C>(w.A0), s.N), Q1 = mul(lift<C>(w.A1), s.N);
  d.P = to_balls(P), d.Q0 = to_balls(Q0), d.Q1 = to_balls(Q1);
  if constexpr (std::is_same_v<C, rational>) {
    d.exact = true;
    d.Pq = P, d.Q0q = Q0, d.Q1q = Q1;
  }
  return d;
}

// ---- certified roots: Schur decision and spectral radius -------------------------------------
struct RootTest {
  Outcome outcome = Outcome::undecided;
  std::optional<Enclosure<rational>> radius;
};

RootTest root_test(const Vec<Ball>& c) {
  RootTest t;
  const slong deg = static_cast<slong>(c.size()) - 1;
  if (deg < 1) {
    t.outcome = Outcome::holds;
    t.radius = Enclosure<rational>{0, 0};
    return t;
  }
  if (arb_contains_zero(c.back().get())) return t;
  acb_poly_t p;
  acb_poly_init(p);
  for (slong i = 0; i <= deg; ++i) {
    acb_t z;
    acb_init(z);
    acb_set_arb(z, c[static_cast<size_t>(i)].get());
    acb_poly_set_coeff_acb(p, i, z);
    acb_clear(z);
  }
  acb_ptr roots = _acb_vec_init(deg);
  const slong isolated = acb_poly_find_roots(roots, p, nullptr, 0, flint::ball_prec);
  bool all_inside = true, one_outside = false;
  rational lo = 0, hi = 0;
  for (slong i = 0; i < deg; ++i) {
    Ball m;
    acb_abs(m.get(), roots + i, flint::ball_prec);
    const Enclosure<rational> e = bounds(m.get());
    lo = std::max(lo, e.lo);
    hi = std::max(hi, e.hi);
    if (e.hi >= 1) all_inside = false;
    if (e.lo > 1) one_outside = true;
  }
  _acb_vec_clear(roots, deg);
  acb_poly_clear(p);
  // The n balls together hold every root; each holds exactly one when all are isolated.
  if (all_inside) t.outcome = Outcome::holds;
  else if (one_outside && isolated == deg) t.outcome = Outcome::fails;
  t.radius = Enclosure<rational>{isolated == deg ? lo : rational(0), hi};
  return t;
}

QP squarefree(const QP& p) {
  if (p.degree() < 1) return p;
  return divmod(p, gcd(p, p.derivative())).first;
}

/// Exact polynomial: Schur-Cohn decides; the radius from the roots of its square-free part.
RootTest exact_root_test(const QP& c) {
  RootTest t = root_test(lift<Ball>(squarefree(c)));
  std::string why;
  t.outcome = schur_stable(c, &why) ? Outcome::holds : Outcome::fails;
  return t;
}

// ---- loop data ------------------------------------------------------------------------------
struct Prepared {
  QP num, den;  // P_eff, den monic
  int r = 0;
  bool exact = false;
  WallPolys wall;
};

Prepared prepare(const Loop& loop) {
  // the delay first: the long-delay path's work grows like it (nothing of degree n is allocated)
  if (loop.delay < 0) throw InputError("the delay n must be >= 0, got " + std::to_string(loop.delay));
  if (loop.delay > limits::criterion_delay)
    throw InputError("the delay n = " + std::to_string(loop.delay) + " samples is more than the limit of " +
                     std::to_string(limits::criterion_delay) +
                     " (numeric/limits.hpp: the long-delay path's work grows like the delay)");
  const RationalFunction<rational> P = effective_device(loop);
  if (loop.T <= 0) throw InputError("the sample period T must be > 0");
  if (!loop.H.is_discrete()) throw InputError("H must be a transfer function in z");
  Prepared p;
  p.num = P.num();
  p.den = P.den();
  p.r = zero_poles(p.den);
  p.exact = p.r == p.den.degree();
  p.wall = wall_polys(loop);
  const int room = p.wall.L.degree() + loop.delay;
  if (p.wall.A0.degree() > room || p.wall.A1.degree() > room)
    throw InputError("z^-n H(z) is not causal (degree of numerator > degree of denominator + n): the wall "
                     "would need future positions");
  return p;
}

QP to_qp(const Vec<rational>& v) { return QP(v); }

}  // namespace

RationalFunction<rational> effective_device(const Loop& loop) {
  if (loop.plant.is_discrete()) throw InputError("--plant must be a continuous transfer function in s");
  RationalFunction<rational> P = loop.plant.H;
  if (P.is_zero()) throw InputError("--plant is zero: the device does not move");
  if (loop.operator_impedance) {
    if (loop.operator_impedance->is_discrete()) throw InputError("--operator must be an impedance in s");
    const RationalFunction<rational> s(QP{rational(0), rational(1)});
    const RationalFunction<rational> loop_gain = s * loop.operator_impedance->H * P;
    const RationalFunction<rational> one(rational(1));
    if ((one + loop_gain).is_zero()) throw InputError("1 + s Z_op P is zero: the operator cancels the device");
    P = P / (one + loop_gain);
    // The modes of the device and the operator together are the roots of Dp Dz + s Nz Np (each read in
    // lowest terms); P's reduction may cancel some (the operator's poles at the device's zeros). A
    // cancelled mode stays a mode of the loop as written: one in Re s >= 0 is refused by name (realised
    // as written it is a hidden mode no wall moves) -- except one s, the operator's spring deflection
    // beside the position it integrates (the conserved quantity of sim/closed_loop.hpp).
    const RationalFunction<rational>& Z = loop.operator_impedance->H;
    const QP whole = loop.plant.H.den() * Z.den() + QP{rational(0), rational(1)} * Z.num() * loop.plant.H.num();
    QP lost = divmod(whole, P.den()).first;
    if (lost.degree() >= 1 && lost.coeff(0) == 0) lost = divmod(lost, QP{rational(0), rational(1)}).first;
    if (lost.degree() >= 1 && !hurwitz_stable(lost))
      throw InputError("--operator with --plant: P/(1 + s Z_op P) cancels a mode of the device and the operator with Re s >= 0 "
                       "(the factor " + to_string(lost, "s") + " of Dp Dz + s Nz Np): realised as written it is a hidden "
                       "mode the wall does not move, which the transfer function would drop");
  }
  if (P.num().degree() >= P.den().degree())
    throw InputError("the device " + std::string(loop.operator_impedance ? "with the operator " : "") +
                     "P(s) is not strictly proper: force -> position needs relative degree >= 1 (a mass)");
  return P;
}

namespace {

// ---- the planner: the characteristic polynomial (existing paths) or the long-delay path --------
// Costs on one core of the reference machine, fitted to bench/delay.cpp (BM_kmax: device
// 1/(s^2 + s), wall K + 0.5 (z - 1)/(T z); refitted 3 December 2026): sup K by the polynomial path
// 1.7 ms at degree 13, 41 ms at 33, 0.2 s at 63 (~ degree^3.5), by the long-delay path (arcs in
// double intervals first, issue 48) 0.77 ms at n = 10, 7.8 ms at 10^3, 82 ms at 10^4 (~ its 4 n + 64
// first boxes); the Schur test alone ~ degree^3 (0.12 s at 103).
struct Plan {
  bool long_delay = false;
  long degree = 0;
  std::string why;
};
Plan plan(const Prepared& p, const Loop& loop, bool crossings) {
  Plan pl;
  pl.degree = static_cast<long>(loop.delay) + p.wall.L.degree() + p.den.degree();
  const double d = static_cast<double>(pl.degree) / 100;
  const double poly_cost = crossings ? 1e-3 + 2 * std::pow(d, 3.5) : 0.12 * d * d * d;
  const double long_cost = 6e-4 + (4.0 * static_cast<double>(loop.delay) + 64) * (crossings ? 2e-6 : 2e-7);
  char buf[160];
  std::snprintf(buf, sizeof buf, " (polynomial path ~%.2g s, long-delay path ~%.2g s)", poly_cost, long_cost);
  if (loop.path == LoopPath::long_delay) {
    pl.long_delay = true;
    pl.why = "long-delay path (asked for)";
  } else if (loop.path == LoopPath::polynomial) {
    if (pl.degree > limits::model_degree)
      throw InputError("the characteristic polynomial would have degree " + std::to_string(pl.degree) +
                       ", more than the limit of " + std::to_string(limits::model_degree) + " for the polynomial path");
    pl.why = "polynomial path (asked for)";
  } else if (pl.degree > limits::model_degree) {
    pl.long_delay = true;
    pl.why = "long-delay path: the characteristic polynomial would have degree " + std::to_string(pl.degree) +
             ", more than the limit of " + std::to_string(limits::model_degree) + " for the polynomial path";
  } else if (poly_cost > std::max(2 * long_cost, crossings ? 0.02 : 0.5)) {
    // the Schur test alone keeps the polynomial path up to ~0.5 s (degree ~160): it also encloses
    // the spectral radius, which the argument principle does not give
    pl.long_delay = true;
    pl.why = "long-delay path: cheaper than the characteristic polynomial of degree " + std::to_string(pl.degree) + buf;
  } else {
    pl.why = "polynomial path: the characteristic polynomial has degree " + std::to_string(pl.degree) + buf;
  }
  return pl;
}

/// A root at z = +-1 exactly (exact data): the loop is not Schur stable, exactly.
template <class C>
std::optional<std::string> root_at_edge(const Edges<C>& e) {
  if constexpr (std::is_same_v<C, rational>) {
    if (e.at1_0 == 0) return std::string("z = 1");
    if (e.atm1_0 == 0) return std::string("z = -1");
  }
  return std::nullopt;
}

/// z = 1 decided exactly where the sampled data are not (a device pole off s = 0 makes them
/// transcendental): the zero-order hold keeps the DC gain, P_d(1) = P_eff(0). With no device pole
/// at s = 0, c(1) = den_d(1) (L(1) + A(1) P_eff(0)) and den_d(1) != 0 (the poles e^{pT} != 1); with
/// one, den_d(1) = 0 and c(1) = A(1) num_d(1), which A(1) = 0 makes 0. (Where neither holds z = 1 is
/// left to the enclosures, which then separate c(1) from 0.)
std::optional<std::string> dc_root(const Prepared& p) {
  const rational one(1), A1 = p.wall.A0(one);
  if (p.r > 0)
    return A1 == 0 ? std::optional<std::string>("z = 1 (exact: H(1) = 0 beside a device pole at s = 0)") : std::nullopt;
  if (p.wall.L(one) + A1 * p.num(rational(0)) / p.den(rational(0)) == 0)
    return std::string("z = 1 (exact: 1 + H(1) P(0) = 0, the loop's static stiffness is zero)");
  return std::nullopt;
}

template <class C>
StabilityResult decide_long(const Prepared& p, const Loop& loop, const Sampled<C>& s, long prec) {
  StabilityResult r;
  r.exact_data = p.exact;
  r.precision_bits = prec;
  const detail::DelayedLoop dl = delayed_loop(p.wall, s, loop.delay);
  r.degree = static_cast<int>(dl.degree());
  if (const auto at = root_at_edge(edges(p.wall, s, loop.delay))) {
    r.verdict = Verdict::of(false, Status::exact, "a closed-loop root at " + *at + " (exact): on the unit circle");
    return r;
  }
  const detail::Winding w = detail::schur_by_winding(dl, rational(0));
  if (w.outcome == Outcome::undecided) {
    r.verdict = {Outcome::undecided, Status::failed, w.why};
    return r;
  }
  r.verdict = Verdict::of(w.outcome == Outcome::holds, Status::certified,
                          "argument principle on the unit circle in ball arithmetic (long-delay path, " +
                              std::to_string(w.boxes) + " arcs): " + std::to_string(w.inside) + " of the " +
                              std::to_string(dl.degree()) + " roots in |z| < 1");
  return r;
}

}  // namespace

std::optional<Polynomial<rational>> exact_characteristic(const Loop& loop) {
  if (loop.H_gain) throw InputError("stability::exact_characteristic: H_gain is for max_gain");
  const Prepared p = prepare(loop);
  if (!p.exact) return std::nullopt;
  return to_qp(characteristic(p.wall, sample_exact(p.num, p.den, loop.T), loop.delay).c0);
}

std::optional<std::pair<Polynomial<rational>, Polynomial<rational>>> exact_family(const Loop& loop) {
  if (!loop.H_gain) throw InputError("stability::exact_family: H_gain is missing");
  const Prepared p = prepare(loop);
  if (!p.exact) return std::nullopt;
  const Characteristic<rational> ch = characteristic(p.wall, sample_exact(p.num, p.den, loop.T), loop.delay);
  return std::make_pair(to_qp(ch.c0), to_qp(ch.c1));
}

StabilityResult decide(const Loop& loop) {
  if (loop.H_gain) throw InputError("stability::decide: H_gain is for max_gain");
  const Prepared p = prepare(loop);
  const Plan pl = plan(p, loop, false);
  StabilityResult r;
  r.exact_data = p.exact;
  if (!p.exact) {
    if (const auto at = dc_root(p)) {
      r.verdict = Verdict::of(false, Status::exact, "a closed-loop root at " + *at + ": on the unit circle");
      r.path = pl.long_delay ? "long_delay" : "polynomial";
      r.plan = pl.why;
      r.degree = static_cast<int>(pl.degree);
      return r;
    }
  }
  if (pl.long_delay) {
    for (slong prec = 128; prec <= 2048; prec *= 2) {
      flint::BallPrecision scope(prec);
      r = p.exact ? decide_long(p, loop, sample_exact(p.num, p.den, loop.T), prec)
                  : decide_long(p, loop, sample_ball(p.num, p.den, loop.T, p.r), prec);
      if (r.verdict.decided()) break;
    }
    r.path = "long_delay";
    r.plan = pl.why;
    // undecided (a root on or near the circle) and small enough: the polynomial path decides exactly
    // where the data are exact (a root on the circle is then "not stable"), by root enclosures otherwise
    if (r.verdict.decided() || pl.degree > limits::model_degree || loop.path == LoopPath::long_delay) return r;
  }
  r.path = "polynomial";
  r.plan = pl.long_delay ? pl.why + "; undecided there, so the polynomial path" : pl.why;
  if (p.exact) {
    flint::ball_prec = 256;
    const Sampled<rational> s = sample_exact(p.num, p.den, loop.T);
    const QP c = to_qp(characteristic(p.wall, s, loop.delay).c0);
    r.degree = c.degree();
    const RootTest t = exact_root_test(c);
    r.verdict = Verdict::of(t.outcome == Outcome::holds, Status::exact,
                            t.outcome == Outcome::holds ? "Schur-Cohn on the exact characteristic polynomial"
                                                        : "Schur-Cohn: a root on or outside the unit circle");
    r.spectral_radius = t.radius;
    return r;
  }
  for (slong prec = 128; prec <= 8192; prec *= 2) {
    flint::ball_prec = prec;
    const Sampled<Ball> s = sample_ball(p.num, p.den, loop.T, p.r);
    const Vec<Ball> c = characteristic(p.wall, s, loop.delay).c0;
    r.degree = static_cast<int>(c.size()) - 1;
    const RootTest t = root_test(c);
    r.spectral_radius = t.radius;
    r.precision_bits = prec;
    if (t.outcome != Outcome::undecided) {
      r.verdict = Verdict::of(t.outcome == Outcome::holds, Status::certified,
                              t.outcome == Outcome::holds ? "every certified root enclosure inside |z| < 1"
                                                          : "a certified root enclosure outside |z| <= 1");
      return r;
    }
  }
  r.verdict = {Outcome::undecided, Status::failed,
               "a root lies on the unit circle or too close to it to decide at 8192 bits"};
  return r;
}

// ---- max_gain: where a root meets the unit circle --------------------------------------------
namespace {

std::vector<QP> chebyshev(int M, bool second_kind) {  // T_0..T_M or U_0..U_M
  std::vector<QP> v{QP(rational(1)), second_kind ? QP{rational(0), rational(2)} : QP{rational(0), rational(1)}};
  const QP two_x{rational(0), rational(2)};
  while (static_cast<int>(v.size()) <= M) v.push_back(two_x * v[v.size() - 1] - v[v.size() - 2]);
  return v;
}

template <class C>
Vec<C> scaled(const QP& p, const C& k) {
  Vec<C> v;
  for (const rational& c : p.coeffs()) v.push_back(C(c) * k);
  return v;
}

/// Q, R, S of a point e^{j theta}, x = cos(theta): Im(c0 conj c1) = sin(theta) Q(x),
/// Re(c0 conj c1) = R(x), |c1|^2 = S(x) (c0, c1 real polynomials).
template <class C>
struct CirclePolys {
  Vec<C> Q, R, S;
};

template <class C>
CirclePolys<C> circle_polys(const Vec<C>& a, const Vec<C>& b) {
  const int da = static_cast<int>(a.size()) - 1, db = static_cast<int>(b.size()) - 1, M = std::max(da, db);
  auto g = [&](int m) {  // sum_i a_i b_{i-m}: the coefficient of e^{j m theta}
    C r(rational(0));
    for (int i = std::max(0, m); i <= std::min(da, db + m); ++i) r = r + a[static_cast<size_t>(i)] * b[static_cast<size_t>(i - m)];
    return r;
  };
  auto h = [&](int m) {
    C r(rational(0));
    for (int k = 0; k + m <= db; ++k) r = r + b[static_cast<size_t>(k)] * b[static_cast<size_t>(k + m)];
    return r;
  };
  const std::vector<QP> T = chebyshev(M, false), U = chebyshev(M, true);
  CirclePolys<C> c;
  c.R = Vec<C>{g(0)};
  c.S = Vec<C>{h(0)};
  for (int m = 1; m <= M; ++m) {
    c.Q = add(c.Q, scaled(U[static_cast<size_t>(m - 1)], g(m) - g(-m)));
    c.R = add(c.R, scaled(T[static_cast<size_t>(m)], g(m) + g(-m)));
    if (m <= db) c.S = add(c.S, scaled(T[static_cast<size_t>(m)], C(rational(2)) * h(m)));
  }
  return c;
}

/// The Q whose roots in (-1, 1) are sought, as balls: exact data are made square-free and freed
/// of the roots x = +-1 (z = +-1 are handled on their own) first, so isolation cannot stall.
std::optional<Vec<Ball>> roots_poly(const Vec<rational>& Q) {
  QP q = squarefree(QP(Q));
  if (q.is_zero()) return std::nullopt;
  for (const rational& x : {rational(1), rational(-1)})
    while (q.degree() > 0 && q(x) == 0) q = divmod(q, QP{-x, rational(1)}).first;
  return lift<Ball>(q);
}
std::optional<Vec<Ball>> roots_poly(const Vec<Ball>& Q) { return Q; }

Vec<Ball> lift_balls(const Vec<rational>& p) {
  Vec<Ball> v;
  for (const rational& c : p) v.emplace_back(c);
  return v;
}
Vec<Ball> lift_balls(const Vec<Ball>& p) { return p; }

Vec<Ball> derivative(const Vec<Ball>& p) {
  Vec<Ball> d;
  for (size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * Ball(rational(static_cast<long>(i))));
  return d;
}

Ball hull(const rational& lo, const rational& hi) {
  Ball r;
  arb_union(r.get(), Ball(lo).get(), Ball(hi).get(), flint::ball_prec);
  return r;
}

/// Interval Newton on a ball holding one simple root: x <- X cap (m - Q(m)/Q'(X)).
Ball newton(const Vec<Ball>& Q, const Vec<Ball>& dQ, Ball X) {
  for (int it = 0; it < 200; ++it) {
    Ball m;
    arb_get_mid_arb(m.get(), X.get());
    const Ball N = m - eval(Q, m) / eval(dQ, X);
    Ball Y;
    if (!arb_intersection(Y.get(), X.get(), N.get(), flint::ball_prec)) break;
    const bool progress = mag_cmp(arb_radref(Y.get()), arb_radref(X.get())) < 0;
    X = Y;
    if (!progress) break;
  }
  return X;
}

int sign_of(const Ball& b) { return arb_is_positive(b.get()) ? 1 : arb_is_negative(b.get()) ? -1 : 0; }

/// The roots of Q in (-1, 1) from all its complex roots (acb_poly_find_roots, every one isolated;
/// the real ones proven real by acb_poly_validate_real_roots); nullopt when that does not succeed.
std::optional<std::vector<Ball>> real_roots_from_complex(Vec<Ball> Q, const Vec<Ball>& dQ) {
  while (!Q.empty() && arb_is_zero(Q.back().get())) Q.pop_back();  // exact zeros on top (c1(0) = 0, ...)
  const slong deg = static_cast<slong>(Q.size()) - 1;
  if (deg < 1 || arb_contains_zero(Q.back().get())) return std::nullopt;
  acb_poly_t p;
  acb_poly_init(p);
  for (slong i = 0; i <= deg; ++i) {
    acb_t z;
    acb_init(z);
    acb_set_arb(z, Q[static_cast<size_t>(i)].get());
    acb_poly_set_coeff_acb(p, i, z);
    acb_clear(z);
  }
  acb_ptr roots = _acb_vec_init(deg);
  std::optional<std::vector<Ball>> out;
  if (acb_poly_find_roots(roots, p, nullptr, 0, flint::ball_prec) == deg && acb_poly_validate_real_roots(roots, p, flint::ball_prec)) {
    out.emplace();
    const Ball one(rational(1)), minus_one(rational(-1));
    for (slong i = 0; i < deg && out; ++i) {
      if (!arb_contains_zero(acb_imagref(roots + i))) continue;  // a non-real root
      const Ball X(acb_realref(roots + i));
      if (arb_gt(X.get(), one.get()) || arb_lt(X.get(), minus_one.get())) continue;
      if (arb_lt(X.get(), one.get()) && arb_gt(X.get(), minus_one.get())) out->push_back(newton(Q, dQ, X));
      else out.reset();  // a real root not separated from x = +-1
    }
  }
  _acb_vec_clear(roots, deg);
  acb_poly_clear(p);
  return out;
}

/// Every root of Q in (-1, 1): from the complex roots when they are all isolated, else by
/// bisection (centered form, monotonicity, sign change); each refined by interval Newton.
/// nullopt when some piece cannot be decided at this precision.
std::optional<std::vector<Ball>> roots_in_unit_interval(const Vec<Ball>& Q) {
  const Vec<Ball> dQ = derivative(Q);
  if (auto r = real_roots_from_complex(Q, dQ)) return r;
  struct Piece { rational lo, hi; int depth; };
  std::vector<Piece> todo{{rational(-1), rational(1), 0}};
  std::vector<Ball> out;
  // a budget of pieces besides the depth: where the balls stay wide (coefficients spanning 10^600:
  // m = 1e-300 under a delay of 100) every piece splits, and depth 80 alone allowed 2^80 of them
  long pieces = 0;
  while (!todo.empty()) {
    if (++pieces > 200000) return std::nullopt;
    const Piece pc = todo.back();
    todo.pop_back();
    const rational mid = (pc.lo + pc.hi) / 2;
    const Ball X = hull(pc.lo, pc.hi), dX = eval(dQ, X);
    const Ball around = eval(Q, Ball(mid)) + dX * (X - Ball(mid));
    if (!arb_contains_zero(around.get())) continue;
    if (!arb_contains_zero(dX.get())) {  // monotone: a root iff the ends differ in sign
      const int s_lo = sign_of(eval(Q, Ball(pc.lo))), s_hi = sign_of(eval(Q, Ball(pc.hi)));
      if (s_lo != 0 && s_hi != 0) {
        if (s_lo != s_hi) out.push_back(newton(Q, dQ, X));
        continue;
      }
    }
    if (pc.depth >= 80) return std::nullopt;
    todo.push_back({pc.lo, mid, pc.depth + 1});
    todo.push_back({mid, pc.hi, pc.depth + 1});
  }
  return out;
}

struct Candidate {
  Ball K;
  std::string where;
  Ball theta;
  std::optional<rational> exact;
};

std::optional<rational> exact_quotient(const rational& a, const rational& b) { return -a / b; }
std::optional<rational> exact_quotient(const Ball&, const Ball&) { return std::nullopt; }
Ball to_ball(const rational& q) { return Ball(q); }
Ball to_ball(const Ball& b) { return b; }

/// The crossing at z = +-1: K = -c0(z)/c1(z). Returns false when it cannot be decided;
/// `fixed` is set when z is a root for every K.
template <class C>
bool edge_candidate(const C& v0, const C& v1, bool at_one, std::vector<Candidate>& out, bool& fixed) {
  if (is_zero(v1)) {
    fixed = fixed || is_zero(v0);
    return true;
  }
  if (arb_contains_zero(to_ball(v1).get())) return false;
  Candidate c{to_ball(v0) / to_ball(v1), at_one ? "z = 1" : "z = -1", Ball(rational(0)), exact_quotient(v0, v1)};
  c.K = -c.K;
  if (!at_one) arb_const_pi(c.theta.get(), flint::ball_prec);
  out.push_back(c);
  return true;
}

RootTest test_at(const Characteristic<rational>& ch, const rational& K) {
  return exact_root_test(QP(ch.c0) + QP(ch.c1) * QP(K));
}
RootTest test_at(const Characteristic<Ball>& ch, const rational& K) {
  return root_test(add(ch.c0, mul(ch.c1, Vec<Ball>{Ball(K)})));
}

/// The candidates K > 0 at which a root is on the unit circle; nullopt: undecided here.
/// The candidates with K > 0 (an exact K = 0, a crossing at the start, is dropped); nullopt when one
/// is not separated from 0.
std::optional<std::vector<Candidate>> positive_only(const std::vector<Candidate>& all, std::string& why) {
  std::vector<Candidate> positive;
  for (const Candidate& c : all) {
    if (c.exact && *c.exact == 0) continue;
    if (arb_is_positive(c.K.get())) positive.push_back(c);
    else if (!arb_is_nonpositive(c.K.get())) {
      why = "a crossing gain not separated from 0";
      return std::nullopt;
    }
  }
  return positive;
}

/// sup K from the candidate crossings (K > 0) and the stability test at one K below them.
template <class C, class Test>
MaxGain conclude(const std::optional<std::vector<Candidate>>& cands, bool fixed, const std::string& why, Test test_at,
                 const std::string& K);

template <class C>
std::optional<std::vector<Candidate>> crossings(const Characteristic<C>& ch, bool& fixed, std::string& why) {
  std::vector<Candidate> all;
  if (!edge_candidate(ch.at1_0, ch.at1_1, true, all, fixed) || !edge_candidate(ch.atm1_0, ch.atm1_1, false, all, fixed)) {
    why = "c1(+-1) not separated from 0";
    return std::nullopt;
  }
  const CirclePolys<C> cp = circle_polys(ch.c0, ch.c1);
  const std::optional<Vec<Ball>> Q = roots_poly(cp.Q);
  if (!Q) {
    why = "c0/c1 is real on the whole unit circle (degenerate loop)";
    return std::nullopt;
  }
  const auto xs = roots_in_unit_interval(*Q);
  if (!xs) {
    why = "the crossing frequencies could not be isolated (a double root, or one at theta = 0 or pi)";
    return std::nullopt;
  }
  const Vec<Ball> R = lift_balls(cp.R), S = lift_balls(cp.S);
  for (const Ball& x : *xs) {
    const Ball s = eval(S, x);
    if (arb_contains_zero(s.get())) {
      why = "c1 vanishes near a crossing on the circle";
      return std::nullopt;
    }
    Candidate c{-(eval(R, x) / s), "complex pair", Ball(), std::nullopt};
    arb_acos(c.theta.get(), x.get(), flint::ball_prec);
    all.push_back(c);
  }
  return positive_only(all, why);
}

/// The long-delay path's candidates: the crossings at z = +-1 as above, and those in (0, pi) by
/// the best-first search of long_delay.hpp (only the ones that can be the smallest).
template <class C>
std::optional<std::vector<Candidate>> crossings_long(const Edges<C>& e, const detail::DelayedLoop& dl, bool& fixed,
                                                     std::string& why) {
  std::vector<Candidate> all;
  if (!edge_candidate(e.at1_0, e.at1_1, true, all, fixed) || !edge_candidate(e.atm1_0, e.atm1_1, false, all, fixed)) {
    why = "c1(+-1) not separated from 0";
    return std::nullopt;
  }
  std::optional<std::vector<Candidate>> positive = positive_only(all, why);
  if (!positive) return std::nullopt;
  const auto search = detail::smallest_crossings(dl, why);
  if (!search) return std::nullopt;
  for (const auto& c : search->crossings) positive->push_back({c.K, "complex pair", c.theta, std::nullopt});
  return positive;
}

template <class C>
MaxGain attempt(const Characteristic<C>& ch, const std::string& K) {
  MaxGain m;
  bool fixed = false;
  const auto cands = crossings(ch, fixed, m.note);
  return conclude<C>(cands, fixed, m.note, [&](const rational& k) { return test_at(ch, k); }, K);
}

template <class C>
MaxGain attempt_long(const Edges<C>& e, const detail::DelayedLoop& dl, const std::string& K) {
  MaxGain m;
  bool fixed = false;
  const auto cands = crossings_long(e, dl, fixed, m.note);
  return conclude<C>(cands, fixed, m.note, [&](const rational& k) {
    const detail::Winding w = detail::schur_by_winding(dl, k);
    return RootTest{w.outcome, std::nullopt};
  }, K);
}
template <class C, class Test>
MaxGain conclude(const std::optional<std::vector<Candidate>>& cands, bool fixed, const std::string& why, Test test_at,
                 const std::string& K) {
  MaxGain m;
  m.note = why;
  if (fixed) {
    m.outcome = Outcome::fails;
    m.status = std::is_same_v<C, rational> ? Status::exact : Status::certified;
    m.note = "a closed-loop root stays at z = +-1 for every " + K + ": unstable for every " + K;
    return m;
  }
  if (!cands) return m;
  rational lo = 0, hi = 0;
  for (const Candidate& c : *cands) {
    const Enclosure<rational> e = bounds(c.K.get());
    if (&c == &cands->front() || e.lo < lo) lo = e.lo;
    if (&c == &cands->front() || e.hi < hi) hi = e.hi;
  }
  // a short rational in (0, lo): any K below the first crossing tells the sign of the whole interval
  const rational probe = cands->empty() ? rational(1) : parse_rational(decimal_outward(lo / 2, 3, -1));
  const RootTest t = test_at(probe);
  m.status = std::is_same_v<C, rational> ? Status::exact : Status::certified;
  if (t.outcome == Outcome::undecided) {
    m.status = Status::failed;
    m.note = "stability at " + K + " = " + probe.str() + " undecided";
    return m;
  }
  if (t.outcome == Outcome::fails) {
    m.outcome = Outcome::fails;
    m.note = "unstable at " + K + " = " + probe.str() +
             " and no root meets the unit circle in between: unstable for every small " + K + " > 0";
    return m;
  }
  m.outcome = Outcome::holds;
  if (cands->empty()) {
    m.infinite = true;
    m.note = "stable at " + K + " = 1 and no root meets the unit circle for any " + K + " > 0";
    return m;
  }
  m.enclosure = {lo, hi};
  std::vector<const Candidate*> at_min;
  for (const Candidate& c : *cands)
    if (bounds(c.K.get()).lo <= hi) at_min.push_back(&c);
  if (at_min.size() == 1) {
    m.crossing = at_min[0]->where;
    m.theta = bounds(at_min[0]->theta.get());
    if (at_min[0]->exact) m.exact = *at_min[0]->exact;
  } else {
    m.crossing = "not separated";
  }
  if (!m.exact) m.status = Status::certified;
  m.note = "stable at " + K + " = " + probe.str() + "; the first root on the unit circle is at the supremum";
  return m;
}

bool narrow_enough(const MaxGain& m, int digits) {
  if (m.infinite || m.exact || m.outcome != Outcome::holds) return true;
  return m.crossing != "not separated" && (m.enclosure.hi - m.enclosure.lo) * pow10(digits + 1) <= m.enclosure.lo;
}

}  // namespace

std::optional<GridGain> max_gain_grid(const Loop& loop, long N) {
  if (!loop.H_gain) throw InputError("max_gain_grid: H_gain (the part of H multiplied by the gain) is missing");
  if (N < 2 || N > 100000000) throw InputError("max_gain_grid: N must be in [2, 1e8]");
  const Prepared p = prepare(loop);
  flint::BallPrecision scope(128);
  const detail::DelayedLoop dl = p.exact ? delayed_loop(p.wall, sample_exact(p.num, p.den, loop.T), loop.delay)
                                         : delayed_loop(p.wall, sample_ball(p.num, p.den, loop.T, p.r), loop.delay);
  auto doubles = [](const Vec<Ball>& v) {
    std::vector<double> d;
    for (const Ball& b : v) d.push_back(b.to_double());
    return d;
  };
  const std::vector<double> P = doubles(dl.P), Q0 = doubles(dl.Q0), Q1 = doubles(dl.Q1);
  auto poly = [](const std::vector<double>& c, std::complex<double> z) {
    std::complex<double> r = 0;
    for (size_t i = c.size(); i-- > 0;) r = r * z + c[i];
    return r;
  };
  const double pi = 3.14159265358979323846;
  auto gain = [&](double th) {
    const std::complex<double> z = std::polar(1.0, th);
    return -(std::polar(1.0, static_cast<double>(loop.delay) * th) * poly(P, z) + poly(Q0, z)) / poly(Q1, z);
  };
  std::optional<GridGain> best;
  auto consider = [&](double K, double th) {
    if (K > 0 && std::isfinite(K) && (!best || K < best->K)) best = GridGain{K, th / to_real<double>(loop.T)};
  };
  // z = 1 (theta = 0, where Im K = 0 always): K = -c0(1)/c1(1) when c0(1) is not a structural zero
  double size = 0;
  for (double x : P) size += std::abs(x);
  for (double x : Q0) size += std::abs(x);
  const std::complex<double> at_one = gain(0);
  if (std::abs(poly(P, 1.0) + poly(Q0, 1.0)) > 1e-12 * size) consider(at_one.real(), 0);
  std::complex<double> prev = gain(pi / static_cast<double>(N));
  for (long i = 2; i <= N; ++i) {
    const double th = pi * static_cast<double>(i) / static_cast<double>(N);
    const std::complex<double> k = gain(i == N ? pi : th);
    if ((k.imag() > 0) != (prev.imag() > 0) && std::isfinite(k.imag()) && std::isfinite(prev.imag())) {
      const double s = prev.imag() / (prev.imag() - k.imag());  // linear interpolation of the zero of Im K
      consider(prev.real() + s * (k.real() - prev.real()), th - (1 - s) * pi / static_cast<double>(N));
    }
    prev = k;
  }
  return best;
}

Loop mass_damper_wall(const rational& m, const rational& b, const rational& B, const rational& T, int n) {
  if (m < 0 || T <= 0 || (m == 0 && b == 0))
    throw InputError("mass_damper_wall: need m >= 0, T > 0 and m, b not both 0");
  Loop loop;
  loop.T = T;
  loop.delay = n;
  loop.plant = tf(QP(rational(1)), QP{rational(0), b, m});
  loop.H = tf(QP{-B, B}, QP{rational(0), T}, T);  // B (z - 1)/(T z)
  loop.H_gain = tf(QP(rational(1)), QP(rational(1)), T);
  return loop;
}

CirclePolynomials circle_polynomials(const Polynomial<rational>& c0, const Polynomial<rational>& c1) {
  if (c0.is_zero() || c1.is_zero()) throw InputError("circle_polynomials: c0 and c1 must not be zero");
  const CirclePolys<rational> c = circle_polys<rational>(c0.coeffs(), c1.coeffs());
  return {QP(c.Q), QP(c.R), QP(c.S)};
}

MaxGain max_gain(const Loop& loop, int digits) { return max_gain(loop, digits, "K"); }

MaxGain max_gain(const Loop& loop, int digits, const std::string& gain_name) {
  if (!loop.H_gain) throw InputError("max_gain: H_gain (the part of H multiplied by the gain) is missing");
  if (loop.H_gain->H.is_zero()) throw InputError("the gain does not appear in H");
  if (digits < 1 || digits > 1000) throw InputError("--digits must be in [1, 1000], got " + std::to_string(digits));
  const Prepared p = prepare(loop);
  Plan pl = plan(p, loop, true);
  const slong first = std::max<slong>(128, 4 * digits + 64);
  MaxGain last;
  // the polynomial path's ladder to 64x the first precision, or 8x beyond degree 50: there each
  // rung's root finding costs seconds at thousands of bits, and a case undecided at 8x (a plant pole
  // at -1e300 under a delay of 100: coefficients spanning 10^600) ran > 400 s before it said so
  const auto top = [&] { return (pl.long_delay || pl.degree > 50 ? 8 : 64) * first; };
  for (slong prec = first; prec <= top(); prec *= 2) {
    // the long-delay path undecided at 8x its first precision, and the polynomial small enough: it takes over
    if (pl.long_delay && prec == 8 * first && pl.degree <= limits::model_degree && loop.path != LoopPath::long_delay) {
      pl.long_delay = false;
      pl.why += "; undecided there, so the polynomial path";
      prec = first;
    }
    flint::BallPrecision scope(prec);
    if (pl.long_delay) {
      if (p.exact) {
        const Sampled<rational> s = sample_exact(p.num, p.den, loop.T);
        last = attempt_long(edges(p.wall, s, loop.delay), delayed_loop(p.wall, s, loop.delay), gain_name);
      } else {
        const Sampled<Ball> s = sample_ball(p.num, p.den, loop.T, p.r);
        last = attempt_long(edges(p.wall, s, loop.delay), delayed_loop(p.wall, s, loop.delay), gain_name);
      }
    } else {
      last = p.exact ? attempt(characteristic(p.wall, sample_exact(p.num, p.den, loop.T), loop.delay), gain_name)
                     : attempt(characteristic(p.wall, sample_ball(p.num, p.den, loop.T, p.r), loop.delay), gain_name);
    }
    last.precision_bits = prec;
    last.path = pl.long_delay ? "long_delay" : "polynomial";
    last.plan = pl.why;
    if (last.outcome != Outcome::undecided && narrow_enough(last, digits)) return last;
  }
  if (last.outcome == Outcome::holds)
    last.note += "; the enclosure stayed wider than 10^-" + std::to_string(digits) + " at " +
                 std::to_string(last.precision_bits) + " bits";
  return last;
}

}  // namespace hapstab::stability
