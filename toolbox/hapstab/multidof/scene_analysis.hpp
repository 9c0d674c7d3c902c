// hapstab/multidof/scene_analysis.hpp -- a scene studied by paper 000 from start to end: the one
// entry point of `hapstab multidof analyze|design` and of Python's hapstab.multidof.analyze|design
// (the command prints these results; Python returns them).
//
// analyze_scene, Theorem 5:
//   1. what `multidof analyze` does not model is refused by name (scene::check_command), then the
//      scene becomes a Problem (scene_multidof.hpp: E reduced, [delay] folded in, hidden modes);
//   2. the LMIs (16) with an exact certificate (analysis.hpp): first split by the permutations of
//      identical DOFs where the scene has them (symmetry.hpp: small blocks, their points lifted),
//      else, or where a block is not proven feasible, the whole program;
//   3. the premises (scene_premises): Assumption 1 on the reduced blocks, then the blocks' hidden
//      modes as written;
//   4. the scene's own loop decided as written (loop_as_written.hpp; step 2 of it needs 3).
//   Theorem 5 concludes stability only when (16) is certified feasible AND every premise holds;
//   ok() also needs the loop as written not proven unstable.
// design_scene, Theorem 6:
//   1. as above (`multidof design`); 2. the CCL design and its independent verification
//   (design.hpp); 3. the premises; 4. the loop with the designed V decided as written (certified:
//   appended to the verification; a refutation makes the design fail); 5. that loop simulated
//   from the scene's inputs (exact ZOH, numeric): a cross-check that can warn but never decides.
//   A contradiction -- the closed-loop decision refuting Theorem 6's certified conclusion, or a
//   simulation diverging where a certificate proves the loop stable -- is reported, never
//   resolved (the command exits 3).
// Both stop at the next interruption point when the caller's InterruptScope asks
// (numeric/interrupt.hpp: each LMI solve, each Riccati point, the simulation's progress).
// Implements: paper 000 Theorem 5, Theorem 6, Assumption 1.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/multidof/assumptions.hpp"
#include "hapstab/multidof/design.hpp"
#include "hapstab/multidof/loop_as_written.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"

namespace hapstab::multidof {

/// Assumption 1 on the reduced blocks (check_assumptions), then the premises the realisations as
/// written must meet (hidden_mode_premises). Theorems 5 and 6 conclude only when every line holds.
std::vector<AssumptionCheck> scene_premises(const SceneProblem& sp);

/// "" when every premise holds; else the first that does not, in words: "Assumption 1 fails
/// (NAME)", "a premise is undecided (NAME)".
std::string premise_failure(const std::vector<AssumptionCheck>& premises);

/// The [delay] in words ("[delay] 2 sample period(s): E := z^-2 E (...)"), for a scene with one.
std::string delay_text(const SceneProblem& sp);

/// Called as each stage of analyze_scene / design_scene starts, with its name (the command's
/// progress on stderr, cli/progress.hpp); empty: nothing is called.
using StageHook = std::function<void(const std::string&)>;

struct SceneAnalysisOptions {
  lmi::Options lmi;
  double load_seconds = 0;  ///< time the caller spent reading the scene: counted in realisation and total
  StageHook stage;
  bool symmetry = true;     ///< split (16) by the permutations of identical DOFs (symmetry.hpp); false: the whole program
};

struct SceneAnalysis {
  SceneProblem scene;                     ///< the scene as paper 000's problem
  AnalysisResult lmis;                    ///< Theorem 5's LMIs (16), their point and certificate
  std::vector<AssumptionCheck> premises;  ///< scene_premises
  LoopAsWritten loop;                     ///< the scene's own loop (its coupling or none), decided
  bool feasible = false;                  ///< (16) feasible
  bool certified = false;                 ///< (16)'s verdict proven exactly (feasible or infeasible)
  bool premises_hold = false;
  bool stability_concluded = false;       ///< feasible, certified and premises_hold: Theorem 5 concludes
  struct Seconds {
    double realisation = 0, assumptions = 0, loop_as_written = 0, total = 0;  ///< wall time; (16)'s own in lmis
  } seconds;
  /// "feasible", "infeasible" or "undecided" (lmi::Feasibility).
  std::string verdict() const;
  bool as_written_unstable() const { return loop.stable && !*loop.stable; }
  /// Stability concluded and the loop as written not proven unstable (the command's exit 0).
  bool ok() const { return stability_concluded && !as_written_unstable(); }
  /// Whether Theorem 5 concludes is not known -- no premise fails, and (16) is proven neither
  /// feasible nor infeasible, or proven feasible with a premise undecided -- and the loop as written
  /// is not proven unstable (the command's exit 3: an undecided answer is never counted as "no
  /// conclusion").
  bool undecided() const;
};

/// Step 2 alone: (16) by the symmetric split when `symmetry` and it decides, else the whole
/// program; the plan's first step says which and why.
AnalysisResult analyze_scene_lmis(const SceneProblem& sp, const lmi::Options& opt, bool symmetry = true);

/// Theorem 5 on a scene (see the header). InputError for what the scene does not model or an
/// inconsistent scene (scene_multidof.hpp), naming the scene.
SceneAnalysis analyze_scene(const scene::Scene& sc, const SceneAnalysisOptions& opt = {});

struct SceneDesignOptions {
  DesignOptions design;   ///< CCL iterations (1..10000), back-end
  double duration = 10;   ///< seconds simulated for the cross-check, in (0, 1e6]
  bool symmetry = true;   ///< split by the permutations of identical DOFs where the scene has them (design_by_symmetry)
  StageHook stage;
};

/// "velocities -> 0" of a simulation: the last second's largest |v| below 1e-3 of the run's peak
/// (or 1e-9 absolute), and not diverged; `text` the numbers.
struct Decay {
  bool decays = false;
  std::string text;
};

struct SceneDesign {
  SceneProblem scene;
  DesignResult design;                    ///< V, the CCL run and its verification, with steps 4-5 appended
  std::vector<AssumptionCheck> premises;  ///< scene_premises
  std::string premise_failure;            ///< "" when every premise holds
  bool feasible = false;    ///< a V passed every check and the loop with it is not proven unstable
  bool certified = false;   ///< ... with the design's exact certificates
  std::optional<LoopAsWritten> loop_with_v;  ///< the loop with the designed V, decided (when a V exists)
  std::optional<Decay> simulation;           ///< the cross-check (when a V exists)
  std::string warning;        ///< the simulation's numeric observation against the verdict, or ""
  std::string contradiction;  ///< a simulation or decision against a certificate, or ""
  bool has_v() const { return design.V.D.rows() > 0; }
  /// A verified V, every premise holding, no contradiction (the command's exit 0).
  bool ok() const { return contradiction.empty() && feasible && premise_failure.empty(); }
  /// A verified V whose conclusion waits only on premises that are undecided, none failing (the
  /// command's exit 3, not 1: an undecided premise is not a failed one).
  bool undecided() const;
};

/// Theorem 6 on a scene (see the header). InputError as analyze_scene, and for iterations or
/// duration out of range.
SceneDesign design_scene(const scene::Scene& sc, const SceneDesignOptions& opt = {});

/// The loop Theorem 6 designs V for, as the scene writes its blocks: the environment as written
/// (perturb_C applied) with the [delay] folded in as z^-n E (V is fed the applied force), and V
/// (none if V is null) in parallel with the devices.
sim::LoopSpec loop_with_coupling(const SceneProblem& sp, const StateSpace<rational>* V);

/// That loop simulated for `duration` seconds from the scene's inputs and initial state (exact
/// ZOH, no energies; stops at |v| > 1e6); an interruption point at each progress call.
sim::SimResult simulate_with_coupling(const SceneProblem& sp, const StateSpace<rational>* V, double duration);

/// Did the simulated velocities decay (Decay)? T is the sample period.
Decay velocities_decay(const sim::SimResult& r, double T);

}  // namespace hapstab::multidof
