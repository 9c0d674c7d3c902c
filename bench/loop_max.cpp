// bench/loop_max.cpp -- `stability --scene S --max NAME` beyond one DOF (stability/loop_max.hpp):
// the certified supremum of an environment gain g (E scaled by g) of the contact scenes of
// multidof/example.hpp (N mass-damper devices, N 1-DOF operators) and of the 2-DOF loop of
// paper 000 Sec. VI with pure-mass devices (the scene of tests/stability/test_loop_max.cpp).
// BM_loop_max/<N>: the whole supremum (isolation, Krawczyk enclosure to 16 digits, the certified
// walk below it, decide_loop on both sides); counters `holds` (1: certified) and `cover` (the
// walk's eigenvalue enclosures). BM_decide/<N>: ONE certified verdict of the same loop
// (stability::decide_loop at g = 1/2), the unit a bisection on verdicts would pay ~50 times for
// 16 digits: the ratio BM_loop_max / BM_decide is the supremum's cost in verdicts.
// BM_theorem5_max/<N>: Theorem 5's largest coupling stiffness kc (conservatism/theorem5_max.hpp: the
// scene with the coupling V27/kc of conservatism/example.hpp, bisection on certified Theorem-4
// verdicts to 1 digit, as the figure multidof_conservatism: finer, a midpoint lands where one 8-DOF
// program's exact infeasibility certificate takes minutes), counter `programs` (LMI programs solved); BM_theorem5_at/<N>: ONE such
// verdict; BM_exact_by_verdicts/<N>: the same scene's stable -> NOT stable change in kc by
// certified decide_loop verdicts (6 digits: not affine in kc, so the certified crossing of
// BM_loop_max does not apply), counter `verdicts`.
#include <benchmark/benchmark.h>

#include "hapstab/conservatism/example.hpp"
#include "hapstab/conservatism/theorem5_max.hpp"
#include "hapstab/multidof/example.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/stability/loop_as_written.hpp"
#include "hapstab/stability/loop_max.hpp"

using namespace hapstab;

namespace {

std::string with_gain(std::string toml) {  // [parameters] g = 1 and [environment] gain = "g"
  auto put = [&](const std::string& after, const std::string& line) {
    const size_t at = toml.find(after);
    if (at != std::string::npos) toml.insert(at + after.size(), line);
  };
  put("[parameters]\n", "g = \"1\"\n");
  put("[environment]\n", "gain = \"g\"\n");
  return toml;
}

stability::LoopAt family(int N) {
  const std::string text = with_gain(multidof::example::contact_scene(N));
  return [text](const rational& g) { return scene::parse_scene(text, "contact", {{"g", g}}).loop; };
}

void BM_loop_max(benchmark::State& state) {
  const stability::LoopAt at = family(static_cast<int>(state.range(0)));
  stability::LoopMax r;
  for (auto _ : state) {
    r = stability::max_parameter(at, rational(1, 2), "g", 2, 16);  // no coupling, gain = "g": affine outright (scene/parameter_degree.hpp)
    benchmark::DoNotOptimize(r.sup.hi);
  }
  state.counters["holds"] = r.outcome == Outcome::holds ? 1 : 0;
  state.counters["cover"] = static_cast<double>(r.cover_intervals);
}
BENCHMARK(BM_loop_max)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_decide(benchmark::State& state) {
  const sim::LoopSpec s = family(static_cast<int>(state.range(0)))(rational(1, 2));
  for (auto _ : state) benchmark::DoNotOptimize(stability::decide_loop(s).stable);
}
BENCHMARK(BM_decide)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

conservatism::SceneAt coupled(int N) {  // V = V27 / kc on every device
  const std::string text = conservatism::with_coupling27(multidof::example::contact_scene(N), N, false);
  return [text](const rational& kc) { return scene::parse_scene(text, "contact", {{"kc", kc}}); };
}

void BM_theorem5_max(benchmark::State& state) {
  const conservatism::SceneAt at = coupled(static_cast<int>(state.range(0)));
  conservatism::VerdictBracket b;
  for (auto _ : state) {
    b = conservatism::theorem5_max(at, rational(1000), "kc", 1);
    benchmark::DoNotOptimize(b.lo);
  }
  state.counters["holds"] = b.lo && b.hi ? 1 : 0;
  state.counters["programs"] = static_cast<double>(b.steps.size());
}
BENCHMARK(BM_theorem5_max)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_theorem5_at(benchmark::State& state) {
  const scene::Scene sc = coupled(static_cast<int>(state.range(0)))(rational(1000));
  for (auto _ : state) benchmark::DoNotOptimize(conservatism::theorem5_at(sc).yes);
}
BENCHMARK(BM_theorem5_at)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

void BM_exact_by_verdicts(benchmark::State& state) {
  const conservatism::SceneAt at = coupled(static_cast<int>(state.range(0)));
  conservatism::VerdictBracket b;
  for (auto _ : state) {
    b = conservatism::exact_max_by_verdicts([&](const rational& kc) { return at(kc).loop; }, rational(1000), "kc", 6);
    benchmark::DoNotOptimize(b.lo);
  }
  state.counters["verdicts"] = static_cast<double>(b.steps.size());
}
BENCHMARK(BM_exact_by_verdicts)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
