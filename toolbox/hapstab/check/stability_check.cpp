// hapstab/check/stability_check.cpp -- see stability_check.hpp.
#include "hapstab/check/stability_check.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/check/loop_model.hpp"
#include "hapstab/check/scene_model.hpp"
#include "hapstab/check/reciprocal.hpp"
#include "hapstab/check/schur_cohn.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::check {

namespace {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;
constexpr long max_charpoly_degree = 2000;
constexpr long max_family_degree = 150;  // D(E) from 2d + 1 exact resultants of degree d (as stability-max)

struct LoopCharpoly {
  P c;                     // the characteristic polynomial, the checker's own (every pole at s = 0)
  std::optional<P> c1;     // with a pole off s = 0: c is c0 of c(z; E) = c0 + E c1
  std::optional<rational> x;  // and E = e^x, x = p T
  std::string text;        // what was checked
  std::optional<detail::LoopDevice> spring;  // two poles off s = 0: the device, and the wall A/L
  P A, L;
  std::optional<detail::LoopDevice> winding;  // every pole at s = 0, decided by the argument principle (A/L as above)
};

constexpr long max_winding_delay = 100000;  // the model's limit (limits.hpp): about 4 (n + 16) arcs

LoopCharpoly characteristic(const nlohmann::json& model, bool argument_principle, bool scene_device) {
  detail::only_fields(model, {"plant", "H", "operator", "set", "T", "delay"}, "model");
  const detail::LoopDevice d = detail::read_loop_device(model, true, scene_device);
  const RF H = detail::parse_model_field(model, "H", 'z', d.T, d.params);
  const int extra = d.pole ? 1 : d.spring ? 2 : 0;
  if (H.num().degree() > H.den().degree() + d.n) throw InputError("model.H: z^-n H(z) is not causal");
  const bool off_zero = d.pole || d.spring;
  if (argument_principle) {
    if (d.n > max_winding_delay) throw InputError("model.delay: above this checker's limit of " + std::to_string(max_winding_delay));
    return {P(rational(1)), std::nullopt, std::nullopt,
            "degree " + std::to_string(d.k + extra) + " device" +
                (d.pole ? ", pole s = " + d.pole->str() + " (E = e^{pT} in balls)"
                        : d.spring ? ", two poles off s = 0 (e^{A_c T} in balls)" : "") +
                ", delay " + std::to_string(d.n) + ", never expanded",
            std::nullopt, H.num(), H.den(), d};
  }
  if (H.den().degree() + d.n + d.k + extra > (off_zero ? max_family_degree : max_charpoly_degree))
    throw InputError("model: the characteristic polynomial has degree " + std::to_string(H.den().degree() + d.n + d.k + extra) +
                     ", beyond this checker's limit of " + std::to_string(off_zero ? max_family_degree : max_charpoly_degree) +
                     (off_zero ? " with a device pole off s = 0" : ""));
  const std::string text = "degree " + std::to_string(d.k + extra) + " device, delay " + std::to_string(d.n);
  if (d.spring)
    return {P(rational(1)), std::nullopt, std::nullopt,
            text + ", poles at the roots of s^2 + (" + d.spring->first.str() + ") s + (" + d.spring->second.str() + ")", d,
            H.num(), H.den(), std::nullopt};
  if (!d.pole) return {detail::loop_polynomial(d, H.num(), H.den()), std::nullopt, std::nullopt, text, std::nullopt, P(), P(), std::nullopt};
  const auto [c0, c1] = detail::loop_family_in_E(d, H.num(), H.den());
  return {c0, c1, *d.pole * d.T, text + ", pole s = " + d.pole->str() + " (E = e^{pT})", std::nullopt, P(), P(), std::nullopt};
}

/// Schur stability of c0 + E c1 at the true E = e^x (x rational, != 0): the enclosure [lo, hi] of E
/// is narrowed (Arb, 128 to 8192 bits) until D(E) = Res(c, c*) (check/reciprocal.hpp, a polynomial
/// in E) has no root in [lo, hi]; then no c(.; E), E in [lo, hi], has a root on the unit circle, the
/// number of roots inside is the same for all of them (the degree does not move: deg c1 < deg c0),
/// and Schur-Cohn at E = lo decides every one, the true E among them. D = 0 identically: c and c*
/// share a root for every E, so NOT stable (reciprocal.hpp). E transcendental is never a root of D
/// (rational coefficients), so only the precision can run out: InputError then.
SchurCohn decide_family(const P& c0, const P& c1, const rational& x, std::string& how) {
  if (c1.degree() >= c0.degree())
    throw InputError("model: the E-part of the characteristic polynomial has degree >= c0's (checker defect)");
  const P D = detail::reciprocal_resultant(c0, c1);
  if (D.is_zero()) {
    how = "D(E) = Res(c, c*) = 0 for every E: c and c* share a root";
    return {false, "a pair of roots b, 1/b (or a root on the circle) for every E"};
  }
  for (long bits = 128; bits <= 8192; bits *= 2) {
    const auto [lo, hi] = detail::exp_enclosure(x, bits);
    if (D(lo) == 0 || D(hi) == 0 || detail::roots_between(D, lo, hi, true) != 0) continue;
    how = "E = e^(" + x.str() + ") in [" + detail::decimal(lo) + ", " + detail::decimal(hi) + "] (Arb, " + std::to_string(bits) +
          " bits), where D(E) = Res(c, c*) (degree " + std::to_string(D.degree()) + " in E) has no root (Sturm); at E = lo,";
    return schur_cohn(c0 + c1 * P(lo));
  }
  throw InputError("model: the loop is too close to its stability boundary for this checker (e^{pT}'s enclosure at 8192 bits "
                   "still holds a root of D(E))");
}

using BallPoly = std::vector<flint::Ball>;  // ascending coefficients

BallPoly balls(const P& p) {
  BallPoly r;
  for (int i = 0; i <= p.degree(); ++i) r.emplace_back(p.coeff(i));
  return r;
}
BallPoly operator*(const BallPoly& a, const BallPoly& b) {
  if (a.empty() || b.empty()) return {};  // the zero polynomial (balls of a zero P are empty)
  BallPoly r(a.size() + b.size() - 1, flint::Ball(0L));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
BallPoly operator+(const BallPoly& a, const BallPoly& b) {
  BallPoly r(std::max(a.size(), b.size()), flint::Ball(0L));
  for (size_t i = 0; i < r.size(); ++i) {
    if (i < a.size()) r[i] += a[i];
    if (i < b.size()) r[i] += b[i];
  }
  return r;
}

/// c(z) = z^n P1(z) + P0(z), P1 and P0 in ball coefficients (z^n kept apart: the argument
/// principle never expands it); every coefficient holds the exact one.
struct Parts {
  BallPoly P1, P0;
};

BallPoly shifted(const BallPoly& p, long n) {  // z^n p
  BallPoly r(static_cast<size_t>(n), flint::Ball(0L));
  r.insert(r.end(), p.begin(), p.end());
  return r;
}

/// The spring's parts (loop_model.hpp) at `bits`: Phi = e^{A_c T} by arb_mat_exp (scaling and
/// squaring with a bounded Taylor remainder), P1 = L (z - 1)^k Delta, P0 = A (Ndp Delta + (z - 1)^k Nq).
Parts spring_parts(const detail::LoopDevice& d, const P& A, const P& L, long bits, flint::Ball& trace) {
  flint::BallPrecision scope(bits);
  const auto [a1, a0] = *d.spring;
  arb_mat_t M, E;
  arb_mat_init(M, 2, 2);
  arb_mat_init(E, 2, 2);
  const rational entries[2][2] = {{rational(0), d.T}, {-a0 * d.T, -a1 * d.T}};  // A_c T
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) arb_set(arb_mat_entry(M, i, j), flint::Ball(entries[i][j]).get());
  arb_mat_exp(E, M, bits);
  flint::Ball phi[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) arb_set(phi[i][j].get(), arb_mat_entry(E, i, j));
  arb_mat_clear(M);
  arb_mat_clear(E);
  const flint::Ball det = phi[0][0] * phi[1][1] - phi[0][1] * phi[1][0];
  trace = phi[0][0] + phi[1][1];
  const flint::Ball R0(d.R0), R1(d.R1);
  const BallPoly Delta{det, -trace, flint::Ball(1L)};
  const BallPoly Nq{R1 * phi[0][0] - R0 * phi[0][1] - R1 * det, R0 * phi[0][1] - R1 + R1 * phi[1][1]};
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(d.k));
  return {balls(L * Dk) * Delta, balls(A) * (balls(d.Ndp) * Delta + balls(Dk) * Nq)};
}

/// The mass-damper's parts (loop_model.hpp) at `bits`, E = e^{pT} by arb_exp:
/// P1 = L (z - 1)^k (z - E), P0 = A (Ndp (z - E) + r (E - 1)(z - 1)^k).
Parts pole_parts(const detail::LoopDevice& d, const P& A, const P& L, long bits) {
  flint::BallPrecision scope(bits);
  flint::Ball E(*d.pole * d.T);
  arb_exp(E.get(), E.get(), bits);
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(d.k));
  const BallPoly zE{-E, flint::Ball(1L)};
  const BallPoly rE1{flint::Ball(d.r) * (E - flint::Ball(1L))};
  return {balls(L * Dk) * zE, balls(A) * (balls(d.Ndp) * zE + balls(Dk) * rE1)};
}

/// With a device pole off s = 0: c(1) = 0 exactly? c(1) = F g with F = 1 - E (a mass-damper) or
/// Delta(1) = det(I - Phi) (a spring), != 0 since no e^{pT} is 1, and g rational: with k = 0,
/// g = L(1) + A(1) (Ndp(1) - rho) (rho = r, or R1: N_q(1) = -R1 Delta(1)); with k >= 1 the
/// (z - 1)^k terms vanish and g = A(1) Ndp(1). (loop_model.hpp's c(z) at z = 1.)
bool dc_zero(const detail::LoopDevice& d, const P& A, const P& L) {
  const rational one(1);
  if (d.k > 0) return A(one) * d.Ndp(one) == 0;
  return L(one) + A(one) * (d.Ndp(one) - (d.spring ? d.R1 : d.r)) == 0;
}

/// Every pole at s = 0: exact parts P1 = L (z - 1)^k, P0 = A Nd.
std::pair<P, P> exact_parts(const detail::LoopDevice& d, const P& A, const P& L) {
  return {L * P{rational(-1), rational(1)}.pow(static_cast<unsigned>(d.k)), A * d.Nd};
}

/// The parts of the loop at `bits`, whatever the device (every pole at s = 0, a mass-damper, a spring).
Parts loop_parts(const detail::LoopDevice& d, const P& A, const P& L, long bits) {
  flint::Ball trace;
  if (d.spring) return spring_parts(d, A, L, bits, trace);
  if (d.pole) return pole_parts(d, A, L, bits);
  const auto [P1, P0] = exact_parts(d, A, L);
  return {balls(P1), balls(P0)};
}

/// schur_cohn.hpp's test for every polynomial whose coefficients lie in the balls `a` (the
/// leading one excluding 0): each step's |p_0| < |p_d| decided over the whole box (every step's
/// transform computed in ball arithmetic holds the exact transform of each point); nullopt when
/// a step is not decided at this precision.
std::optional<SchurCohn> schur_cohn_balls(BallPoly a) {
  while (a.size() > 1) {
    const size_t d = a.size() - 1;
    const flint::Ball a0 = abs(a.front()), ad = abs(a.back());
    if (ad.below(a0))
      return SchurCohn{false, "Schur-Cohn at degree " + std::to_string(d) + ": |p_0| > |p_d| for every polynomial in the enclosure"};
    if (!a0.below(ad)) return std::nullopt;
    BallPoly q(d, flint::Ball(0L));
    for (size_t i = 0; i < d; ++i) q[i] = a.back() * a[i + 1] - a.front() * a[d - 1 - i];
    for (size_t i = 0; i < d; ++i) q[i] = q[i] / q[d - 1];  // q[d - 1] = p_d^2 - p_0^2 > 0
    a = std::move(q);
  }
  return SchurCohn{true, "every Schur-Cohn step passes for every polynomial in the enclosure"};
}

/// Schur stability of the loop with a spring: Schur-Cohn over Phi's enclosure at 128 to 8192
/// bits until every step is decided; the verdict then holds for the true Phi, which it holds.
SchurCohn decide_spring(const detail::LoopDevice& d, const P& A, const P& L, std::string& how) {
  if (dc_zero(d, A, L)) {  // a root exactly on the circle, which no enclosure decides
    how = "c(1) = 0 exactly (det(I - Phi) times a rational factor that is 0):";
    return {false, "a root on the unit circle at z = 1"};
  }
  for (long bits = 128; bits <= 8192; bits *= 2) {
    flint::BallPrecision scope(bits);
    flint::Ball trace;
    const Parts parts = spring_parts(d, A, L, bits, trace);
    const BallPoly c = shifted(parts.P1, d.n) + parts.P0;
    if (c.back().contains_zero()) throw InputError("model: the leading coefficient's enclosure holds 0 (checker defect)");
    if (auto sc = schur_cohn_balls(c)) {
      const Enclosure<rational> t = trace.bounds();
      how = "Phi = e^{A_c T} enclosed (Arb, " + std::to_string(bits) + " bits; trace(Phi) in [" + detail::decimal(t.lo) + ", " +
            detail::decimal(t.hi) + "]), c(z)'s coefficients in ball arithmetic;";
      return *sc;
    }
  }
  throw InputError("model: the loop is too close to its stability boundary for this checker (Schur-Cohn undecided on "
                   "e^{A_c T}'s enclosure at 8192 bits)");
}

flint::CBall value_at(const BallPoly& p, const flint::CBall& z) {
  flint::CBall v{flint::Ball(0L), flint::Ball(0L)};
  for (size_t i = p.size(); i-- > 0;) v = v * z + flint::CBall{p[i], flint::Ball(0L)};
  return v;
}
flint::Ball value_at(const BallPoly& p, const flint::Ball& x) {
  flint::Ball v(0L);
  for (size_t i = p.size(); i-- > 0;) v = v * x + p[i];
  return v;
}

/// c(e^{j pi t}) = e^{j pi n t} P1(z) + P0(z) for every t in the ball `t` (a complex rectangle).
flint::CBall on_circle(const Parts& c, long n, const flint::Ball& t) {
  flint::CBall z, zn;
  arb_sin_cos_pi(z.im.get(), z.re.get(), t.get(), flint::ball_prec);
  const flint::Ball nt = t * n;
  arb_sin_cos_pi(zn.im.get(), zn.re.get(), nt.get(), flint::ball_prec);
  return zn * value_at(c.P1, z) + value_at(c.P0, z);
}

/// Schur stability of c(z) = z^n P1(z) + P0(z) (loop_parts: every pole at s = 0, a mass-damper or a
/// spring), with z^n never expanded: the argument principle on the upper half circle z = e^{j pi t},
/// t in [0, 1]. c has real coefficients, so its roots inside |z| < 1 number m = (the change of arg c
/// over t in [0, 1])/pi when c(1), c(-1) != 0 (exactly with every pole at s = 0, where = 0 is a root
/// on the circle: NOT stable; in balls otherwise, at 128 to 8192 bits).
/// The interval is cut into arcs, each bisected until c's rectangle over it (ball arithmetic)
/// excludes 0; then it lies in one open half-plane Re > 0, Im > 0, Re < 0 or Im < 0 (h = 0, 1, 2, 3
/// quarter turns), where arg c stays within a quarter turn of h pi/2. Adjacent arcs share a point,
/// so their half-planes are not opposite, and the unwrapped arg follows U += +-1 or 0 quarter turns
/// per arc (exact integers, no arg computed); the first and last arcs hold the real c(1), c(-1), so
/// their half-planes are Re ones and m = (U_last - U_first)/2. Stable iff m = deg c. An arc
/// narrower than 2^-100 without a decision: too close to the boundary (InputError). The
/// coefficients' balls (of e^{pT}, e^{A_c T}) are part of every rectangle: the count holds for the
/// true c.
SchurCohn decide_winding(const detail::LoopDevice& d, const P& A, const P& L, std::string& how) {
  const bool exact = !d.pole && !d.spring;
  long bits = 128;
  Parts parts = loop_parts(d, A, L, bits);
  const long degree = d.n + static_cast<long>(parts.P1.size()) - 1;
  if (static_cast<long>(parts.P0.size()) - 1 >= degree)
    throw InputError("model: the part of c without z^n has degree >= deg c (checker defect: z^-n H is causal)");
  for (const double end : {1.0, -1.0}) {
    const bool odd = end < 0 && d.n % 2;
    if (exact) {
      const auto [P1, P0] = exact_parts(d, A, L);
      const rational x(static_cast<long>(end));
      if ((odd ? -P1(x) : P1(x)) + P0(x) == 0) {
        how = "c(" + std::string(end > 0 ? "1" : "-1") + ") = 0 exactly:";
        return {false, "a root on the unit circle at z = " + std::string(end > 0 ? "1" : "-1")};
      }
      continue;
    }
    if (end > 0 && dc_zero(d, A, L)) {
      how = "c(1) = 0 exactly (its factor other than 1 - e^{pT} or det(I - Phi) is 0):";
      return {false, "a root on the unit circle at z = 1"};
    }
    for (;;) {  // transcendental coefficients: c(+-1) != 0 shown in balls
      flint::BallPrecision scope(bits);
      const flint::Ball x(static_cast<long>(end)), p1 = value_at(parts.P1, x);
      if (!((odd ? -p1 : p1) + value_at(parts.P0, x)).contains_zero()) break;
      if ((bits *= 2) > 8192)
        throw InputError("model: the loop is too close to its stability boundary for this checker (c(" +
                         std::string(end > 0 ? "1" : "-1") + ") not separated from 0 at 8192 bits)");
      parts = loop_parts(d, A, L, bits);
    }
  }
  flint::BallPrecision scope(bits);
  const long arcs0 = 4 * (degree + 16);
  rational min_width(1);
  for (int i = 0; i < 100; ++i) min_width /= 2;
  struct Arc { rational a, b; };
  std::vector<Arc> todo;  // a stack: the leftmost arc on top
  for (long i = arcs0; i > 0; --i) todo.push_back({rational(i - 1) / arcs0, rational(i) / arcs0});
  long turns = 0, first = -1, last = -1, decided = 0;
  while (!todo.empty()) {
    const Arc arc = todo.back();
    todo.pop_back();
    const flint::CBall v = on_circle(parts, d.n, flint::Ball::hull(arc.a, arc.b));
    long h = -1;
    if (v.re.positive()) h = 0;
    else if (v.im.positive()) h = 1;
    else if (v.re.negative()) h = 2;
    else if (v.im.negative()) h = 3;
    if (h < 0) {
      if (arc.b - arc.a < min_width)
        throw InputError("model: the loop is too close to its stability boundary for this checker (c(e^{j pi t}) not "
                         "separated from 0 on an arc of width 2^-100)");
      const rational mid = (arc.a + arc.b) / 2;
      todo.push_back({mid, arc.b});
      todo.push_back({arc.a, mid});
      continue;
    }
    ++decided;
    if (first < 0) first = h;
    else {
      const long step = ((h - last) % 4 + 4) % 4;
      if (step == 2) throw InputError("model: opposite half-planes on adjacent arcs (checker defect)");
      turns += step == 1 ? 1 : step == 3 ? -1 : 0;
    }
    last = h;
  }
  if (first % 2 || last % 2 || turns % 2) throw InputError("model: the ends of the half circle are not real (checker defect)");
  const long inside = turns / 2;
  how = "the argument principle on z = e^{j pi t}, t in [0, 1] (" + std::to_string(decided) +
        " arcs, each with c's rectangle in one half-plane; Arb, " + std::to_string(bits) + " bits): " + std::to_string(inside) + " of the " +
        std::to_string(degree) + " roots inside |z| < 1;";
  if (inside == degree) return {true, "every root inside"};
  return {false, std::to_string(degree - inside) + " root(s) on or outside the unit circle"};
}

/// nullopt when `given` (ascending) is a non-zero multiple of c, else what differs.
std::optional<std::string> differs(const nlohmann::json& given, const P& c) {
  if (!given.is_array() || given.empty()) throw InputError("evidence.charpoly: not a non-empty array of \"p/q\"");
  std::vector<rational> g;
  for (size_t i = 0; i < given.size(); ++i) g.push_back(detail::exact_string(given[i], "evidence.charpoly[" + std::to_string(i) + "]"));
  const P gp(g);
  if (gp.degree() != c.degree())
    return "evidence.charpoly has degree " + std::to_string(gp.degree()) + ", the loop as written " + std::to_string(c.degree());
  const rational ratio = gp.leading() / c.leading();
  for (int i = 0; i <= c.degree(); ++i)
    if (gp.coeff(i) != ratio * c.coeff(i))
      return "evidence.charpoly is not the characteristic polynomial of the loop as written (coefficient of z^" +
             std::to_string(i) + ": " + gp.coeff(i).str() + ", expected " + rational(ratio * c.coeff(i)).str() + ")";
  return std::nullopt;
}

}  // namespace

Verdict check_stability(const nlohmann::json& cert) {
  const auto [written, claim, evidence] = detail::certificate_parts(cert);
  const nlohmann::json model = detail::scene_loop_model(written);  // a scene: its one-DOF loop, read here
  detail::only_fields(claim, {"quantity", "status", "stable"}, "claim");
  detail::only_fields(evidence, {"charpoly", "argument_principle"}, "evidence");
  const bool winding = evidence.contains("argument_principle");
  if (winding && evidence.at("argument_principle") != true)
    throw InputError("evidence.argument_principle: not true (its only value: the checker counts the roots itself)");
  if (winding && evidence.contains("charpoly")) throw InputError("evidence: both charpoly and argument_principle");
  if (!claim.contains("status") || !claim.at("status").is_string() ||
      (claim.at("status") != "exact" && claim.at("status") != "certified"))
    throw InputError("claim.status: missing or neither \"exact\" nor \"certified\"");
  if (!claim.contains("stable") || !claim.at("stable").is_boolean()) throw InputError("claim.stable: missing or not true/false");
  const bool stable = claim.at("stable").get<bool>();
  const LoopCharpoly m = characteristic(model, winding, written.contains("scene"));
  SchurCohn sc;
  std::string what = "the characteristic polynomial (degree " + std::to_string(m.c.degree()) + ", " + m.text + ")";  // not for a spring
  if (m.winding) {  // every pole at s = 0, a long delay: z^n never expanded
    if (claim.at("status") != "certified")
      throw InputError("claim.status: decided by the argument principle, the verdict is \"certified\"");
    std::string how;
    sc = decide_winding(*m.winding, m.A, m.L, how);
    what = "c(z) = z^n P1(z) + P0(z) (" + m.text + ") rebuilt from the model; " + how;
  } else if (m.spring) {  // transcendental Phi: the checker derives c(z) in balls itself
    if (evidence.contains("charpoly"))
      throw InputError("evidence.charpoly: the device has poles off s = 0, so the polynomial's coefficients are not rational");
    if (claim.at("status") != "certified") throw InputError("claim.status: with device poles off s = 0 the verdict is \"certified\"");
    std::string how;
    sc = decide_spring(*m.spring, m.A, m.L, how);
    what = "c(z) (" + m.text + ") rebuilt from the model; " + how;
  } else if (m.c1) {  // transcendental E: no polynomial to hand over, the checker derives c0, c1 itself
    if (evidence.contains("charpoly"))
      throw InputError("evidence.charpoly: the device has a pole off s = 0, so the polynomial's coefficients are not rational");
    if (claim.at("status") != "certified") throw InputError("claim.status: with a device pole off s = 0 the verdict is \"certified\"");
    std::string how;
    sc = decide_family(m.c, *m.c1, *m.x, how);
    what = "c(z; E) = c0 + E c1 (degree " + std::to_string(m.c.degree()) + ", " + m.text + ") rebuilt from the model; " + how;
  } else {
    if (!evidence.contains("charpoly")) throw InputError("evidence.charpoly: missing");
    if (auto why = differs(evidence.at("charpoly"), m.c)) return {false, *why};
    sc = schur_cohn(m.c);
  }
  if (sc.stable != stable)
    return {false, std::string("claim: ") + (stable ? "stable" : "NOT stable") + ", but on " + what + ": " + sc.why};
  return {true, std::string(stable ? "stable" : "NOT stable") + ": " + what + (m.c1 || m.spring || m.winding ? " " : " rebuilt from the model; ") + sc.why};
}

}  // namespace hapstab::check
