// bench/delay.cpp -- delays of teleoperation scale (issue 43): speed against accuracy of the
// methods for b* (paper 001, (45)) and for sup K (stability --max) against the delay n, in one run.
//   BM_bound/<method>/<n>: the wall H = 10 + 5 (z - 1)/(T z), T = 1 ms (an interior maximum for
//     n up to ~1000, where the grid must resolve the e^{-j n theta} oscillation); method 0 the exact
//     path (the degree-n polynomial, n <= 100), 1 the long-delay path (certified, 30 digits; boxes
//     pruned in double intervals, Arb near the maximum: issue 48), 5 the same path in Arb balls
//     alone (before issue 48), 2 the fast path (double), 3 and 4 grids of 10^4 and 10^6 points (double).
//   BM_bound_resonant/<method>/<n>: the same methods on the resonant H = (z - 1)/(z^2 - 2 r (3/10) z
//     + r^2), r = 1 - 10^-5 (issue 48's case: a peak 1e-5 wide that grids miss).
//   BM_kmax/<method>/<n>: device 1/(s^2 + s) behind a ZOH, wall K + 0.5 (z - 1)/(T z); method 0 the
//     polynomial path (n <= 60), 1 the long-delay path (certified, 20 digits; arcs decided in double
//     intervals first), 4 the same in Arb balls alone (before issue 48), 2 and 3 grids of 10^4 and
//     10^6 points (double, max_gain_grid).
// Counters: rel_err against a reference with more precision (b*: the long-delay path at 45 digits;
// digits = -log10(rel_err), 16 where the error is below the reference's own;
// sup K: at 40 digits; both certified enclosures far narrower than any error shown), n, method.
// Targets (reported, not asserted; issue 43): bound --delay 1000 <= 1 s, 10000 <= 10 s;
// stability --max K --delay 1000 <= 2 s, 10000 <= 20 s (whole process).
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <optional>

#include "keep.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/bound_detail.hpp"
#include "hapstab/stability/long_delay.hpp"
#include "hapstab/stability/sampled_loop.hpp"

using namespace hapstab;

namespace {

const rational kT(1, 1000);

const char* const kWall = "10 + 5*(z-1)/(T*z)";
const char* const kResonant = "(z-1)/(z^2 - 2*(99999/100000)*(3/10)*z + (99999/100000)^2)";

passivity::BoundProblem problem(const char* H, int n) {
  ParseOptions o;
  o.variable = 'z';
  o.T = kT;
  passivity::BoundProblem p;
  p.H = parse_tf(H, o).H;
  p.T = kT;
  p.delay = n;
  return p;
}

stability::Loop loop(int n, stability::LoopPath path) {
  stability::Loop l = stability::mass_damper_wall(rational(1), rational(1), rational(1, 2), kT, n);
  l.path = path;
  return l;
}

double rel(double v, const rational& ref) { return std::max(std::abs(v - to_real<double>(ref)) / to_real<double>(abs(ref)), 1e-40); }

const rational& bound_ref(const char* H, int n) {
  static std::map<std::pair<const char*, int>, rational> refs;
  auto it = refs.find({H, n});
  if (it == refs.end())
    it = refs.emplace(std::make_pair(H, n), passivity::bound_certified(problem(H, n), 45, passivity::BoundPath::long_delay).value).first;
  return it->second;
}

const rational& kmax_ref(int n) {
  static std::map<int, rational> refs;
  auto it = refs.find(n);
  if (it == refs.end()) {
    const stability::MaxGain g = stability::max_gain(loop(n, stability::LoopPath::long_delay), 40);
    it = refs.emplace(n, (g.enclosure.lo + g.enclosure.hi) / 2).first;
  }
  return it->second;
}

void bound_methods(benchmark::State& st, const char* H) {
  const int method = static_cast<int>(st.range(0)), n = static_cast<int>(st.range(1));
  const passivity::BoundProblem p = problem(H, n);
  double v = 0;
  for (auto _ : st) {
    switch (method) {
      case 0: v = passivity::bound_certified(p, 30, passivity::BoundPath::exact).value_double(); break;
      case 1: v = passivity::bound_certified(p, 30, passivity::BoundPath::long_delay).value_double(); break;
      case 5: v = passivity::detail::certified_long_delay(p, 30, false).value_double(); break;
      case 2: v = passivity::bound(p, passivity::Method::fast).value_double(); break;
      default: v = passivity::bound_grid(p, method == 3 ? 10000 : 1000000).value_double(); break;
    }
    keep(v);
  }
  const double e = rel(v, bound_ref(H, n));
  st.counters["rel_err"] = e;
  st.counters["digits"] = std::min(16.0, -std::log10(e));
  st.counters["n"] = n;
  st.counters["method"] = method;
}
void BM_bound(benchmark::State& st) { bound_methods(st, kWall); }
void BM_bound_resonant(benchmark::State& st) { bound_methods(st, kResonant); }
BENCHMARK(BM_bound)->ArgsProduct({{0}, {1, 10, 30, 60, 100}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bound)->ArgsProduct({{1, 5, 2, 3, 4}, {1, 10, 100, 1000, 10000}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bound_resonant)->ArgsProduct({{1, 5, 3, 4}, {1000, 10000}})->Unit(benchmark::kMillisecond);

void BM_kmax(benchmark::State& st) {
  const int method = static_cast<int>(st.range(0)), n = static_cast<int>(st.range(1));
  double v = 0;
  for (auto _ : st) {
    if (method <= 1 || method == 4) {
      std::optional<stability::detail::ArbOnly> arb_only;  // method 4: Arb for every arc
      if (method == 4) arb_only.emplace();
      const stability::MaxGain g =
          stability::max_gain(loop(n, method == 0 ? stability::LoopPath::polynomial : stability::LoopPath::long_delay), 20);
      v = to_real<double>(g.enclosure.lo);
    } else {
      const auto g = stability::max_gain_grid(loop(n, stability::LoopPath::automatic), method == 2 ? 10000 : 1000000);
      v = g ? g->K : NAN;
    }
    keep(v);
  }
  st.counters["rel_err"] = std::isfinite(v) ? rel(v, kmax_ref(n)) : 1.0;
  st.counters["digits"] = std::min(16.0, -std::log10(st.counters["rel_err"].value));
  st.counters["n"] = n;
  st.counters["method"] = method;
}
BENCHMARK(BM_kmax)->ArgsProduct({{0}, {1, 10, 30, 60}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_kmax)->ArgsProduct({{1, 4, 2, 3}, {1, 10, 100, 1000, 10000}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
