// cli/sweep_plot.cpp -- `hapstab sweep plot DIR --x K --y B --z bound`: a heat map (or contour
// lines) of one column of DIR/points.csv over two others, drawn by plots/sweep_map.gp (or
// plots/sweep_contour.gp) into DIR/figures/. Points are told apart by the row's `status`
// column: certified or exact (solid cells), numeric (hatched cells, not proven), infinite
// values (grey cells) and failed points (crossed cells).
// DIR is untrusted (a sweep folder received from someone else, possibly read-only, possibly
// holding planted files and symbolic links; docs/security.md): points.csv is read as a regular
// file inside DIR, the plot data is written to a fresh private folder (report::PrivateFolder),
// never into DIR, the column names reach gnuplot as -e values (GnuplotVars), gnuplot loads
// nothing but the installed scripts, and the figure is copied into DIR/figures by
// report::install_file (a symbolic link at DIR/figures is refused, one at the figure's name is
// replaced, never followed).
// The figures sweep_map and sweep_contour of `hapstab reproduce` are the (K, B) region as a sweep.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <cctype>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/sweep_cli.hpp"
#include "hapstab/study/spec.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/process.hpp"

namespace hapstab::cli::sweep {

namespace fs = std::filesystem;

namespace {

/// The bytes one record of points.csv may hold (a row is a few hundred bytes).
constexpr size_t max_record_bytes = 1u << 20;

/// The fields of one CSV record (RFC 4180 quoting; a record may span lines inside quotes).
bool read_csv_record(std::istream& in, std::vector<std::string>& fields) {
  fields.assign(1, "");
  bool quoted = false, any = false;
  size_t bytes = 0;
  for (int c; (c = in.get()) != EOF;) {
    any = true;
    if (++bytes > max_record_bytes)
      throw InputError("sweep plot: a record of points.csv is longer than " + std::to_string(max_record_bytes) + " bytes");
    if (quoted) {
      if (c == '"' && in.peek() == '"') fields.back() += static_cast<char>(in.get());
      else if (c == '"') quoted = false;
      else fields.back() += static_cast<char>(c);
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      return true;
    } else {
      fields.back() += static_cast<char>(c);
    }
  }
  return any;
}

size_t column_of(const std::vector<std::string>& head, const std::string& name, const std::string& option) {
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == name) return k;
  std::string cols;
  for (const auto& h : head) cols += " " + h;
  throw InputError(option + " '" + name + "': points.csv has no such column (columns:" + cols + ")");
}

std::string number_for_plot(const std::string& text) {
  const auto q = try_parse_rational(text);
  if (!q) return "";
  std::ostringstream os;
  os.precision(17);
  os << to_real<double>(*q);
  return os.str();
}

const char* const plot_files[] = {"proven.dat", "numeric.dat", "infinite.dat", "failed.dat"};

/// The edges of the cell of each distinct value v_0 < v_1 < ... of one axis: halfway to each
/// neighbour (geometric halfway on a log axis), the outer edges as far out as the inner ones, so
/// uneven values (B = 0, 1/2, 5, 20) get cells as wide as their gaps and never overlap.
}  // namespace

std::map<double, std::pair<double, double>> cell_edges(std::vector<double> v, bool log) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::map<double, std::pair<double, double>> e;
  auto mid = [log](double a, double b) { return log ? std::sqrt(a * b) : (a + b) / 2; };
  auto out = [log](double a, double m) { return log ? a * a / m : 2 * a - m; };  // a reflected over m
  if (v.size() == 1) {
    const double a = v[0], h = log ? 1.25 : std::max(std::abs(a) * 0.1, 0.5);
    e[a] = log ? std::pair{a / h, a * h} : std::pair{a - h, a + h};
    return e;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    const double lo = i > 0 ? mid(v[i - 1], v[i]) : out(v[0], mid(v[0], v[1]));
    const double hi = i + 1 < v.size() ? mid(v[i], v[i + 1]) : out(v[i], mid(v[i - 1], v[i]));
    e[v[i]] = {lo, hi};
  }
  return e;
}

std::optional<study::Spec> spec_of(const fs::path& sweep) {
  std::error_code ec;
  if (!fs::exists(sweep / "spec.toml", ec)) return std::nullopt;
  const fs::path f = report::input_file_inside(sweep, "spec.toml", "sweep plot", study::max_spec_bytes);
  return study::parse_spec(study::read_spec_file(f.string()), "spec.toml");
}

PlotData read_plot_data(const fs::path& sweep, const std::string& x, const std::string& y, const std::string& z,
                        const std::optional<study::Spec>& spec, bool categorical) {
  for (const auto& [name, option] : {std::pair{x, "--x"}, {y, "--y"}, {z, "--z"}})
    for (char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw InputError(std::string(option) + " '" + report::text(name) + "': a column name (letters, digits, _)");
  // a regular file inside the folder: not a FIFO, /dev/zero or a link out of it
  const fs::path csv = report::input_file_inside(sweep, "points.csv", "sweep plot", std::numeric_limits<std::uintmax_t>::max());
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw InputError("sweep plot: cannot read points.csv in '" + report::text(sweep.string()) + "'");
  std::vector<std::string> head, row;
  read_csv_record(in, head);
  const size_t cx = column_of(head, x, "--x"), cz = column_of(head, z, "--z");
  const bool has_y = !y.empty();  // a map (x, y) or a line plot over x
  const size_t cy = has_y ? column_of(head, y, "--y") : 0;
  const size_t cerr = column_of(head, "error", "error");
  std::optional<size_t> cstatus;
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == "status") cstatus = k;
  PlotData d;
  std::vector<size_t> group_columns;  // the line plot's other axes
  bool xcat = false, ycat = false;     // listed axes of a map: one equal column/row per value
  if (spec)
    for (const auto& a : spec->axes) {
      if (a.name == x) d.xlog = a.log, xcat = categorical && a.listed;
      if (a.name == y) d.ylog = a.log, ycat = categorical && a.listed;
      if (!has_y && a.name != x) group_columns.push_back(column_of(head, a.name, "axis"));
    }
  constexpr size_t max_lines = 12;
  bool first = true;
  while (read_csv_record(in, row)) {
    if (row.size() != head.size()) continue;
    const std::string px = number_for_plot(row[cx]), py = has_y ? number_for_plot(row[cy]) : "0";
    if (px.empty() || py.empty())
      throw InputError("--x/--y: the row of point " + report::text(row[0].substr(0, 40)) + " has no number there");
    PlotRow r;
    r.x = std::stod(px);
    r.y = std::stod(py);
    const std::string pz = number_for_plot(row[cz]);
    const std::string status = cstatus ? row[*cstatus] : "numeric";
    r.kind = !row[cerr].empty() ? 3 : pz.empty() ? 2 : (status == "certified" || status == "exact") ? 0 : 1;
    if (r.kind <= 1) {
      r.z = std::stod(pz);
      d.zmin = first ? r.z : std::min(d.zmin, r.z);
      d.zmax = first ? r.z : std::max(d.zmax, r.z);
      first = false;
    }
    for (size_t c : group_columns) r.group += (r.group.empty() ? "" : ", ") + head[c] + " = " + row[c];
    if (std::find(d.groups.begin(), d.groups.end(), r.group) == d.groups.end()) {
      if (d.groups.size() == max_lines)
        throw InputError("sweep plot without --y: more than " + std::to_string(max_lines) +
                         " lines (one per value of the other axes); give --y for a map");
      d.groups.push_back(r.group);
    }
    if ((d.xlog && r.x <= 0) || (d.ylog && r.y <= 0)) throw InputError("sweep plot: a log axis holds a value <= 0");
    d.rows.push_back(std::move(r));
  }
  if (d.rows.empty()) throw InputError("sweep plot: points.csv in '" + report::text(sweep.string()) + "' has no points");
  // a listed axis (values = [0, 1/2, 5, 20]) on a map: value k of the sorted list at position k,
  // labelled with its exact value (study::exact_text of the parsed number: digits, '.', '/', '-' only)
  auto categories = [&](double PlotRow::*coord, std::string& tics) {
    std::vector<double> v;
    for (const PlotRow& r : d.rows) v.push_back(r.*coord);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    tics = "(";
    for (size_t k = 0; k < v.size(); ++k) {
      std::ostringstream o;
      o.precision(6);
      o << v[k];
      tics += (k ? ", \"" : "\"") + o.str() + "\" " + std::to_string(k);
    }
    tics += ")";
    for (PlotRow& r : d.rows) r.*coord = static_cast<double>(std::lower_bound(v.begin(), v.end(), r.*coord) - v.begin());
  };
  if (xcat) categories(&PlotRow::x, d.xtics), d.xlog = false;
  if (ycat) categories(&PlotRow::y, d.ytics), d.ylog = false;
  if (first) d.zmin = 0, d.zmax = 1;  // nothing finite: the colour bar of an empty map
  if (d.zmax == d.zmin) d.zmin -= 0.5, d.zmax += 0.5;
  // a full grid, x slower: blocks of `run` rows of equal x, each block with the first block's y values
  size_t run = 0;
  while (run < d.rows.size() && d.rows[run].x == d.rows[0].x) ++run;
  d.full_grid = d.rows.size() % run == 0;
  for (size_t i = 0; d.full_grid && i < d.rows.size(); ++i) {
    const size_t block = i - i % run;
    d.full_grid = d.rows[i].x == d.rows[block].x && d.rows[i].y == d.rows[i % run].y &&
                  (block == 0 || d.rows[block].x != d.rows[block - run].x);
  }
  return d;
}

namespace {

/// Writes the plot data into `data`: per kind the cells (x y xlo xhi ylo yhi [z]) of the map,
/// grid.dat (x y z, NaN where not a number; a blank line per x block) for level lines, and
/// line.dat (x z per line, two blank lines between lines: gnuplot's index) for the line plot.
void write_plot_files(const PlotData& d, const fs::path& data) {
  fs::create_directories(data);
  std::vector<double> xs, ys;
  for (const PlotRow& r : d.rows) xs.push_back(r.x), ys.push_back(r.y);
  const auto ex = cell_edges(xs, d.xlog), ey = cell_edges(ys, d.ylog);
  std::ofstream f[4] = {open_data_file(data / plot_files[0]), open_data_file(data / plot_files[1]),
                        open_data_file(data / plot_files[2]), open_data_file(data / plot_files[3])};
  std::ofstream grid = open_data_file(data / "grid.dat"), line = open_data_file(data / "line.dat");
  for (auto* o : {&f[0], &f[1], &f[2], &f[3], &grid, &line}) o->precision(17);
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const PlotRow& r = d.rows[i];
    // 2% of overlap between neighbours (in the drawn scale): no hairline seams between cells
    auto widen = [](std::pair<double, double> e, bool log) {
      if (log) return std::pair{e.first * std::pow(e.second / e.first, -0.01), e.second * std::pow(e.second / e.first, 0.01)};
      const double w = 0.01 * (e.second - e.first);
      return std::pair{e.first - w, e.second + w};
    };
    const auto [xlo, xhi] = widen(ex.at(r.x), d.xlog);
    const auto [ylo, yhi] = widen(ey.at(r.y), d.ylog);
    f[r.kind] << r.x << " " << r.y << " " << xlo << " " << xhi << " " << ylo << " " << yhi;
    if (r.kind <= 1) f[r.kind] << " " << r.z;
    f[r.kind] << "\n";
    if (i > 0 && r.x != d.rows[i - 1].x) grid << "\n";
    grid << r.x << " " << r.y << " " << (r.kind <= 1 ? std::to_string(r.z) : std::string("NaN")) << "\n";
  }
  // line plot: per group, its points in order of x; kinds as a third column (0..3)
  for (size_t g = 0; g < d.groups.size(); ++g) {
    std::vector<const PlotRow*> pts;
    for (const PlotRow& r : d.rows)
      if (r.group == d.groups[g]) pts.push_back(&r);
    std::stable_sort(pts.begin(), pts.end(), [](const PlotRow* a, const PlotRow* b) { return a->x < b->x; });
    if (g > 0) line << "\n\n";
    for (const PlotRow* r : pts) line << r->x << " " << (r->kind <= 1 ? r->z : 0.0) << " " << r->kind << "\n";
  }
  for (size_t k = 0; k < 4; ++k) close_data_file(f[k], data / plot_files[k]);
  close_data_file(grid, data / "grid.dat");
  close_data_file(line, data / "line.dat");
}

/// A label: NAME [unit] (the unit from the spec's [units]) unless the user gave one.
std::string label(const std::string& given, const std::string& name, const std::optional<study::Spec>& spec) {
  if (!given.empty()) return given;
  const std::string u = spec ? study::unit_of(*spec, name) : "";
  return u.empty() ? name : name + " [" + u + "]";
}

/// --levels: "N" (N automatic levels) or "a,b,c" (those values), as gnuplot's cntrparam text
/// built from the parsed numbers (only digits, '.', 'e', '-' and ',' reach gnuplot's eval).
std::string levels_text(const std::string& text) {
  if (text.empty()) return "";
  if (text.find(',') == std::string::npos && std::all_of(text.begin(), text.end(), ::isdigit)) {
    const long n = std::stol(text.substr(0, 6));
    if (n < 1 || n > 100) throw InputError("--levels: a count in [1, 100] or a list of values (got '" + report::text(text) + "')");
    return "auto " + std::to_string(n);
  }
  std::string out = "discrete ";
  std::stringstream ss(text);
  std::string w;
  int count = 0;
  while (std::getline(ss, w, ',')) {
    const auto q = try_parse_rational(w);
    if (!q || ++count > 100)
      throw InputError("--levels: expected a count or comma-separated numbers, e.g. 1,2,5 (got '" + report::text(text) + "')");
    std::ostringstream o;
    o.precision(17);
    o << to_real<double>(*q);
    out += (count > 1 ? "," : "") + o.str();
  }
  return out;
}

/// --size W,H in centimetres: the figure's size on paper (pdf, tex), and the same layout in
/// pixels for png (1600 px per 6 in) and svg (1200 px per 6 in).
std::pair<double, double> size_cm(const std::string& text) {
  const auto comma = text.find(',');
  std::optional<rational> w, h;
  if (comma != std::string::npos) w = try_parse_rational(text.substr(0, comma)), h = try_parse_rational(text.substr(comma + 1));
  if (!w || !h || *w < 2 || *h < 2 || *w > 100 || *h > 100)
    throw InputError("--size: W,H in centimetres, each in [2, 100], e.g. 8.5,6 (got '" + report::text(text) + "')");
  return {to_real<double>(*w), to_real<double>(*h)};
}

/// What plots/sweep_*.gp show: the labels (with units), the colour range, which parts have points
/// (gnuplot refuses an empty data file), log axes, levels, size and the line titles.
GnuplotVars plot_vars(const PlotData& d, const fs::path& data, const std::string& xl, const std::string& yl,
                      const std::string& zl) {
  GnuplotVars v{{{"xlabel", xl}, {"ylabel", yl}, {"zlabel", zl}}, {}};
  const char* parts[] = {"has_proven", "has_numeric", "has_infinite", "has_failed"};
  for (size_t k = 0; k < 4; ++k) {
    std::error_code ec;
    v.numbers.emplace_back(parts[k], fs::file_size(data / plot_files[k], ec) > 0 && !ec ? 1 : 0);
  }
  v.numbers.insert(v.numbers.end(), {{"zmin", d.zmin}, {"zmax", d.zmax}, {"xlog", d.xlog}, {"ylog", d.ylog},
                                     {"ngroups", double(d.groups.size())}});
  // the plotted window: the cells' outer edges
  std::vector<double> xs, ys;
  for (const PlotRow& r : d.rows) xs.push_back(r.x), ys.push_back(r.y);
  const auto ex = cell_edges(xs, d.xlog), ey = cell_edges(ys, d.ylog);
  v.numbers.insert(v.numbers.end(), {{"xmin", ex.begin()->second.first}, {"xmax", ex.rbegin()->second.second},
                                     {"ymin", ey.begin()->second.first}, {"ymax", ey.rbegin()->second.second},
                                     {"xfirst", ex.begin()->first}, {"xlast", ex.rbegin()->first},
                                     {"yfirst", ey.begin()->first}, {"ylast", ey.rbegin()->first}});
  for (size_t g = 0; g < d.groups.size(); ++g) v.text.push_back({"group" + std::to_string(g + 1), d.groups[g]});
  if (!d.xtics.empty()) v.text.push_back({"xtics", d.xtics});
  if (!d.ytics.empty()) v.text.push_back({"ytics", d.ytics});
  return v;
}

// The (K, B) passivity region of the delayed backward-difference wall (paper 001, Example 4, n = 1)
// as a sweep: docs/sweep_kb_region.toml. `hapstab reproduce` draws its map and level lines.
const char* const kb_region_spec = R"spec(command = "bound"
[args]
H = "K + B*(z-1)/(T*z)"
T = "1/1000"
delay = 1
digits = 30
[axes]
B = { from = "0", to = "2", points = 41 }
K = { from = "0", to = "3000", points = 41 }
)spec";

// A figure's own sweep: DATADIR/NAME.toml holds `spec`, run (resumable) into DATADIR/NAME.
fs::path run_figure_sweep(const fs::path& datadir, const std::string& name, const char* spec_text, const std::string& what) {
  const fs::path spec = datadir / (name + ".toml"), out = datadir / name;
  std::ofstream f = open_data_file(spec);
  f << spec_text;
  close_data_file(f, spec);
  report::run_checked({self_exe().string(), "sweep", spec.string(), "--out", out.string(), "--resume", "--quiet"},
                      "hapstab sweep (" + what + ")");
  return out;
}

void kb_region_data(const fs::path& datadir) {
  const fs::path out = run_figure_sweep(datadir, "sweep_kb_region", kb_region_spec, "the (K, B) region");
  write_plot_files(read_plot_data(out, "B", "K", "bound", std::nullopt), datadir);
}

// with the units of this sweep's columns, for the axes
GnuplotVars kb_region_vars(const fs::path& datadir) {
  const PlotData d = read_plot_data(datadir / "sweep_kb_region", "B", "K", "bound", std::nullopt);
  GnuplotVars v = plot_vars(d, datadir, "B [N s/m]", "K [N/m]", "b* [N s/m]");
  v.text.push_back({"levels", levels_text("1,2,3,4")});
  return v;
}

const RegisterFigure map_figure({"sweep_map", "toolbox",
                                 "hapstab sweep: certified b* of the delayed backward-difference wall K + B(z-1)/(Tz) "
                                 "(n = 1, T = 1 ms, 30 digits) on a 41 x 41 exact (B, K) grid",
                                 kb_region_data, kb_region_vars});
const RegisterFigure contour_figure({"sweep_contour", "toolbox",
                                     "hapstab sweep: level lines of b*(B, K) of the same wall; the b* = 1 line is the "
                                     "passivity boundary of passivity_kb_region (n = 1) for b = 1 N s/m",
                                     kb_region_data, kb_region_vars});

// The same wall against K, one line per B: the 1-D plot (`sweep plot DIR --x K --z bound`).
const char* const line_spec = R"spec(command = "bound"
[args]
H = "K + B*(z-1)/(T*z)"
T = "1/1000"
delay = 1
digits = 30
[axes]
B = { values = ["0", "1/2", "1", "2"] }
K = { from = "0", to = "3000", points = 31 }
)spec";

void line_data(const fs::path& datadir) {
  const fs::path out = run_figure_sweep(datadir, "sweep_line", line_spec, "b* against K");
  write_plot_files(read_plot_data(out, "K", "", "bound", spec_of(out)), datadir);
}

GnuplotVars line_vars(const fs::path& datadir) {
  const fs::path out = datadir / "sweep_line";
  const PlotData d = read_plot_data(out, "K", "", "bound", spec_of(out));
  return plot_vars(d, datadir, "K [N/m]", "b* [N s/m]", "b* [N s/m]");
}

const RegisterFigure line_figure({"sweep_line", "toolbox",
                                  "hapstab sweep: certified b* of the same wall against K, one line per B = 0, 1/2, 1, "
                                  "2 N s/m (sweep plot's 1-D form, without --y)",
                                  line_data, line_vars});

}  // namespace

int plot(const PlotOptions& o) {
  const std::vector<std::string> formats = figure_formats(o.format);
  const fs::path dir(o.dir);
  if (o.y.empty() && o.contour) throw InputError("--contour needs --y (level lines of z over x and y)");
  const std::string script = o.y.empty() ? "sweep_line" : o.contour ? "sweep_contour" : "sweep_map";
  const std::string name = o.name.empty() ? script : report::file_component(o.name, "--name");
  const std::optional<study::Spec> spec = spec_of(dir);
  const PlotData d = read_plot_data(dir, o.x, o.y, o.z, spec, script == "sweep_map");
  const std::string levels = levels_text(o.levels);
  if (!levels.empty() && !o.y.empty() && !d.full_grid)
    throw InputError("--levels: level lines need a full grid with --x the slower axis (the spec's axes in the order y, x "
                     "are not)");
  if (o.contour && !d.full_grid)
    throw InputError("--contour: level lines need a full grid with --x the slower axis (an axis listed before --y's in the spec)");
  const report::PrivateFolder work("hapstab-plot");  // the data and the figure, until it is copied into DIR
  const fs::path data = work.path() / "data", drawn = work.path() / "figures";
  write_plot_files(d, data);
  GnuplotVars vars = plot_vars(d, data, label(o.xlabel, o.x, spec), o.y.empty() ? label(o.zlabel, o.z, spec) : label(o.ylabel, o.y, spec),
                               label(o.zlabel, o.z, spec));
  vars.text.push_back({"title", o.title});
  if (!levels.empty()) vars.text.push_back({"levels", levels});
  if (!o.size.empty()) {
    const auto [w, h] = size_cm(o.size);
    vars.numbers.insert(vars.numbers.end(), {{"size_w_cm", w}, {"size_h_cm", h}});
  }
  for (const std::string& f : formats) {
    run_gnuplot(script, data, drawn, f, name, vars);
    const bool tex = f == "tex";  // the cairolatex pair NAME.tex + NAME.pdf, in figures/tex/
    for (const std::string& file : tex ? std::vector<std::string>{name + ".tex", name + ".pdf"} : std::vector<std::string>{name + "." + f})
      std::cout << report::install_file(tex ? drawn / "tex" / file : drawn / file, tex ? dir / "figures" / "tex" : dir / "figures",
                                        file, "sweep plot").string()
                << " (" << d.rows.size() << " points)\n";
  }
  return exit_ok;
}

}  // namespace hapstab::cli::sweep
