// `hapstab plot nyquist|bode (--H EXPR | --num C --den C | --mat FILE:VAR) --T T [--set NAME=VALUE]...
//   [--delay n] [--wedge] --out DIR [--format png,pdf,svg,tex] [--name NAME] [--digits D] [--json]`
// Figures of the user's own virtual environment H(z), drawn by plots/user_*.gp like every figure
// (cli/figure.hpp): data in DIR/data/, figures in DIR/figures/ (cairolatex in DIR/figures/tex/).
//   nyquist  the curve G(w) = T H(z) z^-n/(1 - z), z = e^{jwT}, 0 < w <= pi/T, whose largest real
//            part is the passivity bound b* of paper 001 (45): b* (certified, passivity::bound, the
//            same number as `hapstab bound`) is drawn as the line Re = b* and its maximiser marked.
//            When H(1) != 0, Im G ~ T H(1)/(wT) grows without bound as w -> 0: the window is cut at
//            |Im| <= the extent of the curve for wT >= pi/20 (and 2 max|Re|), the figure says below
//            which w the curve leaves it, and the JSON gives that w (clip_omega).
//            --wedge adds NAME_wedge: k* H(e^{j theta}) z^-n at the wedge gain k* = k*_wedge with the
//            forbidden wedges (apex -1) of the wedge criterion (25) of paper 002 at theta = pi/6, pi/3,
//            5 pi/6 and its critical theta (contact/wedge.hpp), as contact_nyquist draws k*H.
//   bode     |H(e^{jwT}) z^-n| in dB and its phase in degrees (unwrapped) against w on a log axis,
//            from 10^-4 pi/T to the Nyquist frequency pi/T, with w* of b* marked.
// The curves are numeric (double evaluation of the exact H's rounded coefficients, refined where
// consecutive points are far apart in the plot: resonances); b* is certified.
// JSON: {bound, omega, status, figures: [files], clip_omega (rad/s or null), points}.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/tf_options.hpp"
#include "hapstab/contact/wedge.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/passivity/bound.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"

namespace hapstab::cli::cmd_plot {  // its own namespace: the commands compile in unity batches
namespace {

namespace fs = std::filesystem;
using cplx = std::complex<double>;

const TfRules tf_rules{/*period_required=*/true, /*causal=*/false, /*with_delay=*/true,
                       /*hidden_poles=*/HiddenPoles::allow_marginal};  // the bound objective sees the frequency response

struct Opts {
  TfOptions tf;
  std::string kind, out, format = "png", name;
  int digits = 30;
  bool wedge = false, json = false;
};

// H(e^{j theta}) e^{-j n theta} in double (coefficients rounded once).
struct Response {
  std::vector<double> num, den;  // ascending
  int delay = 0;
  explicit Response(const TransferFunction& H, int n) : delay(n) {
    for (const auto& c : H.num().coeffs()) num.push_back(to_real<double>(c));
    for (const auto& c : H.den().coeffs()) den.push_back(to_real<double>(c));
  }
  static cplx horner(const std::vector<double>& p, cplx z) {
    cplx v = 0;
    for (auto it = p.rbegin(); it != p.rend(); ++it) v = v * z + *it;
    return v;
  }
  cplx operator()(double theta) const {
    const cplx z = std::polar(1.0, theta);
    return horner(num, z) / horner(den, z) * std::polar(1.0, -delay * theta);
  }
};

// G = T H' (1/2 + j cot(theta/2)/2) = T H'/(1 - e^{j theta}), without the cancellation of 1 - e^{j theta}.
cplx nyquist_point(const Response& r, double T, double theta) {
  return T * r(theta) * cplx(0.5, 0.5 / std::tan(theta / 2));
}

struct Sample {
  double theta;
  cplx g;
};

// Dense samples of f on (lo, hi]: log- and linearly spaced, then midpoints inserted wherever two
// neighbours lie more than `step` apart in the plot's scaled coordinates (resonances), at most
// `cap` points; non-finite values (a pole on the circle) are dropped.
template <class F, class Dist>
std::vector<Sample> sample_curve(F f, Dist dist, double lo, double hi, double step, std::vector<double> th = {},
                                 size_t cap = 50000) {
  th.erase(std::remove_if(th.begin(), th.end(), [&](double t) { return !(t > lo && t <= hi); }), th.end());
  for (int i = 0; i <= 2000; ++i) th.push_back(lo * std::pow(hi / lo, i / 2000.0));
  for (int i = 1; i <= 2000; ++i) th.push_back(hi * i / 2000.0);
  std::sort(th.begin(), th.end());
  std::vector<Sample> s;
  for (double t : th) s.push_back({t, f(t)});
  for (int pass = 0; pass < 24 && s.size() < cap; ++pass) {
    std::vector<Sample> next;
    bool added = false;
    for (size_t i = 0; i + 1 < s.size(); ++i) {
      next.push_back(s[i]);
      const double gap = s[i + 1].theta - s[i].theta;
      if (gap > 1e-12 * hi && next.size() + s.size() < cap && !(dist(s[i].g, s[i + 1].g) <= step)) {
        const double m = s[i].theta + gap / 2;
        next.push_back({m, f(m)}), added = true;
      }
    }
    next.push_back(s.back());
    s.swap(next);
    if (!added) break;
  }
  s.erase(std::remove_if(s.begin(), s.end(), [](const Sample& p) { return !std::isfinite(p.g.real()) || !std::isfinite(p.g.imag()); }),
          s.end());
  return s;
}

std::string describe(const Opts& o, const TransferFunction& H) {
  std::string s = !o.tf.H.empty() ? o.tf.H : !o.tf.mat.empty() ? "--mat " + o.tf.mat : H.to_string();
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  std::string values;  // the --set values the expression was drawn at: "K = 1000, B = 5"
  if (!o.tf.H.empty())
    for (const auto& a : o.tf.sets) {
      const size_t eq = a.find('=');
      const std::string v = eq == std::string::npos ? a : a.substr(0, eq) + " = " + a.substr(eq + 1);
      values += ", " + (v.size() > 40 ? v.substr(0, 37) + "..." : v);
    }
  return "H = " + s + values + ", T = " + to_decimal(H.T, 6) + " s" + (o.tf.delay ? ", n = " + std::to_string(o.tf.delay) : "");
}

struct Result {
  passivity::Bound b;
  std::optional<double> clip_omega;
  size_t points = 0;
  std::vector<std::string> figures;
  GnuplotVars labels, wedge_labels;  ///< what the scripts show (H as the user wrote it: untrusted)
};

double omega_star(const passivity::Bound& b) {
  return b.omega_enclosure ? to_real<double>((b.omega_enclosure->lo + b.omega_enclosure->hi) / 2) : std::nan("");
}

// The angles where the curves change fastest: each pole of H near the unit circle (|p| > 0.5),
// +- a few multiples of its distance to the circle (resonances a grid would step over), and the
// maximiser of b*. Poles by the companion matrix in double (deg den <= 200, as for b*).
std::vector<double> critical_angles(const Response& r, double T, const passivity::Bound& b) {
  std::vector<double> th;
  const auto n = Eigen::Index(r.den.size()) - 1;
  if (n >= 1 && n <= 200 && r.den.back() != 0) {
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i) C(0, i) = -r.den[size_t(n - 1 - i)] / r.den.back();
    for (Eigen::Index i = 1; i < n; ++i) C(i, i - 1) = 1;
    const Eigen::VectorXcd p = Eigen::EigenSolver<Eigen::MatrixXd>(C, false).eigenvalues();
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      const double rho = std::abs(p(i)), phi = std::abs(std::arg(p(i))), d = std::max(std::abs(1 - rho), 1e-12);
      if (rho > 0.5)
        for (double k : {0.0, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) th.push_back(phi + k * d), th.push_back(phi - k * d);
    }
  }
  if (b.omega_enclosure) th.push_back(omega_star(b) * T);
  return th;
}

// The Nyquist window: Re over the curve (bounded unless b* = inf: then points 100 times the
// extent away are left out), |Im| up to the curve's extent for theta >= pi/20 and 2 max|Re|.
struct Window {
  double re_lo = 0, re_hi = 0, ylim = 1, xw = 1;
  Window(const std::vector<Sample>& s, bool infinite) {
    double extent = 0, im_max = 0;
    for (const auto& p : s)
      if (p.theta >= M_PI / 20) extent = std::max(extent, std::abs(p.g));
    for (const auto& p : s) {
      if (!infinite || std::abs(p.g) <= 100 * extent) re_lo = std::min(re_lo, p.g.real()), re_hi = std::max(re_hi, p.g.real());
      if (p.theta >= M_PI / 20) im_max = std::max(im_max, std::abs(p.g.imag()));
    }
    ylim = 1.15 * std::max({im_max, 2 * std::max(std::abs(re_lo), std::abs(re_hi)), 1e-300});
    xw = std::max(re_hi - re_lo, 1e-300);
  }
  bool outside(cplx a) const { return std::abs(a.imag()) > ylim || a.real() < re_lo - xw || a.real() > re_hi + xw; }
  double dist(cplx a, cplx b) const {
    if (outside(a) && outside(b)) return 0;  // not drawn: no refinement
    return std::hypot((a.real() - b.real()) / xw, (a.imag() - b.imag()) / (2 * ylim));
  }
};

void nyquist_data(const Opts& o, const TransferFunction& H, const fs::path& datadir, Result& res) {
  const Response r(H, o.tf.delay);
  const double T = to_real<double>(H.T), pi = M_PI;
  auto f = [&](double th) { return nyquist_point(r, T, th); };
  const std::vector<double> extra = critical_angles(r, T, res.b);
  // twice: the first pass finds the peaks (resonances), the second samples in their window
  std::vector<Sample> s = sample_curve(f, [](cplx, cplx) { return 0.0; }, pi * 1e-6, pi, 1, extra);
  Window w(s, res.b.infinite);
  s = sample_curve(f, [&](cplx a, cplx b) { return w.dist(a, b); }, pi * 1e-6, pi, 2e-3, extra);
  w = Window(s, res.b.infinite);
  const double re_lo = w.re_lo, re_hi = w.re_hi, ylim = w.ylim, xw = w.xw;
  auto o_ = open_data_file(datadir / (o.name + ".dat"));
  o_ << "# " << report::comment(describe(o, H)) << "\n# index 0: G = T H z^-n/(1 - z) at z = e^{j w T}: theta = wT, w [rad/s], Re G, Im G"
     << " (points with |Im G| > " << 10 * ylim << " dropped)\n";
  for (const auto& p : s) {
    if (std::abs(p.g.imag()) > 10 * ylim || p.g.real() < re_lo - 10 * xw || p.g.real() > re_hi + 10 * xw) {
      if (p.theta < pi / 20) res.clip_omega = std::max(res.clip_omega.value_or(0.0), p.theta / T);
      continue;
    }
    if (std::abs(p.g.imag()) > ylim && p.theta < pi / 20) res.clip_omega = std::max(res.clip_omega.value_or(0.0), p.theta / T);
    o_ << p.theta << " " << p.theta / T << " " << p.g.real() << " " << p.g.imag() << "\n";
  }
  res.points = s.size();
  const double ws = omega_star(res.b);
  o_ << "\n\n# index 1: the maximiser: Re G = b*, Im G, w*\n";
  const bool mark = !res.b.infinite && std::isfinite(ws) && ws > 0;
  if (mark) o_ << res.b.value_double() << " " << f(ws * T).imag() << " " << ws << "\n";
  else o_ << "NaN NaN NaN\n";
  const double bstar = res.b.infinite ? std::nan("") : res.b.value_double();
  close_data_file(o_, datadir / (o.name + ".dat"));
  res.labels = {{{"what", describe(o, H)}, {"bstar_text", res.b.infinite ? "inf" : to_decimal(res.b.value, 8)},
                 {"infinite_note", res.b.infinite ? res.b.where : ""},
                 {"clip_omega_text", res.clip_omega ? to_decimal(exact_rational(*res.clip_omega), 4) : ""}},
                {{"bstar", bstar}, {"has_bstar", std::isfinite(bstar) ? 1 : 0}, {"has_mark", mark ? 1 : 0},
                 {"ymax", ylim}, {"xmin", std::min(re_lo, std::isfinite(bstar) ? bstar : re_lo) - 0.08 * xw},
                 {"xmax", std::max(re_hi, std::isfinite(bstar) ? bstar : re_hi) + 0.08 * xw}}};
}

void bode_data(const Opts& o, const TransferFunction& H, const fs::path& datadir, Result& res) {
  const Response r(H, o.tf.delay);
  const double T = to_real<double>(H.T), pi = M_PI;
  auto f = [&](double th) { return r(th); };
  auto dist = [pi](cplx a, cplx b) {  // 0.25 dB or 1 degree
    const double db = 20 * std::abs(std::log10(std::abs(a) / std::abs(b)));
    const double deg = std::abs(std::arg(a / b)) * 180 / pi;
    return std::max(db / 0.25, deg / 1.0) * 1e-3;
  };
  std::vector<Sample> s = sample_curve(f, dist, pi * 1e-4, pi, 1e-3, critical_angles(r, T, res.b));
  auto o_ = open_data_file(datadir / (o.name + ".dat"));
  o_ << "# " << report::comment(describe(o, H)) << "\n# index 0: w [rad/s], |H z^-n| [dB], phase [deg] (unwrapped), theta = wT\n";
  double prev = 0, unwrap = 0, db_lo = 1e300, db_hi = -1e300;
  for (size_t i = 0; i < s.size(); ++i) {
    const double ph = std::arg(s[i].g) * 180 / pi;
    if (i > 0) unwrap += std::remainder(ph - prev, 360.0) - (ph - prev);
    prev = ph;
    const double mag = std::abs(s[i].g), db = mag > 0 ? 20 * std::log10(mag) : -400.0;
    if (mag > 0) db_lo = std::min(db_lo, db), db_hi = std::max(db_hi, db);
    o_ << s[i].theta / T << " " << db << " " << ph + unwrap << " " << s[i].theta << "\n";
  }
  // a zero on the unit circle sends the magnitude to -inf: the axis shows 100 dB below the peak
  if (!(db_hi >= db_lo)) db_lo = -1, db_hi = 1;
  db_lo = std::max(db_lo, db_hi - 100);
  res.points = s.size();
  const double ws = omega_star(res.b);
  close_data_file(o_, datadir / (o.name + ".dat"));
  res.labels = {{{"what", describe(o, H)}, {"bstar_text", res.b.infinite ? "inf" : to_decimal(res.b.value, 8)}},
                {{"omega_star", ws}, {"has_mark", std::isfinite(ws) && ws > 0 ? 1 : 0}, {"wmin", pi * 1e-4 / T}, {"wmax", pi / T},
                 {"db_min", db_lo - 5}, {"db_max", db_hi + 5 + 0.05 * (db_hi - db_lo)}}};
}

// k* H(e^{j theta}) z^-n with the forbidden wedges of (25): {Re h + m Im h <= -1 and Re h - m Im h
// <= -1}, m = cot(theta/2), clipped to the window; k* = k*_wedge of H z^-n (contact/wedge.hpp).
// The wedges (apex -1) are the criterion's for the loop gain k H: at k = k*_wedge the curve touches
// the wedge of its critical theta, as in contact_nyquist. When k*_wedge is infinite (every k > 0
// passes) or not evaluated, the curve is H itself (k = 1) and the title says so.
void wedge_data(const Opts& o, const TransferFunction& H, const fs::path& datadir, Result& res) {
  std::vector<rational> zn(static_cast<size_t>(o.tf.delay) + 1, rational(0));
  zn.back() = 1;
  const TransferFunction Hn = tf(H.num(), H.den() * Polynomial<rational>(std::move(zn)), H.T);  // H z^-n: the loop's H
  contact::ContactAnalysis a;
  try {
    a = contact::analyze_contact(Hn, 20);
  } catch (const InputError& e) {
    throw InputError(std::string("--wedge: ") + e.what());
  }
  const bool at_kstar = a.wedge.evaluated() && !a.wedge.gain_infinite;
  const double k = at_kstar ? to_real<double>(a.wedge.max_gain.value) : 1.0;
  const Response response(Hn, 0);
  const auto r = [&](double th) { return k * response(th); };  // the loop gain k H on the circle
  std::vector<Sample> curve;
  double x0 = -1.5, x1 = 0.5, y0 = -1, y1 = 1;
  for (int i = 0; i <= 4000; ++i) {
    const double th = M_PI * i / 4000;
    const cplx h = r(th);
    if (!std::isfinite(h.real()) || !std::isfinite(h.imag())) continue;
    curve.push_back({th, h});
    x0 = std::min(x0, h.real()), x1 = std::max(x1, h.real()), y0 = std::min(y0, h.imag()), y1 = std::max(y1, h.imag());
  }
  const double px = 0.1 * (x1 - x0), py = 0.1 * (y1 - y0);
  x0 -= px, x1 += px, y0 -= py, y1 += py;
  auto w = open_data_file(datadir / (o.name + "_wedge.dat"));
  w << "# " << report::comment(describe(o, H)) << "\n# index 0: k H(e^{j theta}) e^{-j n theta} with k = " << k
    << (at_kstar ? " (k*_wedge)" : "") << ": Re, Im, theta\n";
  for (const auto& p : curve) w << p.g.real() << " " << p.g.imag() << " " << p.theta << "\n";
  const double crit = a.wedge.evaluated() ? a.wedge.theta_at_min : M_PI / 2;
  const double thetas[] = {M_PI / 6, M_PI / 3, crit, 5 * M_PI / 6};
  for (double th : thetas) {
    const double m = std::sin(th) / (1 - std::cos(th));
    auto poly = clip_to_halfplane({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, 1, m);
    poly = clip_to_halfplane(poly, 1, -m);
    w << "\n\n# wedge at theta = " << th << " (polygon)\n";
    for (const auto& p : poly) w << p.first << " " << p.second << " " << th << "\n";
    if (!poly.empty()) w << poly[0].first << " " << poly[0].second << " " << th << "\n";
    else w << "NaN NaN NaN\n";
  }
  w << "\n\n# index 5: k H(e^{j theta}) at the wedge thetas\n";
  for (double th : thetas) w << r(th).real() << " " << r(th).imag() << " " << th << "\n";
  const std::string verdict = !a.wedge.evaluated() ? "wedge (25) not evaluated: " + a.wedge.verdict.evidence
                              : a.wedge.gain_infinite ? "k*_wedge = inf"
                                                      : "k*_wedge = " + to_decimal(a.wedge.max_gain.value, 6);
  // the curve's name in the legend and on the axes: k*H at the wedge gain, else H
  const std::string curve_name = at_kstar ? "k*H" : "H";
  close_data_file(w, datadir / (o.name + "_wedge.dat"));
  res.wedge_labels = {{{"what", describe(o, H)}, {"verdict", verdict + (at_kstar ? ": the curve is k*H" : ": the curve is H")},
                       {"curve", curve_name}},
                      {{"xmin", x0}, {"xmax", x1}, {"ymin", y0}, {"ymax", y1}, {"theta_crit", crit}}};
}

// plots/<script>.gp draws DIR/figures/<stem>.<format> from DIR/data/<name>*.
void draw(const std::string& script, const std::string& name, const std::string& stem, const fs::path& dir,
          const std::vector<std::string>& formats, const GnuplotVars& labels, Result& res) {
  for (const auto& f : formats) {
    // the script reads DIR/data/<name>*.dat: its name comes from --name, passed as `name`
    run_gnuplot(script, dir / "data", dir / "figures", f, name, labels);
    const std::string ext = f == "tex" ? "tex" : f;
    res.figures.push_back(((f == "tex" ? dir / "figures" / "tex" : dir / "figures") / (stem + "." + ext)).string());
  }
}

int run(const Opts& o) {
  if (o.kind != "nyquist" && o.kind != "bode") throw InputError("plot: expected nyquist or bode (got '" + report::text(o.kind) + "')");
  if (o.wedge && o.kind != "nyquist") throw InputError("--wedge: only with plot nyquist");
  if (o.digits < 10 || o.digits > 280) throw InputError("--digits must be in [10, 280]");
  Opts opt = o;
  if (opt.name.empty()) opt.name = o.kind;
  report::file_component(opt.name, "--name");
  const auto formats = figure_formats(o.format);
  const TransferFunction H = parse_tf_options(o.tf, tf_rules);
  const fs::path dir = output_folder(o.out, "--out");
  fs::create_directories(dir / "data");
  passivity::BoundProblem p;
  p.H = H.H, p.T = H.T, p.delay = o.tf.delay;
  Result res;
  res.b = passivity::bound(p, passivity::Method::certified, o.digits);
  if (o.kind == "nyquist") nyquist_data(opt, H, dir / "data", res);
  else bode_data(opt, H, dir / "data", res);
  draw("user_" + o.kind, opt.name, opt.name, dir, formats, res.labels, res);
  if (o.wedge) {
    wedge_data(opt, H, dir / "data", res);
    draw("user_wedge", opt.name, opt.name + "_wedge", dir, formats, res.wedge_labels, res);
  }
  nlohmann::json j{{"bound", res.b.decimal},
                   {"omega", res.b.omega ? nlohmann::json(*res.b.omega) : nlohmann::json(nullptr)},
                   {"status", to_string(res.b.status)},
                   {"clip_omega", res.clip_omega ? nlohmann::json(*res.clip_omega) : nlohmann::json(nullptr)},
                   {"points", res.points},
                   {"figures", res.figures}};
  if (o.json) print_json(j);
  else {
    std::cout << "b* = " << j["bound"].get<std::string>() << "   [" << j["status"].get<std::string>() << "]"
              << (res.b.omega ? " at w* = " + *res.b.omega + " rad/s" : "") << "\n";
    if (res.clip_omega) std::cout << "  the Nyquist curve leaves the window for w < " << *res.clip_omega << " rad/s (Im G ~ T H(1)/(wT))\n";
    for (const auto& f : res.figures) std::cout << "  " << f << "\n";
  }
  return exit_ok;
}

const Register reg({"plot",
                    "Nyquist plot of T H z^-n/(1-z) with b* marked, or Bode plot of H, for your own H (PNG/PDF/SVG/cairolatex)",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      app.add_option("kind", o->kind, "nyquist or bode")->required();
                      add_tf_options(app, o->tf, tf_rules, "H(z) as an exact expression, e.g. \"K + B*(z-1)/(T*z)\"");
                      app.add_option("--out", o->out, "output folder (data/ and figures/ inside)")->required();
                      app.add_option("--format", o->format, "comma-separated: png, pdf, svg, tex (default png)");
                      app.add_option("--name", o->name, "file name of the figure (default: nyquist or bode)");
                      app.add_option("--digits", o->digits, "digits of the certified b* (default 30, as hapstab bound)");
                      app.add_flag("--wedge", o->wedge, "nyquist: also NAME_wedge, H with the forbidden wedges of (25), paper 002");
                      app.add_flag("--json", o->json, "JSON output (bound, omega, status, clip_omega, points, figures)");
                      return [o]() { return run(*o); };
                    }});

}  // namespace
}  // namespace hapstab::cli::cmd_plot
