// bench/python_binding.cpp -- the C++ side of bench/python_binding.py: one point of each of
// Python's vectorised calls, timed here on one thread as the binding computes it (the same
// library calls: python/bind_passivity.cpp), so the script can state the ratio of a Python call
// over N points to N C++ calls.
//   r_double       Im r(jw) of (44) in double at one w (r_eq44), as r(T, omega_array)
//   bound_fast     the wall K + B(z-1)/(Tz), T = 1 ms, B = 5, delay 1, at one K: parse + fast b*
//   bound_cert     the same, certified (30 digits), as bound(..., params={"K": array})
//   parse          parse_tf of the wall at one K (what a point cost before the expression was parsed once)
//   parsed_at      ParsedExpression::at, the wall at one K from the expression parsed once (the binding's)
// K runs over the values Python sweeps (0 .. 40000), so the exact and certified cases mix alike.
#include <benchmark/benchmark.h>

#include <cmath>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/sampling/r_forms.hpp"
#include "keep.hpp"

using namespace hapstab;

namespace {

const char* wall = "K + B*(z-1)/(T*z)";

ParseOptions options(double K) {
  ParseOptions o;
  o.variable = 'z';
  o.T = rational(1, 1000);
  o.parameters = {{"K", exact_rational(K)}, {"B", rational(5)}};
  return o;
}

void bound_point(benchmark::State& st, passivity::Method m) {
  const long n = st.range(0);  // the number of K values of the Python sweep
  ParseOptions fixed = options(0);
  fixed.parameters.erase("K");
  const ParsedExpression wall_of(wall, fixed, {"K"});
  long i = 0;
  for (auto _ : st) {
    const double K = 40000.0 * double(i % n) / double(n - 1);
    ++i;
    const TransferFunction H = wall_of.at({{"K", exact_rational(K)}});
    passivity::BoundProblem p;
    p.H = H.H;
    p.T = H.T;
    p.delay = 1;
    passivity::Bound b = passivity::bound(p, m, 30, 100000);
    keep(b);
  }
}

void BM_bound_fast(benchmark::State& st) { bound_point(st, passivity::Method::fast); }
void BM_bound_cert(benchmark::State& st) { bound_point(st, passivity::Method::certified); }

void BM_parse(benchmark::State& st) {
  long i = 0;
  for (auto _ : st) {
    TransferFunction H = parse_tf(wall, options(double(++i % 40000)));
    keep(H);
  }
}

void BM_parsed_at(benchmark::State& st) {
  ParseOptions fixed = options(0);
  fixed.parameters.erase("K");
  const ParsedExpression wall_of(wall, fixed, {"K"});
  long i = 0;
  for (auto _ : st) {
    TransferFunction H = wall_of.at({{"K", exact_rational(double(++i % 40000))}});
    keep(H);
  }
}

void BM_r_double(benchmark::State& st) {
  const double T = 1e-3;
  double w = 0.5;
  for (auto _ : st) {
    double im = sampling::r_eq44(T, w * T).imag();
    keep(im);
    w += 3.0;
    if (w > 3000) w = 0.5;
  }
}

}  // namespace

BENCHMARK(BM_r_double)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_parse)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_parsed_at)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_bound_fast)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_bound_cert)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
