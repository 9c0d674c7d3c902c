// hapstab/multidof/planner.hpp -- which numeric path finds Theorem 5's point, and one exact
// re-check that decides whichever path found it (the pattern of Drake's choose_best_solver:
// each path states its premises, one function tries them cheapest first).
//
// A path (SolvePath) has a name, its premises (checked on the problem before anything is
// solved: "X pinned to one direction by the facial conditions", "the generic SDP's Schur
// complement fits in memory") and a search that returns candidate points of (16), exact
// (rational), or a verdict it proves without a point (an infeasibility certificate). The planner
//   1. skips a path whose premises do not hold (recording the premise that fails),
//   2. re-checks each candidate point in exact arithmetic on the rational data (15)
//      (detail::exact_recheck: the only place a point becomes a proof); the first that passes
//      decides, and its path is named in the verdict,
//   3. moves on when a path finds no point, or its points fail the re-check (recording why, and
//      saying in the final verdict that the earlier path's point failed),
// and records every path's fate in AnalysisResult::plan. Where no path decides and the last path
// has a numeric verdict of its own (the SDP solver's, unchecked), that is the verdict, numeric;
// where a path was skipped only because the problem is beyond a size limit, the planner refuses
// the problem by that limit (InputError, exit 2).
//
// The default paths, cheapest first (analysis.hpp, AnalysisPath): the structured KYP/Riccati
// path (path_kyp.cpp: X pinned to one direction), the same with X searched over a d-dimensional
// facial set (path_kyp_search.cpp), the frequency-domain witness of infeasibility
// (path_witness.cpp), then the generic SDP (path_generic.cpp). The least dissipative coupling
// (least_dissipative.cpp) is planned the same way after a feasible verdict. Tests give the
// planner their own paths (e.g. a path whose point is spoiled, to drive the hand-over).
//
// The path choice of DESIGN.md ("Structure to exploit, cheapest first").
//
// Implements: paper 000 Theorem 5.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hapstab/multidof/analysis.hpp"
#include "hapstab/multidof/detail.hpp"

namespace hapstab::multidof {

using detail::ExactEnv;

/// A point of (16) a path found, for the planner's exact re-check.
struct CandidatePoint {
  ExactEnv env;
  MatQ QV;
  double margin = 0;          ///< reported as AnalysisResult::margin; a point decides only if > 0
  std::string construction;   ///< appended to the re-check's evidence when it passes
};

/// What the planner hands a path.
struct PathContext {
  const Problem& pb;
  const EhatSplit& split;
  const FacialConditions& facial;
  const lmi::Options& opt;
  AnalysisMode mode;
};

/// A path's premises: `why` says which one fails. `input_limit`: it fails only because the
/// problem is beyond a size limit (numeric/limits.hpp); if no other path decides, the planner
/// refuses the problem with `why` (InputError).
struct Premises {
  bool hold = true;
  std::string why;
  bool input_limit = false;
  static Premises met() { return {}; }
  static Premises unmet(std::string why, bool input_limit = false) { return {false, std::move(why), input_limit}; }
};

/// What a path's search returns.
struct PathResult {
  std::vector<CandidatePoint> points;   ///< re-checked in order; the first that passes decides
  std::optional<Verdict> proven;        ///< a verdict proven without a point (fails: Farkas, facial, witness)
  std::optional<Verdict> unchecked;     ///< the path's own verdict if no point passes (numeric: the solver's)
  std::optional<CandidatePoint> report; ///< the point reported with `unchecked` (the solver's, rounded)
  std::string solver_detail;            ///< the path's account (solver, Riccati solves, ...)
  std::string no_point;                 ///< why the search found nothing (no point, no proof)
  double margin = 0;                    ///< AnalysisResult::margin when no point decides
  double numeric_seconds = 0;           ///< spent in the numeric search (SDP solver, Riccati equations)
  std::optional<detail::Pinned> pinned; ///< the structure it used (X pinned), for the least dissipative step
  std::optional<FrequencyWitness> witness; ///< with `proven`: the exact witness it rests on (path_witness.cpp)
  std::optional<WeightedWitness> weighted_witness; ///< with `proven`: the several-frequency witness (path_kyp_search.cpp)
};

struct SolvePath {
  std::string name;  ///< "structured KYP/Riccati", "generic SDP"
  std::function<Premises(const PathContext&)> premises;
  std::function<PathResult(const PathContext&)> search;
};

/// The planner's loop for a study whose paths decide by themselves (Theorem 6's design,
/// design.cpp), the same rules as analyze_with's: paths cheapest first; a path whose premises
/// fail is skipped (its fate names the premise); a path that runs and decides ends the plan (the
/// later ones "not needed"); one that runs without deciding hands over, its result kept; every
/// fate goes to `plan`. Returns the deciding path's result, else the last result any path
/// produced (`decided_by` empty), else nullopt -- and then, when a path was skipped only for a
/// size limit, that limit is in `input_limit` (the caller refuses by it).
template <class R>
struct StudyPath {
  std::string name;
  std::function<Premises()> premises;
  /// nullopt: the path found nothing (`why` says so); else its result, `decided` when it decides
  std::function<std::optional<R>(std::string& why, bool& decided)> run;
};
template <class R>
std::optional<R> run_plan(const std::vector<StudyPath<R>>& paths, std::vector<PlanStep>& plan, std::string& decided_by,
                          std::string& input_limit) {
  std::optional<R> kept;
  for (const auto& p : paths) {
    if (!decided_by.empty()) {
      plan.push_back({p.name, "not needed", "the " + decided_by + " path decided"});
      continue;
    }
    const Premises pr = p.premises();
    if (!pr.hold) {
      plan.push_back({p.name, "skipped", pr.why});
      if (pr.input_limit && input_limit.empty()) input_limit = pr.why;
      continue;
    }
    std::string why;
    bool decided = false;
    std::optional<R> r = p.run(why, decided);
    if (r && decided) {
      plan.push_back({p.name, "decided", ""});
      decided_by = p.name;
      kept = std::move(r);
      continue;
    }
    plan.push_back({p.name, r ? "did not decide" : "no point", why});
    if (r) kept = std::move(r);
  }
  return kept;
}

/// The default paths for `path` (analysis.hpp), cheapest first.
std::vector<SolvePath> default_paths(AnalysisPath path = AnalysisPath::automatic);

/// Theorem 5 by the planner over `paths` (analyze() is this with default_paths); the least
/// dissipative step (full mode) is planned by least_dissipative.cpp.
AnalysisResult analyze_with(const Problem& pb, const std::vector<SolvePath>& paths, const lmi::Options& opt = {},
                            AnalysisMode mode = AnalysisMode::full);

/// The paths, each in its own file: the structured KYP/Riccati path (path_kyp.cpp;
/// `backend_premise`: in automatic planning a chosen SDP back-end is the user's choice of the
/// generic path; no premise on the number of DOF: the path is chosen by cost) and the generic
/// SDP (path_generic.cpp).
SolvePath kyp_riccati_path(bool backend_premise);

/// The premises both structured KYP paths share (Q_V not block diagonal; in automatic planning
/// no SDP back-end chosen): the first that fails, nullopt when both hold.
std::optional<Premises> riccati_premises(const PathContext& c, bool backend_premise);
/// The structured paths' candidate points at an exact X (path_kyp.cpp): P11 from the Riccati
/// equation of (16)'s first LMI with Q_E = Delta_D X (`d` = detail::kyp_data at X, Q_E = 0), then
/// Q_E = Delta_D X - eps I, Q_V = Q_E + Q_E^2/eps + eps I for two eps, for the exact re-check.
struct RiccatiPoints {
  std::vector<CandidatePoint> points;
  lmi::KypPoint kp;
  std::string no_point;  ///< why there is none
  double numeric_seconds = 0;
  std::optional<detail::Pinned> modal;  ///< set when the point was found in a scaled modal basis
  std::string basis_note;               ///< says so, for the path's account
};
RiccatiPoints riccati_points(const Problem& pb, const MatQ& X, const std::vector<rational>& theta,
                             const lmi::KypData& d);
SolvePath generic_sdp_path();
/// The structured KYP/Riccati path when the facial conditions leave X a d-dimensional set (d > 1):
/// an outer search over X = sum g_i X_i by the frequency-domain form of the KYP lemma, the
/// Riccati point at the X it chose (path_kyp_search.cpp).
SolvePath kyp_search_path(bool backend_premise);
/// Certified infeasibility by a frequency-domain witness (path_witness.cpp; premise: X pinned).
SolvePath frequency_witness_path();

}  // namespace hapstab::multidof
