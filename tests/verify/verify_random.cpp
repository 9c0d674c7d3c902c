// tests/verify/verify_random.cpp -- the random differential campaign (docs/verification.md):
// random instances of a criterion, each compared with a reference computed by a DIFFERENT
// algorithm in about twice the precision of the result under test. A certified enclosure must
// contain its reference; a correctly rounded decimal must be within half a unit in its last
// place of the reference. Any miss prints the case (and how to rerun it) and exits 1.
//
//   verify_random --cases N --seed S [--criterion all|r,bound,wedge,level,multidof] [--case K]
//                 [--max-undecided F]
//
// Apart from misses: refused (the criterion rejected a generated input) fails the run; failed (a
// certified computation returned Status::failed) fails the run; undecided (a NumericalError, an
// honest "cannot decide") fails it only above F of the cases per criterion (default 0.005;
// `--inject-undecided` makes every case undecided, for the test that a flood fails the run).
//
// Case K of seed S is generated from its own generator (seed, K), so `--case K` replays one.
//
// r:      r(jw) = T/(e^{jwT} - 1) of paper 001 (44) as `hapstab r` prints it (r_decimal: MPFI
//         intervals on -(T/2)cot(wT/2), Ziv's loop) against T/(e^{jwT} - 1) evaluated from the
//         complex exponential in 100-digit MPFR. wT anywhere in (0, 4 pi], near 0 (1e-15), near
//         pi and near 2 pi; 10 to 40 digits. Also the truncated series (34) and its error bound:
//         |r_N - r| must be within the printed bound.
// bound:  b* of paper 001 (45)/(54) by bound_certified (exact objective in cos wT, Descartes
//         isolation, interval enclosure) against the objective Re{T H z^-n e^{-jw td}/(1 - z)} + eta
//         evaluated directly in complex 100-digit MPFR: (1) at the certified maximiser the
//         reference lies in [lo, hi]; (2) no point of a 4096-point double grid, refined by golden
//         section in 100 digits around its three best points, and neither end (w -> 0, wT = pi)
//         exceeds hi. H: orders 1-8, complex poles of radius up to 1 - 1e-6, real poles up to
//         +-(1 - 1e-6), integer delays 0-4, fractional delays (orders 1-3), eta; a quarter of the cases are
//         virtual walls K + B (z - 1)/(T z), whose maximiser is at wT = pi (or w = 0 with delays);
//         a tenth are FIR H built so that the objective's derivative has a double root (a
//         horizontal inflection) or a triple one (a flat maximum) at a chosen frequency.
// wedge, level: see their sections below.
// multidof: Theorems 5 and 6 of paper 000 on random case-ii scenes against the exact-ZOH
//         simulation of the loop with the designed coupling (check_multidof).
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lmi/passivity_level.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/multidof/design.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/sampling/r_decimal.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"

using namespace hapstab;
using Ref = mp100;  // the reference precision: 100 digits, > 2 x the 40 digits under test
using CRef = std::complex<Ref>;
using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

namespace {

// A certified computation that returned Status::failed on an input in its scope: not a wrong
// number and not an honest "undecided" (NumericalError) either -- counted as failed, fails the run.
struct CertifiedFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Tally {
  long cases = 0, misses = 0, refused = 0, undecided = 0, failed = 0;
  double seconds = 0, slowest = 0;
  long slowest_case = -1;
};
double reference_seconds = 0;  // time spent computing references (the rest is the code under test)
struct Stopwatch {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  ~Stopwatch() { reference_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

std::mt19937_64 case_rng(unsigned long seed, unsigned long criterion, long k) {
  std::seed_seq s{seed, criterion, static_cast<unsigned long>(k)};
  return std::mt19937_64(s);
}
long uniform(std::mt19937_64& g, long lo, long hi) { return lo + static_cast<long>(g() % static_cast<unsigned long>(hi - lo + 1)); }
bool chance(std::mt19937_64& g, double p) { return std::uniform_real_distribution<double>(0, 1)(g) < p; }
rational pow10(int e) {
  integer p = 1;
  for (int i = 0; i < std::abs(e); ++i) p *= 10;
  return e >= 0 ? rational(p) : rational(integer(1), p);
}
Ref ref(const rational& q) { return to_real<Ref>(q); }

// min of f on [a, b] by golden section in 100 digits (80 steps: the bracket shrinks by
// 0.618^80 ~ 1e-17), started from a grid cell around a grid minimum
Ref golden_min(const std::function<Ref(const Ref&)>& f, Ref a, Ref b) {
  const Ref gr = (sqrt(Ref(5)) - 1) / 2;
  for (int it = 0; it < 80; ++it) {
    const Ref x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    if (f(x1) < f(x2)) b = x2;
    else a = x1;
  }
  return f((a + b) / 2);
}
Ref ref_pi() { return boost::math::constants::pi<Ref>(); }

// |printed - v| <= 1/2 unit in the last of `digits` places (relative slack 1e-90 for v's own error)
bool correctly_rounded(const std::string& printed, const Ref& v, int digits) {
  const rational p = parse_rational(printed);
  if (v == 0) return p == 0;
  const Ref e = floor(log10(abs(v)));
  const Ref ulp = pow(Ref(10), e - digits + 1);
  return abs(ref(p) - v) <= ulp / 2 + abs(v) * Ref("1e-90");
}

// ---- r(jw) --------------------------------------------------------------------------------
bool check_r(std::mt19937_64& g, std::ostream& why) {
  const rational T(uniform(g, 1, 1000), uniform(g, 1, 100000));
  const int digits = static_cast<int>(uniform(g, 10, 40));
  // theta = wT: uniform, near 0, near pi, near 2 pi (rational approximations of pi to 20 digits)
  const rational pi20 = parse_rational("3.14159265358979323846");
  rational theta;
  switch (uniform(g, 0, 3)) {
    case 0: theta = rational(uniform(g, 1, 1000000), 1000000) * 4 * pi20; break;
    case 1: theta = rational(uniform(g, 1, 1000)) * pow10(-static_cast<int>(uniform(g, 3, 15))); break;
    case 2: theta = pi20 + rational(uniform(g, -1000, 1000)) * pow10(-static_cast<int>(uniform(g, 3, 12))); break;
    default: theta = 2 * pi20 + rational(uniform(g, 1, 1000)) * pow10(-static_cast<int>(uniform(g, 3, 12))); break;
  }
  const rational omega = theta / T;
  const long N = uniform(g, 0, 50);
  why << "r: T = " << T << ", w = " << omega << ", N = " << N << ", digits = " << digits << "\n";
  const auto r = sampling::r_decimal(T, omega, N, digits);
  Stopwatch reference_time;
  const Ref th = ref(theta), Tr = ref(T);
  const CRef z(cos(th), sin(th));
  const CRef rv = CRef(Tr, 0) / (z - CRef(1, 0));  // T/(e^{j theta} - 1), no cotangent anywhere
  bool ok = true;
  if (!correctly_rounded(r.re, rv.real(), digits)) ok = false, why << "  re " << r.re << " vs " << rv.real() << "\n";
  if (!correctly_rounded(r.im, rv.imag(), digits)) ok = false, why << "  im " << r.im << " vs " << rv.imag() << "\n";
  // the truncated series r_N = T (e^{-j theta} - 1) sum_{|n|<=N} 1/(theta + 2 pi n)^2, summed here
  Ref s = 0;
  for (long n = -N; n <= N; ++n) s += 1 / pow(th + 2 * ref_pi() * n, 2);
  const CRef rN = CRef(Tr, 0) * (CRef(cos(th), -sin(th)) - CRef(1, 0)) * CRef(s, 0);
  if (!correctly_rounded(r.series_re, rN.real(), digits)) ok = false, why << "  series re " << r.series_re << " vs " << rN.real() << "\n";
  if (!correctly_rounded(r.series_im, rN.imag(), digits)) ok = false, why << "  series im " << r.series_im << " vs " << rN.imag() << "\n";
  if (r.series_error_bound && abs(rN - rv) > ref(parse_rational(*r.series_error_bound)))
    ok = false, why << "  |r_N - r| = " << abs(rN - rv) << " exceeds the bound " << *r.series_error_bound << "\n";
  return ok;
}

// ---- b* -----------------------------------------------------------------------------------
// A random stable H of order 1-8 with exact coefficients: pole pairs z^2 - a z + b with
// a^2 < 4b, b = |p|^2 < 1 (radius up to 1 - 1e-6), real poles in (-1, 1), random zeros.
RF random_stable_H(std::mt19937_64& g, int order) {
  auto near_one = [&] { return 1 - pow10(-static_cast<int>(uniform(g, 1, 6))) * rational(uniform(g, 1, 9)); };
  P den(rational(1));
  int n = 0;
  while (n < order) {
    if (order - n >= 2 && chance(g, 0.6)) {
      const rational b = chance(g, 0.5) ? near_one() * near_one() : rational(uniform(g, 1, 999), 1000);
      // a = 2 sqrt(b) cos(phi), rounded toward 0 to a rational with a^2 < 4b
      const double ad = 2 * std::sqrt(static_cast<double>(b)) * std::cos(std::uniform_real_distribution<double>(0.001, 3.14)(g));
      rational a = rational(static_cast<long>(ad * 1e9), 1000000000);
      while (a * a >= 4 * b) a = a * 999 / 1000;
      den = den * P({b, -a, rational(1)});
      n += 2;
    } else {
      rational p = chance(g, 0.5) ? near_one() : rational(uniform(g, -999, 999), 1000);
      if (chance(g, 0.5)) p = -p;
      den = den * P({-p, rational(1)});
      n += 1;
    }
  }
  const int m = static_cast<int>(uniform(g, 0, order));
  std::vector<rational> num(static_cast<size_t>(m) + 1);
  for (auto& c : num) c = rational(uniform(g, -1000, 1000), uniform(g, 1, 100));
  if (num.back() == 0) num.back() = 1;
  return RF(P(num), den);
}

Ref objective(const passivity::BoundProblem& p, const Ref& omega) {
  const Ref th = omega * ref(p.T);
  const CRef z(cos(th), sin(th));
  CRef W = p.H.num()(z) / p.H.den()(z);
  for (int i = 0; i < p.delay; ++i) W /= z;
  if (p.frac_delay) {
    const Ref ph = -omega * ref(*p.frac_delay);
    W *= CRef(cos(ph), sin(ph));
  }
  return (CRef(ref(p.T), 0) * W / (CRef(1, 0) - z)).real() + ref(p.eta);
}

// An H whose objective has a stationary point of multiplicity >= 2 at c0 = cos(w0 T): with
// H(z) = (1 - z) sum_{k>=1} q_k z^-k / T (proper) the objective T H/(1 - z) has real part
// f(c) - q_0 = sum_{k>=1} q_k T_k(c), c = cos wT (T_k Chebyshev), any polynomial f we like. We take
// f' = s (c - c0)^2 r(c) (a horizontal inflection: df/dw has a double root at w0) or
// f' = -s (c - c0)^3 (1 + (c - c1)^2) (a flat maximum, f(c0) - f ~ (c - c0)^4), r random of
// degree 0-2, integrate exactly and convert to the Chebyshev basis exactly.
RF double_root_H(std::mt19937_64& g, const rational& T, std::ostream& why) {
  const rational c0(uniform(g, -99, 99), 100), s(uniform(g, 1, 1000), uniform(g, 1, 10));
  const P x({rational(0), rational(1)}), lin({-c0, rational(1)});
  P df;
  if (chance(g, 0.5)) {
    std::vector<rational> rc(static_cast<size_t>(uniform(g, 0, 2)) + 1);
    for (auto& c : rc) c = rational(uniform(g, -100, 100), uniform(g, 1, 20));
    if (rc.back() == 0) rc.back() = 1;
    df = P(s) * lin * lin * P(rc);
    why << "  objective with a double root of its derivative at cos wT = " << c0 << "\n";
  } else {
    const rational c1(uniform(g, -100, 100), 100);
    df = P(-s) * lin * lin * lin * (P(rational(1)) + P({-c1, rational(1)}) * P({-c1, rational(1)}));
    why << "  objective with a flat maximum (triple root of its derivative) at cos wT = " << c0 << "\n";
  }
  std::vector<rational> f(static_cast<size_t>(df.degree()) + 2);  // f = integral of df + constant
  f[0] = rational(uniform(g, -1000, 1000), 100);
  for (int k = 0; k <= df.degree(); ++k) f[static_cast<size_t>(k) + 1] = df.coeff(k) / (k + 1);
  // monomials -> Chebyshev: peel the leading term with T_d (leading coefficient 2^(d-1))
  const int d = static_cast<int>(f.size()) - 1;
  std::vector<P> Tk = {P(rational(1)), x};
  while (static_cast<int>(Tk.size()) <= d) Tk.push_back(P(rational(2)) * x * Tk.back() - Tk[Tk.size() - 2]);
  P rest(f);
  std::vector<rational> q(static_cast<size_t>(d) + 1);
  for (int k = d; k >= 0; --k) {
    q[static_cast<size_t>(k)] = rest.coeff(k) / Tk[static_cast<size_t>(k)].coeff(k);
    rest = rest - P(q[static_cast<size_t>(k)]) * Tk[static_cast<size_t>(k)];
  }
  // sum_{k>=1} q_k z^-k = (sum_k q_k z^(d-k)) / z^d. The constant q_0 is left out: it only
  // shifts the objective, and without it H is proper (T H/(1 - z) = -T H z^-1/(1 - z^-1)).
  std::vector<rational> num(static_cast<size_t>(d) + 1), zd(static_cast<size_t>(d) + 1);
  for (int k = 1; k <= d; ++k) num[static_cast<size_t>(d - k)] = q[static_cast<size_t>(k)];
  zd[static_cast<size_t>(d)] = T;
  return RF(P({rational(1), rational(-1)}) * P(num), P(zd));
}

bool check_bound(std::mt19937_64& g, std::ostream& why) {
  passivity::BoundProblem p;
  p.T = chance(g, 0.5) ? rational(1, 1000) : rational(uniform(g, 1, 100), uniform(g, 100, 100000));
  // A fractional delay t_d = (p/q) T in 6% of the cases (q <= 8: exact in cos(wT/q); q = 100:
  // the interval branch-and-bound), on H of order <= 3 with n <= 1: the objective's degree
  // grows like q (order + n), and an order-8 case takes 5-20 s against 0.1 s without.
  // The branch-and-bound (q = 100) gets orders 1-2: on an order-3 resonance it can spend 50 s
  // before it gives up (an honest NumericalError, counted as undecided).
  const bool frac = chance(g, 0.06), generic_frac = frac && chance(g, 1.0 / 6);
  const bool degenerate = !frac && chance(g, 0.1);
  if (degenerate) {  // a stationary point of multiplicity >= 2 (double_root_H)
    p.H = double_root_H(g, p.T, why);
  } else if (chance(g, 0.25)) {  // virtual wall K + B (z - 1)/(T z)
    const rational K(uniform(g, 0, 100000)), B(uniform(g, -100, 1000), 10);
    p.H = RF(P(K)) + RF(P({-B, B}), P({rational(0), p.T}));
  } else {
    p.H = random_stable_H(g, static_cast<int>(uniform(g, 1, generic_frac ? 2 : frac ? 3 : 8)));
  }
  p.delay = degenerate ? 0 : static_cast<int>(uniform(g, 0, frac ? 1 : 4));
  if (frac) {
    const long q = generic_frac ? 100 : uniform(g, 2, 8);
    p.frac_delay = p.T * rational(uniform(g, 1, q - 1), q);
  }
  if (chance(g, 0.3)) p.eta = rational(uniform(g, 0, 1000), 1000);
  why << "bound: H = (" << to_string(p.H.num(), "z") << ")/(" << to_string(p.H.den(), "z") << "), T = " << p.T
      << ", delay = " << p.delay << (p.frac_delay ? ", td = " + p.frac_delay->str() : "") << ", eta = " << p.eta << "\n";
  const auto b = passivity::bound_certified(p, 30);
  if (b.infinite) {
    why << "  certified says infinite (no generated case has a pole at z = 1)\n";
    return false;
  }
  Stopwatch reference_time;
  const Ref lo = ref(b.enclosure->lo), hi = ref(b.enclosure->hi);
  const Ref eps = Ref("1e-27") * std::max(Ref(1), Ref(abs(hi)));  // 30 digits asked, 3 for the maximiser's width
  const Ref w_end = ref_pi() / ref(p.T);
  // w -> 0: the objective is even and analytic in w, so f(w0) = f(0) + O((w0 T)^2) = f(0) + 1e-60;
  // 1 - cos(w0 T) = 5e-61 keeps 40 of the 100 digits (w0 T = 1e-40 would keep 20: too few).
  const Ref w0 = Ref("1e-30") / ref(p.T);
  bool ok = true;
  // (1) the reference at the certified maximiser lies in the enclosure
  if (b.omega_enclosure) {
    Ref w = (ref(b.omega_enclosure->lo) + ref(b.omega_enclosure->hi)) / 2;
    if (w < w0) w = w0;
    const Ref f = objective(p, w);
    if (f < lo - eps || f > hi + eps)
      ok = false, why << "  at the certified maximiser w = " << w << " the objective is " << f << ", outside [" << lo << ", " << hi << "]\n";
  }
  // (2) nothing exceeds hi: a double grid, refined in 100 digits around its best three points
  const int n = 4096;
  std::vector<std::pair<double, int>> best;
  for (int i = 1; i < n; ++i) {
    const double th = M_PI * i / n;
    const std::complex<double> z = std::polar(1.0, th);
    std::complex<double> W = p.H.num()(z) / p.H.den()(z) * std::pow(z, -p.delay);
    if (p.frac_delay) W *= std::polar(1.0, -th * static_cast<double>(*p.frac_delay / p.T));
    best.push_back({(static_cast<double>(p.T) * W / (1.0 - z)).real(), i});
  }
  std::partial_sort(best.begin(), best.begin() + 3, best.end(), std::greater<>());
  Ref top = std::max(objective(p, w0), objective(p, w_end));
  for (int k = 0; k < 3; ++k)
    top = std::max(top, -golden_min([&](const Ref& w) { return -objective(p, w); }, w_end * (best[k].second - 1) / n,
                                    w_end * (best[k].second + 1) / n));
  if (top > hi + eps) ok = false, why << "  the objective reaches " << top << " > hi = " << hi << "\n";
  return ok;
}

// ---- wedge (25) and Tsypkin (21) ---------------------------------------------------------
// w(theta) = Re H(e^{j theta}) + |Im H(e^{j theta})| cot(theta/2) + 1 and Re H + 1, evaluated
// directly in complex 100-digit MPFR (not through t = tan(theta/2) and exact rational functions).
Ref wedge_side(const RF& H, const Ref& theta, bool wedge) {
  const CRef z(cos(theta), sin(theta));
  const CRef h = H.num()(z) / H.den()(z);
  return h.real() + (wedge ? Ref(abs(h.imag()) * cos(theta / 2) / sin(theta / 2)) : Ref(0)) + 1;
}

bool check_criterion(const RF& H, const contact::CriterionReport& c, bool wedge, int digits, std::ostream& why) {
  Stopwatch reference_time;
  if (!c.evaluated() || !c.margin.enclosure) {
    why << "  " << c.name << " not evaluated\n";
    return false;
  }
  const Ref lo = ref(c.margin.enclosure->lo), hi = ref(c.margin.enclosure->hi);
  const Ref scale = std::max(Ref(1), Ref(abs(hi)));
  const Ref eps = pow(Ref(10), -(digits - 3)) * scale;
  const Ref th0 = Ref("1e-30");  // w is even in theta: w(1e-30) = w(0) + O(1e-60)
  bool ok = true;
  // (1) at the reported minimiser: a double, within 2^-52 theta* of the true one, so the value
  // there exceeds the minimum by at most |w'| 2^-52 theta* (w has kinks where Im H changes sign:
  // the one-sided slopes, from 100-digit differences, bound it)
  const Ref ts = std::max(Ref(c.theta_at_min), th0);
  const Ref at = wedge_side(H, ts, wedge);
  const Ref h = ts * Ref("1e-30");
  const Ref slope = std::max(abs(wedge_side(H, ts + h, wedge) - at), abs(at - wedge_side(H, ts - h, wedge))) / h;
  const Ref off = slope * ts * pow(Ref(2), -51);
  if (at < lo - eps || at > hi + eps + off)
    ok = false, why << "  " << c.name << ": at the reported minimiser theta = " << ts << " the reference is " << at
                    << ", not in [" << lo << ", " << hi << "]\n";
  // (2) nothing is below lo: the ends, a 4096-point grid, golden section around its 3 lowest points
  const Ref pi_ = ref_pi();
  Ref low = std::min(wedge_side(H, th0, wedge), wedge_side(H, pi_, wedge));
  const int n = 4096;
  std::vector<std::pair<double, int>> grid;  // located in double, refined in 100 digits
  for (int i = 1; i < n; ++i) {
    const double th = M_PI * i / n;
    const std::complex<double> z = std::polar(1.0, th), h = H.num()(z) / H.den()(z);
    grid.push_back({h.real() + (wedge ? std::abs(h.imag()) / std::tan(th / 2) : 0.0), i});
  }
  std::partial_sort(grid.begin(), grid.begin() + 3, grid.end());
  for (int k = 0; k < 3; ++k)
    low = std::min(low, golden_min([&](const Ref& th) { return wedge_side(H, th, wedge); }, pi_ * (grid[k].second - 1) / n,
                                   pi_ * (grid[k].second + 1) / n));
  if (low < lo - eps) ok = false, why << "  " << c.name << ": the reference reaches " << low << " < lo = " << lo << "\n";
  // (3) the exact verdict: holds iff the margin is positive
  if (c.verdict.holds() != (lo > 0))
    ok = false, why << "  " << c.name << ": holds = " << c.verdict.holds() << " but the margin is [" << lo << ", " << hi << "]\n";
  if (c.verdict.holds() && low <= 0) ok = false, why << "  " << c.name << " holds but the reference reaches " << low << "\n";
  // (4) k* = -1/(min - 1) when the minimum of the left side (margin - 1) is negative
  if (c.gain_infinite != (lo >= 1)) {
    if (!(lo < 1 && hi >= 1)) ok = false, why << "  " << c.name << ": gain_infinite = " << c.gain_infinite << " with margin [" << lo << ", " << hi << "]\n";
  } else if (!c.gain_infinite && c.max_gain.enclosure) {
    const Ref klo = ref(c.max_gain.enclosure->lo), khi = ref(c.max_gain.enclosure->hi);
    const Ref k_ref = -1 / (at - 1);  // from the reference at the minimiser (|w*-1| >= |at-1| - off)
    const Ref k_tol = k_ref * (eps + off) / abs(at - 1);
    if (k_ref < klo - k_tol || k_ref > khi + k_tol)
      ok = false, why << "  " << c.name << ": k* in [" << klo << ", " << khi << "] but -1/(w* - 1) = " << k_ref << "\n";
  }
  return ok;
}

bool check_wedge(std::mt19937_64& g, std::ostream& why) {
  TransferFunction tf;
  tf.T = rational(1, 1000);
  tf.H = random_stable_H(g, static_cast<int>(uniform(g, 1, 6)));
  why << "wedge: H = (" << to_string(tf.H.num(), "z") << ")/(" << to_string(tf.H.den(), "z") << ")\n";
  const int digits = 20;
  const auto a = contact::analyze_contact(tf, digits);
  return check_criterion(tf.H, a.wedge, true, digits, why) && check_criterion(tf.H, a.tsypkin, false, digits, why);
}

// ---- SISO passivity level (ISP) ----------------------------------------------------------
// phi* = min_theta Re G(e^{j theta}) by passivity_level_certified (the exact objective of the
// passivity bound, Descartes isolation) against (a) Re G evaluated directly in 100 digits on a
// double grid refined by golden section, and (b) the Lemma 1 LMI on the double realisation
// (an interior-point SDP solver in double, whose stopping tolerance gives it 5-6 digits on
// well-conditioned cases: agreement to 1e-3 relative is expected (8.6e-5 seen in 1000 cases);
// the largest deviation, the solver's failures and the disagreements are reported, not misses).
double level_lmi_deviation = 0;
long level_lmi_compared = 0, level_lmi_failed = 0, level_lmi_disagreed = 0;

bool check_level(std::mt19937_64& g, std::ostream& why) {
  TransferFunction tf;
  tf.T = rational(1, 1000);
  tf.H = random_stable_H(g, static_cast<int>(uniform(g, 1, 4)));
  if (chance(g, 0.5)) tf.H = tf.H + RF(P(rational(uniform(g, 0, 1000), 10)));  // a feedthrough
  why << "level: G = (" << to_string(tf.H.num(), "z") << ")/(" << to_string(tf.H.den(), "z") << ")\n";
  const auto c = lmi::passivity_level_certified(tf.H, lmi::PassivityKind::isp, 30);
  if (c.status == Status::failed) throw CertifiedFailed("certified level failed: " + c.note);
  Stopwatch reference_time;
  if (!c.enclosure) {
    why << "  no enclosure\n";
    return false;
  }
  const Ref lo = ref(c.enclosure->lo), hi = ref(c.enclosure->hi);
  const Ref eps = Ref("1e-27") * std::max(Ref(1), Ref(abs(hi)));
  auto re_g = [&](const Ref& th) {
    const CRef z(cos(th), sin(th));
    return (tf.H.num()(z) / tf.H.den()(z)).real();
  };
  const Ref pi_ = ref_pi();
  Ref low = std::min(re_g(Ref(0)), re_g(pi_));
  const int n = 4096;
  std::vector<std::pair<double, int>> grid;
  for (int i = 1; i < n; ++i) {
    const std::complex<double> z = std::polar(1.0, M_PI * i / n);
    grid.push_back({(tf.H.num()(z) / tf.H.den()(z)).real(), i});
  }
  std::partial_sort(grid.begin(), grid.begin() + 3, grid.end());
  for (int k = 0; k < 3; ++k)
    low = std::min(low, golden_min(re_g, pi_ * (grid[k].second - 1) / n, pi_ * (grid[k].second + 1) / n));
  bool ok = true;
  if (low < lo - eps) ok = false, why << "  Re G reaches " << low << " < lower bound " << lo << "\n";
  if (c.theta_min >= 0) {  // the minimiser is a double: Re G there exceeds phi* by |G'| 2^-52 theta
    const Ref ts(c.theta_min), at = re_g(ts);
    const Ref h = std::max(ts, Ref(1)) * Ref("1e-30");
    const Ref off = abs(re_g(ts + h) - at) / h * std::max(ts, Ref(1)) * pow(Ref(2), -51);
    if (at > hi + eps + off) ok = false, why << "  Re G at the minimiser is " << at << " > upper bound " << hi << "\n";
  }
  // the LMI on the double realisation, where its conditioning allows (poles within |z| < 0.99)
  auto sys = tf2ss(tf).cast<double>();
  sys.T = tf.T;
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(sys.A).eigenvalues();
  if (ev.size() > 0 && ev.cwiseAbs().maxCoeff() < 0.99) {
    const auto l = lmi::passivity_level_lmi(sys, lmi::PassivityKind::isp, 1);
    if (l.status == Status::failed) {  // the SDP solver's failure, not a wrong number: counted
      ++level_lmi_failed;
    } else {
      const double mid = static_cast<double>((c.enclosure->lo + c.enclosure->hi) / 2);
      const double dev = std::abs(l.level - mid) / std::max(1.0, std::abs(mid));
      ++level_lmi_compared;
      level_lmi_deviation = std::max(level_lmi_deviation, dev);
      // The LMI is solved in double by an SDP solver: a cross-check at LOWER precision, not a
      // reference. Beyond 1e-3 it is counted (and its case listed) but only a miss when the
      // 100-digit checks above also fail. In the 100,000-case run (17 disagreements) the cases
      // looked at had poles close to the unit circle and the LMI far below the true level
      // (e.g. -123656 against -1926.22, which a 400,000-point grid confirms).
      if (!(dev <= 1e-3)) {
        ++level_lmi_disagreed;
        why << "  LMI disagrees: " << l.level << " against certified " << mid << " (not a miss)\n";
      }
    }
  }
  return ok;
}

}  // namespace

// ---- multidof: Theorems 5 and 6 against simulation ---------------------------------------
// Both theorems are sufficient conditions, so simulation can refute them only where they
// conclude. A random case-ii scene (N = 1-3 devices 1/(m s + b), one 1-DOF operator
// g (s^2 + a s + c)/(s^2 + d s + e) each, paper 000's Fig. 5 environment with N contact points on
// one mass, backward Euler, T = 1-20 ms). Where Assumption 1 holds and Theorem 6 returns a
// coupling V that passed its exact independent verification, the loop with that V is
// simulated (exact ZOH, an impulse on one DOF, 3000 periods) and must settle: a diverging or
// growing response is a miss. Theorem 5 (stability-only mode) must then be feasible too: a
// certified infeasible Theorem 5 beside a verified Theorem 6 design is a miss.
struct MultidofTally {
  long applicable = 0, designed = 0, settled = 0, steady = 0, t5_feasible = 0;
} multidof_tally;

std::string random_multidof_scene(std::mt19937_64& g) {
  const int n = static_cast<int>(uniform(g, 1, 3));
  auto q = [&](long lo, long hi, long den) { return "\"" + std::to_string(uniform(g, lo, hi)) + "/" + std::to_string(den) + "\""; };
  std::ostringstream s;
  const long T_ms = std::vector<long>{1, 2, 5, 10, 20}[static_cast<size_t>(uniform(g, 0, 4))];
  s << "[scene]\nname = \"random case ii, " << n << " devices\"\nT = \"" << T_ms << "/1000\"\n\n[parameters]\n";
  s << "M = " << q(5, 200, 100) << "\nk = " << q(100, 2000, 1) << "\nB = " << q(1, 100, 10) << "\n";
  for (int i = 1; i <= n; ++i) s << "k" << i << " = " << q(100, 1000, 1) << "\nB" << i << " = " << q(1, 40, 10) << "\n";
  std::vector<std::string> b(static_cast<size_t>(n));
  for (int i = 1; i <= n; ++i) {
    b[static_cast<size_t>(i - 1)] = q(50, 300, 100);
    s << "\n[[device]]\nname = \"d" << i << "\"\nm = " << q(5, 50, 100) << "\nb = " << b[static_cast<size_t>(i - 1)] << "\n";
  }
  for (int i = 1; i <= n; ++i)
    s << "\n[[operator]]\nname = \"H" << i << "\"\ndofs = [\"d" << i << "\"]\ntf = \"" << uniform(g, 1, 20) << "/100*(s^2+"
      << uniform(g, 1, 10) << "*s+" << uniform(g, 1, 20) << ")/(s^2+" << uniform(g, 1, 10) << "*s+" << uniform(g, 1, 20) << ")\"\n";
  std::string den = "(M*s^2 + (B";
  for (int i = 1; i <= n; ++i) den += "+B" + std::to_string(i);
  den += ")*s + k";
  for (int i = 1; i <= n; ++i) den += "+k" + std::to_string(i);
  den += ")";
  s << "\n[environment]\ndomain = \"s\"\nmethod = \"backward_euler\"\ntf = [";
  for (int i = 1; i <= n; ++i) {
    const std::string ci = "(k" + std::to_string(i) + " + B" + std::to_string(i) + "*s)";
    s << (i > 1 ? ",\n  [" : "[");
    for (int j = 1; j <= n; ++j) {
      const std::string cj = "(k" + std::to_string(j) + " + B" + std::to_string(j) + "*s)";
      s << (j > 1 ? ", " : "") << "\"" << (i == j ? "k" + std::to_string(i) + " + B" + std::to_string(i) + "*s - " + ci + "^2/" + den
                                                  : "-" + ci + "*" + cj + "/" + den)
        << "\"";
    }
    s << "]";
  }
  s << "]\n\n[[input]]\ntype = \"impulse\"\ndof = \"d" << uniform(g, 1, n) << "\"\nmagnitude = \"1/10\"\n";
  s << "\n[multidof]\nosp = [";
  for (int i = 0; i < n; ++i) s << (i ? ", " : "") << b[static_cast<size_t>(i)];
  std::string ones = "1";  // one first-order SISO coupling per device
  for (int i = 1; i < n; ++i) ones += ", 1";
  s << "]\nqv_block_diagonal = false\n\n[multidof.coupling]\nmbar = [" << ones << "]\nnbar = [" << ones << "]\n";
  return s.str();
}

bool check_multidof(std::mt19937_64& g, std::ostream& why) {
  const std::string text = random_multidof_scene(g);
  why << "multidof scene:\n" << text;
  const scene::Scene sc = scene::parse_scene(text, "random scene");
  const multidof::SceneProblem sp = multidof::problem_from_scene(sc);
  if (!multidof::all_hold(multidof::check_assumptions(sp.problem.structure, sp.operators, sp.operator_names))) return true;
  ++multidof_tally.applicable;
  const auto design = multidof::design(sp.problem);
  if (!design.verdict.holds() || !design.verdict.proven()) return true;
  ++multidof_tally.designed;
  Stopwatch reference_time;
  bool ok = true;
  const auto t5 = multidof::analyze(sp.problem, {}, multidof::AnalysisMode::stability_only);
  if (t5.verdict.holds()) ++multidof_tally.t5_feasible;
  if (t5.verdict.fails() && t5.verdict.proven())
    ok = false, why << "  Theorem 6 returned a verified coupling but Theorem 5 is certified infeasible: " << t5.verdict.evidence << "\n";
  sim::LoopSpec spec = sc.loop;
  spec.coupling = design.V;
  sim::SimOptions so;
  so.steps = 3000;
  so.record_every = 0;
  so.energy = false;
  const auto run = sim::Simulator(spec).run(so);
  const std::string& trend = run.summary.trend;
  if (run.summary.diverged || trend == "growing" || trend == "diverged")
    ok = false, why << "  the loop with the verified coupling does not settle: trend " << trend << ", max |v| " << run.summary.max_velocity << "\n";
  else if (trend == "steady")
    ++multidof_tally.steady;
  else
    ++multidof_tally.settled;
  return ok;
}

int main(int argc, char** argv) {
  long cases = 1000, only = -1, first = 0;
  double max_undecided = 0.005;  // per criterion: more undecided cases than this fraction fail the run
  bool inject_undecided = false;  // test hook: every case throws NumericalError (the flood test)
  unsigned long seed = 1;
  std::string criterion = "all";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "verify_random: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--cases") cases = std::stol(value());
      else if (a == "--seed") seed = std::stoul(value());
      else if (a == "--criterion") criterion = value();
      else if (a == "--case") only = std::stol(value());
      else if (a == "--first") first = std::stol(value());  // cases first .. first + N - 1: a campaign in chunks
      else if (a == "--max-undecided") max_undecided = std::stod(value());
      else if (a == "--inject-undecided") inject_undecided = true;
      else throw std::invalid_argument(a);
    } catch (const std::exception&) {
      std::cerr << "verify_random: bad option '" << a << "' (expected --cases N --seed S [--first K] [--criterion all|r,bound,wedge,level,multidof] [--case K] [--max-undecided F])\n";
      return 2;
    }
  }
  const std::vector<std::pair<std::string, std::function<bool(std::mt19937_64&, std::ostream&)>>> criteria = {
      {"r", check_r}, {"bound", check_bound}, {"wedge", check_wedge}, {"level", check_level}, {"multidof", check_multidof}};
  std::set<std::string> chosen;  // --criterion: "all" or a comma-separated list
  for (size_t a = 0; a <= criterion.size();) {
    const size_t b = std::min(criterion.find(',', a), criterion.size());
    const std::string name = criterion.substr(a, b - a);
    const bool known = name == "all" || std::any_of(criteria.begin(), criteria.end(), [&](const auto& c) { return c.first == name; });
    if (!known) {
      std::cerr << "verify_random: --criterion takes r, bound, wedge, level, multidof or all (comma-separated), not '" << name << "'\n";
      return 2;
    }
    chosen.insert(name);
    a = b + 1;
  }
  int failed = 0;
  std::printf("%-9s %8s %7s %8s %10s %10s %10s  %s\n", "criterion", "cases", "misses", "refused", "undecided", "seconds",
              "reference", "slowest case");
  for (size_t c = 0; c < criteria.size(); ++c) {
    const auto& [name, check] = criteria[c];
    if (!chosen.count("all") && !chosen.count(name)) continue;
    Tally t;
    reference_seconds = 0;
    const auto start = std::chrono::steady_clock::now();
    for (long k = (only >= 0 ? only : first); k < (only >= 0 ? only + 1 : first + cases); ++k) {
      auto g = case_rng(seed, c, k);
      std::ostringstream why;
      ++t.cases;
      const auto rerun = " (rerun: verify_random --seed " + std::to_string(seed) + " --criterion " + name + " --case " +
                         std::to_string(k) + ")\n";
      const auto case_start = std::chrono::steady_clock::now();
      try {
        if (inject_undecided) throw NumericalError("injected (--inject-undecided)");
        if (!check(g, why)) {
          ++t.misses;
          std::cerr << "MISS case " << k << rerun << why.str();
        } else if (only >= 0) {
          std::cerr << "case " << k << " holds: " << why.str();
        }
      } catch (const InputError& e) {  // the generator made an input the criterion refuses: its bug
        ++t.refused;
        std::cerr << "REFUSED case " << k << ": " << e.what() << rerun << why.str();
      } catch (const CertifiedFailed& e) {  // a certified path that failed: reported as failed
        ++t.failed;
        std::cerr << "FAILED case " << k << ": " << e.what() << rerun << why.str();
      } catch (const NumericalError& e) {  // an honest "cannot decide": counted, not a wrong number
        ++t.undecided;
        if (only >= 0) std::cerr << "undecided case " << k << ": " << e.what() << rerun << why.str();
      } catch (const std::exception& e) {
        ++t.misses;
        std::cerr << "MISS case " << k << ": " << e.what() << rerun << why.str();
      }
      const double case_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - case_start).count();
      if (case_seconds > t.slowest) t.slowest = case_seconds, t.slowest_case = k;
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-9s %8ld %7ld %8ld %10ld %10.1f %10.1f  %.2f s (case %ld)\n", name.c_str(), t.cases, t.misses,
                t.refused, t.undecided, t.seconds, reference_seconds, t.slowest, t.slowest_case);
    if (name == "level")
      std::printf("          (LMI: compared on %ld cases, largest relative deviation from the certified level %.1e;"
                  " the SDP solver failed on %ld; beyond 1e-3 on %ld)\n", level_lmi_compared, level_lmi_deviation,
                  level_lmi_failed, level_lmi_disagreed);
    if (name == "multidof")
      std::printf("          (Assumption 1 held in %ld cases; Theorem 6 designed a verified coupling in %ld, Theorem 5 feasible\n"
                  "           in %ld of those; the loop with the coupling settled in %ld, neither settled nor grew in 3000 periods in %ld)\n",
                  multidof_tally.applicable, multidof_tally.designed, multidof_tally.t5_feasible, multidof_tally.settled,
                  multidof_tally.steady);
    if (t.misses > 0 || t.refused > 0) failed = 1;
    // Undecided and failed are reported apart from misses; a flood of undecided (a regression that
    // made a method give up everywhere would otherwise pass) and any failed certified path fail the run.
    const long undecided_cap = static_cast<long>(max_undecided * static_cast<double>(t.cases));
    if (t.undecided > undecided_cap) {
      std::printf("          undecided: %ld of %ld cases, above the cap of %ld (--max-undecided %g)\n", t.undecided,
                  t.cases, undecided_cap, max_undecided);
      failed = 1;
    }
    if (t.failed > 0) {
      std::printf("          failed: %ld certified computations returned failed\n", t.failed);
      failed = 1;
    }
  }
  return failed;
}
