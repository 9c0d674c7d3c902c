// cli/figures_stability.cpp -- figures of issue 19 ("beyond the papers", part ext):
//   ext_stability_vs_passivity  (K, B) plane: the stability limit K_stab(B) of the sampled loop
//                               (device 1/(m s^2 + b s), b = 1 N s/m, T = 1 ms, m = 1, 0.01, 0.001 kg)
//                               against the passivity limit b*(K, B, n) < b of paper 001, n = 0..3
//   ext_stability_speed         `stability --max` time against digits (bench/bench_stability)
// Files: DATADIR/ext_stability_vs_passivity.dat; the bench chart's files (bench/chart-stability).
#include <fstream>

#include "cli/figure.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::cli::figures_stability {  // its own namespace: the commands compile in unity batches
namespace {

const rational kT(1, 1000), kb(1);
const rational kMasses[] = {rational(1), rational(1, 100), rational(1, 1000)};

/// The passive stiffnesses of the backward-difference wall form [0, Kmax) (b* convex in K, b*(0) = B):
/// Kmax by bisection on certified b* (10 digits); NaN when B >= b (no passive K).
double passive_limit(const rational& B, int n) {
  if (B >= kb) return std::nan("");
  auto passive = [&](const rational& K) {
    passivity::BoundProblem p;
    const Polynomial<rational> z = Polynomial<rational>::monomial(1), one(rational(1));
    p.H = RationalFunction<rational>(z * K + (z - one) * (B / kT), z);
    p.T = kT;
    p.delay = n;
    const passivity::Bound r = passivity::bound_certified(p, 10);
    return !r.infinite && r.value < kb;
  };
  rational lo(0), hi = 4 * (kb + B) / kT;  // the stability limit is below 2(b + B)/T (2n+1) + a little
  for (int it = 0; it < 36; ++it) {
    const rational mid = exact_rational(to_real<double>((lo + hi) / 2));
    (passive(mid) ? lo : hi) = mid;
  }
  return to_real<double>(lo);
}

double stable_limit(const rational& m, const rational& B, int n) {
  const stability::MaxGain g = stability::max_gain(stability::mass_damper_wall(m, kb, B, kT, n), 8);
  if (g.outcome != Outcome::holds || g.infinite) return std::nan("");
  return to_real<double>(g.enclosure.lo);
}

void write_vs_passivity(const std::filesystem::path& dir) {
  std::ofstream f = open_data_file(dir / "ext_stability_vs_passivity.dat");
  f << "# (K, B) plane: stability limit K_stab (stability --max, certified, 8 digits) of the loop\n"
    << "# 1/(m s^2 + b s), ZOH, wall K + B(z-1)/(Tz), delay n, b = 1 N s/m, T = 1 ms; and the passivity\n"
    << "# limit Kmax with b*(K, B, n) < b (paper 001 (45)/(53), certified b*, bisection; NaN: none)\n"
    << "# columns: B[N s/m], then for n = 0..3: K_stab(m = 1) K_stab(m = 0.01) K_stab(m = 0.001) K_pass\n";
  for (int i = 0; i <= 40; ++i) {
    const rational B(i, 20);
    f << to_real<double>(B);
    for (int n = 0; n <= 3; ++n) {
      for (const rational& m : kMasses) f << " " << stable_limit(m, B, n);
      f << " " << passive_limit(B, n);
    }
    f << "\n";
  }
}

const RegisterFigure vs_passivity({"ext_stability_vs_passivity", "ext",
                                   "How conservative passivity is: the exact stability limit K_stab(B) of the sampled "
                                   "loop (device 1/(m s^2 + b s), b = 1 N s/m, T = 1 ms, three masses) against the "
                                   "passivity limit b* < b of paper 001, delays n = 0..3",
                                   [](const std::filesystem::path& d) { write_vs_passivity(d); }});

const RegisterFigure speed({"ext_stability_speed", "ext",
                            "stability --max: time per call against the requested digits (10..100) for four loops, "
                            "each result a certified enclosure",
                            [](const std::filesystem::path& d) { write_bench_chart_data("stability", d); },
                            [](const std::filesystem::path& d) { return bench_timing_vars("stability", d); }});

}  // namespace
}  // namespace hapstab::cli::figures_stability
