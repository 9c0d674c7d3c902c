// hapstab/multidof/loop_as_written.hpp -- the scene's own loop, decided.
//
// Theorem 5 concludes stability "for every coupling V whose V-hat^Gamma is Delta_V-OSP with
// Delta_V >= Gamma^-1 Q_V Gamma^-1": a statement about a family of loops. The scene writes one
// loop: its devices, operators, environment (perturb_C applied), [delay] and its [coupling] (or
// none), each realisation as written. That loop is decided as follows:
//
//  1. A block that hides a mode outside the stability region: NOT stable [exact], the mode
//     named (sim/hidden_modes.hpp).
//  2. With a [coupling] V and no delay, when Assumption 1 holds: Theorem 4 for that V
//     (check_theorem4: V-hat^Gamma's OSP level, E-hat^Gamma's ISP level and (14) in one LMI
//     program, exact re-check) proves the loop stable. It is sufficient only: when it does not
//     conclude, step 3 decides. (With a delay the scene's V is fed the computed force and the
//     devices the delayed one (sim/loop.hpp), a loop Theorem 4 with z^-n E does not describe.)
//  3. stability::decide_loop (stability/loop_as_written.hpp), the decider `hapstab stability
//     --scene` and `hapstab simulate` use: the one-DOF exact test, or the closed-loop matrix of
//     any number of DOF with a certified Schur decision.
// Loops with [contact], an encoder, Coulomb friction or a passivity controller are not linear:
// not decided (null, naming `hapstab simulate`).
#pragma once

#include <optional>
#include <string>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/multidof/scene_multidof.hpp"
#include "hapstab/stability/loop_as_written.hpp"

namespace hapstab::multidof {

struct LoopAsWritten {
  std::optional<bool> stable;       ///< nullopt: not decided (see why)
  Status status = Status::failed;   ///< exact or certified when decided
  std::string coupling;             ///< "none (the direct connection)" or the scene's [coupling]
  std::string method;               ///< "hidden mode", "Theorem 4 with the scene's coupling", the decider's method
  std::string why;                  ///< what was proven, or why nothing was
  long states = 0;                  ///< order of the closed-loop matrix when that decided
  std::optional<double> spectral_radius;  ///< numeric; nullopt when not computed
  /// Theorem 4 with the scene's coupling proven infeasible by the two-frequency witness (step 2):
  /// the witness as decided (it does not decide the loop: Theorem 4 is sufficient only)
  std::optional<CouplingWitness> theorem4_witness;
};

/// `assumptions_hold`: Assumption 1 holds for the scene (needed by step 2).
LoopAsWritten loop_as_written(const SceneProblem& sp, bool assumptions_hold,
                              const lmi::Options& opt = {});

/// The same decider on any loop (design's loop with its V): stability::decide_loop, as a LoopAsWritten.
/// `hidden`: spec's hidden modes when known (the scene's, computed for the premises).
LoopAsWritten decided_loop(const sim::LoopSpec& spec, const std::string& coupling,
                           const sim::LoopHiddenModes* hidden = nullptr);

}  // namespace hapstab::multidof
