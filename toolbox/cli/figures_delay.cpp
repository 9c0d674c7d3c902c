// cli/figures_delay.cpp -- the figures of issue 43 (delays of teleoperation scale; part "ext"):
//   ext_long_delay        where the methods fail: b* (paper 001, (45)) and sup K (stability --max)
//                         against the delay n = 1..10^4 for a virtual wall K + B (z - 1)/(T z),
//                         certified (exact path where it is cheap, the long-delay path beyond)
//                         beside double-precision grids of 10^4 and 10^6 points and the closed
//                         forms of Sec. VI where they exist ((46) at n = 0, (53) at n = 1, the
//                         conservative (2n+1) KT/2 + B and the value at w = 0, (2n+1) KT/2 - B),
//                         and the relative error of each grid.
//   ext_long_delay_speed  time and accuracy of the paths against n, one Google Benchmark run
//                         (bench/delay.cpp, bench/chart-delay).
// Files: DATADIR/ext_long_delay_bound.dat, ext_long_delay_kmax.dat; the bench chart's files.
#include <cmath>
#include <fstream>

#include "cli/figure.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/catalogue.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::cli {
namespace {

const rational kT(1, 1000);
const int kDelays[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};

passivity::BoundProblem wall(const rational& K, const rational& B, int n) {
  const Polynomial<rational> z = Polynomial<rational>::monomial(1), one(rational(1));
  passivity::BoundProblem p;
  p.H = RationalFunction<rational>(z * K + (z - one) * (B / kT), z);  // K + B (z - 1)/(T z)
  p.T = kT;
  p.delay = n;
  return p;
}

void write_bound(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "ext_long_delay_bound.dat";
  std::ofstream f = open_data_file(file);
  f << "# b* of paper 001 (45) for the walls K + B(z-1)/(Tz), T = 1 ms, delay n: stiff K = 1000, B = 5 N s/m and\n"
    << "# soft K = 10, B = 5 (an interior maximum up to n ~ 1000). certified: bound_certified (30 digits; its path\n"
    << "# below: 0 exact, 1 long-delay); grid N: the maximum of the objective on N points in double (a lower estimate).\n"
    << "# closed forms: (2n+1)KT/2 + B is (53)'s conservative upper bound, (2n+1)KT/2 - B the value at w = 0 (a lower\n"
    << "# bound); (46) KT/2 + B at n = 0 and (53) with n = 1 are exact (the last rows, n = 0 and 1, stiff wall).\n"
    << "# n  stiff: certified grid1e4 grid1e6 upper(53) at_w0 path  soft: certified grid1e4 grid1e6 upper(53) at_w0 path\n";
  for (int n : kDelays) {
    f << n;
    for (const rational& K : {rational(1000), rational(10)}) {
      const rational B(5);
      const passivity::BoundProblem p = wall(K, B, n);
      const passivity::Bound c = passivity::bound_certified(p, 30);
      f << ' ' << c.value_double() << ' ' << passivity::bound_grid(p, 10000).value_double() << ' '
        << passivity::bound_grid(p, 1000000).value_double() << ' '
        << to_real<double>(passivity::catalogue::delayed_wall_conservative(n, K, B, kT)) << ' '
        << to_real<double>(rational(2 * n + 1) * K * kT / 2 - B) << ' ' << (c.path == passivity::BoundPath::exact ? 0 : 1);
    }
    f << '\n';
  }
  f << "\n\n# exact closed forms, stiff wall: n b*\n0 " << to_real<double>(passivity::catalogue::virtual_wall(1000, 5, kT))
    << "\n1 " << to_real<double>(passivity::catalogue::delayed_wall_n1(1000, 5, kT)) << '\n';
  close_data_file(f, file);
}

void write_kmax(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "ext_long_delay_kmax.dat";
  std::ofstream f = open_data_file(file);
  f << "# sup K of stability --max: device 1/(m s^2 + b s), m = 1 kg, b = 1 N s/m, ZOH, wall K + B(z-1)/(Tz) with\n"
    << "# B = 0.5 N s/m, T = 1 ms, delay n. certified: max_gain (20 digits; path 0 polynomial, 1 long-delay); grid N:\n"
    << "# max_gain_grid (double, N points); law: 2(b + B)/((2n + 1) T), the small-T approximation (claim\n"
    << "# ext.stability.small_T_law: nT small).\n"
    << "# n certified grid1e4 grid1e6 law path\n";
  for (int n : kDelays) {
    const stability::Loop loop = stability::mass_damper_wall(rational(1), rational(1), rational(1, 2), kT, n);
    const stability::MaxGain g = stability::max_gain(loop, 20);
    auto grid = [&](long N) {
      const auto r = stability::max_gain_grid(loop, N);
      return r ? r->K : std::nan("");
    };
    f << n << ' ' << to_real<double>(g.enclosure.lo) << ' ' << grid(10000) << ' ' << grid(1000000) << ' '
      << 2 * 1.5 / ((2 * n + 1) * 1e-3) << ' ' << (g.path == "long_delay" ? 1 : 0) << '\n';
  }
  close_data_file(f, file);
}

const RegisterFigure long_delay({"ext_long_delay", "ext",
                                 "Delays of teleoperation scale: b* and sup K against the delay n = 1..10^4 for a "
                                 "virtual wall, certified (exact path, long-delay path beyond) beside double grids of "
                                 "10^4 and 10^6 points and Sec. VI's closed forms, with each grid's relative error",
                                 [](const std::filesystem::path& d) {
                                   write_bound(d);
                                   write_kmax(d);
                                 }});

const RegisterFigure speed({"ext_long_delay_speed", "ext",
                            "b* and sup K against the delay: time and accuracy of the exact (polynomial) path, the "
                            "long-delay path, the fast path and 10^4/10^6-point grids in one benchmark run",
                            [](const std::filesystem::path& d) { write_bench_chart_data("delay", d); },
                            [](const std::filesystem::path& d) { return bench_timing_vars("delay", d); }});

}  // namespace
}  // namespace hapstab::cli
