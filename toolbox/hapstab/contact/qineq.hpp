// hapstab/contact/qineq.hpp -- the q-inequalities (21), (22), (24) of paper 002 at a frequency
// theta = 2 pi k/N, and their half-planes in the Nyquist plane of H (Fig. 6).
//
//   Re lambda_k^q = Re[(1 - e^{j q theta})(1 + H)] = (1 - cos q theta)(1 + Re H) + sin(q theta) Im H > 0   (24)
//   q = 0 stands for (21): Re mu_k = 1 + Re H > 0 (Tsypkin).  Dividing (24) by 1 - cos q theta > 0
//   gives (22): Re H + sin(q theta)/(1 - cos q theta) Im H > -1; when q theta = 0 mod 2 pi, (24) is
//   the impossible 0 > 0.
// Every boundary line passes through H = -1; the arrows of Fig. 6 point along the normal (nx, ny).
// Templates on the real type (double for plots, mpfloat<D> for the proofs).
//
// Implements: paper 002 (21), (22), (24), Fig. 6.
#pragma once

#include <cmath>

namespace hapstab::contact {

/// The open half-plane {h : nx (Re h + 1) + ny Im h > 0} of inequality q at theta (q = 0: (21)).
template <class R>
struct HalfPlane {
  R nx, ny;
  bool degenerate() const { return nx == 0 && ny == 0; }  ///< (24) with q theta = 0 mod 2 pi: 0 > 0
};

template <class R>
HalfPlane<R> q_halfplane(const R& theta, int q) {
  using std::cos;
  using std::sin;
  if (q == 0) return {R(1), R(0)};
  const R a = theta * q;
  return {R(1) - cos(a), sin(a)};
}

/// The left side of (24) (of (21) for q = 0): > 0 means the inequality holds at h = re + j im.
template <class R>
R q_lhs(const R& theta, int q, const R& re, const R& im) {
  HalfPlane<R> hp = q_halfplane(theta, q);
  return hp.nx * (re + 1) + hp.ny * im;
}

/// The wedge branch pair of (25) at theta: q = 1 and q = N - 1 (= q = -1) of (22), i.e.
/// max(Re h + m Im h, Re h - m Im h) + 1 with m = cot(theta/2); > 0 means outside the wedge.
template <class R>
R wedge_lhs(const R& theta, const R& re, const R& im) {
  using std::cos;
  using std::sin;
  const R m = sin(theta) / (1 - cos(theta));
  const R a = re + m * im, b = re - m * im;
  return (a > b ? a : b) + 1;
}

}  // namespace hapstab::contact
