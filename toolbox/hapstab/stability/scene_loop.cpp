// The loop of a one-DOF scene as a stability::Loop (stability/scene_loop.hpp).
#include "hapstab/stability/scene_loop.hpp"

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
                     " DOFs: `stability --scene` decides one-DOF loops (the multi-DOF loop as written: `hapstab multidof analyze`)");
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
  Loop loop;
  loop.T = sc.T;
  const rational n = L.delay / sc.T;
  if (den(n) != 1)
    throw InputError(f + "[delay]: t_d/T = " + to_decimal(n, 12) +
                     " is not a whole number of samples (the Schur test takes the integer delay z^-n)");
  if (n > limits::criterion_delay)
    throw InputError(f + "[delay]: " + to_decimal(n, 12) + " samples, more than the limit of " +
                     std::to_string(limits::criterion_delay) + " (numeric/limits.hpp)");
  loop.delay = static_cast<int>(num(n).convert_to<long>());
  const Polynomial<rational> s_poly(std::vector<rational>{rational(0), rational(1)});
  const TransferFunction g = ss2tf(L.devices[0].G)(0, 0);  // force -> velocity
  loop.plant = tf(g.num(), g.den() * s_poly, 0);            // force -> position
  if (!L.operators.empty()) {
    const auto& op = L.operators[0];
    TransferFunction z = ss2tf(op.Z)(0, 0);
    if (!op.mass.empty() && op.mass[0] != 0) z = parallel(z, tf(op.mass[0] * s_poly, Polynomial<rational>(rational(1)), 0));
    loop.operator_impedance = z;
  }
  loop.H = ss2tf(*L.environment)(0, 0);
  return loop;
}

}  // namespace hapstab::stability
