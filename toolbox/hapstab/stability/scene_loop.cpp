// The loop of a one-DOF scene as a stability::Loop (stability/scene_loop.hpp).
#include "hapstab/stability/scene_loop.hpp"

#include "hapstab/stability/loop_as_written.hpp"

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/scene/parameter_degree.hpp"

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

Loop scene_loop_affine(const std::function<scene::Scene(const rational&)>& scene_at, const std::string& name,
                       const std::string& prefix) {
  auto same = [](const TransferFunction& a, const TransferFunction& b) { return a.num() == b.num() && a.den() == b.den(); };
  const scene::Scene s0 = scene_at(rational(0));
  long points = 0;
  try {
    points = scene::points_needed_one_dof(scene::parameter_degree(s0, name));
  } catch (const InputError& e) {
    throw InputError(prefix + e.what());
  }
  Loop loop = scene_loop(s0);
  const Loop one = scene_loop(scene_at(rational(1)));
  const RationalFunction<rational> H1 = one.H.H - loop.H.H;
  if (H1.is_zero()) throw InputError(prefix + "the scene's [environment] does not depend on " + name);
  std::vector<rational> values{rational(2), rational(1, 3), rational(-7, 2)};  // with 0 and 1: 5 values
  for (long j = 5; j < points; ++j) values.push_back(rational(j + 1, 2 * j + 1));  // 6/11, 7/13, ...: distinct, in (1/2, 1)
  for (const rational& k : values) {
    const Loop lk = scene_loop(scene_at(k));
    const bool device_same = same(lk.plant, loop.plant) && lk.operator_impedance.has_value() == loop.operator_impedance.has_value() &&
                             (!lk.operator_impedance || same(*lk.operator_impedance, *loop.operator_impedance));
    if (!device_same || lk.delay != loop.delay)
      throw InputError(prefix + "only a gain of [environment] can be maximised, but " + name +
                       " changes the device, the operator or the delay");
    const RationalFunction<rational> affine = loop.H.H + RationalFunction<rational>(k) * H1;
    if (!same(lk.H, tf(affine.num(), affine.den(), loop.T)))
      throw InputError(prefix + "[environment] must be affine in " + name + " (H = H0 + " + name + " H1), e.g. a stiffness");
  }
  loop.H_gain = tf(H1.num(), H1.den(), loop.T);
  return loop;
}

}  // namespace hapstab::stability
