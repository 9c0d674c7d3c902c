// hapstab/multidof/environment.hpp -- the virtual environment E(z) of paper 000 and the
// realisations built from it and from the coupling V, all exact (rational):
//
//   E-hat = E(z) T z/(z-1):   A = [[A_E, B_E], [0, I]], B = [[B_E T], [I T]],
//                             C = [C_E, D_E], D = D_E T                          (15)
//   E-hat^Gamma = Gamma E-hat Gamma^-1 = (A, B Gamma^-1, Gamma C, Gamma D Gamma^-1)  (text after (15))
//   V-hat = (z-1)/(T z) (V - K):  A = [[A_V, -B_V/T], [0, 0]], B = [[B_V/T], [I]],
//                             C = [C_V, (K - D_V)/T], D = (D_V - K)/T            (17)
//   (A_V, B_V, C_V, D_V) = (A_V^G, B_V^G Gamma, Gamma^-1 C_V^G, Gamma^-1 D_V^G Gamma)  (23)
//
// E-hat has m eigenvalues at z = 1 (the accumulator): with V_a = (I - A_E)^{-1} B_E its
// eigenvectors at 1 are [V_a b; b]. `ehat_split` gives the exact similarity Pi0 = [[I, V_a],
// [0, I]] that separates them: Pi0^-1 A Pi0 = diag(A_E, I), C Pi0 = [C_E, E(1)], so that the
// facial-reduction equalities of Theorem 5's first LMI can be imposed exactly (analysis.hpp).
//
// The reconstructed Fig. 5 environment (DESIGN.md): one mass M tied to ground by k, B and
// touched at m massless contact points through k_i, B_i; E maps contact displacements to
// contact forces: E(s) = diag(Z_i) - z z^T / (M s^2 + (B + sum B_i) s + k + sum k_i),
// Z_i = k_i + B_i s, z = (Z_1..Z_m)^T. It is improper (the dampers), so it is discretised by
// substituting s (backward Euler s = (z-1)/(Tz), Tustin s = (2/T)(z-1)/(z+1)); ZOH needs a
// proper E(s) and is refused for it with an InputError.
//
// Implements: paper 000 (15), (17), (23).
#pragma once

#include <string>
#include <vector>

#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/lti/state_space.hpp"
#include "hapstab/multidof/structure.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::multidof {

struct MechanicalEnvironment {
  rational M, k, B;                 ///< virtual mass, its spring and damper to ground
  std::vector<rational> kc, Bc;     ///< contact springs k_i and dampers B_i (one per DOF)
  void validate() const;
};

/// E(s) of the mechanical environment (continuous transfer matrix, improper when some B_i > 0).
TransferMatrix mechanical_impedance(const MechanicalEnvironment& env);

/// Discretises a continuous transfer matrix by substituting s: backward Euler or Tustin
/// (exact; entries reduced). ZOH throws InputError (use c2d on a proper state space).
TransferMatrix c2d(const TransferMatrix& Hs, const rational& T, C2dMethod method);

/// Exact minimal realisation of a discrete proper transfer matrix (tf2ss, then minreal).
StateSpace<rational> minimal_ss(const TransferMatrix& Hz);

/// The Fig. 5 environment discretised and minimally realised (4 states for 2 contacts).
StateSpace<rational> mechanical_environment(const MechanicalEnvironment& env, const rational& T,
                                            C2dMethod method = C2dMethod::backward_euler);

/// The same environment discretised by backward Euler DIRECTLY in state space (no transfer
/// matrices; for large m): state (y_{k-1}, v_{k-1}, x_{k-1}) of the mass and the contacts,
/// m + 2 states (not minimal: the contact delays are kept even when B_i = 0), exact.
StateSpace<rational> mechanical_environment_be_ss(const MechanicalEnvironment& env, const rational& T);

/// Schur stability of a matrix (every eigenvalue of A in |z| < 1), decided rigorously. From
/// kLyapunovFromStates states on, a Lyapunov certificate (numeric/lyapunov.hpp: solve in double,
/// verify P > 0 and P - A^T P A > 0 with Arb balls on the exact A) is tried first; when it proves
/// nothing, and always for smaller A, the exact Schur-Cohn test on det(zI - A) decides
/// (poly/stability.hpp). False also for eigenvalues ON the unit circle. `method`, if given,
/// receives which of the two decided.
bool schur_stable(const MatQ& A, std::string* method = nullptr);
/// The certificate costs O(n^3) ball operations whatever the entries (0.5 ms at 18 states, 2 ms at
/// 34); Schur-Cohn's cost grows with the characteristic polynomial's coefficients: 0.1-0.3 ms on
/// the sparse scene environments (18, 34 states), but 71 ms at 32 states and 2.4 s at 64 for dense
/// matrices of small rationals (bench/exact_core.cpp, schur_stable). Trying the certificate first
/// from 12 states on risks milliseconds to save seconds.
inline constexpr Eigen::Index kLyapunovFromStates = 12;

/// Static gain E(1) = C (I - A)^{-1} B + D; InputError if 1 is an eigenvalue of A.
MatQ dc_gain(const StateSpace<rational>& E);

/// (15).
StateSpace<rational> ehat(const StateSpace<rational>& E);
/// Gamma Sys Gamma^-1 on the realisation: (A, B Gamma^-1, Gamma C, Gamma D Gamma^-1).
StateSpace<rational> scale_gamma(const StateSpace<rational>& sys, const MatQ& Gamma);
/// (17) with Gamma = I (V-hat of any V; V-hat^Gamma is vhat(V^Gamma, K) since K commutes with Gamma).
StateSpace<rational> vhat(const StateSpace<rational>& V, const MatQ& K);
/// (23): V from V^Gamma and Gamma.
StateSpace<rational> coupling_from_gamma(const StateSpace<rational>& VG, const MatQ& Gamma);

/// The split of E-hat along its eigenvalues at 1 (see the header comment).
struct EhatSplit {
  MatQ Va;                   ///< (I - A_E)^{-1} B_E
  MatQ Pi0;                  ///< [[I, Va], [0, I]]
  MatQ E1;                   ///< E(1), static gain
  StateSpace<rational> t;    ///< (Pi0^-1 A Pi0, Pi0^-1 B, C Pi0, D): A = diag(A_E, I)
};
EhatSplit ehat_split(const StateSpace<rational>& E);

/// Block-diagonal concatenation of state-space models (decentralised V = blockdiag(V_i)).
StateSpace<rational> blockdiag(const std::vector<StateSpace<rational>>& blocks);

}  // namespace hapstab::multidof
