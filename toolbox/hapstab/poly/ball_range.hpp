// hapstab/poly/ball_range.hpp -- a certified enclosure of the range {f(u) : u in [lo, hi]} of a
// rational function f = N/D with rational coefficients, in Arb ball arithmetic: the
// coefficients become balls once (at the working precision), then each range is one ball
// Horner evaluation of N and D at the ball [lo, hi] and a ball division. The enclosure is as
// wide as interval Horner makes it (about |f'| (hi - lo) plus the dependency effect), plus
// rounding at `prec` bits; a point lo = hi gives a ball of rounding width, not an exact value.
// Used by the certified margins of the wedge criterion (contact/wedge.hpp), where it replaced
// 100-digit MPFI evaluation with rational coefficients converted on every call.
#pragma once

#include <memory>

#include "hapstab/numeric/result.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab {

class BallRationalFunction {
 public:
  /// f's coefficients as balls at `prec` bits (prec >= 16).
  BallRationalFunction(const RationalFunction<rational>& f, long prec);
  /// Rational bounds of f on [lo, hi] (lo <= hi), at `prec` bits (at most the constructor's
  /// precision is useful). Throws NumericalError when the enclosure of the denominator there
  /// contains 0 (a pole, or [lo, hi] too wide).
  Enclosure<rational> range(const rational& lo, const rational& hi, long prec) const;

 private:
  struct Balls;
  std::shared_ptr<const Balls> b_;
};

}  // namespace hapstab
