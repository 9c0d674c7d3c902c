// The largest passive value of a parameter of H (max_gain.hpp): K_max = 1/max psi on the certified
// maximiser of b* (certified.cpp), else a bracket of certified b* evaluations; and the closed forms
// of Secs. VI-VII solved for the parameter.
#include "hapstab/passivity/max_gain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/shared_decimal.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::passivity {

BoundProblem at_gain(const GainProblem& p, const rational& K) {
  BoundProblem q = p.base;
  q.H = p.base.H + QRatFun(K) * p.H1;
  return q;
}

namespace {

std::string dec(const rational& q) { return to_decimal(q, 17); }

/// The reported digits of an enclosure (shared_decimal), or all of an exact value.
void set_decimal(MaxGain& m, int digits) {
  if (m.infinite) return;  // "inf"
  if (m.status == Status::exact) {
    m.decimal = to_decimal(m.value, digits);
    m.digits = digits;
    return;
  }
  const SharedDecimal s = shared_decimal(m.enclosure->lo, m.enclosure->hi, digits);
  m.decimal = s.text;
  m.digits = s.digits;
}

/// K_max = 0 (exact): not passive at K = 0, or b* = +inf for every K > 0.
void zero(MaxGain& m, std::string why) {
  m.outcome = Outcome::fails;
  m.status = Status::exact;
  m.value = 0;
  m.enclosure = Enclosure<rational>{0, 0};
  m.decimal = "0";
  m.digits = 1;
  m.note = std::move(why);
}

/// psi = f1/(b - eta - f0) maximised at working precision D by certified_rational, over c = cos(wT)
/// (or cos(wT/q) for t_d = (p/q) T). False when D was not enough; nullopt when the change of variable
/// for t_d does not apply (degree above 96): the bracketing decides then.
template <unsigned D>
std::optional<bool> max_psi(const BoundProblem& q0, const BoundProblem& q1, const rational& bp, int digits, Bound& out) {
  BoundProblem e0 = q0, e1 = q1;
  detail::Domain dom;
  if (q0.frac_delay) {
    const auto f0 = detail::frac_exact_problem<D>(q0, 96), f1 = detail::frac_exact_problem<D>(q1, 96);
    if (!f0 || !f1) return std::nullopt;
    e0 = f0->problem;
    e1 = f1->problem;
    dom = f0->domain;
  }
  const QRatFun F0 = objective(e0.H, e0.T, e0.delay).f, F1 = objective(e1.H, e1.T, e1.delay).f;
  const QRatFun psi = F1 / (QRatFun(bp) - F0);
  BoundProblem pp = e0;  // T for w, eta = 0; H's denominator only tells where poles on the circle may be
  pp.eta = 0;
  pp.H = QRatFun(QPoly(rational(1)), e0.H.den() * e1.H.den());
  return detail::certified_rational<D>(psi, pp, digits, out, dom);
}

/// K_max from the maximum of psi: 1/psi* (exact when psi* is), +inf when psi* <= 0, 0 when psi is
/// unbounded. False when psi*'s enclosure contains 0 (not decided at this precision).
bool from_psi(const Bound& psi, const GainProblem& p, MaxGain& m) {
  m.omega = psi.omega_enclosure;
  m.where = psi.where;
  if (psi.infinite) {
    zero(m, "b*(" + p.name + ") = +inf for every " + p.name + " > 0: f1/(b - eta - f0) is unbounded (" + psi.where + ")");
    return true;
  }
  const auto& [lo, hi] = *psi.enclosure;
  if (hi <= 0) {
    m.outcome = Outcome::holds;
    m.infinite = true;
    m.status = Status::exact;
    m.decimal = "inf";
    m.omega.reset();
    m.where.clear();
    m.note = "f1 <= 0 at every frequency: b* does not grow with " + p.name + ", so b*(" + p.name + ") <= b*(0) < b for every " +
             p.name + " >= 0";
    return true;
  }
  if (lo <= 0) return false;
  m.outcome = Outcome::holds;
  m.status = psi.status == Status::exact ? Status::exact : Status::certified;
  m.value = psi.status == Status::exact ? 1 / psi.value : (1 / hi + 1 / lo) / 2;
  m.enclosure = psi.status == Status::exact ? Enclosure<rational>{m.value, m.value} : Enclosure<rational>{1 / hi, 1 / lo};
  return true;
}

/// The double estimate of K_max = min over w with f1 > 0 of (b - eta - f0)/f1: a 4097-point grid
/// over [0, pi/T], then golden-section search around the best point. +inf when f1 <= 0 on the grid.
double estimate(const BoundProblem& q0, const BoundProblem& q1, double bp, double* omega) {
  const double T = to_real<double>(q0.T), pi = 3.14159265358979323846, top = pi / T * (1 - 1e-12);
  auto phi = [&](double w) {
    const double f1 = objective_at(q1, w);
    return f1 > 0 ? (bp - objective_at(q0, w)) / f1 : std::numeric_limits<double>::infinity();
  };
  // eight points per period 2 pi/nu of the delay's kernels (a delay of 1000 samples oscillates
  // 500 times over [0, pi/T]), at least 4096
  const rational nu = rational(q0.delay) + (q0.frac_delay ? *q0.frac_delay / q0.T : rational(0));
  const int N = static_cast<int>(std::clamp(8 * to_real<double>(nu), 4096.0, 1048576.0));
  int best = 0;
  double vbest = phi(0);
  for (int k = 1; k <= N; ++k) {
    const double v = phi(top * k / N);
    if (v < vbest) vbest = v, best = k;
  }
  double a = top * std::max(0, best - 1) / N, c = top * std::min(N, best + 1) / N;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 100 && c - a > 1e-16 * c; ++it) {
    const double x1 = c - g * (c - a), x2 = a + g * (c - a);
    if (phi(x1) < phi(x2)) c = x2;
    else a = x1;
  }
  const double w = (a + c) / 2, v = phi(w);
  *omega = v < vbest ? w : top * best / N;
  return std::min(v, vbest);
}

/// K_max bracketed by certified b* (at most 20 digits of b*, the branch-and-bound's): L with
/// b*(L) < b proven (so [0, L] is passive, b* being convex) and U with b*(U) >= b proven, around
/// the double estimate. Each b* takes the path its planner chooses (the long-delay path for a
/// delay of 1000 samples), so the bracket is what a long delay costs: ~30 certified b*.
void bracket(const GainProblem& p, const BoundProblem& q0, const BoundProblem& q1, int digits, MaxGain& m) {
  double omega = 0;
  BoundProblem e0 = q0, e1 = q1;
  e0.eta = e1.eta = 0;
  const double Kg = estimate(e0, e1, to_real<double>(p.b - q0.eta), &omega);
  if (!std::isfinite(Kg) || Kg <= 0)
    throw NumericalError("--max " + p.name + ": no frequency where b* grows with " + p.name +
                         " on a 4097-point grid, so K_max may be infinite, which a bracket of b* values cannot prove; "
                         "round t_d to a fraction p/q of T with a small q (decided exactly)");
  const int dig = std::min(digits, 20);
  rational L = 0, bL = m.at_zero.value, bU = 0;
  std::optional<rational> U;
  long evaluations = 0;
  auto try_at = [&](const rational& K) {
    if (K <= L || (U && K >= *U)) return;
    ++evaluations;
    const Bound b = bound_certified(at_gain(p, K), dig);
    if (!b.infinite && b.enclosure->hi < p.b) L = K, bL = b.value;
    else if (b.infinite || b.enclosure->lo >= p.b) U = K, bU = b.infinite ? rational(0) : b.value;
  };
  for (double delta : {1e-13, 1e-11, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1}) {
    try_at(exact_rational(Kg * (1 - delta)));
    try_at(exact_rational(Kg * (1 + delta)));
    if (L > 0 && U) break;
  }
  for (double f = 2; !U && f < 1e30; f *= 4) try_at(exact_rational(Kg * f));
  for (double f = 0.5; L == 0 && f > 1e-30; f /= 4) try_at(exact_rational(Kg * f));
  if (!U || L == 0)
    throw NumericalError("--max " + p.name + ": certified b* did not bracket b around the estimate " + p.name + " = " +
                         std::to_string(Kg));
  // secant steps on the b* values at the ends (b* is known to 10^-dig): each chord meets b at or
  // below K_max (b* is convex), so Ks (1 -+ w) narrows the bracket from both sides, down to a few
  // digits above b*'s own resolution
  const rational finest = pow10(-(dig - 3));
  for (int it = 0; it < 12 && *U - L > finest * *U && bU > bL; ++it) {
    const rational Ks = L + (p.b - bL) * (*U - L) / (bU - bL), w = std::max(finest, (*U - L) / *U / 1000);
    const rational before = *U - L;
    try_at(Ks * (1 - w));
    try_at(Ks * (1 + w));
    if (*U - L == before) break;
  }
  m.outcome = Outcome::holds;
  m.status = Status::certified;
  m.value = (L + *U) / 2;
  m.enclosure = Enclosure<rational>{L, *U};
  m.where = "near w = " + to_decimal(exact_rational(omega), 12) + " rad/s (double estimate)";
  m.method = "certified bracket: b*(" + p.name + ") is convex in " + p.name + "; b*(lo) < b and b*(hi) >= b proven by " +
             std::to_string(evaluations) + " certified b* evaluations (" + std::to_string(dig) + " digits) around a double estimate";
}

}  // namespace

std::optional<rational> jump_at_minus_one(const GainProblem& p) {
  const BoundProblem q = with_integer_delay(p.base);
  if (!q.frac_delay) return std::nullopt;  // sin(nu pi) = 0: the pole term stays finite at wT = pi
  const rational nu = rational(q.delay) + *q.frac_delay / q.T, m1(-1);
  std::optional<rational> rho[2];
  int k = 0;
  for (const QRatFun* part : {&p.base.H, &p.H1}) {
    const QPoly &N = part->num(), &D = part->den();
    if (D(m1) != 0) rho[k++] = rational(0);
    else if (const rational d1 = D.derivative()(m1); d1 != 0) rho[k++] = N(m1) / d1;
    else return std::nullopt;  // a repeated pole on the circle: refused by check_assumptions anyway
  }
  const int sin_sign = integer(num(nu) / den(nu)) % 2 == 0 ? 1 : -1;  // sin(nu pi), nu > 0 not whole
  if (sgn(*rho[1]) * sin_sign >= 0) return std::nullopt;
  const rational K = -*rho[0] / *rho[1];
  if (K <= 0) return std::nullopt;
  return K;
}

namespace {

/// K_max at a jump of b* (MaxGain::jump): where the enclosure holds the K above which the pole at
/// z = -1 makes b* = +inf and b*(K) <= b there is proven, K_max = K exactly (b* < b on [0, K) by
/// convexity from b*(0) < b; +inf above).
void mark_jump(const GainProblem& p, MaxGain& m, int digits) {
  if (m.outcome != Outcome::holds || m.infinite || !m.enclosure) return;
  const std::optional<rational> K = jump_at_minus_one(p);
  if (!K || !m.enclosure->contains(*K)) return;
  const Bound at = bound_certified(at_gain(p, *K), digits);
  if (at.infinite || at.enclosure->hi > p.b) return;
  m.jump = true;
  m.at_sup = at;
  m.omega.reset();  // b* does not reach b at a frequency: it diverges at wT = pi just above the sup
  m.where = "wT = pi (H's pole at z = -1)";
  m.status = Status::exact;
  m.value = *K;
  m.enclosure = Enclosure<rational>{*K, *K};
}

}  // namespace

MaxGain max_gain(const GainProblem& p, int digits) {
  if (digits < 10 || digits > 280) throw InputError("--digits must be in [10, 280] (got " + std::to_string(digits) + ")");
  if (p.b <= 0) throw InputError("the device damping b must be > 0 (got " + to_decimal(p.b, 17) + ")");
  if (p.H1.is_zero()) throw InputError("H does not depend on " + p.name);
  BoundProblem p1 = p.base;
  p1.H = p.H1;
  p1.eta = 0;
  try {
    check_assumptions(p1);
  } catch (const InputError& e) {
    throw InputError("the part of H in " + p.name + " (H = H0 + " + p.name + " H1): " + e.what());
  }
  MaxGain m;
  m.method = "certified: " + p.name + "_max = 1/max psi, psi = f1/(b - eta - f0) in cos wT (the maximiser of b*: "
             "Descartes root isolation, MPFR Newton, MPFI enclosure, " + std::to_string(digits) + " digits)";
  m.at_zero = bound_certified(p.base, digits);
  if (m.at_zero.infinite || m.at_zero.enclosure->lo >= p.b) {
    zero(m, "not passive at " + p.name + " = 0: b*(0) = " + (m.at_zero.infinite ? "inf" : m.at_zero.decimal) +
                " >= b = " + dec(p.b));
    // b*(0) = +inf shown in balls (a pole on the circle beyond the exact path): K_max = 0 no more than certified
    if (m.at_zero.infinite && m.at_zero.status == Status::certified) m.status = Status::certified;
    return m;
  }
  if (m.at_zero.enclosure->hi >= p.b)
    throw NumericalError("b = " + dec(p.b) + " lies inside the enclosure of b*(0); raise --digits");
  if (p.H1.den()(rational(1)) == 0) {  // H0 has no pole at z = 1 (b*(0) is finite): H has one for every K != 0
    zero(m, "the part of H in " + p.name + " has a pole at z = 1 (an integrator): b* = +inf for every " + p.name + " > 0");
    return m;
  }
  const BoundProblem q0 = with_integer_delay(p.base), q1 = with_integer_delay(p1);
  const rational bp = p.b - q0.eta;
  // psi has the degree of the delayed objective: where b* itself takes the long-delay path (a delay
  // of hundreds of samples), psi's exact maximisation would not end in minutes -- bracket instead
  if (plan_bound(at_gain(p, 1)).path == BoundPath::long_delay) {
    m.path = BoundPath::long_delay;
    bracket(p, q0, q1, digits, m);
    mark_jump(p, m, digits);
    set_decimal(m, digits);
    m.note = "a long delay: " + p.name + "_max bracketed by certified b* on the long-delay path" +
             (m.jump                ? "; exact at the jump of b*"
              : digits > m.digits ? " (" + std::to_string(digits) + " digits asked, about 17 given)"
                                  : std::string());
    return m;
  }
  // 1: decided; 0: precision D not enough; -1: t_d's change of variable does not apply
  auto attempt = [&](auto precision) -> int {
    constexpr unsigned D = decltype(precision)::value;
    Bound psi;
    const std::optional<bool> ok = max_psi<D>(q0, q1, bp, digits, psi);
    if (!ok) return -1;
    return *ok && from_psi(psi, p, m) ? 1 : 0;
  };
  try {
    int r = 0;
    if (digits <= 30) r = attempt(std::integral_constant<unsigned, 50>{});
    if (r == 0 && digits <= 80) r = attempt(std::integral_constant<unsigned, 100>{});
    if (r == 0) r = attempt(std::integral_constant<unsigned, 300>{});
    if (r == 1) {
      mark_jump(p, m, digits);
      set_decimal(m, digits);
      return m;
    }
    if (r == 0 && !q0.frac_delay) throw NumericalError("could not decide " + std::to_string(digits) + " digits of " + p.name + "_max");
  } catch (const NumericalError&) {
    if (!q0.frac_delay) throw;  // the exact path failed in a way a bracket of b* would not fix
  }
  m.omega.reset();
  m.where.clear();
  bracket(p, q0, q1, digits, m);
  mark_jump(p, m, digits);
  set_decimal(m, digits);
  if (!m.jump && digits > m.digits) m.note = std::to_string(digits) + " digits asked; a bracket by certified b* (20 digits) gives about 17";
  return m;
}

BoundaryCheck check_boundary(const GainProblem& p, const MaxGain& m, int digits) {
  if (m.outcome != Outcome::holds || m.infinite || !m.enclosure)
    throw InputError("check_boundary: K_max is not a finite positive number");
  BoundaryCheck c;
  if (m.jump) {  // b*(K_max) <= b, and +inf above by the pole at z = -1 (jump_at_minus_one), not b* = b
    c.at_lo = c.at_hi = bound_certified(at_gain(p, m.value), digits);
    c.holds = !c.at_lo.infinite && c.at_lo.enclosure->lo <= p.b && jump_at_minus_one(p) == m.value;
    return c;
  }
  c.at_lo = bound_certified(at_gain(p, m.enclosure->lo), digits);
  c.at_hi = m.enclosure->lo == m.enclosure->hi ? c.at_lo : bound_certified(at_gain(p, m.enclosure->hi), digits);
  c.holds = !c.at_lo.infinite && c.at_lo.enclosure->lo <= p.b && (c.at_hi.infinite || c.at_hi.enclosure->hi >= p.b);
  return c;
}

// ---------------------------------------------------------------------------------------------
// closed forms solved for the parameter
namespace {

QPoly affine(const rational& c0, const rational& c1) { return QPoly(std::vector<rational>{c0, c1}); }

/// One piece of a piecewise closed form of b*: on the K where every `region` polynomial is >= 0,
/// b*(K) = b exactly where `crossing`(K) = 0.
struct Branch {
  QPoly crossing;
  std::vector<QPoly> region;
  std::string formula;
};

/// Sign of the linear (or constant) r at the root of p isolated by `root`.
int sign_at_root(const QPoly& r, const QPoly& p, RootInterval root) {
  if (r.degree() <= 0) return r.is_zero() ? 0 : sgn(r.coeff(0));
  if (root.is_exact()) return sgn(r(root.lo));
  const rational rho = -r.coeff(0) / r.coeff(1);
  if (p(rho) == 0 && root.lo <= rho && rho <= root.hi) return 0;
  while (root.lo <= rho && rho <= root.hi && !root.is_exact()) root = refine_root(p, root, (root.hi - root.lo) / 4);
  return sgn(r((root.lo + root.hi) / 2));
}

struct Crossing {
  QPoly p;
  RootInterval r;
  std::string formula;
};

/// The smallest K > 0 where some branch crosses b inside its region (nullopt: none).
std::optional<Crossing> first_crossing(const std::vector<Branch>& branches) {
  std::optional<Crossing> best;
  const rational tiny = pow10(-60);
  for (const Branch& br : branches) {
    if (br.crossing.degree() <= 0) continue;
    for (RootInterval r : isolate_real_roots(br.crossing)) {
      if (br.crossing(rational(0)) == 0 && r.lo <= 0 && r.hi >= 0) continue;  // K = 0: b*(0) = b, not a crossing above 0
      while (r.lo < 0 && r.hi > 0) r = refine_root(br.crossing, r, (r.hi - r.lo) / 4);
      if (r.hi <= 0) continue;
      bool inside = true;
      for (const QPoly& g : br.region) inside = inside && sign_at_root(g, br.crossing, r) >= 0;
      if (!inside) continue;
      if (!r.is_exact()) r = refine_root(br.crossing, r, tiny * (1 + r.hi));
      if (!best || r.hi < best->r.lo || (r.lo <= best->r.hi && r.is_exact() && !best->r.is_exact()))
        best = Crossing{br.crossing, r, br.formula};
    }
  }
  return best;
}

/// Every class condition g (linear) >= 0 on [0, K*] (K* = +inf: on [0, inf)).
bool holds_on(const std::vector<QPoly>& conditions, const std::optional<Crossing>& c) {
  for (const QPoly& g : conditions) {
    if (g(rational(0)) < 0) return false;
    if (!c) {
      if (g.coeff(1) < 0) return false;
    } else if (g(c->r.lo) < 0 || g(c->r.hi) < 0) {
      return false;
    }
  }
  return true;
}

std::vector<rational> padded(std::vector<rational> a, size_t n) {
  a.resize(std::max(a.size(), n), rational(0));
  return a;
}

}  // namespace

std::optional<MaxGainClosedForm> max_gain_closed_form(const GainProblem& p) {
  const BoundProblem q = with_integer_delay(p.base);
  if (q.frac_delay || p.b <= 0 || p.H1.is_zero()) return std::nullopt;
  check_problem_size(q);
  const rational& T = q.T;
  const int n = q.delay;
  const rational bp = p.b - q.eta;
  const std::string& K = p.name;
  const std::string bs = q.eta == 0 ? "b" : "b - eta", bsp = q.eta == 0 ? "b" : "(b - eta)";
  const std::string with = " with b = " + dec(p.b) + (q.eta == 0 ? "" : ", eta = " + dec(q.eta)) + ", T = " + dec(T);
  MaxGainClosedForm cf;
  std::vector<Branch> branches;
  std::vector<QPoly> conditions;  // linear in K, >= 0 on [0, K_max]
  const auto a0 = catalogue::backward_difference_coefficients(q.H, T), a1 = catalogue::backward_difference_coefficients(p.H1, T);
  if (a0 && a1) {
    const size_t M = std::max(a0->size(), a1->size());
    const std::vector<rational> c0 = padded(*a0, M), c1 = padded(*a1, M);
    std::vector<QPoly> alpha;  // alpha_m(K) = c0_m + K c1_m
    std::vector<size_t> used;
    for (size_t m = 0; m < M; ++m) {
      alpha.push_back(affine(c0[m], c1[m]));
      conditions.push_back(alpha.back());
      if (!alpha.back().is_zero()) used.push_back(m);
    }
    const bool wall = M <= 2;
    const QPoly Kw = alpha[0], Bw = M > 1 ? alpha[1] : QPoly();
    const bool stiffness = wall && c1[0] == 1 && (M < 2 || c1[1] == 0) && c0[0] == 0;  // H = K + B(z-1)/(Tz)
    const bool damping = wall && M == 2 && c1[0] == 0 && c1[1] == 1 && c0[1] == 0;      // H = K + B(z-1)/(Tz) in B
    const rational B0 = M > 1 ? c0[1] : rational(0), K0 = c0[0];
    if (n == 0) {
      QPoly s;
      rational w = 2 / T;  // (2/T)^{m-1}, from m = 0
      w = 1 / w;
      for (size_t m = 0; m < M; ++m, w *= 2 / T) s += alpha[m] * QPoly(w);
      cf.name = wall ? "virtual wall (backward difference)" : "non-negative combination of backward differences H_m";
      cf.equation = "(46)";
      std::string f = stiffness ? K + " <= 2(" + bs + " - B)/T" + with + ", B = " + dec(B0)
                      : damping ? K + " <= " + bs + " - KT/2" + with + ", K = " + dec(K0)
                                : "sum_m alpha_m(" + K + ") (2/T)^{m-1} = " + bs + " (linear in " + K + ")" + with;
      branches.push_back({s - QPoly(bp), {}, f});
    } else if (used.size() == 1 && (used[0] == 0 || n % 2 == 0 || used[0] == 1)) {
      const size_t m = used[0];
      const rational w = m == 0 ? rational(2 * n + 1) * T / 2 : catalogue::delayed_backward_difference(int(m), n, T);
      cf.name = m == 0 ? "constant with delay n = " + std::to_string(n) + " (Dirichlet kernel)"
                       : "backward difference H_" + std::to_string(m) + " with delay n = " + std::to_string(n);
      cf.equation = "Example 4";
      const bool plain = c0[m] == 0 && c1[m] == 1;
      std::string f = m == 0 ? (plain ? K + " <= 2" + bsp + "/((2n+1)T), n = " + std::to_string(n) + with
                                      : "(2n+1) alpha_0(" + K + ") T/2 = " + bs + ", n = " + std::to_string(n) + with)
                             : "alpha_" + std::to_string(m) + "(" + K + ") (2/T)^" + std::to_string(m - 1) + " = " + bs + with;
      branches.push_back({alpha[m] * QPoly(w) - QPoly(bp), {}, f});
    } else if (wall && n == 1) {
      cf.name = "virtual wall with delay n = 1";
      cf.equation = "(53)";
      const QPoly KT = Kw * QPoly(T);
      // KT >= 4B: KT/2 + B + (KT - 2B) = 3KT/2 - B;  KT < 4B: KT/2 + B + K^2T^2/(8B), times 8B > 0
      const std::string a = stiffness ? K + " <= 2(" + bs + " + B)/(3T) (KT >= 4B: " + bs + " >= 5B)" + with + ", B = " + dec(B0)
                            : "3KT/2 - B = " + bs + " (KT >= 4B)" + with;
      const std::string c = stiffness ? K + " T = 2 sqrt(B(2" + bsp + " - B)) - 2B (KT < 4B: " + bs + " < 5B)" + with + ", B = " + dec(B0)
                            : damping ? K + " = ((2" + bsp + " - KT) + sqrt((2" + bsp + " - KT)^2 - 2K^2T^2))/4 (B > KT/4)" + with + ", K = " + dec(K0)
                                      : "KT/2 + B + K^2T^2/(8B) = " + bs + " (KT < 4B)" + with;
      branches.push_back({KT * QPoly(rational(3, 2)) - Bw - QPoly(bp), {KT - Bw * QPoly(4)}, a});
      branches.push_back({Bw * QPoly(8) * (KT * QPoly(rational(1, 2)) + Bw - QPoly(bp)) + KT * KT, {Bw * QPoly(4) - KT}, c});
    } else if (wall && n >= 2) {
      cf.name = "virtual wall with delay n = " + std::to_string(n) + " (conservative)";
      cf.equation = "(53)";
      cf.tight = false;
      const rational w = rational(2 * n + 1) * T / 2;
      std::string f = stiffness ? K + " >= 2(" + bs + " - B)/((2n+1)T), n = " + std::to_string(n) + with + ", B = " + dec(B0) +
                                      " (a lower bound: (2n+1)KT/2 + B bounds b* from above)"
                                : "(2n+1)KT/2 + B = " + bs + ", n = " + std::to_string(n) + with + " (a lower bound of " + K + "_max)";
      branches.push_back({Kw * QPoly(w) + Bw - QPoly(bp), {}, f});
    } else {
      return std::nullopt;
    }
  } else {
    // Tustin walls K + (2B/T)(z-1)/(z+1): each part times (z + 1) a polynomial of degree <= 1
    const QPoly zp1(std::vector<rational>{rational(1), rational(1)});
    auto tustin = [&](const QRatFun& H, rational& Kt, rational& Bt) {
      const QRatFun P = H * QRatFun(zp1);
      if (P.den().degree() != 0 || P.num().degree() > 1) return false;
      const rational n0 = P.num().coeff(0) / P.den().coeff(0), n1 = P.num().coeff(1) / P.den().coeff(0);
      Kt = (n0 + n1) / 2;
      Bt = (n1 - n0) / 2 * T / 2;
      return true;
    };
    rational k0, b0, k1, b1;
    if (!tustin(q.H, k0, b0) || !tustin(p.H1, k1, b1) || n > 1) return std::nullopt;
    const QPoly Kw = affine(k0, k1), Bw = affine(b0, b1), KT = Kw * QPoly(T);
    const bool stiffness = k1 == 1 && b1 == 0 && k0 == 0, damping = k1 == 0 && b1 == 1 && b0 == 0;
    if (n == 0) {
      cf.name = "Tustin wall";
      cf.equation = "Example 3";
      branches.push_back({KT * QPoly(rational(1, 2)) - Bw - QPoly(bp), {},
                          stiffness ? K + " <= 2(" + bs + " + B)/T" + with + ", B = " + dec(b0)
                                    : "KT/2 - B = " + bs + with});
    } else {
      cf.name = "Tustin wall with delay n = 1";
      cf.equation = "Example 4";
      branches.push_back({KT * QPoly(rational(3, 2)) - Bw - QPoly(bp), {KT - Bw * QPoly(2)},
                          stiffness ? K + " <= 2(" + bs + " + B)/(3T) (KT >= 2B)" + with + ", B = " + dec(b0)
                                    : "3KT/2 - B = " + bs + " (KT >= 2B)" + with});
      branches.push_back({Bw * QPoly(3) - KT * QPoly(rational(1, 2)) - QPoly(bp), {Bw * QPoly(2) - KT},
                          damping ? K + " <= (" + bs + " + KT/2)/3 (2B >= KT)" + with + ", K = " + dec(k0)
                                  : "3B - KT/2 = " + bs + " (KT < 2B)" + with});
    }
  }
  // b*(0) < b in the closed form itself (the first branch whose region holds at 0)
  for (const Branch& br : branches) {
    bool at0 = true;
    for (const QPoly& g : br.region) at0 = at0 && g(rational(0)) >= 0;
    if (at0 && br.crossing(rational(0)) >= 0) return std::nullopt;
    if (at0) break;
  }
  const std::optional<Crossing> c = first_crossing(branches);
  if (!holds_on(conditions, c)) return std::nullopt;
  if (!c) {
    cf.infinite = true;
    cf.formula = branches.front().formula + ": no crossing, b* < b for every " + K + " >= 0";
    return cf;
  }
  cf.formula = c->formula;
  if (c->r.is_exact()) cf.value = c->r.lo;
  else {
    cf.root_of = c->p;
    cf.root_in = Enclosure<rational>{c->r.lo, c->r.hi};
  }
  return cf;
}

std::string closed_form_decimal(const MaxGainClosedForm& c, int digits) {
  if (c.infinite) return "inf";
  if (c.value) return to_decimal(*c.value, digits);
  RootInterval r{c.root_in->lo, c.root_in->hi};
  for (int k = 0; k < 50; ++k) {
    if (const auto d = common_decimal(r.lo, r.hi, digits)) return *d;
    r = refine_root(*c.root_of, r, (r.hi - r.lo) * pow10(-digits));
  }
  return to_decimal((r.lo + r.hi) / 2, digits);
}

bool agrees(const MaxGainClosedForm& c, const MaxGain& m) {
  if (c.infinite) return m.infinite;
  if (m.infinite) return !c.tight;
  if (m.outcome != Outcome::holds || !m.enclosure) return false;
  const auto& [lo, hi] = *m.enclosure;
  if (!c.tight) return c.value ? *c.value <= hi : c.root_in->lo <= hi;
  if (c.value) return m.enclosure->contains(*c.value);
  // the algebraic root inside [lo, hi]: the root of root_of isolated by root_in lies in [lo, hi]
  const QPoly& P = *c.root_of;
  const rational a = std::max(lo, c.root_in->lo), b = std::min(hi, c.root_in->hi);
  if (a > b) return false;
  if (P(a) == 0) return true;
  return count_real_roots(P, a, b) == 1;
}

BoundMax bound_max(GainProblem g, int digits, bool check) {
  BoundMax r;
  r.max = max_gain(g, digits);
  if (r.max.outcome == Outcome::holds) r.closed_form = max_gain_closed_form(g);
  if (check && r.max.outcome == Outcome::holds && !r.max.infinite) r.check = check_boundary(g, r.max, digits);
  r.problem = std::move(g);
  return r;
}

}  // namespace hapstab::passivity
