// hapstab/check/loop_model.cpp -- see loop_model.hpp.
#include "hapstab/check/loop_model.hpp"

#include <vector>

#include "hapstab/check/certificate.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/ball.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::check::detail {

using P = Polynomial<rational>;
using RF = RationalFunction<rational>;

RF parse_model_field(const nlohmann::json& model, const char* key, char variable, const rational& T,
                     const std::map<std::string, rational>& params, HiddenPoles hidden_poles) {
  const std::string where = std::string("model.") + key;
  if (!model.contains(key)) throw InputError(where + ": missing");
  if (!model.at(key).is_string()) throw InputError(where + ": not a string (an expression)");
  ParseOptions po;
  po.variable = variable;
  po.T = T;
  po.parameters = params;
  po.hidden_poles = hidden_poles;
  try {
    const TransferFunction t = parse_tf(model.at(key).get<std::string>(), po);
    if (t.is_discrete() != (variable == 'z'))
      throw InputError(std::string("expected a transfer function in ") + variable);
    return t.H;
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

namespace {

/// Nd with P_d = Nd/(z - 1)^k for P_eff = N(s)/s^k (header: Z{l^m} by S_m = -z S'_{m-1}).
P sampled_numerator(const P& N, int k, const rational& T) {
  const RF z(P{rational(0), rational(1)});
  RF S = z / RF(P{rational(-1), rational(1)});  // S_0 = z/(z - 1)
  RF Y(rational(0));
  rational Tm(1), fact(1);
  std::vector<RF> Sm{S};
  for (int m = 1; m <= k; ++m) Sm.push_back(-(z * Sm.back().derivative()));
  for (int m = 1; m <= k; ++m) {
    Tm *= T;
    fact *= m;
    const rational b = N.coeff(k - m);  // the coefficient of s^(k-m): b / s^(m+1) in P_eff/s
    if (b != 0) Y += RF(b * Tm / fact) * Sm[static_cast<size_t>(m)];
  }
  const RF Pd = RF(P{rational(-1), rational(1)}) / z * Y;
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(k));
  const auto [q, rem] = divmod(Dk, Pd.den());
  if (!rem.is_zero()) throw InputError("model.plant: the sampled device's denominator is not (z - 1)^k (checker defect)");
  return Pd.num() * q;
}

/// The spring's R, Ndp (loop_model.hpp): den = s^k q, q monic of degree 2.
LoopDevice spring_device(LoopDevice d, const P& N, const P& den) {
  const rational a0 = den.coeff(d.k), a1 = den.coeff(d.k + 1);
  const P q{a0, a1, rational(1)};
  const P sinv{-a1 / a0, rational(-1) / a0};  // s^-1 mod q: s (s + a1) = -a0 mod q
  P R = divmod(N, q).second;
  for (int i = 0; i <= d.k; ++i) R = divmod(R * sinv, q).second;
  std::vector<rational> sk1(static_cast<size_t>(d.k) + 2, rational(0));
  sk1.back() = 1;  // s^(k+1)
  const auto [Q, rem] = divmod(N - R * P(sk1), q);
  if (!rem.is_zero()) throw InputError("model.plant: N - R s^(k+1) is not divisible by q (checker defect)");
  d.R0 = R.coeff(0);
  d.R1 = R.degree() >= 1 ? R.coeff(1) : rational(0);
  if (Q.coeff(d.k) + d.R1 != 0) throw InputError("model.plant: the step response is not 0 at t = 0 (checker defect)");
  d.spring = std::make_pair(a1, a0);
  d.Ndp = sampled_numerator(Q, d.k, d.T);
  return d;
}

}  // namespace

LoopDevice read_loop_device(const nlohmann::json& model, bool one_pole, bool scene_device) {
  LoopDevice d;
  if (!model.contains("plant")) throw InputError("model.plant: missing");
  const PeriodDelay pd = read_period_delay(model);
  d.T = pd.T;
  d.n = pd.n;
  d.params = model_parameters(model);
  RF dev = parse_model_field(model, "plant", 's', d.T, d.params,
                            scene_device ? HiddenPoles::allow_integrator : HiddenPoles::refuse);
  if (dev.is_zero()) throw InputError("model.plant: zero (the device does not move)");
  if (model.contains("operator")) {
    const RF s(P{rational(0), rational(1)});
    const RF Z = parse_model_field(model, "operator", 's', d.T, d.params);
    const RF one = RF(rational(1)) + s * Z * dev;
    if (one.is_zero()) throw InputError("model.operator: 1 + s Z_op P is zero");
    const P whole = dev.den() * Z.den() + P{rational(0), rational(1)} * Z.num() * dev.num();
    dev = dev / one;
    // the device's and the operator's modes are the roots of Dp Dz + s Nz Np: one the reduction cancels stays a
    // mode of the loop as written, refused in Re s >= 0 (but one s: the operator spring's deflection beside the
    // position it integrates, a conserved quantity)
    P lost = divmod(whole, dev.den()).first;
    if (lost.degree() >= 1 && lost.coeff(0) == 0) lost = divmod(lost, P{rational(0), rational(1)}).first;
    if (lost.degree() >= 1 && !hurwitz_stable(lost))
      throw InputError("model.operator: P/(1 + s Z_op P) cancels a mode of the device and the operator with Re s >= 0: "
                       "realised as written it is a hidden mode the wall does not move");
  }
  if (dev.num().degree() >= dev.den().degree()) throw InputError("model.plant: the device is not strictly proper");
  const P N = dev.num() * P(rational(1) / dev.den().leading());
  const P den = dev.den() * P(rational(1) / dev.den().leading());  // monic
  d.k = 0;
  while (d.k < den.degree() && den.coeff(d.k) == 0) ++d.k;  // den = s^k den1, den1(0) != 0
  if (d.k == den.degree()) {
    d.Nd = sampled_numerator(N, d.k, d.T);
    return d;
  }
  if (!one_pole || den.degree() - d.k > 2)
    throw InputError(std::string("model.plant: the device has ") + (den.degree() - d.k == 1 ? "a pole" : "poles") +
                     " off s = 0 (e^{pT} is transcendental): this checker handles " +
                     (one_pole ? "devices with at most two poles off s = 0 (a mass-damper, a spring)"
                               : "devices with every pole at s = 0 only"));
  if (den.degree() - d.k == 2) return spring_device(d, N, den);
  const rational p = -den.coeff(d.k) / den.coeff(d.k + 1);  // den = s^k (s - p)
  rational pk1(1);
  for (int i = 0; i <= d.k; ++i) pk1 *= p;
  d.pole = p;
  d.r = N(p) / pk1;
  std::vector<rational> sk1(static_cast<size_t>(d.k) + 2, rational(0));
  sk1.back() = d.r;
  const auto [Q, rem] = divmod(N - P(sk1), P{-p, rational(1)});
  if (!rem.is_zero()) throw InputError("model.plant: N - r s^(k+1) is not divisible by s - p (checker defect)");
  d.Ndp = sampled_numerator(Q, d.k, d.T);
  return d;
}

std::pair<P, P> loop_family_in_E(const LoopDevice& d, const P& A, const P& L) {
  if (!d.pole) throw InputError("loop_family_in_E: the device has no pole off s = 0 (checker defect)");
  std::vector<rational> zn(static_cast<size_t>(d.n) + 1, rational(0));
  zn.back() = 1;
  const P z{rational(0), rational(1)};
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(d.k));
  const P zLD = P(zn) * L * Dk;  // z^n L (z - 1)^k
  const P rD = Dk * P(d.r);
  return {z * zLD + A * (z * d.Ndp - rD), A * (rD - d.Ndp) - zLD};
}

std::pair<rational, rational> exp_enclosure(const rational& x, long bits) {
  flint::BallPrecision scope(bits);
  flint::Ball e(x);
  arb_exp(e.get(), e.get(), bits);
  const Enclosure<rational> b = e.bounds();
  return {b.lo, b.hi};
}

P loop_polynomial(const LoopDevice& d, const P& A, const P& L) {
  std::vector<rational> zn(static_cast<size_t>(d.n) + 1, rational(0));
  zn.back() = 1;
  const P Dk = P{rational(-1), rational(1)}.pow(static_cast<unsigned>(d.k));
  return P(zn) * L * Dk + A * d.Nd;
}

}  // namespace hapstab::check::detail
