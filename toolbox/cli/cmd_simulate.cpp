// `hapstab simulate --scene FILE --out DIR [--json] [--quiet] [--force] [--set NAME=VALUE] [--format csv|mat|csv,mat]`:
// runs a scene's sampled-data loop with the exact-ZOH simulator (sim/) and writes
//   DIR/samples.csv   time series at the sample instants (one header row: t [s], x_0 [m], v_0 [m/s], ...)
//   DIR/fine.csv      the exact intersample grid (when [simulate] substeps > 1)
//   DIR/plot.gp       the gnuplot script that draws them (gnuplot plot.gp, in DIR)
//   DIR/samples.mat   with --format mat: the same series as MATLAB matrices (write_mat_samples)
//   DIR/summary.json  {diverged, max_velocity, energy_generated, limit_cycle: {period, amplitude} | null, ...}
// It also registers the simulator's figures (experiments of paper 001 and 002) with
// `hapstab figure` / `hapstab reproduce`.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/contact/limit_cycle.hpp"
#include "hapstab/lti/discretize.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/scene/run.hpp"
#include "hapstab/scene/schema.hpp"
#include "hapstab/sim/hidden_modes.hpp"
#include "hapstab/sim/simulator.hpp"

namespace hapstab::cli::cmd_simulate {  // its own namespace: the commands compile in unity batches
namespace {

namespace fs = std::filesystem;

struct Opts {
  std::string scene, out;
  bool json = false, quiet = false, force = false;
  std::string format = "csv";
  double max_mb = 200;
  std::vector<std::string> sets;
};

nlohmann::json num_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json summary_json(const sim::Summary& s, const scene::Scene& sc) {
  nlohmann::json j;
  j["diverged"] = s.diverged;
  j["max_velocity"] = num_or_null(s.max_velocity);
  j["energy_generated"] = num_or_null(s.energy_generated);
  if (s.limit_cycle) {
    j["limit_cycle"] = {{"period", s.limit_cycle->period}, {"amplitude", s.limit_cycle->amplitude}};
    if (s.limit_cycle->period_samples > 0) j["limit_cycle"]["period_samples"] = s.limit_cycle->period_samples;
  } else {
    j["limit_cycle"] = nullptr;
  }
  j["trend"] = s.trend;
  j["step_matrix_radius"] = s.step_matrix_radius;  // the exact ZOH matrices' proven error (Arb)
  j["steps_run"] = s.steps_run;
  j["min_port_energy"] = num_or_null(s.min_port_energy);
  j["port_energy"] = s.e_port;
  j["actuator_energy"] = s.e_act;
  j["passivity_observer"] = s.e_po;
  j["status"] = "numeric";
  j["method"] = "exact ZOH discretisation (50-digit Van Loan exponentials rounded to double), double recursion";
  if (!sc.loop.coulomb.empty()) {
    j["method"] = j["method"].get<std::string>() +
                  "; Coulomb friction: stick/slip events located by bisection (1e-15 T) on T/16 sub-steps, double "
                  "matrix exponentials (sim/coulomb.hpp)";
    j["friction_events"] = s.friction_events;
  }
  if (!sc.loop.passivity_controller.empty()) {
    j["pc_dissipated"] = s.pc_dissipated;
    j["pc_active_samples"] = s.pc_active;
  }
  if (!sc.loop.quantizers.empty()) j["quantum"] = to_decimal(sc.loop.quantizers.front().step, 17);
  j["scene"] = sc.file;
  j["T"] = to_decimal(sc.T, 17);
  return j;
}

/// A CSV column header: "v_0 [m/s]".
std::string column_name(const char* name, int dof, const char* unit) {
  return std::string(name) + "_" + std::to_string(dof) + " [" + unit + "]";
}

void write_csv(const fs::path& dir, const sim::SimResult& r) {
  const auto& S = r.samples;
  const int N = S.N;
  {
    std::ofstream f(dir / "samples.csv");
    if (!f) throw InputError("--out: cannot write " + (dir / "samples.csv").string());
    // One header row, `name_j [unit]` (j the DOF index, as in watch_dof), so pandas.read_csv and
    // MATLAB's readtable read the file without options; through the CSV writer (report/escape.hpp).
    const char* names[] = {"x", "v", "u", "fh", "E_port", "E_act", "E_po", "storage"};
    const char* units[] = {"m", "m/s", "N", "N", "J", "J", "J", "J"};
    f << report::csv::cell("t [s]");
    for (int j = 0; j < N; ++j)
      for (int c = 0; c < 8; ++c) f << ',' << report::csv::cell(column_name(names[c], j, units[c]));
    f << "\n" << std::setprecision(17);
    for (size_t i = 0; i < S.rows(); ++i) {
      f << S.t[i];
      for (int j = 0; j < N; ++j) {
        const size_t k = i * size_t(N) + size_t(j);
        f << ',' << S.x[k] << ',' << S.v[k] << ',' << S.u[k] << ',' << S.fh[k] << ',' << S.e_port[k] << ','
          << S.e_act[k] << ',' << S.e_po[k] << ',';
        if (std::isfinite(S.storage[k])) f << S.storage[k];
        else f << "NaN";
      }
      f << '\n';
    }
    close_data_file(f, dir / "samples.csv");
  }
  if (r.fine.rows() > 0) {
    const auto& F = r.fine;
    std::ofstream f = open_data_file(dir / "fine.csv");
    f << report::csv::cell("t [s]");
    for (int j = 0; j < N; ++j)
      f << ',' << report::csv::cell(column_name("x", j, "m")) << ',' << report::csv::cell(column_name("v", j, "m/s"));
    f << "\n" << std::setprecision(17);
    for (size_t i = 0; i < F.rows(); ++i) {
      f << F.t[i];
      for (int j = 0; j < N; ++j) f << ',' << F.x[i * size_t(N) + size_t(j)] << ',' << F.v[i * size_t(N) + size_t(j)];
      f << '\n';
    }
    close_data_file(f, dir / "fine.csv");
  }
}

// --format mat: DIR/samples.mat (level 5, zlib; MATLAB's load and scipy.io.loadmat read it) with
// t (rows x 1, s) and per quantity a rows x N matrix, column j = DOF j: x [m], v [m/s], u [N],
// fh [N], E_port, E_act, E_po, storage [J] (NaN where undefined); T (s); and when the scene asks
// for the intersample grid, fine_t, fine_x, fine_v.
void write_mat_samples(const fs::path& file, const sim::SimResult& r, const rational& T) {
  const auto& S = r.samples;
  const size_t N = size_t(S.N), rows = S.rows();
  auto per_dof = [&](const char* name, const std::vector<double>& row_major, size_t n_rows) {
    MatMatrix m{name, n_rows, N, std::vector<double>(n_rows * N)};
    for (size_t i = 0; i < n_rows; ++i)
      for (size_t j = 0; j < N; ++j) m.data[j * n_rows + i] = row_major[i * N + j];
    return m;
  };
  std::vector<MatMatrix> vars{{"T", 1, 1, {to_real<double>(T)}}, {"t", rows, 1, S.t}};
  const std::pair<const char*, const std::vector<double>*> series[] = {
      {"x", &S.x},           {"v", &S.v},         {"u", &S.u},       {"fh", &S.fh},
      {"E_port", &S.e_port}, {"E_act", &S.e_act}, {"E_po", &S.e_po}, {"storage", &S.storage}};
  for (const auto& [name, data] : series) vars.push_back(per_dof(name, *data, rows));
  if (r.fine.rows() > 0) {
    vars.push_back({"fine_t", r.fine.rows(), 1, r.fine.t});
    vars.push_back(per_dof("fine_x", r.fine.x, r.fine.rows()));
    vars.push_back(per_dof("fine_v", r.fine.v, r.fine.rows()));
  }
  write_mat(file, vars);
}

// Every string from the scene reaches the script as a gnuplot string literal (report::gnuplot::quote),
// and for the cairolatex terminal, whose text LaTeX typesets, LaTeX-escaped first. Each DOF is
// named by its device ("left", or "arm[1]" for the second DOF of a 2-DOF device) and keeps one
// colour of the Okabe-Ito palette (plots/common.gp's) in every panel; the quantities of the energy
// plot are told apart by dash type.
void write_gnuplot(const fs::path& dir, const scene::Scene& sc, int N, bool fine) {
  using report::gnuplot::quote;
  // checked: a plot.gp left in --out that could not be replaced would be run by the user instead
  std::ofstream g = open_data_file(dir / "plot.gp");
  g << "# Draws the series of `hapstab simulate` (scene " << report::comment(sc.file) << ").\n"
    << "# Run in this folder: gnuplot plot.gp   (or gnuplot -e \"fmt='pdf'\" plot.gp; fmt: png pdf svg tex)\n"
    << "if (!exists(\"fmt\")) fmt = 'png'\n"
    << "set datafile separator ','\nset datafile missing 'NaN'\n"
    << "set grid lc rgb '#d0d0d0' lw 0.5\nset key box opaque samplen 2\nset xlabel 't [s]'\n"
    << "ext = (fmt eq 'tex') ? 'tex' : fmt\n"
    << "if (fmt eq 'png') set terminal pngcairo size 1600,1000 enhanced font 'DejaVu Sans,20' linewidth 2\n"
    << "if (fmt eq 'pdf') set terminal pdfcairo size 6in,3.75in enhanced font 'DejaVu Sans,10'\n"
    << "if (fmt eq 'svg') set terminal svg size 1200,750 enhanced background rgb 'white'\n"
    << "if (fmt eq 'tex') set terminal cairolatex pdf size 5in,3.1in\n"
    << "# the Okabe-Ito palette (colour-blind safe), one colour per DOF\n";
  const char* palette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  for (int k = 0; k < 8; ++k) g << "set linetype " << k + 1 << " lc rgb '" << palette[k] << "' lw 2\n";
  g << "set linetype cycle 8\n"
    << "int_fhv = (fmt eq 'tex') ? '$\\int f_h v\\,dt$' : '\xE2\x88\xAB f_h v dt'\n"
    << "int_uv = (fmt eq 'tex') ? '$\\int u v\\,dt$' : '\xE2\x88\xAB u v dt'\n"
    << "scene_title = (fmt eq 'tex') ? " << quote(report::latex::escape(sc.name)) << " : " << quote(sc.name) << "\n";
  // dof_J: the label of DOF J, by its device's name
  int j = 0;
  for (const auto& d : sc.loop.devices)
    for (Eigen::Index k = 0; k < d.dofs(); ++k, ++j) {
      const std::string label = d.dofs() == 1 ? d.name : d.name + "[" + std::to_string(k) + "]";
      g << "dof_" << j << " = (fmt eq 'tex') ? " << quote(report::latex::escape(label)) << " : " << quote(label) << "\n";
    }
  for (; j < N; ++j) g << "dof_" << j << " = 'DOF " << j << "'\n";  // not reached: the devices hold every DOF
  auto cols = [&](const char* what, int off, const char* ylabel, bool with_fine) {
    g << "set output '" << what << ".'.ext\nset ylabel '" << ylabel << "'\nset title scene_title noenhanced\nplot ";
    for (int j = 0; j < N; ++j) {
      if (j) g << ", ";
      if (with_fine && fine)
        g << "'fine.csv' skip 1 using 1:" << (off == 2 ? 2 + 2 * j : 3 + 2 * j) << " with lines lt " << j + 1
          << " lw 1 title dof_" << j << ".' (exact, between samples)' noenhanced, ";
      g << "'samples.csv' skip 1 using 1:" << (off + 8 * j) << " with "
        << (with_fine && fine ? "points pt 7 ps 0.6" : "lines") << " lt " << j + 1 << " title dof_" << j
        << (with_fine && fine ? ".' at samples'" : "") << " noenhanced";
    }
    g << "\n";
  };
  for (const auto& p : sc.simulate.plots) {
    if (p == "position") cols("position", 2, "x [m]", true);
    if (p == "velocity") cols("velocity", 3, "v [m/s]", true);
    if (p == "force") cols("force", 4, "u [N]", false);
    if (p == "energy") {
      g << "set output 'energy.'.ext\nset ylabel 'energy [J]'\nset title 'port energies' noenhanced\nplot ";
      for (int j = 0; j < N; ++j) {
        if (j) g << ", ";
        g << "'samples.csv' skip 1 using 1:" << 6 + 8 * j << " with lines lt " << j + 1 << " title dof_" << j
          << ".': '.int_fhv noenhanced, "
          << "'samples.csv' skip 1 using 1:" << 8 + 8 * j << " with lines lt " << j + 1 << " dt 2 title dof_" << j
          << ".': passivity observer' noenhanced, "
          << "'samples.csv' skip 1 using 1:" << 7 + 8 * j << " with lines lt " << j + 1 << " dt 3 title dof_" << j
          << ".': '.int_uv noenhanced";
      }
      g << "\n";
    }
  }
  close_data_file(g, dir / "plot.gp");
}

int run(const Opts& o) {
  if (o.format != "csv" && o.format != "mat" && o.format != "csv,mat" && o.format != "mat,csv")
    throw InputError("--format: expected csv, mat or csv,mat (got '" + report::text(o.format) + "')");
  // a limit that is NaN, infinite or negative would disable or invert the check: refused
  if (!std::isfinite(o.max_mb) || o.max_mb < 0) {
    std::ostringstream os;
    os << "--max-output: the output size limit must be a finite number of MB >= 0, got " << o.max_mb;
    throw InputError(os.str());
  }
  const bool csv = o.format.find("csv") != std::string::npos, mat = o.format.find("mat") != std::string::npos;
  auto sc = scene::load_scene(o.scene, parse_sets(o.sets));
  scene::SceneRun prepared = scene::prepare_run(sc);
  const auto& S = sc.simulate;
  const sim::Simulator* simulator = prepared.simulator.get();
  const int N = simulator->loop().N;
  // Output size check before running.
  const double rows = prepared.rows, fine_rows = prepared.fine_rows;
  const double bytes = rows * (1 + 8 * N) * 24 + fine_rows * (1 + 2 * N) * 24;
  if (bytes > o.max_mb * 1e6 && !o.force) {
    std::ostringstream os;
    os << o.scene << ": simulate: the run would write about " << std::fixed << std::setprecision(0) << bytes / 1e6
       << " MB, more than the limit of " << o.max_mb
       << " MB; raise simulate.record_every, narrow simulate.window, or pass --force (or --max-output MB)";
    throw InputError(os.str());
  }
  const fs::path dir = output_folder(o.out, "--out");  // before the run, which may take long
  sim::SimOptions so = prepared.options;
  const auto t0 = std::chrono::steady_clock::now();
  if (!o.quiet && S.steps >= 2000000)
    so.progress = [](double f) {
      std::cerr << "\rsimulate: " << int(f * 100 + 0.5) << "%" << std::flush;
      if (f >= 1) std::cerr << "\n";
    };
  sim::SimResult r;
  try {
    r = simulator->run(so);
  } catch (const InputError& e) {
    throw InputError(o.scene + ": " + e.what());
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (csv) write_csv(dir, r);
  if (csv) write_gnuplot(dir, sc, N, r.fine.rows() > 0);
  if (mat) write_mat_samples(dir / "samples.mat", r, sc.T);
  auto j = summary_json(r.summary, sc);
  j["seconds"] = secs;
  // Internal stability from the blocks' hidden modes (exact; sim/hidden_modes.hpp): a mode no
  // input reaches or no output shows may leave the sampled outputs at rest while it grows.
  const sim::LoopHiddenModes hidden = sim::hidden_modes(sc.loop);
  nlohmann::json hj = nlohmann::json::array();
  for (const auto& h : hidden.modes)
    hj.push_back({{"block", h.block}, {"kind", h.kind}, {"where", h.where.text(h.discrete ? "z" : "s", h.pair)}, {"stable", h.stable}});
  j["hidden_modes"] = hj;
  j["internally_unstable"] = !hidden.stable();
  if (!hidden.stable()) j["internal_instability"] = hidden.summary();
  {
    std::ofstream f = open_data_file(dir / "summary.json");
    f << j.dump(2) << "\n";
    close_data_file(f, dir / "summary.json");
  }
  if (o.json) {
    print_json(j);
  } else if (!o.quiet) {
    const auto& s = r.summary;
    std::cout << sc.name << ": " << s.steps_run << " steps in " << secs << " s\n"
              << "  diverged          " << (s.diverged ? "yes" : "no") << "\n"
              << "  max |v|           " << s.max_velocity << " m/s\n"
              << "  energy generated  " << s.energy_generated << " J  (max over t of -sum_j int f_h v dt; numeric)\n"
              << "  trend             " << s.trend << "\n";
    if (!hidden.stable())
      std::cout << "  INTERNALLY UNSTABLE (exact, whatever the samples show): " << hidden.summary() << "\n";
    else if (!hidden.modes.empty())
      std::cout << "  hidden modes      " << hidden.summary() << "\n";
    if (s.limit_cycle)
      std::cout << "  limit cycle       period " << s.limit_cycle->period << " s, amplitude " << s.limit_cycle->amplitude
                << " m" << (s.limit_cycle->period_samples > 0 ? " (sampled sequence exactly periodic)" : "") << "\n";
    else
      std::cout << "  limit cycle       none\n";
    std::cout << "  files             " << (csv ? (dir / "samples.csv").string() + (r.fine.rows() > 0 ? ", fine.csv" : "") + ", plot.gp, " : "")
              << (mat ? (dir / "samples.mat").string() + ", " : "") << "summary.json\n";
  }
  return exit_ok;
}


// ---- figures of the simulator's experiments (hapstab figure / reproduce) ------------------

sim::SimResult run_scene(const scene::Scene& sc, long record_every = 1) {
  sim::Simulator simulator(sc.loop);
  sim::SimOptions so;
  so.steps = sc.simulate.steps;
  so.record_every = record_every;
  so.substeps = sc.simulate.substeps;
  so.fine_from = sc.simulate.window_from;
  so.fine_to = sc.simulate.window_to;
  so.max_velocity = sc.simulate.max_velocity;
  return simulator.run(so);
}

void write_tightness(const fs::path& dir) {
  for (const char* side : {"below", "above"}) {
    auto sc = scene::load_scene((examples_dir() / (std::string("001_tightness_") + side + ".toml")).string());
    sc.simulate.substeps = 1;
    auto r = run_scene(sc);
    std::ofstream f(dir / (std::string("sim_tightness_") + side + ".dat"));
    // the first row is t = 0- (before the impulse: at rest, no energy in), so the energy curve starts
    // at 0 and the impulse's work at the human port shows as the jump at t = 0
    f << "# t  v  int f_h v dt   (" << report::comment(sc.name) << "); first row: t = 0-, before the impulse\n"
      << std::setprecision(12) << "0 0 0\n";
    for (size_t i = 0; i < r.samples.rows(); ++i) f << r.samples.t[i] << ' ' << r.samples.v[i] << ' ' << r.samples.e_port[i] << '\n';
  }
  // Random passive operators Z_O = mo s + bo + ko/s at b = 1.01 b*.
  auto sc = scene::load_scene((examples_dir() / "001_tightness_above.toml").string());
  std::mt19937 g(2024);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<std::vector<double>> cols;
  std::vector<double> t;
  for (int i = 0; i < 24; ++i) {
    auto spec = sc.loop;
    spec.operators = {sim::mass_spring_damper_operator("random", 0, exact_rational(1e-3 * U(g)), exact_rational(5 * U(g)),
                                                       exact_rational(2e5 * U(g)))};
    sim::Simulator simulator(spec);
    sim::SimOptions so;
    so.steps = sc.simulate.steps;
    auto r = simulator.run(so);
    if (t.empty()) t = r.samples.t;
    cols.push_back(r.samples.e_port);
  }
  std::ofstream f(dir / "sim_tightness_random.dat");
  f << "# t  int f_h v dt of each operator; first row: t = 0-, before the impulse\n" << std::setprecision(12) << 0;
  for (size_t k = 0; k < cols.size(); ++k) f << " 0";
  f << '\n';
  for (size_t i = 0; i < t.size(); ++i) {
    f << t[i];
    for (const auto& c : cols) f << ' ' << (i < c.size() ? c[i] : 0.0);
    f << '\n';
  }
}

void write_bias_wall(const fs::path& dir) {
  auto sc = scene::load_scene((examples_dir() / "002_bias_wall.toml").string());
  auto r = run_scene(sc);
  // The reduced discrete model of paper 002 Fig. 2: H = E(z) P_zoh(z), r = f_bias / E(1), with
  // P(s) = 1/((m+mo) s^2 + (b+bo) s + ko) (device + operator, force -> position), discretised
  // exactly for the hold (50 digits, rounded to rationals 1e-50 away).
  const auto& p = sc.parameters;
  const rational M = p.at("m") + p.at("mo"), bt = p.at("b") + p.at("bo"), k = p.at("ko");
  Mat<mp50> A(2, 2), B(2, 1);
  A << 0, 1, mp50(-k / M), mp50(-bt / M);
  B << 0, mp50(1 / M);
  auto zp = zoh_pair<mp50>(A, B, to_real<mp50>(sc.T));
  StateSpace<rational> Pd;
  Pd.A = Mat<rational>(2, 2);
  Pd.B = Mat<rational>(2, 1);
  for (int i = 0; i < 4; ++i) Pd.A.data()[i] = exact_rational(zp.Phi.data()[i]);
  for (int i = 0; i < 2; ++i) Pd.B.data()[i] = exact_rational(zp.Gamma.data()[i]);
  Pd.C = Mat<rational>(1, 2);
  Pd.C << 1, 0;
  Pd.D = Mat<rational>::Zero(1, 1);
  Pd.T = sc.T;
  ParseOptions po;
  po.variable = 'z';
  po.T = sc.T;
  po.parameters = p;
  const auto E = parse_tf("K + B*(z-1)/(T*z)", po);
  const auto H = series(E, ss2tf(Pd)(0, 0));
  const rational E1 = p.at("K");
  const double rr = to_real<double>(p.at("F") / E1);
  auto theta = contact::simulate_fig2(H, 1.0, rr, long(r.samples.rows()));
  const double T = to_real<double>(sc.T);
  const double t0 = sc.simulate.window_from, t1 = sc.simulate.window_to;
  std::ofstream fs_(dir / "sim_bias_wall_samples.dat"), ff(dir / "sim_bias_wall_fine.dat");
  fs_ << "# t  x(kT) full model  theta_k reduced model (paper 002 Fig. 2)\n" << std::setprecision(15);
  double maxdiff = 0, scale = 0, pen_s = 0, pen_f = 0;
  for (size_t i = 0; i < r.samples.rows() && i < theta.size(); ++i) {
    maxdiff = std::max(maxdiff, std::fabs(r.samples.x[i] - theta[i]));
    scale = std::max(scale, std::fabs(theta[i]));
    if (r.samples.t[i] >= t0 && r.samples.t[i] <= t1) {
      fs_ << r.samples.t[i] << ' ' << r.samples.x[i] << ' ' << theta[i] << '\n';
      pen_s = std::max(pen_s, r.samples.x[i]);
    }
  }
  ff << "# t  x(t) full model, exact between samples\n" << std::setprecision(15);
  for (size_t i = 0; i < r.fine.rows(); ++i) {
    ff << r.fine.t[i] << ' ' << r.fine.x[i] << '\n';
    pen_f = std::max(pen_f, r.fine.x[i]);
  }
  fs_ << "# max |x(kT) - theta_k| / max|theta| = " << maxdiff / scale << " over " << theta.size() << " samples (T = " << T
      << ")\n# max penetration at samples " << pen_s << " m, between samples " << pen_f << " m\n";
}

const RegisterFigure fig_tightness({"sim_tightness", "001",
                                    "Tightness of the passivity bound b* = KT/2 + B: a passive operator tuned to wT = pi "
                                    "destabilises b = 0.99 b*; at 1.01 b* no passive operator draws energy out",
                                    &write_tightness});
const RegisterFigure fig_bias_wall({"sim_bias_wall", "002",
                                    "Operator pressing on a sampled wall with a bias force: the full sampled-data model "
                                    "(between samples) against the reduced discrete model of Fig. 2",
                                    &write_bias_wall});

const Register simulate_cmd({"simulate",
                             "Simulate a scene's sampled-data loop exactly (ZOH) and write CSV, gnuplot script, summary",
                             [](CLI::App& app) {
                               auto o = std::make_shared<Opts>();
                               app.add_option("--scene", o->scene, "Scene file (TOML; see examples/README.md)")->required();
                               app.add_option("--out", o->out, "Output folder")->required();
                               app.add_flag("--json", o->json, "Print the summary as JSON");
                               app.add_flag("--quiet", o->quiet, "No progress and no human summary");
                               app.add_flag("--force", o->force, "Write even when the output exceeds --max-output");
                               app.add_option("--max-output", o->max_mb, "Output size limit in MB (default 200)");
                               app.add_option("--set", o->sets, "Override a scene parameter: NAME=VALUE (exact)");
                               app.add_option("--format", o->format, "csv (default), mat (MATLAB samples.mat) or csv,mat");
                               return [o]() { return run(*o); };
                             }});

}  // namespace
}  // namespace hapstab::cli::cmd_simulate
