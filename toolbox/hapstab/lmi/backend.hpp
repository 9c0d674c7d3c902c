// hapstab/lmi/backend.hpp -- the SDP back-ends behind one interface: DSDP 5.8 (default),
// CSDP 6 (cross-check) and a built-in primal-dual IPM (ipm.cpp: DSDP
// and CSDP spend ~300 us of bookkeeping per iteration on a 43-variable program). All solve the
// standard form
//
//   maximise b^T y   subject to   S_j(y) = C_j + sum_k y_k A_jk  >= 0   (j = 1..J blocks)
//   dual:  minimise sum_j tr(C_j X_j)  s.t.  sum_j tr(A_jk X_j) = -b_k,  X_j >= 0,
//
// so y are the LMI's decision variables and X its multipliers. When the LMI is infeasible,
// X is a Farkas ray: X >= 0, sum_j tr(A_jk X_j) = 0, sum_j tr(C_j X_j) < 0.
//
// Both libraries are C code that is not thread-safe: every call is serialised by one process-
// wide mutex. DSDP keeps pointers into our arrays until DSDPDestroy (they live until then).
// CSDP's easy_sdp prints to stdout, reads ./param.csdp if one exists and calls exit() on some
// malformed input: we validate the data first, and run CSDP in a forked child process whose
// stdout is /dev/null and whose working directory is a fresh private folder ($TMPDIR or /tmp,
// created and removed by the parent) holding our own param.csdp (default parameters,
// printlevel 0), so neither a stray param.csdp nor an exit() can change results or end the
// caller. The DIMACS error measures are computed by us, from the
// returned (y, X), with the same formulas for both back-ends.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <mutex>
#include <string>
#include <vector>

#include "hapstab/lmi/program.hpp"

namespace hapstab::lmi {

/// automatic (solve()'s default): programs are first solved by the built-in IPM and
/// that answer is kept only when exactly certified; otherwise DSDP (then CSDP), as `dsdp`.
enum class Backend { automatic, dsdp, csdp, ipm };
const char* to_string(Backend b);
/// "auto", "dsdp", "csdp" or "ipm" (the CLI's --backend); throws InputError naming the choices.
Backend parse_backend(const std::string& name);

struct SdpTerm {
  int var;                          ///< index k of y_k
  Eigen::SparseMatrix<double> A;    ///< symmetric block coefficient, both triangles stored, no
                                    ///< explicit zeros (a Lyapunov term A^T E_ij A is dense, a
                                    ///< Q_E(i,j) entry has 2 non-zeros: storage follows the data)
  /// Optional: A = sum of s * basis.col(u) * basis.col(v)^T over these (program.hpp's LowRank).
  /// Empty = not known. The IPM checks it against A before it uses it; DSDP and CSDP ignore it.
  std::vector<Factor> factors = {};
};
struct SdpBlock {
  Eigen::MatrixXd C;   ///< symmetric constant
  std::vector<SdpTerm> terms;
  Eigen::MatrixXd basis = {};  ///< the columns the terms' factors index (may be empty)
};
struct StandardForm {
  int m = 0;                   ///< number of y variables
  Eigen::VectorXd b;           ///< objective (maximised)
  std::vector<SdpBlock> blocks;
};

enum class SolveStatus { optimal, infeasible, unbounded, numerical_trouble };
const char* to_string(SolveStatus s);

struct BackendResult {
  SolveStatus status = SolveStatus::numerical_trouble;
  std::string detail;          ///< solver's own termination code / reason, in words
  Eigen::VectorXd y;
  std::vector<Eigen::MatrixXd> X;  ///< multipliers (a Farkas ray when infeasible)
  double primal_objective = 0;     ///< b^T y
  double dual_objective = 0;       ///< sum tr(C X)
  std::array<double, 6> dimacs{};  ///< DIMACS err1..err6 (computed by hapstab from y, X)
  int iterations = 0;              ///< -1: not reported (CSDP's easy_sdp does not return it)
};

/// Checks sizes, symmetry and finiteness; throws InputError (never reaches the C code).
void validate(const StandardForm& sf);

BackendResult solve_dsdp(const StandardForm& sf);
/// CSDP in a forked child; the child is killed after `time_limit` seconds (easy_sdp can loop
/// forever on some degenerate programs), which is reported as numerical_trouble.
BackendResult solve_csdp(const StandardForm& sf, double time_limit = 30);
/// The words BackendResult::detail starts with when CSDP was stopped at its time limit.
inline constexpr const char* kCsdpTimedOut = "CSDP did not finish within its time limit";
/// The built-in primal-dual interior-point method (ipm.cpp): HKM direction, Mehrotra
/// predictor-corrector, infeasible start; the Schur complement from the terms' low-rank pieces
/// (SdpTerm::factors) where given, else dense (n^2 x m per block: a block whose dense data would
/// exceed 2^26 doubles declines at once with numerical_trouble); no infeasibility detection of its own (diverging iterates end in
/// numerical_trouble), so solve() trusts it only through an exact certificate (solve.hpp).
BackendResult solve_ipm(const StandardForm& sf);
/// `automatic` is resolved by solve() (solve.hpp); here it means DSDP.
inline BackendResult solve_standard(const StandardForm& sf, Backend b, double csdp_time_limit = 30) {
  return b == Backend::csdp ? solve_csdp(sf, csdp_time_limit) : b == Backend::ipm ? solve_ipm(sf) : solve_dsdp(sf);
}

/// DIMACS errors of (y, X) for the standard form above (S from y).
std::array<double, 6> dimacs_errors(const StandardForm& sf, const Eigen::VectorXd& y,
                                    const std::vector<Eigen::MatrixXd>& X);

/// The mutex that serialises every call into DSDP or CSDP.
std::mutex& sdp_mutex();

}  // namespace hapstab::lmi
