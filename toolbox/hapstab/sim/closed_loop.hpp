// hapstab/sim/closed_loop.hpp -- the sampled-data loop of sim/loop.hpp as one linear map per
// sample period, built from the realisations as the scene writes them (nothing reduced): the
// simulator's step (sim/simulator.hpp) written as a matrix.
//
// With the composed plant s' = A s + B_u u (+ B_w w), positions y = C_x s, the controller
// xi+ = A_c xi + B_c y, u = C_c xi + D_c y, and the delay t_d = n T + f (0 <= f < T): the force
// computed at kT acts on [kT + t_d, (k+1)T + t_d), so over the period [kT, (k+1)T) the plant sees
// u_{k-n-1} on [kT, kT + f) and u_{k-n} on [kT + f, (k+1)T). With Phi_h = e^{A h},
// Gamma_h = int_0^h e^{A t} dt B_u:
//   s_{k+1}  = Phi_T s_k + Phi_{T-f} Gamma_f u_{k-n-1} + Gamma_{T-f} u_{k-n}
//   xi_{k+1} = A_c xi_k + B_c C_x s_k,     u_k = C_c xi_k + D_c C_x s_k,
// and the state X_k = [s_k; xi_k; u_{k-1}; ...; u_{k-L}], L = n (+ 1 when f > 0): the forces still
// to act. So X_{k+1} = M X_k exactly, and the loop as written is (asymptotically) stable iff M is
// Schur stable. M holds exponentials of exact data, so it is enclosed (numeric/ball_expm.hpp,
// component by component of the plant as the simulator does) -- except when every component of
// A is nilpotent (the devices and operators have all their poles at s = 0: pure masses, springs),
// where e^{A h} is a finite sum and M is exact (rational).
//
// Conserved quantities. The composition integrates every velocity into a position (the sampler
// reads it) while an operator's spring integrates the same velocity into its deflection: their
// difference never changes, whatever force acts (a mode at s = 0 that no force reaches; the
// 2x2 hand of examples/000_two_dof_loop.toml has one). It is not a hidden mode of any block, and
// it neither grows nor decays: the loop settles to the equilibrium that difference selects. So the
// plant is first reduced, exactly, to the part the forces [u, w] reach (lti::controllable_split);
// then to the part the sampled positions show (the dual split: a device's own position state behind
// its velocity output); the removed modes are classified exactly: s = 0 semisimple (conserved
// quantities, reported), Re s < 0 (harmless), anything else makes the loop NOT stable; zeros in
// both removed parts are not decided (removed_undecided). M is built on the reduced plant.
//
// Contact, encoders, Coulomb friction and the passivity controller are not linear: the loop is
// then not one matrix and sampled_closed_loop refuses it (InputError naming the part).
// Implements: paper 000 (11), Sec. VI; paper 001 Fig. 1.
#pragma once

#include <optional>

#include "hapstab/numeric/ball_matrix.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::sim {

struct SampledClosedLoop {
  BallMatrix M;               ///< X_{k+1} = M X_k, enclosed
  MatQ jump;                  ///< X's jump for a unit impulse on each DOF (nx x N; the plant's B_w, reduced)
  MatQ positions;             ///< the sampled positions y_k = positions X_k (N x nx)
  std::optional<MatQ> exact;  ///< M exactly, when the plant's exponentials are rational
  Eigen::Index plant_states = 0, controller_states = 0, buffer_states = 0;
  /// G1 = [[A, 0, B_u], [B_c C_x, A_c - I, 0], [D_c C_x, C_c, -I]], exact: M has the eigenvalue
  /// z = 1 iff G1 is singular (an equilibrium s, xi, u of the loop with the force held constant:
  /// (Phi_T - I) s + Gamma_T u = J (A s + B_u u) with J = int_0^T e^{At} dt, whose eigenvalues
  /// (e^{lambda T} - 1)/lambda never vanish for rational A and T: lambda = 2 pi j k / T, k != 0, is
  /// transcendental). So z = 1 is decided exactly, where no enclosure can.
  MatQ dc;
  /// The plant modes no force reaches (removed before M is built): how many are conserved
  /// quantities (s = 0, semisimple), whether any is outside Re s < 0 otherwise (then the loop is
  /// NOT stable, exactly), and the account in words ("" when nothing was removed).
  long conserved = 0;
  bool removed_unstable = false;
  bool removed_undecided = false;  ///< zeros no force reaches AND zeros no output shows: not decided
  std::string removed;
  /// The exact data M is assembled from, for an enclosure at another precision or of a family
  /// M(p) (stability/loop_max.hpp): the reduced plant (A, B_u), the controller's rows
  /// u_k = Ku [s; xi], xi+ = Kx [s; xi], and the delay t_d = n T + f.
  MatQ A, Bu, Ku, Kx;
  long n = 0;
  rational f = 0, T = 0;
};

/// What in the loop is not linear time-invariant ("" when nothing): contact, encoders, Coulomb
/// friction, the passivity controller.
std::string nonlinear_parts(const LoopSpec& spec);

SampledClosedLoop sampled_closed_loop(const LoopSpec& spec);

/// (Phi, Gamma) of s' = A s + B in over h, enclosed component by component of A (the lemma of
/// sim/simulator.cpp: exact restriction), radii per entry (0 off the components' blocks). The
/// simulator's step matrices are these midpoints.
struct PlantZoh {
  BallMatrix Phi, Gamma;
};
PlantZoh plant_zoh(const MatQ& A, const MatQ& B, const rational& h);
/// The same exactly, when every component of A is nilpotent (e^{A h} a finite sum); else nullopt.
std::optional<std::pair<MatQ, MatQ>> exact_plant_zoh(const MatQ& A, const MatQ& B, const rational& h);

}  // namespace hapstab::sim
