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
// device or operator, `count`, ss blocks, matrices, list parameters, [coupling], [contact],
// [passivity_controller], encoders, Coulomb friction, a fractional delay, an unknown section or
// key. Sections that do not enter the loop's stability ([[input]], [initial], [simulate],
// [reproduce], [multidof]) are ignored. The producer checks what it writes (cli/certificate.cpp),
// so a scene this reading refuses never gets a certificate.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace hapstab::check::detail {

/// `model` itself when it has no "scene" field; else the loop model {plant, H[, operator], set: {},
/// T, delay} (plus model.name, copied, when `free` is true: stability-max's K) of the scene in
/// model.scene with the values model.set. InputError naming the part of the scene that is
/// malformed or beyond this checker.
nlohmann::json scene_loop_model(const nlohmann::json& model, bool free = false);

}  // namespace hapstab::check::detail
