// hapstab/multidof/loop_as_written.hpp -- the scene's own loop, decided where it can be.
//
// Theorem 5 concludes stability "for every coupling V whose V-hat^Gamma is Delta_V-OSP with
// Delta_V >= Gamma^-1 Q_V Gamma^-1": a statement about a family of loops. The scene writes one
// loop: its devices, operators, environment, [delay] and its [coupling] (or none). That loop is
// decided as follows, and left undecided (null) with the reason otherwise:
//
//  1. With a [coupling] V and no delay, Theorem 4 for that V (check_theorem4: V-hat^Gamma's OSP
//     level, E-hat^Gamma's ISP level and (14) in one LMI program, exact re-check) proves the
//     loop stable when Assumption 1 holds. It is sufficient only: when it does not conclude,
//     step 2 decides. (With a delay the scene's V is fed the computed force and the devices the
//     delayed one (sim/loop.hpp), a loop Theorem 4 with z^-n E does not describe: step 2 only.)
//  2. A one-DOF loop (one device, at most one operator) is the loop of `hapstab stability`
//     (stability/sampled_loop.hpp): device P(s) = G(s)/s behind a ZOH, operator Z_op(s) =
//     m_op s + Z(s), force -z^-n H(z) x(kT) with H = E (no coupling) or H = E/(1 + E V) (the
//     coupling in the algebraic loop of the controller, as the simulator composes it). Its
//     exact/certified Schur test decides stable or not stable. Modes the reduction E/(1 + E V)
//     cancels are roots of (d_E d_V + n_E n_V)/den H, checked exactly by Schur-Cohn (an unstable
//     hidden mode makes the loop unstable whatever the rest does).
//  Loops with [contact], an encoder, Coulomb friction or a passivity controller are not linear:
//  neither step models them (null, naming `hapstab simulate`).
#pragma once

#include <optional>
#include <string>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/multidof/scene_multidof.hpp"

namespace hapstab::multidof {

struct LoopAsWritten {
  std::optional<bool> stable;       ///< nullopt: not decided (see why)
  Status status = Status::failed;   ///< exact or certified when decided
  std::string coupling;             ///< "none (the direct connection)" or the scene's [coupling]
  std::string method;               ///< "Theorem 4 with the scene's coupling", "exact Schur test", ""
  std::string why;                  ///< what was proven, or why nothing was
};

/// `assumptions_hold`: Assumption 1 holds for the scene (needed by step 1).
LoopAsWritten loop_as_written(const scene::Scene& sc, const SceneProblem& sp, bool assumptions_hold,
                              const lmi::Options& opt = {});

}  // namespace hapstab::multidof
