// bench/stability.cpp -- `stability --max` (stability/sampled_loop.hpp): time against digits.
// BM_max/<case>/<digits>: the largest stable stiffness of a haptic loop to 10..100 digits; the
// counters are the certified relative width of the enclosure (`certified_width`) and the
// relative error of its midpoint against the same computation at 300 digits (`rel_err`).
// Cases: 0 = device 1/(s^2 + s), spring, n = 0; 1 = damper wall B = 2, n = 3; 2 = heavy damping
// (m = 0.001, bT/m = 1), n = 1; 3 = pure mass 1/s^2 with B = 2 (exact data).
#include <benchmark/benchmark.h>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/stability/sampled_loop.hpp"

using namespace hapstab;

namespace {

stability::Loop loop_of(int which) {
  const rational T(1, 1000);
  switch (which) {
    case 0: return stability::mass_damper_wall(1, 1, 0, T, 0);
    case 1: return stability::mass_damper_wall(1, 1, 2, T, 3);
    case 2: return stability::mass_damper_wall(rational(1, 1000), 1, rational(1, 2), T, 1);
    default: return stability::mass_damper_wall(1, 0, 2, T, 0);
  }
}

double rel(const rational& x, const rational& ref) { return to_real<double>(abs(x - ref) / ref); }

void BM_max(benchmark::State& state) {
  const stability::Loop loop = loop_of(static_cast<int>(state.range(0)));
  const int digits = static_cast<int>(state.range(1));
  stability::MaxGain g;
  for (auto _ : state) {
    g = stability::max_gain(loop, digits);
    benchmark::DoNotOptimize(g.enclosure.lo);
  }
  const stability::MaxGain ref = stability::max_gain(loop, 300);
  const rational mid = (g.enclosure.lo + g.enclosure.hi) / 2, ref_mid = (ref.enclosure.lo + ref.enclosure.hi) / 2;
  state.counters["rel_err"] = std::max(rel(mid, ref_mid), 1e-300);
  state.counters["certified_width"] = std::max(rel(g.enclosure.hi, g.enclosure.lo), 1e-300);
  state.counters["digits"] = digits;
  state.counters["precision_bits"] = static_cast<double>(g.precision_bits);
  state.SetLabel(g.crossing);
}
BENCHMARK(BM_max)->ArgsProduct({{0, 1, 2, 3}, {10, 15, 20, 30, 50, 70, 100}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
