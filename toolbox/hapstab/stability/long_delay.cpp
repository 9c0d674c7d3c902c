// The long-delay path of the stability test (stability/long_delay.hpp): the argument principle
// and the D-decomposition crossings of c(z, K) = z^n P + Q0 + K Q1 on the unit circle, in Arb
// balls, without the polynomial of degree n + m.
#include "hapstab/stability/long_delay.hpp"
#include "hapstab/stability/sampled_loop.hpp"

#include <algorithm>
#include <cmath>
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

struct Angle {
  jet::Jet<Ball> th, c, t, s;  // theta, cos(theta), 1 - cos(theta), 1 + cos(theta) as jets
  Ball s1, c1, sh, ch;         // sin, cos of theta and of theta/2
  double lo = 0, hi = 0;       // theta's ends, rounded outward (the choice of form only)
};
Angle angle(const Ball& theta) {
  Angle a;
  flint::sin_cos(theta * Ball(0.5), a.sh, a.ch);
  a.s1 = Ball(2L) * (a.sh * a.ch);
  a.c1 = Ball(1L) - Ball(2L) * flint::sqr(a.sh);
  a.th = jet::variable(theta);
  a.c = {a.c1, -a.s1, -a.c1};
  a.t = {Ball(2L) * flint::sqr(a.sh), a.s1, a.c1};
  a.s = {Ball(2L) * flint::sqr(a.ch), -a.s1, -a.c1};
  a.lo = theta.to_double() - theta.radius();
  a.hi = theta.to_double() + theta.radius();
  return a;
}

/// p(c) in the three forms.
struct CPoly {
  std::vector<Ball> c, t, s;
};
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
jet::Jet<Ball> eval(const CPoly& p, const Angle& a) {
  if (a.hi <= near_zero) return jet::horner(p.t, a.t);
  if (a.lo >= near_pi) return jet::horner(p.s, a.s);
  return jet::horner(p.c, a.c);
}

/// p(z) (real coefficients) in the three forms, evaluated at z = e^{j theta}.
struct ZPoly {
  std::vector<Ball> z, at1, atm1;
};
template <class C>
ZPoly zpoly(const std::vector<C>& a) {
  return {balls(a), balls(taylor_shift(a, C(1L))), balls(taylor_shift(a, C(-1L)))};
}
CBall eval(const ZPoly& p, const Angle& a) {
  if (a.hi <= near_zero) return flint::horner(p.at1, {-a.t.v, a.s1});     // z - 1 = (cos - 1) + j sin
  if (a.lo >= near_pi) return flint::horner(p.atm1, {a.s.v, a.s1});       // z + 1 = (cos + 1) + j sin
  return flint::horner(p.z, {a.c1, a.s1});
}

bool narrow_arg(const Ball& a) { return a.finite() && a.radius() < 0.25; }

}  // namespace

// ---- the argument principle --------------------------------------------------------------------
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
  const Ball count = total / Ball::pi();
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

template <class C>
CrossingForm crossing_form(long n, const std::vector<C>& P, const std::vector<C>& Q0, const std::vector<C>& Q1) {
  CrossingForm f;
  f.n = n;
  long lu = 0, lv = 0, lh = 0;
  std::vector<C> RU, SU, RV, SV, H1, unused;
  const std::vector<C> u = correlation(P, Q1, lu), v = correlation(Q0, Q1, lv), h = correlation(Q1, Q1, lh);
  chebyshev_sums(u, lu, RU, SU);
  chebyshev_sums(v, lv, RV, SV);
  chebyshev_sums(h, lh, H1, unused);
  f.RU = cpoly(RU), f.SU = cpoly(SU), f.RV = cpoly(RV), f.SV = cpoly(SV), f.H1 = cpoly(H1);
  const C one(1L), mone(-1L), nn(n);
  const C q0 = nn * horner_at(RU, one) + horner_at(SU, one) + horner_at(SV, one);
  const C sign = n % 2 == 0 ? one : mone;
  const C qpi = C(0L) - sign * nn * horner_at(RU, mone) + sign * horner_at(SU, mone) + horner_at(SV, mone);
  f.q0 = Ball(q0), f.qpi = Ball(qpi);
  if constexpr (std::is_same_v<C, rational>) f.q0_zero = q0 == 0, f.qpi_zero = qpi == 0;
  return f;
}

struct CrossingValues {
  jet::Jet<Ball> q;  // q, q', q''
  Ball K;            // -Re(c0 conj c1)/|c1|^2
};
CrossingValues crossing_values(const CrossingForm& f, const Ball& theta) {
  const Angle a = angle(theta);
  Ball sn, cn;
  flint::sin_cos(theta * f.n, sn, cn);
  const jet::Jet<Ball> Kn = jet::kernel_K(a.th, f.n, sn, cn, a.s1, a.c1);
  const jet::Jet<Ball> cos_n{cn, -(sn * f.n), -((cn * f.n) * f.n)};
  const jet::Jet<Ball> RU = eval(f.RU, a), SU = eval(f.SU, a);
  CrossingValues v;
  v.q = Kn * RU + cos_n * SU + eval(f.SV, a);
  v.K = -((cn * RU.v - (sn * a.s1) * SU.v + eval(f.RV, a).v) / eval(f.H1, a).v);
  return v;
}

Ball upper(const Ball& x) { return x.upper_end(); }
double lower_double(const Ball& x) { return x.finite() ? x.to_double() - x.radius() : -HUGE_VAL; }

}  // namespace

std::optional<CrossingSearch> smallest_crossings(const DelayedLoop& L, std::string& why) {
  const CrossingForm f = L.exact ? crossing_form(L.n, L.Pq, L.Q0q, L.Q1q) : crossing_form(L.n, L.P, L.Q0, L.Q1);
  CrossingSearch out;
  const long M = 4 * (L.n + static_cast<long>(L.P.size())) + 64;
  struct Piece {
    double key;  // the smallest K the piece may hold (the order only)
    long i;
    int level;
    bool operator<(const Piece& o) const { return key > o.key; }  // a min-queue
  };
  std::priority_queue<Piece> queue;
  const long budget = 64 * M + 100000;  // arcs: a degenerate q (identically 0 on an arc) cannot run away
  std::optional<Ball> best;  // the smallest upper end of a positive crossing gain found so far
  auto above = [&](const Ball& K) {  // every point of K is above the best crossing (or <= 0)
    if (!K.finite()) return false;
    if (!upper(K).positive()) return true;
    return best && best->below(K);
  };
  auto keep = [&](long i, int level) {
    ++out.boxes;
    const Ball X = flint::hull(theta_at(i, level, M), theta_at(i + 1, level, M));
    const CrossingValues v = crossing_values(f, X);
    if (above(v.K)) return;
    queue.push({lower_double(v.K), i, level});
  };
  for (long i = 0; i < M; ++i) keep(i, 0);
  while (!queue.empty()) {
    const Piece pc = queue.top();
    queue.pop();
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
            if (!best || upper(K).below(*best)) best = upper(K);
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
  const std::vector<rational> q0 = Q0.is_zero() ? std::vector<rational>{rational(0)} : Q0.coeffs();
  long lu = 0, lv = 0, lh = 0;
  const std::vector<rational> u = detail::correlation(P.coeffs(), Q1.coeffs(), lu),
                              v = detail::correlation(q0, Q1.coeffs(), lv),
                              h = detail::correlation(Q1.coeffs(), Q1.coeffs(), lh);
  std::vector<rational> RU, SU, RV, SV, H1, unused;
  detail::chebyshev_sums(u, lu, RU, SU);
  detail::chebyshev_sums(v, lv, RV, SV);
  detail::chebyshev_sums(h, lh, H1, unused);
  return {Polynomial<rational>(RU), Polynomial<rational>(SU), Polynomial<rational>(RV), Polynomial<rational>(SV),
          Polynomial<rational>(H1)};
}

}  // namespace hapstab::stability
