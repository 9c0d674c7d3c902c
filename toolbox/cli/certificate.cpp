// cli/certificate.cpp -- see certificate.hpp.
#include "cli/certificate.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/loop_max_certificate.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/check/bound_cells.hpp"
#include "hapstab/check/bound_objective.hpp"
#include "hapstab/check/certificate.hpp"
#include "hapstab/check/stability_loop_check.hpp"
#include "hapstab/check/stability_loop_symmetric_check.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/interval.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/sturm.hpp"
#include "hapstab/sim/loop.hpp"
#include "hapstab/stability/max_evidence.hpp"

namespace hapstab::cli {

namespace {

using QPoly = Polynomial<rational>;

// The checkers' size limit (check/bound_objective.hpp): q (deg H + 1) + P <= 1000.
constexpr long certificate_max_size = 1000;
// Beyond 64 a certified (not exact) b* or K_max has the cells' form even where the expanded one would
// serve: the independent checker expands only to 64 (its Sturm sequences in fractions), and the expanded
// check grows like the cube of the size (degree 236: 20 s) where the cells' does not. Beyond 300 an exact
// one too (its claim then an enclosure: the expanded check there takes minutes), unless H has a pole on
// the unit circle (the cells bound f only where |D|^2 > 0), which keeps the expanded form up to 1000.
constexpr long cells_preferred_size = 64, cells_exact_size = 300;

// The whole delay in samples, nu = n + t_d/T.
rational delay_samples(const passivity::BoundProblem& p) {
  return rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
}

// Whether H has a pole on the unit circle: |D(e^{jw})|^2 = B(cos w) vanishes in [-1, 1] (check/bound_cells.hpp).
bool pole_on_circle(const RationalFunction<rational>& H, const passivity::BoundProblem& p) {
  // the cells' kernel sets a simple pole at z = -1 apart for an integer delay (check/bound_cells.hpp)
  const rational nu = delay_samples(p);
  return !isolate_real_roots(check::detail::kernel_form(H, rational(1), nu, rational(0)).B, rational(-1), rational(1)).empty();
}

// The cells' form for a finite b* or K_max of this size and status (above), or the expanded one; refused
// by name where neither serves in seconds (a pole on the circle beyond 300: the expanded check takes minutes).
bool cells_form(const integer& size, Status status, bool circle_pole) {
  if (size <= cells_preferred_size || (size <= cells_exact_size && status == Status::exact)) return false;
  if (circle_pole && size > cells_exact_size)
    throw InputError("--certificate: H has a pole on the unit circle, which the cells' form (check/bound_cells.hpp) does not "
                     "take, and the expanded form's size " + size.str() + " is beyond " + std::to_string(cells_exact_size) +
                     " (its exact Sturm sequences grow like the cube of the size: 300 takes ~7 s, 900 minutes): no certificate");
  return !circle_pole;
}

// The continued-fraction convergents of x, smallest first, until one satisfies `ok` (at most 400).
template <class Ok>
std::optional<rational> first_convergent(const rational& x, Ok ok) {
  integer h0 = 1, h1 = 0, k0 = 0, k1 = 1;  // h_{-1}/k_{-1} = 1/0, h_{-2}/k_{-2} = 0/1
  integer p = numerator(x), q = denominator(x);
  for (int step = 0; step < 400 && q != 0; ++step) {
    integer a = p / q;
    if (p < 0 && a * q != p) a -= 1;  // floor
    const integer r = p - a * q;
    const integer h = a * h0 + h1, k = a * k0 + k1;
    h1 = h0;
    h0 = h;
    k1 = k0;
    k0 = k;
    const rational c(h, k);
    if (ok(c)) return c;
    p = q;
    q = r;
  }
  return std::nullopt;
}

template <unsigned D>
rational to_rational(const mpfloat<D>& x) {
  return exact_rational(x);
}

// The objective f (without eta) in c = cos(wT/q), tau = n + t_d/T = P/q, on its domain
// [cos(pi/q), 1] (end_lo <= cos(pi/q) <= end_hi, rationals; -1 for q = 1): the producer's own route
// (passivity::objective, and the fractional-delay path's H(w^q)/S(w) for q >= 2).
struct WitnessObjective {
  RationalFunction<rational> f{QPoly(rational(0))};
  long q = 1;
  rational end_lo = -1, end_hi = -1;
};

WitnessObjective witness_objective(const passivity::BoundProblem& p) {
  WitnessObjective w;
  const rational tau = delay_samples(p);
  if (den(tau) == 1) {
    w.f = passivity::objective(p.H, p.T, num(tau).convert_to<int>()).f;
    return w;
  }
  const auto fe = passivity::detail::frac_exact_problem<50>(p, certificate_max_size);
  if (!fe) throw NumericalError("--certificate: the objective in cos(wT/q) could not be formed");
  w.f = passivity::objective(fe->problem.H, fe->problem.T, fe->problem.delay).f;
  w.q = fe->domain.q;
  w.end_lo = fe->domain.end_lo;
  w.end_hi = fe->domain.end_hi;
  return w;
}

// A rational c0 in [end_hi, 1] (inside the domain) with f(c0) >= target (B(c0) != 0).
std::optional<rational> find_witness(const WitnessObjective& o, const rational& target,
                                     const std::optional<Enclosure<rational>>& omega, const rational& T) {
  const RationalFunction<rational>& f = o.f;
  auto ok = [&](const rational& c) {
    if (c < o.end_hi || c > 1) return false;
    const rational d = f.den()(c);
    return d != 0 && f.num()(c) / d >= target;
  };
  for (const rational& c : {rational(1), o.end_hi, rational(0)})
    if (ok(c)) return c;
  if (o.q > 1)  // a maximum at the end wT = pi, irrational for q >= 4: a simpler rational just inside
    if (auto c0 = first_convergent(o.end_hi, ok)) return c0;
  if (omega) {  // cos(w T/q) at the midpoint of the maximiser's enclosure
    using R = mpfloat<300>;
    const rational w = (omega->lo + omega->hi) / 2;
    const R c = cos(R(w * T / rational(o.q)));
    if (auto c0 = first_convergent(to_rational(c), ok)) return c0;
  }
  // every critical point of f in the domain, refined to 2^-1000
  const QPoly crit = f.num().derivative() * f.den() - f.num() * f.den().derivative();
  if (crit.is_zero()) return std::nullopt;
  const rational width = rational(1) / rational(pow(integer(2), 1000));
  for (RootInterval r : isolate_real_roots(crit, o.end_lo, rational(1))) {
    if (!r.is_exact()) r = refine_root(crit, r, width);
    if (ok(r.lo)) return r.lo;
    if (ok(r.hi)) return r.hi;
    if (auto c0 = first_convergent((r.lo + r.hi) / 2, ok)) return c0;
  }
  return std::nullopt;
}

// The checkers expand the delay: their polynomials in cos(wT/q) have size q (deg H + 1) + P
// (check/bound_objective.hpp); InputError beyond their limit.
integer certificate_size(const RationalFunction<rational>& H, const passivity::BoundProblem& p) {
  const rational tau = delay_samples(p);
  return den(tau) * (std::max(H.num().degree(), H.den().degree()) + 1) + num(tau);
}
void check_certificate_size(const RationalFunction<rational>& H, const passivity::BoundProblem& p) {
  const rational tau = delay_samples(p);
  const integer size = certificate_size(H, p);
  if (size > certificate_max_size)
    throw InputError("--certificate: the checkers expand the delay t_d/T = " + to_decimal(tau, 12) +
                     " exactly, in cos(wT/q) with q = " + den(tau).str() + ": size q (deg H + 1) + P = " +
                     (size > integer(1000000000L) ? std::string("> 10^9") : size.str()) + ", beyond their limit of " +
                     std::to_string(certificate_max_size) + " (no certificate)");
}

// --set NAME=VALUE as written, each value an exact "p/q".
nlohmann::json sets_json(const std::vector<std::string>& sets) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : parse_sets(sets)) j[name] = value.str();
  return j;
}

// H(z) as the user wrote it: {"H": --H, "set": --set}, or {"num", "den"} of --num/--den or of the
// .mat's num and den (its doubles exactly), descending powers of z. A .mat state space is refused:
// its transfer function would be hapstab's derivation, not the model as written.
nlohmann::json tf_model_json(const TfOptions& tf) {
  if (!tf.H.empty()) return {{"H", tf.H}, {"set", sets_json(tf.sets)}};
  std::vector<rational> num, den;
  if (!tf.mat.empty()) {
    const MatModel m = read_mat_model(tf.mat, "--mat");
    if (!m.tf)
      throw InputError("--certificate: " + m.where + " holds a state space; a certificate holds H as written (--H, "
                       "--num/--den, or a .mat's num and den): no certificate");
    num = m.tf->first;
    den = m.tf->second;
  } else {
    num = parse_coefficients(tf.num, "--num");
    den = parse_coefficients(tf.den, "--den");
  }
  const auto strings = [](const std::vector<rational>& c) {
    nlohmann::json a = nlohmann::json::array();
    for (const rational& x : c) a.push_back(x.str());
    return a;
  };
  return {{"num", strings(num)}, {"den", strings(den)}};
}

// A certified claim of the enclosure as printed (lo_s, hi_s: decimals rounded outward): status
// "certified", lo and hi those decimals exactly, and the decimals themselves; returns [lo, hi].
Enclosure<rational> printed_enclosure(nlohmann::json& claim, const std::string& lo_s, const std::string& hi_s) {
  const rational lo = parse_rational(lo_s, "enclosure"), hi = parse_rational(hi_s, "enclosure");
  claim["status"] = "certified";
  claim["lo"] = lo.str();
  claim["hi"] = hi.str();
  claim["printed_lo"] = lo_s;
  claim["printed_hi"] = hi_s;
  return {lo, hi};
}

// The model of the one-DOF loop of `stability` as written (plant, H, operator, set, T, delay).
nlohmann::json loop_model_json(const StabilityText& text, const rational& T) {
  if (!text.scene.empty()) return scene_model_json(text.scene, text.sets);  // the checkers read its one-DOF loop themselves
  nlohmann::json m;
  m["plant"] = text.plant;
  m["H"] = text.H;
  if (!text.op.empty()) m["operator"] = text.op;
  m["set"] = sets_json(text.sets);
  m["T"] = T.str();
  m["delay"] = text.delay;
  return m;
}

// b* = +inf: the claim, and the first rational pole c_p of the objective in the band (a root of
// its denominator, met exactly or by a convergent of a refined isolating interval) and side that
// check/ verifies (the objective -> +inf there, check/bound_objective.hpp), or an irrational pole's
// isolating interval (pole_lo, pole_hi) and side; InputError when none. (The pole at the band's end
// wT = pi, z = -1 met by a fractional delay, has the local form: bound_certificate. The checkers still
// take the older evidence (end_lo, end_hi] isolating cos(pi/q).)
nlohmann::json infinite_bound_evidence(nlohmann::json j, nlohmann::json claim, const WitnessObjective& o) {
  claim["status"] = "exact";
  claim["infinite"] = true;
  j["claim"] = claim;
  const QPoly& den = o.f.den();
  std::vector<rational> poles;
  std::vector<RootInterval> irrational;  // isolating intervals of poles with no rational value
  if (den.degree() >= 1)
    for (const RootInterval& r0 : isolate_real_roots(den, o.end_lo, rational(1))) {
      const RootInterval r = r0.is_exact() ? r0 : refine_root(den, r0, rational(1) / rational(pow(integer(2), 200)));
      if (r.is_exact() && den(r.lo) == 0) poles.push_back(r.lo);
      // a convergent of the midpoint inside the interval (an earlier one may be another root: c = 0)
      else if (auto c = first_convergent((r.lo + r.hi) / 2, [&](const rational& x) { return r.lo <= x && x <= r.hi && den(x) == 0; }))
        poles.push_back(*c);
      else if (!r.is_exact()) irrational.push_back(refine_root(den, r0, rational(1) / rational(pow(integer(2), 40))));
    }
  std::vector<nlohmann::json> candidates;
  for (const rational& c : poles)
    for (long side : {-1L, 1L}) candidates.push_back({{"pole_c", c.str()}, {"side", side}});
  // an irrational pole inside the band (H's pole on the circle through t_d/T = p/q): its isolating
  // interval, open, the ends no roots of the objective's denominator
  for (const RootInterval& r : irrational)
    for (long side : {-1L, 1L}) candidates.push_back({{"pole_lo", r.lo.str()}, {"pole_hi", r.hi.str()}, {"side", side}});
  for (const nlohmann::json& e : candidates) {
    j["evidence"] = e;
    try {
      if (check::check_certificate(j).verified) return j;
    } catch (const InputError&) {  // this candidate is not in the checker's terms: the next one
    }
  }
  throw InputError("--certificate: b* = +inf, but no pole of the objective in the band (rational, irrational and isolated, "
                   "or the band's end cos(pi/q)) was shown to send it to +inf: no certificate");
}

}  // namespace

nlohmann::json scene_model_json(const std::string& path, const std::vector<std::string>& sets) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  if (!in) throw InputError("--certificate: cannot read the scene '" + path + "' again");
  return {{"scene", all.str()}, {"set", sets_json(sets)}};
}

nlohmann::json certificate_header(const char* kind) {
  nlohmann::json j;
  j["certificate"] = "hapstab";
  j["version"] = 1;
  j["kind"] = kind;
  j["produced_by"] = std::string("hapstab ") + HAPSTAB_VERSION;  // informative; no time: the same model gives the same file
  return j;
}

// The printed claim proven by check/, or no certificate (never a weaker claim written silently).
void verify_before_writing(const nlohmann::json& j) {
  check::Verdict v;
  try {
    v = check::check_certificate(j);
  } catch (const InputError& e) {
    throw InputError(std::string("--certificate: the checker does not take this model (") + e.what() + "): no certificate");
  }
  if (!v.verified)
    throw InputError("--certificate: the evidence does not prove the printed claim (" + v.reason + "): no certificate");
}


// The cells of check/bound_cells.hpp on which f < hi: a uniform start of ~2 per period 2 pi/nu on
// [0, 355/113] (355/113 > pi), each failing cell halved (at most 60 times); refused by name beyond the
// checkers' limit.
nlohmann::json cells_below(const check::detail::KernelForm& f, const rational& hi, const rational& nu, int degree) {
  const rational end(355, 113);
  const long start = std::max(64L, 2 * (static_cast<long>(to_real<double>(nu)) + 1 + static_cast<long>(degree)));
  nlohmann::json ends = nlohmann::json::array();
  std::vector<std::pair<rational, int>> stack;  // (right end, depth), popped left to right
  rational a(0);
  for (long k = start; k >= 1; --k) stack.emplace_back(end * rational(k, start), 0);
  while (!stack.empty()) {
    const auto [b_end, depth] = stack.back();
    stack.pop_back();
    if (check::detail::cell_below(f, a, b_end, hi)) {
      ends.push_back(b_end.str());
      a = b_end;
      if (ends.size() > check::detail::max_bound_cells)
        throw InputError("--certificate: more than " + std::to_string(check::detail::max_bound_cells) +
                         " cells (the checkers' limit) would be needed: no certificate");
      continue;
    }
    if (depth >= 60)
      throw NumericalError("--certificate: f < " + to_decimal(hi, 15) + " not shown near theta = " + to_decimal(a, 12) +
                           " after 60 halvings (a pole on the circle, or the claim too tight): no certificate");
    stack.emplace_back(b_end, depth + 1);
    stack.emplace_back((a + b_end) / 2, depth + 1);
  }
  return ends;
}

// The kernel form of H (check/bound_cells.hpp) with nu = n + t_d/T; refused by name where H has a pole
// on the unit circle (the cells bound f only where |D|^2 > 0).
check::detail::KernelForm cells_kernel(const RationalFunction<rational>& H, const passivity::BoundProblem& p) {
  const rational nu = delay_samples(p);
  check::detail::KernelForm f = check::detail::kernel_form(H, p.T, nu, p.eta);
  if (!isolate_real_roots(f.B, rational(-1), rational(1)).empty())
    throw InputError("--certificate: H has a pole on the unit circle (|D|^2 vanishes at some cos wT in [-1, 1]), which the "
                     "cells' form (check/bound_cells.hpp) does not take, and the delay is beyond the expanded form's size: "
                     "no certificate");
  return f;
}

// The maximiser of f on [0, pi] in doubles: the best of 16 points per period 2 pi/nu, then Newton on f'
// (f'' < 0), kept inside [0, pi).
rational cells_maximiser(const check::detail::KernelForm& f, const rational& below_pi) {
  const long n = 16 * (static_cast<long>(to_real<double>(f.nu)) + 1 + static_cast<long>(f.B.degree()));
  rational best(0);
  double best_v = -1e300;
  for (long k = 0; k <= n; ++k) {
    const rational t = below_pi * rational(k, n);
    const double v = check::detail::objective_at(f, t).v;
    if (v > best_v) best_v = v, best = t;
  }
  double t = to_real<double>(best);
  for (int it = 0; it < 30; ++it) {
    const check::detail::PointJet j = check::detail::objective_at(f, exact_rational(t));
    if (!(j.dd < 0)) break;
    const double next = std::clamp(t - j.d / j.dd, 0.0, to_real<double>(below_pi));
    if (next == t) break;
    t = next;
  }
  return exact_rational(t);
}

// theta = wT at the midpoint of a maximiser's enclosure (or, where that does not show f > lo, the maximiser
// found by cells_maximiser), kept below pi; refused by name unless f > lo there.
rational cells_witness(const check::detail::KernelForm& f, const std::optional<Enclosure<rational>>& omega, const rational& T,
                       const rational& lo) {
  const rational below_pi(314159265358979L, 100000000000000L);
  rational theta = omega ? (omega->lo + omega->hi) / 2 * T : rational(0);
  if (theta > below_pi) theta = below_pi;
  if (!check::detail::point_above(f, theta, lo)) theta = cells_maximiser(f, below_pi);
  if (!check::detail::point_above(f, theta, lo))
    throw NumericalError("--certificate: the objective at the maximiser (theta = " + to_decimal(theta, 12) + ") was not shown above " +
                         to_decimal(lo, 15) + ": no certificate");
  return theta;
}

// b* beyond the expanded form's size (a long delay): the cells of check/bound_cells.hpp and a witness
// at the maximiser; the claim b*'s enclosure widened by 10^-13 of its size and printed to 12 digits
// outward (the cells need f < hi strictly).
nlohmann::json bound_cells_evidence(const passivity::BoundProblem& p, const passivity::Bound& b, nlohmann::json& claim) {
  const Enclosure<rational>& e = *b.enclosure;
  const rational size = std::max({rational(abs(e.lo)), rational(abs(e.hi)), p.T});
  const rational delta = size / rational(pow(integer(10), 13));
  const auto [lo, hi] = printed_enclosure(claim, decimal_outward(e.lo - delta, 12, -1), decimal_outward(e.hi + delta, 12, +1));
  const check::detail::KernelForm f = cells_kernel(p.H, p);
  const rational theta0 = cells_witness(f, b.omega_enclosure, p.T, lo);
  return {{"cells", cells_below(f, hi, f.nu, p.H.den().degree())}, {"witness_theta", theta0.str()}};
}

// bound --max beyond the expanded form's size: K_max's enclosure widened by 10^-12 and printed to 12
// digits outward; b0 halfway between b*(0) and b; the cells of f at K = 0 below b0 and at K = lo below
// b, the witness of f at K = hi above b (check/bound_max_check.hpp); K_max = 0 by the witness at 0.
nlohmann::json bound_max_cells_evidence(const passivity::GainProblem& g, const passivity::MaxGain& m, nlohmann::json& claim) {
  const auto at = [&](const rational& k) { return cells_kernel(g.base.H + RationalFunction<rational>(k) * g.H1, g.base); };
  const int degree = std::max(g.base.H.den().degree(), g.H1.den().degree());
  if (m.outcome == Outcome::fails) {
    // K_max = 0 with b*(0) < b: b* = +inf for every K > 0 (the part in K's pole at z = -1 met by the fractional
    // delay, check/bound_max_check.cpp jump_fails at hi = 0); else b*(0) >= b, by the witness at K = 0
    if (!m.at_zero.infinite && m.at_zero.enclosure && m.at_zero.enclosure->hi < g.b) return {{"jump_at_z", "-1"}};
    return {{"witness_theta", cells_witness(at(rational(0)), m.at_zero.omega_enclosure, g.base.T, g.b).str()}};
  }
  const Enclosure<rational>& e = *m.enclosure;
  const rational widen = rational(1) / rational(pow(integer(10), 12));
  Enclosure<rational> claimed{m.value, m.value};
  if (m.jump) {  // K_max exact at a jump of b* (MaxGain::jump): b*(K_max) < b by cells, +inf above by the residue at z = -1
    claim["status"] = "exact";
    claim["value"] = m.value.str();
  } else {
    claimed = printed_enclosure(claim, decimal_outward(e.lo * (1 - widen), 12, -1), decimal_outward(e.hi * (1 + widen), 12, +1));
  }
  const rational b0 = (m.at_zero.enclosure->hi + g.b) / 2;
  nlohmann::json ev;
  ev["b0_hi"] = b0.str();
  ev["cells_at_0"] = cells_below(at(rational(0)), b0, at(rational(0)).nu, degree);
  ev["cells_at_lo"] = cells_below(at(claimed.lo), g.b, at(claimed.lo).nu, degree);
  if (m.jump) ev["jump_at_z"] = "-1";
  else ev["witness_theta"] = cells_witness(at(claimed.hi), m.omega, g.base.T, g.b).str();
  return ev;
}

nlohmann::json bound_certificate(const TfOptions& tf, const passivity::BoundProblem& p,
                                 const passivity::Bound& b, int digits) {
  // a finite b* beyond the sizes above has the cells' evidence (check/bound_cells.hpp); b* = +inf from H's
  // pole at z = -1 met by a fractional delay (t_d/T not whole) the local form, at any size (check/bound_check.hpp)
  const bool long_delay = !b.infinite && b.enclosure && cells_form(certificate_size(p.H, p), b.status, pole_on_circle(p.H, p));
  const rational nu = delay_samples(p);
  const bool at_minus_one = b.infinite && den(nu) != 1 && p.H.den()(rational(-1)) == 0;
  // b* = +inf [certified]: a simple pole on the circle inside the band, shown where it is (circle_pole.cpp)
  const bool on_circle = b.infinite && b.status == Status::certified;
  const bool integrator = b.infinite && p.H.den()(rational(1)) == 0;  // H's pole at z = 1: the form below, nothing expanded
  if (!long_delay && !at_minus_one && !on_circle && !integrator) check_certificate_size(p.H, p);
  if (!b.infinite && b.status != Status::exact && b.status != Status::certified)
    throw InputError("--certificate: b* is numeric here (--method fast or grid); a certificate needs --method certified");
  nlohmann::json j = certificate_header("bound");
  nlohmann::json m = tf_model_json(tf);
  m["T"] = p.T.str();
  m["delay"] = p.delay;
  if (p.frac_delay) m["frac_delay"] = p.frac_delay->str();
  m["eta"] = p.eta.str();
  j["model"] = m;
  nlohmann::json claim;
  claim["quantity"] = p.frac_delay ? "b* = sup_{0 <= w <= pi/T} Re{T H(z) z^-n e^{-j w t_d}/(1 - z)} + eta, z = e^{jwT} (paper 001, (45)/(54))"
                                   : "b* = sup_{0 <= w <= pi/T} Re{T H(z) z^-n/(1 - z)} + eta, z = e^{jwT} (paper 001, (45)/(54))";
  if (integrator) {  // +inf whatever the residue's sign (check/bound_check.cpp, check_integrator)
    // the objective's own pole first, where the expanded form fits (a positive residue: (45) -> +inf at w = 0)
    if (certificate_size(p.H, p) <= certificate_max_size) {
      try {
        return infinite_bound_evidence(j, claim, witness_objective(p));
      } catch (const InputError&) {  // a negative residue: (45) -> -inf there; bound's definition, the form below
      }
    }
    claim["status"] = "exact";
    claim["infinite"] = true;
    j["claim"] = claim;
    j["evidence"] = {{"integrator", true}};
    verify_before_writing(j);
    return j;
  }
  if (at_minus_one) {  // the sign at z = -1 may be -inf while another pole gives +inf: then the forms below
    nlohmann::json local = j;
    local["claim"] = claim;
    local["claim"]["status"] = "exact";
    local["claim"]["infinite"] = true;
    local["evidence"] = {{"pole_at_z", "-1"}};
    check::Verdict v;
    try {
      v = check::check_certificate(local);
    } catch (const InputError& e) {  // beyond the checkers' terms (a delay above 100000)
      throw InputError(std::string("--certificate: the checkers do not take this model (") + e.what() + "): no certificate");
    }
    if (v.verified) return local;
    check_certificate_size(p.H, p);
  }
  if (on_circle) {  // the local form at any size: q(c) exact, cos(theta0) isolated (check/bound_check.hpp)
    const auto pole = passivity::detail::circle_pole(p);
    if (!pole) throw NumericalError("--certificate: the pole on the circle that gave b* = +inf was not found again");
    claim["status"] = "certified";
    claim["infinite"] = true;
    j["claim"] = claim;
    nlohmann::json q = nlohmann::json::array();
    for (const rational& a : pole->q.coeffs()) q.push_back(a.str());
    j["evidence"] = {{"pole_on_circle", {{"q", q}, {"c_lo", pole->c_lo.str()}, {"c_hi", pole->c_hi.str()}}}};
    verify_before_writing(j);
    return j;
  }
  if (b.infinite) return infinite_bound_evidence(j, claim, witness_objective(p));
  if (long_delay) {
    j["evidence"] = bound_cells_evidence(p, b, claim);
    j["claim"] = claim;
    verify_before_writing(j);
    return j;
  }
  rational target;
  if (b.status == Status::exact) {
    claim["status"] = "exact";
    claim["value"] = b.value.str();
    target = b.value;
  } else {
    const auto [lo, hi] = passivity::reported_enclosure(b, digits);  // what is printed, rounded outward
    target = printed_enclosure(claim, lo, hi).lo;
  }
  j["claim"] = claim;
  const WitnessObjective obj = witness_objective(p);
  const auto c0 = find_witness(obj, target - p.eta, b.omega_enclosure, p.T);
  if (!c0) throw NumericalError("--certificate: no rational witness c0 with f(c0) >= " + target.str() + " was found");
  j["evidence"] = {{"witness_c", c0->str()}};
  if (obj.q > 1) j["evidence"]["domain_c_lo"] = obj.end_lo.str();  // <= cos(pi/q): the checkers' interval [c_lo, 1]
  // checked before it is written: a b* the producer got wrong (a pole it missed) is refused by name
  // here, not written as a certificate both checkers refute (issue 46's indep_bound_inf_inside)
  verify_before_writing(j);
  return j;
}

namespace {

// A bound-max certificate's header, its model as written and its claim's quantity (check/bound_max_check.hpp).
nlohmann::json bound_max_header(const TfOptions& tf, const passivity::GainProblem& g, nlohmann::json& claim) {
  nlohmann::json j = certificate_header("bound-max");
  nlohmann::json mo;
  mo["H"] = tf.H;
  mo["set"] = sets_json(tf.sets);
  mo["name"] = g.name;
  mo["T"] = g.base.T.str();
  mo["delay"] = g.base.delay;
  if (g.base.frac_delay) mo["frac_delay"] = g.base.frac_delay->str();
  mo["eta"] = g.base.eta.str();
  mo["damping"] = g.b.str();
  j["model"] = mo;
  const std::string& K = g.name;
  claim["quantity"] = K + "_max = sup{" + K + "0 >= 0 : b*(" + K + ") < b for every " + K + " in [0, " + K +
                      "0)}, H = H0 + " + K + " H1, b* of paper 001 (45)/(54), b = model.damping";
  return j;
}

// bound --max with K_max = 0 by b*(0) = +inf (check/bound_max_check.cpp, at_zero_infinite_form): the evidence
// of `bound`'s certificate of b* = +inf for H at K = 0 (written, and verified, by bound_certificate with
// --set K=0), the claim K_max = 0 with that certificate's status.
nlohmann::json bound_max_at_zero_infinite(const TfOptions& tf, const passivity::GainProblem& g, const passivity::Bound& at_zero,
                                          int digits) {
  TfOptions at0 = tf;
  at0.sets.push_back(g.name + "=0");
  const nlohmann::json c0 = bound_certificate(at0, g.base, at_zero, digits);
  nlohmann::json claim;
  nlohmann::json j = bound_max_header(tf, g, claim);
  claim["status"] = c0.at("claim").at("status");
  if (claim["status"] == "exact") claim["value"] = "0";
  else claim["lo"] = claim["hi"] = "0";
  j["claim"] = claim;
  j["evidence"] = {{"at_zero_infinite", c0.at("evidence")}};
  verify_before_writing(j);
  return j;
}

}  // namespace

nlohmann::json bound_max_certificate(const TfOptions& tf, const passivity::BoundMax& r, int digits) {
  const passivity::GainProblem& g = r.problem;
  const passivity::MaxGain& m = r.max;
  const std::string K = g.name;
  if (tf.H.empty())
    throw InputError("--certificate: --max needs H as an expression in its parameter (--H), not --num/--den or --mat");
  if (m.status != Status::exact && m.status != Status::certified)
    throw InputError("--certificate: sup " + K + " is not certified here: no certificate");
  if (m.outcome == Outcome::undecided) throw InputError("--certificate: sup " + K + " is undecided: no claim to certify");
  // K_max = 0 by H's uncancelled pole at z = 1 (an integrator, in H0 or in the part in K; check/bound_max_check.cpp):
  // b* = +inf at K = 0 or at every K > 0, nothing expanded
  const bool integrator = m.outcome == Outcome::fails && (g.base.H.den()(rational(1)) == 0 || g.H1.den()(rational(1)) == 0);
  if (m.outcome == Outcome::fails && m.at_zero.infinite && !integrator)  // K_max = 0 by b*(0) = +inf, at any size
    return bound_max_at_zero_infinite(tf, g, m.at_zero, digits);
  // beyond the expanded form's size: the cells' form (bound_max_cells_evidence)
  const integer size = std::max(certificate_size(g.base.H, g.base), certificate_size(g.H1, g.base));
  const bool long_delay = !integrator && (size > certificate_max_size ||
                                          (!m.infinite && m.outcome != Outcome::fails &&
                                           cells_form(size, m.status, pole_on_circle(g.base.H, g.base) || pole_on_circle(g.H1, g.base))));
  if (long_delay && m.infinite)
    throw InputError("--certificate: sup " + K + " = +inf beyond the expanded form's size has no cells' form: no certificate");
  if (!long_delay && !integrator) {
    check_certificate_size(g.base.H, g.base);
    check_certificate_size(g.H1, g.base);
  }
  nlohmann::json claim;
  nlohmann::json j = bound_max_header(tf, g, claim);
  claim["status"] = to_string(m.status);
  if (integrator) {
    claim["status"] = "exact";
    claim["value"] = "0";
    j["claim"] = claim;
    j["evidence"] = {{"integrator", true}};
    verify_before_writing(j);
    return j;
  }
  if (long_delay) {
    if (m.outcome == Outcome::fails) {
      claim["status"] = "exact";
      claim["value"] = "0";
    } else if (!m.enclosure || !m.at_zero.enclosure) {
      throw InputError("--certificate: sup " + K + " or b*(0) has no enclosure: no certificate");
    }
    j["evidence"] = bound_max_cells_evidence(g, m, claim);
    j["claim"] = claim;
    verify_before_writing(j);
    return j;
  }
  nlohmann::json evidence;
  const bool zero = m.outcome == Outcome::fails;
  std::optional<rational> hi;
  if (m.infinite) {
    claim["infinite"] = true;
  } else if (zero) {  // b*(0) >= b: K_max = 0
    claim["status"] = "exact";
    claim["value"] = "0";
    hi = rational(0);
  } else {
    if (!m.enclosure) throw InputError("--certificate: sup " + K + " has no enclosure: no certificate");
    if (m.status == Status::exact) {
      claim["value"] = m.value.str();
      hi = m.value;
    } else {  // what is printed: the enclosure rounded outward at digits + 3 (cli/bound_max.cpp)
      hi = printed_enclosure(claim, decimal_outward(m.enclosure->lo, digits + 3, -1), decimal_outward(m.enclosure->hi, digits + 3, +1)).hi;
    }
  }
  if (!zero) {  // b*(0) <= b0 < b, the printed b*(0) rounded outward
    if (m.at_zero.infinite || !m.at_zero.enclosure) throw InputError("--certificate: b*(0) has no enclosure");
    const rational b0 = parse_rational(passivity::reported_enclosure(m.at_zero, digits).hi, "b*(0)");
    if (b0 >= g.b) throw InputError("--certificate: b*(0) is not shown below b at " + std::to_string(digits) + " digits; raise --digits");
    evidence["b0_hi"] = b0.str();
  }
  // K_max = 0 with b*(0) < b: b* = +inf for every K > 0 (psi unbounded: the part in K's pole at z = -1 met by the
  // fractional delay), the jump form at hi = 0; a cause the form does not take is refused by name below
  const bool jump_at_zero = zero && !m.at_zero.infinite && m.at_zero.enclosure && m.at_zero.enclosure->hi < g.b;
  if (hi && (m.jump || jump_at_zero)) {  // b* = +inf above hi: the residue at z = -1 changes sign there (MaxGain::jump)
    evidence["jump_at_z"] = "-1";
    const WitnessObjective obj = witness_objective(passivity::at_gain(g, *hi));
    if (obj.q > 1) evidence["domain_c_lo"] = obj.end_lo.str();
  } else if (hi) {  // b*(hi) >= b: a witness for H0 + hi H1
    passivity::BoundProblem p = passivity::at_gain(g, *hi);
    const WitnessObjective obj = witness_objective(p);
    const auto omega = zero ? m.at_zero.omega_enclosure : m.omega;
    const auto c1 = find_witness(obj, g.b - p.eta, omega, p.T);
    if (!c1) throw NumericalError("--certificate: no rational witness c1 with b*(" + K + " = " + hi->str() + ") >= b was found");
    evidence["witness_c"] = c1->str();
    if (obj.q > 1) evidence["domain_c_lo"] = obj.end_lo.str();
  } else {
    const WitnessObjective obj = witness_objective(g.base);
    if (obj.q > 1) evidence["domain_c_lo"] = obj.end_lo.str();
  }
  j["claim"] = claim;
  j["evidence"] = evidence;
  if (jump_at_zero) verify_before_writing(j);
  return j;
}

nlohmann::json matrix_json(const Mat<rational>& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < M.cols(); ++j) row.push_back(M(i, j).str());
    rows.push_back(row);
  }
  return rows;
}

namespace {

// The claim of Lemma 1's lower bound (check/passivity_level*_check.hpp): "lower_bound", or "bounds" where the
// frequency value's hi is written beside it; lo as printed (rounded down). `for_what` names what P is of.
void lemma1_claim(nlohmann::json& claim, bool osp, bool upper, const rational& lower_bound, int digits, const std::string& for_what) {
  const std::string printed = decimal_outward(lower_bound, digits, -1);
  claim["quantity"] = std::string(osp ? "delta*" : "phi*") + ", the level of paper 000 Definition 2 by Lemma 1, >= lo" +
                      (upper ? " and <= hi (the frequency value, not the level here: an OSP value <= 0)" : "") +
                      ": lo by Lemma 1's LMI (2) at the rounded P" + for_what;
  claim["status"] = upper ? "bounds" : "lower_bound";
  claim["lo"] = parse_rational(printed, "lower bound").str();
  claim["printed_lo"] = printed;
}

}  // namespace

nlohmann::json passivity_level_certificate(const TfOptions& tf, const RationalFunction<rational>& G, bool osp,
                                           const lmi::PassivityLevel& c, const lmi::PassivityLevel& l, bool is_level,
                                           bool upper_only, int digits) {
  // not the level (the LMI's numeric level is the result): its exactly checked lower bound, with P
  const bool lemma1 = !is_level && l.lower_bound && l.lemma1_P;
  if (!lemma1 && c.status != Status::exact && c.status != Status::certified)
    throw InputError("--certificate: the level is not certified here (the certified frequency path gave none): no certificate");
  if (!lemma1 && ((!is_level && !upper_only) || !c.enclosure))
    throw InputError("--certificate: the certified frequency value is not the result printed here: no certificate");
  const bool upper = upper_only && c.enclosure;  // the frequency value's hi, witnessed
  nlohmann::json j = certificate_header("passivity-level");
  j["model"] = tf_model_json(tf);
  const rational T = parse_rational(tf.T, "--T");
  j["model"]["T"] = T.str();
  j["model"]["kind"] = osp ? "osp" : "isp";
  nlohmann::json claim;
  claim["quantity"] = osp ? "delta* = min_{0 <= theta <= pi} Re(1/G(e^{j theta})), the OSP level of paper 000 Definition 2 (Lemma 1)"
                          : "phi* = min_{0 <= theta <= pi} Re G(e^{j theta}), the ISP level of paper 000 Definition 2 (Lemma 1)";
  nlohmann::json evidence = nlohmann::json::object();
  rational hi;
  if (lemma1) {  // level >= lo by Lemma 1 at P for G's realisation (tf2ss, the one the LMI solved), lo as printed
    lemma1_claim(claim, osp, upper, *l.lower_bound, digits, ", for the realisation (A, B, C, D) of G in the evidence");
    const StateSpace<rational> r = tf2ss(TransferFunction{G, Domain::z, T});
    evidence = {{"A", matrix_json(r.A)}, {"B", matrix_json(r.B)}, {"C", matrix_json(r.C)}, {"D", matrix_json(r.D)},
                {"P", matrix_json(*l.lemma1_P)}};
    if (!upper) {
      j["claim"] = claim;
      j["evidence"] = evidence;
      verify_before_writing(j);
      return j;
    }
    const std::string printed_hi = decimal_outward(c.enclosure->hi, digits, +1);
    hi = parse_rational(printed_hi, "enclosure");
    claim["hi"] = hi.str();
    claim["printed_hi"] = printed_hi;
  } else if (upper_only) {  // the level <= hi only (Lemma 1 also needs P > 0; check/passivity_level_check.hpp)
    claim["quantity"] = std::string(osp ? "delta*" : "phi*") +
                        ", the level of paper 000 Definition 2, <= hi: an upper bound only (the frequency value is not "
                        "the level here: an OSP value <= 0, or a zero of G on the unit circle)";
    claim["status"] = "upper_bound";
    const std::string printed = decimal_outward(c.enclosure->hi, digits, +1);
    hi = parse_rational(printed, "enclosure");
    claim["hi"] = hi.str();
    claim["printed_hi"] = printed;
  } else if (c.status == Status::exact && c.enclosure->lo == c.enclosure->hi) {
    claim["status"] = "exact";
    claim["value"] = c.enclosure->lo.str();
    hi = c.enclosure->lo;
  } else {  // the enclosure as printed, rounded outward (cmd_passivity_level.cpp)
    hi = printed_enclosure(claim, decimal_outward(c.enclosure->lo, digits, -1), decimal_outward(c.enclosure->hi, digits, +1)).hi;
  }
  j["claim"] = claim;
  // Re W = -f with f the objective of (z - 1) W at T = 1 (the producer's route): a witness with f >= -hi
  const QPoly zm1{rational(-1), rational(1)};
  const RationalFunction<rational> W = osp ? RationalFunction<rational>(G.den(), G.num()) : G;
  WitnessObjective obj;
  obj.f = passivity::objective(RationalFunction<rational>(zm1 * W.num(), W.den()), rational(1), 0).f;
  std::optional<Enclosure<rational>> theta;
  if (c.theta_min >= 0) theta = Enclosure<rational>{exact_rational(c.theta_min), exact_rational(c.theta_min)};
  const auto c0 = find_witness(obj, -hi, theta, rational(1));
  if (!c0) throw NumericalError("--certificate: no rational witness c0 with Re W(c0) <= " + hi.str() + " was found");
  evidence["witness_c"] = c0->str();
  j["evidence"] = evidence;
  verify_before_writing(j);  // a hypothesis the checkers verify (no zero of G on the circle for OSP) may fail
  return j;
}


namespace {

// Rational points of the unit circle near c = cos(theta), theta in [0, pi], as {witness_c, witness_s}:
// z = (1 - t^2 + 2jt)/(1 + t^2) with t ~ tan(theta/2) = sqrt((1 - c)/(1 + c)) to 40, 80, 160 digits
// (rounded down and up); c = +-1 exactly when c is.
std::vector<nlohmann::json> circle_witnesses(const rational& c) {
  auto point = [](const rational& cc, const rational& ss) { return nlohmann::json{{"witness_c", cc.str()}, {"witness_s", ss.str()}}; };
  if (c >= 1) return {point(rational(1), rational(0))};
  if (c <= -1) return {point(rational(-1), rational(0))};
  std::vector<nlohmann::json> out;
  const rational u = (1 - c) / (1 + c);
  for (int digits : {40, 80, 160}) {
    integer scale = 1;
    for (int k = 0; k < digits; ++k) scale *= 10;
    const integer r = bmp::sqrt(integer(num(u) * scale * scale / den(u)));
    for (const integer& k : {r, integer(r + 1)}) {
      const rational t(k, scale), w = 1 + t * t;
      out.push_back(point((1 - t * t) / w, 2 * t / w));
    }
  }
  return out;
}

}  // namespace

nlohmann::json passivity_level_mimo_certificate(const StateSpace<rational>& sys, bool osp, const lmi::PassivityLevel& c,
                                                const lmi::PassivityLevel& l, bool is_level, bool upper_only, int digits) {
  // not the level (the LMI's numeric level is the result): its exactly checked lower bound, with P
  const bool lemma1 = !is_level && l.lower_bound && l.lemma1_P;
  if (!lemma1 && c.status != Status::exact && c.status != Status::certified)
    throw InputError("--certificate: the level is not certified here (the certified frequency path gave none: " +
                     (c.note.empty() ? std::string("no reason given") : c.note) + "): no certificate");
  if (!lemma1 && ((!is_level && !upper_only) || !c.enclosure))
    throw InputError("--certificate: the certified frequency value is not the level here: no certificate");
  if (!lemma1 && !upper_only && osp && c.enclosure->lo <= 0)
    throw InputError("--certificate: an OSP value <= 0 bounds Lemma 1's level only from above (it is not the level): no "
                     "certificate");
  const bool upper = upper_only && c.enclosure;  // the frequency value's hi, witnessed on the circle
  nlohmann::json j = certificate_header("passivity-level-mimo");
  j["model"] = {{"A", matrix_json(sys.A)}, {"B", matrix_json(sys.B)}, {"C", matrix_json(sys.C)},
                {"D", matrix_json(sys.D)}, {"T", sys.T.str()}, {"kind", osp ? "osp" : "isp"}};
  nlohmann::json claim;
  claim["quantity"] = osp ? "delta* = sup {nu : He G - nu G^H G >= 0 on the unit circle} = min_{0 <= theta <= pi} "
                            "lambda_min(He G^-1(e^{j theta})), He G = (G + G^H)/2, G = C(zI - A)^-1 B + D: the OSP level of "
                            "paper 000 Definition 2 (Lemma 1)"
                          : "phi* = min_{0 <= theta <= pi} lambda_min(He G(e^{j theta})), He G = (G + G^H)/2, G = C(zI - A)^-1 B + D: "
                            "the ISP level of paper 000 Definition 2 (Lemma 1)";
  const bool exact = !upper_only && !lemma1 && c.status == Status::exact && c.enclosure->lo == c.enclosure->hi;
  const auto put_hi = [&] {
    const std::string printed = decimal_outward(c.enclosure->hi, digits, +1);
    claim["hi"] = parse_rational(printed, "enclosure").str();
    claim["printed_hi"] = printed;
  };
  if (lemma1) {  // level >= lo by Lemma 1 at P (check/passivity_level_mimo_check.hpp), lo as printed; with hi beside
    lemma1_claim(claim, osp, upper, *l.lower_bound, digits, "");
    if (upper) put_hi();
  } else if (upper_only) {  // the level <= hi only (check/passivity_level_mimo_check.hpp), hi as printed
    claim["quantity"] = std::string(osp ? "delta*" : "phi*") +
                        ", the level of paper 000 Definition 2, <= hi: an upper bound only (the frequency value is not the "
                        "level here: an OSP value <= 0)";
    claim["status"] = "upper_bound";
    put_hi();
  } else if (exact) {
    claim["status"] = "exact";
    claim["value"] = c.enclosure->lo.str();
  } else {  // the enclosure as printed, rounded outward (cmd_passivity_level.cpp)
    printed_enclosure(claim, decimal_outward(c.enclosure->lo, digits, -1), decimal_outward(c.enclosure->hi, digits, +1));
  }
  j["claim"] = claim;
  std::vector<nlohmann::json> candidates{nlohmann::json::object()};
  if (!exact && (!lemma1 || upper)) {
    if (!c.c_min && c.theta_min < 0)
      throw NumericalError("--certificate: the certified MIMO path gave no minimiser to place the witness at");
    candidates = circle_witnesses(c.c_min ? *c.c_min : exact_rational(std::cos(c.theta_min)));
  }
  std::string why;
  for (nlohmann::json e : candidates) {  // the first that check/ verifies
    if (lemma1) e["P"] = matrix_json(*l.lemma1_P);
    j["evidence"] = e;
    const check::Verdict v = check::check_certificate(j);
    if (v.verified) return j;
    why = v.reason;
  }
  throw NumericalError("--certificate: no witness found that proves the printed claim (check/: " + why + ")");
}

nlohmann::json r_certificate(const rational& T, const rational& omega, const std::string& printed_im, int digits) {
  nlohmann::json j = certificate_header("r");
  j["model"] = {{"T", T.str()}, {"omega", omega.str()}};
  const rational im = parse_rational(printed_im, "Im r");
  rational u = abs(im);
  for (int k = 1; k < digits; ++k) u /= 10;
  nlohmann::json claim;
  claim["quantity"] = "r(jw) = T/(e^{jwT} - 1) (paper 001, (44))";
  claim["re"] = rational(-T / 2).str();
  claim["im_lo"] = rational(im - u).str();
  claim["im_hi"] = rational(im + u).str();
  claim["printed_im"] = printed_im;
  j["claim"] = claim;
  j["evidence"] = nlohmann::json::object();
  return j;
}

namespace {

int poles_off_zero(const stability::Loop& loop) {
  const QPoly den = stability::effective_device(loop).den();
  int k = 0;
  while (k < den.degree() && den.coeff(k) == 0) ++k;
  return den.degree() - k;
}

}  // namespace

bool beyond_stability_kind(const stability::Loop& loop) { return poles_off_zero(loop) > 2; }

nlohmann::json stability_evidence(const stability::Loop& loop) {
  const QPoly den = stability::effective_device(loop).den();
  const int off_zero = poles_off_zero(loop);  // device poles off s = 0
  if (off_zero > 2)
    throw InputError("--certificate: the stability kind takes devices with every pole at s = 0 (a mass 1/(m*s^2)), one "
                     "real pole off it (a mass-damper 1/(m*s^2 + b*s)) or two (a spring 1/(m*s^2 + b*s + k)); more "
                     "have the kind stability-loop (the closed-loop matrix)");
  // the degree of c = z^n L D_d + A N_d, as the checkers count it (deg L + n + the device's order)
  const long degree = loop.delay + loop.H.den().degree() + den.degree();
  if (degree > (off_zero ? 150 : 2000)) {
    // never expanded: the checkers count the roots inside by the argument principle on the circle
    // (check/stability_check.hpp), e^{pT} or e^{A_c T} in balls
    if (loop.delay > 100000)
      throw InputError("--certificate: a delay above the checkers' limit of 100000 samples");
    return {{"argument_principle", true}};
  }
  const std::optional<QPoly> c = stability::exact_characteristic(loop);
  if (!c) {
    // one simple real pole off s = 0 (a mass-damper) or two (a spring): the checkers derive the
    // loop's polynomial and enclose e^{pT} or e^{A_c T} themselves (check/loop_model.hpp): no
    // evidence to hand over
    return nlohmann::json::object();
  }
  if (c->degree() > 2000)
    throw InputError("--certificate: the characteristic polynomial has degree " + std::to_string(c->degree()) +
                     ", beyond the checkers' limit of 2000");
  nlohmann::json coeffs = nlohmann::json::array();
  for (const rational& x : c->coeffs()) coeffs.push_back(x.str());
  return {{"charpoly", coeffs}};
}

nlohmann::json stability_certificate(const StabilityText& text, const stability::Loop& loop,
                                     const stability::StabilityResult& r, const nlohmann::json& evidence) {
  if (!r.verdict.decided()) throw InputError("--certificate: the verdict is undecided: there is no claim to certify");
  nlohmann::json j = certificate_header("stability");
  j["model"] = loop_model_json(text, loop.T);
  j["claim"] = {{"quantity", "Schur stability of the sampled loop: device P(s) behind a zero-order hold, force = -z^-n H(z) x(kT)"},
                {"stable", r.verdict.holds()},
                {"status", to_string(r.verdict.status)}};
  j["evidence"] = evidence;
  // without a charpoly the checkers prove by enclosures: "certified" (an exact verdict, a root at
  // z = 1, is weakened to it)
  if (!evidence.contains("charpoly")) j["claim"]["status"] = "certified";
  // the checker decides alone, or reads the scene itself: refuse what it cannot verify
  if (!evidence.contains("charpoly") || !text.scene.empty()) verify_before_writing(j);
  return j;
}

namespace {

// A basis of ker M (columns), exactly: reduced row echelon form, one vector per free column.
MatQ kernel_basis(MatQ M) {
  const Eigen::Index rows = M.rows(), cols = M.cols();
  std::vector<Eigen::Index> pivots;
  Eigen::Index r = 0;
  for (Eigen::Index c = 0; c < cols && r < rows; ++c) {
    Eigen::Index p = r;
    while (p < rows && M(p, c).is_zero()) ++p;
    if (p == rows) continue;
    M.row(p).swap(M.row(r));
    const rational lead = M(r, c);
    for (Eigen::Index k = 0; k < cols; ++k) M(r, k) /= lead;
    for (Eigen::Index i = 0; i < rows; ++i)
      if (i != r && !M(i, c).is_zero()) {
        const rational f = M(i, c);
        for (Eigen::Index k = 0; k < cols; ++k) M(i, k) -= f * M(r, k);
      }
    pivots.push_back(c);
    ++r;
  }
  MatQ K = MatQ::Zero(cols, cols - static_cast<Eigen::Index>(pivots.size()));
  Eigen::Index j = 0;
  for (Eigen::Index c = 0; c < cols; ++c) {
    if (std::find(pivots.begin(), pivots.end(), c) != pivots.end()) continue;
    K(c, j) = 1;
    for (size_t i = 0; i < pivots.size(); ++i) K(pivots[i], j) = -M(static_cast<Eigen::Index>(i), c);
    ++j;
  }
  return K;
}

// The unobservable subspace of (A, C) as columns V with A V = V A_h, or (transposed) the uncontrollable
// one of (A, B) as rows W with W A = A_h W: {basis, A_h}; nullopt when there is none.
std::optional<std::pair<MatQ, MatQ>> hidden_subspace(const StateSpace<rational>& s, bool unobservable) {
  const Eigen::Index n = s.A.rows();
  const MatQ A = unobservable ? MatQ(s.A) : MatQ(s.A.transpose()), C = unobservable ? MatQ(s.C) : MatQ(s.B.transpose());
  MatQ O(C.rows() * n, n), blockp = C;
  for (Eigen::Index k = 0; k < n; ++k) {
    O.middleRows(k * C.rows(), C.rows()) = blockp;
    blockp = exact_product(blockp, A);
  }
  const MatQ V = kernel_basis(O);
  if (V.cols() == 0) return std::nullopt;
  const MatQ Vt = V.transpose();
  const MatQ Ah = exact_solve(exact_product(Vt, V), exact_product(Vt, exact_product(A, V)), "the hidden subspace's Gram matrix");
  if (unobservable) return std::pair<MatQ, MatQ>{V, Ah};
  return std::pair<MatQ, MatQ>{Vt, MatQ(Ah.transpose())};  // W = V^T: W A_orig = A_h W with A_h = Ah^T
}

}  // namespace

std::optional<nlohmann::json> hidden_mode_certificate(const StabilityText& text, const rational& T, const sim::LoopSpec& spec) {
  struct Candidate {
    std::string block, name;  ///< name: devices and operators only
    const StateSpace<rational>* ss;
  };
  std::vector<Candidate> blocks;
  if (spec.environment) blocks.push_back({"environment", "", &*spec.environment});
  if (spec.coupling) blocks.push_back({"coupling", "", &*spec.coupling});
  for (const auto& d : spec.devices) blocks.push_back({"device", d.name, &d.G});
  for (const auto& o : spec.operators) blocks.push_back({"operator", o.name, &o.Z});
  for (const Candidate& b : blocks) {
    if (b.ss->A.rows() == 0) continue;
    for (const bool unobservable : {false, true}) {
      const auto h = hidden_subspace(*b.ss, unobservable);
      if (!h) continue;
      nlohmann::json j = certificate_header("stability-loop");
      j["model"] = loop_model_json(text, T);
      j["claim"] = {{"quantity", "Schur stability of the scene's sampled loop as written: NOT stable by a mode its " + b.block +
                                     (b.name.empty() ? std::string() : " '" + b.name + "'") + " hides (no interconnection moves it)"},
                    {"stable", false},
                    {"status", "exact"}};
      nlohmann::json hidden{{"block", b.block},
                            {"kind", unobservable ? "unobservable" : "uncontrollable"},
                            {"basis", matrix_json(h->first)},
                            {"A_h", matrix_json(h->second)}};
      if (b.block == "device" || b.block == "operator") hidden["name"] = b.name;
      j["evidence"] = {{"hidden", hidden}};
      try {
        if (check::check_certificate(j).verified) return j;
      } catch (const InputError&) {  // the checker reads this block otherwise (tf, m and b): the closed-loop matrix's kind
      }
    }
  }
  return std::nullopt;
}

std::vector<int> balancing_exponents(const Eigen::MatrixXd& M) {
  const Eigen::Index n = M.rows();
  std::vector<int> e(static_cast<size_t>(n), 0);
  for (int sweep = 0; sweep < 30; ++sweep) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      double row = 0, col = 0;
      for (Eigen::Index k = 0; k < n; ++k)
        if (k != i) {
          row += std::ldexp(std::abs(M(i, k)), e[size_t(k)] - e[size_t(i)]);
          col += std::ldexp(std::abs(M(k, i)), e[size_t(i)] - e[size_t(k)]);
        }
      if (row == 0 || col == 0) continue;
      int f = 0;  // col 4^f ~ row: column i scaled by 2^f, row i by 2^-f
      while (std::ldexp(col, 2 * f) < row / 2 && f < 60) ++f;
      while (std::ldexp(col, 2 * f) > 2 * row && f > -60) --f;
      if (f != 0) e[size_t(i)] += f, changed = true;
    }
    if (!changed) break;
  }
  return e;
}

SchurDecision stein_evidence(const std::vector<std::vector<std::pair<rational, rational>>>& M) {
  BallMatrix Mb(static_cast<Eigen::Index>(M.size()), static_cast<Eigen::Index>(M.size()));
  for (size_t i = 0; i < M.size(); ++i)
    for (size_t k = 0; k < M.size(); ++k) {
      const auto& [lo, hi] = M[i][k];
      const double mid = rational((lo + hi) / 2).convert_to<double>();
      const rational off = rational(hi - lo) / 2 + abs(rational((lo + hi) / 2) - exact_rational(mid));
      Mb.mid(Eigen::Index(i), Eigen::Index(k)) = mid;
      Mb.rad(Eigen::Index(i), Eigen::Index(k)) = std::nextafter(off.convert_to<double>(), 1e300);
    }
  // balanced first (a fast lag beside a slow mass spreads M's entries over many decades): the Stein P
  // of D^-1 M D, D = diag(2^e) (Parlett-Reinsch), gives P = D^-1 P_b D^-1 and w = D w_b for M itself
  // (a congruence), exactly, as the scaling is by powers of two
  const Eigen::Index n = Mb.mid.rows();
  const std::vector<int> e = balancing_exponents(Mb.mid);
  BallMatrix Bal = Mb;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < n; ++k) {
      Bal.mid(i, k) = std::ldexp(Mb.mid(i, k), e[size_t(k)] - e[size_t(i)]);
      Bal.rad(i, k) = std::ldexp(Mb.rad(i, k), e[size_t(k)] - e[size_t(i)]);
    }
  SchurDecision d = schur_decide(Bal);
  if (!d.stable) return d;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index k = 0; k < n; ++k) d.P(i, k) = std::ldexp(d.P(i, k), -e[size_t(i)] - e[size_t(k)]);
    if (d.w.size() == n) d.w(i) = std::ldexp(d.w(i), e[size_t(i)]);
  }
  return d;
}

namespace {

nlohmann::json exact_rows(const Eigen::MatrixXd& A) {
  nlohmann::json r = nlohmann::json::array();
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < A.cols(); ++k) row.push_back(exact_rational(A(i, k)).str());
    r.push_back(row);
  }
  return r;
}

// The Stein evidence of one small loop of the split (the checker's own matrix, as stability_loop_certificate
// does for the whole): {space[, class], conserved, P[, w]} and its verdict.
std::pair<bool, nlohmann::json> symmetric_block(const check::detail::SceneLoop& loop, const std::string& space, int cls) {
  check::detail::LoopMatrix lm;
  {
    flint::BallPrecision scope(128);
    lm = check::detail::loop_matrix(loop, 128);
  }
  std::vector<std::vector<std::pair<rational, rational>>> M(lm.M.size());
  for (size_t i = 0; i < lm.M.size(); ++i)
    for (const auto& x : lm.M[i]) {
      const auto e = x.bounds();
      M[i].emplace_back(e.lo, e.hi);
    }
  const SchurDecision d = stein_evidence(M);
  if (!d.stable)
    throw InputError("--certificate: no Stein certificate for the " + space + " block's closed-loop matrix (" + d.why + "): no certificate");
  nlohmann::json b{{"space", space}};
  if (cls >= 0) b["class"] = cls;
  if (lm.conserved > 0) b["conserved"] = lm.conserved;
  b["P"] = exact_rows(d.P);
  if (!*d.stable) b["w"] = exact_rows(d.w.transpose())[0];
  return {*d.stable, b};
}

// Beyond 64 DOFs: kind stability-loop-symmetric (check/stability_loop_symmetric_check.hpp), the small loops of the
// split by identical DOFs, each with its Stein evidence; NOT stable by the first block that is.
nlohmann::json stability_loop_symmetric_certificate(const nlohmann::json& model, const check::detail::SceneLoop& L, bool stable) {
  const auto classes = check::detail::identical_dofs(L);
  std::string why;
  const auto split = check::detail::split_loop(L, classes, why);
  if (!split)
    throw InputError("--certificate: " + std::to_string(L.dofs()) + " DOFs, more than a whole loop's certificate takes (64), and the "
                     "split by identical DOFs does not apply (" + why + "): no certificate");
  nlohmann::json j = certificate_header("stability-loop-symmetric");
  j["model"] = model;
  nlohmann::json blocks = nlohmann::json::array();
  long total = 0;
  bool whole = true;
  for (size_t a = 0; a <= split->sizes.size(); ++a) {
    if (a > 0 && split->sizes[a - 1] < 2) continue;
    auto [holds, b] = a == 0 ? symmetric_block(split->fixed, "fixed", -1) : symmetric_block(split->zero_sum[a - 1], "zero-sum", int(a - 1));
    const long copies = a == 0 ? 1 : static_cast<long>(split->sizes[a - 1]) - 1;
    total += copies * b.value("conserved", 0L);
    whole = whole && holds;
    if (!holds && !stable) {  // one block shows it
      blocks = nlohmann::json::array({b});
      break;
    }
    blocks.push_back(b);
  }
  if (whole != stable)
    throw NumericalError("--certificate: the checker's split and the loop as written got different verdicts (a defect): no certificate");
  j["claim"] = {{"quantity", "Schur stability of the scene's sampled loop (devices, operators, zero-order hold, force = -z^-n E(z) "
                             "x(kT)), shown on the small loops of its split by the permutations of identical DOFs, built by the checker"},
                {"stable", stable},
                {"status", "certified"}};
  if (stable && total > 0) j["claim"]["conserved"] = total;
  j["evidence"] = {{"classes", classes}, {"blocks", blocks}};
  verify_before_writing(j);
  return j;
}

}  // namespace

nlohmann::json stability_loop_certificate(const StabilityText& text, const rational& T, bool stable) {
  nlohmann::json j = certificate_header("stability-loop");
  j["model"] = loop_model_json(text, T);
  if (!text.scene.empty()) {  // beyond a whole loop's 64 DOFs: the split's certificate
    std::optional<check::detail::SceneLoop> L;
    try {
      L = check::detail::read_scene_loop(j["model"], check::detail::kMaxSymmetricDofs);
    } catch (const InputError& e) {  // refused by name below, as the whole loop's reading says -- except beyond the split's own limit
      if (std::string(e.what()).find("more than " + std::to_string(check::detail::kMaxSymmetricDofs)) != std::string::npos)
        throw InputError(std::string("--certificate: the checker does not take this scene (") + e.what() +
                         ": beyond stability-loop-symmetric's " + std::to_string(check::detail::kMaxSymmetricDofs) + " DOFs): no certificate");
    }
    if (L && L->dofs() > 64) return stability_loop_symmetric_certificate(j["model"], *L, stable);
  }
  check::SceneLoopMatrix sm;
  try {
    sm = check::scene_loop_matrix(j["model"], 128);  // on the quotient by the conserved quantities
  } catch (const InputError& e) {
    throw InputError(std::string("--certificate: the checker does not take this ") + (text.scene.empty() ? "loop" : "scene") +
                     " (" + e.what() + "): no certificate");
  }
  SchurDecision d = stein_evidence(sm.M);
  if (!d.stable)
    throw InputError("--certificate: no Stein certificate for the checker's closed-loop matrix (" + d.why + "): no certificate");
  if (*d.stable != stable)
    throw NumericalError("--certificate: the checker's closed-loop matrix and the loop as written got different verdicts (a "
                         "defect): no certificate");
  j["claim"] = {{"quantity", "Schur stability of the scene's sampled loop (devices, operators, zero-order hold, "
                             "force = -z^-n E(z) x(kT)), its closed-loop matrix built by the checker"},
                {"stable", stable},
                {"status", "certified"}};
  if (sm.conserved > 0) {  // what "stable" then means (check/stability_loop_check.hpp)
    j["claim"]["conserved"] = sm.conserved;
    j["claim"]["quantity"] = "stability of the scene's sampled loop (devices, operators, zero-order hold, force = -z^-n E(z) "
                             "x(kT)), its closed-loop matrix M built by the checker, with its k = `conserved` quantities "
                             "(l^T [A B] = 0: each an eigenvalue 1 of M) set aside: stable = every other mode inside the unit "
                             "circle (the loop settles to the equilibrium they select, not to 0), NOT stable = one outside it";
  }
  j["evidence"] = {{"P", exact_rows(d.P)}};
  if (!stable) j["evidence"]["w"] = exact_rows(d.w.transpose())[0];
  verify_before_writing(j);
  return j;
}

nlohmann::json stability_loop_verdicts_certificate(const std::string& scene, const std::vector<std::string>& sets, const rational& T,
                                                   const std::string& name, const std::vector<std::pair<rational, bool>>& verdicts) {
  nlohmann::json j = certificate_header("stability-loop-verdicts");
  j["model"] = scene_model_json(scene, sets);
  j["model"]["name"] = name;
  nlohmann::json claimed = nlohmann::json::array(), parts = nlohmann::json::array();
  for (const auto& [at, stable] : verdicts) {
    std::vector<std::string> with = sets;
    with.push_back(name + "=" + at.str());
    claimed.push_back({{"at", at.str()}, {"stable", stable}});
    parts.push_back(stability_loop_certificate({"", "", "", 0, with, scene}, T, stable));
  }
  j["claim"] = {{"quantity", "the certified verdicts of the scene's loop at the values of " + name + " tried (the loop is not affine in " +
                                 name + ": no supremum is claimed, stability between these values is not)"},
                {"status", "certified"},
                {"verdicts", claimed}};
  j["evidence"] = {{"verdicts", parts}};
  verify_before_writing(j);
  return j;
}

namespace {

// A short rational in (0, x), x > 0: the first continued-fraction convergent of x/2 there.
rational short_below(const rational& x) {
  const auto c = first_convergent(x / 2, [&](const rational& y) { return y > 0 && y < x; });
  return c ? *c : rational(x / 2);
}

// sup = 0: a K = e > 0 below every positive root of D(K) = Res_z(c, c*) (then the family keeps one
// verdict on (0, e], NOT stable when the producer's answer holds); 1 when D has none or D = 0.
rational unstable_point(const stability::Loop& loop) {
  const auto family = stability::exact_family(loop);
  if (!family) throw InputError("--certificate: the loop's exact family c0 + K c1 could not be formed");
  QPoly D = stability::reciprocal_resultant(family->first, family->second);
  if (D.is_zero()) return rational(1);
  while (D.coeff(0) == 0) D = divmod(D, QPoly{rational(0), rational(1)}).first;  // the roots at K = 0
  if (D.degree() < 1) return rational(1);
  const auto roots = isolate_real_roots(D, rational(0), cauchy_bound(D));
  if (roots.empty()) return rational(1);
  RootInterval r = roots.front();
  while (r.lo <= 0) r = refine_root(D, r, rational((r.hi - r.lo) / 4));  // the root is > 0 (D(0) != 0)
  return short_below(r.lo);
}

}  // namespace

nlohmann::json stability_max_certificate(const StabilityText& text, const std::string& K, const stability::Loop& loop,
                                         const stability::MaxGain& m, int digits) {
  const auto family = stability::exact_family(loop);
  if (!family) {  // a device pole off s = 0: e^{pT} is transcendental, the resultant has no exact form; the
                  // loop's matrix, affine in K, has (stability-loop-max, cli/loop_max_certificate.hpp)
    if (m.outcome == Outcome::undecided || (m.status != Status::exact && m.status != Status::certified))
      throw InputError("--certificate: sup " + K + " is not decided here: there is no claim to certify");
    return stability_loop_max_certificate(loop_model_json(text, loop.T), K, sup_claim(m));
  }
  if (family->first.degree() > 150)
    throw InputError("--certificate: the characteristic polynomial has degree " + std::to_string(family->first.degree()) +
                     ", beyond the checkers' limit of 150 (D(" + K + ") = Res_z(c, c*) has degree up to twice that)");
  if (m.outcome == Outcome::undecided || (m.status != Status::exact && m.status != Status::certified))
    throw InputError("--certificate: sup " + K + " is not decided here: there is no claim to certify");
  nlohmann::json j = certificate_header("stability-max");
  j["model"] = loop_model_json(text, loop.T);
  j["model"]["name"] = K;
  nlohmann::json claim{{"quantity", K + "_max = sup{" + K + "0 > 0 : the loop is stable for every " + K + " in (0, " + K +
                                        "0)} (0 when none), H = H0 + " + K + " H1; the loop of `stability` (device P(s), "
                                        "zero-order hold, force = -z^-n H(z) x(kT))"},
                       {"status", to_string(m.status)}};
  nlohmann::json evidence = nlohmann::json::object();
  if (m.outcome == Outcome::fails) {  // unstable for every small K: K_max = 0
    claim["status"] = "exact";
    claim["value"] = "0";
    evidence["unstable_at"] = unstable_point(loop).str();
  } else if (m.infinite) {
    claim["infinite"] = true;
    evidence["stable_at"] = "1";
  } else if (m.exact) {
    claim["status"] = "exact";
    claim["value"] = m.exact->str();
    evidence["stable_at"] = short_below(*m.exact).str();
  } else {  // the enclosure as printed: digits + 3, rounded outward (cmd_stability.cpp)
    const nlohmann::json e = enclosure_json(m.enclosure, digits + 3);
    evidence["stable_at"] = short_below(printed_enclosure(claim, e[0].get<std::string>(), e[1].get<std::string>()).lo).str();
  }
  j["claim"] = claim;
  j["evidence"] = evidence;
  verify_before_writing(j);
  return j;
}

namespace {

// The left side + 1 of the criterion (the wedge's (25), else Tsypkin's (21)) at c = cos(theta) in
// [-1, 1], exactly, by the producer's route (contact::wedge_branches in u = tan^2(theta/2)); c = -1
// is theta = pi, where it is H(-1) + 1.
rational criterion_at(const TransferFunction& H, const contact::WedgeBranches& br, bool wedge, const rational& c) {
  if (c == -1) return H.num()(rational(-1)) / H.den()(rational(-1)) + 1;
  const rational u = (1 - c) / (1 + c);
  const rational J = br.im_over_t(u);
  return br.re(u) + (wedge ? abs(J) : rational(0)) + 1;
}

// claim {lo, hi, printed}: the enclosure of r rounded outward at digits + 5 (as --json's
// *_enclosure), and the shared digits the command printed (when it printed any).
nlohmann::json printed_range(const Certified<rational>& r, int digits) {
  const Enclosure<rational> e = r.enclosure ? *r.enclosure : Enclosure<rational>{r.value, r.value};
  nlohmann::json j{{"lo", parse_rational(decimal_outward(e.lo, digits + 5, -1), "enclosure").str()},
                   {"hi", parse_rational(decimal_outward(e.hi, digits + 5, +1), "enclosure").str()}};
  const SharedDecimal s = shared_decimal(e.lo, e.hi, digits);
  if (s.digits > 0) j["printed"] = s.text;
  return j;
}

// The margin and k* of one criterion (claim.<key>_margin, claim.<key>_gain) and the witness
// c0 of their upper bounds (evidence.<key>_witness_c): near the certified minimiser, the first
// that shows the left side + 1 <= min(margin hi, 1 - 1/k* hi) there.
// Where the minimum is at theta = pi (exactly H(-1) + 1 for both criteria, cot(pi/2) = 0) and the
// certified enclosure holds it, the margin and k* = 1/(1 - mu) are claimed exactly (lo = hi, the
// witness c0 = -1): equal gains of (25) and (21) are then ordered (reproduce's
// 002.wedge_gain_ge_tsypkin), which enclosures rounded outward cannot do. The checkers decide
// lo = hi as any enclosure; the producer's check before writing catches a wrong min_at_pi.
void margin_claims(const TransferFunction& H, const contact::WedgeBranches& br, const contact::CriterionReport& c,
                   const std::string& key, bool wedge, int digits, nlohmann::json& claim, nlohmann::json& evidence) {
  claim[key + "_margin"] = printed_range(c.margin, digits);
  std::optional<rational> exact;
  if (c.min_at_pi && c.margin.enclosure) {
    const rational v = criterion_at(H, br, wedge, rational(-1));
    if (c.margin.enclosure->lo <= v && v <= c.margin.enclosure->hi) exact = v;
  }
  if (exact) claim[key + "_margin"]["lo"] = claim[key + "_margin"]["hi"] = exact->str();
  rational target = parse_rational(claim[key + "_margin"]["hi"].get<std::string>(), "margin");
  if (c.gain_infinite) {
    claim[key + "_gain"] = {{"infinite", true}};
  } else if (c.max_gain.status == Status::exact || c.max_gain.status == Status::certified) {
    claim[key + "_gain"] = printed_range(c.max_gain, digits);
    if (exact && *exact < 1) claim[key + "_gain"]["lo"] = claim[key + "_gain"]["hi"] = rational(1 / (1 - *exact)).str();
    const rational k_hi = parse_rational(claim[key + "_gain"]["hi"].get<std::string>(), "k*");
    target = std::min(target, rational(1 - 1 / k_hi));
  }
  auto ok = [&](const rational& x) { return x >= -1 && x <= 1 && criterion_at(H, br, wedge, x) <= target; };
  std::vector<rational> tries{rational(-1), rational(1)};
  if (!c.min_at_pi)
    for (const rational& u : {c.u_at_min.lo, c.u_at_min.hi, rational((c.u_at_min.lo + c.u_at_min.hi) / 2)})
      tries.push_back((1 - u) / (1 + u));
  for (const rational& x : tries)
    if (ok(x)) {
      evidence[key + "_witness_c"] = x.str();
      return;
    }
  if (auto x = first_convergent(tries.back(), ok)) {
    evidence[key + "_witness_c"] = x->str();
    return;
  }
  throw NumericalError("--certificate: no rational witness shows the " + key + " margin <= " + target.str());
}

}  // namespace

nlohmann::json wedge_certificate(const TfOptions& tf, const contact::ContactAnalysis& a, int digits) {
  // a pole on the circle where the branches stay bounded (z = -1 with Im H cot(theta/2) finite) is
  // still evaluated by the producer, as a limit; the checkers refuse every pole on the circle
  if (a.assumptions.pole_on_unit_circle || !a.wedge.evaluated() || !a.tsypkin.evaluated())
    throw InputError("--certificate: H has a pole on the unit circle (the criteria are then limits, or not evaluated): "
                     "no certificate");
  nlohmann::json j = certificate_header("wedge");
  j["model"] = tf_model_json(tf);
  j["model"]["T"] = tf.T.empty() ? std::string("1") : parse_rational(tf.T, "--T").str();
  j["claim"] = {{"quantity", "Tsai & Colgate (paper 002): wedge criterion (25), Tsypkin's condition (21), the assumptions of Sec. 2"},
                {"status", "exact"},
                {"wedge", a.wedge.verdict.holds()},
                {"tsypkin", a.tsypkin.verdict.holds()},
                {"h_stable", a.assumptions.h_stable},
                {"closed_loop_stable", a.assumptions.closed_loop_stable},
                {"dc_gain_nonnegative", a.assumptions.dc_gain_nonnegative}};
  nlohmann::json evidence = nlohmann::json::object();
  const contact::WedgeBranches br = contact::wedge_branches(a.H);
  margin_claims(a.H, br, a.wedge, "wedge", true, digits, j["claim"], evidence);
  margin_claims(a.H, br, a.tsypkin, "tsypkin", false, digits, j["claim"], evidence);
  j["evidence"] = evidence;
  verify_before_writing(j);
  return j;
}

nlohmann::json limit_cycle_certificate(const TfOptions& tf, const rational& k, const rational& rho,
                                       const contact::ExactOrbit& orbit, int order) {
  if (!orbit.found || orbit.y.empty()) throw InputError("--certificate: no periodic orbit was proven: no claim to certify");
  if (order < 1) throw InputError("--certificate: H is a constant: the loop has no state, so no orbit to certify");
  nlohmann::json j = certificate_header("limit-cycle");
  j["model"] = tf_model_json(tf);
  j["model"]["T"] = tf.T.empty() ? std::string("1") : parse_rational(tf.T, "--T").str();
  j["model"]["gain"] = k.str();
  j["model"]["rho"] = rho.str();
  nlohmann::json claim{{"quantity", "a periodic solution of paper 002's loop (4), y = -k H(z) x, x = max(y, -rho): least "
                                    "period, amplitude (max - min)/2 of y, samples with y < -rho, attraction"},
                       {"status", "exact"},
                       {"period", orbit.period},
                       {"amplitude", orbit.amplitude.str()},
                       {"printed_amplitude", to_decimal(orbit.amplitude, 20)},  // as cmd_limit_cycle.cpp prints it
                       {"free_steps", orbit.free_steps}};
  if (orbit.stability_decided) claim["attracting"] = orbit.stable;
  j["claim"] = claim;
  nlohmann::json y = nlohmann::json::array();
  for (int i = 0; i < order; ++i) y.push_back(orbit.y[static_cast<size_t>(i) % orbit.y.size()].str());
  j["evidence"] = {{"y", y}};
  verify_before_writing(j);
  return j;
}

void write_certificate(const std::string& file, const nlohmann::json& certificate) {
  std::ofstream f(file);
  if (!f) throw InputError("--certificate: cannot write '" + file + "'");
  f << certificate.dump(2) << "\n";
  if (!f) throw InputError("--certificate: cannot write '" + file + "'");
}

}  // namespace hapstab::cli
