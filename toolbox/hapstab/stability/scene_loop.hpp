// hapstab/stability/scene_loop.hpp -- the loop of a one-DOF scene (scene/scene.hpp) as the
// stability::Loop of sampled_loop.hpp, for `hapstab stability --scene`: the [[device]] as
// force -> position P(s) = G(s)/s, the [[operator]] as the impedance Z(s) + m s on the device, the
// [environment] E(z) as the wall H(z), and [delay] as z^-n (n = t_d/T, any n up to
// limits::criterion_delay: the long-delay path takes what the polynomial path cannot).
//
// What the Schur test of a linear one-DOF loop cannot model is refused by name (InputError): a
// second DOF, [contact], an encoder (quantum), Coulomb friction, [passivity_controller], a
// [coupling] (multidof analyze checks the modes E/(1 + E V) cancels), a delay that is not a whole
// number of samples, a missing [environment].
#pragma once

#include <functional>

#include "hapstab/scene/scene.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::stability {

/// The loop of a one-DOF scene (H_gain empty; see the header for what is refused).
Loop scene_loop(const scene::Scene& sc);

/// The one-DOF scene's loop with NAME a gain of [environment] to maximise: H = H0 + NAME H1
/// (H_gain = H1), PROVEN: scene/parameter_degree.hpp bounds H's degree in NAME from the scene's
/// text, and H is checked equal to H0 + NAME H1 at that many values (at least 5: NAME = 0, 1, 2,
/// 1/3, -7/2, then 6/11, 7/13, ...). `scene_at(p)` loads the scene with NAME = p. InputError
/// (prefixed `prefix`, e.g. "--max K: ") when NAME moves the device, the operator or the delay, or
/// is not proven to enter H affinely.
Loop scene_loop_affine(const std::function<scene::Scene(const rational&)>& scene_at, const std::string& name,
                       const std::string& prefix);

}  // namespace hapstab::stability
