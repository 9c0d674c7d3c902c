#include "hapstab/contact/wedge.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <deque>
#include <memory>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/poly/ball_range.hpp"
#include "hapstab/poly/sturm.hpp"
#include "hapstab/poly/unit_circle.hpp"

namespace hapstab::contact {

namespace {

using Poly = QPoly;

// p(t) even (no odd powers) -> q(u) with p(t) = q(t^2). Throws if p is not even.
Poly even_to_u(const Poly& p) {
  std::vector<rational> c;
  for (int i = 0; i <= p.degree(); ++i) {
    if (i % 2 == 1) {
      if (p.coeff(i) != 0) throw NumericalError("wedge: a branch is not even in t = tan(theta/2)");
    } else {
      c.push_back(p.coeff(i));
    }
  }
  return Poly(std::move(c));
}

RatFun rf_even_to_u(const RatFun& f) { return RatFun(even_to_u(f.num()), even_to_u(f.den())); }

// Distinct roots of p in [0, inf), sorted (p nonzero, degree >= 0).
std::vector<RootInterval> nonneg_roots(const Poly& p) {
  if (p.degree() <= 0) return {};
  return isolate_real_roots(p, rational(0), cauchy_bound(p));
}

// f has no pole in [0, inf] (den > 0 there: den is monic, so no root on [0, inf) suffices;
// at infinity the limit is finite iff deg num <= deg den).
void require_no_pole(const RatFun& f) {
  if (!nonneg_roots(f.den()).empty() || f.num().degree() > f.den().degree())
    throw InputError("wedge: a branch has a pole on the unit circle (H has a pole with |z| = 1)");
}

// The sign of lim_{u->inf} f(u) (den monic).
int sign_at_infinity(const RatFun& f) {
  if (f.num().is_zero() || f.num().degree() < f.den().degree()) return 0;
  return sgn(f.num().leading());
}
rational value_at_infinity(const RatFun& f) {
  if (f.num().is_zero() || f.num().degree() < f.den().degree()) return 0;
  return f.num().leading() / f.den().leading();
}

// Enclosure of max_i f_i over [lo, hi]: exact at a point, else ball Horner at prec bits
Enclosure<rational> eval_max(const std::vector<RatFun>& fs, const std::vector<BallRationalFunction>& balls,
                             const rational& lo, const rational& hi, long prec) {
  Enclosure<rational> r{rational(0), rational(0)};
  for (size_t i = 0; i < fs.size(); ++i) {
    Enclosure<rational> v{rational(0), rational(0)};
    if (lo == hi) v.lo = v.hi = fs[i](lo);
    else v = balls[i].range(lo, hi, prec);
    if (i == 0 || v.lo > r.lo) r.lo = v.lo;
    if (i == 0 || v.hi > r.hi) r.hi = v.hi;
  }
  return r;
}

// ---- certified fast path: outward-rounded double intervals, branch and bound -------------
// Every operation is done in round-to-nearest and then widened by one ulp on each side, so the
// result encloses the exact one (a rational coefficient is rounded correctly, error <= 1/2 ulp).
struct DI {
  double lo, hi;
};
inline DI widen(double lo, double hi) { return {std::nextafter(lo, -INFINITY), std::nextafter(hi, INFINITY)}; }
inline DI di_add(DI a, DI b) { return widen(a.lo + b.lo, a.hi + b.hi); }
inline DI di_mul(DI a, DI b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return widen(std::min(std::min(p1, p2), std::min(p3, p4)), std::max(std::max(p1, p2), std::max(p3, p4)));
}
inline bool di_div(DI a, DI b, DI& r) {  // false when b contains 0
  if (!(b.lo > 0 || b.hi < 0)) return false;
  const double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo, p4 = a.hi / b.hi;
  r = widen(std::min(std::min(p1, p2), std::min(p3, p4)), std::max(std::max(p1, p2), std::max(p3, p4)));
  return std::isfinite(r.lo) && std::isfinite(r.hi);
}
std::vector<DI> di_coeffs(const Poly& p, bool reversed, int n) {
  std::vector<DI> c(static_cast<size_t>(n) + 1, DI{0, 0});
  for (int i = 0; i <= p.degree(); ++i) {
    const double d = to_real<double>(p.coeff(i));
    c[reversed ? n - i : i] = widen(d, d);
  }
  return c;
}
DI di_horner(const std::vector<DI>& c, DI x) {
  DI r = c.back();
  for (size_t i = c.size() - 1; i-- > 0;) r = di_add(di_mul(r, x), c[i]);
  return r;
}
struct FastFun {
  std::vector<DI> num, den, rnum, rden;
  int shift = 0;  // deg den - deg num (>= 0 for a bounded function)
  explicit FastFun(const RatFun& f) : FastFun(f.num(), f.den()) {}
  FastFun(const Poly& n, const Poly& d) {
    const int dn = std::max(n.degree(), 0), dd = d.degree();
    num = di_coeffs(n, false, dn);
    den = di_coeffs(d, false, dd);
    rnum = di_coeffs(n, true, dn);
    rden = di_coeffs(d, true, dd);
    shift = dd - dn;
  }
  // f on u in x (domain 0) or on u = 1/v, v in x (domain 1): f = v^shift rnum(v)/rden(v)
  bool eval(int domain, DI x, DI& r) const {
    if (domain == 0) return di_div(di_horner(num, x), di_horner(den, x), r);
    if (!di_div(di_horner(rnum, x), di_horner(rden, x), r)) return false;
    for (int k = 0; k < shift; ++k) r = di_mul(r, x);
    return true;
  }
};

// nullopt: undecided within the box budget (then Sturm decides).
std::optional<bool> fast_boxes(const std::vector<FastFun>& ff);
std::optional<bool> fast_max_positive(const std::vector<RatFun>& fs) {
  for (const auto& f : fs)
    if (f.num().is_zero() || f.num().degree() > f.den().degree()) return std::nullopt;
  std::vector<FastFun> ff;
  for (const auto& f : fs) ff.emplace_back(f);
  return fast_boxes(ff);
}
std::optional<bool> fast_boxes(const std::vector<FastFun>& ff) {
  struct Box {
    int domain;
    double lo, hi;
  };
  // breadth first (a queue), so a box where every branch is negative is met at a coarse level
  std::deque<Box> stack{{0, 0.0, 1.0}, {1, 0.0, 1.0}};
  int budget = 3000;
  while (!stack.empty()) {
    const Box b = stack.front();
    stack.pop_front();
    bool positive = false, all_negative = true, bounded = true;
    for (const auto& f : ff) {
      DI r;
      if (!f.eval(b.domain, DI{b.lo, b.hi}, r)) {
        bounded = false;
        all_negative = false;
        continue;
      }
      if (r.lo > 0) {
        positive = true;
        break;
      }
      if (!(r.hi < 0)) all_negative = false;
    }
    if (positive) continue;
    if (bounded && all_negative) return false;  // every branch < 0 on the whole box
    if (--budget <= 0 || b.hi - b.lo < 1e-10) return std::nullopt;
    const double m = 0.5 * (b.lo + b.hi);
    stack.push_back({b.domain, b.lo, m});
    stack.push_back({b.domain, m, b.hi});
  }
  return true;
}

}  // namespace

WedgeBranches wedge_branches(const TransferFunction& H) {
  if (!H.is_discrete()) throw InputError("wedge: H must be a discrete transfer function H(z) (give --T)");
  ReIm ri = on_unit_circle(H.H);
  const Poly t = Poly::monomial(1);
  RatFun J(ri.im.num(), ri.im.den() * t);  // Im H / tan(theta/2): exact (Im H is odd in t)
  return {rf_even_to_u(ri.re), rf_even_to_u(J)};
}

bool wedge_holds(const TransferFunction& H) {
  if (!H.is_discrete() || !H.is_proper()) throw InputError("wedge_holds: H must be a causal H(z)");
  // f+- + 1 = (Re(N~ conj D~) +- Im(N~ conj D~)/t + |D~|^2) / |D~|^2: one common denominator,
  // no gcd needed; Im(N~ conj D~) is odd in t, so the division by t is exact.
  const int n = std::max(H.num().degree(), H.den().degree());
  const ComplexPolynomial Nt = unit_circle_polynomial(H.num(), n), Dt = unit_circle_polynomial(H.den(), n);
  const ComplexPolynomial ncd = Nt * conj(Dt);
  const Poly d = norm(Dt);
  if (ncd.im.coeff(0) != 0) throw NumericalError("wedge_holds: Im H is not odd in t");
  Poly jn = ncd.im.is_zero() ? Poly() : Poly(std::vector<rational>(ncd.im.coeffs().begin() + 1, ncd.im.coeffs().end()));
  const Poly pu = even_to_u(ncd.re + jn + d), mu = even_to_u(ncd.re - jn + d), du = even_to_u(d);
  if (pu.degree() <= du.degree() && mu.degree() <= du.degree() && !pu.is_zero() && !mu.is_zero()) {
    if (auto v = fast_boxes({FastFun(pu, du), FastFun(mu, du)})) return *v;
  }
  return max_positive({RatFun(pu, du), RatFun(mu, du)}, true);
}

double theta_of_u(const rational& u) { return 2.0 * std::atan(std::sqrt(static_cast<double>(mpfloat<30>(u)))); }

bool max_positive(const std::vector<RatFun>& fs, bool strict, bool fast) {
  if (fs.empty()) throw InputError("max_positive: no functions");
  // certified fast path: positive on every box (the denominators bounded away from 0 there
  // too), or every branch negative on some box; near-touching cases fall through to Sturm
  if (fast)
    if (auto v = fast_max_positive(fs)) return *v;
  for (const auto& f : fs) require_no_pole(f);
  auto fails = [&](const std::vector<int>& s) {
    for (int x : s)
      if (strict ? x > 0 : x >= 0) return false;
    return true;
  };
  // u = infinity
  {
    std::vector<int> s;
    for (const auto& f : fs) s.push_back(sign_at_infinity(f));
    if (fails(s)) return false;
  }
  Poly Q(rational(1));
  for (const auto& f : fs)
    if (!f.num().is_zero()) Q = Q * f.num();
  auto signs_at = [&](const rational& u) {
    std::vector<int> s;
    for (const auto& f : fs) s.push_back(sgn(f.num()(u)));
    return s;
  };
  std::vector<RootInterval> roots = nonneg_roots(Q);
  // points strictly between roots (and before the first, after the last)
  std::vector<rational> samples;
  // u = 0 unless it is itself a root: its sign is the sign on [0, first root) (an isolating
  // interval may start at 0 without 0 being a root)
  if (roots.empty() || !(roots.front().is_exact() && roots.front().lo == 0)) samples.push_back(rational(0));
  for (size_t i = 0; i + 1 < roots.size(); ++i) samples.push_back((roots[i].hi + roots[i + 1].lo) / 2);
  samples.push_back(roots.empty() ? rational(1) : roots.back().hi + 1);
  for (const auto& u : samples)
    if (fails(signs_at(u))) return false;
  // at each root: the branches vanishing there give 0, the others keep their sign on the interval
  for (const auto& r : roots) {
    if (r.is_exact()) {
      if (fails(signs_at(r.lo))) return false;
      continue;
    }
    const rational mid = (r.lo + r.hi) / 2;
    std::vector<int> s;
    for (const auto& f : fs) {
      const Poly& p = f.num();
      if (p.is_zero()) {
        s.push_back(0);
        continue;
      }
      const bool vanishes = p.degree() > 0 && (p(r.lo) == 0 || count_real_roots(p, r.lo, r.hi) > 0);
      s.push_back(vanishes ? 0 : sgn(p(mid)));
    }
    if (fails(s)) return false;
  }
  return true;
}

MinOfMax min_of_max(const std::vector<RatFun>& fs, int digits) {
  if (fs.empty()) throw InputError("min_of_max: no functions");
  for (const auto& f : fs) require_no_pole(f);
  struct Cand {
    RootInterval iv;
    std::shared_ptr<const RootRefiner> p;  // refines the root iv isolates (null for exact points)
    Enclosure<rational> v;
  };
  std::vector<Cand> cands;
  cands.push_back({{rational(0), rational(0)}, nullptr, {}});
  auto add_roots = [&](const Poly& p) {
    if (p.is_zero() || p.degree() <= 0) return;
    auto ref = std::make_shared<const RootRefiner>(p);  // one square-free part per polynomial
    for (const auto& r : ref->isolate(rational(0), cauchy_bound(p))) cands.push_back({r, ref, {}});
  };
  for (const auto& f : fs) add_roots(f.derivative().num());
  for (size_t i = 0; i < fs.size(); ++i)
    for (size_t j = i + 1; j < fs.size(); ++j) add_roots((fs[i] - fs[j]).num());
  // u = infinity (theta = pi): exact limits
  rational inf_val = value_at_infinity(fs[0]);
  for (const auto& f : fs) inf_val = std::max(inf_val, value_at_infinity(f));

  // balls at the precision a round needs: its width 10^-(digits+8) per round, plus 64 bits
  std::vector<BallRationalFunction> balls;
  long prec = 0;
  // When a denominator's ball over the interval contains 0 (a small |D|^2 near a pole close to
  // the unit circle), the root is refined 2^32 times further and the balls get 32 more bits:
  // D has no root on [0, inf], so this ends.
  auto refine = [&](Cand& c, rational w, long bits) {
    for (int tries = 0;; ++tries) {
      if (bits > prec) {
        prec = bits;
        balls.clear();
        for (const auto& f : fs) balls.emplace_back(f, prec);
      }
      if (!c.iv.is_exact()) c.iv = c.p->refine(c.iv, w * std::max(rational(1), c.iv.hi));
      try {
        c.v = eval_max(fs, balls, c.iv.lo, c.iv.hi, prec);
        return;
      } catch (const NumericalError&) {
        if (c.iv.is_exact() || tries == 16) throw;
      }
      w /= rational(integer(1) << 32);
      bits += 32;
    }
  };
  // A coarse pass (roots to ~1e-6, a cheap enclosure of max_i f_i there) drops the candidates
  // whose lower bound is above some candidate's upper bound (or the value at infinity): they
  // cannot hold the minimum, and refining them to `digits` would be wasted. The minimum's
  // enclosure is unchanged: a dropped lower bound is above the final upper bound.
  {
    const rational coarse(1, 1000000);
    rational g = inf_val;
    for (auto& c : cands) {
      refine(c, coarse, 128);
      g = std::min(g, c.v.hi);
    }
    cands.erase(std::remove_if(cands.begin(), cands.end(), [&](const Cand& c) { return c.v.lo > g; }), cands.end());
  }
  rational width = rational(1) / bmp::pow(integer(10), static_cast<unsigned>(digits + 8));
  MinOfMax best;
  for (int round = 0; round < 6; ++round) {
    const long bits = 64 + static_cast<long>(3.33 * (digits + 8) * (round + 1));
    for (auto& c : cands) refine(c, width, bits);
    Enclosure<rational> g{inf_val, inf_val};
    best.at_infinity = true;
    best.u = {rational(0), rational(0)};
    for (const auto& c : cands) {
      if (c.v.hi < g.hi) {
        best.u = {c.iv.lo, c.iv.hi};
        best.at_infinity = false;
      }
      g.lo = std::min(g.lo, c.v.lo);
      g.hi = std::min(g.hi, c.v.hi);
    }
    best.value = g;
    best.decided = g.lo == g.hi || common_decimal(g.lo, g.hi, digits).has_value();
    if (best.decided) break;
    width /= bmp::pow(integer(10), static_cast<unsigned>(digits + 8));
  }
  return best;
}

Assumptions check_assumptions(const TransferFunction& H, const rational& k) {
  Assumptions a;
  const Poly& N = H.num();
  const Poly& D = H.den();
  a.pole_on_unit_circle = unit_circle_roots(D) > 0;  // poly/stability.hpp
  a.h_stable = schur_stable(D);
  a.closed_loop_stable = !(D + N * k).is_zero() && schur_stable(D + N * k);
  const rational d1 = D(rational(1));
  if (d1 != 0) {
    a.h1 = N(rational(1)) / d1;
    a.dc_gain_nonnegative = *a.h1 >= 0;
  }
  if (!H.is_proper()) a.violated.push_back("H is not causal (deg num > deg den)");
  if (!a.h_stable)
    a.violated.push_back(a.pole_on_unit_circle ? "H stable (H has a pole on the unit circle)"
                                               : "H stable (H has a pole outside the unit circle)");
  if (!a.closed_loop_stable) a.violated.push_back("(1+H)^-1 stable");
  if (!a.dc_gain_nonnegative)
    a.violated.push_back(a.h1 ? "H(1) >= 0 (H(1) = " + to_decimal(*a.h1, 17) + ")" : "H(1) >= 0 (H(1) is infinite)");
  return a;
}

namespace {

CriterionReport run_criterion(const std::string& name, const std::vector<RatFun>& sides, int digits) {
  CriterionReport r;
  r.name = name;
  std::vector<RatFun> plus1;
  for (const auto& f : sides) plus1.push_back(f + RatFun(1));
  const bool holds = max_positive(plus1, true);
  r.verdict = Verdict::of(holds, Status::exact,
                          std::string("left side + 1 ") + (holds ? "> 0" : "<= 0 somewhere") +
                              " on [0, pi]: exact real-root isolation of the numerators in u = tan^2(theta/2)");
  MinOfMax mm = min_of_max(plus1, digits);
  const rational mid = (mm.value.lo + mm.value.hi) / 2;
  if (mm.value.lo == mm.value.hi)
    r.margin = Certified<rational>::exact_value(mm.value.lo, "exact value at an end point");
  else
    r.margin = Certified<rational>::certified_value(mid, mm.value, "exact root isolation + Arb ball enclosure");
  if (!mm.decided) r.margin.note = "enclosure too wide to decide every requested digit";
  r.theta_at_min = mm.at_infinity ? M_PI : theta_of_u((mm.u.lo + mm.u.hi) / 2);
  r.min_at_pi = mm.at_infinity;
  if (!mm.at_infinity) r.u_at_min = mm.u;
  r.gain_infinite = max_positive(sides, false);
  if (!r.gain_infinite) {
    // g = margin - 1 < 0 (exact); k* = -1/g
    const rational glo = mm.value.lo - 1, ghi = mm.value.hi - 1;
    if (ghi < 0) {
      Enclosure<rational> k{rational(-1) / glo, rational(-1) / ghi};
      const rational km = rational(-1) / (mid - 1);
      if (k.lo == k.hi)
        r.max_gain = Certified<rational>::exact_value(k.lo, "-1/min_theta(left side)");
      else
        r.max_gain = Certified<rational>::certified_value(km, k, "-1/min_theta(left side), certified");
    } else {
      r.max_gain = Certified<rational>::numeric_value(rational(-1) / (mid - 1), "-1/min: enclosure touches 0");
      r.max_gain.note = "min of the left side is negative (exact) but within the enclosure width of 0";
    }
  }
  return r;
}

}  // namespace

ContactAnalysis analyze_contact(const TransferFunction& H, int digits) {
  if (digits < 1 || digits > 60) throw InputError("--digits must be in [1, 60], got " + std::to_string(digits));
  ContactAnalysis a;
  a.H = H;
  if (!H.is_discrete()) throw InputError("wedge: H must be a discrete transfer function H(z) (give --T)");
  if (!H.is_proper()) throw InputError("wedge: H(z) = " + H.to_string() + " is not causal (deg num > deg den)");
  a.assumptions = check_assumptions(H);
  a.wedge.name = "wedge (25)";
  a.tsypkin.name = "Tsypkin (21)";
  // Each criterion is evaluated when its branches are bounded on all of [0, pi]: always when H
  // has no pole on the unit circle; also e.g. for a simple pole at z = -1 (Tustin), where
  // Re H and Im H / tan(theta/2) stay finite -- the verdict then still says the paper's
  // assumption "H stable" is violated.
  WedgeBranches b = wedge_branches(H);
  auto bounded = [](const std::vector<RatFun>& fs) {
    try {
      for (const auto& f : fs) require_no_pole(f);
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  std::vector<RatFun> wb{b.re + b.im_over_t, b.re - b.im_over_t}, tb{b.re};
  if (bounded(wb)) a.wedge = run_criterion("wedge (25)", wb, digits);
  if (bounded(tb)) a.tsypkin = run_criterion("Tsypkin (21)", tb, digits);
  return a;
}

namespace {
std::complex<double> eval_h(const TransferFunction& H, double theta) {
  const std::complex<double> z = std::polar(1.0, theta);
  return H.num()(z) / H.den()(z);
}
}  // namespace

double wedge_margin_at(const TransferFunction& H, double theta) {
  const auto h = eval_h(H, theta);
  const double m = std::sin(theta) / (1 - std::cos(theta));
  return std::max(h.real() + m * h.imag(), h.real() - m * h.imag()) + 1;
}

GridMin grid_margin(const TransferFunction& H, int n, bool wedge) {
  if (n < 2) throw InputError("grid_margin: need at least 2 points");
  // coefficients rounded to double once (the grid is a double-precision method)
  const Polynomial<double> N = H.num().cast<double>(), D = H.den().cast<double>();
  GridMin g{INFINITY, 0};
  for (int i = wedge ? 1 : 0; i < n; ++i) {  // theta = 0 is a 0*inf limit for the wedge: skipped
    const double th = M_PI * i / (n - 1);
    const std::complex<double> z = std::polar(1.0, th), h = N(z) / D(z);
    double v = h.real() + 1;
    if (wedge) {
      const double m = std::sin(th) / (1 - std::cos(th));
      v = std::max(h.real() + m * h.imag(), h.real() - m * h.imag()) + 1;
    }
    if (v < g.value) g = {v, th};
  }
  return g;
}

}  // namespace hapstab::contact
