// bench/multidof.cpp -- paper 000: speed of the Theorem 5 analysis and the Theorem 6 design on
// the Sec. VI example (targets: analysis <= 10 ms, design <= 2 s), DSDP beside CSDP, and the
// scaling with N = 1..16 devices (1-3 DOF each, sizes 1,2,3,1,2,3,...: m = 1..31) for two
// structures:
//   case-i-like  : ONE operator using every device (Gamma = g I)
//   case-ii-like : one operator per device (Gamma block-scalar per device)
// The scaling runs Theorem 5's certified verdict only (analyze(..., AnalysisMode::
// stability_only): Q_E, Q_V eliminated exactly, the constructed point re-checked exactly; the
// full margin program has ~1500 variables at m = 31 and takes minutes there).
// Random environments: Fig. 5-type (one mass, m contacts; M in [0.1, 1], k in [100, 2000],
// B in [1, 10], k_i in [100, 1000], B_i in [0.5, 3]), backward Euler T = 0.01, exact direct
// state space (m + 2 states), and with probability 1/2 a per-device force-gain miscalibration
// E := S E, S = blockdiag(s_j I) with s_j in [0.75, 2.25] (a non-reciprocal environment). The same
// `samples` = 10 environments per N, each analysed and timed. Counters: m, `time_median_ms`,
// `time_min_ms`, `time_max_ms` over them (an environment whose X E(1) cannot be symmetric is
// certified infeasible WITHOUT an SDP: the fast end of the spread), `certified_count` and
// `fraction` certified stable (exact certificate) -- how much the structure reduces conservatism.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <sstream>

#include "hapstab/multidof/design.hpp"
#include "hapstab/multidof/example.hpp"
#include "hapstab/multidof/scene_multidof.hpp"

using namespace hapstab;
using namespace hapstab::multidof;

namespace {

rational rnd(std::mt19937& g, int lo, int hi, int den) {
  std::uniform_int_distribution<int> d(lo * den, hi * den);
  return rational(d(g), den);
}

Problem random_problem(int N, bool one_operator, unsigned seed) {
  std::mt19937 g(seed);
  std::vector<int> sizes;
  for (int j = 0; j < N; ++j) sizes.push_back(1 + j % 3);
  int m = 0;
  for (int s : sizes) m += s;
  MechanicalEnvironment env;
  env.M = rnd(g, 1, 10, 1) / 10;
  env.k = rnd(g, 100, 2000, 1);
  env.B = rnd(g, 1, 10, 2);
  for (int i = 0; i < m; ++i) {
    env.kc.push_back(rnd(g, 100, 1000, 1));
    env.Bc.push_back(rnd(g, 1, 6, 2) / 2);
  }
  Problem pb;
  pb.E = mechanical_environment_be_ss(env, rational(1, 100));
  if (std::uniform_int_distribution<int>(0, 1)(g)) {
    MatQ S = MatQ::Zero(m, m);
    int off = 0;
    for (int s : sizes) {
      const rational sj = rnd(g, 1, 4, 4) / 2 + rational(1, 4);
      for (int k = 0; k < s; ++k) S(off + k, off + k) = sj;
      off += s;
    }
    pb.E.C = S * pb.E.C;
    pb.E.D = S * pb.E.D;
  }
  const rational d("137/100");
  if (one_operator) {
    Operator o{"H", m, {}};
    for (int j = 0; j < N; ++j) o.devices.push_back(device("d" + std::to_string(j), sizes[static_cast<size_t>(j)], d));
    pb.structure.operators = {o};
  } else {
    for (int j = 0; j < N; ++j)
      pb.structure.operators.push_back(
          Operator{"H" + std::to_string(j), sizes[static_cast<size_t>(j)], {device("d" + std::to_string(j), sizes[static_cast<size_t>(j)], d)}});
  }
  pb.coupling.mbar = sizes;
  pb.coupling.nbar.assign(sizes.size(), 1);
  return pb;
}

void BM_AnalyzeExample(benchmark::State& st) {
  const auto pb = example::problem(static_cast<int>(st.range(0)), st.range(1) != 0);
  lmi::Options o;
  o.backend = st.range(2) ? lmi::Backend::csdp : lmi::Backend::dsdp;
  AnalysisResult r;
  for (auto _ : st) r = analyze(pb, o);
  st.counters["feasible"] = r.verdict.holds();
  st.counters["certified"] = r.verdict.proven();
  st.counters["margin"] = r.margin;
  st.SetLabel(std::string(st.range(2) ? "csdp" : "dsdp") + (st.range(0) == 1 ? " case i" : " case ii") +
              (st.range(1) ? " perturbed" : " nominal"));
}
BENCHMARK(BM_AnalyzeExample)
    ->Args({1, 0, 0})->Args({1, 1, 0})->Args({2, 0, 0})->Args({2, 1, 0})->Args({1, 0, 1})->Args({2, 1, 1})
    ->Unit(benchmark::kMillisecond);

void BM_DesignExample(benchmark::State& st) {
  const auto pb = example::problem(static_cast<int>(st.range(0)), st.range(1) != 0);
  DesignResult r;
  for (auto _ : st) r = design(pb);
  st.counters["feasible"] = r.verdict.holds();
  st.counters["certified"] = r.verdict.holds() && r.verdict.proven();
  st.counters["iterations"] = r.iterations;
  st.SetLabel(std::string(st.range(0) == 1 ? "case i" : "case ii") + (st.range(1) ? " perturbed" : " nominal"));
}
BENCHMARK(BM_DesignExample)->Args({1, 0})->Args({2, 1})->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Scaling(benchmark::State& st) {
  const int N = static_cast<int>(st.range(0));
  const bool one = st.range(1) == 0;
  // every N gets the same n random environments, each timed: the chart shows the median time with
  // its min-max spread and the fraction certified with its 95% Wilson interval (one environment
  // per N made the times jump 0.2-50 ms with the environment, not with N)
  constexpr int samples = 10;
  std::vector<double> ms;
  int certified = 0, m = 0;
  for (auto _ : st) {
    ms.clear();
    certified = 0;
    for (int s = 0; s < samples; ++s) {
      const auto ps = random_problem(N, one, 7u * static_cast<unsigned>(s) + 31u * static_cast<unsigned>(N));
      m = ps.structure.m();
      const auto t0 = std::chrono::steady_clock::now();
      const auto rs = analyze(ps, {}, AnalysisMode::stability_only);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      certified += rs.verdict.holds() && rs.verdict.proven();
    }
  }
  std::sort(ms.begin(), ms.end());
  st.counters["m"] = m;
  st.counters["samples"] = samples;
  st.counters["certified_count"] = certified;
  st.counters["fraction"] = static_cast<double>(certified) / samples;
  st.counters["time_median_ms"] = (ms[samples / 2 - 1] + ms[samples / 2]) / 2;
  st.counters["time_min_ms"] = ms.front();
  st.counters["time_max_ms"] = ms.back();
  st.SetLabel(one ? "case-i structure (one operator)" : "case-ii structure (one operator per device)");
}
BENCHMARK(BM_Scaling)
    ->ArgsProduct({{1, 2, 3, 4, 6, 8, 10, 12, 16}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// ---- the contact scenes of bench/contact_scene.py (example::contact_scene: N devices, N 1-DOF
// operators, paper 000's Fig. 5 environment with N contact points on one mass, case ii), the whole certified
// analysis (full mode: the margin program, then the least dissipative coupling), per stage:
// realisation (scene -> minimal E), SDP, certificate (Ê, facial reduction, exact checks), for
// the built-in IPM (auto's first choice) beside DSDP (N <= 16: 226 s at N = 32).
// mode 0: automatic (the structured KYP path of analysis.hpp from 8 DOF on), 1: DSDP (generic
// programs), 2: the generic programs on the built-in IPM (AnalysisPath::generic_sdp: the path
// before issue 33; N <= 48 here, about 30 s there, more than 300 s at N = 64).
void BM_ContactScene(benchmark::State& st) {
  const int N = static_cast<int>(st.range(0));
  const int mode = static_cast<int>(st.range(1));
  lmi::Options opt;
  if (mode == 1) opt.backend = lmi::Backend::dsdp;
  const AnalysisPath path = mode == 2 ? AnalysisPath::generic_sdp : AnalysisPath::automatic;
  const std::string text = example::contact_scene(N);
  double realisation = 0, sdp = 0, certificate = 0;
  AnalysisResult r;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto sp = problem_from_scene(scene::parse_scene(text, "contact scene"));
    realisation = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r = analyze(sp.problem, opt, AnalysisMode::full, path);
    sdp = r.sdp_seconds;
    certificate = r.seconds - r.sdp_seconds;
  }
  st.counters["realisation_s"] = realisation;
  st.counters["sdp_s"] = sdp;
  st.counters["certificate_s"] = certificate;
  st.counters["certified"] = r.verdict.proven() && r.verdict.holds();
  st.counters["least_dissipative_norm"] = r.Q_V_min_norm;
  st.counters["least_dissipative_certified"] = r.min_point_certified;
  st.SetLabel(mode == 1 ? "DSDP" : mode == 2 ? "generic SDP, built-in IPM (before)" : "automatic (structured KYP path)");
}
BENCHMARK(BM_ContactScene)
    ->Args({2, 0})->Args({4, 0})->Args({8, 0})->Args({16, 0})->Args({24, 0})->Args({32, 0})->Args({48, 0})
    ->Args({64, 0})->Args({96, 0})->Args({128, 0})
    ->Args({2, 1})->Args({4, 1})->Args({8, 1})->Args({16, 1})
    ->Args({2, 2})->Args({4, 2})->Args({8, 2})->Args({16, 2})->Args({24, 2})->Args({32, 2})->Args({48, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Theorem 6 on the contact scene with one first-order SISO coupling block per device: mode 0 automatic (the block-wise path of design.hpp from 8 DOF
// on), 1 the generic CCL (DesignPath::generic_sdp: the path before issue 33; 5.7 s at N = 8,
// 55 s at N = 16, more than 15 min at N = 32). Library time only (the CLI also simulates).
void BM_ContactDesign(benchmark::State& st) {
  const int N = static_cast<int>(st.range(0));
  DesignOptions opt;
  opt.path = st.range(1) == 1 ? DesignPath::generic_sdp : DesignPath::automatic;
  const auto sp = problem_from_scene(scene::parse_scene(example::contact_scene(N), "contact scene"));
  DesignResult r;
  for (auto _ : st) r = design(sp.problem, opt);
  st.counters["certified"] = r.verdict.holds() && r.verdict.proven();
  st.counters["iterations"] = r.iterations;
  st.SetLabel(st.range(1) == 1 ? "generic CCL (before)" : "automatic (block-wise from 8 DOF)");
}
BENCHMARK(BM_ContactDesign)
    ->Args({2, 0})->Args({4, 0})->Args({8, 0})->Args({16, 0})->Args({32, 0})->Args({64, 0})->Args({128, 0})
    ->Args({2, 1})->Args({4, 1})->Args({8, 1})->Args({16, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
