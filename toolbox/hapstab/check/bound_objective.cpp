// hapstab/check/bound_objective.cpp -- see bound_objective.hpp.
#include "hapstab/check/bound_objective.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/nonnegative.hpp"
#include "hapstab/check/on_circle.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check::detail {

namespace {

using P = Polynomial<rational>;
using circle::OnCircle;
using circle::mul;

OnCircle power(OnCircle x, long n) {
  OnCircle r{P(rational(1)), P()};
  while (n > 0) {
    if (n & 1) r = mul(r, x);
    n >>= 1;
    if (n) x = mul(x, x);
  }
  return r;
}

// p(x) for a point x = a(c) + js b(c) on the circle, by Horner.
OnCircle at(const P& p, const OnCircle& x) {
  OnCircle r{P(), P()};
  for (int k = p.degree(); k >= 0; --k) {
    r = mul(r, x);
    r.a += P(p.coeff(k));
  }
  return r;
}

// |a + js b|^2 = a^2 + (1 - c^2) b^2
P modulus2(const OnCircle& x) { return x.a * x.a + circle::one_minus_c2() * x.b * x.b; }

}  // namespace

DelayModel read_delay_model(const nlohmann::json& model) {
  DelayModel m;
  const PeriodDelay pd = read_period_delay(model);
  m.T = pd.T;
  m.n = pd.n;
  m.td = model.contains("frac_delay") ? exact_field(model, "frac_delay", "model") : rational(0);
  if (m.td < 0) throw InputError("model.frac_delay: the delay t_d must be >= 0, got " + m.td.str());
  m.eta = exact_field(model, "eta", "model");
  if (m.eta < 0) throw InputError("model.eta: must be >= 0, got " + m.eta.str());
  const rational tau = rational(m.n) + m.td / m.T;
  // q and P as longs only when they are small (t_d = 10^-25 s makes q = 10^22)
  const integer cap(1000000000L);
  if (den(tau) > cap || num(tau) > cap)
    throw InputError("model.frac_delay: t_d/T = " + rational(m.td / m.T).str().substr(0, 60) +
                     " has a numerator or denominator above 10^9, beyond this checker's limit");
  m.q = den(tau).convert_to<long>();
  m.P = num(tau).convert_to<long>();
  return m;
}

void check_size(const DelayModel& m, int deg_num, int deg_den, long max_size) {
  const long size = m.q * (std::max(deg_num, deg_den) + 1) + m.P;
  if (size > max_size)
    throw InputError("model: the objective in cos(wT/" + std::to_string(m.q) + ") has size q (deg H + 1) + P = " +
                     std::to_string(size) + ", beyond this checker's limit of " + std::to_string(max_size) +
                     " (it expands the delay exactly)");
}

ObjectivePolys bound_objective(const RationalFunction<rational>& H, const rational& T, long Pexp, long q) {
  const OnCircle v{P{rational(0), rational(1)}, P(rational(1))};        // v = c + js
  const OnCircle conj_v{P{rational(0), rational(1)}, P(rational(-1))};  // conj(v) = c - js
  const OnCircle vq = power(v, q);
  OnCircle N = at(H.num(), vq);
  if (Pexp > 0) N = mul(N, power(conj_v, Pexp));
  const OnCircle D = at(H.den(), vq);
  const OnCircle E{P(rational(1)) - vq.a, -vq.b};  // 1 - v^q
  const P& s2 = circle::one_minus_c2();
  const P X = N.a * D.a + s2 * N.b * D.b, Y = N.b * D.a - N.a * D.b;  // N conj(D) = X + jsY
  ObjectivePolys o{T * (X * E.a + s2 * Y * E.b), modulus2(D) * modulus2(E)};
  const P one_minus_c{rational(1), rational(-1)};
  while (o.B.degree() > 0 && o.B(rational(1)) == 0 && o.A(rational(1)) == 0) {
    const auto [qa, ra] = divmod(o.A, one_minus_c);
    const auto [qb, rb] = divmod(o.B, one_minus_c);
    if (!ra.is_zero() || !rb.is_zero()) break;
    o.A = qa;
    o.B = qb;
  }
  return o;
}

namespace {
// The signs of V_k = d^k U_k(a/d), k = 0 .. q-1 (V_0 = 1, V_1 = 2a, V_k = 2a V_{k-1} - d^2 V_{k-2}):
// in integers, no gcd per step; d > 0, so V_k and U_k(c) have one sign.
std::vector<int> chebyshev_u_signs(const rational& c, long q) {
  const integer a = num(c), d = den(c), d2 = d * d;
  std::vector<int> out;
  integer prev = 1, cur = 2 * a;
  out.push_back(1);
  for (long k = 1; k < q; ++k) {
    out.push_back(cur > 0 ? 1 : cur < 0 ? -1 : 0);
    const integer next = 2 * a * cur - d2 * prev;
    prev = cur;
    cur = next;
  }
  return out;  // out[k] = sign U_k(c), k = 0 .. q-1
}
}  // namespace

bool at_or_below_domain_end(const rational& c, long q) {
  if (c == -1) return true;
  if (c < -1 || c > 1) return false;
  for (int s : chebyshev_u_signs(c, q))  // U_0 .. U_{q-1}: all > 0 iff phi < pi/q
    if (s <= 0) return true;
  return false;
}

bool in_domain(const rational& c, long q) {
  if (c < -1 || c > 1) return false;
  const std::vector<int> u = chebyshev_u_signs(c, q);  // U_0 .. U_{q-1}
  for (long k = 0; k + 1 < q; ++k)
    if (u[static_cast<size_t>(k)] <= 0) return false;
  return u.back() >= 0;
}

P chebyshev_u(long k) {
  P prev(rational(1)), cur{rational(0), rational(2)};
  if (k == 0) return prev;
  const P two_c{rational(0), rational(2)};
  for (long i = 1; i < k; ++i) {
    P next = two_c * cur - prev;
    prev = cur;
    cur = next;
  }
  return cur;
}

std::string shortened(const rational& x) { return x.str().size() > 40 ? x.str().substr(0, 40) + "..." : x.str(); }

std::optional<std::string> upper_bound_fails(const ObjectivePolys& f, const rational& bound, const std::string& bound_name,
                                             const rational& c_lo, long q, std::string& how) {
  if (!at_or_below_domain_end(c_lo, q))
    return "evidence.domain_c_lo = " + shortened(c_lo) + " is not <= cos(pi/" + std::to_string(q) +
           ") (U_0 .. U_" + std::to_string(q - 1) + " all > 0 there): [c_lo, 1] misses part of the band";
  const std::string on = "[" + (c_lo == -1 ? std::string("-1") : shortened(c_lo)) + ", 1]";
  const P upper = bound * f.B - f.A;
  const std::string degree = std::to_string(std::max(f.A.degree(), f.B.degree()));
  const std::string var = q == 1 ? "" : " in c = cos(wT/" + std::to_string(q) + ")";
  auto why = nonnegative_on(upper, c_lo, rational(1));
  if (!why) {
    how = bound_name + " B - A >= 0 on " + on + " by Sturm, degree " + degree + var;
    return std::nullopt;
  }
  // across an irrational end where the objective has a pole (-inf inside): U_{q-1} > 0 inside the band
  if (q > 1 && !nonnegative_on(upper * chebyshev_u(q - 1), c_lo, rational(1))) {
    how = bound_name + " B - A times U_" + std::to_string(q - 1) + "(c) (> 0 inside the band) >= 0 on " + on + " by Sturm, degree " + degree + var;
    return std::nullopt;
  }
  return bound_name + " B(c) - A(c) on " + on + ": " + *why;
}

std::optional<std::string> lower_bound_fails(const ObjectivePolys& f, const rational& target, const rational& c0, long q) {
  if (c0 < -1 || c0 > 1) return "evidence.witness_c = " + shortened(c0) + " is outside [-1, 1]";
  if (!in_domain(c0, q))
    return "evidence.witness_c = " + shortened(c0) + " is outside the band: not in [cos(pi/" + std::to_string(q) +
           "), 1] (w > pi/T)";
  // f on the reduced A/B: at a pole of H that cancels in A/B (a Tustin pole at z = -1, say) the
  // value is f's limit there, which the supremum reaches
  const P g = gcd(f.A, f.B);
  const P Ar = divmod(f.A, g).first, Br = divmod(f.B, g).first;
  const rational b0 = Br(c0);
  if (b0 == 0) return "evidence.witness_c = " + shortened(c0) + " is a pole of the objective (a pole of H on the unit circle)";
  const rational v = Ar(c0) / b0;
  if (v < target)
    return "the objective at the witness c0 = " + shortened(c0) + " is " + to_decimal(v, 12) + " < " + to_decimal(target, 12);
  return std::nullopt;
}

std::optional<std::string> unbounded_above_fails(const ObjectivePolys& f, const rational& c_p, long side, long q) {
  const std::string at = "evidence.pole_c = " + shortened(c_p);
  if (!in_domain(c_p, q)) return at + " is outside the band [cos(pi/" + std::to_string(q) + "), 1]";
  if (side == 1 && c_p == 1) return "evidence.side = +1 at c_p = 1: no point of the band lies above it";
  if (side == -1) {
    bool inside = c_p > -1;
    for (long k = 1; k <= q && inside; ++k) inside = chebyshev_u(k - 1)(c_p) > 0;
    if (!inside) return "evidence.side = -1 at the band's end c_p = cos(pi/" + std::to_string(q) + "): no point of the band lies below it";
  }
  const P g = gcd(f.A, f.B);
  const P Ar = divmod(f.A, g).first;
  P R = divmod(f.B, g).first;
  if (R(c_p) != 0) return at + " is not a pole of the objective (the reduced denominator is " + to_decimal(R(c_p), 12) + " there)";
  const P root{-c_p, rational(1)};
  long m = 0;
  while (R(c_p) == 0) {
    R = divmod(R, root).first;
    ++m;
  }
  const int sign = (Ar(c_p) > 0 ? 1 : -1) * (R(c_p) > 0 ? 1 : -1) * (m % 2 == 1 ? static_cast<int>(side) : 1);
  if (sign < 0)
    return "the objective tends to -inf as c -> " + shortened(c_p) + (side > 0 ? " from above" : " from below") +
           " (a pole of order " + std::to_string(m) + " of the reduced A/B, residue term of sign -1 on that side)";
  return std::nullopt;
}

std::optional<std::string> unbounded_inside_fails(const ObjectivePolys& f, const rational& s, const rational& b, long side, long q) {
  if (!(s < b)) return std::string("evidence: not pole_lo < pole_hi");
  if (!in_domain(s, q) || !in_domain(b, q))
    return "evidence: pole_lo or pole_hi is outside the band [cos(pi/" + std::to_string(q) + "), 1]";
  const P g = gcd(f.A, f.B);
  const P Ar = divmod(f.A, g).first, R = divmod(f.B, g).first;
  const auto square_free = [](const P& p) { return p.degree() < 1 ? p : divmod(p, gcd(p, p.derivative())).first; };
  const P Rs = square_free(R), As = square_free(Ar);
  if (Rs.degree() < 1 || Rs(s) == 0 || Rs(b) == 0 || sturm_count(Rs, s, b) != 1)
    return std::string("(pole_lo, pole_hi) does not isolate one pole of the objective (the reduced denominator has not exactly "
                       "one root inside it and none at its ends)");
  if (As(s) == 0 || As(b) == 0 || (As.degree() >= 1 && sturm_count(As, s, b) != 0))
    return std::string("the reduced numerator has a root in [pole_lo, pole_hi]");
  const rational& at = side > 0 ? b : s;
  if ((Ar(at) > 0) != (R(at) > 0))
    return std::string("the objective tends to -inf as c -> the pole from ") + (side > 0 ? "above" : "below") +
           " (Ar R < 0 on that side of it in (pole_lo, pole_hi))";
  return std::nullopt;
}

std::optional<std::string> unbounded_at_end_fails(const ObjectivePolys& f, const rational& s, const rational& b, long q) {
  if (q < 2) return std::string("evidence.end_lo: the band's end is c = -1 (an integer delay): give pole_c");
  if (!(s >= -1 && s < b && b <= 1)) return "evidence: not -1 <= end_lo < end_hi <= 1";
  const P U = chebyshev_u(q - 1);
  if (U(s) == 0 || U(b) == 0) return std::string("evidence: end_lo or end_hi is a root of U_{q-1} (cos(k pi/q))");
  if (sturm_count(U, s, rational(1)) != 1 || sturm_count(U, s, b) != 1)
    return "(end_lo, end_hi] does not isolate cos(pi/" + std::to_string(q) + ") (U_{q-1} has not exactly one root in (end_lo, 1) "
           "and in (end_lo, end_hi))";
  const P g = gcd(f.A, f.B);
  const P Ar = divmod(f.A, g).first, R = divmod(f.B, g).first;
  const P G = gcd(R, U);  // square-free, its roots U's: none at s or 1
  if (G.degree() < 1 || sturm_count(G, s, rational(1)) < 1)
    return "cos(pi/" + std::to_string(q) + ") is not a pole of the objective (the reduced denominator and U_{q-1} share no root "
           "there)";
  const auto square_free = [](const P& p) { return divmod(p, gcd(p, p.derivative())).first; };
  const P Rs = square_free(R), As = square_free(Ar);
  if (Rs(s) == 0 || Rs(b) == 0 || sturm_count(Rs, s, b) != 1)
    return std::string("the reduced denominator has another root in (end_lo, end_hi], or one at its ends");
  if (As(s) == 0 || As(b) == 0 || sturm_count(As, s, b) != 0)
    return std::string("the reduced numerator has a root in [end_lo, end_hi]");
  if ((Ar(b) > 0) != (R(b) > 0))
    return "the objective tends to -inf as c -> cos(pi/" + std::to_string(q) + ") from above (Ar R < 0 on (c_e, end_hi])";
  return std::nullopt;
}

}  // namespace hapstab::check::detail
