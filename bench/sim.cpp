// Sampled-data simulator: speed against accuracy (plots/sim_speed_accuracy.gp via bench/chart-sim)
// and the two speed targets of issue 7:
//   * 1-DOF wall with contact (device + sampled wall K + B(z-1)/(Tz), bias force): >= 50 M steps/s;
//   * 2-DOF loop with a 2x2 operator (examples/000_two_dof_loop.toml): >= 5 M steps/s.
// Methods on the same 1-DOF run (paper 002's bias wall with its hand, 2000 periods): exact ZOH
// (sim/), RK4 with n substeps per period, adaptive Odeint (Dormand-Prince 5(4)) at several
// tolerances. Error: max_k |x_k - x_ref,k| / max |x_ref| against the exact-ZOH recursion run in
// 50-digit arithmetic (the reference has no integration error and ~1e-48 rounding).
#include <benchmark/benchmark.h>

#include "keep.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <filesystem>

#include "hapstab/lti/discretize.hpp"
#include "hapstab/numeric/ball_expm.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"

using namespace hapstab;
using namespace hapstab::sim;

namespace {

using Q = rational;

// The 1-DOF problem: device m, b; hand mo, bo, ko; wall K (B = 0); bias F. (002_bias_wall.toml)
struct P1 {
  double m = 0.05, b = 1, mo = 0.2, bo = 2, ko = 500, K = 20000, F = 2, T = 1e-3;
};
constexpr long kSteps = 2000;

LoopSpec spec1(bool with_operator) {
  P1 p;
  LoopSpec s;
  s.T = Q(1, 1000);
  s.devices.push_back(mass_damper("dev", Q(1, 20), Q(1)));
  if (with_operator) s.operators.push_back(mass_spring_damper_operator("hand", 0, Q(1, 5), Q(2), Q(500)));
  // E = K + B(z-1)/(Tz) with B = 1/10 (one state)
  const Q K(20000), B(1, 10);
  s.environment = StateSpace<Q>{Mat<Q>::Zero(1, 1), Mat<Q>::Ones(1, 1), Mat<Q>::Constant(1, 1, -B / s.T),
                                Mat<Q>::Constant(1, 1, K + B / s.T), s.T};
  s.contact = {0};
  s.biases.push_back({0, Q(2), 0});
  (void)p;
  return s;
}

// Reference: the exact-ZOH recursion in mp50 (state [v, x, q]).
const std::vector<double>& reference() {
  static std::vector<double> ref = [] {
    using MP = mp50;
    const MP m = MP(1) / 20, b = 1, mo = MP(1) / 5, bo = 2, ko = 500, K = 20000, B = MP(1) / 10, F = 2, T = MP(1) / 1000;
    const MP M = m + mo;
    Mat<MP> A = Mat<MP>::Zero(3, 3), Bm = Mat<MP>::Zero(3, 1);
    A(0, 0) = -(b + bo) / M;
    A(0, 2) = -ko / M;
    A(1, 0) = 1;
    A(2, 0) = 1;
    Bm(0, 0) = 1 / M;
    auto zp = zoh_pair<MP>(A, Bm, T);
    Vec<MP> s = Vec<MP>::Zero(3);
    MP pprev = 0;
    std::vector<double> out;
    for (long k = 0; k <= kSteps; ++k) {
      out.push_back(double(s(1)));
      MP pk = s(1) > 0 ? s(1) : MP(0);
      MP u = -(K * pk + B * (pk - pprev) / T) + F;
      pprev = pk;
      s = (zp.Phi * s + zp.Gamma * u).eval();
    }
    return out;
  }();
  return ref;
}

double rel_error(const std::vector<double>& x) {
  const auto& r = reference();
  double dev = 0, scale = 0;
  for (size_t i = 0; i < r.size() && i < x.size(); ++i) {
    dev = std::max(dev, std::fabs(x[i] - r[i]));
    scale = std::max(scale, std::fabs(r[i]));
  }
  return dev / scale;
}

// ---- exact ZOH (the simulator), accuracy run + speed run
void BM_zoh(benchmark::State& st) {
  Simulator sim(spec1(true));
  SimOptions o;
  o.steps = kSteps;
  auto r = sim.run(o);
  const double err = rel_error(r.samples.x);
  SimOptions fast;
  fast.steps = st.range(0);
  fast.record_every = 0;
  fast.energy = st.range(1) != 0;
  for (auto _ : st) {
    auto rr = sim.run(fast);
    keep(rr.summary.max_velocity);
  }
  st.SetItemsProcessed(st.iterations() * st.range(0));
  st.counters["max_rel_error"] = err;
  st.counters["energy"] = double(fast.energy);
}
BENCHMARK(BM_zoh)->Args({2000000, 0})->Args({2000000, 1})->Unit(benchmark::kMillisecond)->Name("zoh/1dof_hand");

// The target case: 1-DOF wall with contact, no operator (device + wall only).
void BM_zoh_wall(benchmark::State& st) {
  Simulator sim(spec1(false));
  SimOptions fast;
  fast.steps = st.range(0);
  fast.record_every = 0;
  fast.energy = st.range(1) != 0;
  for (auto _ : st) {
    auto rr = sim.run(fast);
    keep(rr.summary.max_velocity);
  }
  st.SetItemsProcessed(st.iterations() * st.range(0));
  st.counters["target_steps_per_s"] = 50e6;
}
BENCHMARK(BM_zoh_wall)->Args({5000000, 0})->Args({5000000, 1})->Unit(benchmark::kMillisecond)->Name("zoh/1dof_wall_contact");

// 2-DOF loop with a 2x2 operator (the example scene).
void BM_zoh_2dof(benchmark::State& st) {
  auto sc = scene::load_scene((std::filesystem::path(HAPSTAB_SOURCE_DIR) / "examples" / "000_two_dof_loop.toml").string());
  Simulator sim(sc.loop);
  SimOptions fast;
  fast.steps = st.range(0);
  fast.record_every = 0;
  fast.energy = st.range(1) != 0;
  fast.max_velocity = 1e300;
  for (auto _ : st) {
    auto rr = sim.run(fast);
    keep(rr.summary.max_velocity);
  }
  st.SetItemsProcessed(st.iterations() * st.range(0));
  st.counters["target_steps_per_s"] = 5e6;
  st.counters["states"] = double(sim.loop().plant.states() + sim.loop().controller.states());
}
BENCHMARK(BM_zoh_2dof)->Args({1000000, 0})->Args({1000000, 1})->Unit(benchmark::kMillisecond)->Name("zoh/2dof_2x2_operator");

// ---- RK4 with n substeps per period (fixed-size, hand-written: the usual alternative)
struct Rk4 {
  double M = 0.25, bt = 3, ko = 500, K = 20000, B = 0.1, F = 2, T = 1e-3;
  double run(long steps, int n, std::vector<double>* out) const {
    double v = 0, x = 0, q = 0, pprev = 0;
    const double h = T / n;
    for (long k = 0; k <= steps; ++k) {
      if (out) out->push_back(x);
      if (k == steps) break;
      const double pk = x > 0 ? x : 0;
      const double u = -(K * pk + B * (pk - pprev) / T) + F;
      pprev = pk;
      for (int i = 0; i < n; ++i) {
        auto f = [&](double v_, double q_) { return (u - bt * v_ - ko * q_) / M; };
        const double k1v = f(v, q), k1x = v;
        const double k2v = f(v + 0.5 * h * k1v, q + 0.5 * h * k1x), k2x = v + 0.5 * h * k1v;
        const double k3v = f(v + 0.5 * h * k2v, q + 0.5 * h * k2x), k3x = v + 0.5 * h * k2v;
        const double k4v = f(v + h * k3v, q + h * k3x), k4x = v + h * k3v;
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        const double dx = h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        x += dx;
        q += dx;
      }
    }
    return x + v + q;
  }
};
void BM_rk4(benchmark::State& st) {
  Rk4 r;
  keep(r);
  const int n = int(st.range(0));
  std::vector<double> xs;
  r.run(kSteps, n, &xs);
  const double err = rel_error(xs);
  for (auto _ : st) {
    benchmark::DoNotOptimize(r.run(200000, n, nullptr));  // an rvalue: the const& overload is safe
  }
  st.SetItemsProcessed(st.iterations() * 200000);
  st.counters["max_rel_error"] = err;
  st.counters["substeps"] = n;
}
BENCHMARK(BM_rk4)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond)->Name("rk4");

// ---- adaptive Odeint (Dormand-Prince 5(4)), restarted at every sample (the force jumps there)
void odeint_run(long steps, double tol, std::vector<double>* out) {
  using namespace boost::numeric::odeint;
  using S = std::array<double, 3>;
  const Rk4 p;
  double u = 0;
  auto rhs = [&](const S& s, S& d, double) {
    d[0] = (u - p.bt * s[0] - p.ko * s[2]) / p.M;
    d[1] = s[0];
    d[2] = s[0];
  };
  S s{0, 0, 0};
  double pprev = 0;
  // relative tolerance tol, absolute tol x 1e-6 (the state is x ~ 1e-4 m, v ~ 1e-2 m/s): an
  // absolute tolerance equal to the relative one made tol = 1e-14 a relative 1e-10 per step on x,
  // and Odeint's error at "1e-14" 6e-9 (issue 41); now 1e-10
  auto stepper = make_controlled(tol * 1e-6, tol, runge_kutta_dopri5<S>());
  for (long k = 0; k <= steps; ++k) {
    if (out) out->push_back(s[1]);
    if (k == steps) break;
    const double pk = s[1] > 0 ? s[1] : 0;
    u = -(p.K * pk + p.B * (pk - pprev) / p.T) + p.F;
    pprev = pk;
    integrate_adaptive(stepper, rhs, s, k * p.T, (k + 1) * p.T, p.T / 4);
  }
}
void BM_odeint(benchmark::State& st) {
  const double tol = std::pow(10.0, -double(st.range(0)));
  std::vector<double> xs;
  odeint_run(kSteps, tol, &xs);
  const double err = rel_error(xs);
  for (auto _ : st) odeint_run(20000, tol, nullptr);
  st.SetItemsProcessed(st.iterations() * 20000);
  st.counters["max_rel_error"] = err;
  st.counters["tolerance"] = tol;
}
BENCHMARK(BM_odeint)->Arg(6)->Arg(9)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond)->Name("odeint");

}  // namespace

// ---- the set-up: the exact-ZOH step matrices, 50-digit Taylor (lti/discretize.hpp, the
// method before issue 15) against Arb's arb_mat_exp enclosure (numeric/ball_expm.hpp, what the
// simulator uses), on a chain of n masses and dampers (A n x n, B n x 2) at T = 1 ms.
// Counters: radius = the Arb enclosure's proven bound on |exact - double midpoint|.
MatQ chain(int n, MatQ& B) {
  MatQ A = MatQ::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = rational(-(i + 2), 3);
    if (i + 1 < n) A(i, i + 1) = rational(1, i + 1), A(i + 1, i) = rational(-7, i + 2);
  }
  B = MatQ::Zero(n, 2);
  B(0, 0) = 1;
  B(n - 1, 1) = rational(1, 10);
  return A;
}
void BM_zoh_setup(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const bool arb = st.range(1) == 1;
  MatQ B;
  const MatQ A = chain(n, B);
  const rational T(1, 1000);
  double radius = 0;
  for (auto _ : st) {
    if (arb) {
      auto z = zoh_enclosure(A, B, T);
      radius = std::max(z.Phi.radius, z.Gamma.radius);
      keep(z.Phi.mid);
    } else {
      Mat<mp50> Am(n, n), Bm(n, 2);
      for (Eigen::Index i = 0; i < A.size(); ++i) Am.data()[i] = to_real<mp50>(A.data()[i]);
      for (Eigen::Index i = 0; i < B.size(); ++i) Bm.data()[i] = to_real<mp50>(B.data()[i]);
      auto z = zoh_pair<mp50>(Am, Bm, to_real<mp50>(T));
      keep(z.Phi);
    }
  }
  st.counters["radius"] = radius;
  st.SetLabel(arb ? "arb_mat_exp enclosure" : "mp50 Taylor (before)");
}
BENCHMARK(BM_zoh_setup)->ArgsProduct({{4, 16, 32}, {0, 1}})->Unit(benchmark::kMillisecond)->Name("zoh_setup");

// ---- the simulator's set-up (issue 33): Simulator::Simulator on an N-device loop shaped like
// bench/contact_scene.py's (N mass-dampers 1/(m s + b), N one-port operators with two states,
// 0.1 (s^2 + 5 s + 10)/(s^2 + s + 1), an N x N discrete environment: a wall K_i + B_i (z - 1)/(T z)
// per DOF plus a rank-one coupling of all DOFs), T = 10 ms, with a fractional delay (two pieces,
// energy Gram matrices for both). Counters: states of the plant, radius = Piece::radius.
LoopSpec n_device_loop(int N) {
  LoopSpec s;
  s.T = Q(1, 100);
  s.delay = Q(1, 300);
  for (int i = 0; i < N; ++i) s.devices.push_back(mass_damper("d" + std::to_string(i), Q(1, 10), Q(137, 100)));
  for (int i = 0; i < N; ++i) {  // Z = 1/10 + (2/5 s + 9/10)/(s^2 + s + 1)
    OperatorBlock o;
    o.name = "H" + std::to_string(i);
    o.ports = {i};
    Mat<Q> A(2, 2), B(2, 1), C(1, 2), D(1, 1);
    A << 0, 1, -1, -1;
    B << 0, 1;
    C << Q(9, 10), Q(2, 5);
    D << Q(1, 10);
    o.Z = StateSpace<Q>{A, B, C, D, 0};
    s.operators.push_back(o);
  }
  Mat<Q> Ae = Mat<Q>::Zero(N, N), Be = Mat<Q>::Identity(N, N), Ce = Mat<Q>::Zero(N, N), De(N, N);
  for (int i = 0; i < N; ++i) {
    const Q K(500 + 100 * (i % 4)), B(1 + i % 3);
    Ce(i, i) = -B / s.T;
    for (int j = 0; j < N; ++j) De(i, j) = Q(-1, 10 * N) + (i == j ? K + B / s.T : Q(0));
  }
  s.environment = StateSpace<Q>{Ae, Be, Ce, De, s.T};
  return s;
}
void BM_sim_setup(benchmark::State& st) {
  const LoopSpec spec = n_device_loop(int(st.range(0)));
  double radius = 0, states = 0;
  for (auto _ : st) {
    Simulator sim(spec);
    radius = std::max(sim.piece_before().radius, sim.piece_after().radius);
    states = double(sim.loop().plant.states());
    keep(radius);
  }
  st.counters["radius"] = radius;
  st.counters["states"] = states;
}
BENCHMARK(BM_sim_setup)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond)->Name("sim_setup");

BENCHMARK_MAIN();
