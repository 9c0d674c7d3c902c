// hapstab/contact/model.hpp -- H(z) of paper 002 from the physical model of its Fig. 1:
//
//     H(z) = E(z) (1 - z^-1) Z{ 1/(m s^3 + b s^2 + s^2 O(s)) }                   (Fig. 2)
//
// device mass m, damping b, sample period T, a passive operator impedance O(s) (force/velocity:
// a spring K/s, a damper B, a mass M s, or any positive-real rational) and the virtual wall E(z)
// (force/penetration). F(s) = 1/(s^2 (m s + b + O(s))) is split exactly over Q into its poles at
// s = 0, sum_i c_i/s^i (whose z-transforms are exact: z/(z-1), Tz/(z-1)^2, T^2 z(z+1)/(2(z-1)^3),
// T^3 z(z^2+4z+1)/(6(z-1)^4)), and a remainder R(s) = C (sI - A)^-1 B with no pole at 0, whose
// sampled impulse response gives Z{R} = z C (zI - e^{AT})^-1 B. e^{AT} is transcendental: it is
// computed in 100-digit arithmetic (lti/discretize.hpp expm), rounded to rationals of `digits`
// significant digits, and the rest is exact. So the poles at z = 1 are exact and every other
// coefficient carries a relative error of about 10^-digits (stated in `coefficient_error`).
// Walls: backward-difference and Tustin spring-dampers with a delay of d samples.
//
// Implements: paper 002 Fig. 1, Fig. 2.
#pragma once

#include <string>

#include "hapstab/lti/tf.hpp"

namespace hapstab::contact {

struct PhysicalModel {
  rational m = 1, b = 0, T = rational(1, 1000);
  TransferFunction O;  ///< operator impedance O(s) (continuous); zero for no operator
  TransferFunction E;  ///< virtual wall E(z) (discrete, sample period T)
};

struct ModelH {
  TransferFunction H;        ///< E(z) G(z), rational coefficients
  TransferFunction G;        ///< (1 - z^-1) Z{F}: the device + operator sampled through the ZOH
  double coefficient_error;  ///< bound on the relative error of the rounded coefficients
  std::string method;
};

/// H(z) of Fig. 2 for the model. InputError: m <= 0, T <= 0, O not continuous, E not discrete
/// with the same T, or a pole of F of order > 4 at s = 0.
ModelH model_H(const PhysicalModel& pm, int digits = 40);

/// O(s) = M s + B + K/s (any of them may be 0).
TransferFunction hand_impedance(const rational& K, const rational& B, const rational& M = 0);

enum class WallKind { backward_difference, tustin };
/// E(z) = (K + B D(z)) z^-delay, D(z) = (z-1)/(T z) (backward difference) or 2(z-1)/(T(z+1)) (Tustin).
TransferFunction virtual_wall(WallKind kind, const rational& K, const rational& B, const rational& T, int delay);

/// Direct check: simulates the continuous plant 1/(s (m s + b + O(s))) (force -> position) under a
/// piecewise-constant force with RK4 (`substeps` per sample) and compares the sampled position
/// with G(z); returns the max relative deviation over `samples` samples.
double zoh_check_by_simulation(const PhysicalModel& pm, const TransferFunction& G, int samples, int substeps);

}  // namespace hapstab::contact
