// The passivity bound (45)/(54) for any delay nu = n + t_d/T samples without expanding z^-n
// (the long-delay path; bound_detail.hpp). With H~ = H - rho/(z + 1) (rho = 0 unless H has a
// simple pole at z = -1) and the c = cos(theta) pieces of H~ without delay (bound.hpp),
// A = R - (1 + c) Q, E = R + (1 - c) Q, B = |D|^2, the objective is
//   f(theta) = (T/2) [ (A/B + rho) cos(nu theta) + (E/B + rho/2) S_nu(theta)
//                      - (rho/2) sin(nu theta) tan(theta/2) ] + eta,     S_nu = sin(nu theta) cot(theta/2)
// (claim 001.eq45.delay_form, proofs/delay_kernels.cpp): low-order rational functions of c times
// two oscillating kernels, finite on all of [0, pi] in the sinc forms of numeric/jet.hpp. For a
// whole delay n the last term is rho (-1)^n S_n(pi - theta)/2, finite at pi too; for nu not whole it
// goes to -(rho/2) sin(nu pi)(+inf) at pi: +inf (b* = +inf, fractional_divergence) or -inf, whose
// last piece [a, pi] the branch-and-bound bounds by its sign (Maximiser::tail).
// f(0) = (T/2)[A(1)/B(1) + rho + nu (2 E(1)/B(1) + rho)] + eta exactly, and f'(0) = 0 (f is even).
//
// Certified: interval branch-and-bound over theta in [0, pi] in Arb balls with order-2 jets:
// on each box the second-order Taylor form bounds f from above; a box whose bound is below the
// best proven value is dropped, one where f' has one sign gives its end, one where f is concave
// (f'' < 0) gives its maximum by interval Newton on f'. The first boxes are ~1/(4 nu) wide (the
// kernels oscillate with period 2 pi/nu), so the work grows like nu (claim 001.eq45.taylor_bound).
// Each box is first decided in double intervals with rounding bounds (numeric/dinterval.hpp, the
// bounds derived there in units of u = 2^-53): the same jets over Dint, sin and cos of theta/2 and
// of nu theta at the box's grid point pi k/D by an exact integer reduction of k p/(q D) (nu = p/q;
// no bit of nu theta lost), widened over the box by their Lipschitz constants 1/2 and nu. Pruned
// there: a box whose natural or midpoint-Taylor bound, or whose value at its higher end where f
// is monotone, or (f concave) f(x) + f'(x)^2/(-2 sup f'') at a Newton point x, lies below the
// best proven value; a box far above it (10^-6) with f' holding 0 and f'' not negative is split
// without Arb. The rest -- the few boxes near the maximum -- take the Arb process below. A retry
// at more bits skips the first boxes the last attempt pruned below its proven value (<= b*).
// Fast: the same f in double, sampled on the same grid, its best local maxima polished by Newton.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/dinterval.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/jet.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::passivity::detail {

using flint::Ball;
using jet::Jet;

// ---- the exact pieces -------------------------------------------------------------------------
std::optional<LongDelayPole> long_delay_applies(const BoundProblem& p, std::string* why) {
  LongDelayPole pole;
  const rational nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  const QPoly& D = p.H.den();
  // H's poles on |z| = 1 (H is stable: no reciprocal pairs); the last D's kept on this thread (a
  // vectorised b* over a parameter of H's numerator asks about one D at every point)
  thread_local std::optional<std::pair<QPoly, QPoly>> last;
  if (!last || !(last->first == D)) last.emplace(D, gcd(D, reversed(D)));
  const QPoly& circle = last->second;
  if (circle.degree() > 0) {
    const QPoly plus_one({rational(1), rational(1)});
    if (circle.degree() > 1 || !(circle == plus_one || circle == plus_one.monic())) {
      if (why) *why = "H has a pole on the unit circle at z != -1 (" + to_string(circle, "z") + " divides its denominator)";
      return std::nullopt;
    }
    // a simple pole at z = -1: H = H~ + rho/(z + 1), rho = N(-1)/D'(-1)
    pole.at_minus_one = true;
    pole.rho = p.H.num()(rational(-1)) / D.derivative()(rational(-1));
    // nu not whole: the pole's part (T/2) rho sin((nu + 1) theta)/sin(theta) -> -rho sin(nu pi) (T/2)/(pi - theta)
    // at theta -> pi, sign sin(nu pi) = (-1)^floor(nu); +inf (fractional_divergence decides it exactly
    // before any path) or -inf, which the branch-and-bound's tail bound sets aside (Maximiser::tail)
    if (den(nu) != 1 && pole.rho != 0) {
      const integer whole = num(nu) / den(nu);  // nu > 0: floor
      const bool plus_inf = (pole.rho > 0) == (whole % 2 != 0);
      if (plus_inf) {
        if (why) *why = "H has a pole at z = -1 that the delay nu = " + to_decimal(nu, 12) +
                        " samples sends to +inf at wT = pi (b* = +inf, decided by the exact divergence test)";
        return std::nullopt;
      }
    }
  }
  return pole;
}

std::optional<DelayForm> delay_form(const BoundProblem& p, std::string* why) {
  const std::optional<LongDelayPole> pole = long_delay_applies(p, why);
  if (!pole) return std::nullopt;
  DelayForm f;
  f.nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  f.n = p.delay;
  f.integer_nu = den(f.nu) == 1;
  if (f.integer_nu) f.n = num(f.nu).convert_to<long>();
  f.T = p.T;
  f.eta = p.eta;
  QRatFun Ht = p.H;
  if (pole->at_minus_one) {
    f.rho = pole->rho;
    Ht = p.H - QRatFun(QPoly(f.rho), QPoly({rational(1), rational(1)}));
  }
  const Objective o = objective(Ht, p.T, 0);
  const QPoly one_plus_c({rational(1), rational(1)}), one_minus_c({rational(1), rational(-1)});
  f.A = o.R - one_plus_c * o.Q;
  f.E = o.R + one_minus_c * o.Q;
  f.B = o.B;
  const rational one(1), mone(-1);
  f.at_zero = p.T / 2 * (f.A(one) / f.B(one) + f.rho + f.nu * (2 * f.E(one) / f.B(one) + f.rho)) + p.eta;
  if (f.integer_nu) {
    const rational sign = f.n % 2 == 0 ? 1 : -1;
    f.at_pi = p.T / 2 * sign * (f.A(mone) / f.B(mone) + f.rho + f.rho * f.nu) + p.eta;
  }
  f.constant = f.A.is_zero() && f.E.is_zero() && f.rho == 0;
  return f;
}

namespace {

// ---- the objective as a jet, in double or in balls ------------------------------------------
template <class S>
struct Form {
  std::vector<S> A, E, B;  // ascending in c
  S half_T, rho, half_rho, nu, eta, pi;
  S parity;           // (-1)^n (integer nu only)
  S pole_weight;      // rho (-1)^n / 2
  bool pole = false;  // a pole of H at z = -1 (rho != 0)
  bool frac_pole = false;  // that pole with nu not whole: its part -rho sin(nu theta) tan(theta/2)/2 -> -inf at pi
  explicit Form(const DelayForm& f)
      : half_T(jet::scalar<S>(f.T / 2)), rho(jet::scalar<S>(f.rho)), half_rho(jet::scalar<S>(f.rho / 2)),
        nu(jet::scalar<S>(f.nu)), eta(jet::scalar<S>(f.eta)), pi(jet::scalar_pi<S>()),
        parity(f.n % 2 == 0 ? 1.0 : -1.0), pole_weight(jet::scalar<S>(f.rho / 2 * (f.n % 2 == 0 ? 1 : -1))),
        pole(f.rho != 0), frac_pole(f.rho != 0 && !f.integer_nu) {
    auto fill = [](std::vector<S>& v, const QPoly& p) {
      for (const rational& c : p.coeffs()) v.push_back(jet::scalar<S>(c));
      if (v.empty()) v.push_back(S(0.0));
    };
    fill(A, f.A);
    fill(E, f.E);
    fill(B, f.B);
  }
};

/// Which terms of f objective_jet sums: all of them; all but the part of a pole at z = -1 met by a
/// fractional delay that is unbounded at pi, -(T/2)(rho/2) sin(nu theta) tan(theta/2); or H~'s alone,
/// without any of the pole's part (Maximiser::tail bounds the rest).
enum class Terms { all, bounded, without_pole };

/// f, f', f'' at theta (a point, or every point of a ball or interval), given sin and cos of
/// theta/2 and of nu theta there.
template <class S>
Jet<S> objective_jet(const Form<S>& F, const S& theta, const S& sh, const S& ch, const S& snu, const S& cnu,
                     Terms terms = Terms::all) {
  const S s1 = S(2.0) * (sh * ch), c1 = S(1.0) - S(2.0) * (sh * sh);
  const Jet<S> th = jet::variable(theta);
  const Jet<S> c{c1, -s1, -c1};
  const Jet<S> b = jet::horner(F.B, c);
  const Jet<S> alpha = jet::horner(F.A, c) / b, gamma = jet::horner(F.E, c) / b;
  const Jet<S> cos_nu{cnu, -(F.nu * snu), -((F.nu * F.nu) * cnu)};
  const Jet<S> s_nu = jet::kernel_S(th, F.nu, snu, cnu, sh, ch);
  if (terms == Terms::without_pole) {
    Jet<S> out = F.half_T * (alpha * cos_nu + gamma * s_nu);
    out.v = out.v + F.eta;
    return out;
  }
  Jet<S> f = (alpha + jet::constant(F.rho)) * cos_nu + (gamma + jet::constant(F.half_rho)) * s_nu;
  if (F.frac_pole) {  // rho sin(nu theta) cot(theta) = rho S_nu/2 - rho sin(nu theta) tan(theta/2)/2 (claim 001.eq45.delay_form)
    if (terms == Terms::all) {
      const Jet<S> sin_nu{snu, F.nu * cnu, -((F.nu * F.nu) * snu)};
      const Jet<S> sin_half{sh, S(0.5) * ch, S(-0.25) * sh}, cos_half{ch, S(-0.5) * sh, S(-0.25) * ch};
      f = f - F.half_rho * (sin_nu * (sin_half / cos_half));
    }
  } else if (F.pole) {  // S_n(eps), eps = pi - theta: sin(n eps) = -(-1)^n sin(n theta), cos(n eps) = (-1)^n cos(n theta),
                 // sin(eps/2) = cos(theta/2), cos(eps/2) = sin(theta/2)
    const Jet<S> eps = jet::constant(F.pi) - th;
    f = f + F.pole_weight * jet::kernel_S(eps, F.nu, -(F.parity * snu), F.parity * cnu, ch, sh);
  }
  Jet<S> out = F.half_T * f;
  out.v = out.v + F.eta;
  return out;
}
template <class S>
Jet<S> objective_jet(const Form<S>& F, const S& theta) {
  S sh, ch, snu, cnu;
  jet::sin_cos(theta * S(0.5), sh, ch);
  jet::sin_cos(F.nu * theta, snu, cnu);
  return objective_jet(F, theta, sh, ch, snu, cnu);
}

// ---- the objective in double intervals on the branch-and-bound's grid ------------------------
/// f, f', f'' enclosed in double intervals (numeric/dinterval.hpp) at theta = pi k/D or over
/// [pi (k - 1)/D, pi (k + 1)/D], for the grid points of the search (D = M 2^level): sin and cos
/// of theta/2 = pi k/(2D) and of nu theta = pi p k/(q D) (nu = p/q) by sin_cos_pi's exact integer
/// reduction, so no bit of nu theta is lost however large nu is; over a box they are widened by
/// their Lipschitz bounds 1/2 and nu times the half-width pi/D. Unavailable (ok() false) when
/// p, q or the products do not fit 128 bits.
class DoubleGrid {
 public:
  explicit DoubleGrid(const DelayForm& df) : F_(df) {
    const integer p = num(df.nu), q = den(df.nu), limit = integer(1) << 100;
    ok_ = p < limit && q < limit;
    if (ok_) p_ = to_i128(p), q_ = to_i128(q);
  }
  bool ok() const { return ok_; }
  /// false when the integers overflow (the caller takes Arb)
  bool eval(__int128 k, __int128 D, bool box, Jet<Dint>& out) const {
    __int128 pk = 0, qD = 0;
    if (!ok_ || __builtin_mul_overflow(p_, k, &pk) || __builtin_mul_overflow(q_, D, &qD)) return false;
    Dint sh, ch, snu, cnu;
    if (!sin_cos_pi(k, 2 * D, sh, ch) || !sin_cos_pi(pk, qD, snu, cnu)) return false;
    const Dint pi = dint_pi(), inv = Dint(1.0) / Dint::from_i128(D);
    Dint theta = Dint::from_i128(k) * inv * pi;
    if (box) {
      const double r = (inv * pi).hi, rn = (F_.nu * Dint(r)).hi;
      theta = theta.widened(r).clamp(0, pi.hi);
      sh = sh.widened(r / 2).clamp(-1, 1), ch = ch.widened(r / 2).clamp(-1, 1);
      snu = snu.widened(rn).clamp(-1, 1), cnu = cnu.widened(rn).clamp(-1, 1);
    }
    out = objective_jet(F_, theta, sh, ch, snu, cnu);
    return true;
  }
  const Form<Dint>& form() const { return F_; }

 private:
  static __int128 to_i128(const integer& x) {  // 0 <= x < 2^100
    const integer hi = x >> 64, lo = x - (hi << 64);
    return (static_cast<__int128>(hi.convert_to<unsigned long long>()) << 64) | lo.convert_to<unsigned long long>();
  }
  Form<Dint> F_;
  bool ok_ = false;
  __int128 p_ = 0, q_ = 1;
};

// ---- the double scan: where the maximum is, in double (the fast path, and the certified path's
// first lower bound) ---------------------------------------------------------------------------
struct Peak {
  double value, theta;
};

/// The objective in double on the grid theta_i = pi i/M, the local maxima within the margin a
/// sample can miss a maximum by (|f''| h^2/2) polished by Newton on f', and the resonances of H
/// (the minima of B(c)) searched more finely: the best points found, largest value first.
std::vector<Peak> double_peaks(const DelayForm& df, long M, size_t keep) {
  const Form<double> F(df);
  const double pi = 3.14159265358979323846, h = pi / static_cast<double>(M);
  std::vector<double> v(static_cast<size_t>(M) + 1);
  v[0] = to_real<double>(df.at_zero);
  // h i rounded can pass fl(pi) by an ulp: kept inside [0, pi] (beyond pi the formula is not f: with a pole at
  // z = -1 met by a fractional delay it is +-1e17 there)
  for (long i = 1; i <= M; ++i) v[static_cast<size_t>(i)] = objective_jet(F, std::min(pi, h * static_cast<double>(i))).v;
  std::vector<Peak> peaks{{v[0], 0.0}};
  // Newton on f' from a start, kept inside [lo, hi]: the best point met
  auto polish = [&](double x, double lo, double hi) {
    Peak best{objective_jet(F, x).v, x};
    for (int it = 0; it < 30; ++it) {
      const Jet<double> j = objective_jet(F, x);
      if (j.v > best.value) best = {j.v, x};
      if (!(j.dd < 0)) break;
      const double xn = std::clamp(x - j.d / j.dd, lo, hi);
      if (std::abs(xn - x) <= 1e-16 * std::max(1.0, x)) break;
      x = xn;
    }
    const double fx = objective_jet(F, x).v;
    if (fx > best.value) best = {fx, x};
    peaks.push_back(best);
  };
  double top = v[0], curvature = 0;
  std::vector<long> local;
  for (long i = 1; i <= M; ++i) {
    top = std::max(top, v[static_cast<size_t>(i)]);
    if (v[static_cast<size_t>(i)] >= v[static_cast<size_t>(i) - 1] &&
        (i == M || v[static_cast<size_t>(i)] >= v[static_cast<size_t>(i) + 1])) {
      local.push_back(i);
      curvature = std::max(curvature, std::abs(objective_jet(F, h * static_cast<double>(i)).dd));
    }
  }
  const double margin = curvature * h * h / 2;
  for (long i : local)
    if (v[static_cast<size_t>(i)] >= top - margin)
      polish(std::min(pi, h * static_cast<double>(i)), h * static_cast<double>(i - 1), std::min(pi, h * static_cast<double>(i + 1)));
  // narrow resonances of H (minima of B(c), its critical points) may fall between samples: around
  // each, samples at the grid's scale and at the resonance's own, its half-width in theta
  // w = sqrt(2 B(c0)/B''(c0)) / sin(theta0) (B doubles there), which a pole at radius 1 - 1e-5
  // makes ~1e-5 rad against the grid's pi/(4 nu + 64) (delay 200, before: 0.70 for b* = 25.8)
  if (df.B.degree() >= 2) {
    const QPoly dB = df.B.derivative(), ddB = dB.derivative();
    for (auto r : isolate_real_roots(dB, rational(-1), rational(1))) {
      // an isolating interval can be wide: the centre of the resonance to double precision first
      if (!r.is_exact()) r = refine_root(dB, r, rational(1, 1000000000000000LL));
      const double c = to_real<double>((r.lo + r.hi) / 2), th = std::acos(std::clamp(c, -1.0, 1.0));
      const double b0 = to_real<double>(df.B(exact_rational(c))), b2 = to_real<double>(ddB(exact_rational(c)));
      const double width = b2 > 0 && b0 >= 0 ? std::sqrt(2 * b0 / b2) / std::max(std::sin(th), 1e-8) : h;
      double at = th, val = -std::numeric_limits<double>::infinity();
      for (const double step : {h / 8, std::min(h, width) / 8}) {
        for (int k = -32; k <= 32; ++k) {
          const double x = std::clamp(th + k * step, 0.0, pi);
          const double fx = objective_jet(F, x).v;
          if (fx > val) val = fx, at = x;
        }
      }
      const double reach = std::min(h, width) / 8;
      polish(at, std::max(0.0, at - reach), std::min(pi, at + reach));
    }
  }
  std::sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.value > b.value; });
  if (peaks.size() > keep) peaks.resize(keep);
  return peaks;
}

// ---- certified: branch-and-bound over theta in Arb balls ------------------------------------
Ball upper(const Ball& x) { return x.upper_end(); }
Ball lower(const Ball& x) { return x.lower_end(); }
bool less(const Ball& a, const Ball& b) { return arb_lt(a.get(), b.get()); }  // exact balls: exact comparison

/// sup over |t| <= r of d t + M t^2/2 for every d in the ball d and M = upper bound of f'' (the
/// Taylor form's increment over a box of half-width r around its midpoint), as a ball.
Ball taylor_increment(const Ball& d, const Ball& M, const Ball& r) {
  const Ball D = upper(flint::abs(d));
  if (M.negative()) {
    // concave: the maximum of D t + M t^2/2 is D^2/(-2M) at t = D/(-M), when that is inside [0, r]
    const Ball t = D / (-M);
    if (arb_le(upper(t).get(), lower(r).get())) return D * D / (-(M * 2L));
  }
  const Ball Mp = M.negative() ? Ball(0L) : M;
  return D * r + Mp * r * r / Ball(2L);
}

struct Piece {  // theta in [pi i / (M 2^level), pi (i + 1) / (M 2^level)]
  long i;
  int level;
};

class Maximiser {
 public:
  enum class Where { zero, pi, interior };
  /// settled: the first boxes an earlier attempt pruned in double intervals below its proven
  /// value proven_lo (<= b*, so they cannot hold the maximum at any precision), skipped here
  Maximiser(const DelayForm& df, long boxes, int digits, bool use_double, const std::vector<char>* settled = nullptr,
            const std::optional<rational>& proven_lo = std::nullopt)
      : df_(df), F_(df), floor_nu_(integer(num(df.nu) / den(df.nu)).convert_to<long>()), dbl_(df), use_double_(use_double && dbl_.ok()),
        M_(boxes), settled_(settled),
        first_pruned_(static_cast<size_t>(boxes), 0) {
    // the deepest level whose indices M 2^level stay below 2^62
    while (max_level_ > 0 && (M_ >> (62 - max_level_)) > 0) --max_level_;
    budget_ = 200 * M_ + 200000;  // Arb evaluations (~0.1 ms each at degree 60, 256 bits); set_budget lowers it
    tol_factor_ = Ball(pow10(-(digits + 3)));
    L_ = lower(Ball(df.at_zero));
    Ld_ = arf_get_d(arb_midref(L_.get()), ARF_RND_FLOOR);  // every change of L_ updates Ld_ <= L_
    H_ = upper(Ball(df.at_zero));
    best_at_ = Ball(0L);
    if (proven_lo) raise(Ball(*proven_lo));  // dyadic (an Arb end): exact
    best_hi_ = H_;
    if (df.at_pi) {
      add_exact_end(*df.at_pi, Ball::pi());
    } else if (!F_.frac_pole) {  // fractional nu: f(pi) = (T/2) A(-1)/B(-1) cos(nu pi) + eta, enclosed (beside a
                                 // pole at z = -1, f -> -inf at pi: no candidate there)
      Ball s, c;
      jet::sin_cos(F_.nu * F_.pi, s, c);
      const Ball v = F_.half_T * (Ball(df.A(rational(-1)) / df.B(rational(-1))) * c) + F_.eta;
      add_candidate(v, F_.pi, Where::pi);
    }
  }

  void set_budget(long evaluations) { budget_ = std::min(budget_, evaluations); }
  /// Runs the search; false when the work budget ran out before every piece was resolved.
  bool run() {
    // the best points of the double scan, evaluated in balls: a proven lower bound near b* from the start
    for (const Peak& pk : double_peaks(df_, M_, 8)) {
      if (pk.theta <= 0 || !less(Ball(pk.theta), F_.pi)) continue;  // a proven value of f only inside (0, pi)
      raise(lower(eval(Ball(pk.theta)).v));
    }
    for (long i = 0; i < M_; ++i) {  // every box, depth first
      if (settled_ && (*settled_)[static_cast<size_t>(i)]) {
        first_pruned_[static_cast<size_t>(i)] = 1;
        ++double_pruned_;
        continue;
      }
      std::vector<Piece> stack{{i, 0}};
      while (!stack.empty()) {
        const Piece p = stack.back();
        stack.pop_back();
        process(p, stack);
      }
    }
    return unresolved_ == 0;
  }

  Ball lo() const { return L_; }
  Ball hi() const { return less(H_, L_) ? L_ : H_; }
  /// Every upper bound not at an exact end value lies below v (none: true).
  bool others_below(const rational& v) const {
    if (arf_is_neg_inf(arb_midref(H_other_.get()))) return true;
    return H_other_.finite() && H_other_.bounds().hi < v;
  }
  const Ball& best_at() const { return best_at_; }
  Where best_where() const { return best_where_; }
  long evaluations() const { return evals_; }
  long double_evaluations() const { return double_evals_; }
  long double_pruned() const { return double_pruned_; }
  const std::vector<char>& first_pruned() const { return first_pruned_; }
  long unresolved() const { return unresolved_; }  // pieces settled by tolerance, depth or budget
  /// the last piece at pi left unresolved (tail): its bounds do not tighten with more bits
  bool tail_unresolved() const { return tail_unresolved_ > 0; }

 private:
  Ball theta(long i, int level) const {  // pi i / (M 2^level)
    Ball t(i);
    arb_div_si(t.get(), t.get(), M_, flint::ball_prec);
    arb_mul_2exp_si(t.get(), t.get(), -level);
    return t * F_.pi;
  }
  Jet<Ball> eval(const Ball& th) {
    ++evals_;
    return objective_jet(F_, th);
  }
  void raise(const Ball& lo) {
    if (less(L_, lo)) {
      L_ = lo;
      Ld_ = arf_get_d(arb_midref(L_.get()), ARF_RND_FLOOR);  // L_ is exact (an end): Ld_ <= L_
    }
  }
  void best(const Ball& u, const Ball& at, Where where) {
    if (less(best_hi_, u)) best_hi_ = u, best_at_ = at, best_where_ = where;
  }
  void add_candidate(const Ball& v, const Ball& at, Where where = Where::interior) {  // a piece's maximum lies in v
    if (!v.finite()) ++unresolved_;  // +inf into H: a piece not resolved, whatever path put it there
    raise(lower(v));
    const Ball u = upper(v);
    if (less(H_, u)) H_ = u;
    if (less(H_other_, u)) H_other_ = u;
    best(u, at, where);
  }
  void add_exact_end(const rational& v, const Ball& at) {  // f(pi) for an integer delay
    const Ball b(v);
    raise(lower(b));
    const Ball u = upper(b);
    if (less(H_, u)) H_ = u;
    best(u, at, Where::pi);
  }
  void unresolved(const Ball& ub, const Ball& at) {
    ++unresolved_;
    if (less(H_, ub)) H_ = ub;
    if (less(H_other_, ub)) H_other_ = ub;
    best(ub, at, Where::interior);
  }
  void end_value(long i, int level) {  // the candidate at the grid point pi i/(M 2^level)
    if (i == 0) return;                            // f(0): an exact end, already counted
    if (i == (M_ << level) && df_.at_pi) return;   // f(pi) for integer nu: likewise
    const Ball th = theta(i, level);
    add_candidate(eval(th).v, th);
  }

  /// What the double intervals say of a piece: pruned (its upper bound below the best proven
  /// value, by the natural enclosure, the Taylor form at its midpoint, or, where f is monotone,
  /// the value at the higher end); split (none of Arb's tests could settle it either: f' holds
  /// 0, f'' is not negative, and the bound lies far above the best value, 10^-6 of its scale,
  /// beyond any rounding: the halves are taken without Arb); else arb (Arb's process below).
  enum class InDouble { pruned, split, arb };
  InDouble in_double(const Piece& p) {
    const long last = M_ << p.level;
    if (F_.frac_pole && p.i + 1 == last) return InDouble::arb;  // the tail at pi: tail() in Arb
    const bool at_zero = p.i == 0, at_pi = p.i + 1 == last && df_.at_pi.has_value();
    const __int128 D = static_cast<__int128>(M_) << (p.level + 1), k = 2 * static_cast<__int128>(p.i) + 1;
    Jet<Dint> J, Jm;
    ++double_evals_;
    if (!dbl_.eval(k, D, true, J)) return InDouble::arb;
    const double w = (Dint(2.0) * dint_pi() / Dint::from_i128(D)).hi;  // the box's width, rounded up
    const Dint w2 = Dint(w) * Dint(w) * Dint(0.5);
    if (at_zero || at_pi) {  // as in process(): f <= f(end) + max(f'', 0) w^2/2
      if (!(J.dd.hi > 0)) return InDouble::pruned;
      const Dint end = Dint::from_rational(at_zero ? df_.at_zero : *df_.at_pi);
      return (end + Dint(J.dd.hi) * w2).hi < Ld_ ? InDouble::pruned : InDouble::arb;
    }
    if (J.v.hi < Ld_) return InDouble::pruned;
    ++double_evals_;
    if (!dbl_.eval(k, D, false, Jm)) return InDouble::arb;
    if (Jm.v.lo > Ld_) raise(Ball(Jm.v.lo));  // a proven value of f at the midpoint
    // sup over |t| <= w/2 of f'(m) t + max(f'', 0) t^2/2, or the concave form (taylor_increment)
    const Dint r(w / 2), D1(Jm.d.abs_upper()), M(J.dd.hi);
    Dint inc = D1 * r + Dint(std::max(J.dd.hi, 0.0)) * r * r * Dint(0.5);
    if (M.hi < 0) {
      const Dint t = D1 / (-M);
      if (t.hi <= r.lo) inc = D1 * D1 / (-(M * 2L));
    }
    const double ub = (Jm.v + inc).hi;
    if (ub < Ld_) return InDouble::pruned;
    if (J.d.positive() || J.d.negative()) {  // monotone: the maximum at one end
      Jet<Dint> Je;
      const __int128 ke = J.d.positive() ? k + 1 : k - 1;
      ++double_evals_;
      return dbl_.eval(ke, D, false, Je) && Je.v.hi < Ld_ ? InDouble::pruned : InDouble::arb;
    }
    if (J.dd.negative() && concave_below(k, D, Jm, J.dd.hi)) return InDouble::pruned;
    // Split in double only where the gap above the best value is the function's, not the
    // rounding's: the midpoint's own enclosure is narrow against the gap (near w = 0 the kernels'
    // cancellation blows double enclosures up at every depth, and splitting on them went 50 levels
    // deep over a whole box: (z - 1) sum z^-k, N = 80, never ended), and never more splits than
    // Arb's budget of evaluations, so the double pass cannot outgrow the Arb pass it prunes for.
    const double scale = std::max(std::abs(Ld_), 1e-300), gap = ub - Ld_;
    const bool far = std::isfinite(ub) && gap > 1e-6 * scale && Jm.v.hi - Jm.v.lo < 1e-3 * gap &&
                     J.d.contains_zero() && !J.dd.negative();
    if (!far || p.level + 1 >= max_level_ || double_splits_ >= budget_) return InDouble::arb;
    ++double_splits_;
    return InDouble::split;
  }

  /// f concave on the box pi [k - 1, k + 1]/D (sup f'' = M < 0): f <= f(x) + f'(x)^2/(-2M) for
  /// every x of the box, taken at a point x near the critical point found by Newton's steps on f'
  /// in double over grid points 2^20 times finer; true when that bound is below the best value.
  bool concave_below(__int128 k, __int128 D, Jet<Dint> Jx, double M) {
    constexpr int finer = 20;
    if (D >= (static_cast<__int128>(1) << 100)) return false;
    const __int128 Df = D << finer, lo = (k - 1) << finer, hi = (k + 1) << finer;
    __int128 kx = k << finer;
    const double per_radian = static_cast<double>(Df) / 3.141592653589793, reach = std::ldexp(2.0, finer);
    for (int it = 0; it < 4; ++it) {
      const double step = -Jx.d.mid() / Jx.dd.mid() * per_radian;
      if (!std::isfinite(step) || std::abs(step) < 0.5) break;
      const __int128 next = std::clamp<__int128>(kx + std::llround(std::clamp(step, -reach, reach)), lo, hi);
      Jet<Dint> Jn;
      ++double_evals_;
      if (next == kx || !dbl_.eval(next, Df, false, Jn)) break;
      kx = next, Jx = Jn;
    }
    if (Jx.v.lo > Ld_) raise(Ball(Jx.v.lo));
    const Dint d(Jx.d.abs_upper());
    return (Jx.v + d * d / Dint(-2 * M)).hi < Ld_;
  }

  void process(const Piece& p, std::vector<Piece>& stack) {
    if (use_double_) {
      const InDouble d = in_double(p);
      if (d == InDouble::pruned) {
        ++double_pruned_;
        if (p.level == 0) first_pruned_[static_cast<size_t>(p.i)] = 1;
        return;
      }
      if (d == InDouble::split) {
        stack.push_back({2 * p.i + 1, p.level + 1});
        stack.push_back({2 * p.i, p.level + 1});
        return;
      }
    }
    const long last = M_ << p.level;
    if (F_.frac_pole && p.i + 1 == last) return tail(p, stack);
    const bool at_zero = p.i == 0, at_pi = p.i + 1 == last && df_.at_pi.has_value();
    const Ball a = theta(p.i, p.level), b = theta(p.i + 1, p.level);
    const Ball X = flint::hull(a, b);
    const Jet<Ball> J = eval(X);
    const Ball w = upper(b - a);
    Ball ub;
    if (at_zero || at_pi) {
      // f'(0) = 0 (f is even) and f'(pi) = 0 for an integer delay (f is even about pi):
      // f <= f(end) + max(f'', 0) w^2/2 on the box, and f(end) is the maximum there when f'' <= 0
      const Ball M = upper(J.dd);
      if (!M.positive()) return;
      ub = upper(Ball(at_zero ? df_.at_zero : *df_.at_pi) + M * w * w / Ball(2L));
    } else {
      if (J.v.finite() && less(upper(J.v), L_)) return;  // the natural enclosure is enough: one evaluation
      const Ball m = flint::hull(a, b).mid();
      const Jet<Ball> Jm = eval(m);
      raise(lower(Jm.v));
      ub = upper(Jm.v + taylor_increment(Jm.d, upper(J.dd), upper(w / Ball(2L))));
    }
    if (J.v.finite()) ub = less(upper(J.v), ub) ? upper(J.v) : ub;
    if (less(ub, L_)) return;  // below the best proven value: not the maximum
    if (J.d.positive()) return end_value(p.i + 1, p.level);  // increasing: the maximum at the right end
    if (J.d.negative()) return end_value(p.i, p.level);      // decreasing: at the left end
    if (J.dd.negative() && !at_zero && !at_pi) return concave(X, J, p);
    // settled: within the tolerance of the best proven value (a flat or degenerate piece), or out
    // of depth or of budget; its upper bound stays in the enclosure
    if (less(ub, L_ + tol(L_)) || p.level >= max_level_ || evals_ > budget_) return unresolved(ub, X);
    stack.push_back({2 * p.i + 1, p.level + 1});
    stack.push_back({2 * p.i, p.level + 1});
  }

  /// The last piece [a, pi] when a pole of H at z = -1 meets a fractional delay and sends f to -inf
  /// there (long_delay_applies admits only that sign), by the smaller of two upper bounds:
  ///  - f = g - (T/2)(rho/2) sin(nu theta) tan(theta/2), g bounded (Terms::bounded): where
  ///    rho sin(nu theta) > 0 on the piece, tan(theta/2) >= tan(a/2) > 0 gives
  ///    f <= sup g - (T/4) inf(rho sin(nu theta)) tan(a/2), which falls like 1/(pi - a);
  ///  - with nu = m + tau (m = floor(nu), 0 < tau < 1) the pole's part (T/2) rho sin((nu + 1) theta)/sin(theta)
  ///    is (T/2) rho [cos(tau theta) K_{m+1}(theta) + cos((m + 1) theta) sin(tau theta)/sin(theta)],
  ///    K_{m+1} = sin((m + 1) theta)/sin(theta) finite; where (m + 1)(pi - a) < pi/2, cos((m + 1) theta) has
  ///    the sign of (-1)^(m+1) and sin(tau theta) > 0, so the second part has the sign of rho (-1)^(m+1),
  ///    negative on the -inf side (rho sin(nu pi) = rho (-1)^m sin(tau pi) > 0): f <= sup [f~ + (T/2) rho
  ///    cos(tau theta) K_{m+1}], f~ H~'s part (Terms::without_pole), finite at pi -- the bound that holds
  ///    when tau is so small (10^-30) that the first needs more halvings than the search has.
  /// Pruned when below the best proven value; else halved (the left half an ordinary piece, the right
  /// the tail again); out of depth or budget it keeps the smaller bound (+inf if neither holds).
  void tail(const Piece& p, std::vector<Piece>& stack) {
    const Ball a = theta(p.i, p.level), X = flint::hull(a, Ball::pi());
    Ball sh, ch, snu, cnu;
    jet::sin_cos(X * Ball(0.5), sh, ch);
    jet::sin_cos(F_.nu * X, snu, cnu);
    ++evals_;
    const Ball g = upper(objective_jet(F_, X, sh, ch, snu, cnu, Terms::bounded).v);
    const Ball weight = lower(F_.rho * snu);
    Ball ub = Ball::infinity(true);  // not shown: +inf, which an unresolved piece keeps in the enclosure
    if (g.finite() && weight.positive()) {
      Ball sa, ca;
      jet::sin_cos(a * Ball(0.5), sa, ca);
      const Ball t = lower(sa / ca);
      if (t.positive()) ub = upper(g - F_.half_T * Ball(0.5) * weight * t);
    }
    if (less(Ball(floor_nu_ + 1) * (F_.pi - a), F_.pi * Ball(0.5))) {
      const Ball tau = F_.nu - Ball(floor_nu_);
      Ball s_m, c_m, s_1, c_1, s_tau, c_tau;
      jet::sin_cos(Ball(floor_nu_ + 1) * X, s_m, c_m);
      jet::sin_cos(X, s_1, c_1);
      jet::sin_cos(tau * X, s_tau, c_tau);
      const Ball K = jet::kernel_K(jet::variable(X), floor_nu_ + 1, s_m, c_m, s_1, c_1).v;
      const Ball bound = upper(objective_jet(F_, X, sh, ch, snu, cnu, Terms::without_pole).v + F_.half_T * F_.rho * c_tau * K);
      if (bound.finite() && (!ub.finite() || less(bound, ub))) ub = bound;
    }
    if (ub.finite() && less(ub, L_)) return;
    if (p.level >= max_level_ || evals_ > budget_) {
      ++tail_unresolved_;
      return unresolved(ub, X);
    }
    stack.push_back({2 * p.i + 1, p.level + 1});
    stack.push_back({2 * p.i, p.level + 1});
  }

  /// f'' < 0 on X: at most one critical point, the maximum over X; interval Newton on f' encloses it.
  void concave(Ball X, Jet<Ball> J, const Piece& p) {
    bool proven = false;
    for (int it = 0; it < 80; ++it) {
      const Ball m = X.mid();
      const Jet<Ball> Jm = eval(m);
      const Ball N = m - Jm.d / J.dd;
      Ball Y;
      if (!flint::intersect(Y, X, N)) {  // no critical point: f is monotone on X, the maximum at an end
        end_value(p.i, p.level);
        end_value(p.i + 1, p.level);
        return;
      }
      if (arb_contains_interior(X.get(), N.get())) proven = true;
      const bool progress = Y.radius() < 0.5 * X.radius();
      X = Y;
      if (!progress && it > 0) break;
      J = eval(X);
      if (!J.dd.negative()) break;
    }
    // the value over the last X by the mean-value form, intersected with the natural enclosure
    const Ball m = X.mid();
    const Jet<Ball> Jm = eval(m), Jx = eval(X);
    Ball v = Jm.v + Jx.d * (X - m);
    Ball both;
    if (Jx.v.finite() && flint::intersect(both, v, Jx.v)) v = both;
    add_candidate(v, X);
    if (!proven) {  // the critical point was not shown to exist: the ends may hold the maximum
      end_value(p.i, p.level);
      end_value(p.i + 1, p.level);
    }
  }

  /// 10^-(digits + 3) relative to |L| (or to T when L is 0): below it a piece needs no refinement.
  Ball tol(const Ball& L) const {
    const Ball scale = upper(flint::abs(L));
    return upper((scale.is_zero() ? F_.half_T : scale) * tol_factor_);
  }

  const DelayForm& df_;
  Form<Ball> F_;
  long floor_nu_ = 0;  // m = floor(nu) (tail's second bound)
  DoubleGrid dbl_;
  bool use_double_;
  double Ld_ = -std::numeric_limits<double>::infinity();  // a double <= L_
  long double_evals_ = 0, double_pruned_ = 0, double_splits_ = 0;
  long M_;
  const std::vector<char>* settled_;
  std::vector<char> first_pruned_;
  int max_level_ = 56;
  long budget_ = 0;
  Ball tol_factor_;
  Ball L_, H_, H_other_ = Ball::infinity(false), best_hi_, best_at_;
  Where best_where_ = Where::zero;
  long evals_ = 0, unresolved_ = 0, tail_unresolved_ = 0;
};

}  // namespace

std::optional<std::array<Dint, 3>> delay_objective_double(const DelayForm& f, __int128 k, __int128 D, bool box) {
  const DoubleGrid grid(f);
  Jet<Dint> j;
  if (!grid.eval(k, D, box, j)) return std::nullopt;
  return std::array<Dint, 3>{j.v, j.d, j.dd};
}

std::array<Ball, 3> delay_objective_ball(const DelayForm& f, const Ball& theta) {
  const Jet<Ball> j = objective_jet(Form<Ball>(f), theta);
  return {j.v, j.d, j.dd};
}

// ---- the drivers ----------------------------------------------------------------------------
long grid_boxes(const rational& nu) {
  // four boxes per period 2 pi/nu of the kernels over [0, pi] (period / 8 wide), at least 64
  const integer up = (num(nu) + den(nu) - 1) / den(nu);
  return 4 * up.convert_to<long>() + 64;
}

Bound certified_long_delay(const BoundProblem& p, int digits, bool double_pruning, long budget) {
  std::string why;
  const std::optional<DelayForm> df = delay_form(p, &why);
  if (!df) {
    if (auto inf = fractional_divergence(p)) {  // a pole at z = -1 meeting a fractional delay: +inf
      inf->path = BoundPath::long_delay;
      return *inf;
    }
    throw NumericalError("the long-delay path does not decide this case: " + why);
  }
  Bound out;
  out.path = BoundPath::long_delay;
  if (df->constant) {  // H = 0: the objective is eta everywhere
    out.status = Status::exact;
    out.enclose(df->eta, df->eta);
    out.decimal = to_decimal(df->eta, digits);
    out.omega = "0";
    out.omega_enclosure = Enclosure<rational>{0, 0};
    out.where = "constant (every w attains it)";
    out.method = "exact: H = 0, the objective is eta";
    return out;
  }
  const long boxes = grid_boxes(df->nu);
  const double lognu = std::log10(to_real<double>(df->nu) + 1);
  // 128 bits (two limbs, no allocation in Arb) while they hold the digits asked plus those the
  // kernels' size ~nu costs; a retry doubles them when the enclosure came out wider
  long bits = std::max<long>(128, static_cast<long>(3.33 * (digits + lognu)) + 12);
  {
    // and those that A/B, E/B cost where |D|^2 = B(c) is smallest on [-1, 1] (its critical points
    // and the ends: (z + 1/3)^64 cancels 2^128 at c = -1) and at the double scan's best points:
    // doubled until f there holds the digits asked, before the search rather than after it
    const double pi = 3.14159265358979323846, nudge = pi / static_cast<double>(8 * boxes);
    std::vector<rational> cs{rational(-1), rational(1)};
    if (df->B.degree() >= 2)
      for (const auto& r : isolate_real_roots(df->B.derivative(), rational(-1), rational(1))) cs.push_back((r.lo + r.hi) / 2);
    rational cmin = cs.front();
    for (const rational& c : cs)
      if (abs(df->B(c)) < abs(df->B(cmin))) cmin = c;
    std::vector<double> probes{std::clamp(std::acos(std::clamp(to_real<double>(cmin), -1.0, 1.0)), nudge, pi - nudge)};
    for (const Peak& pk : double_peaks(*df, boxes, 8))
      if (pk.theta > 0 && pk.theta < pi) probes.push_back(pk.theta);
    // (relative to the largest |f| probed, so that a probe where f is near 0 asks nothing of it; at most 4096
    // bits: beyond, the search's own retries decide)
    for (; bits < 4096; bits *= 2) {
      flint::BallPrecision scope(bits);
      const Form<Ball> F(*df);
      bool finite = true;
      Ball scale(0L), widest(0L);
      for (const double th : probes) {
        const Ball v = objective_jet(F, Ball(th)).v;
        finite = finite && v.finite();
        if (!finite) break;
        if (less(scale, upper(flint::abs(v)))) scale = upper(flint::abs(v));
        if (less(widest, Ball(v.radius()))) widest = Ball(v.radius());
      }
      if (finite && !less(scale * Ball(pow10(-(digits + 3))), widest)) break;
    }
  }
  long double_evals = 0, arb_evals = 0;  // over the attempts
  std::vector<char> settled;          // the first boxes the last attempt pruned in double intervals,
  std::optional<rational> proven_lo;  // below this proven value of f: a retry skips them
  for (int attempt = 0;; ++attempt, bits *= 2) {
    flint::BallPrecision scope(bits);
    Maximiser mx(*df, boxes, digits, double_pruning, proven_lo ? &settled : nullptr, proven_lo);
    if (budget > 0) mx.set_budget(budget);
    const bool complete = mx.run();
    // with a budget (the exact path stands behind: bound.cpp) a search that ran out of it, or left b* unbounded
    // above, hands over at once rather than retrying at more bits
    if (budget > 0 && (!complete || !mx.hi().finite()))
      throw NumericalError("the long-delay path did not settle b* within its budget of " + std::to_string(budget) +
                           " evaluations (" + std::to_string(mx.unresolved()) + " pieces unresolved at " + std::to_string(bits) + " bits)");
    if (mx.lo().finite()) settled = mx.first_pruned(), proven_lo = mx.lo().bounds().lo;
    double_evals += mx.double_evaluations(), arb_evals += mx.evaluations();
    if (!mx.hi().finite()) {
      if (attempt < 2) continue;
      throw NumericalError("the long-delay path could not bound b* from above (" + std::to_string(mx.unresolved()) +
                           " pieces unresolved at " + std::to_string(bits) + " bits)");
    }
    const rational lo = mx.lo().bounds().lo, hi = mx.hi().bounds().hi;
    const bool narrow = lo == hi || common_decimal(lo, hi, digits).has_value() ||
                        hi - lo < std::max(abs(lo), abs(hi)) * pow10(-digits - 2);
    // more bits narrow what rounding widened, not a last piece at pi out of depth (nu = 1 + 10^-30)
    if (!narrow && attempt < 2 && !mx.tail_unresolved()) continue;
    // exact when the best value is an exact end (w = 0, or w = pi/T with an integer delay) and
    // every other piece's upper bound lies below it
    const rational best_end = df->at_pi ? std::max(df->at_zero, *df->at_pi) : df->at_zero;
    const bool exact = mx.others_below(best_end) && lo <= best_end && best_end <= hi;
    if (exact) {
      out.status = Status::exact;
      out.enclose(best_end, best_end);
      out.decimal = to_decimal(best_end, digits);
    } else {
      out.status = Status::certified;
      out.enclose(lo, std::max(lo, hi));
      out.decimal = enclosure_decimal(lo, std::max(lo, hi), digits);
    }
    const bool at_zero = exact ? best_end == df->at_zero : mx.best_where() == Maximiser::Where::zero;
    const bool at_pi = exact ? !at_zero : mx.best_where() == Maximiser::Where::pi;
    if (at_zero) {
      out.omega = "0";
      out.omega_enclosure = Enclosure<rational>{0, 0};
      out.where = "w = 0";
    } else {
      const Enclosure<rational> th = (at_pi ? Ball::pi() : mx.best_at()).bounds();
      out.omega_enclosure = Enclosure<rational>{th.lo / p.T, th.hi / p.T};
      out.omega = enclosure_decimal(out.omega_enclosure->lo, out.omega_enclosure->hi, std::min(digits, 17));
      out.where = at_pi ? "w = pi/T" : "interior";
    }
    const std::string pruning = double_evals > 0 ? std::to_string(mx.double_pruned()) + " pieces pruned in double intervals (" +
                                                       std::to_string(double_evals) + " evaluations), "
                                                 : std::string();
    out.method = "certified: long-delay branch-and-bound over w in double intervals with rounding bounds and Arb balls (nu = " +
                 to_decimal(df->nu, 12) + " samples, never expanded: " + std::to_string(boxes) + " boxes, " + pruning +
                 std::to_string(arb_evals) + " evaluations of f, f', f'' in Arb, interval Newton; " +
                 std::to_string(bits) + " bits)";
    // pieces left unresolved (settled within the tolerance, out of depth or of budget) keep their
    // upper bounds in H, so the enclosure and the status hold either way; a wide one says why
    if (!narrow) out.note += std::string(out.note.empty() ? "" : "; ") + "the enclosure is wider than " +
                             std::to_string(digits) + " digits at " + std::to_string(bits) + " bits" +
                             (complete ? std::string() : " (" + std::to_string(mx.unresolved()) + " pieces unresolved)");
    return out;
  }
}

}  // namespace hapstab::passivity::detail

namespace hapstab::passivity {

std::optional<FastLongDelay> fast_long_delay(const BoundProblem& p) {
  using namespace detail;
  const std::optional<DelayForm> df = delay_form(p, nullptr);
  if (!df) return std::nullopt;
  if (df->constant) return FastLongDelay{to_real<double>(df->eta), 0.0, 0.0};
  // |D|^2 = B(c) cancelling below 1e-9 of its largest coefficient on [-1, 1] (a resonance of radius above
  // ~1 - 3e-5, a pole of high order near the circle; the fast short path's rule, fast.cpp): the double scan
  // misses the peak (radius 1 - 1e-12 at n = 5000 gave 8.0 for b* = 1194815 at stop 87's review). Decided
  // exactly (Sturm on B - t): the certified path answers those.
  rational scale = 0;
  for (int k = 0; k <= df->B.degree(); ++k) scale = std::max(scale, rational(abs(df->B.coeff(k))));
  const QPoly low = df->B - QPoly(scale / 1000000000);
  if (low(rational(-1)) <= 0 || count_real_roots(low, rational(-1), rational(1)) > 0) return std::nullopt;
  const Peak best = double_peaks(*df, grid_boxes(df->nu), 1).front();
  // the rounding error of f at the maximiser, to first order: each Horner sum p(c) is off by
  // ~ deg eps sum|p_i c^i|, the argument nu theta by ~ eps nu theta (times f's derivative in it),
  // and the sums of the terms by eps times their sizes
  const Form<double> F(*df);
  const double th = best.theta, c = std::cos(th), eps = std::ldexp(1.0, -52);
  auto cond = [&](const std::vector<double>& q, double& value) {  // sum |q_i c^i| and q(c)
    double s = 0, v = 0, ci = 1;
    for (double x : q) s += std::abs(x) * ci, ci *= std::abs(c);
    for (size_t i = q.size(); i-- > 0;) v = v * c + q[i];
    value = v;
    return s * static_cast<double>(q.size());
  };
  double a, e, b;
  const double ca = cond(F.A, a), ce = cond(F.E, e), cb = cond(F.B, b);
  const double nu = to_real<double>(df->nu), S = th > 0 ? std::abs(std::sin(nu * th) / std::tan(th / 2)) : 2 * nu;
  const double half_T = to_real<double>(df->T) / 2, rho = std::abs(to_real<double>(df->rho));
  const double alpha = std::abs(a / b), gamma = std::abs(e / b);
  const double horner = half_T * ((ca + std::abs(a) * cb / std::abs(b)) + (ce + std::abs(e) * cb / std::abs(b)) * S) / std::abs(b);
  // a pole at z = -1 met by a fractional delay: its part rho sin(nu theta) tan(theta/2)/2, large near pi
  const double tan_half = df->integer_nu || rho == 0 ? 0 : std::tan(th / 2);
  const double sums = 4 * half_T * ((alpha + rho) + (gamma + rho) * S + rho * nu + rho * tan_half);
  // d f/d(nu theta) <= (T/2)(|alpha| + rho + (|gamma| + rho) cot(theta/2) + rho tan(theta/2)); nu theta is off by eps nu theta
  const double argument = th > 0 ? nu * th * half_T * (alpha + rho + (gamma + rho) / std::tan(th / 2) + rho * tan_half) : 0;
  const double err = eps * (horner + sums + argument);
  return FastLongDelay{best.value, best.theta / to_real<double>(p.T),
                       16 * err / std::max(std::abs(best.value), std::numeric_limits<double>::min())};
}

}  // namespace hapstab::passivity
