// bench/sampling.cpp -- speed against accuracy of r(jw) (paper 001): every closed form (35)-(38),
// (44) (and (44) as a naive complex division) x scalar (double, mp50, mp100); the series (34)
// truncated at N = 10..10^6; the Euler-Maclaurin accelerated series at 10..90 digits; the certified
// MPFI enclosure; and a per-point accuracy sweep of each double form over wT in [1e-8, pi].
// Counters: rel_err = max(|Re r~ - Re r|/|Re r|, |Im r~ - Im r|/|Im r|) (componentwise: the
// cancellation in Re of (36), (37) and naive (44) is invisible in |r~ - r|/|r| because |Re r| = T/2
// << |Im r| ~ T/wT for small wT) against a 2x-precision reference of (38) at
// the SAME (rounded) inputs (double -> 40 digits, mp50 -> 100, mp100 -> 200); digits = -log10(rel_err);
// ulps = rel_err/2^-52 for double. form/* time one evaluation, cycling through 64 wT log-spaced in
// [1e-8, pi], and report the worst rel_err over those 64; series/accelerated use wT = 1.2345.
// Targets (reported, not asserted): (44) double <= 20 ns/eval and <= 4 eps; 30 digits <= 50 us.
//   bench_sampling --benchmark_format=json     (bench/chart-sampling turns it into a chart)
#include <benchmark/benchmark.h>

#include "keep.hpp"

#include <array>
#include <cmath>
#include <string>

#include "hapstab/sampling/series.hpp"

using namespace hapstab;
using namespace hapstab::sampling;

namespace {

template <class S> struct Ref;
template <> struct Ref<double> { using type = mpfloat<40>; static constexpr const char* name = "double"; };
template <> struct Ref<mp50> { using type = mp100; static constexpr const char* name = "mp50"; };
template <> struct Ref<mp100> { using type = mpfloat<200>; static constexpr const char* name = "mp100"; };

template <class S>
typename Ref<S>::type up(const S& x) {
  return typename Ref<S>::type(x);  // exact widening (both binary)
}

// relative error of v = r(T, theta) against the 2x-precision (38) at the same inputs
template <class S>
double rel_err(const std::complex<S>& v, const S& T, const S& theta) {
  using R = typename Ref<S>::type;
  const R Tr = up(T), th = up(theta);
  const R re = -Tr / 2, im = -Tr / 2 * cos(th / 2) / sin(th / 2);
  const R er = abs((up(v.real()) - re) / re), ei = abs((up(v.imag()) - im) / im);
  return static_cast<double>(er > ei ? er : ei);
}

void set_err(benchmark::State& st, double e, bool is_double) {
  st.counters["rel_err"] = e;
  st.counters["digits"] = e > 0 ? -std::log10(e) : 200.0;
  if (is_double) st.counters["ulps"] = e / 2.220446049250313e-16;
}

const std::array<double, 64>& thetas() {
  static std::array<double, 64> t = [] {
    std::array<double, 64> a{};
    for (int i = 0; i < 64; ++i) a[i] = std::pow(10.0, -8.0 + (std::log10(M_PI) + 8.0) * i / 63);
    a[63] = M_PI;
    return a;
  }();
  return t;
}

using FormFn = std::complex<double> (*)(const double&, const double&);
enum class Form { eq35, eq36, eq37, eq38, eq44, eq44_naive };
const char* form_name(Form f) {
  switch (f) {
    case Form::eq35: return "eq35";
    case Form::eq36: return "eq36";
    case Form::eq37: return "eq37";
    case Form::eq38: return "eq38";
    case Form::eq44: return "eq44";
    case Form::eq44_naive: return "eq44_naive";
  }
  return "";
}
template <class S>
std::complex<S> eval(Form f, const S& T, const S& th) {
  switch (f) {
    case Form::eq35: return r_eq35(T, th);
    case Form::eq36: return r_eq36(T, th);
    case Form::eq37: return r_eq37(T, th);
    case Form::eq38: return r_eq38(T, th);
    case Form::eq44: return r_eq44(T, th);
    case Form::eq44_naive: return r_eq44_naive(T, th);
  }
  return {};
}

// One form, one scalar: the timing loop calls the form directly (no switch inside the loop).
template <class S, Form F>
void BM_form(benchmark::State& st) {
  std::array<S, 64> th;
  for (int i = 0; i < 64; ++i) th[i] = S(thetas()[i]);
  const S T = S(1) / 1000;
  size_t i = 0;
  for (auto _ : st) {
    std::complex<S> v;
    if constexpr (F == Form::eq35) v = r_eq35(T, th[i]);
    if constexpr (F == Form::eq36) v = r_eq36(T, th[i]);
    if constexpr (F == Form::eq37) v = r_eq37(T, th[i]);
    if constexpr (F == Form::eq38) v = r_eq38(T, th[i]);
    if constexpr (F == Form::eq44) v = r_eq44(T, th[i]);
    if constexpr (F == Form::eq44_naive) v = r_eq44_naive(T, th[i]);
    keep(v);
    i = (i + 1) & 63;
  }
  double worst = 0;
  for (int k = 0; k < 64; ++k) worst = std::max(worst, rel_err(eval(F, T, th[k]), T, th[k]));
  set_err(st, worst, std::is_same_v<S, double>);
}

template <class S>
void BM_series(benchmark::State& st) {
  const long N = st.range(0);
  const S T = S(1) / 1000, th = S(1.2345);
  std::complex<S> v;
  for (auto _ : st) {
    v = r_series(T, th, N);
    keep(v);
  }
  set_err(st, rel_err(v, T, th), std::is_same_v<S, double>);
}

template <class S>
void BM_accelerated(benchmark::State& st) {
  const int digits = static_cast<int>(st.range(0));
  const S T = S(1) / 1000, th = S(1.2345);
  AcceleratedR<S> a{};
  for (auto _ : st) {
    a = r_series_accelerated(T, th, digits);
    keep(a);
  }
  set_err(st, rel_err(a.value, T, th), std::is_same_v<S, double>);
  st.counters["N"] = static_cast<double>(a.N);
  st.counters["K"] = a.K;
}

// certified enclosure of the infinite series at 60 digits (N = 20, K = 40): time, and the
// relative width of the Im enclosure as its "error"
void BM_certified(benchmark::State& st) {
  const rational T(1, 1000), theta(12345, 10000);
  SeriesEnclosure<60> e{};
  for (auto _ : st) {
    e = r_series_certified<60>(T, theta, 20, 40);
    keep(e);
  }
  mpfloat<60> w = mpfloat<60>(upper(e.im) - lower(e.im)) / abs(mpfloat<60>(lower(e.im)));
  set_err(st, static_cast<double>(w), false);
}

// accuracy sweep: one entry per (double form, wT), 1 iteration
void sweep(benchmark::State& st, Form f, double theta) {
  const double T = 1e-3;
  std::complex<double> v;
  for (auto _ : st) {
    v = eval(f, T, theta);
    keep(v);
  }
  st.counters["theta"] = theta;
  set_err(st, rel_err(v, T, theta), true);
}

template <class S>
void register_forms() {
  const std::string s = Ref<S>::name;
  benchmark::RegisterBenchmark(("form/eq35/" + s).c_str(), BM_form<S, Form::eq35>);
  benchmark::RegisterBenchmark(("form/eq36/" + s).c_str(), BM_form<S, Form::eq36>);
  benchmark::RegisterBenchmark(("form/eq37/" + s).c_str(), BM_form<S, Form::eq37>);
  benchmark::RegisterBenchmark(("form/eq38/" + s).c_str(), BM_form<S, Form::eq38>);
  benchmark::RegisterBenchmark(("form/eq44/" + s).c_str(), BM_form<S, Form::eq44>);
  benchmark::RegisterBenchmark(("form/eq44_naive/" + s).c_str(), BM_form<S, Form::eq44_naive>);
  auto* b = benchmark::RegisterBenchmark(("series/" + s).c_str(), BM_series<S>);
  for (long N = 10; N <= 1000000; N *= 10) b->Arg(N);
  if (!std::is_same_v<S, double>) b->Unit(benchmark::kMicrosecond);
}

const int registered = [] {
  register_forms<double>();
  register_forms<mp50>();
  register_forms<mp100>();
  benchmark::RegisterBenchmark("accelerated/double", BM_accelerated<double>)->Arg(8)->Arg(15);
  benchmark::RegisterBenchmark("accelerated/mp50", BM_accelerated<mp50>)
      ->Arg(10)->Arg(20)->Arg(30)->Arg(40)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("accelerated/mp100", BM_accelerated<mp100>)
      ->Arg(30)->Arg(60)->Arg(90)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("certified/ival60", BM_certified)->Unit(benchmark::kMicrosecond);
  for (Form f : {Form::eq35, Form::eq36, Form::eq37, Form::eq38, Form::eq44, Form::eq44_naive}) {
    for (int i = 0; i <= 200; ++i) {
      double th = std::pow(10.0, -8.0 + (std::log10(M_PI) + 8.0) * i / 200);
      if (i == 200) th = M_PI;
      benchmark::RegisterBenchmark((std::string("sweep/") + form_name(f) + "/" + std::to_string(i)).c_str(),
                                   [f, th](benchmark::State& st) { sweep(st, f, th); })
          ->Iterations(1);
    }
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
