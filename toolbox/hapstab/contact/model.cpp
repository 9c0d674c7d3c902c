#include "hapstab/contact/model.hpp"

#include <cmath>
#include <vector>

#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::contact {

namespace {

using Poly = QPoly;
using RatFun = QRatFun;

// Z{1/s^i} (samples of t^{i-1}/(i-1)! at t = kT), i = 1..4, exact.
RatFun z_of_inverse_power(int i, const rational& T) {
  const Poly z = Poly::monomial(1);
  const Poly zm1 = z - Poly(rational(1));
  switch (i) {
    case 1: return RatFun(z, zm1);
    case 2: return RatFun(z * T, zm1.pow(2));
    case 3: return RatFun(z * (z + Poly(rational(1))) * (T * T / 2), zm1.pow(3));
    case 4: return RatFun(z * (z * z + z * rational(4) + Poly(rational(1))) * (T * T * T / 6), zm1.pow(4));
    default: throw InputError("model_H: F(s) has a pole of order " + std::to_string(i) + " > 4 at s = 0");
  }
}

}  // namespace

TransferFunction hand_impedance(const rational& K, const rational& B, const rational& M) {
  // (M s^2 + B s + K)/s
  if (K < 0 || B < 0 || M < 0) throw InputError("hand_impedance: K, B, M must be >= 0 (a passive operator)");
  return tf(Poly(std::vector<rational>{K, B, M}), Poly::monomial(1));
}

TransferFunction virtual_wall(WallKind kind, const rational& K, const rational& B, const rational& T, int delay) {
  if (T <= 0) throw InputError("virtual_wall: T must be > 0");
  if (delay < 0) throw InputError("virtual_wall: delay must be >= 0");
  const Poly z = Poly::monomial(1);
  const Poly one(rational(1));
  RatFun D = kind == WallKind::backward_difference ? RatFun(z - one, z * T) : RatFun((z - one) * rational(2), (z + one) * T);
  RatFun E = RatFun(K) + RatFun(B) * D;
  if (delay > 0) E = E * RatFun(one, Poly::monomial(delay));
  return {E, Domain::z, T};
}

ModelH model_H(const PhysicalModel& pm, int digits) {
  if (pm.m <= 0) throw InputError("model_H: the device mass m must be > 0");
  if (pm.b < 0) throw InputError("model_H: the device damping b must be >= 0");
  if (pm.T <= 0) throw InputError("model_H: the sample period T must be > 0");
  if (digits < 20 || digits > 90) throw InputError("model_H: digits must be in [20, 90]");
  if (!pm.E.is_discrete() || pm.E.T != pm.T) throw InputError("model_H: E(z) must be discrete with the model's T");
  const Poly s = Poly::monomial(1);
  RatFun Oimp = pm.O.num().is_zero() ? RatFun(0) : pm.O.H;
  if (!pm.O.num().is_zero() && pm.O.is_discrete()) throw InputError("model_H: O(s) must be continuous");
  // F(s) = 1/(s^2 (m s + b + O(s)))
  RatFun imp = RatFun(Poly(std::vector<rational>{pm.b, pm.m})) + Oimp;
  RatFun F = RatFun(Poly(rational(1)), s * s) / imp;
  const Poly& Nf = F.num();
  const Poly& Df = F.den();
  int p = 0;
  while (p <= Df.degree() && Df.coeff(p) == 0) ++p;
  std::vector<rational> d0c(Df.coeffs().begin() + p, Df.coeffs().end());
  const Poly D0(d0c);
  // Taylor coefficients of Nf/D0 at 0 up to order p-1
  std::vector<rational> d(p);
  for (int k = 0; k < p; ++k) {
    rational a = Nf.coeff(k);
    for (int j = 1; j <= k; ++j) a -= D0.coeff(j) * d[k - j];
    d[k] = a / D0.coeff(0);
  }
  RatFun Gz(0);
  Poly taylor;
  for (int k = 0; k < p; ++k) {
    Gz += RatFun(d[k]) * z_of_inverse_power(p - k, pm.T);
    taylor += Poly::monomial(k, d[k]);
  }
  // remainder R = (Nf - D0 * taylor)/(s^p D0), exact division by s^p
  Poly rn = Nf - D0 * taylor;
  for (int k = 0; k < p; ++k)
    if (rn.coeff(k) != 0) throw NumericalError("model_H: partial fraction remainder not divisible by s^p");
  Poly Rn(std::vector<rational>(rn.coeffs().begin() + std::min<long>(p, rn.coeffs().size()), rn.coeffs().end()));
  double coef_err = 0;
  std::string method = "exact partial fractions at s = 0";
  if (!Rn.is_zero()) {
    TransferFunction R = tf(Rn, D0);
    StateSpace<rational> rs = tf2ss(R);
    if (rs.D(0, 0) != 0) throw NumericalError("model_H: remainder not strictly proper");
    Mat<mp100> AT = rs.A.cast<mp100>() * mp100(pm.T);
    Mat<mp100> Ad = expm(AT);
    StateSpace<rational> ds = rs;
    ds.T = pm.T;
    for (Eigen::Index i = 0; i < Ad.rows(); ++i)
      for (Eigen::Index j = 0; j < Ad.cols(); ++j) {
        mpfloat<90> v(Ad(i, j));
        // round to `digits` significant digits
        mpfloat<90> scale = v == 0 ? mpfloat<90>(1) : pow(mpfloat<90>(10), floor(log10(abs(v))) - digits + 1);
        ds.A(i, j) = v == 0 ? rational(0) : exact_rational(mpfloat<90>(round(v / scale))) * exact_rational(scale);
      }
    TransferMatrix tm = ss2tf(ds);
    Gz += RatFun(Poly::monomial(1)) * tm(0, 0).H;
    coef_err = std::pow(10.0, -digits + 1);
    method += " + e^{AT} in 100 digits rounded to " + std::to_string(digits) + " significant digits";
  }
  const Poly z = Poly::monomial(1);
  RatFun Gd = RatFun(z - Poly(rational(1)), z) * Gz;
  ModelH out;
  out.G = {Gd, Domain::z, pm.T};
  out.H = {pm.E.H * Gd, Domain::z, pm.T};
  out.coefficient_error = coef_err;
  out.method = method;
  return out;
}

double zoh_check_by_simulation(const PhysicalModel& pm, const TransferFunction& G, int samples, int substeps) {
  // continuous plant force -> position: 1/(s (m s + b + O(s))) = Od/(s((ms+b)Od + On))
  const Poly s = Poly::monomial(1);
  RatFun Oimp = pm.O.num().is_zero() ? RatFun(0) : pm.O.H;
  RatFun P = RatFun(Poly(rational(1)), s) / (RatFun(Poly(std::vector<rational>{pm.b, pm.m})) + Oimp);
  StateSpace<rational> cs = tf2ss(tf(P.num(), P.den()));
  StateSpace<rational> dsys = tf2ss(G);
  const int n = static_cast<int>(cs.A.rows()), nd = static_cast<int>(dsys.A.rows());
  Mat<double> A = cs.A.cast<double>(), B = cs.B.cast<double>(), C = cs.C.cast<double>();
  Mat<double> Ad = dsys.A.cast<double>(), Bd = dsys.B.cast<double>(), Cd = dsys.C.cast<double>(),
              Dd = dsys.D.cast<double>();
  Vec<double> x = Vec<double>::Zero(n), xd = Vec<double>::Zero(nd);
  const double T = static_cast<double>(mpfloat<30>(pm.T)), h = T / substeps;
  double maxdev = 0, maxabs = 0;
  unsigned seed = 7;
  for (int k = 0; k < samples; ++k) {
    seed = seed * 1103515245u + 12345u;
    const double f = ((seed >> 8) % 2001) / 1000.0 - 1.0;  // force held over the sample
    const double yc = (C * x)(0, 0);
    const double yd = (Cd * xd + Dd * f)(0, 0);
    maxdev = std::max(maxdev, std::abs(yc - yd));
    maxabs = std::max(maxabs, std::abs(yc));
    for (int j = 0; j < substeps; ++j) {
      auto fx = [&](const Vec<double>& v) -> Vec<double> { return A * v + B.col(0) * f; };
      Vec<double> k1 = fx(x), k2 = fx(x + 0.5 * h * k1), k3 = fx(x + 0.5 * h * k2), k4 = fx(x + h * k3);
      x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    xd = Ad * xd + Bd.col(0) * f;
  }
  return maxabs > 0 ? maxdev / maxabs : maxdev;
}

}  // namespace hapstab::contact
