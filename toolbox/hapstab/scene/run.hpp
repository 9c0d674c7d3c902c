// hapstab/scene/run.hpp -- a scene's [simulate] section as a run of the exact-ZOH simulator:
// the simulator of the scene's loop and the options of its section, and the size of what the
// run records. The one preparation of `hapstab simulate` and of Python's hapstab.simulate.
#pragma once

#include <memory>
#include <string>

#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"

namespace hapstab::scene {

struct SceneRun {
  std::unique_ptr<sim::Simulator> simulator;
  sim::SimOptions options;  ///< from [simulate] (no progress callback)
  double rows = 0;          ///< sample rows the run records
  double fine_rows = 0;     ///< intersample rows (substeps > 1 inside the window)
};

/// Refuses what `command` does not model (check_command) and a scene without [simulate]; builds
/// the simulator (its InputError prefixed with the scene's file). InputError naming the scene.
SceneRun prepare_run(const Scene& sc, const std::string& command = "simulate");

}  // namespace hapstab::scene
