// hapstab/conservatism/example.hpp -- the scenes of the conservatism study (issue 42): a scene of
// paper 000's Sec. VI or a contact scene (multidof/example.hpp) with the paper's coupling (27)
// written into the loop, scaled to a stiffness kc, and its environment scaled by g:
//   [parameters] g = "1", kc = "1000";  [environment] gain = "g"  (E := g E);
//   [coupling] gain = "1/kc", ss = (27)  (V = V27 / kc: kc scales the coupling's stiffness).
// For 2 DOF the coupling is (27) itself; for N devices, (27)'s first block (d_a's) on each. A scene
// without [[input]] gets the force impulse of Sec. VI on d1 (the simulated witness needs one).
// Implements: paper 000 (27), Sec. VI.
#pragma once

#include <string>

namespace hapstab::conservatism {

/// The scene text `toml` (with [parameters], [environment] and [multidof] sections) of `dofs`
/// devices, with g, kc and the coupling V27 / kc as above. `paper27`: (27)'s two blocks (2 DOF).
std::string with_coupling27(std::string toml, int dofs, bool paper27);

}  // namespace hapstab::conservatism
