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

#include "hapstab/scene/scene.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::stability {

/// The loop of a one-DOF scene (H_gain empty; see the header for what is refused).
Loop scene_loop(const scene::Scene& sc);

}  // namespace hapstab::stability
