// hapstab/sim/loop.hpp -- a sampled-data haptic loop, composed from the blocks a scene names.
//
// The loop (paper 001 Fig. 1, paper 002 Fig. 1, paper 000 Sec. VI with N degrees of freedom):
//
//   devices   continuous, force -> velocity (1/(m s + b) per DOF, or any strictly proper
//             MIMO state space); the position of DOF j is the integral of its velocity.
//   operators continuous impedances Z_O(s): velocity -> force; the force on the device is
//             -Z_O v (a passive Z_O absorbs energy). Each operator acts on a list of DOFs.
//   exogenous forces w (impulses, constant bias, profiles) act beside the operator; the
//             human port force is f_h = -Z_O v + w.
//   sampler   positions x(kT), optionally through an encoder of resolution Delta (the
//             controller sees Delta floor(x/Delta), or Delta round(x/Delta) half up); optional unilateral contact (paper 002's xi): the wall
//             occupies x > 0 and the environment sees the penetration max(0, x_j(kT)).
//   environment E(z) (an impedance, displacement -> force; paper 001's H(z)), optional
//             coupling V(z) (an admittance, force -> displacement, in parallel with the
//             device as in paper 000 (11)): x_e = xi(x) + V u,  u = -E x_e. The algebraic
//             loop through D_E, D_V is solved exactly: (I + D_E D_V) u = ...; singular -> error.
//   delay     the force u_k computed from the samples at kT is applied from kT + t_d on
//             (t_d = n T + f, 0 <= f < T: integer and fractional computation delay).
//   hold      zero-order hold; the continuous part is discretised exactly for the
//             piecewise-constant input, so there is no integration error between samples.
//
// Composition is exact (rational arithmetic): the continuous plant (devices + operators) and
// the discrete controller (contact-free part: E, V and the algebraic loop) come out as two
// state-space models, which sim/simulator.hpp discretises and runs.
//
// Implements: paper 000 (11); paper 001 Fig. 1; paper 002 Fig. 1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::sim {

/// A continuous device (force -> velocity), `dofs()` inputs = outputs. D must be 0.
struct DeviceBlock {
  std::string name;
  StateSpace<rational> G;              ///< continuous, force -> velocity
  std::optional<std::vector<rational>> mass;  ///< per DOF, when the device is a mass-damper (kinetic storage)
  Eigen::Index dofs() const { return G.inputs(); }
};

/// A continuous operator impedance Z_O(s) = mass_i s (per port, optional) + Z(s) (proper,
/// state space) acting on the listed DOFs (velocity -> force). The inertia term moves rigidly
/// with the device (paper 001's mass-spring operators); compose() solves the resulting
/// implicit derivative exactly.
struct OperatorBlock {
  std::string name;
  StateSpace<rational> Z;       ///< continuous, |ports| inputs and outputs (may have 0 states)
  std::vector<rational> mass;   ///< per port, >= 0; empty = no inertia
  std::vector<int> ports;       ///< global DOF indices
};

/// One exogenous force on DOF `dof`.
struct Impulse {
  int dof = 0;
  rational time = 0;       ///< applied at the sample instant round(time/T) (state jump B*I)
  rational magnitude = 0;  ///< N s
};
struct Bias {
  int dof = 0;
  rational force = 0;  ///< N, constant from `start` on (held like the actuator force)
  rational start = 0;
};
struct Profile {
  int dof = 0;
  std::vector<double> samples;  ///< force at t = kT (k = 0, 1, ...), held over [kT, (k+1)T); 0 after the end
};

/// An encoder on DOF `dof`: the sampled position is Delta floor(x/Delta) (an incremental
/// encoder's count), or Delta floor(x/Delta + 1/2) when `round`. Applied before the contact clip.
struct Quantizer {
  int dof = 0;
  rational step = 0;  ///< Delta > 0 (m)
  bool round = false;
};
/// Coulomb friction f_c >= 0 on DOF `dof`: -f_c sgn(v) while slipping, any force in [-f_c, f_c]
/// while stuck (v = 0); sim/coulomb.hpp. One-DOF loops whose other states rest when v = 0.
struct Coulomb {
  int dof = 0;
  rational force = 0;
};

struct LoopSpec {
  rational T = 0;                         ///< sample period (> 0)
  std::vector<DeviceBlock> devices;        ///< DOFs numbered in this order
  std::vector<OperatorBlock> operators;
  std::optional<StateSpace<rational>> environment;  ///< discrete, N x N, displacement -> force
  std::optional<StateSpace<rational>> coupling;     ///< discrete, N x N, force -> displacement
  std::vector<int> contact;               ///< DOFs with the unilateral wall (empty: none)
  rational delay = 0;                     ///< computation delay t_d >= 0 (seconds)
  std::vector<Impulse> impulses;
  std::vector<Bias> biases;
  std::vector<Profile> profiles;
  std::vector<rational> x0, v0;           ///< initial positions / velocities per DOF (optional)
  std::vector<Quantizer> quantizers;      ///< at most one per DOF
  std::vector<Coulomb> coulomb;           ///< at most one per DOF
  std::vector<int> passivity_controller;  ///< DOFs with Hannaford-Ryu's PO/PC at the actuator (sim/simulator.hpp)
  int dofs() const;
};

/// The composed loop, exactly.
///  plant: continuous, states s = [device states; positions; operator states];
///         inputs [u (N, actuator force from the controller); w (N, exogenous force)];
///         outputs [x (N positions); v (N velocities); f_h (N human-port forces)].
///  controller: discrete (T), input the sampled (contact-clipped) positions, output the
///         actuator force u (N). Absent environment: u = 0 (zeros, no states).
struct ComposedLoop {
  int N = 0;
  rational T = 0;
  StateSpace<rational> plant;
  StateSpace<rational> controller;
  std::vector<int> position_state;  ///< index in s of the position of DOF j
  std::vector<std::optional<rational>> mass;  ///< kinetic storage 1/2 m v^2 per DOF when known
};

/// Checks dimensions (naming the blocks) and composes. InputError on a device with D != 0,
/// a DOF index out of range, a non-square environment/coupling, a singular algebraic loop
/// det(I + D_E D_V) = 0, T <= 0 or a negative delay.
ComposedLoop compose(const LoopSpec& spec);

/// The connected components of the graph of a square A (i ~ k when A(i, k) != 0 or A(k, i) != 0),
/// each in increasing order, in order of their first index: A is block diagonal over them (up to
/// a permutation). The N DOFs of a loop whose blocks couple none of them fall apart into N.
std::vector<std::vector<Eigen::Index>> components(const Mat<rational>& A);

/// A physical mass-damper device 1/(m s + b) (m > 0, b >= 0), one DOF, kinetic storage 1/2 m v^2.
/// (Inline: the scene module builds these without linking the sim library.)
/// Operator Z_O(s) = m s + b + k/s on DOF `port` (mass, damper and spring; passive for
/// m, b, k >= 0): the spring is one state (its deflection), the mass is the inertia term.
inline DeviceBlock mass_damper(std::string name, const rational& m, const rational& b) {
  if (m <= 0) throw InputError(name + ": mass m must be > 0, got " + m.str());
  if (b < 0) throw InputError(name + ": damping b must be >= 0, got " + b.str());
  DeviceBlock d;
  d.name = std::move(name);
  d.G = StateSpace<rational>{Mat<rational>::Constant(1, 1, -b / m), Mat<rational>::Constant(1, 1, 1 / m), Mat<rational>::Constant(1, 1, rational(1)),
                      Mat<rational>::Zero(1, 1), 0};
  d.mass = std::vector<rational>{m};
  return d;
}

inline OperatorBlock mass_spring_damper_operator(std::string name, int port, const rational& m, const rational& b,
                                          const rational& k) {
  if (m < 0 || b < 0 || k < 0)
    throw InputError(name + ": operator m, b, k must be >= 0 (a passive mass-spring-damper)");
  OperatorBlock o;
  o.name = std::move(name);
  o.ports = {port};
  o.mass = {m};
  if (k != 0) {  // f = b v + k q, q' = v
    o.Z = StateSpace<rational>{Mat<rational>::Zero(1, 1), Mat<rational>::Constant(1, 1, rational(1)), Mat<rational>::Constant(1, 1, k), Mat<rational>::Constant(1, 1, b), 0};
  } else {
    o.Z = StateSpace<rational>{Mat<rational>(0, 0), Mat<rational>(0, 1), Mat<rational>(1, 0), Mat<rational>::Constant(1, 1, b), 0};
  }
  return o;
}

}  // namespace hapstab::sim
