// b* = +inf from a simple pole of H on the unit circle inside the band, 0 < wT < pi (paper 001,
// (45)/(54)), decided locally at any delay: nothing is expanded, so it answers where the exact
// path's degree is beyond its limit and the long-delay path does not take such a pole.
//
// Near z0 = e^{j theta0}, a simple pole of H: H = R/(z - z0) + O(1), R = N(z0)/D'(z0), and
// e^{j theta} - z0 = j z0 (theta - theta0) + O((theta - theta0)^2), so the objective is
//   f(theta) = Re{T H e^{-j nu theta}/(1 - e^{j theta})} = Im(c)/(theta - theta0) + O(1),
//   c = T R e^{-j nu theta0}/((1 - z0) z0)                         (Re(k/(j d)) = Im(k)/d).
// Im(c) != 0 sends f to +inf on one side of theta0, inside (0, pi): b* = +inf. Im(c) = 0 (H =
// (z - 1)/(z^2 + 1) at an even delay) leaves the case to the other paths, which refuse it by name.
//
// z0 exactly: H's poles on |z| = 1 are the roots of gcd(D, reversed D) (H is stable: no reciprocal
// pairs); without z = +-1 that factor C is palindromic of degree 2m, z^-m C(z) = q(cos theta),
// q = a_m + 2 sum_k a_{m+k} T_k (z^k + z^-k = 2 T_k(cos theta)), and cos theta0 is a root of q in
// (-1, 1), isolated by Sturm sequences and refined to 2^-96. Every ball below holds the whole
// isolating interval, so what it shows holds at the root.
#if HAPSTAB_FLINT3
#include <flint/acb.h>
#else
#include <acb.h>
#endif

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/flint.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/poly/sturm.hpp"

namespace hapstab::passivity::detail {

namespace {

/// A complex ball, freed on scope exit.
struct Acb {
  acb_t v;
  Acb() { acb_init(v); }
  ~Acb() { acb_clear(v); }
  Acb(const Acb&) = delete;
  Acb& operator=(const Acb&) = delete;
};

/// p(z) for a complex ball z, by Horner's rule.
void evaluate(acb_t out, const QPoly& p, const acb_t z, long prec) {
  flint::Ball a;
  acb_zero(out);
  for (int k = p.degree(); k >= 0; --k) {
    acb_mul(out, out, z, prec);
    flint::set(a.get(), p.coeff(k), prec);
    acb_add_arb(out, out, a.get(), prec);
  }
}

/// The palindromic C(z) = z^m q(cos theta) on the circle: q = a_m + 2 sum_{k>=1} a_{m+k} T_k(c).
QPoly cosine_form(const QPoly& C) {
  const int m = C.degree() / 2;
  const QPoly c({rational(0), rational(1)});
  QPoly t_prev({rational(1)}), t_k = c, q({C.coeff(m)});
  for (int k = 1; k <= m; ++k) {
    q = q + t_k * QPoly({2 * C.coeff(m + k)});
    const QPoly next = c * t_k * QPoly({rational(2)}) - t_prev;
    t_prev = t_k;
    t_k = next;
  }
  return q;
}

/// Im(c) of the pole whose cos(theta0) lies in [lo, hi], at `prec` bits; theta0 written into `theta`.
void pole_term(const BoundProblem& p, const rational& lo, const rational& hi, const rational& nu, long prec, arb_t im,
               arb_t theta) {
  flint::Ball c0, x, s0;
  flint::set(c0.get(), lo, prec);
  flint::set(x.get(), hi, prec);
  arb_union(c0.get(), c0.get(), x.get(), prec);
  arb_sqr(s0.get(), c0.get(), prec);
  arb_sub_si(s0.get(), s0.get(), 1, prec);
  arb_neg(s0.get(), s0.get());
  arb_sqrt(s0.get(), s0.get(), prec);  // sin(theta0) > 0
  arb_acos(theta, c0.get(), prec);
  Acb z0, N, dD, k, e, w;
  acb_set_arb_arb(z0.v, c0.get(), s0.get());
  evaluate(N.v, p.H.num(), z0.v, prec);
  evaluate(dD.v, p.H.den().derivative(), z0.v, prec);
  acb_div(k.v, N.v, dD.v, prec);  // R (indeterminate when D'(z0) may be 0: a pole not shown simple)
  flint::set(x.get(), nu, prec);
  arb_mul(x.get(), x.get(), theta, prec);
  arb_sin_cos(acb_imagref(e.v), acb_realref(e.v), x.get(), prec);
  acb_conj(e.v, e.v);  // e^{-j nu theta0}
  acb_mul(k.v, k.v, e.v, prec);
  acb_sub_ui(w.v, z0.v, 1, prec);
  acb_neg(w.v, w.v);
  acb_mul(w.v, w.v, z0.v, prec);  // (1 - z0) z0
  acb_div(k.v, k.v, w.v, prec);
  flint::set(x.get(), p.T, prec);
  acb_mul_arb(k.v, k.v, x.get(), prec);
  arb_set(im, acb_imagref(k.v));
}

}  // namespace

std::optional<CirclePole> circle_pole(const BoundProblem& p) {
  const QPoly& D = p.H.den();
  QPoly C = gcd(D, reversed(D));
  if (C.degree() < 2) return std::nullopt;
  for (const int s : {1, -1}) {  // z = 1 (integrator_pole) and z = -1 are the band's ends, not this form's
    const QPoly lin({rational(-s), rational(1)});
    while (C.degree() > 0 && C(rational(s)) == 0) C = divmod(C, lin).first;
  }
  if (C.degree() < 2 || C.degree() % 2 != 0) return std::nullopt;
  C = C.monic();
  for (int i = 0; i <= C.degree(); ++i)
    if (C.coeff(i) != C.coeff(C.degree() - i)) return std::nullopt;  // not palindromic: not only circle roots
  const QPoly q = cosine_form(C);
  const QPoly sf = square_free_part(q);
  const rational nu = rational(p.delay) + (p.frac_delay ? *p.frac_delay / p.T : rational(0));
  for (RootInterval r : isolate_real_roots(sf, rational(-1), rational(1))) {
    r = refine_root(sf, r, rational(1) / rational(integer(1) << 96));
    if (r.lo <= -1 || r.hi >= 1) continue;  // q(+-1) != 0 (z = +-1 removed): refined away from the ends
    for (const long prec : {128L, 384L}) {
      flint::Ball im, theta;
      pole_term(p, r.lo, r.hi, nu, prec, im.get(), theta.get());
      const int sign = arb_is_positive(im.get()) ? 1 : arb_is_negative(im.get()) ? -1 : 0;
      if (sign == 0) continue;
      CirclePole out;
      out.q = q;
      out.c_lo = r.lo;
      out.c_hi = r.hi;
      out.side = sign;
      arf_t end;
      arf_init(end);
      arb_get_lbound_arf(end, theta.get(), prec);
      out.theta_lo = flint::to_rational(end);
      arb_get_ubound_arf(end, theta.get(), prec);
      out.theta_hi = flint::to_rational(end);
      arf_clear(end);
      return out;
    }
  }
  return std::nullopt;
}

std::optional<Bound> circle_pole_divergence(const BoundProblem& p) {
  const auto pole = circle_pole(p);
  if (!pole) return std::nullopt;
  Bound out;
  out.infinite = true;
  out.status = Status::certified;
  out.path = BoundPath::at_pole;
  out.decimal = "inf";
  out.omega_enclosure = Enclosure<rational>{pole->theta_lo / p.T, pole->theta_hi / p.T};
  out.omega = to_decimal((pole->theta_lo + pole->theta_hi) / (2 * p.T), 17);
  out.where = std::string("pole on the unit circle at wT = ") + to_decimal(pole->theta_lo, 12) +
              ": Re -> +inf as w -> it from " + (pole->side > 0 ? "above" : "below");
  out.method = "certified: H's simple pole z0 = e^{j theta0} inside the band, f = Im(c)/(theta - theta0) + O(1) with "
               "c = T R e^{-j nu theta0}/((1 - z0) z0), R = N(z0)/D'(z0), and Im(c) " +
               std::string(pole->side > 0 ? "> 0" : "< 0") + " shown in balls (the delay never expanded)";
  return out;
}

}  // namespace hapstab::passivity::detail
