// The loop of a one-DOF scene as a stability::Loop (stability/scene_loop.hpp).
#include "hapstab/stability/scene_loop.hpp"

#include "hapstab/stability/loop_as_written.hpp"

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::stability {

Loop scene_loop(const scene::Scene& sc) {
  const sim::LoopSpec& L = sc.loop;
  const std::string f = sc.file + ": ";
  if (L.dofs() != 1)
    throw InputError(f + "the scene has " + std::to_string(L.dofs()) +
                     " DOFs: `stability --scene --max` maximises a gain of one-DOF loops (without --max, `stability --scene` decides the loop of any number of DOF)");
  auto refuse = [&](bool present, const std::string& what, const std::string& why) {
    if (present) throw InputError(f + what + " is not modelled by the Schur test of the linear loop (" + why + ")");
  };
  refuse(!L.contact.empty(), "[contact]", "a unilateral wall; `hapstab wedge` or `simulate`");
  refuse(!L.quantizers.empty(), "[[device]] quantum", "an encoder; `simulate`");
  bool friction = false;
  for (const auto& c : L.coulomb) friction = friction || c.force > 0;
  refuse(friction, "[[device]] coulomb", "Coulomb friction; `simulate`");
  refuse(!L.passivity_controller.empty(), "[passivity_controller]", "a time-varying damper; `simulate`");
  refuse(L.coupling.has_value(), "[coupling]", "`hapstab multidof analyze` decides the loop with a coupling and checks "
                                               "the modes E/(1 + E V) cancels");
  if (!L.environment) throw InputError(f + "[environment] is required: the wall H(z) of the loop");
  try {
    return one_dof_loop(L);
  } catch (const InputError& e) {
    throw InputError(f + e.what());
  }
}

}  // namespace hapstab::stability
