// cli/figures_ext.cpp -- the figures of part "ext" (beyond the papers; issue 19), registered with
// `hapstab figure` / `hapstab reproduce` (data for plots/ext_*.gp):
//
//   ext_pc_wall   paper 001's wall beyond b* (b = 0.99 b*, operator tuned to wT = pi), simulated
//                 without and with Hannaford-Ryu's passivity observer/controller: position,
//                 the wall force commanded and the force applied (the PC cancels the wall's
//                 force at every sample at which it pushes: applied 0 up to rounding),
//                 human-port energy.
//   ext_zwidth    the Z-width of a device of damping b: the walls K + B(z-1)/(Tz) z^-n it
//                 renders passively (region in the (K, B) plane, n = 0..3, from certified b*)
//                 beside those it renders stably (mass 0.1 kg; certified stability limit), and
//                 the largest |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w over the passive ones.
// Files: DATADIR/<name>_*.dat, columns in each file's header.
#include <cmath>
#include <complex>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <vector>

#include "cli/figure.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/sim/simulator.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::cli;
namespace fs = std::filesystem;

// The force the wall commands at each recorded sample (the controller's output on the sampled
// positions, before the passivity controller): the composed loop's discrete controller run over
// x(kT). Without the PC it is the applied force; with it, what the PC's damper cancelled.
std::vector<double> wall_force(const sim::LoopSpec& spec, const sim::SampleTrace& s) {
  if (spec.delay != 0 || !spec.contact.empty() || !spec.quantizers.empty() || s.N != 1)
    throw std::logic_error("ext_pc_wall: the wall force is rebuilt for one DOF without delay, contact or encoder");
  const StateSpace<double> c = sim::compose(spec).controller.cast<double>();
  Vec<double> xc = Vec<double>::Zero(c.states());
  std::vector<double> u(s.rows());
  for (size_t k = 0; k < s.rows(); ++k) {
    Vec<double> y(1);
    y(0) = s.x[k];
    u[k] = (c.C * xc + c.D * y)(0);
    xc = c.A * xc + c.B * y;
  }
  return u;
}

void write_pc_wall(const fs::path& dir) {
  auto sc = scene::load_scene((examples_dir() / "001_tightness_below.toml").string());
  for (const bool on : {false, true}) {
    sim::LoopSpec spec = sc.loop;
    if (on) spec.passivity_controller = {0};
    sim::SimOptions so;
    so.steps = sc.simulate.steps;
    so.max_velocity = sc.simulate.max_velocity;
    const sim::SimResult r = sim::Simulator(spec).run(so);
    const std::vector<double> uw = wall_force(spec, r.samples);
    // The rebuilt wall force is the applied force when no PC acts (a check on the rebuild; the
    // last row, recorded after the last period, holds the force of the period before it).
    for (size_t k = 0; !on && k + 1 < uw.size(); ++k)
      if (std::fabs(uw[k] - r.samples.u[k]) > 1e-9 * (std::fabs(uw[k]) + 1e-12))
        throw NumericalError("ext_pc_wall: the rebuilt wall force differs from the applied one at t = " +
                             std::to_string(r.samples.t[k]) + " s");
    std::ofstream f = open_data_file(dir / (std::string("ext_pc_wall_") + (on ? "on" : "off") + ".dat"));
    f << "# " << report::comment(sc.name) << (on ? ", with" : ", without") << " the passivity controller\n"
      << "# trend " << r.summary.trend << ", energy generated " << r.summary.energy_generated;
    if (on) f << ", PC dissipated " << r.summary.pc_dissipated[0] << " J at " << r.summary.pc_active << " samples";
    f << "\n# t [s]  x [m]  u (actuator force applied, after the PC) [N]  int f_h v dt [J]  "
         "wall force commanded (before the PC) [N]\n"
         "# (the last row is recorded after the last period: u is the force held over it, no wall force: NaN)\n";
    for (size_t i = 0; i < r.samples.rows(); ++i) {
      f << r.samples.t[i] << ' ' << r.samples.x[i] << ' ' << r.samples.u[i] << ' ' << r.samples.e_port[i] << ' ';
      if (i + 1 < r.samples.rows()) f << uw[i] << '\n';
      else f << "NaN\n";  // recorded after the last period: its u is the force held over that period
    }
  }
}

// The rays of the (K, B) plane: (K, B) = r ((2/T) cos t, sin t), directions in (KT/2, B), the
// coordinates in which b* = KT/2 + B (n = 0) is a straight line; the ratio B/(KT/2) = tan t runs
// log-uniformly from 1e-3 to 1e3 between the two axes (t = 0, pi/2), as the figure's log axes
// show them. (Rays of equal angle in (K, B) itself put all but one point at B > 1.96 -- K is 1000
// times B on the passive boundary -- and left the boundary near B = 0 undrawn.)
double ray_angle(int i, int dirs) {
  if (i == 0) return 0;
  if (i == dirs) return M_PI / 2;
  return std::atan(std::pow(10.0, -3.0 + 6.0 * (i - 1) / (dirs - 2)));
}
rational ray_K(double t, const rational& T) { return exact_rational(std::cos(t)) * 2 / T; }

// b* of the unit wall K(t) + sin(t) (z-1)/(Tz) with delay n (certified, 20 digits): by
// homogeneity b*(r K, r B) = r b*(K, B), so r_max = b / b* on the ray of angle t.
double unit_bstar(double t, const rational& T, int n) {
  passivity::BoundProblem p;
  const rational c = ray_K(t, T), s = exact_rational(std::sin(t));
  // (c + s/T) - (s/T) z^-1 = ((c + s/T) z - s/T)/z
  p.H = RationalFunction<rational>(Polynomial<rational>(std::vector<rational>{-s / T, c + s / T}),
                                   Polynomial<rational>::monomial(1));
  p.T = T;
  p.delay = n;
  const passivity::Bound b = passivity::bound(p, passivity::Method::certified, 20);
  if (b.infinite) return INFINITY;
  return to_real<double>(b.enclosure->hi);  // the upper end: the region drawn is inside the proven one
}

// The stability limit on the same ray for a device 1/(m s^2 + b s): sup r with the wall
// r (c + s (z-1)/(Tz)) z^-n stable for all smaller r (stability::max_gain, certified, 12 digits;
// the lower enclosure end, inside the stable region). NaN when no r > 0 is stable (a pure damper
// leaves the device's integrator at z = 1) or the test cannot decide.
double unit_stability_limit(double t, const rational& m, const rational& b, const rational& T, int n) {
  const rational c = ray_K(t, T), s = exact_rational(std::sin(t));
  stability::Loop loop = stability::mass_damper_wall(m, b, rational(0), T, n);
  loop.H = tf(Polynomial<rational>(rational(0)), Polynomial<rational>(rational(1)), T);
  loop.H_gain = tf(Polynomial<rational>(std::vector<rational>{-s / T, c + s / T}), Polynomial<rational>::monomial(1), T);
  const stability::MaxGain g = stability::max_gain(loop, 12);
  if (g.outcome != Outcome::holds || g.infinite) return NAN;
  return to_real<double>(g.enclosure.lo);
}

void write_zwidth(const fs::path& dir) {
  const rational T(1, 1000);
  const double b = 2, Td = 1e-3;  // device damping N s/m
  std::ofstream reg = open_data_file(dir / "ext_zwidth_region.dat");
  std::ofstream zw = open_data_file(dir / "ext_zwidth_magnitude.dat");
  reg << "# passive walls K + B(z-1)/(Tz) z^-n of a device with b = " << b << " N s/m, T = 1 ms: boundary K, B\n"
      << "# (K, B) = (b / b*_hi(t)) ((2/T) cos t, sin t), b* certified (upper enclosure end: inside the region)\n"
      << "# one block per n = 0..3: K [N/m]  B [N s/m]\n";
  zw << "# largest |Z(jw)| = |H(e^{jwT}) e^{-jnwT}|/w over the boundary walls above (60 directions), and\n"
     << "# the device's own |m jw + b| for m = 0.1 kg; columns: w [rad/s]  n=0  n=1  n=2  n=3  device\n";
  const int dirs = 60;
  std::vector<std::vector<std::pair<double, double>>> walls(4);
  for (int n = 0; n <= 3; ++n) {
    for (int i = 0; i <= dirs; ++i) {
      const double t = ray_angle(i, dirs);
      const double r = b / unit_bstar(t, T, n);
      walls[size_t(n)].push_back({r * to_real<double>(ray_K(t, T)), r * std::sin(t)});
      reg << walls[size_t(n)].back().first << ' ' << walls[size_t(n)].back().second << '\n';
    }
    reg << "\n\n";
  }
  // the stable walls of the same device with mass m = 0.1 kg (passivity does not depend on m)
  std::ofstream st = open_data_file(dir / "ext_zwidth_stable.dat");
  st << "# stable walls K + B(z-1)/(Tz) z^-n of the device 1/(m s^2 + b s), m = 0.1 kg, b = " << b
     << " N s/m, T = 1 ms: boundary from the certified stability limit (stability::max_gain) on each ray\n"
     << "# one block per n = 0..3: K [N/m]  B [N s/m]\n";
  for (int n = 0; n <= 3; ++n) {
    for (int i = 0; i < dirs; ++i) {  // the last ray (pure damper) is never stable for small r
      const double t = ray_angle(i, dirs);
      const double r = unit_stability_limit(t, rational(1, 10), exact_rational(b), T, n);
      if (std::isfinite(r)) st << r * to_real<double>(ray_K(t, T)) << ' ' << r * std::sin(t) << '\n';
    }
    st << "\n\n";
  }
  for (int k = 0; k <= 400; ++k) {
    const double w = std::pow(10.0, 0.0 + k * (std::log10(M_PI / Td * 0.999)) / 400);
    zw << w;
    for (int n = 0; n <= 3; ++n) {
      double best = 0;
      const std::complex<double> z = std::exp(std::complex<double>(0, w * Td));
      for (const auto& [K, B] : walls[size_t(n)]) {
        const std::complex<double> H = (K + B * (z - 1.0) / (Td * z)) * std::pow(z, -n);
        best = std::max(best, std::abs(H) / w);
      }
      zw << ' ' << best;
    }
    zw << ' ' << std::abs(std::complex<double>(b, 0.1 * w)) << '\n';
  }
}

const RegisterFigure fig_pc({"ext_pc_wall", "ext",
                             "A wall beyond b* (b = 0.99 b*, operator tuned to wT = pi) without and with the "
                             "Hannaford-Ryu passivity controller: position, the wall force commanded and the force applied (the PC "
                             "cancels it), port energy",
                             &write_pc_wall});
const RegisterFigure fig_zwidth({"ext_zwidth", "ext",
                                 "Z-width of a device with b = 2 N s/m, T = 1 ms: the walls K + B(z-1)/(Tz) z^-n it "
                                 "renders passively (certified b*) and stably (m = 0.1 kg, certified limit), and the passive "
                                 "walls' largest |Z(jw)|",
                                 &write_zwidth});

}  // namespace
