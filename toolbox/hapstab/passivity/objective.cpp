// The objective of (45) in c = cos(wT), exact (see bound.hpp for why the c-form never cancels),
// and the objective evaluated on the unit circle itself (grid method, objective_at).
#include <cmath>

#include "hapstab/passivity/bound_detail.hpp"

namespace hapstab::passivity {


namespace {
// p scaled to integer coefficients: p = ints / scale, scale > 0 the lcm of the denominators
std::vector<integer> integer_coeffs(const std::vector<rational>& p, integer& scale) {
  scale = 1;
  for (const auto& c : p) scale = bmp::lcm(scale, den(c));
  std::vector<integer> out;
  for (const auto& c : p) out.push_back(num(c) * (scale / den(c)));
  return out;
}
}  // namespace

// ---------------------------------------------------------------------------------------------
// the exact objective in c = cos(wT)
Objective objective(const QRatFun& H, const rational& T, int delay) {
  // in integers: N = alpha n, D = beta d (shifted by z^n), so a, cs carry alpha beta and e beta^2
  integer alpha, beta;
  const std::vector<integer> n = integer_coeffs(H.num().coeffs(), alpha);
  std::vector<integer> d = integer_coeffs(H.den().coeffs(), beta);
  d.insert(d.begin(), static_cast<size_t>(delay), integer(0));  // D' = D z^n
  const int M = std::max(static_cast<int>(n.size()), static_cast<int>(d.size()));
  const detail::CForm<integer> cf = detail::c_form(
      n, d, detail::chebyshev_tables<integer>(M), [](const integer& x) { return x == 0; },
      [](const integer& x) { return x; });
  auto poly = [](const std::vector<integer>& c, const rational& scale) {
    std::vector<rational> r;
    for (const auto& x : c) r.emplace_back(rational(x) * scale);
    return QPoly(std::move(r));
  };
  const rational ab = 1 / rational(alpha * beta), bb = 1 / rational(beta * beta);
  Objective o;
  o.R = poly(cf.R, ab);
  o.Q = poly(cf.Q, ab);
  o.B = poly(cf.B, bb);
  // f = (T/2)(R - (1 + c) Q) / B = (T/2)(beta/alpha)(R' - (1 + c) Q') / B' in the integer pieces
  o.f = QRatFun(poly(cf.A, T / 2 * rational(beta) / rational(alpha)), poly(cf.B, rational(1)));
  return o;
}

namespace detail {

// The objective at theta = wT > 0 evaluated on the unit circle itself, in the scalar R:
//   Re{T W/(1 - z)} = (T/2) (Re W - cot(theta/2) Im W),  W = H(z) z^-n e^{-j theta t_d/T},
// since 1/(1 - e^{j theta}) = 1/2 + (j/2) cot(theta/2). Horner on |z| = 1 keeps the relative
// accuracy of R whatever the degree; the c-form A(c)/B(c) does not: its monomial coefficients
// grow like 2^degree, and in double it returned 0.34 for z^-50 (b* = 0.0505) and 1e171 for
// z^-500. At theta = 0 the limit is the exact c-form value at c = 1.
template <class R>
CircleObjective<R>::CircleObjective(const BoundProblem& p)
    : T(to_real<R>(p.T)), eta(to_real<R>(p.eta)), lag(R(p.delay)),
      frac(p.frac_delay ? to_real<R>(*p.frac_delay / p.T) : R(0)), has_frac(p.frac_delay.has_value()) {
  for (const auto& c : p.H.num().coeffs()) num.push_back(to_real<R>(c));
  for (const auto& c : p.H.den().coeffs()) den.push_back(to_real<R>(c));
}

template <class R>
R CircleObjective<R>::operator()(const R& th) const {
  const R zr = cos(th), zi = sin(th);
  auto horner = [&](const std::vector<R>& poly, R& re, R& im) {
    re = 0, im = 0;
    for (size_t i = poly.size(); i-- > 0;) {
      const R nr = re * zr - im * zi + poly[i];
      im = re * zi + im * zr;
      re = nr;
    }
  };
  R nr, ni, dr, di;
  horner(num, nr, ni);
  horner(den, dr, di);
  const R d2 = dr * dr + di * di;
  const R hr = (nr * dr + ni * di) / d2, hi = (ni * dr - nr * di) / d2;
  R ph = th * lag;
  if (has_frac) ph += th * frac;
  const R cr = cos(ph), ci = -sin(ph);
  const R wr = hr * cr - hi * ci, wi = hr * ci + hi * cr;
  return T / 2 * (wr - wi * cos(th / 2) / sin(th / 2)) + eta;
}
template struct CircleObjective<double>;
template struct CircleObjective<mp50>;

// The limit at theta = 0, exactly: with the c-form pieces of H without delay and nu = n + t_d/T,
// f(0) = (T/2)(A(1) + 2 nu E(1))/B(1) + eta, A = R - (1 + c) Q, E = R + (1 - c) Q (long_delay.cpp);
// nothing of degree n is formed.
double objective_at_zero(const BoundProblem& p) {
  const Objective o = objective(p.H, p.T, 0);
  const rational one(1);
  const rational nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  const rational R1 = o.R(one), A1 = R1 - 2 * o.Q(one);
  return to_real<double>(p.T / 2 * (A1 + 2 * nu * R1) / o.B(one) + p.eta);
}

}  // namespace detail

double objective_at(const BoundProblem& p, double omega) {
  if (omega == 0) return detail::objective_at_zero(p);
  return static_cast<double>(detail::objective_on_circle<mp50>(p, mp50(omega) * to_real<mp50>(p.T)));
}

}  // namespace hapstab::passivity
