// bench/contact.cpp -- paper 002: the cost of deciding the wedge criterion (25) and Tsypkin (21)
// exactly over all of theta in [0, pi] against grid checks, and the speed of the Lur'e
// simulation of Fig. 5.
//   BM_verdict/i/s      exact verdict only (wedge_holds: certified interval fast path, Sturm
//                       fallback), H of order 2..6 as given (s=0), at 0.9 k* (s=1), 0.999 k* (s=2)
//   BM_certified/i/D    verdict + certified margin and k* to D digits (analyze_contact)
//   BM_grid/i/N         N-point double grid of the wedge margin
//   BM_lure/n           double simulation of Fig. 5, order n, steps/s as a counter
// Counters: rel_err of the margin against the 40-digit certified value (enclosure < 1e-40
// wide, so rel_err below 1e-35 reads as exact); the grid's error is its sampling error.
// Targets (reported, not asserted): certified wedge check for order <= 6 in <= 1 ms;
// >= 50 M steps/s for order 2 (a plain Python loop: ~0.4 M steps/s).
#include <benchmark/benchmark.h>

#include "keep.hpp"

#include <cmath>

#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"

using namespace hapstab;
using namespace hapstab::contact;

namespace {

const char* kCases[] = {
    "0.3*(z+1)/(z^2-0.5*z+0.1)",                                   // order 2
    "0.05*(z+1)/((z-0.999)*(z-0.5))/z",                            // order 3, near-integrator + delay
    "(-44/25*z + 23/25)/(z^2 + 2451/2500*z + 1849/2500)/z^2",      // order 4
    "2*(z+0.5)*(z-0.2)/((z^2-1.6*z+0.89)*(z^2+0.3*z+0.4)*(z-0.1))",  // order 5, resonance
    "0.3*(z+1)/(z^2-0.5*z+0.1)/(z-0.2)/(z^2+0.3*z+0.4)/(z-0.7)",   // order 6
};

TransferFunction H_of(int i) {
  ParseOptions po;
  po.variable = 'z';
  po.T = 1;
  return parse_tf(kCases[i], po);
}

double ref_margin(int i) {
  static std::vector<double> r;
  if (r.empty())
    for (size_t k = 0; k < std::size(kCases); ++k)
      r.push_back(static_cast<double>(mpfloat<50>(analyze_contact(H_of(static_cast<int>(k)), 40).wedge.margin.value)));
  return r[i];
}

// scale 0: H as given (the wedge fails for most); 1: 0.9 k*_wedge H (holds, margin 0.1);
// 2: 0.999 k*_wedge H (holds, margin 1e-3: the fast path needs finer boxes)
TransferFunction scaled(int i, int which) {
  TransferFunction H = H_of(i);
  if (which == 0) return H;
  ContactAnalysis a = analyze_contact(H, 10);
  if (a.wedge.gain_infinite) return H;
  const rational f = which == 1 ? rational(9, 10) : rational(999, 1000);
  const rational k = f * exact_rational(static_cast<double>(mpfloat<30>(a.wedge.max_gain.enclosure->lo)));
  H.H = H.H * RatFun(k);
  return H;
}

void BM_verdict(benchmark::State& st) {
  const int i = static_cast<int>(st.range(0));
  TransferFunction H = scaled(i, static_cast<int>(st.range(1)));
  for (auto _ : st) {
    bool h = wedge_holds(H);
    keep(h);
  }
  st.SetLabel("order " + std::to_string(H.den().degree()));
}

void BM_certified(benchmark::State& st) {
  const int i = static_cast<int>(st.range(0)), d = static_cast<int>(st.range(1));
  TransferFunction H = H_of(i);
  double m = 0;
  for (auto _ : st) {
    ContactAnalysis a = analyze_contact(H, d);
    m = static_cast<double>(mpfloat<50>(a.wedge.margin.value));
    keep(m);
  }
  const double ref = ref_margin(i);
  st.counters["rel_err"] = std::abs(m - ref) / std::abs(ref);
  st.SetLabel("order " + std::to_string(H.den().degree()));
}

void BM_grid(benchmark::State& st) {
  const int i = static_cast<int>(st.range(0)), n = static_cast<int>(st.range(1));
  TransferFunction H = H_of(i);
  double m = 0;
  for (auto _ : st) {
    m = grid_margin(H, n, true).value;
    keep(m);
  }
  const double ref = ref_margin(i);
  st.counters["rel_err"] = std::abs(m - ref) / std::abs(ref);
  st.SetLabel("order " + std::to_string(H.den().degree()));
}

void BM_lure(benchmark::State& st) {
  const int order = static_cast<int>(st.range(0));
  const char* e = order == 2 ? "0.3*(z+1)/(z^2-0.5*z+0.1)" : order == 4 ? "0.3*(z+1)/(z^2-0.5*z+0.1)/z^2"
                                                                        : "0.3*(z+1)/(z^2-0.5*z+0.1)/(z-0.2)/(z^2+0.3*z+0.4)/(z-0.7)";
  ParseOptions po;
  po.variable = 'z';
  po.T = 1;
  // gain 5: beyond the linear limit 3, a bounded oscillation: the loop keeps switching between
  // contact and free flight (no decay into denormals, no divergence)
  LureLoop L = make_lure_loop(parse_tf(e, po), 5, 1);
  std::vector<double> s(L.order(), 0.0);
  s[0] = 3;
  const long steps = 1 << 20;
  for (auto _ : st) {
    double y = run_steps(L, s, steps);
    keep(y);
  }
  st.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps) * st.iterations(), benchmark::Counter::kIsRate);
  st.SetLabel("order " + std::to_string(order));
}

}  // namespace

BENCHMARK(BM_verdict)->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_certified)->ArgsProduct({{0, 1, 2, 3, 4}, {6, 15, 30}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_grid)->ArgsProduct({{0, 1, 2, 3, 4}, {100, 1000, 10000, 100000}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_lure)->Arg(2)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
