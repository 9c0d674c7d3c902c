// hapstab/sim/simulator.hpp -- the exact-ZOH sampled-data simulator for a ComposedLoop
// (sim/loop.hpp): paper 001 Fig. 1, paper 002 Fig. 1 (full model, not the reduced Fig. 2),
// paper 000's N-DOF loop.
//
// Exactness. Between samples the continuous plant sees a piecewise-constant input (held
// actuator force, changing once inside the period at kT + f when the delay has a fractional
// part f; held exogenous force), so the state at every sample instant and at every requested
// intersample instant is x(t) = Phi(t) x + Gamma(t) u: no integration error. Phi, Gamma and
// the energy Gram matrices are enclosed once in ball arithmetic from the exact (rational) loop
// (numeric/ball_expm.hpp, Arb) and rounded to double; Piece::radius bounds the difference
// from the exact matrices (rounding included, typically one ulp). The remaining error is the
// double recursion itself. Each enclosure is taken on the part of the plant its result depends
// on (a connected component of the plant for Phi, Gamma; the states and inputs port j's power
// depends on for W_j): an exact restriction (simulator.cpp states the lemma), so N DOFs coupled
// only through the controller cost N small enclosures, not O(N^4) ball arithmetic.
//
// Encoders and Coulomb friction (LoopSpec::quantizers, ::coulomb). The controller sees the
// quantized sampled position (before the contact clip). Coulomb friction with stiction is
// event-located inside each piece (sim/coulomb.hpp: one-DOF loops; the pieces are then
// propagated with double matrix exponentials, and the energies too).
//
// Passivity controller (LoopSpec::passivity_controller; Hannaford and Ryu, IEEE T-RO 18(1),
// 2002), in its original form: at sample k the observer adds the energy the wall's actuator
// absorbs over the coming period as the samples see it, E_obs -= T u_k v_k (u the force applied
// over the period, after the delay; v the exact sampled velocity: a velocity measurement); when
// E_obs < 0 the controller adds a damper u_k -= alpha v_k with alpha = -E_obs/(T v_k^2), which
// brings E_obs back to 0 (nothing when v_k = 0). Summary::pc_dissipated is the sum of -E_obs
// removed, pc_active the samples at which it acted. The rectangle rule T u_k v_k is the
// observer's own error: it is not the exact energy int u v (Summary::e_act) and can miss what
// a wall generates (docs/friction.md). Integer delays only.
//
// Contact. The unilateral wall is evaluated at the sample instants (the papers' sampled wall,
// paper 002's xi on the sampled position): the environment sees max(0, x_j(kT)); the device and
// operator dynamics are continuous and the force is held. No event detection inside the period:
// the wall is a sampled-data controller, not a physical constraint on the continuous motion.
//
// Energy. Per DOF and per step, exactly for the piecewise-constant input:
//   E_port = int f_h v dt   (human port: operator + exogenous force on the device), the
//            quadratic form z^T W z of z = [state; input] with W = int_0^h e^{M^T t} Q e^{M t} dt
//            (Van Loan's second block exponential); impulses add I (v- + v+)/2;
//   E_act  = int u v dt = u (x_end - x_start) per constant-input piece (actuator port);
//   storage = 1/2 m v^2 for mass-damper devices;
//   E_po   = T sum_k f_h(kT) v(kT): the Hannaford-Ryu passivity observer, as a measurement.
// The interface generated energy at time t when sum_j E_port_j(t) < 0 (zero initial storage).
//
// The hot loop uses fixed-size Eigen types for the common sizes and preallocated dynamic ones
// otherwise; it allocates nothing per step.
//
// Implements: paper 000 Sec. VI; paper 001 Fig. 1; paper 002 Fig. 1.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "hapstab/sim/coulomb.hpp"
#include "hapstab/sim/loop.hpp"

namespace hapstab::sim {

struct SimOptions {
  long steps = 0;            ///< sample periods to run (> 0)
  long record_every = 1;     ///< store every n-th sample instant (0: store none)
  int substeps = 1;          ///< intersample grid: output every T/substeps (exact), >= 1
  double fine_from = 0, fine_to = -1;  ///< time window for the intersample grid (to < from: none)
  bool energy = true;        ///< exact port energies and the passivity observer
  double max_velocity = 1e4; ///< |v| above this (or non-finite) stops the run: diverged
  int watch_dof = -1;        ///< DOF whose sampled position feeds limit-cycle detection (-1: first contact DOF or 0)
  std::function<void(double)> progress;  ///< called with the fraction done (every ~1/100)
};

/// Samples at t = kT (one row per recorded instant; per-DOF columns).
struct SampleTrace {
  int N = 0;
  std::vector<double> t;
  std::vector<double> x, v, u, fh;              ///< row-major: [row * N + j]
  std::vector<double> e_port, e_act, e_po, storage;
  size_t rows() const { return t.size(); }
};
/// Exact intersample grid (positions and velocities).
struct FineTrace {
  int N = 0;
  std::vector<double> t, x, v;
  size_t rows() const { return t.size(); }
};

struct LimitCycle {
  double period = 0;     ///< seconds
  double amplitude = 0;  ///< half the peak-to-peak of the watched sampled position
  long period_samples = 0;  ///< > 0 when the sampled sequence repeats exactly (within 1e-6 of the amplitude)
};

struct Summary {
  bool diverged = false;
  long steps_run = 0;
  double max_velocity = 0;            ///< max |v_j(kT)| over DOFs and samples
  double energy_generated = 0;        ///< max(0, -min_t sum_j E_port_j(t)): net energy the interface put out
  double min_port_energy = 0;         ///< min_t sum_j E_port_j(t)
  std::vector<double> e_port, e_act, e_po;  ///< final values per DOF
  std::string trend;                  ///< "rest", "decaying", "steady", "growing", "diverged"
  double step_matrix_radius = 0;      ///< proven bound on |exact - double| of the step matrices (Piece::radius)
  std::optional<LimitCycle> limit_cycle;
  long friction_events = 0;           ///< times the device velocity reached 0 inside a period (Coulomb friction)
  std::vector<double> pc_dissipated;  ///< per DOF: energy the passivity controller's damper removed (observer units)
  long pc_active = 0;                 ///< samples at which the passivity controller acted
};

struct SimResult {
  SampleTrace samples;
  FineTrace fine;
  Summary summary;
};

class Simulator {
 public:
  explicit Simulator(const LoopSpec& spec);
  /// Runs from the spec's initial state. InputError on steps <= 0, substeps < 1.
  SimResult run(const SimOptions& options) const;
  const ComposedLoop& loop() const { return loop_; }

  // The exact step matrices (double), exposed for tests and the bench.
  /// The energy Gram matrix of one port on its support: W_j (size (n+2N)^2) is exactly zero
  /// outside support x support (simulator.cpp, make_piece), so int f_h v dt = z_R^T W z_R with
  /// z_R = z(support).
  struct PortGram {
    std::vector<Eigen::Index> support;    ///< R_j, increasing indices into z = [s; u; w]
    Mat<double> W;                        ///< W_j[R_j, R_j]
    Mat<double> dense(Eigen::Index nz) const;  ///< W_j itself, nz x nz
  };
  struct Piece {
    double h = 0;
    Mat<double> Phi, Gu, Gw;              ///< s+ = Phi s + Gu u + Gw w over a piece of length h
    std::vector<PortGram> W;              ///< per DOF: int f_h v dt = z^T W_j z
    double radius = 0;                    ///< every entry above (and W_j's zeros) is within this of the exact value
  };
  const Piece& piece_before() const { return p1_; }  ///< [kT, kT+f) (h = 0 when f = 0)
  const Piece& piece_after() const { return p2_; }   ///< [kT+f, (k+1)T)
  long delay_steps() const { return nd_; }

 private:
  LoopSpec spec_;
  ComposedLoop loop_;
  long nd_ = 0;       ///< integer part of the delay in samples
  double f_ = 0;      ///< fractional part (seconds)
  Piece p1_, p2_;
  std::optional<CoulombStepper> coulomb_;  ///< when the spec has Coulomb friction f_c > 0
  Mat<double> Ac_, Bc_, Cc_, Dc_;  ///< controller
  Mat<double> Cx_, Cv_, Cf_, Dfu_, Dfw_, Bw_;  ///< plant outputs / impulse input
  Piece make_piece(const rational& h, bool energy) const;
  template <int NX, int NC, int NN>
  friend struct Engine;
};

/// Limit-cycle / trend analysis of a sampled sequence (the tail of a run), exposed for tests.
std::optional<LimitCycle> detect_limit_cycle(const std::vector<double>& y, double T, std::string& trend);

}  // namespace hapstab::sim
