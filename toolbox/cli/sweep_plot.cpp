// cli/sweep_plot.cpp -- `hapstab sweep plot DIR --x K --y B --z bound`: a heat map (or contour
// lines) of one column of DIR/points.csv over two others, drawn by plots/sweep_map.gp (or
// plots/sweep_contour.gp) into DIR/figures/. Points are told apart by the row's `status`
// column: certified or exact (filled squares), numeric (open squares, not proven), infinite
// values (crosses) and failed points (red x). The data files are written to DIR/plot-data/.
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

}  // namespace

int plot(const PlotOptions& o) {
  for (const auto& [name, option] : {std::pair{o.x, "--x"}, {o.y, "--y"}, {o.z, "--z"}})
    for (char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw InputError(std::string(option) + " '" + name + "': a column name (letters, digits, _)");
  if (o.format != "png" && o.format != "pdf" && o.format != "svg")
    throw InputError("--format must be png, pdf or svg (got " + o.format + ")");
  const fs::path dir(o.dir);
  std::ifstream in(dir / "points.csv", std::ios::binary);
  if (!in) throw InputError("sweep plot: no points.csv in '" + o.dir + "'");
  std::vector<std::string> head, row;
  read_csv_record(in, head);
  const size_t cx = column_of(head, o.x, "--x"), cy = column_of(head, o.y, "--y"), cz = column_of(head, o.z, "--z");
  const size_t cerr = column_of(head, "error", "error");
  std::optional<size_t> cstatus;
  for (size_t k = 0; k < head.size(); ++k)
    if (head[k] == "status") cstatus = k;
  const fs::path data = dir / "plot-data";
  fs::create_directories(data);
  std::ofstream proven(data / "proven.dat"), numeric(data / "numeric.dat"), infinite(data / "infinite.dat"),
      failed(data / "failed.dat"), grid(data / "grid.dat");
  size_t rows = 0;
  std::array<size_t, 4> counts{};  // proven, numeric, infinite, failed
  std::string last_x;
  while (read_csv_record(in, row)) {
    if (row.size() != head.size()) continue;
    const std::string x = number_for_plot(row[cx]), y = number_for_plot(row[cy]);
    if (x.empty() || y.empty()) throw InputError("--x/--y: the row of point " + row[0] + " has no number there");
    ++rows;
    const std::string z = number_for_plot(row[cz]);
    const std::string status = cstatus ? row[*cstatus] : "numeric";
    if (!last_x.empty() && x != last_x) grid << "\n";  // gnuplot's grid format: a blank line per x block
    last_x = x;
    grid << x << " " << y << " " << (z.empty() || !row[cerr].empty() ? "NaN" : z) << "\n";
    const bool is_proven = status == "certified" || status == "exact";
    const int kind = !row[cerr].empty() ? 3 : z.empty() ? 2 : is_proven ? 0 : 1;
    ++counts[static_cast<size_t>(kind)];
    if (kind == 3) failed << x << " " << y << "\n";
    else if (kind == 2) infinite << x << " " << y << "\n";
    else (kind == 0 ? proven : numeric) << x << " " << y << " " << z << "\n";
  }
  // The labels, and the plot's parts that have points (gnuplot refuses an empty data file).
  std::ofstream labels(data / "labels.gp");
  labels << "xname = '" << o.x << "'\nyname = '" << o.y << "'\nzname = '" << o.z << "'\n";
  const char* parts[] = {
      "datadir.'/proven.dat' using 1:2:3 with points pt 5 ps 1.2 lc palette title 'certified / exact'",
      "datadir.'/numeric.dat' using 1:2:3 with points pt 4 ps 1.2 lc palette title 'numeric (not proven)'",
      "datadir.'/infinite.dat' using 1:2 with points pt 2 ps 1.2 lc rgb 'black' title zname.' = inf'",
      "datadir.'/failed.dat' using 1:2 with points pt 1 ps 1.5 lc rgb 'red' title 'failed'"};
  std::string plot_line;
  for (size_t k = 0; k < 4; ++k)
    if (counts[k]) plot_line += (plot_line.empty() ? "plot " : ", ") + std::string(parts[k]);
  if (rows == 0) throw InputError("sweep plot: points.csv in '" + o.dir + "' has no points");
  labels << "map_plot = \"" << plot_line << "\"\n";
  for (auto* f : {&proven, &numeric, &infinite, &failed, &grid, &labels}) f->close();
  run_gnuplot(o.contour ? "sweep_contour" : "sweep_map", data, dir / "figures", o.format);
  std::cout << (dir / "figures" / ((o.contour ? "sweep_contour." : "sweep_map.") + o.format)).string() << " (" << rows
            << " points)\n";
  return exit_ok;
}

}  // namespace hapstab::cli::sweep
