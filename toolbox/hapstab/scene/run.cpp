// hapstab/scene/run.cpp -- see run.hpp.
#include "hapstab/scene/run.hpp"

#include <algorithm>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/schema.hpp"

namespace hapstab::scene {

SceneRun prepare_run(const Scene& sc, const std::string& command) {
  check_command(sc.root, sc.file, command);  // what it does not model is refused (schema.hpp)
  if (!sc.simulate.present)
    throw InputError(sc.file + ": simulate: missing; add [simulate] with duration = \"...\" (seconds) or steps = N");
  SceneRun r;
  try {
    r.simulator = std::make_unique<sim::Simulator>(sc.loop);
  } catch (const InputError& e) {
    throw InputError(sc.file + ": " + e.what());
  }
  const auto& S = sc.simulate;
  sim::SimOptions& so = r.options;
  so.steps = S.steps;
  so.record_every = S.record_every;
  so.substeps = S.substeps;
  so.fine_from = S.window_from;
  so.fine_to = S.window_to;
  so.max_velocity = S.max_velocity;
  so.watch_dof = S.watch_dof;
  so.energy = S.energy;
  r.rows = S.record_every > 0 ? double(S.steps) / double(S.record_every) + 1 : 0;
  if (S.substeps > 1 && S.window_to >= S.window_from) {
    const double T = to_real<double>(sc.T);
    const double span = std::min(S.window_to, double(S.steps) * T) - S.window_from;
    r.fine_rows = std::max(0.0, span / T + 1) * S.substeps;
  }
  return r;
}

}  // namespace hapstab::scene
