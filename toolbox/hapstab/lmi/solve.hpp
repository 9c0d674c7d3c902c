// hapstab/lmi/solve.hpp -- solve(prog) -> SolveResult, in the spirit of Drake's solvers::Solve.
//
// Pipeline: (1) linear equalities are eliminated EXACTLY (rational Gauss-Jordan on the
// doubles' exact values: x = x0 + N z), so a rounded z always satisfies them exactly;
// inconsistent equalities are an exact infeasibility certificate. (2) Linear inequalities
// become 1x1 blocks. (3) Equilibration (Options::scale, on by default): every block is scaled
// by a congruence D F D with D diagonal powers of two (row magnitudes ~ 1), every variable by a
// power of two (coefficients ~ 1). Powers of two are exact, congruence keeps definiteness, so
// the solver's verdict is unchanged in exact arithmetic while DSDP/CSDP see data of magnitude
// ~1 instead of 1e-6..1e6. The margin t and strict_threshold are measured in these
// equilibrated coordinates; SolveResult::min_eigenvalue gives the original ones.
// Equilibration is not always a gain: on homogeneous LMIs (Lyapunov, KYP) whose solution set
// is a cone, the margin t <= cap is reached by a scaled-up solution and the congruence changes
// which direction the margin measures; bench and tests showed cases where the raw data certify
// and the equilibrated do not, and the reverse. Scaling::automatic therefore tries both (raw
// first) and keeps the first decided verdict; SolveResult::detail says which one was used.
// (4) The built-in IPM first (kept only when certified), else DSDP or CSDP
// (backend.hpp). (5) Verdict and exact certificate (certificate.hpp).
//
// Verdict with the margin objective: feasible iff the solver is optimal and t* >
// strict_threshold; infeasible iff t* < -strict_threshold (or the solver reports
// infeasibility); otherwise undecided (|t*| <= threshold: strictness cannot be decided
// numerically -- typical of a non-strict LMI without interior, see facial_reduce).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lmi/program.hpp"

namespace hapstab::lmi {

enum class Scaling {
  automatic,  ///< the data as given first; equilibrated retry when the verdict is undecided or
              ///< the back-end had numerical trouble (the decided result is kept)
  never,
  always
};

struct Options {
  /// automatic: a program with at most `ipm_max_rows` LMI rows in all is first solved by the
  /// built-in IPM, and that result is returned only when its exact certificate passed (a
  /// rounded feasible point or a Farkas ray); anything else goes to DSDP (and the CSDP
  /// fallback), whose SolveResult::detail then records the IPM attempt. Needs certify; without it
  /// automatic is DSDP. dsdp / csdp / ipm: that back-end only.
  /// Measured (bench_lmi, bench_multidof): with the low-rank Schur complement the IPM is the
  /// fastest back-end at every size tried -- the 32-device contact scene 0.1 s / 1 s / 10 s
  /// for N = 8 / 16 / 32 against DSDP's 0.2 / 4.5 / 226 s -- so it goes first up to 2048 rows;
  /// a program whose dense Schur complement data would not fit declines at once (ipm.cpp).
  Backend backend = Backend::automatic;
  int ipm_max_rows = 2048;
  double strict_threshold = 1e-7;  ///< margin needed to call a strict LMI feasible
  Scaling scale = Scaling::automatic;  ///< equilibration (see above)
  /// DSDP stops with an indefinite Schur matrix (-8) or short steps on some KYP LMIs that CSDP
  /// solves: when the DSDP verdict is undecided or in numerical trouble, re-solve with CSDP
  /// (SolveResult::solver and detail say so). Off in the back-end agreement tests.
  bool fallback = true;
  bool certify = true;             ///< run the exact checks
  /// Seconds after which a CSDP call is stopped (reported as numerical trouble): CSDP's
  /// easy_sdp can loop without end on degenerate programs. 0 = automatic, 5 s + 20 ms per
  /// decision variable (CSDP needs 9 s for the 760-variable m = 32 bench program). DSDP and
  /// the IPM stop on their iteration limits.
  double csdp_time_limit = 0;
};

enum class Feasibility { feasible, infeasible, undecided };
const char* to_string(Feasibility f);

enum class Certificate {
  none,               ///< not requested, or the solver failed
  feasible_exact,     ///< rounded solution checked exactly: every constraint holds
  infeasible_exact,   ///< Farkas certificate (or inconsistent equalities) checked exactly
  rounding_failed,    ///< feasible numerically, but no rounding passed the exact check
  numeric_only        ///< infeasible numerically; no exact certificate could be checked
};
const char* to_string(Certificate c);

class SolveResult {
 public:
  SolveStatus status = SolveStatus::numerical_trouble;
  Feasibility verdict = Feasibility::undecided;
  Certificate certificate = Certificate::none;
  std::string solver;              ///< "DSDP" or "CSDP"
  std::string detail;              ///< solver's termination reason and certificate notes
  double margin = 0;               ///< t* (equilibrated), NaN when the program has no strict LMI
  double objective = 0;            ///< value of the linear objective (minimise) at x
  std::array<double, 6> dimacs{};  ///< DIMACS errors (equilibrated standard form)
  int iterations = 0;              ///< back-end iterations; -1 when not reported (CSDP)
  int rounding_bits = 0;           ///< bits of the dyadic rounding that passed (53 = exact double)
  std::vector<double> x;           ///< all scalar variables
  std::vector<rational> x_exact;   ///< the certified point (when certificate == feasible_exact)
  std::vector<double> min_eigenvalue;       ///< per LMI, at x, original coordinates
  std::vector<Eigen::MatrixXd> multipliers; ///< per posed LMI block (reduced coordinates)

  bool is_success() const { return status == SolveStatus::optimal && verdict == Feasibility::feasible; }
  bool certified() const { return certificate == Certificate::feasible_exact; }
  Eigen::MatrixXd solution(const MatrixVariable& v) const;
  MatQ exact_solution(const MatrixVariable& v) const;  ///< throws unless certified()
  double solution(int scalar) const { return x.at(static_cast<size_t>(scalar)); }
};

SolveResult solve(const Program& prog, const Options& opt = {});

}  // namespace hapstab::lmi
