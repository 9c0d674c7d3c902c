// hapstab/sim/hidden_modes.hpp -- the modes each block of a loop hides, checked exactly on the
// realisations as the scene writes them (before anything is reduced).
//
// A mode of a block that its input cannot reach (uncontrollable) or its output cannot show
// (unobservable) is an eigenvalue of every loop the block is part of: no interconnection
// through the block's ports moves it. So the loop as written is internally unstable when any
// block hides a mode with
//   |z| >= 1   (discrete blocks: environment E(z), coupling V(z); exact Schur-Cohn), or
//   Re s >= 0  (continuous blocks: devices G(s), operators Z(s); exact Routh; after the
//               zero-order hold such a mode has |e^{sT}| >= 1),
// whatever a reduced model of the loop says -- and the sampled outputs may stay at rest (an
// uncontrollable mode with zero initial state). A hidden mode inside the stability region is
// harmless to stability and is reported once. So is a hidden mode exactly at z = 1 (s = 0) that is
// semisimple in the block's hidden parts (a device's own position state behind a velocity output):
// like the conserved quantities of sim/closed_loop.hpp it neither grows nor decays, and it is named so --
// the same physics written as m, b or as ss gets one verdict. Each mode is named by its block, its kind and a
// certified enclosure of where it is (poly/roots.hpp). lti::hidden_modes does the exact Kalman
// decompositions. The hidden parts are the uncontrollable quotient and the unobservable restriction,
// which no loop moves (lti::hidden_marginal_semisimple); a Jordan chain through the block's visible
// part -- a hidden constant into a PI wall's integrator -- is the loop's to break. (The whole A was
// tested before stop 88, and such loops, whose state settles, were "NOT stable [exact]".)
//
// Used by every command that decides the loop as written (`multidof analyze|design`,
// `stability --scene`, `simulate`), so that they agree.
// Implements: paper 000 Theorem 5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/realization.hpp"
#include "hapstab/poly/roots.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::sim {

struct HiddenMode {
  std::string block;  ///< "environment", "coupling", "device 'd_a'", "operator 'H1'"
  std::string kind;   ///< "uncontrollable" or "unobservable"
  bool discrete = true;
  RootEnclosure where;  ///< z (discrete) or s (continuous), certified; the one with Im > 0 of a pair
  bool pair = false;    ///< a complex pair: `where` and its conjugate
  bool stable = true;   ///< |z| < 1 or Re s < 0 (decided exactly for the block's hidden factor), or `settles`
  /// Exactly at z = 1 (s = 0) and semisimple in the block's hidden parts: it neither grows nor decays; driven
  /// by the loop's decaying signals (or by none) it settles to a constant. Counted as the plant's
  /// conserved quantities are (sim/closed_loop.hpp), wherever it is written, and named as such.
  bool settles = false;
  std::string text() const;  ///< "environment: unobservable mode z = 2 (|z| >= 1)"
};

struct LoopHiddenModes {
  std::vector<HiddenMode> modes;  ///< every hidden mode of every block
  /// The minimal realisations of the discrete blocks that hide modes (nullopt: nothing hidden
  /// there). The loop as written has the eigenvalues of the loop on these plus the hidden modes
  /// (Kalman form: block triangular), so with every hidden mode stable both are equally stable:
  /// stability::decide_loop builds its matrix on them (a tf environment of N DOF can hide ~2N).
  std::optional<StateSpace<rational>> environment_minimal, coupling_minimal;
  /// Not "" when the set-aside modes at z = 1 (s = 0) may chain through the loop (marginal_chain
  /// below): the verdict is then undecided, never stable. Says why.
  std::string undecided;
  bool stable() const;            ///< no hidden mode outside the stability region
  /// One line: "" when nothing is hidden; the unstable modes when any; else "stable hidden modes: ...".
  std::string summary() const;
};

/// The modes at z = 1 (s = 0) of a realisation, by Kalman part (algebraic multiplicities, exact):
///   injectors   -- no input reaches them, an output (or the reached part) sees them: a constant the
///                  loop must balance, which moves its equilibrium off 0;
///   integrators -- an input reaches them, no output shows them: they sum what the loop feeds them.
/// (Modes neither reached nor shown are neither.) A semisimple mode at 1 settles in a loop that
/// decays -- unless an injector's constant reaches an integrator through the loop: at the new
/// equilibrium the integrator's input is a constant, it grows linearly, and z = 1 is a Jordan block
/// of the loop as written although each block's A is semisimple there (issue 46's review: an
/// environment ss hiding a constant force beside a sum of positions). Only when both kinds are
/// present can that happen; hidden_modes() then sets LoopHiddenModes::undecided.
struct MarginalParts {
  long injectors = 0, integrators = 0;
};
MarginalParts marginal_parts(const StateSpace<rational>& s, const rational& at);

/// The hidden modes of one block (`name` as above), from its Kalman decompositions (lti).
/// `marginal_semisimple`: the block's A has its eigenvalue z = 1 (s = 0) semisimple (then a hidden
/// mode exactly there settles).
std::vector<HiddenMode> block_hidden_modes(const HiddenModes& decomposed, bool discrete, const std::string& name,
                                           bool marginal_semisimple = false);

/// Every block of the loop: devices, operators, environment, coupling. `environment`, when given,
/// is the environment's decomposition already computed (lti::hidden_modes of spec.environment).
LoopHiddenModes hidden_modes(const LoopSpec& spec, const HiddenModes* environment = nullptr);

}  // namespace hapstab::sim
