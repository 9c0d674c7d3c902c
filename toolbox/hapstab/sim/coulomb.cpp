// Coulomb friction with stiction, event-located (see coulomb.hpp).
#include "hapstab/sim/coulomb.hpp"

#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

#include "hapstab/numeric/error.hpp"

namespace hapstab::sim {

namespace {

constexpr int max_events = 1000;

Mat<double> to_double(const Mat<rational>& M) {
  Mat<double> R(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.size(); ++i) R.data()[i] = to_real<double>(M.data()[i]);
  return R;
}

// The velocity state: C's velocity row must be a unit vector (a mass-damper device).
int velocity_state(const StateSpace<rational>& P) {
  int iv = -1;
  for (Eigen::Index k = 0; k < P.A.rows(); ++k) {
    const rational& c = P.C(1, k);
    if (c == 0) continue;
    if (c != 1 || iv >= 0) iv = -2;
    if (iv == -1) iv = int(k);
  }
  if (iv < 0 || P.D(1, 0) != 0 || P.D(1, 1) != 0)
    throw InputError("coulomb friction: the device's velocity must be one state (a mass-damper device m, b)");
  return iv;
}

}  // namespace

CoulombStepper::CoulombStepper(const StateSpace<rational>& P, const rational& fc, const std::vector<double>& pieces) {
  if (P.inputs() != 2)
    throw InputError("coulomb friction: only one-DOF loops are supported (this loop has " + std::to_string(P.inputs() / 2) +
                     " DOFs)");
  iv_ = velocity_state(P);
  const auto n = P.A.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (i == iv_) continue;
    bool rests = P.B(i, 0) == 0 && P.B(i, 1) == 0;
    for (Eigen::Index k = 0; k < n && rests; ++k) rests = k == iv_ || P.A(i, k) == 0;
    if (!rests)
      throw InputError("coulomb friction: state " + std::to_string(i) +
                       " of the loop moves while the device sticks; supported: a mass-damper device with operators "
                       "of mass, damper and spring (m, b, k)");
  }
  if (P.B(iv_, 0) <= 0) throw InputError("coulomb friction: the actuator force does not accelerate the device");
  A_ = to_double(P.A);
  B_ = to_double(P.B);
  cx_ = to_double(Mat<rational>(P.C.row(0).transpose()));
  g_ = to_real<double>(P.B(iv_, 0));
  fc_ = to_real<double>(fc);
  // z = [s; F; w], z' = M z; port power f_h v = z^T Q z
  const auto nz = n + 2;
  M_ = Mat<double>::Zero(nz, nz);
  M_.topLeftCorner(n, n) = A_;
  M_.topRightCorner(n, 2) = B_;
  Mat<rational> a(1, nz), b(1, nz);
  a << P.C.row(2), P.D.row(2);
  b << P.C.row(1), P.D.row(1);
  Q_ = to_double(Mat<rational>((a.transpose() * b + b.transpose() * a) / rational(2)));
  for (double h : pieces)
    if (h > 0) cache_.push_back(step(h / substeps));
}

CoulombStepper::Step CoulombStepper::step(double h) const {
  const auto n = A_.rows(), nz = M_.rows();
  Step st;
  st.h = h;
  const Mat<double> E = (M_ * h).exp();  // [[e^{Ah}, Gamma], [0, I]]
  st.Phi = E.topLeftCorner(n, n);
  st.gu = E.block(0, n, n, 1);
  st.gw = E.block(0, n + 1, n, 1);
  Mat<double> C = Mat<double>::Zero(2 * nz, 2 * nz);  // Van Loan: W = F22^T F12
  C.topLeftCorner(nz, nz) = -M_.transpose() * h;
  C.topRightCorner(nz, nz) = Q_ * h;
  C.bottomRightCorner(nz, nz) = M_ * h;
  const Mat<double> F = C.exp();
  st.W = F.bottomRightCorner(nz, nz).transpose() * F.topRightCorner(nz, nz);
  return st;
}

const CoulombStepper::Step& CoulombStepper::cached(double h) const {
  for (const Step& st : cache_)
    if (st.h == h) return st;
  throw std::logic_error("coulomb friction: no sub-step of length " + std::to_string(h));
}

double CoulombStepper::velocity_after(const Vec<double>& s, double F, double w, double tau) const {
  const Step st = step(tau);
  return (st.Phi.row(iv_) * s)(0) + st.gu(iv_) * F + st.gw(iv_) * w;
}

void CoulombStepper::chunk(Vec<double>& s, const Step& st, double u, double F, double w, double& e_port,
                           double& e_act) const {
  Vec<double> z(s.size() + 2);
  z << s, F, w;
  e_port += z.dot(st.W * z);
  const double x0 = cx_.dot(s);
  s = st.Phi * s + st.gu * F + st.gw * w;
  e_act += u * (cx_.dot(s) - x0);
}

int CoulombStepper::advance(Vec<double>& s, double u, double w, double h, double& e_port, double& e_act) const {
  const double delta = h / substeps;
  const Step& sub = cached(delta);
  double t = 0;
  int events = 0;
  while (h - t > 1e-12 * h) {
    const double v = s(iv_);
    int dir;
    if (v == 0) {
      const double a0 = (A_.row(iv_) * s)(0) + B_(iv_, 0) * u + B_(iv_, 1) * w;
      if (std::fabs(a0) <= fc_ * g_) return events;  // sticks: every state rests until the inputs change
      dir = a0 > 0 ? 1 : -1;
    } else {
      dir = v > 0 ? 1 : -1;
    }
    const double F = u - fc_ * dir;
    const double len = std::min(delta, h - t);
    const Step odd = len == delta ? Step{} : step(len);
    const Step& st = len == delta ? sub : odd;
    const double v1 = (st.Phi.row(iv_) * s)(0) + st.gu(iv_) * F + st.gw(iv_) * w;
    if (v1 * dir > 0) {
      chunk(s, st, u, F, w, e_port, e_act);
      t += len;
      continue;
    }
    double lo = 0, hi = len;  // v(lo) dir > 0 (or v = 0 leaving in dir), v(hi) dir <= 0
    while (hi - lo > 1e-15 * h) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (velocity_after(s, F, w, mid) * dir > 0 ? lo : hi) = mid;
    }
    chunk(s, step(hi), u, F, w, e_port, e_act);
    s(iv_) = 0;
    t += hi;
    if (++events > max_events)
      throw NumericalError("coulomb friction: more than " + std::to_string(max_events) +
                           " stick/slip events in one piece (chattering); shorten T or check the scene");
  }
  return events;
}

}  // namespace hapstab::sim
