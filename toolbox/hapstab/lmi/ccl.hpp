// hapstab/lmi/ccl.hpp -- cone complementarity linearisation (El Ghaoui, Oustry, AitRami,
// IEEE TAC 42(8), 1997) for programs whose variables come in pairs constrained to be inverses,
// Y = Q^{-1} (paper 000, Theorem 6's (22): Sigma = Q_V^{-1}, Y = Q^{-1}).
//
// The pairs are relaxed to [[Y, I], [I, Q]] >= 0 (Y >= Q^{-1}); then tr(YQ) >= n with equality
// iff Y = Q^{-1}. Step k minimises the linearisation sum_pairs tr(Y_k Q + Y Q_k) subject to the
// program's LMIs and the relaxations; the value decreases to 2 sum n_i exactly when the pairs
// become inverse. Stop rules:
//   success  -- the objective reaches 2 sum n_i within `tol` (relative), or the user's
//               `accept` callback (e.g. "the closed loop is Schur", checked independently)
//               returns true;
//   failure  -- the objective stalls (relative decrease below `stall_tol` for `stall_iters`
//               consecutive steps) above the target, max_iter is reached, or a sub-problem
//               is infeasible / fails. A failure is never reported as success.
// Every step is recorded in the iteration log.
//
// Implements: paper 000 (22).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hapstab/lmi/program.hpp"
#include "hapstab/lmi/solve.hpp"

namespace hapstab::lmi {

struct InversePair {
  MatrixVariable Y, Q;  ///< both n x n symmetric variables of the program
};

struct CclOptions {
  int max_iter = 60;
  double tol = 1e-6;        ///< success when objective <= 2 sum n (1 + tol)
  double stall_tol = 1e-6;  ///< relative decrease counted as a stall
  int stall_iters = 6;
  Options solver;           ///< back-end and thresholds for each sub-problem
  /// Optional independent acceptance test, called after every step with its solution.
  std::function<bool(const SolveResult&)> accept;
};

struct CclStep {
  int k;
  double objective;     ///< sum tr(Y_k Q + Y Q_k) at the new point
  double trace_yq;      ///< sum tr(Y Q) at the new point (n at an exact inverse pair)
  std::string status;   ///< solver status of the sub-problem
};

struct CclResult {
  bool success = false;
  std::string reason;
  double target = 0;    ///< 2 sum n
  std::vector<CclStep> log;
  SolveResult last;          ///< the last sub-problem's result (the candidate solution)
};

/// Runs CCL on a copy of `prog` (its objective is replaced).
CclResult ccl_solve(const Program& prog, const std::vector<InversePair>& pairs, const CclOptions& opt = {});

/// tr(E) of a square expression.
Expr trace(const Expr& E);

}  // namespace hapstab::lmi
