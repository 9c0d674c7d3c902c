// hapstab/multidof/problem.cpp -- Theorem 5's problem (analysis.hpp): its validation, the size
// limit of the generic SDP, and the small conversions every path shares.
#include "hapstab/multidof/analysis.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "hapstab/multidof/detail.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::multidof {

using namespace detail;

Eigen::MatrixXd to_double(const MatQ& M) {
  MatrixXd D(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) D(i, j) = to_real<double>(M(i, j));
  return D;
}

Expr scalar_times(const Expr& se, const MatrixXd& M) {
  // M = sum_i col_i e_i^T  ->  s M = sum_i col_i * s * e_i^T
  Expr r = Expr::zero(static_cast<int>(M.rows()), static_cast<int>(M.cols()));
  for (Eigen::Index j = 0; j < M.cols(); ++j) {
    if (M.col(j).isZero(0.0)) continue;
    MatrixXd e = MatrixXd::Zero(1, M.cols());
    e(0, j) = 1;
    r += MatrixXd(M.col(j)) * se * e;
  }
  return r;
}

void Problem::validate(bool with_coupling) const {
  structure.validate();
  E.validate("environment E");
  if (!E.is_discrete()) throw InputError("environment E must be discrete (sample period T > 0)");
  if (E.inputs() != E.outputs())
    throw InputError("environment E is not square: " + std::to_string(E.outputs()) + " outputs, " +
                     std::to_string(E.inputs()) + " inputs (a square m x m E is required)");
  if (E.inputs() != structure.m())
    throw InputError("block sizes do not add up: the operators have sum m_i = " + std::to_string(structure.m()) +
                     " DOF but the environment E has m = " + std::to_string(E.inputs()));
  if (!schur_stable(E.A))
    throw InputError("environment E is not stable: A_E has an eigenvalue on or outside the unit circle "
                     "(exact Schur-Cohn test); Theorem 5 needs a stable E");
  if (with_coupling) coupling.validate(structure.m());
}


namespace detail {

MatrixXd gamma_inv_scale(const MatrixXd& Q, const MatrixXd& X) {
  MatrixXd Gi = MatrixXd::Zero(X.rows(), X.cols());
  for (Eigen::Index i = 0; i < X.rows(); ++i) Gi(i, i) = 1.0 / std::sqrt(X(i, i));
  return Gi * Q * Gi;
}

std::vector<double> gamma_sqrt(const Problem& pb, const MatrixXd& X) {
  std::vector<double> g;
  int off = 0;
  for (int s : pb.structure.operator_sizes()) {
    g.push_back(std::sqrt(X(off, off)));
    off += s;
  }
  return g;
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace detail

std::string detail::generic_size_exceeded(const Problem& pb, long extra_unknowns, const std::string& what) {
  const long n = static_cast<long>(pb.E.states());
  const double v = static_cast<double>(n) * (n + 1) / 2 + static_cast<double>(extra_unknowns);
  const double bytes = 8 * v * v;
  if (bytes <= limits::generic_sdp_bytes) return "";
  std::ostringstream o;
  o.precision(3);
  o << what << " for an environment realisation of order " << n
    << " (with any [delay] folded in) has about " << v << " scalar unknowns: its Schur complement would need "
    << bytes / 1e9 << " GB, more than the limit of " << limits::generic_sdp_bytes / 1e9
    << " GB. The structured KYP/Riccati path (tried first whenever the facial conditions pin X to one direction)"
       " avoids it; a shorter [delay] or a smaller environment fits";
  return o.str();
}

void check_generic_size(const Problem& pb, long extra_unknowns, const std::string& what) {
  const std::string why = generic_size_exceeded(pb, extra_unknowns, what);
  if (!why.empty()) throw InputError(why);
}

}  // namespace hapstab::multidof
