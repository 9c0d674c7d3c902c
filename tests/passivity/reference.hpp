// tests/passivity/reference.hpp -- an independent high-precision reference for the passivity
// bound (45)/(54), by a DIFFERENT algorithm from the library: direct complex evaluation of
// Re{T H(e^{jθ}) e^{-jnθ} e^{-jθ τ}/(1 - e^{jθ})} in 100-digit MPFR (no c = cos θ form, no Sturm),
// dense sampling of θ in (0, π] plus extra samples around given resonance angles, then
// golden-section refinement of the best local maxima. θ -> 0 is approached at θ = 1e-30 (the
// objective is smooth there; 100 digits absorb the cancellation of T/(1 - z) ~ 1e30).
#pragma once

#include <algorithm>
#include <vector>

#include <map>
#include <string>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/scalar.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::testref {

/// The bound problem of an exact expression of z with T, parameters and an integer delay n.
inline passivity::BoundProblem make(const std::string& e, const std::string& T, std::map<std::string, rational> par = {},
                                    int n = 0) {
  ParseOptions o;
  o.variable = 'z';
  o.T = parse_rational(T);
  o.parameters = std::move(par);
  o.hidden_poles = HiddenPoles::allow_marginal;  // as `bound` reads H
  passivity::BoundProblem p;
  p.H = parse_tf(e, o).H;
  p.T = o.T;
  p.delay = n;
  return p;
}

using R = mp100;

struct Ref {
  R value;
  R theta;
};

inline R objective(const RationalFunction<rational>& H, const rational& T, int n, const rational& tau, const R& th) {
  R zr = cos(th), zi = sin(th);
  auto eval = [&](const Polynomial<rational>& p, R& re, R& im) {
    re = 0;
    im = 0;
    for (size_t i = p.coeffs().size(); i-- > 0;) {
      R nr = re * zr - im * zi + R(p.coeffs()[i]);
      R ni = re * zi + im * zr;
      re = nr;
      im = ni;
    }
  };
  R nr, ni, dr, di;
  eval(H.num(), nr, ni);
  eval(H.den(), dr, di);
  R d2 = dr * dr + di * di;
  R hr = (nr * dr + ni * di) / d2, hi = (ni * dr - nr * di) / d2;
  // multiply by e^{-j(n + tau) th}
  R ph = -(R(n) + R(tau)) * th;
  R cr = cos(ph), ci = sin(ph);
  R wr = hr * cr - hi * ci, wi = hr * ci + hi * cr;
  // T/(1 - z)
  R ar = 1 - zr, ai = -zi, a2 = ar * ar + ai * ai;
  R Tr = R(T);
  R gr = Tr * ar / a2, gi = -Tr * ai / a2;
  return wr * gr - wi * gi;
}

/// sup over θ in (0, π] (θ = 0 as the limit θ = 1e-30).
/// `resonances`: angles θ around which 601 extra samples `resonance_step` apart are taken (the
/// step must be below the peak width, ~ 1 - pole radius).
inline Ref reference(const RationalFunction<rational>& H, const rational& T, int n, const rational& tau = 0,
                     const std::vector<double>& resonances = {}, int samples = 3000,
                     const char* resonance_step = "1e-5") {
  const R pi = boost::math::constants::pi<R>();
  std::vector<R> th;
  th.push_back(R("1e-30"));
  for (int k = 1; k <= samples; ++k) th.push_back(pi * k / samples);
  for (double a : resonances)
    for (int k = -300; k <= 300; ++k) {
      R x = R(a) + R(k) * R(resonance_step);
      if (x > 0 && x <= pi) th.push_back(x);
    }
  std::sort(th.begin(), th.end());
  std::vector<R> v(th.size());
  for (size_t i = 0; i < th.size(); ++i) v[i] = objective(H, T, n, tau, th[i]);
  // local maxima (including the ends), refine the best few by golden section
  std::vector<size_t> idx;
  for (size_t i = 0; i < th.size(); ++i) {
    bool left = i == 0 || v[i] >= v[i - 1];
    bool right = i + 1 == th.size() || v[i] >= v[i + 1];
    if (left && right) idx.push_back(i);
  }
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return v[a] > v[b]; });
  if (idx.size() > 6) idx.resize(6);
  Ref best{v[idx[0]], th[idx[0]]};
  const R gr = (sqrt(R(5)) - 1) / 2;
  for (size_t i : idx) {
    R a = i == 0 ? th[0] : th[i - 1], b = i + 1 == th.size() ? pi : th[i + 1];
    R x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    R f1 = objective(H, T, n, tau, x1), f2 = objective(H, T, n, tau, x2);
    for (int it = 0; it < 260 && b - a > R("1e-45"); ++it) {
      if (f1 < f2) {
        a = x1; x1 = x2; f1 = f2; x2 = a + gr * (b - a); f2 = objective(H, T, n, tau, x2);
      } else {
        b = x2; x2 = x1; f2 = f1; x1 = b - gr * (b - a); f1 = objective(H, T, n, tau, x1);
      }
    }
    R fa = objective(H, T, n, tau, a), fb = objective(H, T, n, tau, b);
    for (auto [x, f] : {std::pair{x1, f1}, std::pair{x2, f2}, std::pair{a, fa}, std::pair{b, fb}})
      if (f > best.value) best = {f, x};
  }
  return best;
}

}  // namespace hapstab::testref
