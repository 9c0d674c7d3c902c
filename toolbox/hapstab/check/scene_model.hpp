// hapstab/check/scene_model.hpp -- the one-DOF loop a scene writes, read by the checker itself
// from the scene's TOML text (issue 47: a certificate of `stability --scene` holds the scene as
// written, not what hapstab's scene loader made of it).
//
// A scene's one-DOF loop (docs/scene.md) is the loop of loop_model.hpp:
//   [[device]]    m, b        ->  plant P(s) = 1/(m s^2 + b s)        (force -> position, G(s)/s)
//                 tf = "G"    ->  plant P(s) = G(s)/s
//   [[operator]]  m, b, k     ->  Z_op(s) = m s + b + k/s
//                 tf = "Z", mass = [mo]  ->  Z_op(s) = Z(s) + mo s
//   [environment] tf = "E" in z, or in s with method = "backward_euler" (s = (z - 1)/(T z)) or
//                 "tustin" (s = 2 (z - 1)/(T (z + 1))); gain g  ->  H(z) = g E(z)
//   [delay]       time = t_d (n = t_d/T) or samples = n: a whole number n >= 0 of samples
//   [parameters]  each name replaced by its definition, in parentheses, wherever it is named (a
//                 `--set` value, model.set, replaces the definition); `free` (the parameter
//                 `stability --max` maximises) stays a name.
// What this reading does not model is refused by name (InputError: beyond this checker): a second
// device or operator (a count above 1 included), ss blocks, matrices, [coupling], [contact],
// [passivity_controller], encoders, Coulomb friction, a fractional delay, an unknown section or
// key. Sections that do not enter the loop's stability ([[input]], [initial], [simulate],
// [reproduce], [multidof]) are ignored. The producer checks what it writes (cli/certificate.cpp),
// so a scene this reading refuses never gets a certificate.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::check::detail {

/// A scene's loop of any number of DOF, as the `stability-loop` kind reads it (its own reading, as
/// above, for the multi-DOF loop; check/stability_loop_check.hpp builds the closed loop from it):
///   [[device]] m, b              one DOF each (device order), 1/(m s + b) force -> velocity
///   [[device]] ss or tf          a strictly proper block G(s) as written (tf: column by column), its
///                                DOFs the next inputs; an operator's mass on it is refused
///   [[operator]] m, b, k         on one DOF: adds m to its mass, b to its damping, k x to its force
///   [[operator]] tf = Z, mass    on its DOFs: a proper impedance matrix Z(s), velocity -> force (a
///                                spring as k/s too: its state and x are a conserved quantity, set
///                                aside by check/stability_loop_check.hpp), and a mass per port
///   [[operator]] ss, mass        the same impedance as a realisation as written (A n x n, B n x q,
///                                C q x n, D q x q over its q DOFs)
///   [environment] tf or ss       N x N (a string for one DOF) in z, or tf in s by backward
///                                Euler/Tustin; times gain (an ss block's C and D)
///   [coupling] tf or ss          V(z), force -> displacement, in parallel with the device (paper 000
///                                (11)): x_e = x + V u, u = -E x_e, the same keys as [environment]
///   [delay]                      t_d in [0, 1000 T], a fraction of a sample too
///   repeated blocks                (docs/scene.md) written out first as hapstab's reader does: [[device]]
///                                and [[operator]] with count = n (at most 64) as n copies NAME[k], "[i]" ->
///                                "[k]" in their strings; list parameters NAME = [..] or {repeat, times}:
///                                NAME[k] -> (v_k), sum(NAME) -> ((v_1) + ... + (v_n)); [environment] and
///                                [coupling] by diagonal / off_diagonal [/ blocks = K] as their N x N text
/// Refused by name: anything else ([contact], encoders, friction, ...).
struct SceneLoop {
  using Matrix = std::vector<std::vector<rational>>;
  /// A discrete N x N block: its transfer matrix, or its realisation as written (ss).
  struct Discrete {
    std::vector<std::vector<RationalFunction<rational>>> tf;  ///< N x N, in z, proper (discretised, times gain)
    bool is_ss = false;
    Matrix A, B, C, D;  ///< with is_ss (C and D times gain)
  };
  /// A device: a mass-damper (one DOF, its m and b in mass, damping), or a block (ss as written, or
  /// tf: the transfer matrix, realised by the checker) on `dofs` DOFs from `first`.
  struct Device {
    std::string name;  ///< the table's name ("" when it has none)
    size_t first = 0, dofs = 1;
    bool block = false;
    Matrix A, B, C;                                           ///< ss
    std::vector<std::vector<RationalFunction<rational>>> tf;  ///< tf (in s, strictly proper)
  };
  rational T;
  long delay = 0;        ///< t_d = (delay + fraction) T
  rational fraction = 0;  ///< in [0, 1)
  std::vector<Device> devices;
  /// per DOF: a mass-damper's m and b plus its m, b, k operators; a block DOF's operators' m (must
  /// be 0), b and k
  std::vector<rational> mass, damping, stiffness;
  struct Impedance {
    std::string name;                                         ///< the table's name ("" when it has none)
    std::vector<int> ports;                                   ///< DOF indices
    std::vector<std::vector<RationalFunction<rational>>> Z;  ///< tf: |ports| x |ports|, in s, proper
    bool is_ss = false;
    Matrix A, B, C, D;  ///< ss, as written
  };
  std::vector<Impedance> operators;  ///< the tf and ss operators
  Discrete E;                        ///< the environment
  std::optional<Discrete> V;         ///< the coupling
  /// conserved quantities the checker's own realisation adds, not the model: a `--plant` P without a
  /// pole at s = 0, realised as G = s P with its position integrated (x - P's output is constant)
  size_t own_conserved = 0;
  size_t dofs() const { return mass.size(); }
};

/// model.scene read as above (model.set overrides parameters; at most max_dofs DOFs, written out: 64, or the
/// 256 of stability-loop-symmetric, which reads N^2 entries but builds small loops); or, for a model without a scene, the
/// one-DOF loop of `stability --plant P --H H [--operator Z] --delay n` as written ({plant, H,
/// operator, set, T, delay}): one device block G = s P_eff, P_eff = P/(1 + s Z P), of relative degree
/// >= 2 (else beyond); without a pole of P_eff at s = 0, the integrated position carries one conserved
/// quantity of the checker's own (own_conserved = 1: on its quotient, position = P_eff's output, the
/// model as written). InputError naming what is malformed or beyond this reading.
SceneLoop read_scene_loop(const nlohmann::json& model, size_t max_dofs = 64);

/// `model` itself when it has no "scene" field; else the loop model {plant, H[, operator], set: {},
/// T, delay} (plus model.name, copied, when `free` is true: stability-max's K) of the scene in
/// model.scene with the values model.set. InputError naming the part of the scene that is
/// malformed or beyond this checker.
nlohmann::json scene_loop_model(const nlohmann::json& model, bool free = false);

/// The entries of the scene's [environment] or [coupling] (`block`) `tf` over `dofs` DOFs, each as
/// read_scene_loop reads it but as an expression in z with the parameter `free` left a name (the others
/// substituted, s discretised, times the gain): what check/affine.hpp proves affine in `free`
/// (stability_loop_max_check.hpp). InputError naming what is malformed or beyond (an ss block).
std::vector<std::vector<std::string>> block_entries(const nlohmann::json& model, const std::string& block, const std::string& free,
                                                    size_t dofs);

}  // namespace hapstab::check::detail
