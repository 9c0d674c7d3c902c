// bench/loop_max.cpp -- `stability --scene S --max NAME` beyond one DOF (stability/loop_max.hpp):
// the certified supremum of an environment gain g (E scaled by g) of the contact scenes of
// multidof/example.hpp (N mass-damper devices, N 1-DOF operators) and of the 2-DOF loop of
// paper 000 Sec. VI with pure-mass devices (the scene of tests/stability/test_loop_max.cpp).
// BM_loop_max/<N>: the whole supremum (isolation, Krawczyk enclosure to 16 digits, the certified
// walk below it, decide_loop on both sides); counters `holds` (1: certified) and `cover` (the
// walk's eigenvalue enclosures). BM_decide/<N>: ONE certified verdict of the same loop
// (stability::decide_loop at g = 1/2), the unit a bisection on verdicts would pay ~50 times for
// 16 digits: the ratio BM_loop_max / BM_decide is the supremum's cost in verdicts.
#include <benchmark/benchmark.h>

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
    r = stability::max_parameter(at, rational(1, 2), "g", 16);
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

}  // namespace

BENCHMARK_MAIN();
