// cli/scenes.hpp -- the example scenes in `hapstab reproduce`. Every examples/*.toml runs with the
// commands its sections call for, as a user would run them:
//   [simulate]  ->  hapstab simulate --scene F --out DIR/scenes/STEM --json
//   [multidof]  ->  hapstab multidof analyze --scene F --json,  hapstab multidof design --scene F --json
// and the expectations of its [reproduce] table are checked against each command's JSON:
//   [reproduce]
//   paper = "001"                               # the report section it belongs to
//   claim = "below b* the interface generates energy"
//   simulate = { trend = "growing", energy_generated = "> 0" }   # per command: JSON key = expected
//   analyze = { feasible = true }               # booleans/strings/numbers compare equal, of the same
//   design = { feasible = true }                # type; "> x", ">= x", "< x", "<= x", "== x" compare
//                                               # numbers; "!= null" / "== null" (limit_cycle)
// Strict: the scene is checked against the schema first (an unknown expectation key is refused,
// scene/schema.hpp); every command a scene runs must have a non-empty expectation table; an
// expected key the command does not print, or a value of another type, is a failure.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hapstab::cli {

struct SceneRun {
  std::string file;      ///< examples/NAME.toml (file name only)
  std::string paper;     ///< [reproduce].paper, or "toolbox"
  std::string claim;     ///< [reproduce].claim, or the scene's name
  std::string command;   ///< "simulate", "multidof analyze", "multidof design" ("scene load": refused by the schema)
  std::string expected;  ///< "key = value; ..."
  std::string got;       ///< the same keys' values in the command's JSON
  bool ok = true;
  std::string error;     ///< why it failed (exit code, unreadable JSON, unmet expectation)
  double seconds = 0;
  std::string no_certificate;  ///< why its verdict has none (produce_scene_certificates), or ""
};

/// Runs every scene in examples_dir() (sorted by file name) of `paper` ("" = all); outputs go to
/// outdir/scenes/. Progress on stderr unless quiet. A scene whose file cannot be read is a failed run.
std::vector<SceneRun> run_scenes(const std::string& paper, const std::filesystem::path& outdir, bool quiet);

}  // namespace hapstab::cli
