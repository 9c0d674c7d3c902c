// The long-delay path of the stability test (stability/long_delay.hpp): the argument principle
// and the D-decomposition crossings of c(z, K) = z^n P + Q0 + K Q1 on the unit circle, in Arb
// balls, without the polynomial of degree n + m.
#include "hapstab/stability/long_delay.hpp"
#include "hapstab/stability/sampled_loop.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>
#include <type_traits>
#include <cstdio>
#include <cstdlib>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/jet.hpp"

namespace hapstab::stability::detail {

using flint::Ball;
using flint::CBall;

namespace {

constexpr int max_level = 48;  // bisections below a first box before a piece is left undecided

/// theta = pi i / (M 2^level)
Ball theta_at(long i, int level, long M) {
  Ball t(i);
  arb_div_si(t.get(), t.get(), M, flint::ball_prec);
  arb_mul_2exp_si(t.get(), t.get(), -level);
  return t * Ball::pi();
}

template <class C>
std::vector<Ball> balls(const std::vector<C>& a) {
  std::vector<Ball> b;
  for (const C& x : a) b.emplace_back(x);
  if (b.empty()) b.emplace_back(0L);
  return b;
}

/// The Taylor coefficients of a(x) at x0, a(x) = sum b_k (x - x0)^k (Ruffini-Horner; exact for
/// rational coefficients).
template <class C>
std::vector<C> taylor_shift(std::vector<C> b, const C& x0) {
  const size_t d = b.size();
  for (size_t k = 0; k < d; ++k)
    for (size_t i = d - 1; i > k; --i) b[i - 1] = b[i - 1] + x0 * b[i];
  return b;
}

// ---- theta, and low-degree polynomials whose small values stay small ----------------------------
// A polynomial that vanishes at z = 1 (an integrator's (z - 1)^r, a damper's (z - 1)) is tiny near
// theta = 0 while its coefficients are not: Horner in z (or c) over a box there encloses it with an
// error of the coefficients' size, and nothing near theta = 0 could be decided. Each polynomial is
// therefore also kept in Taylor form at z = 1 (c = 1) and z = -1 (c = -1), evaluated in
// w = z - 1 = 2j sin(theta/2) e^{j theta/2} (t = 1 - c = 2 sin^2(theta/2)) near 0 and in
// w = z + 1 = 2 cos(theta/2) e^{j theta/2} (s = 1 + c = 2 cos^2(theta/2)) near pi.
constexpr double near_zero = 1.0, near_pi = 2.1;  // theta <= 1: the form at 1; theta >= 2.1: at -1

template <class S>
struct AngleT {
  jet::Jet<S> th, c, t, s;  // theta, cos(theta), 1 - cos(theta), 1 + cos(theta) as jets
  S s1, c1, sh, ch;         // sin, cos of theta and of theta/2
  double lo = 0, hi = 0;    // theta's ends, rounded outward (the choice of form only)
};
using Angle = AngleT<Ball>;
/// theta's jets from sin and cos of theta/2 (Ball: every point of the ball; Dint: of the interval)
template <class S>
AngleT<S> angle_from(const S& theta, const S& sh, const S& ch, double lo, double hi) {
  AngleT<S> a;
  a.sh = sh, a.ch = ch;
  a.s1 = S(2.0) * (sh * ch);
  a.c1 = S(1.0) - S(2.0) * (sh * sh);
  a.th = jet::variable(theta);
  a.c = {a.c1, -a.s1, -a.c1};
  a.t = {S(2.0) * (sh * sh), a.s1, a.c1};
  a.s = {S(2.0) * (ch * ch), -a.s1, -a.c1};
  a.lo = lo, a.hi = hi;
  return a;
}
Angle angle(const Ball& theta) {
  Ball sh, ch;
  flint::sin_cos(theta * Ball(0.5), sh, ch);
  return angle_from(theta, sh, ch, theta.to_double() - theta.radius(), theta.to_double() + theta.radius());
}

/// p(c) in the three forms.
template <class S>
struct CPolyT {
  std::vector<S> c, t, s;
};
using CPoly = CPolyT<Ball>;
template <class C>
CPoly cpoly(const std::vector<C>& a) {
  CPoly p;
  p.c = balls(a);
  std::vector<C> at1 = taylor_shift(a, C(1L));  // in (c - 1) = -t
  for (size_t k = 1; k < at1.size(); k += 2) at1[k] = C(0L) - at1[k];
  p.t = balls(at1);
  p.s = balls(taylor_shift(a, C(-1L)));  // in (c + 1) = s
  return p;
}
template <class S>
jet::Jet<S> eval(const CPolyT<S>& p, const AngleT<S>& a) {
  if (a.hi <= near_zero) return jet::horner(p.t, a.t);
  if (a.lo >= near_pi) return jet::horner(p.s, a.s);
  return jet::horner(p.c, a.c);
}

/// A ball's enclosure in double intervals (outward).
Dint to_dint(const Ball& b) {
  if (!b.finite()) return Dint::entire();
  const Enclosure<rational> e = b.bounds();
  const Dint d(Dint::from_rational(e.lo).lo, Dint::from_rational(e.hi).hi);
  return d.finite() ? d : Dint::entire();
}
std::vector<Dint> to_dint(const std::vector<Ball>& v) {
  std::vector<Dint> d;
  for (const Ball& x : v) d.push_back(to_dint(x));
  return d;
}
CPolyT<Dint> to_dint(const CPoly& p) { return {to_dint(p.c), to_dint(p.t), to_dint(p.s)}; }

/// p(z) (real coefficients) in the three forms, evaluated at z = e^{j theta}.
template <class S>
struct ZPolyT {
  std::vector<S> z, at1, atm1;
};
using ZPoly = ZPolyT<Ball>;
template <class C>
ZPoly zpoly(const std::vector<C>& a) {
  return {balls(a), balls(taylor_shift(a, C(1L))), balls(taylor_shift(a, C(-1L)))};
}
template <class S, class Z = std::conditional_t<std::is_same_v<S, Ball>, CBall, CDint>>
Z eval(const ZPolyT<S>& p, const AngleT<S>& a) {
  if (a.hi <= near_zero) return horner(p.at1, Z{-a.t.v, a.s1});  // z - 1 = (cos - 1) + j sin
  if (a.lo >= near_pi) return horner(p.atm1, Z{a.s.v, a.s1});    // z + 1 = (cos + 1) + j sin
  return horner(p.z, Z{a.c1, a.s1});
}
ZPolyT<Dint> to_dint(const ZPoly& p) { return {to_dint(p.z), to_dint(p.at1), to_dint(p.atm1)}; }

/// sin and cos of theta/2 and of n theta at theta = pi k/D or over [pi (k - 1)/D, pi (k + 1)/D]
/// (box), in double intervals (numeric/dinterval.hpp) by sin_cos_pi's exact integer reduction,
/// widened over a box by their Lipschitz bounds 1/2 and n times the half-width pi/D; theta's
/// angle with them. false when the integers overflow.
bool double_angle(long n, __int128 k, __int128 D, bool box, AngleT<Dint>& a, Dint& sn, Dint& cn) {
  __int128 nk = 0;
  Dint sh, ch;
  if (__builtin_mul_overflow(static_cast<__int128>(n), k, &nk) || !sin_cos_pi(k, 2 * D, sh, ch) || !sin_cos_pi(nk, D, sn, cn))
    return false;
  const Dint pi = dint_pi(), inv = Dint(1.0) / Dint::from_i128(D);
  Dint theta = Dint::from_i128(k) * inv * pi;
  if (box) {
    const double r = (inv * pi).hi, rn = (Dint(static_cast<double>(n)) * Dint(r)).hi;
    theta = theta.widened(r).clamp(0, pi.hi);
    sh = sh.widened(r / 2).clamp(-1, 1), ch = ch.widened(r / 2).clamp(-1, 1);
    sn = sn.widened(rn).clamp(-1, 1), cn = cn.widened(rn).clamp(-1, 1);
  }
  a = angle_from(theta, sh, ch, theta.lo, theta.hi);
  return true;
}

/// theta's angle over the arc pi [k - h, k + h]/D (h >= 1; theta's sine and cosine are not
/// needed), widened from its centre by the Lipschitz bounds as in double_angle. false when the
/// integers overflow.
bool arc_angle(__int128 k, __int128 D, long h, AngleT<Dint>& a) {
  Dint sh, ch;
  if (!sin_cos_pi(k, 2 * D, sh, ch)) return false;
  const Dint pi = dint_pi(), inv = Dint(1.0) / Dint::from_i128(D);
  const double r = (Dint(static_cast<double>(h)) * inv * pi).hi;
  const Dint theta = (Dint::from_i128(k) * inv * pi).widened(r).clamp(0, pi.hi);
  sh = sh.widened(r / 2).clamp(-1, 1), ch = ch.widened(r / 2).clamp(-1, 1);
  a = angle_from(theta, sh, ch, theta.lo, theta.hi);
  return true;
}

bool narrow_arg(const Ball& a) { return a.finite() && a.radius() < 0.25; }

}  // namespace

// ---- the argument principle --------------------------------------------------------------------
namespace {

/// The change of arg c over the arc pi [k - 1, k + 1]/D in double intervals, by the three cases
/// of schur_by_winding (each valid wherever its condition is proven on the arc); nullopt where
/// they cannot decide it (the arc then goes to Arb, which decides it or splits it).
class DoubleWinding {
 public:
  DoubleWinding(const ZPoly& P, const ZPoly& Q, long n) : P_(to_dint(P)), Q_(to_dint(Q)), n_(n) {}
  std::optional<Dint> change(long i, int level, long M) const {
    const __int128 D = static_cast<__int128>(M) << (level + 1), k = 2 * static_cast<__int128>(i) + 1;
    Values X, A, B;
    if (!at(k, D, true, X)) return std::nullopt;
    const Dint nP = norm(X.P), nQ = norm(X.Q);
    const CDint one{Dint(1.0), Dint(0.0)};
    const bool p_large = nQ.hi < nP.lo && !contains_zero(X.P), q_large = nP.hi < nQ.lo && !contains_zero(X.Q);
    if (!p_large && !q_large && contains_zero(X.znP + X.Q)) return std::nullopt;
    if (!at(k - 1, D, false, A) || !at(k + 1, D, false, B)) return std::nullopt;
    Dint change;
    if (p_large) {  // arg c = n theta + arg P + arg(1 + Q/(z^n P))
      const Dint turn = arg(B.P / A.P), rest = arg((one + B.Q / B.znP) / (one + A.Q / A.znP));
      if (!narrow(turn) || !narrow(rest)) return std::nullopt;
      change = Dint(2.0) * dint_pi() / Dint::from_i128(D) * Dint(static_cast<double>(n_)) + turn + rest;
    } else if (q_large) {  // arg c = arg Q + arg(1 + z^n P/Q)
      const Dint turn = arg(B.Q / A.Q), rest = arg((one + B.znP / B.Q) / (one + A.znP / A.Q));
      if (!narrow(turn) || !narrow(rest)) return std::nullopt;
      change = turn + rest;
    } else {  // c misses 0 on the arc
      change = arg((B.znP + B.Q) / (A.znP + A.Q));
      if (!narrow(change)) return std::nullopt;
    }
    return change;
  }

 private:
  struct Values {
    CDint znP, Q, P;
  };
  bool at(__int128 k, __int128 D, bool box, Values& v) const {
    AngleT<Dint> a;
    Dint sn, cn;
    if (!double_angle(n_, k, D, box, a, sn, cn)) return false;
    v.P = eval(P_, a);
    v.Q = eval(Q_, a);
    v.znP = CDint{cn, sn} * v.P;
    return true;
  }
  static bool narrow(const Dint& a) { return a.finite() && a.hi - a.lo < 0.5; }
  ZPolyT<Dint> P_, Q_;
  long n_;
};

Ball ball_of(const Dint& x) { return Ball::hull(exact_rational(x.lo), exact_rational(x.hi)); }

}  // namespace

Winding schur_by_winding(const DelayedLoop& L, const rational& K) {
  Winding w;
  const ZPoly P = L.exact ? zpoly(L.Pq) : zpoly(L.P);
  ZPoly Q;
  if (L.exact) {
    std::vector<rational> q(std::max(L.Q0q.size(), L.Q1q.size()), rational(0));
    for (size_t i = 0; i < L.Q0q.size(); ++i) q[i] += L.Q0q[i];
    for (size_t i = 0; i < L.Q1q.size(); ++i) q[i] += K * L.Q1q[i];
    Q = zpoly(q);
  } else {
    std::vector<Ball> q(std::max(L.Q0.size(), L.Q1.size()), Ball(0L));
    for (size_t i = 0; i < L.Q0.size(); ++i) q[i] += L.Q0[i];
    for (size_t i = 0; i < L.Q1.size(); ++i) q[i] += Ball(K) * L.Q1[i];
    Q = zpoly(q);
  }
  struct Values {
    CBall znP, Q, P;
  };
  auto values = [&](const Ball& theta) {
    const Angle a = angle(theta);
    const CBall p = eval(P, a);
    return Values{flint::unit(theta * L.n) * p, eval(Q, a), p};
  };
  const long M = 64;
  Ball total(0L);
  Dint total_d(0.0);  // the changes decided in double intervals
  const std::optional<DoubleWinding> dbl = double_pruning ? std::optional<DoubleWinding>(std::in_place, P, Q, L.n) : std::nullopt;
  struct Piece {
    long i;
    int level;
  };
  for (long first = 0; first < M; ++first) {
    std::vector<Piece> stack{{first, 0}};
    while (!stack.empty()) {
      const Piece pc = stack.back();
      stack.pop_back();
      ++w.boxes;
      if (dbl) {
        if (const std::optional<Dint> change = dbl->change(pc.i, pc.level, M)) {
          total_d += *change;
          ++w.double_boxes;
          continue;
        }
      }
      const Ball a = theta_at(pc.i, pc.level, M), b = theta_at(pc.i + 1, pc.level, M);
      const Values X = values(flint::hull(a, b));
      const Ball nP = flint::norm(X.P), nQ = flint::norm(X.Q);
      Ball change;
      bool ok = false;
      const CBall one{Ball(1L), Ball(0L)};
      if (nQ.below(nP) && !flint::contains_zero(X.P)) {
        // |Q| < |P| on the box: arg c = n theta + arg P + arg(1 + Q/(z^n P)), the last in (-pi/2, pi/2)
        const Values A = values(a), B = values(b);
        const Ball turn = flint::arg(B.P / A.P);
        const Ball rest = flint::arg((one + B.Q / B.znP) / (one + A.Q / A.znP));
        ok = narrow_arg(turn) && narrow_arg(rest);
        if (ok) change = (b - a) * L.n + turn + rest;
      } else if (nP.below(nQ) && !flint::contains_zero(X.Q)) {
        // |z^n P| < |Q|: arg c = arg Q + arg(1 + z^n P/Q)
        const Values A = values(a), B = values(b);
        const Ball turn = flint::arg(B.Q / A.Q);
        const Ball rest = flint::arg((one + B.znP / B.Q) / (one + A.znP / A.Q));
        ok = narrow_arg(turn) && narrow_arg(rest);
        if (ok) change = turn + rest;
      } else if (!flint::contains_zero(X.znP + X.Q)) {  // c misses 0 on the box: its change is below pi
        const Values A = values(a), B = values(b);
        change = flint::arg((B.znP + B.Q) / (A.znP + A.Q));
        ok = narrow_arg(change);
      }
      if (ok) {
        total += change;
        continue;
      }
      if (pc.level >= max_level || w.boxes > 64 * (4 * L.n + 64) + 100000) {
        w.why = "a zero of the characteristic polynomial on or too near the unit circle near wT = " +
                std::to_string(a.to_double()) + " (not decided at " + std::to_string(flint::ball_prec) + " bits)";
        return w;
      }
      stack.push_back({2 * pc.i + 1, pc.level + 1});
      stack.push_back({2 * pc.i, pc.level + 1});
    }
  }
  // the count is (1/pi) times the change over [0, pi]: an integer, read off the ball
  if (!total_d.finite()) {
    w.why = "the winding number's double-interval sum overflowed";
    return w;
  }
  const Ball count = (total + ball_of(total_d)) / Ball::pi();
  const double mid = count.to_double();
  const long k = std::lround(mid);
  if (!(count.radius() < 0.25 && std::abs(mid - static_cast<double>(k)) < 0.25)) {
    w.why = "the winding number was not resolved to an integer at " + std::to_string(flint::ball_prec) + " bits";
    return w;
  }
  w.inside = k;
  w.outcome = k == L.degree() ? Outcome::holds : Outcome::fails;
  return w;
}

// ---- the crossing gains ---------------------------------------------------------------------------
namespace {

/// With U = P conj(Q1) = sum_k u_k e^{j k theta} and V = Q0 conj(Q1) likewise, on the circle
///   Im(c0 conj c1) / sin(theta) = q(theta) = K_n(theta) Re U + cos(n theta) Im U/sin(theta) + Im V/sin(theta),
///   Re(c0 conj c1) = cos(n theta) Re U - sin(n theta) sin(theta) Im U/sin(theta) + Re V,
/// and Re U = sum u_k T_|k|(c), Im U/sin(theta) = sum sgn(k) u_k U_{|k|-1}(c) (Chebyshev), likewise V,
/// |Q1|^2 = sum_k h_k T_|k|(c): five polynomials in c of the loop's own low degree.
struct CrossingForm {
  long n = 0;
  CPoly RU, SU, RV, SV, H1;
  CPoly PP, QQ;                       // |P|^2 and |Q0|^2 on the circle: the gain floor's moduli
  Ball q0, qpi;                       // q(0) = n RU(1) + SU(1) + SV(1), q(pi) = (-1)^(n+1) n RU(-1) + (-1)^n SU(-1) + SV(-1)
  bool q0_zero = false, qpi_zero = false;  // exactly 0 (exact data)
};

template <class C>
std::vector<C> correlation(const std::vector<C>& a, const std::vector<C>& b, long& low) {  // sum_{i-l=k} a_i b_l
  low = -static_cast<long>(b.size()) + 1;
  std::vector<C> r(a.size() + b.size() - 1, C(0L));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t l = 0; l < b.size(); ++l) r[i + b.size() - 1 - l] = r[i + b.size() - 1 - l] + a[i] * b[l];
  return r;
}

/// sum_k w_k T_|k|(c) and sum_k sgn(k) w_k U_{|k|-1}(c) in monomials of c.
template <class C>
void chebyshev_sums(const std::vector<C>& w, long low, std::vector<C>& re, std::vector<C>& im_over_sin) {
  long M = 0;
  for (size_t i = 0; i < w.size(); ++i) M = std::max(M, std::labs(low + static_cast<long>(i)));
  std::vector<std::vector<C>> T{{C(1L)}, {C(0L), C(1L)}}, U{{C(1L)}, {C(0L), C(2L)}};
  for (long m = 2; m <= M; ++m)
    for (auto* tab : {&T, &U}) {
      const auto& a = (*tab)[static_cast<size_t>(m - 1)];
      const auto& b = (*tab)[static_cast<size_t>(m - 2)];
      std::vector<C> c(static_cast<size_t>(m) + 1, C(0L));
      for (size_t i = 0; i < a.size(); ++i) c[i + 1] = c[i + 1] + C(2L) * a[i];
      for (size_t i = 0; i < b.size(); ++i) c[i] = c[i] - b[i];
      tab->push_back(std::move(c));
    }
  re.assign(static_cast<size_t>(M) + 1, C(0L));
  im_over_sin.assign(static_cast<size_t>(std::max(M, 1L)), C(0L));
  for (size_t i = 0; i < w.size(); ++i) {
    const long k = low + static_cast<long>(i), m = std::labs(k);
    const auto& t = T[static_cast<size_t>(m)];
    for (size_t j = 0; j < t.size(); ++j) re[j] = re[j] + w[i] * t[j];
    if (m == 0) continue;
    const auto& u = U[static_cast<size_t>(m - 1)];
    for (size_t j = 0; j < u.size(); ++j) im_over_sin[j] = k > 0 ? im_over_sin[j] + w[i] * u[j] : im_over_sin[j] - w[i] * u[j];
  }
}

template <class C>
C horner_at(const std::vector<C>& p, const C& x) {
  C r(0L);
  for (size_t i = p.size(); i-- > 0;) r = r * x + p[i];
  return r;
}

/// The seven polynomials in c = cos(theta) of the crossing search (sampled_loop.hpp's
/// DelayCirclePolynomials, claims ext.stability.crossing_delay and crossing_floor).
template <class C>
struct CirclePolys {
  std::vector<C> RU, SU, RV, SV, H1, PP, QQ;
};
template <class C>
CirclePolys<C> circle_polys(const std::vector<C>& P, const std::vector<C>& Q0, const std::vector<C>& Q1) {
  CirclePolys<C> r;
  std::vector<C> unused;
  const std::vector<C> Q0s = Q0.empty() ? std::vector<C>{C(0L)} : Q0;
  auto sums = [&](const std::vector<C>& a, const std::vector<C>& b, std::vector<C>& re, std::vector<C>& im) {
    long low = 0;
    const std::vector<C> w = correlation(a, b, low);
    chebyshev_sums(w, low, re, im);
  };
  sums(P, Q1, r.RU, r.SU);
  sums(Q0s, Q1, r.RV, r.SV);
  sums(Q1, Q1, r.H1, unused);
  sums(P, P, r.PP, unused);
  sums(Q0s, Q0s, r.QQ, unused);
  return r;
}

template <class C>
CrossingForm crossing_form(long n, const std::vector<C>& P, const std::vector<C>& Q0, const std::vector<C>& Q1) {
  CrossingForm f;
  f.n = n;
  const CirclePolys<C> c = circle_polys(P, Q0, Q1);
  f.RU = cpoly(c.RU), f.SU = cpoly(c.SU), f.RV = cpoly(c.RV), f.SV = cpoly(c.SV), f.H1 = cpoly(c.H1);
  f.PP = cpoly(c.PP), f.QQ = cpoly(c.QQ);
  const C one(1L), mone(-1L), nn(n);
  const C q0 = nn * horner_at(c.RU, one) + horner_at(c.SU, one) + horner_at(c.SV, one);
  const C sign = n % 2 == 0 ? one : mone;
  const C qpi = C(0L) - sign * nn * horner_at(c.RU, mone) + sign * horner_at(c.SU, mone) + horner_at(c.SV, mone);
  f.q0 = Ball(q0), f.qpi = Ball(qpi);
  if constexpr (std::is_same_v<C, rational>) f.q0_zero = q0 == 0, f.qpi_zero = qpi == 0;
  return f;
}

template <class S>
struct CrossingValuesT {
  jet::Jet<S> q;  // q, q', q''
  S K;            // -Re(c0 conj c1)/|c1|^2
};
using CrossingValues = CrossingValuesT<Ball>;
/// q and K at an angle, given sin and cos of n theta (Ball: every point of the ball; Dint: of the interval).
template <class S>
CrossingValuesT<S> crossing_values(long n, const CPolyT<S>& RU_, const CPolyT<S>& SU_, const CPolyT<S>& RV_,
                                   const CPolyT<S>& SV_, const CPolyT<S>& H1_, const AngleT<S>& a, const S& sn, const S& cn) {
  const jet::Jet<S> Kn = jet::kernel_K(a.th, n, sn, cn, a.s1, a.c1);
  const jet::Jet<S> cos_n{cn, -(sn * n), -((cn * n) * n)};
  const jet::Jet<S> RU = eval(RU_, a), SU = eval(SU_, a);
  CrossingValuesT<S> v;
  v.q = Kn * RU + cos_n * SU + eval(SV_, a);
  v.K = -((cn * RU.v - (sn * a.s1) * SU.v + eval(RV_, a).v) / eval(H1_, a).v);
  return v;
}
CrossingValues crossing_values(const CrossingForm& f, const Ball& theta) {
  const Angle a = angle(theta);
  Ball sn, cn;
  flint::sin_cos(theta * f.n, sn, cn);
  return crossing_values(f.n, f.RU, f.SU, f.RV, f.SV, f.H1, a, sn, cn);
}

/// q and K in double intervals (numeric/dinterval.hpp) at theta = pi k/D or over
/// [pi (k - 1)/D, pi (k + 1)/D] (box), for the grid of the search (D = M 2^level): sin and cos of
/// theta/2 and of n theta by sin_cos_pi's exact integer reduction, widened over a box by their
/// Lipschitz bounds 1/2 and n times the half-width pi/D. nullopt when the integers overflow.
class DoubleCrossings {
 public:
  explicit DoubleCrossings(const CrossingForm& f)
      : n_(f.n), RU_(to_dint(f.RU)), SU_(to_dint(f.SU)), RV_(to_dint(f.RV)), SV_(to_dint(f.SV)), H1_(to_dint(f.H1)),
        PP_(to_dint(f.PP)), QQ_(to_dint(f.QQ)), q0_(to_dint(f.q0)), qpi_(to_dint(f.qpi)) {}
  /// The gain floor over the arc pi [k - h, k + h]/D: a root of c(., K) on the circle at e^{j theta}
  /// for a real K means |K| |Q1| = |z^n P + Q0| >= |P| - |Q0| (|z^n| = 1), so every crossing gain
  /// on the arc has |K| >= (|P| - |Q0|)/|Q1|, a bound that does not depend on n: it prunes the
  /// arcs far from the loop's crossover before the n-fold oscillation is resolved. -inf where it
  /// says nothing (Q1 may vanish on the arc, or the integers overflow).
  double gain_floor(__int128 k, __int128 D, long h) const {
    AngleT<Dint> a;
    if (!arc_angle(k, D, h, a)) return -HUGE_VAL;
    const Dint floor = (modulus(eval(PP_, a).v) - modulus(eval(QQ_, a).v)) / modulus(eval(H1_, a).v);
    return floor.finite() ? floor.lo : -HUGE_VAL;
  }
  std::optional<CrossingValuesT<Dint>> at(__int128 k, __int128 D, bool box) const {
    AngleT<Dint> a;
    Dint sn, cn;
    if (!double_angle(n_, k, D, box, a, sn, cn)) return std::nullopt;
    return crossing_values(n_, RU_, SU_, RV_, SV_, H1_, a, sn, cn);
  }
  const Dint& q0() const { return q0_; }
  const Dint& qpi() const { return qpi_; }

 private:
  long n_;
  /// |w| from |w|^2 enclosed (its lower end clipped at 0, where |w|^2 >= 0 lies)
  static Dint modulus(const Dint& sq) { return sq.finite() && sq.hi >= 0 ? sqrt(Dint(std::max(sq.lo, 0.0), sq.hi)) : Dint::entire(); }
  CPolyT<Dint> RU_, SU_, RV_, SV_, H1_, PP_, QQ_;
  Dint q0_, qpi_;
};

Ball upper(const Ball& x) { return x.upper_end(); }
double lower_double(const Ball& x) { return x.finite() ? x.to_double() - x.radius() : -HUGE_VAL; }

/// A piece of the crossing search, the box pi [i, i + 1]/(M 2^level), decided in double
/// intervals when they suffice: every gain on it above the best crossing (or <= 0), or no root of
/// q on it (q of one sign; or q monotone with one sign at both ends; at theta = 0 and pi, q even
/// about the end and moving away from q(end) != 0, or q'' of one sign where q(end) = 0), the tests
/// of the Arb search in smallest_crossings. false: the piece needs the Arb search.
template <class Above>
bool settled_in_double(const DoubleCrossings& d, long i, int level, long M, bool q0_zero, bool qpi_zero, Above above) {
  const __int128 D = static_cast<__int128>(M) << (level + 1), k = 2 * static_cast<__int128>(i) + 1;
  const auto v = d.at(k, D, true);
  if (!v) return false;
  if (above(v->K)) return true;
  const jet::Jet<Dint>& J = v->q;
  const bool at_zero = i == 0, at_pi = i + 1 == (M << level);
  if (at_zero || at_pi) {
    const Dint& end = at_zero ? d.q0() : d.qpi();
    const bool end_zero = at_zero ? q0_zero : qpi_zero;
    if (!end_zero && !end.contains_zero() && !J.v.contains_zero()) return true;
    if (!end_zero && !end.contains_zero() && !J.dd.contains_zero() && (end.positive() ? J.dd.positive() : J.dd.negative()))
      return true;
    return end_zero && !J.dd.contains_zero();
  }
  if (!J.v.contains_zero()) return true;
  if (J.d.contains_zero()) return false;
  const auto a = d.at(k - 1, D, false), b = d.at(k + 1, D, false);
  if (!a || !b) return false;
  const Dint &qa = a->q.v, &qb = b->q.v;
  return !qa.contains_zero() && !qb.contains_zero() && qa.positive() == qb.positive();
}

}  // namespace

std::optional<CrossingSearch> smallest_crossings(const DelayedLoop& L, std::string& why) {
  const CrossingForm f = L.exact ? crossing_form(L.n, L.Pq, L.Q0q, L.Q1q) : crossing_form(L.n, L.P, L.Q0, L.Q1);
  CrossingSearch out;
  const long M = 4 * (L.n + static_cast<long>(L.P.size())) + 64;
  struct Piece {
    double key;     // the smallest K the piece may hold (the order only)
    long i;
    int level;
    long span = 0;  // > 0: the coarse arc of the first boxes i .. i + span - 1, not yet cut to them
    bool operator<(const Piece& o) const { return key > o.key; }  // a min-queue
  };
  std::priority_queue<Piece> queue;
  const long budget = 64 * M + 100000;  // arcs: a degenerate q (identically 0 on an arc) cannot run away
  std::optional<Ball> best;  // the smallest upper end of a positive crossing gain found so far
  double best_d = HUGE_VAL;  // a double >= best
  auto above = [&](const Ball& K) {  // every point of K is above the best crossing (or <= 0)
    if (!K.finite()) return false;
    if (!upper(K).positive()) return true;
    return best && best->below(K);
  };
  auto above_d = [&](const Dint& K) { return K.finite() && (K.hi <= 0 || best_d < K.lo); };
  // the double-interval twin of every test (numeric/dinterval.hpp), Arb only where it cannot decide
  const std::optional<DoubleCrossings> dbl = double_pruning ? std::optional<DoubleCrossings>(f) : std::nullopt;
  auto keep = [&](long i, int level) {
    ++out.boxes;
    if (dbl) {
      const __int128 k = 2 * static_cast<__int128>(i) + 1, D = static_cast<__int128>(M) << (level + 1);
      if (const auto v = dbl->at(k, D, true)) {
        ++out.double_boxes;
        if (above_d(v->K)) return;
        const double floor = dbl->gain_floor(k, D, 1);
        if (best_d < floor) return;
        queue.push({std::max(v->K.finite() ? v->K.lo : -HUGE_VAL, floor), i, level});
        return;
      }
    }
    const Ball X = flint::hull(theta_at(i, level, M), theta_at(i + 1, level, M));
    const CrossingValues v = crossing_values(f, X);
    if (above(v.K)) return;
    queue.push({lower_double(v.K), i, level});
  };
  // With double intervals the first boxes are reached through coarse arcs cut in eight, each
  // dropped as soon as its gain floor is above the best crossing (DoubleCrossings::gain_floor):
  // the boxes far from the crossover are never evaluated one by one. Arb alone: every box.
  constexpr long cut = 8;
  auto keep_coarse = [&](long i, long span) {
    if (span == 1) return keep(i, 0);
    ++out.boxes, ++out.double_boxes;
    const double floor = dbl->gain_floor(2 * static_cast<__int128>(i) + span, 2 * static_cast<__int128>(M), span);
    if (!(best_d < floor)) queue.push({floor, i, 0, span});
  };
  if (dbl)
    for (long i = 0; i < M; i += M / cut + 1) keep_coarse(i, std::min(M / cut + 1, M - i));
  else
    for (long i = 0; i < M; ++i) keep(i, 0);
  while (!queue.empty()) {
    const Piece pc = queue.top();
    queue.pop();
    if (best_d < pc.key) continue;  // every positive gain on it is above the best crossing found since
    if (pc.span > 0) {
      const long part = (pc.span + cut - 1) / cut;
      for (long j = pc.i; j < pc.i + pc.span; j += part) keep_coarse(j, std::min(part, pc.i + pc.span - j));
      continue;
    }
    if (dbl && settled_in_double(*dbl, pc.i, pc.level, M, f.q0_zero, f.qpi_zero, above_d)) {
      ++out.double_boxes;
      continue;
    }
    const long last = M << pc.level;
    const Ball a = theta_at(pc.i, pc.level, M), b = theta_at(pc.i + 1, pc.level, M), X = flint::hull(a, b);
    const CrossingValues v = crossing_values(f, X);
    if (above(v.K)) continue;
    const jet::Jet<Ball>& J = v.q;
    const bool at_zero = pc.i == 0, at_pi = pc.i + 1 == last;
    if (at_zero || at_pi) {  // q is even about 0 and about pi: q = q(end) + q''(xi) (theta - end)^2/2 there
      const Ball& end = at_zero ? f.q0 : f.qpi;
      const bool end_zero = at_zero ? f.q0_zero : f.qpi_zero;
      if (!end_zero && !end.contains_zero() && !J.v.contains_zero()) continue;
      if (!end_zero && !end.contains_zero() && !J.dd.contains_zero() &&
          (end.positive() ? J.dd.positive() : J.dd.negative()))
        continue;  // q moves away from q(end) != 0: no root
      if (end_zero && !J.dd.contains_zero()) continue;  // q = q''(xi) t^2/2 != 0 for t != 0
    } else {
      if (!J.v.contains_zero()) continue;
      if (!J.d.contains_zero()) {  // q monotone on the box: one crossing iff q changes sign
        const Ball qa = crossing_values(f, a).q.v, qb = crossing_values(f, b).q.v;
        const bool decided = !qa.contains_zero() && !qb.contains_zero();
        if (decided && qa.positive() == qb.positive()) continue;
        if (decided) {  // interval Newton on q
          Ball T = X;
          for (int it = 0; it < 100; ++it) {
            const Ball m = T.mid();
            const Ball N = m - crossing_values(f, m).q.v / crossing_values(f, T).q.d;
            Ball Y;
            if (!flint::intersect(Y, T, N)) break;
            const bool progress = Y.radius() < 0.5 * T.radius();
            T = Y;
            if (!progress && it > 2) break;
          }
          const Ball K = crossing_values(f, T).K;
          if (!K.finite()) {
            why = "c1 vanishes near a crossing on the circle";
            return std::nullopt;
          }
          if (K.contains_zero()) {
            why = "a crossing gain not separated from 0";
            return std::nullopt;
          }
          if (K.positive()) {
            out.crossings.push_back({K, T});
            if (!best || upper(K).below(*best)) {
              best = upper(K);
              best_d = arf_get_d(arb_midref(best->get()), ARF_RND_CEIL);  // best is exact (an end)
            }
          }
          continue;
        }
      }
    }
    if (pc.level >= max_level || out.boxes > budget) {
      why = "a crossing frequency could not be isolated near wT = " + std::to_string(a.to_double()) +
            " (a double root, or one at a box end, at " + std::to_string(flint::ball_prec) + " bits" +
            (out.boxes > budget ? ", or the work budget of " + std::to_string(budget) + " arcs" : std::string()) + ")";
      return std::nullopt;
    }
    keep(2 * pc.i, pc.level + 1);
    keep(2 * pc.i + 1, pc.level + 1);
  }
  // only the crossings that can be the smallest
  if (best) {
    std::vector<DelayCrossing> low;
    for (const auto& c : out.crossings)
      if (!best->below(c.K)) low.push_back(c);
    out.crossings = std::move(low);
  }
  return out;
}

}  // namespace hapstab::stability::detail

namespace hapstab::stability {

DelayCirclePolynomials delay_circle_polynomials(const Polynomial<rational>& P, const Polynomial<rational>& Q0,
                                                const Polynomial<rational>& Q1) {
  if (P.is_zero() || Q1.is_zero()) throw InputError("delay_circle_polynomials: P and Q1 must not be zero");
  const auto c = detail::circle_polys(P.coeffs(), Q0.coeffs(), Q1.coeffs());  // Q0 = 0: no coefficients, taken as {0}
  using Pq = Polynomial<rational>;
  return {Pq(c.RU), Pq(c.SU), Pq(c.RV), Pq(c.SV), Pq(c.H1), Pq(c.PP), Pq(c.QQ)};
}

}  // namespace hapstab::stability
