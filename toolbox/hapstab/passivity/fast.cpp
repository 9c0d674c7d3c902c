// The fast path of the passivity bound (45) (FastBound, bound.hpp): the c-form of the objective
// in double-double from double-double coefficients of N and D z^n (the same template as the exact
// objective, bound_detail.hpp), its critical points found in double by recursion on the
// derivative, polished by Newton in double-double. Status numeric; a case it cannot decide well
// (a pole on or very near the unit circle, a fractional delay) goes to the certified path.
#include <algorithm>
#include <cmath>
#include <limits>

#include "hapstab/numeric/double_double.hpp"
#include "hapstab/passivity/bound_detail.hpp"

namespace hapstab::passivity {

namespace {
/// Monomial coefficients of T_m and U_m (m <= 47), exact integers in double for m < 50.
const detail::ChebyshevTables<double>& cheb_tables() {
  static const detail::ChebyshevTables<double> t = detail::chebyshev_tables<double>(47);
  return t;
}
inline double horner_d(const std::vector<double>& c, double x) {
  double r = 0;
  for (size_t i = c.size(); i-- > 0;) r = r * x + c[i];
  return r;
}
std::vector<double> deriv(const std::vector<double>& c) {
  std::vector<double> r;
  for (size_t i = 1; i < c.size(); ++i) r.push_back(c[i] * static_cast<double>(i));
  return r;
}
/// Real roots of the polynomial c in [a, b] (double), by recursion on the derivative: between
/// consecutive critical points the polynomial is monotone, so one safeguarded bisection/Newton each.
void roots_in(const std::vector<double>& c, double a, double b, std::vector<double>& out) {
  std::vector<double> p = c;
  while (!p.empty() && p.back() == 0) p.pop_back();
  out.clear();
  if (p.size() <= 1) return;
  if (p.size() == 2) {
    double r = -p[0] / p[1];
    if (r >= a && r <= b) out.push_back(r);
    return;
  }
  std::vector<double> crit;
  roots_in(deriv(p), a, b, crit);
  std::vector<double> pts;
  pts.push_back(a);
  for (double x : crit) pts.push_back(x);
  pts.push_back(b);
  auto dp = deriv(p);
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    double x0 = pts[i], x1 = pts[i + 1];
    double f0 = horner_d(p, x0), f1 = horner_d(p, x1);
    if (f0 == 0) { if (out.empty() || out.back() != x0) out.push_back(x0); continue; }
    if (f1 == 0) continue;
    if ((f0 > 0) == (f1 > 0)) continue;
    double lo = x0, hi = x1, x = 0.5 * (x0 + x1);
    for (int it = 0; it < 100; ++it) {
      double fx = horner_d(p, x);
      if (fx == 0) break;
      if ((fx > 0) == (f0 > 0)) lo = x; else hi = x;
      double d = horner_d(dp, x);
      double xn = d != 0 ? x - fx / d : 0.5 * (lo + hi);
      if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
      if (std::abs(xn - x) <= 1e-17 * std::max(1.0, std::abs(x))) { x = xn; break; }
      x = xn;
      if (hi - lo <= 4e-16 * std::max(1.0, std::abs(x))) break;
    }
    out.push_back(x);
  }
}
}  // namespace
FastBound::FastBound(const BoundProblem& p) {
  if (with_integer_delay(p).frac_delay) { ok_ = false; return; }
  const int n = with_integer_delay(p).delay;
  T_ = to_real<double>(p.T);
  eta_ = to_real<double>(p.eta);
  // the c-form in double-double from double-double coefficients of N and D z^n
  const auto& nc = p.H.num().coeffs();
  const auto& dc0 = p.H.den().coeffs();
  std::vector<dd> N, Dp(static_cast<size_t>(n), dd{0, 0});
  for (auto& x : nc) N.push_back(to_dd(x));
  for (auto& x : dc0) Dp.push_back(to_dd(x));
  // H's denominator is monic after reduction; scale-free inputs keep dd products exact enough.
  // Chebyshev -> monomial with integer coefficients, exact in double below degree 48
  if (std::max(N.size(), Dp.size()) >= 48) { ok_ = false; return; }
  const detail::CForm<dd> cf = detail::c_form(
      N, Dp, cheb_tables(), [](const dd& x) { return x.hi == 0; }, [](double b) { return dd{b, 0}; });
  // A = (T/2)(R - (1+c) Q)
  std::vector<dd> A = cf.A;
  dd half_T = to_dd(p.T / 2);
  if (A.empty()) A.push_back(dd{0, 0});
  if (cf.B.empty()) { ok_ = false; return; }
  for (auto& x : A) x = x * half_T;
  for (auto& x : A) { Ahi_.push_back(x.hi); Alo_.push_back(x.lo); }
  for (auto& x : cf.B) { Bhi_.push_back(x.hi); Blo_.push_back(x.lo); }
}

std::optional<std::pair<double, double>> FastBound::evaluate() const {
  if (!ok_) return std::nullopt;
  // B = |D'|^2 > 0 on [-1, 1] unless a pole lies on the unit circle: check at its critical points
  double bscale = 0;
  for (double x : Bhi_) bscale = std::max(bscale, std::abs(x));
  std::vector<double> rb;
  roots_in(deriv(Bhi_), -1.0, 1.0, rb);
  rb.push_back(-1.0);
  rb.push_back(1.0);
  // B cancelling down to min B < 1e-9 max|B_k| on [-1, 1] (a narrow resonance, pole radius above ~1 - 3e-5;
  // or a pole of high order near the circle): the critical points of f are located in double from
  // coefficients that cancel down to min B, and the maximiser is lost (radius 1 - 1e-8 gave -2.8e-4 for a
  // true 66666.7; 1/(z - 1/2)^12's B = (5/4 - c)^12, ratio 1.6e-11, gave 0.7104 for a true 3.3631 at stop
  // 87's review, while the power 11, ratio 1.4e-10, was right: 1e-9 keeps a factor of 100 from it). Such
  // cases go to the certified path, which is exact about them (~0.1-0.3 ms).
  for (double x : rb)
    if (horner_dd(Bhi_, Blo_, x).hi <= 1e-9 * bscale) return std::nullopt;
  // P = A'B - AB' in double-double
  const size_t na = Ahi_.size(), nb = Bhi_.size();
  std::vector<dd> Pd(na + nb, dd{0, 0});
  // (k * hi rounds in double: scale by k in double-double, or P keeps only double accuracy and its
  // root -- the maximiser -- moves by ~1e-16 / P': 5e-11 at radius 0.99999 with a 2-sample delay)
  for (size_t i = 1; i < na; ++i)
    for (size_t j = 0; j < nb; ++j)
      Pd[i - 1 + j] = Pd[i - 1 + j] + dd{Ahi_[i], Alo_[i]} * dd{static_cast<double>(i), 0} * dd{Bhi_[j], Blo_[j]};
  for (size_t i = 0; i < na; ++i)
    for (size_t j = 1; j < nb; ++j)
      Pd[i + j - 1] = Pd[i + j - 1] - dd{Ahi_[i], Alo_[i]} * dd{static_cast<double>(j), 0} * dd{Bhi_[j], Blo_[j]};
  std::vector<double> Ph, Pl;
  for (auto& x : Pd) { Ph.push_back(x.hi); Pl.push_back(x.lo); }
  std::vector<double> roots;
  roots_in(Ph, -1.0, 1.0, roots);
  // Newton on P with P and P' both in double-double. A root located in double from P's cancelling
  // coefficients must converge here, else the case goes to the certified path; the minima of B (the
  // resonance centres, rb) seed extra starts, so a narrow peak is never missed by the double scan.
  std::vector<double> dPh, dPl;
  for (size_t k = 1; k < Ph.size(); ++k) {
    dd c = dd{Ph[k], Pl[k]} * dd{static_cast<double>(k), 0};
    dPh.push_back(c.hi);
    dPl.push_back(c.lo);
  }
  auto polish = [&](double& x) {
    for (int it = 0; it < 12; ++it) {
      dd d = horner_dd(dPh, dPl, x);
      if (d.hi == 0) return false;
      const double step = (horner_dd(Ph, Pl, x) / d).hi;
      if (!std::isfinite(step) || x - step < -1 || x - step > 1) return false;
      x -= step;
      if (std::abs(step) <= 2e-16 * std::max(1.0, std::abs(x))) return true;
    }
    return false;
  };
  std::vector<double> crit;
  for (double x : roots) {
    if (!polish(x)) return std::nullopt;
    crit.push_back(x);
  }
  for (double x : rb)
    if (x > -1 && x < 1 && polish(x)) crit.push_back(x);
  crit.push_back(1.0);
  crit.push_back(-1.0);
  double best = -std::numeric_limits<double>::infinity(), bc = 1;
  for (double x : crit) {
    dd v = horner_dd(Ahi_, Alo_, x) / horner_dd(Bhi_, Blo_, x);
    double vv = (v + dd{eta_, 0}).hi;
    if (vv > best) { best = vv; bc = x; }
  }
  return std::make_pair(best, std::acos(std::clamp(bc, -1.0, 1.0)) / T_);
}

}  // namespace hapstab::passivity
