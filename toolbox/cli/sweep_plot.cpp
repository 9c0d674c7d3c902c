// cli/sweep_plot.cpp -- `hapstab sweep plot DIR --x K --y B --z bound`: a heat map (or contour
// lines) of one column of DIR/points.csv over two others, drawn by plots/sweep_map.gp (or
// plots/sweep_contour.gp) into DIR/figures/. Points are told apart by the row's `status`
// column: certified or exact (solid cells), numeric (hatched cells, not proven), infinite
// values (grey cells) and failed points (crossed cells). The data files are written to DIR/plot-data/.
// The figures sweep_map and sweep_contour of `hapstab reproduce` are the (K, B) region as a sweep.
#include <array>
#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/sweep_cli.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/process.hpp"

namespace hapstab::cli::sweep {

namespace fs = std::filesystem;

namespace {

/// The fields of one CSV record (RFC 4180 quoting; a record may span lines inside quotes).
bool read_csv_record(std::istream& in, std::vector<std::string>& fields) {
  fields.assign(1, "");
  bool quoted = false, any = false;
  for (int c; (c = in.get()) != EOF;) {
    any = true;
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

/// Writes the plot data of column z over (x, y) from sweep/points.csv into `data`: proven.dat,
/// numeric.dat, infinite.dat, failed.dat, grid.dat and labels.gp. Returns the number of points.
size_t write_plot_data(const fs::path& sweep, const std::string& x, const std::string& y, const std::string& z,
                       const fs::path& data) {
  for (const auto& [name, option] : {std::pair{x, "--x"}, {y, "--y"}, {z, "--z"}})
    for (char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw InputError(std::string(option) + " '" + name + "': a column name (letters, digits, _)");
  std::ifstream in(sweep / "points.csv", std::ios::binary);
  if (!in) throw InputError("sweep plot: no points.csv in '" + sweep.string() + "'");
  std::vector<std::string> head, row;
  read_csv_record(in, head);
  const size_t cx = column_of(head, x, "--x"), cy = column_of(head, y, "--y"), cz = column_of(head, z, "--z");
  const size_t cerr = column_of(head, "error", "error");
  std::optional<size_t> cstatus;
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == "status") cstatus = k;
  fs::create_directories(data);
  std::ofstream proven(data / "proven.dat"), numeric(data / "numeric.dat"), infinite(data / "infinite.dat"),
      failed(data / "failed.dat"), grid(data / "grid.dat");
  size_t rows = 0;
  std::array<size_t, 4> counts{};  // proven, numeric, infinite, failed
  std::string last_x;
  while (read_csv_record(in, row)) {
    if (row.size() != head.size()) continue;
    const std::string px = number_for_plot(row[cx]), py = number_for_plot(row[cy]);
    if (px.empty() || py.empty()) throw InputError("--x/--y: the row of point " + row[0] + " has no number there");
    ++rows;
    const std::string pz = number_for_plot(row[cz]);
    const std::string status = cstatus ? row[*cstatus] : "numeric";
    if (!last_x.empty() && px != last_x) grid << "\n";  // gnuplot's grid format: a blank line per x block
    last_x = px;
    grid << px << " " << py << " " << (pz.empty() || !row[cerr].empty() ? "NaN" : pz) << "\n";
    const bool is_proven = status == "certified" || status == "exact";
    const int kind = !row[cerr].empty() ? 3 : pz.empty() ? 2 : is_proven ? 0 : 1;
    ++counts[static_cast<size_t>(kind)];
    if (kind == 3) failed << px << " " << py << "\n";
    else if (kind == 2) infinite << px << " " << py << "\n";
    else (kind == 0 ? proven : numeric) << px << " " << py << " " << pz << "\n";
  }
  if (rows == 0) throw InputError("sweep plot: points.csv in '" + sweep.string() + "' has no points");
  // The labels, and the plot's parts that have points (gnuplot refuses an empty data file).
  std::ofstream labels(data / "labels.gp");
  labels << "xname = '" << x << "'\nyname = '" << y << "'\nzname = '" << z << "'\n";
  const char* parts[] = {  // cells of dx by dy centred on the points (plots/sweep_map.gp)
      "datadir.'/proven.dat' using 1:2:(cx):(cy):3 with boxxyerror fs solid 1.0 noborder fc palette "
      "title 'certified / exact'",
      "datadir.'/numeric.dat' using 1:2:(cx):(cy):3 with boxxyerror fs pattern 4 border lc palette fc palette "
      "title 'numeric (not proven)'",
      "datadir.'/infinite.dat' using 1:2:(cx):(cy) with boxxyerror fs solid 1.0 noborder fc rgb '#999999' "
      "title zname.' = inf'",
      "datadir.'/failed.dat' using 1:2:(cx):(cy) with boxxyerror fs pattern 5 border lc rgb '#D55E00' "
      "fc rgb '#D55E00' title 'failed'"};
  std::string plot_line;
  for (size_t k = 0; k < 4; ++k)
    if (counts[k]) plot_line += (plot_line.empty() ? "plot " : ", ") + std::string(parts[k]);
  labels << "map_plot = \"" << plot_line << "\"\n";
  return rows;
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
  std::ofstream(spec) << kb_region_spec;
  report::run_checked({self_exe().string(), "sweep", spec.string(), "--out", out.string(), "--resume", "--quiet"},
                      "hapstab sweep (the (K, B) region)");
  write_plot_data(out, "B", "K", "bound", datadir);
  // the units of this sweep's columns, for the axes (plots/sweep_map.gp reads them when present)
  std::ofstream(datadir / "labels.gp", std::ios::app) << "xunit = 'N s/m'\nyunit = 'N/m'\nzunit = 'N s/m'\n";
}

const RegisterFigure map_figure({"sweep_map", "toolbox",
                                 "hapstab sweep: certified b* of the delayed backward-difference wall K + B(z-1)/(Tz) "
                                 "(n = 1, T = 1 ms, 30 digits) on a 41 x 41 exact (B, K) grid",
                                 kb_region_data});
const RegisterFigure contour_figure({"sweep_contour", "toolbox",
                                     "hapstab sweep: level lines of b*(B, K) of the same wall; the b* = 1 line is the "
                                     "passivity boundary of passivity_kb_region (n = 1) for b = 1 N s/m",
                                     kb_region_data});

}  // namespace

int plot(const PlotOptions& o) {
  if (o.format != "png" && o.format != "pdf" && o.format != "svg")
    throw InputError("--format must be png, pdf or svg (got " + o.format + ")");
  const fs::path dir(o.dir);
  const size_t rows = write_plot_data(dir, o.x, o.y, o.z, dir / "plot-data");
  run_gnuplot(o.contour ? "sweep_contour" : "sweep_map", dir / "plot-data", dir / "figures", o.format);
  std::cout << (dir / "figures" / ((o.contour ? "sweep_contour." : "sweep_map.") + o.format)).string() << " (" << rows
            << " points)\n";
  return exit_ok;
}

}  // namespace hapstab::cli::sweep
