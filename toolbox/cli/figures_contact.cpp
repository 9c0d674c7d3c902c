// cli/figures_contact.cpp -- the figures of paper 002 (Tsai & Colgate) and of the contact
// module: data writers registered with `hapstab figure` / `hapstab reproduce` (drawn by
// plots/contact_*.gp).
//   contact_fig4_5       the shifted unilateral nonlinearity xi(y+rho)-rho (Fig. 4) and its region (Fig. 5)
//   contact_fig6         the q half-planes (21)/(22) at theta = pi/4 and the forbidden wedge (Fig. 6)
//   contact_nyquist      Nyquist plot of k*H with the forbidden wedges of (25) at several frequencies
//   contact_limit_cycle  penetration time series of Fig. 2 below and above the oscillation onset
//   contact_conservatism k*_Tsypkin, k*_wedge, the linear limit and the simulated onset per case
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "hapstab/contact/conservatism.hpp"
#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/contact/qineq.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {
namespace {

namespace fs = std::filesystem;
using contact::q_halfplane;

TransferFunction H_of(const std::string& s) {
  ParseOptions po;
  po.variable = 'z';
  po.T = 1;
  return parse_tf(s, po);
}

void fig4_5(const fs::path& dir) {
  auto o = open_data_file(dir / "contact_fig4_5.dat");
  o << "# y  xi(y+rho)-rho for rho = 0.5, 1, 2   (index 0)\n";
  for (int i = 0; i <= 400; ++i) {
    const double y = -3 + 6.0 * i / 400;
    o << y << " " << std::max(y, -0.5) << " " << std::max(y, -1.0) << " " << std::max(y, -2.0) << "\n";
  }
  o << "\n\n# region covered as rho runs over (0, inf): x between y and 0 for y < 0, x = y for y >= 0 (index 1)\n";
  o << "-3 -3\n-3 0\n0 0\n-3 -3\n";
}

void fig6(const fs::path& dir) {
  const double th = M_PI / 4;
  auto o = open_data_file(dir / "contact_fig6.dat");
  // index 0..6: boundary line of q = 1..7 (through -1), points +-L along the line
  for (int q = 1; q <= 7; ++q) {
    auto hp = q_halfplane(th, q);
    const double n = std::hypot(hp.nx, hp.ny), dx = -hp.ny / n, dy = hp.nx / n;
    o << "# q = " << q << " boundary line\n" << -1 - 9 * dx << " " << -9 * dy << "\n" << -1 + 9 * dx << " " << 9 * dy
      << "\n\n\n";
  }
  // index 7: arrows (x y dx dy label-q) from a point on each line toward the allowed side
  o << "# arrows: x y dx dy q\n";
  for (int q = 1; q <= 7; ++q) {
    auto hp = q_halfplane(th, q);
    const double n = std::hypot(hp.nx, hp.ny), dx = -hp.ny / n, dy = hp.nx / n;
    const double s = (q % 2 ? 1.6 : -1.6) * (1 + 0.12 * q);
    const double x = -1 + s * dx, y = s * dy;
    o << x << " " << y << " " << 0.35 * hp.nx / n << " " << 0.35 * hp.ny / n << " " << q << "\n";
  }
  o << "\n\n";
  // index 8: forbidden region: no inequality holds (intersection of all complements), clipped to a box
  // clipped to the plotted window [-5, 1.5] x [-3, 3] here (gnuplot's own clipping of filled
  // polygons reaching outside the range is unreliable)
  std::vector<std::pair<double, double>> box{{-5, -3}, {1.5, -3}, {1.5, 3}, {-5, 3}};
  for (int q = 0; q <= 7; ++q) {
    auto hp = q_halfplane(th, q);
    box = clip_to_halfplane(box, hp.nx, hp.ny);
  }
  o << "# forbidden region (polygon)\n";
  for (auto& p : box) o << p.first << " " << p.second << "\n";
  if (!box.empty()) o << box[0].first << " " << box[0].second << "\n";
}

const char* kNyquistH = "0.3*(z+1)/(z^2-0.5*z+0.1)";

void nyquist(const fs::path& dir) {
  TransferFunction H = H_of(kNyquistH);
  contact::ContactAnalysis a = contact::analyze_contact(H, 12);
  const double k = a.wedge.gain_infinite ? 1.0 : static_cast<double>(mpfloat<30>(a.wedge.max_gain.value));
  const double kt = a.tsypkin.gain_infinite ? 1.0 : static_cast<double>(mpfloat<30>(a.tsypkin.max_gain.value));
  auto o = open_data_file(dir / "contact_nyquist.dat");
  o << "# H = " << kNyquistH << "; k*_wedge = " << k << "; k*_Tsypkin = " << kt << "\n# index 0: k*_wedge H(e^{j theta}): re im theta\n";
  auto eval = [&](double th) {
    std::complex<double> z = std::polar(1.0, th);
    return k * H.num()(z) / H.den()(z);
  };
  for (int i = 0; i <= 2000; ++i) {
    const double th = M_PI * i / 2000;
    auto h = eval(th);
    o << h.real() << " " << h.imag() << " " << th << "\n";
  }
  o << "\n\n# index 1: same at k*_Tsypkin\n";
  for (int i = 0; i <= 2000; ++i) {
    const double th = M_PI * i / 2000;
    auto h = eval(th) * (kt / k);
    o << h.real() << " " << h.imag() << " " << th << "\n";
  }
  // wedges at several theta: the forbidden region {both branches <= -1} is bounded by the two
  // lines Re h +- m Im h = -1 through -1; index 2+i: polygon, and the point k H(e^{j theta})
  const double thetas[] = {M_PI / 6, M_PI / 3, a.wedge.theta_at_min, 5 * M_PI / 6};
  for (double th : thetas) {
    const double m = std::sin(th) / (1 - std::cos(th));
    std::vector<std::pair<double, double>> box{{-4.5, -3.2}, {3.5, -3.2}, {3.5, 2.2}, {-4.5, 2.2}};  // plot window
    // Re h + m Im h + 1 <= 0  and  Re h - m Im h + 1 <= 0
    box = clip_to_halfplane(box, 1, m);
    box = clip_to_halfplane(box, 1, -m);
    o << "\n\n# wedge at theta = " << th << " (polygon), then the point\n";
    for (auto& p : box) o << p.first << " " << p.second << " " << th << "\n";
    if (!box.empty()) o << box[0].first << " " << box[0].second << " " << th << "\n";
  }
  o << "\n\n# index 6: points k*H(e^{j theta}) at the wedge thetas: re im theta\n";
  for (double th : thetas) {
    auto h = eval(th);
    o << h.real() << " " << h.imag() << " " << th << "\n";
  }
}

void limit_cycle_series(const fs::path& dir) {
  // Fig. 2 from rest (theta = H (r - xi(theta)), r = 1): H = 0.5/((z-0.5) z); the linear loop
  // is stable for k < 2 (exact), the wedge gives k*; below it the penetration settles, above the
  // linear limit a limit cycle (certified exactly) appears.
  TransferFunction H = H_of("0.5/((z-0.5)*z)");
  contact::ContactAnalysis a = contact::analyze_contact(H, 12);
  const double kw = a.wedge.gain_infinite ? 1.0 : static_cast<double>(mpfloat<30>(a.wedge.max_gain.value));
  auto o = open_data_file(dir / "contact_limit_cycle.dat");
  o << "# H = 0.5/((z-0.5) z), r = 1; columns: k  theta_k at k = 0.9 k*_wedge (" << 0.9 * kw
    << "), at k = 2.6 (above the linear limit 2)\n";
  auto s1 = contact::simulate_fig2(H, 0.9 * kw, 1.0, 80), s2 = contact::simulate_fig2(H, 2.6, 1.0, 80);
  for (size_t i = 0; i < s1.size(); ++i) o << i << " " << s1[i] << " " << s2[i] << "\n";
}

void conservatism(const fs::path& dir) {
  auto fam = contact::default_family();
  auto o = open_data_file(dir / "contact_conservatism.dat");
  o << "# device m = 0.2 kg, b = 0.5 Ns/m, T = 1 ms; wall K (1 + 0.002 D(z)) z^-d\n"
    << "# idx  name  k_tsypkin  k_wedge  k_linear  k_osc  wedge_contradicted  tsypkin_contradicted  applies"
       "  (k in N/m; 0 = not available; wedge/Tsypkin -1 = not evaluated)\n";
  int i = 0;
  for (const auto& c : fam) {
    contact::ConservatismRow r = contact::evaluate_case(c, 30000);
    const std::string& nm = r.c.name;  // quoted in the data (gnuplot reads it as one column)
    const double kw = !r.criteria_evaluated ? -1 : r.wedge_inf ? 1e9 : r.k_wedge;
    const double kt = !r.tsypkin_evaluated ? -1 : r.tsypkin_inf ? 1e9 : r.k_tsypkin;
    o << i++ << " \"" << nm << "\" " << kt << " " << kw << " " << (r.k_linear ? *r.k_linear : 0) << " "
      << (r.k_osc ? *r.k_osc : 0) << " " << r.wedge_contradicted << " " << r.tsypkin_contradicted << " "
      << r.assumptions.empty() << "\n";
  }
}

const RegisterFigure f1({"contact_fig4_5", "002",
                         "Fig. 4/5: the shifted unilateral nonlinearity xi(y+rho)-rho and the region it covers", &fig4_5});
const RegisterFigure f2({"contact_fig6", "002",
                         "Fig. 6: the q-inequalities (21)/(22) at theta = pi/4 as half-planes and the forbidden region",
                         &fig6});
const RegisterFigure f3({"contact_nyquist", "002",
                         "Nyquist plot of k*H at the wedge gain with the forbidden wedges of (25) at several theta",
                         &nyquist});
const RegisterFigure f4({"contact_limit_cycle", "002",
                         "Penetration of Fig. 2 below the wedge gain and in a limit cycle above the linear limit",
                         &limit_cycle_series});
const RegisterFigure f5({"contact_conservatism", "002",
                         "Conservatism: k*_Tsypkin, k*_wedge, linear limit and simulated oscillation onset per wall",
                         &conservatism});

}  // namespace
}  // namespace hapstab::cli
