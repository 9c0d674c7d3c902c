// The exact-ZOH sampled-data simulator (see simulator.hpp).
#include "hapstab/sim/simulator.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/sim/closed_loop.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::sim {

namespace {

Mat<double> to_double(const Mat<rational>& M) {
  Mat<double> R(M.rows(), M.cols());
  for (Eigen::Index i = 0; i < M.size(); ++i) R.data()[i] = to_real<double>(M.data()[i]);
  return R;
}

// ---- The enclosures on the parts of the plant each result depends on (issue 33) ----
//
// Lemma (exact). Let z' = M z and let R be a set of indices closed under M's dependencies:
// i in R and M(i, k) != 0 imply k in R. Then M[R, R^c] = 0, so (M^p)[R, :] = M[R, R] (M^(p-1))[R, :]
// and by induction on p, (M^p)[R, :] is zero outside the columns R and equals M[R, R]^p there.
// Summing the exponential series: (e^{M t})[R, :] is zero outside the columns R and equals
// e^{M[R, R] t} there. The rows R of the flow see z_R only.
//
// ZOH: M = [[A, B], [0, 0]] (z = [s; in], in held). A connected component C of the graph of A
// (i ~ k when A(i, k) != 0 or A(k, i) != 0) with the inputs I_C that B feeds into C is closed,
// and the components partition the states: Phi is block diagonal, Phi[C, C] = e^{A[C, C] h},
// Gamma[C, I_C] = int_0^h e^{A[C, C] t} dt B[C, I_C], every other entry of Phi, Gamma is 0.
//
// Energy: Q_j = (a^T b + b^T a)/2 is zero outside S_j x S_j (S_j: the entries of z that port j's
// rows a = f_h, b = v involve). With R_j the closure of S_j and E = (e^{M t})[R_j, :],
// e^{M^T t} Q_j e^{M t} = E^T Q_j[R_j, R_j] E, so W_j = int_0^h e^{M^T t} Q_j e^{M t} dt is zero
// outside R_j x R_j and W_j[R_j, R_j] = int_0^h e^{M[R,R]^T t} Q_j[R, R] e^{M[R,R] t} dt: Van Loan
// on the small block.
//
// These are identities of the exact matrices, so the Arb enclosure of a block encloses the
// corresponding entries of the whole, and the entries outside the blocks are exact zeros (no
// radius): Piece::radius stays a proven bound. Cost, N DOFs coupled only through the controller
// (the held input): N exponentials of a few states per piece instead of one of n states, and N
// Gram enclosures of a few states instead of N of 2(n + 2N) (O(N^4) ball arithmetic).
using Indices = std::vector<Eigen::Index>;

// The smallest R containing S with i in R, M(i, k) != 0 => k in R; increasing.
Indices dependency_closure(const Mat<rational>& M, const Indices& S) {
  std::vector<char> in(static_cast<size_t>(M.rows()), 0);
  Indices todo;
  for (Eigen::Index i : S)
    if (!in[size_t(i)]) in[size_t(i)] = 1, todo.push_back(i);
  while (!todo.empty()) {
    const Eigen::Index i = todo.back();
    todo.pop_back();
    for (Eigen::Index k = 0; k < M.cols(); ++k)
      if (!in[size_t(k)] && M(i, k) != 0) in[size_t(k)] = 1, todo.push_back(k);
  }
  Indices R;
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    if (in[size_t(i)]) R.push_back(i);
  return R;
}

// (Phi, Gamma) of s' = A s + B in over h, component by component (the lemma above):
// closed_loop.hpp's plant_zoh, its radii folded into one (every entry within it).
ZohEnclosure zoh_of(const Mat<rational>& A, const Mat<rational>& B, const rational& h) {
  const PlantZoh p = sim::plant_zoh(A, B, h);
  return {{p.Phi.mid, p.Phi.max_radius()}, {p.Gamma.mid, p.Gamma.max_radius()}};
}

// Propagation over [0, tau] of a step whose input is u_old on [0, f) and u_new on [f, T):
// s(tau) = P s + Qo u_old + Qn u_new + Qw w (the intersample grid). Each piece is enclosed
// (numeric/ball_expm.hpp); the composition of the two pieces is one double product.
struct Prop {
  Mat<double> P, Qo, Qn, Qw;
};
Prop propagate(const Mat<rational>& A, const Mat<rational>& B, int N, const rational& f, const rational& tau) {
  const auto n = A.rows();
  Prop p;
  const ZohEnclosure first = zoh_of(A, B, tau < f ? tau : f);
  p.P = first.Phi.mid;
  p.Qo = first.Gamma.mid.leftCols(N);
  p.Qn = Mat<double>::Zero(n, N);
  p.Qw = first.Gamma.mid.rightCols(N);
  if (tau > f) {
    const ZohEnclosure second = zoh_of(A, B, tau - f);
    p.P = (second.Phi.mid * p.P).eval();
    p.Qo = (second.Phi.mid * p.Qo).eval();
    p.Qw = (second.Phi.mid * p.Qw + second.Gamma.mid.rightCols(N)).eval();
    p.Qn = second.Gamma.mid.leftCols(N);
  }
  return p;
}

}  // namespace

Simulator::Simulator(const LoopSpec& spec) : spec_(spec), loop_(compose(spec)) {
  const rational& T = loop_.T;
  rational q = spec.delay / T;
  nd_ = long(integer(bmp::numerator(q) / bmp::denominator(q)).convert_to<long>());
  const rational frac = spec.delay - rational(nd_) * T;
  f_ = to_real<double>(frac);
  p1_ = make_piece(frac, true);
  p2_ = make_piece(T - frac, true);
  const int N = loop_.N;
  const auto& P = loop_.plant;
  Cx_ = to_double(Mat<rational>(P.C.topRows(N)));
  Cv_ = to_double(Mat<rational>(P.C.middleRows(N, N)));
  Cf_ = to_double(Mat<rational>(P.C.bottomRows(N)));
  Dfu_ = to_double(Mat<rational>(P.D.bottomRows(N).leftCols(N)));
  Dfw_ = to_double(Mat<rational>(P.D.bottomRows(N).rightCols(N)));
  Bw_ = to_double(Mat<rational>(P.B.rightCols(N)));
  const auto& C = loop_.controller;
  if (!spec.passivity_controller.empty() && f_ > 0)
    throw InputError("passivity controller: the delay must be a whole number of samples (the applied force would "
                     "change inside the period)");
  for (const Coulomb& c : spec.coulomb)
    if (c.force > 0) coulomb_.emplace(loop_.plant, c.force, std::vector<double>{p1_.h, p2_.h});
  Ac_ = to_double(C.A);
  Bc_ = to_double(C.B);
  Cc_ = to_double(C.C);
  Dc_ = to_double(C.D);
}

Mat<double> Simulator::PortGram::dense(Eigen::Index nz) const {
  Mat<double> D = Mat<double>::Zero(nz, nz);
  D(support, support) = W;
  return D;
}

Simulator::Piece Simulator::make_piece(const rational& h, bool energy) const {
  const int N = loop_.N;
  const auto& P = loop_.plant;
  const auto n = P.A.rows(), nz = n + 2 * N;
  Piece pc;
  pc.h = to_real<double>(h);
  const ZohEnclosure zp = zoh_of(P.A, P.B, h);
  pc.Phi = zp.Phi.mid;
  pc.Gu = zp.Gamma.mid.leftCols(N);
  pc.Gw = zp.Gamma.mid.rightCols(N);
  pc.radius = std::max(zp.Phi.radius, zp.Gamma.radius);
  if (!energy) return pc;
  // z = [s; u; w], z' = M z. Power at port j: (a_j z)(b_j z), a = f_h row, b = v row;
  // W_j = int_0^h e^{M^T t} Q_j e^{M t} dt with Q_j = (a^T b + b^T a)/2, on the closure R_j of
  // the entries a and b involve (the lemma above: exact).
  Mat<rational> M = Mat<rational>::Zero(nz, nz);
  M.topLeftCorner(n, n) = P.A;
  M.topRightCorner(n, 2 * N) = P.B;
  for (int j = 0; j < N; ++j) {
    Mat<rational> a(1, nz), b(1, nz);
    a << P.C.row(2 * N + j), P.D.row(2 * N + j);
    b << P.C.row(N + j), P.D.row(N + j);
    Indices S;
    for (Eigen::Index i = 0; i < nz; ++i)
      if (a(0, i) != 0 || b(0, i) != 0) S.push_back(i);
    PortGram g;
    g.support = dependency_closure(M, S);
    if (g.support.empty()) {
      g.W = Mat<double>(0, 0);  // no power at this port: W_j = 0
    } else {
      const Mat<rational> aR = a(0, g.support), bR = b(0, g.support);
      const Mat<rational> Q = (aR.transpose() * bR + bR.transpose() * aR) / rational(2);
      const DoubleEnclosure W = gram_enclosure(Mat<rational>(M(g.support, g.support)), Q, h);
      g.W = W.mid;
      pc.radius = std::max(pc.radius, W.radius);
    }
    pc.W.push_back(std::move(g));
  }
  return pc;
}

// ---------------------------------------------------------------------------------------
namespace {

// An exogenous event at the sample instant k: an impulse (state jump Bw I) or a bias step.
struct Event {
  long k;
  int dof;
  double val;
  bool impulse;
};

// Biases are held from the first sample instant at or after their start; impulses act at the
// nearest sample instant (round half up). In time order; at one instant, in the scene's order.
std::vector<Event> exogenous_events(const LoopSpec& spec, const rational& T) {
  std::vector<Event> ev;
  for (const auto& b : spec.biases) {
    rational q = b.start / T;
    long k = long(bmp::numerator(q) / bmp::denominator(q));
    if (rational(k) * T < b.start) ++k;  // held from the first sample instant at or after start
    ev.push_back({k, b.dof, to_real<double>(b.force), false});
  }
  for (const auto& im : spec.impulses) {
    rational q = im.time / T + rational(1, 2);
    long k = long(integer(bmp::numerator(q) / bmp::denominator(q)).convert_to<long>());  // round half up
    ev.push_back({k, im.dof, to_real<double>(im.magnitude), true});
  }
  std::stable_sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) { return a.k < b.k; });
  return ev;
}

// The intersample grid's propagations over [0, i T/M], i = 1 .. M-1.
std::vector<Prop> fine_propagations(const LoopSpec& spec, const ComposedLoop& L, int M) {
  std::vector<Prop> props;
  rational q = spec.delay / L.T;
  long ndl = long(bmp::numerator(q) / bmp::denominator(q));
  const rational fx = spec.delay - rational(ndl) * L.T;
  for (int i = 1; i < M; ++i) props.push_back(propagate(L.plant.A, L.plant.B, L.N, fx, L.T * rational(i, M)));
  return props;
}

}  // namespace

// One run, in the sizes NX (plant states), NC (controller states), NN (DOFs); Eigen::Dynamic
// for any other size. The constructor sets up the discretised pieces, the initial state, the
// events and the output buffers; run() steps period by period: events, sampler/contact/
// controller, passivity observer, exact propagation over the period (with the port and
// actuator energies), the intersample grid, the divergence check; then the summary.
template <int NX, int NC, int NN>
struct Engine {
  static constexpr int D = Eigen::Dynamic;
  static constexpr int NZ = (NX == D || NN == D) ? D : NX + 2 * NN;
  using MX = Eigen::Matrix<double, NX, NX>;
  using MXN = Eigen::Matrix<double, NX, NN>;
  using MNX = Eigen::Matrix<double, NN, NX>;
  using MNN = Eigen::Matrix<double, NN, NN>;
  using MC = Eigen::Matrix<double, NC, NC>;
  using MCN = Eigen::Matrix<double, NC, NN>;
  using MNC = Eigen::Matrix<double, NN, NC>;
  using MZ = Eigen::Matrix<double, NZ, NZ>;
  using VX = Eigen::Matrix<double, NX, 1>;
  using VN = Eigen::Matrix<double, NN, 1>;
  using VC = Eigen::Matrix<double, NC, 1>;
  using VZ = Eigen::Matrix<double, NZ, 1>;
  using Grams = std::vector<MZ, Eigen::aligned_allocator<MZ>>;

  const Simulator& S;
  const LoopSpec& spec;
  const SimOptions& o;
  const ComposedLoop& L;
  const int N;
  const Eigen::Index n, nc, nz;
  const double T;
  const bool split;   ///< the delay has a fractional part: two pieces per period
  const bool energy;
  // --- the step matrices in the engine's sizes (piece 1: [kT, kT+f), piece 2: [kT+f, (k+1)T))
  const MX Phi1, Phi2;
  const MXN Gu1, Gw1, Gu2, Gw2, Bw;
  const MNX Cx, Cv, Cf;
  const MNN Dfu, Dfw;
  const MC Ac;
  const MCN Bc;
  const MNC Cc;
  const MNN Dc;
  Grams W1, W2;      ///< the port Gram matrices, dense (fixed sizes only: a few states)
  Vec<double> zr, Wzr;  ///< z and W_j z on a port's support (dynamic sizes)
  std::vector<char> contact;
  std::vector<double> quantum;     ///< per DOF, 0: no encoder
  std::vector<char> round_q;       ///< per DOF: round (half up) instead of floor
  long friction_events = 0;
  std::vector<char> pc;            ///< per DOF: passivity controller on
  std::vector<double> e_obs, pc_diss;  ///< observer energy; energy the PC's damper removed
  long pc_active = 0;
  // --- state and work vectors
  VX s, tmp, s0;
  VC xc, xc1;
  VN pos, meas, u, uo, un, w, wbase, v, fh, xa, xb;
  VZ z, Wz;
  // --- delay ring: u_k stored at slot k % Rn; a force delayed past the run's end is never read,
  // so the ring holds at most steps + 2 (a delay longer than the run costs no more than the run)
  const long nd, Rn;
  std::vector<VN, Eigen::aligned_allocator<VN>> ring;
  VN zero_force;  ///< the force before the first delayed one arrives
  // --- exogenous events
  const std::vector<Event> ev;
  size_t next_ev = 0;
  // --- energy accumulators, velocity watch
  std::vector<double> e_port, e_act, e_po;
  double min_port = 0;
  double maxv = 0;
  bool diverged = false;
  // --- limit-cycle watch buffer
  int watch = 0;
  long tail = 0;
  std::vector<double> tailbuf;
  Eigen::Index wpos = 0;
  // --- intersample grid
  const int M;
  const bool fine;
  std::vector<Prop> fine_props;
  // --- output
  SampleTrace& ST;
  FineTrace& FT;
  const long rec;

  Engine(const Simulator& sim, const LoopSpec& sp, const SimOptions& opt, SimResult& R)
      : S(sim), spec(sp), o(opt), L(sim.loop_), N(L.N), n(L.plant.states()), nc(L.controller.states()),
        nz(n + 2 * N), T(to_real<double>(L.T)), split(sim.f_ > 0), energy(opt.energy), Phi1(sim.p1_.Phi),
        Phi2(sim.p2_.Phi), Gu1(sim.p1_.Gu), Gw1(sim.p1_.Gw), Gu2(sim.p2_.Gu), Gw2(sim.p2_.Gw), Bw(sim.Bw_),
        Cx(sim.Cx_), Cv(sim.Cv_), Cf(sim.Cf_), Dfu(sim.Dfu_), Dfw(sim.Dfw_), Ac(sim.Ac_), Bc(sim.Bc_), Cc(sim.Cc_),
        Dc(sim.Dc_), nd(sim.nd_), Rn(std::min(sim.nd_, opt.steps) + 2), ev(exogenous_events(sp, L.T)), M(opt.substeps),
        fine(opt.substeps > 1 && opt.fine_to >= opt.fine_from), ST(R.samples), FT(R.fine), rec(opt.record_every) {
    if constexpr (NZ != D) {
      for (int j = 0; j < N; ++j) {
        W1.emplace_back(S.p1_.W[j].dense(nz));
        W2.emplace_back(S.p2_.W[j].dense(nz));
      }
    } else {
      size_t r = 0;
      for (const Simulator::Piece* p : {&S.p1_, &S.p2_})
        for (const auto& g : p->W) r = std::max(r, g.support.size());
      zr.resize(Eigen::Index(r));
      Wzr.resize(Eigen::Index(r));
    }
    contact.assign(size_t(N), 0);
    for (int j : spec.contact) contact[j] = 1;
    pc.assign(size_t(N), 0);
    for (int j : spec.passivity_controller) pc[size_t(j)] = 1;
    e_obs.assign(size_t(N), 0.0);
    pc_diss.assign(size_t(N), 0.0);
    quantum.assign(size_t(N), 0.0);
    round_q.assign(size_t(N), 0);
    for (const Quantizer& e : spec.quantizers) {
      quantum[size_t(e.dof)] = to_real<double>(e.step);
      round_q[size_t(e.dof)] = e.round;
    }
    initial_state();
    ring.assign(size_t(Rn), VN::Zero(N));
    zero_force = VN::Zero(N);
    e_port.assign(size_t(N), 0.0);
    e_act.assign(size_t(N), 0.0);
    e_po.assign(size_t(N), 0.0);
    watch = o.watch_dof;
    if (watch < 0) watch = spec.contact.empty() ? 0 : spec.contact.front();
    if (watch >= N) throw InputError("watch DOF " + std::to_string(watch) + " does not exist");
    tail = std::min<long>(o.steps, std::max<long>(4096, std::min<long>(o.steps / 2, 1L << 18)));
    tailbuf.assign(size_t(tail), 0.0);
    wpos = L.position_state[watch];
    if (fine) fine_props = fine_propagations(spec, L, M);
    ST.N = FT.N = N;
    reserve_samples();
  }

  void initial_state() {
    s = VX::Zero(n);
    tmp.resize(n);
    s0.resize(n);
    for (int j = 0; j < N; ++j) {
      if (j < int(spec.x0.size())) s(L.position_state[j]) = to_real<double>(spec.x0[j]);
    }
    if (!spec.v0.empty()) {
      // Initial velocities: set the device states by least squares on Cv (mass-damper: exact).
      VN v0 = VN::Zero(N);
      for (int j = 0; j < N && j < int(spec.v0.size()); ++j) v0(j) = to_real<double>(spec.v0[j]);
      Mat<double> Cvd = S.Cv_;
      Vec<double> sv = Cvd.completeOrthogonalDecomposition().solve(Vec<double>(v0));
      s += VX(sv);
    }
    xc = VC::Zero(nc);
    xc1.resize(nc);
    for (VN* x : {&pos, &meas, &u, &uo, &un, &w, &wbase, &v, &fh, &xa, &xb}) x->resize(N);
    z.resize(nz);
    Wz.resize(nz);
    u.setZero();
    wbase.setZero();
  }

  void reserve_samples() {
    if (rec <= 0) return;
    const size_t rows = size_t(o.steps / rec + 2);
    ST.t.reserve(rows);
    for (auto* vec : {&ST.x, &ST.v, &ST.u, &ST.fh, &ST.e_port, &ST.e_act, &ST.e_po, &ST.storage})
      vec->reserve(rows * size_t(N));
  }

  /// The ring slot of sample i (i may be negative).
  size_t slot(long i) const { return size_t((i % Rn + Rn) % Rn); }

  void record_sample(long k) {
    ST.t.push_back(double(k) * T);
    pos.noalias() = Cx * s;
    v.noalias() = Cv * s;
    // f_h just after kT: the input active then
    const VN& ua = split ? (k < nd + 1 ? zero_force : ring[slot(k - nd - 1)]) : un;  // un: after the passivity controller
    fh.noalias() = Cf * s;
    fh.noalias() += Dfu * ua;
    fh.noalias() += Dfw * w;
    for (int j = 0; j < N; ++j) {
      ST.x.push_back(pos(j));
      ST.v.push_back(v(j));
      ST.u.push_back(ua(j));
      ST.fh.push_back(fh(j));
      ST.e_port.push_back(e_port[j]);
      ST.e_act.push_back(e_act[j]);
      ST.e_po.push_back(e_po[j]);
      ST.storage.push_back(L.mass[j] ? 0.5 * to_real<double>(*L.mass[j]) * v(j) * v(j) : std::nan(""));
    }
  }

  // Exogenous events at the sample instant k (impulses jump the state; their port energy is
  // I (v- + v+)/2), then the held exogenous force w of this period.
  void apply_events(long k) {
    while (next_ev < ev.size() && ev[next_ev].k <= k) {
      const Event& e = ev[next_ev++];
      if (e.impulse) {
        const double vb = (Cv.row(e.dof) * s)(0);
        s.noalias() += Bw.col(e.dof) * e.val;
        const double va = (Cv.row(e.dof) * s)(0);
        maxv = std::fabs(va) > maxv ? std::fabs(va) : maxv;  // the recorded sample k holds it
        if (energy) {
          e_port[size_t(e.dof)] += e.val * 0.5 * (vb + va);
          e_po[size_t(e.dof)] += e.val * 0.5 * (vb + va);
        }
      } else {
        wbase(e.dof) += e.val;
      }
    }
    w = wbase;
    if (!spec.profiles.empty())
      for (const auto& p : spec.profiles)
        if (k < long(p.samples.size())) w(p.dof) += p.samples[size_t(k)];
  }

  // Sampler, contact (the environment sees max(0, x_j) on contact DOFs), controller; u_k goes
  // into the delay ring, un is the force applied from kT + f on (zero before the first).
  void sample_and_control(long k) {
    pos.noalias() = Cx * s;
    tailbuf[size_t(k % tail)] = s(wpos);
    meas = pos;
    for (int j = 0; j < N; ++j) {
      meas(j) = quantized(j, meas(j));
      if (contact[size_t(j)]) meas(j) = meas(j) > 0 ? meas(j) : 0.0;
    }
    if (nc > 0) {
      u.noalias() = Cc * xc;
      u.noalias() += Dc * meas;
      xc1.noalias() = Ac * xc;
      xc1.noalias() += Bc * meas;
      xc = xc1;
    } else {
      u.noalias() = Dc * meas;
    }
    ring[slot(k)] = u;
    un = ring[slot(k - nd)];
    if (k < nd) un.setZero();
    if (!spec.passivity_controller.empty()) passivity_control();
  }

  // Hannaford-Ryu PO/PC on the applied force un (see simulator.hpp).
  void passivity_control() {
    v.noalias() = Cv * s;
    for (int j = 0; j < N; ++j) {
      if (!pc[size_t(j)]) continue;
      double& E = e_obs[size_t(j)];
      E -= T * un(j) * v(j);
      if (E < 0 && v(j) != 0) {
        un(j) += E / (T * v(j));  // -alpha v with alpha = -E/(T v^2)
        pc_diss[size_t(j)] -= E;
        E = 0;
        ++pc_active;
      }
    }
  }

  double quantized(int j, double x) const {
    const double q = quantum[size_t(j)];
    return q > 0 ? q * std::floor(x / q + (round_q[size_t(j)] ? 0.5 : 0.0)) : x;
  }

  // The passivity observer: T f_h(kT) v(kT), with uo the force held over [kT, kT+f) when split.
  void observe(long k) {
    if (split) {
      uo = ring[slot(k - nd - 1)];
      if (k < nd + 1) uo.setZero();
    }
    if (!energy) return;
    v.noalias() = Cv * s;
    fh.noalias() = Cf * s;
    fh.noalias() += Dfu * (split ? uo : un);
    fh.noalias() += Dfw * w;
    for (int j = 0; j < N; ++j) e_po[size_t(j)] += T * fh(j) * v(j);
  }

  // E_port_j += z^T W_j z: dense in the fixed sizes; otherwise on the supports R_j (sum_j |R_j|^2
  // per step instead of N (n + 2N)^2; W_j is exactly zero elsewhere).
  void port_energies(const Grams& W, const std::vector<Simulator::PortGram>& G) {
    if constexpr (NZ != D) {
      for (int j = 0; j < N; ++j) {
        Wz.noalias() = W[size_t(j)] * z;
        e_port[size_t(j)] += z.dot(Wz);
      }
    } else {
      for (int j = 0; j < N; ++j) {
        const Simulator::PortGram& g = G[size_t(j)];
        const Eigen::Index r = Eigen::Index(g.support.size());
        zr.head(r) = z(g.support);
        Wzr.head(r).noalias() = g.W * zr.head(r);
        e_port[size_t(j)] += zr.head(r).dot(Wzr.head(r));
      }
    }
  }

  // One piece of constant input ui: s+ = Phi s + Gu ui + Gw w; E_port_j += z^T W_j z with
  // z = [s; ui; w]; E_act_j += ui_j (x_j+ - x_j).
  void propagate_piece(const MX& Phi, const MXN& Gu, const MXN& Gw, const Grams& W,
                       const std::vector<Simulator::PortGram>& G, const VN& ui, double h) {
    if (S.coulomb_) {  // one DOF: events inside the piece (sim/coulomb.hpp)
      Vec<double> sd = s;
      double ep = 0, ea = 0;
      friction_events += S.coulomb_->advance(sd, ui(0), w(0), h, ep, ea);
      s = VX(sd);
      if (energy) {
        e_port[0] += ep;
        e_act[0] += ea;
      }
      return;
    }
    if (energy) {
      z << s, ui, w;
      xa.noalias() = Cx * s;
      port_energies(W, G);
    }
    tmp.noalias() = Phi * s;
    tmp.noalias() += Gu * ui;
    tmp.noalias() += Gw * w;
    s = tmp;
    if (energy) {
      xb.noalias() = Cx * s;
      for (int j = 0; j < N; ++j) e_act[size_t(j)] += ui(j) * (xb(j) - xa(j));
    }
  }

  // The exact propagation over the period, and the running minimum of sum_j E_port_j.
  void propagate_period() {
    if (split) propagate_piece(Phi1, Gu1, Gw1, W1, S.p1_.W, uo, S.p1_.h);
    propagate_piece(Phi2, Gu2, Gw2, W2, S.p2_.W, un, S.p2_.h);
    if (energy) {
      double tot = 0;
      for (int j = 0; j < N; ++j) tot += e_port[size_t(j)];
      min_port = tot < min_port ? tot : min_port;
    }
  }

  // The exact intersample grid from s0 = s(kT): t = (k + i/M) T, i = 0 .. M-1.
  void fine_grid(long k) {
    if (!split) uo.setZero();
    for (int i = 0; i < M; ++i) {
      Vec<double> si = i == 0 ? Vec<double>(s0) : Vec<double>(fine_props[size_t(i - 1)].P * Vec<double>(s0) +
                                                               fine_props[size_t(i - 1)].Qo * Vec<double>(uo) +
                                                               fine_props[size_t(i - 1)].Qn * Vec<double>(un) +
                                                               fine_props[size_t(i - 1)].Qw * Vec<double>(w));
      FT.t.push_back((double(k) + double(i) / M) * T);
      for (int j = 0; j < N; ++j) {
        FT.x.push_back((S.Cx_.row(j) * si)(0));
        FT.v.push_back((S.Cv_.row(j) * si)(0));
      }
    }
  }

  // Max |v_j((k+1)T)|; diverged when one exceeds max_velocity or is not finite.
  void check_velocity() {
    v.noalias() = Cv * s;
    for (int j = 0; j < N; ++j) {
      const double a = std::fabs(v(j));
      if (!(a <= o.max_velocity)) diverged = true;
      maxv = a > maxv ? a : maxv;
    }
  }

  void summarise(long k, Summary& SU) const {
    SU.diverged = diverged;
    SU.steps_run = k;
    SU.max_velocity = maxv;
    SU.min_port_energy = min_port;
    SU.energy_generated = energy ? std::max(0.0, -min_port) : std::nan("");
    SU.e_port = e_port;
    SU.e_act = e_act;
    SU.e_po = e_po;
    SU.friction_events = friction_events;
    SU.pc_dissipated = pc_diss;
    SU.pc_active = pc_active;
    if (diverged) {
      SU.trend = "diverged";
    } else {
      const long len = std::min<long>(k, tail);
      std::vector<double> y(static_cast<size_t>(len), 0.0);
      for (long i = 0; i < len; ++i) y[size_t(i)] = tailbuf[size_t((k - len + i) % tail)];
      SU.limit_cycle = detect_limit_cycle(y, T, SU.trend);
    }
  }

  static void run(const Simulator& S, const LoopSpec& spec, const SimOptions& o, SimResult& R) {
    Engine e(S, spec, o, R);
    e.summarise(e.step_all(), R.summary);
  }

  /// Runs the periods; returns the number run.
  long step_all() {
    const long prog_every = std::max<long>(1, o.steps / 100);
    long next_prog = o.progress ? prog_every : o.steps + 1;
    long k = 0;
    for (; k < o.steps; ++k) {
      apply_events(k);
      sample_and_control(k);
      if (rec > 0 && k % rec == 0) record_sample(k);
      const bool in_window = fine && double(k) * T >= o.fine_from && double(k) * T <= o.fine_to;
      if (in_window) s0 = s;
      observe(k);
      propagate_period();
      if (in_window) fine_grid(k);
      check_velocity();
      if (diverged) return k + 1;
      if (k + 1 == next_prog) {
        o.progress(double(k + 1) / double(o.steps));
        next_prog += prog_every;
      }
    }
    if (rec > 0 && k % rec == 0) {
      w = wbase;
      record_sample(k);
    }
    return k;
  }
};

SimResult Simulator::run(const SimOptions& o) const {
  if (o.steps <= 0) throw InputError("steps must be > 0, got " + std::to_string(o.steps));
  if (o.substeps < 1) throw InputError("substeps must be >= 1, got " + std::to_string(o.substeps));
  if (o.record_every < 0) throw InputError("record_every must be >= 0");
  if (!(o.max_velocity > 0)) throw InputError("max_velocity must be > 0");
  if (coulomb_ && o.substeps > 1 && o.fine_to >= o.fine_from)
    throw InputError("substeps > 1 (the intersample grid) is not available with Coulomb friction (its events move the state)");
  SimResult R;
  const auto n = loop_.plant.states(), nc = loop_.controller.states();
  const int N = loop_.N;
  constexpr int D = Eigen::Dynamic;
  if (N == 1 && n == 2 && nc == 1) Engine<2, 1, 1>::run(*this, spec_, o, R);
  else if (N == 1 && n == 3 && nc == 1) Engine<3, 1, 1>::run(*this, spec_, o, R);
  else if (N == 1 && n == 4 && nc == 1) Engine<4, 1, 1>::run(*this, spec_, o, R);
  else if (N == 1 && n == 2 && nc == 2) Engine<2, 2, 1>::run(*this, spec_, o, R);
  else if (N == 2 && n == 6 && nc == 4) Engine<6, 4, 2>::run(*this, spec_, o, R);
  else Engine<D, D, D>::run(*this, spec_, o, R);
  R.summary.step_matrix_radius = std::max(p1_.radius, p2_.radius);
  return R;
}

// ---------------------------------------------------------------------------------------
namespace {

// Half the peak-to-peak of y[a, b).
double half_range(const std::vector<double>& y, size_t a, size_t b) {
  double lo = y[a], hi = y[a];
  for (size_t i = a; i < b; ++i) {
    lo = std::min(lo, y[i]);
    hi = std::max(hi, y[i]);
  }
  return 0.5 * (hi - lo);
}

// The shortest period P >= 2 with which the second half repeats exactly (within 1e-6 of the
// amplitude a2); 0 when there is none.
size_t exact_period(const std::vector<double>& y, double a2) {
  const size_t n = y.size(), h = n / 2;
  for (size_t P = 2; P <= h / 2; ++P) {
    bool ok = true;
    for (size_t i = h + P; i < n && ok; ++i) ok = std::fabs(y[i] - y[i - P]) <= 1e-6 * a2;
    if (ok) return P;
  }
  return 0;
}

// The mean period (in samples) between upward crossings of the mean over the second half
// (quasi-periodic cycles); none below three crossings.
std::optional<double> crossing_period(const std::vector<double>& y) {
  const size_t n = y.size(), h = n / 2;
  double mean = 0;
  for (size_t i = h; i < n; ++i) mean += y[i];
  mean /= double(n - h);
  long first = -1, last = -1, count = 0;
  for (size_t i = h + 1; i < n; ++i)
    if (y[i - 1] < mean && y[i] >= mean) {
      if (first < 0) first = long(i);
      last = long(i);
      ++count;
    }
  if (count < 3) return std::nullopt;
  return double(last - first) / double(count - 1);
}

}  // namespace

std::optional<LimitCycle> detect_limit_cycle(const std::vector<double>& y, double T, std::string& trend) {
  const size_t n = y.size();
  if (n < 16) {
    trend = "rest";
    return std::nullopt;
  }
  double scale = 0;
  for (double x : y) scale = std::max(scale, std::fabs(x));
  const double a1 = half_range(y, 0, n / 2), a2 = half_range(y, n / 2, n);
  // At rest: the oscillation is below 1e-9 of the signal's size (or below 1e-15 absolute).
  if (a2 <= 1e-9 * scale + 1e-15) {
    trend = "rest";
    return std::nullopt;
  }
  if (a2 < 0.9 * a1) {
    trend = "decaying";
    return std::nullopt;
  }
  if (a2 > 1.1 * a1) {
    trend = "growing";
    return std::nullopt;
  }
  trend = "steady";
  LimitCycle lc;
  lc.amplitude = a2;
  // Exact repetition of the sampled sequence over the second half.
  if (const size_t P = exact_period(y, a2)) {
    lc.period_samples = long(P);
    lc.period = double(P) * T;
    return lc;
  }
  // Otherwise the mean period between upward crossings of the mean.
  const auto samples = crossing_period(y);
  if (!samples) return std::nullopt;  // no oscillation to speak of (a slow drift); trend stays "steady"
  lc.period = *samples * T;
  return lc;
}

}  // namespace hapstab::sim
