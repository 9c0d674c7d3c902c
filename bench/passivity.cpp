// bench/passivity.cpp -- speed against accuracy of the passivity bound b* (paper 001, (45)):
// the double-double fast path, the certified method at 16/30/100 digits, and grid(N) for
// N = 10^2..10^6, on catalogue cases and narrow resonances (pole radius 0.9999, 0.99999), up to
// order 6 with a delay of 2 samples.
// Counters: rel_err = |b - ref|/|ref| against a 100-digit certified reference (its enclosure
// width is < 1e-95 relative, so rel_err below 1e-90 reads as "exact"), and digits = -log10(rel_err).
// Targets (reported, not asserted): fast <= 20 us/case with rel_err <= 1e-13; certified(30) <= 1 ms.
#include <benchmark/benchmark.h>

#include "keep.hpp"

#include <cmath>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"

using namespace hapstab;
using namespace hapstab::passivity;

namespace {

struct Case {
  const char* name;
  const char* expr;
  int n;
};
const Case cases[] = {
    {"wall_n1", "1000 + 5*(z-1)/(T*z)", 1},
    {"iir", "(1-z)/(z-0.9)", 0},
    {"order4", "(z^2-1)*(z+0.5)/((z^2-1.2*z+0.5)*(z^2+0.3*z+0.9))", 0},
    {"resonance_0.9999", "(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)", 0},
    {"resonance4_0.99999", "(z-1)*(z+0.2)/((z^2-2*0.99999*0.3*z+0.99999^2)*(z^2-0.5*z+0.25))", 1},
    {"order6_0.9999_n2", "(z-1)*(z+0.5)*(z^2-0.1*z+0.4)/((z^2-2*0.9999*0.6*z+0.9999^2)*(z^2+0.4*z+0.5)*(z^2-0.2*z+0.3))", 2},
};

BoundProblem problem(int i) {
  ParseOptions o;
  o.variable = 'z';
  o.T = rational(1, 1000);
  BoundProblem p;
  p.H = parse_tf(cases[i].expr, o).H;
  p.T = o.T;
  p.delay = cases[i].n;
  return p;
}

const rational& reference(int i) {
  static std::vector<rational> refs;
  if (refs.empty())
    for (size_t k = 0; k < std::size(cases); ++k) {
      Bound b = bound_certified(problem(static_cast<int>(k)), 100);
      refs.push_back(b.value);
    }
  return refs[i];
}

void set_error(benchmark::State& st, const rational& v, int i) {
  const rational& ref = reference(i);
  double e = ref == 0 ? to_real<double>(abs(v)) : to_real<double>(abs((v - ref) / ref));
  st.counters["rel_err"] = e;
  st.counters["digits"] = e > 0 ? -std::log10(e) : 100.0;
}

// `--method fast` as a user gets it: the dispatcher, which hands a case beyond the double path (|D|^2 below
// 1e-9 of its coefficients: resonance4_0.99999 since stop 87) to the certified path -- counter handed_over = 1
void BM_fast(benchmark::State& st) {
  int i = static_cast<int>(st.range(0));
  BoundProblem p = problem(i);
  reference(i);
  Bound b;
  for (auto _ : st) {
    b = bound(p, Method::fast);  // includes exact -> double-double conversion of H
    keep(b.enclosure->lo);
  }
  set_error(st, b.value, i);
  st.counters["handed_over"] = b.kind == Method::fast ? 0 : 1;
  st.SetLabel(cases[i].name);
}

void BM_certified(benchmark::State& st) {
  int i = static_cast<int>(st.range(0));
  int digits = static_cast<int>(st.range(1));
  BoundProblem p = problem(i);
  reference(i);
  Bound b;
  for (auto _ : st) {
    b = bound_certified(p, digits);
    keep(b.enclosure->lo);
  }
  set_error(st, b.value, i);
  st.SetLabel(cases[i].name);
}

void BM_grid(benchmark::State& st) {
  int i = static_cast<int>(st.range(0));
  long N = st.range(1);
  BoundProblem p = problem(i);
  reference(i);
  Bound b;
  for (auto _ : st) {
    b = bound_grid(p, N);
    keep(b.enclosure->lo);
  }
  set_error(st, b.enclosure->lo, i);
  st.SetLabel(cases[i].name);
}

void case_args(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < static_cast<int>(std::size(cases)); ++i) b->Arg(i);
}
void cert_args(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < static_cast<int>(std::size(cases)); ++i)
    for (int d : {16, 30, 100}) b->Args({i, d});
}
void grid_args(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < static_cast<int>(std::size(cases)); ++i)
    for (long N : {100L, 1000L, 10000L, 100000L, 1000000L}) b->Args({i, N});
}

}  // namespace

BENCHMARK(BM_fast)->Apply(case_args)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_certified)->Apply(cert_args)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_grid)->Apply(grid_args)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
