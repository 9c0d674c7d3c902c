// hapstab/contact/limit_cycle.hpp -- the reality check for the criteria of paper 002: the
// Lur'e loop of a linear H(z) and the unilateral nonlinearity, simulated, and its sustained
// oscillations (limit cycles) detected, measured and -- in rational arithmetic -- proven.
//
//   Fig. 2:  theta_k = H(z) (r - xi(theta_k)),     xi(v) = max(v, 0), r > 0 constant;
//   Fig. 5:  y_k = -H(z) x_k,  x_k = xi(y_k + rho) - rho = max(y_k, -rho)          (4),
// the autonomous form (y = theta - rho, rho = H(1) r/(1 + H(1)) (3)). With a realisation
// s_{k+1} = A s_k + B u_k, y_k = C s_k + D u_k and u_k = -max(y_k, -rho) the algebraic loop
// (D != 0) has the unique solution u_k = -max(C s_k/(1+D), -rho) when 1 + D > 0, so each step
// is one of two affine maps ("contact" y >= -rho: u = -y; "free" y < -rho: u = rho).
//
//  * simulate (double): fixed-size, allocation-free inner loop (>= 50 M steps/s for order 2).
//  * detect: amplitude over the last window, the smallest period p with max|y_k - y_{k-p}| tiny
//    against the amplitude, and the amplitude of the previous window, so that a slow decay
//    (amplitude shrinking) is told apart from a sustained oscillation.
//  * certify (exact): from the period p and the contact/free pattern seen in double, the
//    periodic orbit is the fixed point of the composed affine map, solved exactly over Q;
//    the orbit is then simulated exactly for p steps: every step must take the mode it was
//    assumed to take and the state must repeat exactly (a repeated rational state = an exact
//    periodic solution of (4)). Its local stability is decided exactly (Schur-Cohn on the
//    monodromy matrix).
// Because (4) is positively homogeneous in (y, rho), a limit cycle's amplitude scales with rho
// and whether one exists does not depend on rho > 0.
//
// Implements: paper 002 (3), (4), Fig. 2, Fig. 5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/lti/tf.hpp"

namespace hapstab::contact {

/// The Fig. 5 loop for gain*H: a realisation in double and in rational.
struct LureLoop {
  StateSpace<rational> sys;  ///< realisation of gain*H (controllable form)
  rational rho = 1;
  /// The loop in contact is linear, (1 + k H)^-1: A - B C/(1 + D) Schur stable, decided exactly
  /// (Schur-Cohn on its characteristic polynomial) by make_lure_loop.
  bool contact_stable = true;
  int order() const { return static_cast<int>(sys.A.rows()); }
};
/// Throws InputError for rho <= 0, gain < 0, H not proper, or 1 + gain*H(inf) <= 0 (ill-posed loop).
LureLoop make_lure_loop(const TransferFunction& H, const rational& gain, const rational& rho);

/// Double simulation of Fig. 5 from state s0 for `steps` steps; returns y_k for the last
/// `keep` steps (keep <= steps) and the final state.
struct SimTrace {
  std::vector<double> y;      ///< the last `keep` outputs
  std::vector<double> state;  ///< final state
  bool diverged = false;
};
SimTrace simulate(const LureLoop& L, const std::vector<double>& s0, long steps, long keep);

/// Fig. 2 (theta = H(r - xi(theta))) from rest, returns theta_k for k < steps (for plots/tests).
std::vector<double> simulate_fig2(const TransferFunction& H, double gain, double r, long steps);

/// Steps only, no recording: the hot loop (used by the benchmark). Returns the final y.
double run_steps(const LureLoop& L, std::vector<double>& state, long steps);

struct Oscillation {
  bool oscillates = false;   ///< sustained oscillation (not decaying, amplitude above threshold)
  bool growing = false;      ///< the motion grows: in contact with an unstable linear loop, or diverged
  bool diverged = false;     ///< unbounded growth: overflow, or the envelope grows far beyond rho
  std::optional<long> period;  ///< in samples, when periodic to ~1e-9 relative
  double amplitude = 0;      ///< (max - min)/2 of y over the last window
  double previous_amplitude = 0;  ///< same over the window before it
  double mismatch = 0;       ///< max |y_k - y_{k-p}| / amplitude for the period found
  std::vector<double> window;  ///< the last window of y (for plots)
  std::vector<double> state;   ///< the state after the last sample (on the orbit when periodic)
  std::string note;
};

/// Runs from s0 and classifies. window = samples per window (two windows are compared).
/// Growth is decided, whatever `steps` is:
///  * the last window in contact (y >= -rho throughout): the loop is linear there, and grows iff
///    (1 + k H)^-1 is unstable -- the exact contact_stable, not the amplitude ratio;
///  * leaving contact: by the envelope. (4) is positively homogeneous in (y, rho), so at an
///    amplitude A the loop is the one with rho/A; at A >= 10^6 rho it is within 10^-6 of the cone
///    u = -max(y, 0), which has no scale: a growing envelope there keeps growing -- diverged
///    (numeric). Below that, growth may end on a limit cycle, and the period search decides.
///  * |y| >= 1e150 (overflow guard): diverged.
Oscillation detect(const LureLoop& L, const std::vector<double>& s0, long steps, long window = 4096);

/// Tries several initial states (directions x scales relative to rho); the first oscillation
/// found, else the last result.
Oscillation find_oscillation(const LureLoop& L, long steps, long window = 4096);

/// Exact certificate of a periodic orbit of period p (see the header comment).
struct ExactOrbit {
  bool found = false;          ///< an exact periodic solution of (4) with period p exists
  long period = 0;
  bool stable = false;         ///< monodromy matrix Schur stable (exact), i.e. the orbit attracts
  bool stability_decided = false;  ///< no sample on y = -rho (else `stable` does not decide attraction)
  rational amplitude;          ///< (max - min)/2 of y over the exact orbit
  std::vector<rational> y;     ///< one period of y, exact
  int free_steps = 0;          ///< samples per period out of contact (y < -rho)
  std::string note;
};
/// From a double simulation that found a period: solve and verify the orbit exactly.
ExactOrbit certify_orbit(const LureLoop& L, const std::vector<double>& s_on_orbit, long period);

/// Plain exact simulation with repeated-state detection (useful when the orbit is reached in
/// finitely many steps, e.g. FIR H). Returns the period if a state repeats within `steps`.
std::optional<long> exact_repeat(const LureLoop& L, const std::vector<rational>& s0, long steps);

/// The smallest k > 0 for which (1 + kH)^{-1} is not stable (exact bisection to `rel` relative
/// width, Schur-Cohn); +inf (nullopt) if stable for every k up to kmax.
std::optional<double> closed_loop_gain_limit(const TransferFunction& H, double kmax = 1e9, double rel = 1e-9);

/// Gain sweep: the smallest gain (log grid of n points in [kmin, kmax], then bisection to `rel`)
/// at which a sustained oscillation is observed; nullopt when none in the range.
struct OnsetResult {
  std::optional<double> k_onset;  ///< numeric (simulation)
  std::optional<long> period;     ///< at the onset gain found
  double amplitude_over_rho = 0;
  bool certified = false;         ///< the orbit at k_onset(upper end) was certified exactly
};
OnsetResult oscillation_onset(const TransferFunction& H, double kmin, double kmax, int n = 48, double rel = 1e-3,
                              long steps = 60000);

}  // namespace hapstab::contact
