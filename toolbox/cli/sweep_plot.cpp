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
#include <array>
#include <cctype>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/sweep_cli.hpp"
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

/// Writes the plot data of column z over (x, y) from sweep/points.csv into `data`: proven.dat,
/// numeric.dat, infinite.dat, failed.dat and grid.dat. Returns the number of points.
size_t write_plot_data(const fs::path& sweep, const std::string& x, const std::string& y, const std::string& z,
                       const fs::path& data) {
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
  const size_t cx = column_of(head, x, "--x"), cy = column_of(head, y, "--y"), cz = column_of(head, z, "--z");
  const size_t cerr = column_of(head, "error", "error");
  std::optional<size_t> cstatus;
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == "status") cstatus = k;
  fs::create_directories(data);
  std::ofstream proven = open_data_file(data / plot_files[0]), numeric = open_data_file(data / plot_files[1]),
                infinite = open_data_file(data / plot_files[2]), failed = open_data_file(data / plot_files[3]),
                grid = open_data_file(data / "grid.dat");
  size_t rows = 0;
  std::string last_x;
  while (read_csv_record(in, row)) {
    if (row.size() != head.size()) continue;
    const std::string px = number_for_plot(row[cx]), py = number_for_plot(row[cy]);
    if (px.empty() || py.empty())
      throw InputError("--x/--y: the row of point " + report::text(row[0].substr(0, 40)) + " has no number there");
    ++rows;
    const std::string pz = number_for_plot(row[cz]);
    const std::string status = cstatus ? row[*cstatus] : "numeric";
    if (!last_x.empty() && px != last_x) grid << "\n";  // gnuplot's grid format: a blank line per x block
    last_x = px;
    grid << px << " " << py << " " << (pz.empty() || !row[cerr].empty() ? "NaN" : pz) << "\n";
    const bool is_proven = status == "certified" || status == "exact";
    const int kind = !row[cerr].empty() ? 3 : pz.empty() ? 2 : is_proven ? 0 : 1;
    if (kind == 3) failed << px << " " << py << "\n";
    else if (kind == 2) infinite << px << " " << py << "\n";
    else (kind == 0 ? proven : numeric) << px << " " << py << " " << pz << "\n";
  }
  if (rows == 0) throw InputError("sweep plot: points.csv in '" + report::text(sweep.string()) + "' has no points");
  close_data_file(proven, data / plot_files[0]);
  close_data_file(numeric, data / plot_files[1]);
  close_data_file(infinite, data / plot_files[2]);
  close_data_file(failed, data / plot_files[3]);
  close_data_file(grid, data / "grid.dat");
  return rows;
}

/// What plots/sweep_*.gp show: the column names, and which parts have points (gnuplot refuses an
/// empty data file), from the files write_plot_data wrote into `data`.
GnuplotVars plot_vars(const fs::path& data, const std::string& x, const std::string& y, const std::string& z) {
  GnuplotVars v{{{"xname", x}, {"yname", y}, {"zname", z}}, {}};
  const char* parts[] = {"has_proven", "has_numeric", "has_infinite", "has_failed"};
  for (size_t k = 0; k < 4; ++k) {
    std::error_code ec;
    v.numbers.emplace_back(parts[k], fs::file_size(data / plot_files[k], ec) > 0 && !ec ? 1 : 0);
  }
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

void kb_region_data(const fs::path& datadir) {
  const fs::path spec = datadir / "sweep_kb_region.toml", out = datadir / "sweep_kb_region";
  std::ofstream f = open_data_file(spec);
  f << kb_region_spec;
  close_data_file(f, spec);
  report::run_checked({self_exe().string(), "sweep", spec.string(), "--out", out.string(), "--resume", "--quiet"},
                      "hapstab sweep (the (K, B) region)");
  write_plot_data(out, "B", "K", "bound", datadir);
}

// with the units of this sweep's columns, for the axes (plots/sweep_*.gp use them when set)
GnuplotVars kb_region_vars(const fs::path& datadir) {
  GnuplotVars v = plot_vars(datadir, "B", "K", "bound");
  v.text.insert(v.text.end(), {{"xunit", "N s/m"}, {"yunit", "N/m"}, {"zunit", "N s/m"}});
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

}  // namespace

int plot(const PlotOptions& o) {
  if (o.format != "png" && o.format != "pdf" && o.format != "svg")
    throw InputError("--format must be png, pdf or svg (got " + report::text(o.format) + ")");
  const fs::path dir(o.dir);
  const std::string script = o.contour ? "sweep_contour" : "sweep_map", figure = script + "." + o.format;
  const report::PrivateFolder work("hapstab-plot");  // the data and the figure, until it is copied into DIR
  const fs::path data = work.path() / "data", drawn = work.path() / "figures";
  const size_t rows = write_plot_data(dir, o.x, o.y, o.z, data);
  run_gnuplot(script, data, drawn, o.format, "", plot_vars(data, o.x, o.y, o.z));
  const fs::path out = report::install_file(drawn / figure, dir / "figures", figure, "sweep plot");
  std::cout << out.string() << " (" << rows << " points)\n";
  return exit_ok;
}

}  // namespace hapstab::cli::sweep
