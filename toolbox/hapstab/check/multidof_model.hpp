// hapstab/check/multidof_model.hpp -- the model of the multi-DOF certificate kinds
// (check/multidof_witness_check.hpp, check/multidof_feasible_check.hpp) as the scene writes it:
// the environment E(z) entry by entry (in z, or in s by backward Euler / Tustin) -- or, for an `ss`
// environment, its realisation {A, B, C, D} as written, E = C (xI - A)^-1 B + D taken exactly by
// Faddeev-LeVerrier (lti/realization.hpp's ss2tf; x = z, or s discretised as above) --, its gain, the
// delay, the devices' OSP levels and the operators' DOFs, read from a certificate's model and
// evaluated exactly at Gaussian rational points z (check/gaussian_rational.hpp). With
// `perturb_C` = Pi (paper 000 Sec. VI: C_E := Pi C_E, D_E unchanged) the model is
// E'(z) = Pi (E(z) - E(inf)) + E(inf), whatever the realisation (C (zI - A)^-1 B = E - D).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"
#include "hapstab/check/gaussian_rational.hpp"
#include "hapstab/lti/tf.hpp"

namespace hapstab::check::multidof_model {

using detail::Parts;

constexpr size_t max_dofs = 512;
constexpr size_t max_ss_states = 64;  ///< an `ss` environment's states (Faddeev-LeVerrier: N^4 exact products)

struct Environment {
  char var = 'z';
  bool tustin = false;
  rational T, gain;
  long n = 0;
  std::vector<std::vector<TransferFunction>> E;  ///< m x m, as written (`ss`: its transfer matrix, exactly)
  std::vector<std::vector<rational>> perturb_C;  ///< Pi, m x m; empty: none
  std::vector<std::vector<rational>> D;          ///< E(inf) (D_E), when perturb_C is given
};

/// model.environment {domain, method, gain, E or ss} with model.set's parameters; InputError naming the field.
Environment read_environment(const nlohmann::json& model, const rational& T, long n);
/// A certificate claiming (16) infeasible: its model's fields known, claim.status "exact" and
/// claim.feasible a boolean (InputError otherwise); the refutation when it claims (16) feasible,
/// which `by` (a witness, the facial conditions) can only prove false; nullopt when it claims infeasible.
std::optional<std::string> infeasibility_claim(const Parts& p, const std::string& by);
/// E_ij(z) of an entry as written, exactly, or nullopt at a pole (its denominator as parsed vanishes).
/// An s-entry N(s)/D(s) is sum n_k sigma^k tau^(d-k) / sum d_k sigma^k tau^(d-k) at s = sigma/tau,
/// d = max degree (sigma = z - 1, tau = T z; Tustin 2(z - 1), T(z + 1)): exact at s = infinity too.
std::optional<Cq> entry_at(const Environment& e, const TransferFunction& H, const Cq& z);
/// The model's environment at z: E(z), or E'(z) = Pi (E(z) - E(inf)) + E(inf) with perturb_C;
/// nullopt at a pole of an entry.
std::optional<std::vector<std::vector<Cq>>> environment_at(const Environment& e, const Cq& z);
/// The largest degree of E's entries as rational functions of z (numerator or denominator), times
/// m with perturb_C (a row of Pi sums m entries of different denominators).
long environment_degree(const Environment& e);
/// E-hat(z) / E(z) = T z/(z - 1) z^-n g (paper 000 (11)); z on the unit circle, z != 1 (z^-n = conj(z)^n).
Cq ehat_factor(const Environment& e, const Cq& z);
/// delta_i per DOF from model.devices (a mass-damper's b, or the declared osp), in DOF order.
std::vector<rational> device_levels(const nlohmann::json& model, size_t m);
/// The operator of every DOF (each DOF in exactly one of model.operators).
std::vector<size_t> operator_of(const nlohmann::json& model, size_t m);

}  // namespace hapstab::check::multidof_model
