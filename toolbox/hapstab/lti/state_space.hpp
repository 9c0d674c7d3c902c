// hapstab/lti/state_space.hpp -- state-space models x' = Ax + Bu, y = Cx + Du (continuous,
// T = 0) or x[k+1] = Ax[k] + Bu[k] (discrete, sample period T > 0), MIMO, over any scalar
// of the tower (double, mpfloat<D>, rational). The name `ss` follows python-control/MATLAB.
#pragma once

#include <Eigen/Core>
#include <string>

#include "hapstab/numeric/eigen_traits.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab {

template <class S>
using Mat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S>
using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;

template <class S>
struct StateSpace {
  Mat<S> A, B, C, D;
  rational T = 0;  ///< sample period; 0 means continuous time

  bool is_discrete() const { return T > 0; }
  Eigen::Index states() const { return A.rows(); }
  Eigen::Index inputs() const { return B.cols(); }
  Eigen::Index outputs() const { return C.rows(); }

  /// Throws InputError naming the block whose dimensions do not fit.
  void validate(const std::string& name = "state space") const {
    const auto n = A.rows();
    auto fail = [&](const std::string& what) { throw InputError(name + ": " + what); };
    if (A.cols() != n) fail("A must be square, got " + std::to_string(A.rows()) + "x" + std::to_string(A.cols()));
    if (B.rows() != n) fail("B must have " + std::to_string(n) + " rows (states), got " + std::to_string(B.rows()));
    if (C.cols() != n) fail("C must have " + std::to_string(n) + " columns (states), got " + std::to_string(C.cols()));
    if (D.rows() != C.rows() || D.cols() != B.cols())
      fail("D must be " + std::to_string(C.rows()) + "x" + std::to_string(B.cols()) + " (outputs x inputs), got " +
           std::to_string(D.rows()) + "x" + std::to_string(D.cols()));
    if (T < 0) fail("sample period T must be > 0 (or 0 for continuous time)");
  }

  template <class R>
  StateSpace<R> cast() const {
    return {A.template cast<R>(), B.template cast<R>(), C.template cast<R>(), D.template cast<R>(), T};
  }
};

template <class S>
StateSpace<S> ss(Mat<S> A, Mat<S> B, Mat<S> C, Mat<S> D, rational T = 0) {
  StateSpace<S> sys{std::move(A), std::move(B), std::move(C), std::move(D), T};
  sys.validate();
  return sys;
}

}  // namespace hapstab
