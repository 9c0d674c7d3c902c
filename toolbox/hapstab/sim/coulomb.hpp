// hapstab/sim/coulomb.hpp -- Coulomb friction with stiction inside the exact-ZOH simulator:
// slip/stick events located within each constant-input piece (one-DOF loops).
//
// Model. The device force is u + w-side forces + lambda, lambda = -f_c sgn(v) while slipping;
// at v = 0 the device sticks (lambda balances the rest) while the acceleration without
// friction a0 satisfies |a0| <= f_c g (g = dv'/du > 0, the inverse of the moving mass); else it
// breaks away in the direction of a0. The loop must be one DOF whose other states rest when
// v = 0 (a mass-damper device, operators of mass, damper and spring: position and spring
// deflections integrate v); then a stuck device stays stuck, state unchanged, until the held
// inputs change at the next piece boundary.
//
// Events. A piece of length h is walked in G = 16 sub-steps (exact ZOH for the constant force
// u + lambda, matrices from Eigen's double matrix exponential, ~1e-15 relative); when v changes
// sign inside a sub-step the zero is located by bisection to 1e-15 h, the state is propagated
// there, v set to 0 exactly, and stick/slip decided again. A pair of zeros of v inside one
// sub-step (h/16) is not seen: the loop's oscillations must be slower than 8/h (the
// simulator's figures and scenes are: the fastest, 001's operator tuned to wT = pi, has half a
// period per sample). Port energy int f_h v and actuator energy int u v are exact quadratic
// forms per chunk (Van Loan, double).
#pragma once

#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::sim {

class CoulombStepper {
 public:
  /// plant: the composed continuous plant (sim/loop.hpp: states s, inputs [u; w], outputs
  /// [x; v; f_h]) of a one-DOF loop; piece_lengths: the simulator's constant-input pieces.
  /// InputError naming the reason when the loop is not one DOF or its other states move at v = 0.
  CoulombStepper(const StateSpace<rational>& plant, const rational& fc, const std::vector<double>& piece_lengths);

  /// Advances s over a piece of length h with actuator force u and exogenous force w held;
  /// adds int f_h v dt to e_port and int u v dt to e_act. Returns the number of events (v
  /// reaching 0) in the piece.
  int advance(Vec<double>& s, double u, double w, double h, double& e_port, double& e_act) const;

  static constexpr int substeps = 16;

 private:
  struct Step {
    double h = 0;
    Mat<double> Phi, W;  ///< state transition; port-energy Gram of z = [s; F; w]
    Vec<double> gu, gw;  ///< input columns of the device force F and of w
  };
  Step step(double h) const;
  const Step& cached(double h) const;
  double velocity_after(const Vec<double>& s, double F, double w, double tau) const;
  void chunk(Vec<double>& s, const Step& st, double u, double F, double w, double& e_port, double& e_act) const;

  Mat<double> A_, B_, M_, Q_;
  Vec<double> cx_;
  int iv_ = 0;          ///< the velocity state
  double fc_ = 0, g_ = 0;
  std::vector<Step> cache_;  ///< sub-steps of the simulator's pieces
};

}  // namespace hapstab::sim
