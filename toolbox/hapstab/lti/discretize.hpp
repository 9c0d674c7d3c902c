// hapstab/lti/discretize.hpp -- c2d: continuous state space -> discrete, and the matrix
// exponentials the sampled-data simulator needs (sim/), over double and mpfloat<D>.
//
//   zoh             exact for piecewise-constant inputs (paper 001 Fig. 1's zero-order hold):
//                   Ad = e^{AT}, Bd = int_0^T e^{A s} ds B, both read off Van Loan's block
//                   exponential exp([[A, B], [0, 0]] T) = [[Ad, Bd], [0, I]];
//   tustin          s = (2/T)(z-1)/(z+1)   (paper 001 Sec. VI, the "ideal" Tustin wall);
//   backward_euler  s = (z-1)/(T z)        (paper 000's environment, paper 001's H(z) forms).
// Tustin and backward Euler are rational operations and also run exactly over `rational`.
//
// expm: scaling and squaring with a Taylor kernel whose truncation is controlled in the
// working precision (||X|| <= 1/2 after scaling; the tail after the k-th term is bounded by
// 2 ||X||^{k+1}/(k+1)! and stopped below eps/8), so the same code is accurate to a few
// hundred ulps in double and in mpfloat<D> (tests/lti/test_discretize.cpp states the
// tolerances). It is for set-up, not for hot loops.
//
// Implements: paper 001 Fig. 1.
#pragma once

#include <string>

#include "hapstab/lti/state_space.hpp"

namespace hapstab {

enum class C2dMethod { zoh, tustin, backward_euler };

/// "zoh", "tustin" (also "bilinear"), "backward_euler" (also "euler", "bd") -> method;
/// InputError naming `what` otherwise.
C2dMethod parse_c2d_method(const std::string& name, const std::string& what = "c2d method");

/// Matrix exponential e^{A} (A square). Real scalars only (double, mpfloat<D>).
template <class S>
Mat<S> expm(const Mat<S>& A);

/// The pair (e^{A t}, int_0^t e^{A s} ds B) for real t >= 0 (Van Loan's block exponential).
template <class S>
struct ZohPair {
  Mat<S> Phi, Gamma;
};
template <class S>
ZohPair<S> zoh_pair(const Mat<S>& A, const Mat<S>& B, const S& t);

/// Continuous `sys` (sys.T == 0) -> discrete model with sample period T > 0. zoh needs a
/// real scalar (double, mpfloat<D>); tustin and backward_euler also run over `rational`.
/// InputError if sys is already discrete, T <= 0, or I - A T/2 (tustin) / I - A T
/// (backward Euler) is singular (a pole at s = 2/T or 1/T).
template <class S>
StateSpace<S> c2d(const StateSpace<S>& sys, const rational& T, C2dMethod method = C2dMethod::zoh);

}  // namespace hapstab
