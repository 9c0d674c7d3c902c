// hapstab/check/loop_model.hpp -- the one-DOF sampled loop of `stability` and `stability-max`
// certificates as the checkers read it from the model (issue 19's loop; paper 001's device,
// zero-order hold, wall z^-n H(z)):
//   device  P_eff(s) = P/(1 + s Z_op P) = N(s)/s^k (every pole at s = 0: exact data only)
//   sample  P_d(z) = (1 - z^-1) Z{P_eff(s)/s} = Nd(z)/(z - 1)^k
//   loop    c(z) = z^n L(z) (z - 1)^k + A(z) Nd(z),   H = A/L                (nothing cancelled)
// Derivation of P_d (the checker's own; not the producer's Van Loan exponential): with
// P_eff/s = sum_i b_i / s^(k-i+1), the step response sampled at t = lT is
// y(l) = sum_i b_i (lT)^m / m!, m = k - i >= 1, and Z{l^m} = S_m(z) with S_0 = z/(z - 1),
// S_m = -z dS_{m-1}/dz (differentiating sum_l l^(m-1) z^-l); so P_d = ((z - 1)/z) sum_i b_i
// T^m/m! S_m(z), and Nd = P_d (z - 1)^k must be a polynomial (checked).
// Hypotheses verified: T > 0, n an integer in [0, 100000], the device strictly proper with every
// pole at s = 0 (else InputError: beyond the checkers).
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

struct LoopDevice {
  rational T = 1;                          ///< model.T > 0
  long n = 0;                              ///< model.delay, z^-n
  int k = 0;                               ///< P_eff = N(s)/s^k
  Polynomial<rational> Nd;                 ///< P_d = Nd/(z - 1)^k
  std::map<std::string, rational> params;  ///< model.set
};

/// model.T, model.delay, model.set, model.plant and model.operator (the device, above); InputError
/// naming the field that is missing, malformed or beyond the checkers (a pole off s = 0).
LoopDevice read_loop_device(const nlohmann::json& model);

/// model[key], an expression in `variable` ('s' or 'z') with sample period T and the parameters;
/// InputError naming model.KEY.
RationalFunction<rational> parse_model_field(const nlohmann::json& model, const char* key, char variable, const rational& T,
                                             const std::map<std::string, rational>& params);

/// c(z) = z^n L(z) (z - 1)^k + A(z) Nd(z) of the loop with the wall H = A/L.
Polynomial<rational> loop_polynomial(const LoopDevice& d, const Polynomial<rational>& A, const Polynomial<rational>& L);

}  // namespace hapstab::check::detail
