// hapstab/lmi/certify.hpp -- one protocol from an LMI program to a hapstab::Verdict.
//
// certify_lmi(prog, opt) runs lmi::solve and states its answer in the project's vocabulary
// (numeric/result.hpp): feasible -> holds, infeasible -> fails, undecided -> undecided; the
// status is exact when solve()'s own exact certificate passed (the rounded point satisfies every
// constraint in rational arithmetic, or the Farkas ray / inconsistent equalities were checked
// exactly), numeric otherwise. Callers that re-check the point on data the program only
// approximates (multidof's exact re-check on the rational (15), analysis.hpp) settle the
// verdict with recheck(): their exact check, with a positive margin, is then the proof.
#pragma once

#include <string>

#include "hapstab/lmi/solve.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::lmi {

/// feasible -> holds, infeasible -> fails, undecided -> undecided (and back).
Outcome outcome_of(Feasibility f);
Feasibility feasibility_of(Outcome o);

struct CertifiedSolve {
  SolveResult result;  ///< solve()'s result: solution access, status, margin, multipliers
  Verdict verdict;     ///< evidence: solver_text()
  double seconds = 0;  ///< wall time of solve()

  double margin() const { return result.margin; }
  /// True when the solver returned a point (feasible or not).
  bool has_point() const { return !result.x.empty(); }
  /// "<solver>: <feasibility>, certificate <kind>, margin <t>. <solver detail>"
  std::string solver_text() const;
  /// The value of `v` as a rational matrix: the certified point when solve()'s certificate
  /// passed, else the exact value of the solver's doubles.
  MatQ point(const MatrixVariable& v) const;
  /// The caller's own exact check of the point: passed with a positive margin -> holds,
  /// exact (the check is the proof); otherwise the solver's outcome, numeric. Evidence `why`.
  Verdict recheck(bool passed, std::string why) const;
};

/// lmi::solve(prog, opt) as a CertifiedSolve (see the header comment).
CertifiedSolve certify_lmi(const Program& prog, const Options& opt = {});

}  // namespace hapstab::lmi
