// hapstab/stability/loop_as_written.hpp -- Schur stability of a scene's loop exactly as it is
// written (sim/loop.hpp: devices, operators, environment, coupling, delay), for any number of
// DOF: the one decider behind `hapstab stability --scene`, the `loop_as_written` of `hapstab
// multidof analyze|design`, and the internal-stability line of `hapstab simulate`.
//
//  1. Hidden modes (sim/hidden_modes.hpp): a block that hides a mode outside the stability
//     region makes the loop NOT stable [exact], the mode named -- whatever the rest does.
//  2. One-DOF loops (one device of one DOF, at most one operator): the exact/certified test of
//     stability/sampled_loop.hpp on the transfer functions (device behind the ZOH, operator,
//     E or E/(1 + E V), z^-n); modes that E/(1 + E V) cancels are checked exactly. Its every
//     mode counts (the blocks' hidden modes are step 1).
//  2b. Identical DOFs (stability/symmetry.hpp): a loop invariant under the permutations of its
//     identical DOFs (proven exactly on the realisations) has the spectrum of the loop on the
//     fixed space and of one one-DOF loop per class: each is decided by these steps, and the loop
//     is stable iff every one is (Decider::automatic only).
//  3. Otherwise (and where step 2 refuses a size): the closed-loop matrix M of
//     sim/closed_loop.hpp from the realisations as written -- except that an environment or a
//     coupling whose hidden modes step 1 proved stable enters as its minimal realisation: M as
//     written is block triangular in Kalman coordinates, its spectrum is the reduced M's plus
//     those hidden modes, so both are equally stable (a transfer-matrix environment of N DOF
//     hides ~2N stable modes; the matrix is then ~30% smaller, the Stein solve ~3x cheaper). Exact M (all plant poles at s = 0)
//     of order <= kExactOrder: Schur-Cohn on det(zI - M), exact. Otherwise the Stein
//     certificate in ball arithmetic (numeric/ball_matrix.hpp): stable or NOT stable,
//     certified. Where it cannot decide, z = 1 is decided exactly (the DC equations,
//     closed_loop.hpp); else undecided, with the numeric spectral radius as the margin.
// Loops with contact, encoders, Coulomb friction or a passivity controller are not linear: not
// decided (`hapstab simulate` runs them).
// Implements: paper 000 Sec. VI; paper 001 Fig. 1.
#pragma once

#include <optional>
#include <string>

#include "hapstab/numeric/result.hpp"
#include "hapstab/sim/hidden_modes.hpp"
#include "hapstab/sim/loop.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::stability {

struct LoopVerdict {
  std::optional<bool> stable;  ///< nullopt: not decided (why says why, with the margin)
  Status status = Status::failed;  ///< exact or certified when decided
  std::string method;          ///< "hidden mode", "exact Schur test (one DOF)", "closed-loop matrix: ..."
  std::string path;            ///< the path that decided: hidden_modes, polynomial, long_delay, closed_loop_matrix; "" when none ran
  std::string why;             ///< what was proven, or why nothing was
  sim::LoopHiddenModes hidden; ///< every block's hidden modes (stable ones are not repeated in why)
  long states = 0;             ///< order of the closed loop (the matrix method), 0 otherwise
  std::optional<double> spectral_radius;  ///< numeric (double) spectral radius of the closed loop; nullopt when not computed (a hidden mode decided)
};

/// Exact M up to this order is decided by Schur-Cohn on det(zI - M); beyond, by balls.
inline constexpr long kExactOrder = 64;

/// automatic: as above, with the split by the permutations of identical DOFs (stability/symmetry.hpp)
/// before step 3; no_symmetry: without that split (`stability --scene --no-symmetry`); matrix:
/// step 3 even for one DOF (the campaigns and the tests compare them).
enum class Decider { automatic, no_symmetry, matrix };

/// `hidden`: the loop's hidden modes when the caller has them already (sim::hidden_modes(spec),
/// as `multidof analyze` computes them for its premises): step 1 takes them, not a second copy.
LoopVerdict decide_loop(const sim::LoopSpec& spec, Decider decider = Decider::automatic,
                        const sim::LoopHiddenModes* hidden = nullptr);

/// The one-DOF loop of sampled_loop.hpp from a loop spec (one device of one DOF, at most one
/// operator, an environment): device G(s)/s, operator Z(s) + m s, H = E (the caller puts a
/// coupling in), delay n = t_d/T (InputError unless whole). Shared with stability/scene_loop.
Loop one_dof_loop(const sim::LoopSpec& spec);

}  // namespace hapstab::stability
