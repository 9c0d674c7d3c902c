// hapstab/numeric/jet.hpp -- order-2 jets (f, f', f'') over a scalar S, and the delay kernels
// the long-delay paths are built from. S = flint::Ball gives enclosures of f, f', f'' for every
// point of the ball the variable holds (the derivative bounds of an interval branch-and-bound);
// S = double gives the same formulas as plain numbers (the fast paths), and S = Dint
// (numeric/dinterval.hpp) enclosures in double intervals with rounding bounds (the cheap pruning
// of the certified paths), so all three evaluate one expression.
//
// The kernels, with theta in [0, pi] and nu >= 0 real (the delay in samples):
//   sinc(u) = sin(u)/u                 (sinc(0) = 1)
//   S_nu(theta) = sin(nu theta) cot(theta/2) = 2 nu sinc(nu theta) cos(theta/2) / sinc(theta/2)
//   K_m(theta)  = sin(m theta) / sin(theta) = m sinc(m theta) / sinc(theta)           (theta <= pi/2)
//               = (-1)^(m+1) m sinc(m eps) / sinc(eps),  eps = pi - theta, integer m  (theta >= pi/2)
// Both are finite everywhere on [0, pi] (K_m for integer m); in the sinc forms nothing cancels as
// theta -> 0 (or -> pi), where sin(nu theta) cot(theta/2) written as it stands is 0 * inf.
// sinc near 0 (|u| <= 1/4) is its Taylor polynomial with the remainder bound added to the ball:
// for |u| <= 1/4, j <= 2 and the terms k >= K left out,
//   |d^j/du^j sum_{k>=K} (-1)^k u^{2k}/(2k+1)!| <= sum_{k>=K} (2k)^2 |u|^{2k-2}/(2k+1)!
//                                                <= 2 (2K)^2 4^{-(2K-2)}/(2K+1)!,
// since consecutive terms shrink by a factor below 1/2 (proofs/delay_kernels.cpp checks it).
// Where a ball containing 0 is too wide for the Taylor form, sinc's derivatives are bounded by
// |sinc^(j)(u)| = |int_0^1 t^j cos^(j)(t u) dt| <= 1/(j+1).
#pragma once

#include <cmath>
#include <type_traits>
#include <vector>

#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/dinterval.hpp"

namespace hapstab::jet {

using flint::Ball;

// ---- the scalar operations a jet needs, for double and Ball ---------------------------------
inline void sin_cos(double x, double& s, double& c) { s = std::sin(x); c = std::cos(x); }
inline void sin_cos(const Ball& x, Ball& s, Ball& c) { flint::sin_cos(x, s, c); }
inline double abs_upper(double x) { return std::abs(x); }
inline double abs_upper(const Ball& x) { return x.abs_upper(); }
inline bool contains_zero(double x) { return x == 0; }
inline bool contains_zero(const Ball& x) { return x.contains_zero(); }
inline void add_error(double&, const rational&) {}
inline void add_error(Ball& x, const rational& e) { x = flint::widen(x, e); }
inline double abs_upper(const Dint& x) { return x.abs_upper(); }
inline bool contains_zero(const Dint& x) { return x.contains_zero(); }
inline void add_error(Dint& x, const rational& e) { x = x.widened(Dint::from_rational(e).hi); }
template <class S> S scalar(const rational& q);
template <> inline double scalar<double>(const rational& q) { return to_real<double>(q); }
template <> inline Ball scalar<Ball>(const rational& q) { return Ball(q); }
template <> inline Dint scalar<Dint>(const rational& q) { return Dint::from_rational(q); }
template <class S> S scalar_pi();
template <> inline double scalar_pi<double>() { return 3.14159265358979323846; }
template <> inline Ball scalar_pi<Ball>() { return Ball::pi(); }
template <> inline Dint scalar_pi<Dint>() { return dint_pi(); }

/// f, f', f'' (the second derivative itself, not over 2).
template <class S>
struct Jet {
  S v, d, dd;
};

template <class S> Jet<S> variable(const S& x) { return {x, S(1.0), S(0.0)}; }
template <class S> Jet<S> constant(const S& c) { return {c, S(0.0), S(0.0)}; }
template <class S> Jet<S> operator+(const Jet<S>& a, const Jet<S>& b) { return {a.v + b.v, a.d + b.d, a.dd + b.dd}; }
template <class S> Jet<S> operator-(const Jet<S>& a, const Jet<S>& b) { return {a.v - b.v, a.d - b.d, a.dd - b.dd}; }
template <class S> Jet<S> operator*(const S& k, const Jet<S>& a) { return {k * a.v, k * a.d, k * a.dd}; }
template <class S> Jet<S> operator*(const Jet<S>& a, const Jet<S>& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d, a.dd * b.v + (a.d * b.d) * 2 + a.v * b.dd};
}
template <class S> Jet<S> operator/(const Jet<S>& a, const Jet<S>& b) {
  const S w = a.v / b.v;
  const S w1 = (a.d - w * b.d) / b.v;
  return {w, w1, (a.dd - (w1 * b.d) * 2 - w * b.dd) / b.v};
}

/// phi(u) for a jet u, given phi, phi', phi'' at u.v (the chain rule).
template <class S>
Jet<S> compose(const Jet<S>& u, const S& f, const S& f1, const S& f2) {
  return {f, f1 * u.d, f2 * (u.d * u.d) + f1 * u.dd};
}
/// sin(u) and cos(u) for a jet u, given sin and cos of u.v.
template <class S>
void sin_cos(const Jet<S>& u, const S& s, const S& c, Jet<S>& sj, Jet<S>& cj) {
  sj = compose(u, s, c, -s);
  cj = compose(u, c, -s, -c);
}

/// p(x) (ascending coefficients, at least one) for a jet x, by Horner. Over a wide ball (radius
/// above 2^-60 of its centre's size) p is first shifted to the centre m, p(x) = sum b_k (x - m)^k,
/// and evaluated in x - m: the centred form, whose enclosure follows p's variation over the ball
/// instead of the size of its coefficients (near a narrow resonance |D|^2 is 1e-7 of them). Over a
/// narrower ball the plain form is tried first and the centred one taken when it is not finite or
/// not narrow (since stop 88: a pole of high order near the circle, `bound --H "1/(z+1/2)^20"
/// --delay 190`, left B's enclosure holding 0 and the long-delay path without an upper bound).
template <class S>
Jet<S> horner(const std::vector<S>& p, const Jet<S>& x) {
  auto plain = [](const std::vector<S>& q, const Jet<S>& y) {
    Jet<S> r = constant(q.back());
    for (size_t i = q.size() - 1; i-- > 0;) {
      r = r * y;
      r.v = r.v + q[i];
    }
    return r;
  };
  if constexpr (!std::is_same_v<S, double>) {
    auto centred = [&] {
      const S m(x.v.mid());  // a point (Ball: exact midpoint; Dint: a double inside)
      std::vector<S> b = p;
      for (size_t k = 0; k < b.size(); ++k)
        for (size_t i = b.size() - 1; i > k; --i) b[i - 1] = b[i - 1] + m * b[i];
      return plain(b, Jet<S>{x.v - m, x.d, x.dd});
    };
    if (p.size() > 2 && x.v.radius() > std::ldexp(1.0, -60) * (1 + x.v.abs_upper())) return centred();
    // A narrower ball: plain Horner's enclosure grows like x's radius times sum |p_i| |x|^i, not
    // like p's variation, and where p(x) cancels (|D|^2 near a pole of H close to the circle:
    // (5/4 + c)^20 is 1e-12 at c = -1 of coefficients ~1e7) a radius of 2^-62 already holds 0, at
    // any precision. The centred form then, when the plain enclosure is not finite or not narrow.
    if (p.size() > 2 && x.v.radius() > 0) {
      const Jet<S> r = plain(p, x);
      if (r.v.finite() && r.d.finite() && r.dd.finite() && !(r.v.radius() > std::ldexp(1.0, -20) * r.v.abs_upper()))
        return r;
      return centred();
    }
  }
  return plain(p, x);
}

/// The Taylor coefficients of sinc in t = u^2 (a_k = (-1)^k/(2k+1)!), K of them, and the bound of
/// the remainder of sinc, sinc', sinc'' for |u| <= 1/4 (see the header), for precision `bits`.
struct SincTaylor {
  std::vector<rational> a;
  rational remainder;
};
inline SincTaylor sinc_taylor(long bits) {
  SincTaylor t;
  rational fact = 1;  // (2K+1)!
  for (int K = 1;; ++K) {
    const int k = K - 1;
    t.a.push_back((k % 2 == 0 ? rational(1) : rational(-1)) / fact);
    fact *= (2 * K) * (2 * K + 1);
    rational e = rational(2 * (2 * K) * (2 * K)) / fact;
    for (int i = 0; i < 2 * K - 2; ++i) e /= 4;
    if (K >= 3 && e < rational(1) / rational(integer(1) << static_cast<unsigned>(bits + 8))) {
      t.remainder = e;
      return t;
    }
  }
}

/// sinc, sinc', sinc'' at the scalar u (a ball: enclosures over it), given sin u and cos u.
template <class S>
void sinc_values(const S& u, const S& su, const S& cu, S& f, S& f1, S& f2);

template <>
inline void sinc_values<double>(const double& u, const double& su, const double& cu, double& f, double& f1,
                                double& f2) {
  if (std::abs(u) > 0.25) {
    f = su / u;
    f1 = (cu - f) / u;
    f2 = -f - 2 * f1 / u;
    return;
  }
  static const SincTaylor t = sinc_taylor(53);
  const double x = u * u;
  f = f1 = f2 = 0;
  for (size_t k = t.a.size(); k-- > 0;) {
    const double a = to_real<double>(t.a[k]);
    f = f * x + a;
    if (k >= 1) {
      f1 = f1 * x + a * static_cast<double>(2 * k);
      f2 = f2 * x + a * static_cast<double>(2 * k * (2 * k - 1));
    }
  }
  f1 *= u;
}

template <>
inline void sinc_values<Ball>(const Ball& u, const Ball& su, const Ball& cu, Ball& f, Ball& f1, Ball& f2) {
  if (u.abs_upper() <= 0.25) {
    thread_local long cached_bits = 0;
    thread_local std::vector<Ball> a, a1, a2;
    thread_local rational remainder;
    if (cached_bits != flint::ball_prec) {
      const SincTaylor t = sinc_taylor(flint::ball_prec);
      a.clear(), a1.clear(), a2.clear();
      for (size_t k = 0; k < t.a.size(); ++k) {
        a.emplace_back(t.a[k]);
        const long k2 = static_cast<long>(2 * k);
        a1.emplace_back(t.a[k] * k2);
        a2.emplace_back(k == 0 ? rational(0) : t.a[k] * (k2 * (k2 - 1)));
      }
      remainder = t.remainder;
      cached_bits = flint::ball_prec;
    }
    const Ball x = u * u;
    f = Ball(0L), f1 = Ball(0L), f2 = Ball(0L);
    for (size_t k = a.size(); k-- > 0;) {
      f = f * x + a[k];
      if (k >= 1) {
        f1 = f1 * x + a1[k];
        f2 = f2 * x + a2[k];
      }
    }
    f1 = f1 * u;
    add_error(f, remainder);
    add_error(f1, remainder);
    add_error(f2, remainder);
    return;
  }
  if (!u.contains_zero()) {
    f = su / u;
    f1 = (cu - f) / u;
    f2 = -f - f1 * 2 / u;
    return;
  }
  // a wide ball around 0: the value from Arb, the derivatives from |sinc^(j)| <= 1/(j+1)
  arb_sinc(f.get(), u.get(), flint::ball_prec);
  f1 = Ball::hull(rational(-1, 2), rational(1, 2));
  f2 = Ball::hull(rational(-1, 3), rational(1, 3));
}

template <>
inline void sinc_values<Dint>(const Dint& u, const Dint& su, const Dint& cu, Dint& f, Dint& f1, Dint& f2) {
  if (u.abs_upper() <= 0.25) {  // the Taylor form of the Ball case, its remainder below 2^-68
    struct Coefficients {
      std::vector<Dint> a, a1, a2;
      double remainder = 0;
    };
    static const Coefficients t = [] {
      Coefficients c;
      const SincTaylor st = sinc_taylor(60);
      for (size_t k = 0; k < st.a.size(); ++k) {
        const long k2 = static_cast<long>(2 * k);
        c.a.push_back(Dint::from_rational(st.a[k]));
        c.a1.push_back(Dint::from_rational(st.a[k] * k2));
        c.a2.push_back(Dint::from_rational(k == 0 ? rational(0) : st.a[k] * (k2 * (k2 - 1))));
      }
      c.remainder = Dint::from_rational(st.remainder).hi;
      return c;
    }();
    const Dint x = u * u;
    f = f1 = f2 = Dint(0.0);
    for (size_t k = t.a.size(); k-- > 0;) {
      f = f * x + t.a[k];
      if (k >= 1) {
        f1 = f1 * x + t.a1[k];
        f2 = f2 * x + t.a2[k];
      }
    }
    f1 = f1 * u;
    f = f.widened(t.remainder), f1 = f1.widened(t.remainder), f2 = f2.widened(t.remainder);
    return;
  }
  if (!u.contains_zero()) {
    f = su / u;
    f1 = (cu - f) / u;
    f2 = -f - f1 * 2L / u;
    return;
  }
  // a wide interval around 0: sinc >= -0.2173 (its least value, at u = 4.4934...), |sinc^(j)| <= 1/(j+1)
  f = Dint(-0.22, 1.0), f1 = Dint(-0.5, 0.5), f2 = Dint(-0.34, 0.34);
}

/// sinc(u) for a jet u, given sin and cos of u.v.
template <class S>
Jet<S> sinc(const Jet<S>& u, const S& su, const S& cu) {
  S f, f1, f2;
  sinc_values(u.v, su, cu, f, f1, f2);
  return compose(u, f, f1, f2);
}

/// S_nu(theta) = sin(nu theta) cot(theta/2) for a jet theta in [0, pi], given sin and cos of
/// nu theta.v and of theta.v/2 (see the header). nu = 0 gives 0.
template <class S>
Jet<S> kernel_S(const Jet<S>& theta, const S& nu, const S& s_nu, const S& c_nu, const S& s_half, const S& c_half) {
  const Jet<S> u = nu * theta, h = S(0.5) * theta;
  Jet<S> sh, ch;
  sin_cos(h, s_half, c_half, sh, ch);
  return (S(2.0) * nu) * (sinc(u, s_nu, c_nu) * ch / sinc(h, s_half, c_half));
}

/// K_m(theta) = sin(m theta)/sin(theta) for an integer m >= 0 and a jet theta in [0, pi], given
/// sin and cos of m theta.v and of theta.v (see the header).
template <class S>
Jet<S> kernel_K(const Jet<S>& theta, long m, const S& s_m, const S& c_m, const S& s_1, const S& c_1) {
  if (m == 0) return constant(S(0.0));
  const S mm(static_cast<double>(m));
  const double top = abs_upper(theta.v);
  if (top <= 1.5707) return mm * (sinc(mm * theta, s_m, c_m) / sinc(theta, s_1, c_1));
  // the distance to pi, eps = pi - theta: sin(m eps) = (-1)^(m+1) sin(m theta), cos(m eps) = (-1)^m cos(m theta)
  const Jet<S> eps = constant(scalar_pi<S>()) - theta;
  const double sign = m % 2 == 0 ? 1.0 : -1.0;
  if (abs_upper(eps.v) <= 1.5707)
    return (S(-sign) * mm) * (sinc(mm * eps, S(-sign) * s_m, S(sign) * c_m) / sinc(eps, s_1, -c_1));
  Jet<S> sm, cm, s1, c1;
  sin_cos(mm * theta, s_m, c_m, sm, cm);
  sin_cos(theta, s_1, c_1, s1, c1);
  return sm / s1;
}

}  // namespace hapstab::jet
