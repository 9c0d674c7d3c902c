// cli/figures_passivity.cpp -- the passivity figures of paper 001 and the toolbox's bound charts,
// registered with `hapstab figure` / `hapstab reproduce` (data for plots/passivity_*.gp):
//
//   passivity_fig2         Fig. 2 (a)-(e): closed RHP -> shift by b -> disk 1/(.) -> r(jw)/(.) -> unit disk
//   passivity_fig3         Fig. 3: the operator range with a shortage of passivity eta, and its image
//   passivity_bound_curve  Re{T H z^-n/(1-z)} against w with b* and its maximiser (certified) marked
//   passivity_kb_region    (K, B) passivity regions of virtual walls, delays n = 0..3, backward difference vs Tustin
// Files: DATADIR/<name>.dat (bound curve also _marks.dat). Columns are documented in each file's header.
#include <complex>
#include <fstream>
#include <memory>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/passivity/max_gain.hpp"

namespace {

using namespace hapstab;
using namespace hapstab::passivity;
using cd = std::complex<double>;

std::ofstream open_out(const std::string& dir, const std::string& file) {
  std::ofstream f(dir + "/" + file);
  if (!f) throw InputError("--out: cannot write '" + dir + "/" + file + "'");
  f.precision(12);
  return f;
}

// Fig. 2: each panel is a gnuplot data block (index i) of curves separated by blank lines:
// the boundary of the region, then images of the lines Re Z = x0 and Im Z = y0 of panel (a).
void fig2(const std::string& dir, double b, double T, double w, const std::string& name, double eta) {
  auto f = open_out(dir, name);
  const cd r = T / (std::exp(cd(0, w * T)) - 1.0);  // (44)
  f << "# " << name << ": the Nyquist-plane maps of paper 001, Fig. " << (eta > 0 ? "3" : "2") << "\n";
  f << "# b = " << b << " N s/m, T = " << T << " s, w = " << w << " rad/s, eta = " << eta << ", r(jw) = " << r.real()
    << " + j " << r.imag() << "\n# columns: Re  Im  family(0 boundary, 1 Re-lines, 2 Im-lines)\n";
  // maps: (a) Z, (b) Z + b, (c) 1/(Z + b), (d) r/(Z + b), (e) 2b/(Z + b) - 1   (with shortage: b -> b - eta is
  // what remains after the shift, Z ranges over Re Z >= -eta)
  const double be = b;
  auto map = [&](int panel, cd Z) -> cd {
    switch (panel) {
      case 0: return Z;
      case 1: return Z + be;
      case 2: return 1.0 / (Z + be);
      case 3: return r / (Z + be);
      default: return 2.0 * (be - eta) / (Z + be) - 1.0;
    }
  };
  const double Y = 4 * b;
  for (int panel = 0; panel < 5; ++panel) {
    f << "# panel " << char('a' + panel) << "\n";
    // boundary Re Z = -eta (imaginary axis when eta = 0), y from -inf..inf through a tan parametrisation
    for (int k = -400; k <= 400; ++k) {
      double y = (panel <= 1) ? Y * k / 400.0 : b * std::tan(1.5707 * k / 400.0) * 2;
      cd p = map(panel, cd(-eta, y));
      f << p.real() << " " << p.imag() << " 0\n";
    }
    f << "\n";
    for (double x0 : {0.25 * b, b, 3 * b}) {
      for (int k = -400; k <= 400; ++k) {
        double y = (panel <= 1) ? Y * k / 400.0 : b * std::tan(1.5707 * k / 400.0) * 2;
        cd p = map(panel, cd(x0 - eta, y));
        f << p.real() << " " << p.imag() << " 1\n";
      }
      f << "\n";
    }
    for (double y0 : {-b, 0.0, b}) {
      for (int k = 0; k <= 400; ++k) {
        double x = (panel <= 1) ? 4 * b * k / 400.0 : b * std::tan(1.5707 * k / 400.0) * 2;
        cd p = map(panel, cd(x - eta, y0));
        f << p.real() << " " << p.imag() << " 2\n";
      }
      f << "\n";
    }
    f << "\n";
  }
}

void bound_curve(const std::string& dir) {
  // the delayed wall of (53) with n = 1 and a narrow resonance environment
  struct Case { std::string label, expr; int n; };
  std::vector<Case> cases = {{"wall K=1000, B=5, n=1", "1000 + 5*(z-1)/(T*z)", 1},
                             {"wall K=1000, B=5, n=0", "1000 + 5*(z-1)/(T*z)", 0},
                             {"Tustin wall K=1000, B=5, n=1", "1000 + 2*5/T*(z-1)/(z+1)", 1}};
  auto f = open_out(dir, "passivity_bound_curve.dat");
  auto g = open_out(dir, "passivity_bound_curve_marks.dat");
  f << "# Re{T H(e^{jwT}) z^-n/(1 - e^{jwT})} (45) against w, T = 1 ms; one data block per case\n# columns: w[rad/s] value[N s/m]\n";
  g << "# certified b* and its maximiser; columns: w* b* case-index\n";
  ParseOptions po;
  po.variable = 'z';
  po.T = rational(1, 1000);
  const double T = 1e-3, pi = 3.14159265358979323846;
  int idx = 0;
  for (const auto& c : cases) {
    BoundProblem p;
    p.H = parse_tf(c.expr, po).H;
    p.T = po.T;
    p.delay = c.n;
    Bound b = bound_certified(p, 20);
    f << "# " << c.label << "  b* = " << b.decimal << "\n";
    for (int k = 0; k <= 1000; ++k) {
      double w = pi / T * k / 1000.0;
      f << w << " " << objective_at(p, w) << "\n";
    }
    f << "\n\n";
    double ws = b.omega ? to_real<double>(parse_rational(*b.omega)) : 0.0;
    g << ws << " " << b.value_double() << " " << idx << "  # " << c.label << " b* = " << b.decimal << "\n";
    ++idx;
  }
}

void kb_region(const std::string& dir) {
  // For device damping b = 1 N s/m and T = 1 ms: the passive stiffnesses K (b*(K, B, n) < b), for B
  // in [0, 2] N s/m, delays n = 0..3, backward-difference wall K + B(z-1)/(Tz) and Tustin wall.
  // b*(K) = sup_w [K g(w) + h(w)] is convex in K (a supremum of affine functions), so the passive
  // set is one interval [Kmin, Kmax): Kmin = 0 for the backward-difference walls, but not for the
  // delayed Tustin walls (n = 1, B in (1/3, 1/2]: K in [2(3B - 1)/T, 2(1 + B)/(3T))). A passive K
  // is found first (a golden section on b*), then both ends by max_gain, certified.
  auto f = open_out(dir, "passivity_kb_region.dat");
  const double bdev = 1, Kcap = 1e6;
  f << "# (K, B) passivity regions: passive K in [Kmin, Kmax) with b*(K,B,n) < b = 1 N s/m, T = 1 ms\n"
    << "# columns: B[N s/m], then Kmin Kmax [N/m] for the backward-difference wall n = 0..3, then for the\n"
    << "# Tustin wall n = 0..3 (NaN NaN: no passive K; Kmax = 1e6: the search cap)\n";
  const rational T(1, 1000);
  for (int i = 0; i <= 80; ++i) {
    rational B = rational(i, 40);
    f << to_real<double>(B);
    for (int tustin = 0; tustin < 2; ++tustin)
      for (int n = 0; n <= 3; ++n) {
        auto bstar = [&](double Kd) {
          const rational K = exact_rational(Kd);
          BoundProblem p;
          Polynomial<rational> z = Polynomial<rational>::monomial(1);
          Polynomial<rational> one(rational(1));
          if (!tustin) p.H = RationalFunction<rational>(z * K + (z - one) * (B / T), z);
          else p.H = RationalFunction<rational>((z + one) * K + (z - one) * (2 * B / T), z + one);
          p.T = T;
          p.delay = n;
          Bound r = bound_certified(p, 10);
          return r.infinite ? 1e300 : r.value_double();
        };
        // a passive K: K = 0, else the minimiser of the convex b*(K) (golden section)
        double Kin = 0;
        if (bstar(0) >= bdev) {
          double a = 0, c = Kcap;
          const double g = 0.6180339887498949;
          double x1 = c - g * (c - a), x2 = a + g * (c - a), f1 = bstar(x1), f2 = bstar(x2);
          for (int it = 0; it < 50 && std::min(f1, f2) >= bdev; ++it) {
            if (f1 < f2) { c = x2; x2 = x1; f2 = f1; x1 = c - g * (c - a); f1 = bstar(x1); }
            else { a = x1; x1 = x2; f1 = f2; x2 = a + g * (c - a); f2 = bstar(x2); }
          }
          if (std::min(f1, f2) >= bdev) { f << " NaN NaN"; continue; }
          Kin = f1 < f2 ? x1 : x2;
        }
        // the edges from the passive point Kin, certified (passivity/max_gain.hpp): b* is convex in
        // K, so the passive interval is [Kin - t_down, Kin + t_up) with t the largest passive step
        // along dH/dK = +1 and -1 (the ends drawn are the enclosures' inner ends: inside the region)
        GainProblem g;
        {
          Polynomial<rational> z = Polynomial<rational>::monomial(1);
          Polynomial<rational> one(rational(1));
          const rational K = exact_rational(Kin);
          if (!tustin) g.base.H = RationalFunction<rational>(z * K + (z - one) * (B / T), z);
          else g.base.H = RationalFunction<rational>((z + one) * K + (z - one) * (2 * B / T), z + one);
        }
        g.base.T = T;
        g.base.delay = n;
        g.b = rational(1);
        auto step = [&](int sign) {
          g.H1 = RationalFunction<rational>(rational(sign));
          const MaxGain m = max_gain(g, 12);
          return m.infinite ? Kcap : to_real<double>(m.enclosure->lo);
        };
        const double Kmax = std::min(Kcap, Kin + step(+1));
        const double Kmin = Kin > 0 ? std::max(0.0, Kin - step(-1)) : 0.0;
        f << " " << Kmin << " " << Kmax;
      }
    f << "\n";
  }
}

// Fig. 2 and 3 at the paper's illustration values: b = 1 N s/m, T = 1 ms, w = 1000 rad/s, eta = 0.3 N s/m.
const cli::RegisterFigure f2({"passivity_fig2", "001",
                              "Fig. 2 (a)-(e): the maps that turn the passivity condition into the unit-disk test "
                              "(b = 1 N s/m, T = 1 ms, w = 1000 rad/s)",
                              [](const std::filesystem::path& d) { fig2(d.string(), 1.0, 1e-3, 1000.0, "passivity_fig2.dat", 0.0); }});
const cli::RegisterFigure f3({"passivity_fig3", "001",
                              "Fig. 3: the same maps for an operator with a shortage of passivity eta = 0.3 N s/m",
                              [](const std::filesystem::path& d) { fig2(d.string(), 1.0, 1e-3, 1000.0, "passivity_fig3.dat", 0.3); }});
const cli::RegisterFigure fc({"passivity_bound_curve", "toolbox",
                              "Bound curves: Re{T H(z) z^-n/(1 - z)} over 0 <= w <= pi/T for walls with and without a "
                              "delay, with the certified b* and its maximiser marked",
                              [](const std::filesystem::path& d) { bound_curve(d.string()); }});
const cli::RegisterFigure fk({"passivity_kb_region", "toolbox",
                              "(K, B) passivity regions of virtual walls for a device with b = 1 N s/m, T = 1 ms, "
                              "delays n = 0..3: backward difference against Tustin (certified b* at every point)",
                              [](const std::filesystem::path& d) { kb_region(d.string()); }});

}  // namespace
