// hapstab/scene/scene.hpp -- scene files (TOML) -> models. A scene names only the blocks a
// study needs; every section and key it may hold is declared once in scene/schema.hpp (docs/
// scene.md is generated from it), and anything else, at any depth, is refused with its line.
// This module reads the common part (T, parameters, devices, operators, environment, coupling,
// contact, delay, inputs, initial state) and the [simulate] section; other analyses read their
// own declared sections ([multidof], [reproduce]) from `root`, and each command refuses the
// parts of a scene it does not model (scene::check_command).
//
// Every error is an InputError naming the file, the key and what is wrong, e.g.
//   "wall.toml: operator[0].tf: unstable continuous block claimed passive (pole at s = 3)".
// Numbers are exact: "0.001" or "1/1000" (strings) or TOML integers; TOML floats are refused
// where an exact value matters (they are binary approximations).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <toml++/toml.h>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::scene {

/// The [simulate] section (all optional but one of duration/steps).
struct SimulateSection {
  long steps = 0;               ///< from `steps` or `duration`/T (rounded up)
  long record_every = 1;
  int substeps = 1;
  double window_from = 0, window_to = -1;
  double max_velocity = 1e4;
  int watch_dof = -1;
  bool energy = true;
  std::vector<std::string> plots = {"position", "velocity", "energy"};
  bool present = false;
};

struct Scene {
  std::string file;  ///< for messages
  std::string name, description;
  rational T = 0;
  std::map<std::string, rational> parameters;
  std::map<std::string, std::vector<rational>> lists;  ///< list parameters (docs/scene.md, "Repeated blocks")
  sim::LoopSpec loop;
  SimulateSection simulate;
  toml::table root;  ///< the whole file (checked against the schema), for sections other modules read
};

/// The [environment]'s entries as expressions of T and the scalar parameters, exactly what the
/// reader realised: `tf` as written, or diagonal / off_diagonal written out entry by entry, each
/// list parameter's NAME[k] and sum(NAME) replaced by its exact value; nullopt for an `ss`
/// environment or none. (A certificate's model holds them: cli/multidof_certificate.cpp.)
std::optional<std::vector<std::vector<std::string>>> environment_expressions(const Scene& sc);
/// [environment]'s `ss = {A, B, C, D}` as written (parameters evaluated, before its gain; in the
/// domain's variable: a continuous realisation for domain = "s"), or nullopt when E is written as tf
/// or as a compact matrix (environment_expressions).
std::optional<StateSpace<rational>> environment_ss_as_written(const Scene& sc);

/// Parses and validates a scene file. `overrides` replace [parameters] (CLI --set).
Scene load_scene(const std::string& path, const std::map<std::string, rational>& overrides = {});
/// Same from text (`file` names it in messages).
Scene parse_scene(const std::string& text, const std::string& file,
                  const std::map<std::string, rational>& overrides = {},
                  const std::string& base_dir = ".");

}  // namespace hapstab::scene
