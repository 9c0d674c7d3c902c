// hapstab/lmi/passivity_level_report.hpp -- the OSP/ISP level of a system as `hapstab
// passivity-level` and Python's hapstab.passivity_level report it: the three computations of
// passivity_level.hpp (Lemma 1/2 LMI, frequency grid, certified frequency level) on one model,
// and which of them is the result (the certified level where it is the level, else the LMI, else
// the grid), with the notes that explain the choice. One composition for both callers.
//
// Implements: paper 000 Definition 2, Lemma 1, Lemma 2.
#pragma once

#include <optional>
#include <string>

#include "hapstab/lmi/passivity_level.hpp"

namespace hapstab::lmi {

/// The model: the doubles the SDP and the grid work on, the exact SISO transfer function when
/// there is one (an expression), and the exact realisation as written (a state space given exactly).
struct LevelModel {
  StateSpace<double> sys;
  std::optional<RationalFunction<rational>> G;
  std::optional<StateSpace<rational>> exact;
};

/// Throws InputError (naming `name`) when sys has a pole with |z| > 1 - 1e-9: the levels of
/// Lemmas 1-2 are defined for Schur-stable systems.
void check_schur_stable(const StateSpace<double>& sys, const std::string& name);

struct Levels {
  PassivityLevel l, f, c;  ///< LMI, frequency grid, certified frequency level
  bool lmi_ok = false, freq_ok = false, cert_ok = false;
  bool cert_is_level = false;  ///< c is the level (ISP, or OSP with delta* > 0)
  bool only_bound = false;     ///< the result is c as an upper bound (OSP delta* <= 0, no LMI level)
  bool any = false;            ///< some method gave a level
  enum class Main { lmi, freq, cert } which = Main::freq;
  std::string note;
  const PassivityLevel& main() const { return which == Main::cert ? c : which == Main::lmi ? l : f; }
};

/// The three levels of `m` and the choice among them (header comment).
Levels passivity_levels(const LevelModel& m, PassivityKind kind, int lemma, Backend backend, int grid, int digits);

}  // namespace hapstab::lmi
