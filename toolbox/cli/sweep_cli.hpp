// cli/sweep_cli.hpp -- the parts of `hapstab sweep` (cmd_sweep.cpp registers the command):
// checking a spec against the command registry, running it, merging shards, writing Slurm
// scripts and drawing a map. The library half (spec, records, workers) is hapstab/study.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/study/spec.hpp"

namespace hapstab::cli::sweep {

/// Reads and parses a spec and checks it against the registry: the command exists, takes --set
/// and --json, and has every [args] key as an option (InputError naming the key otherwise).
study::Spec load_spec(const std::string& path);

struct RunOptions {
  std::string spec, out, shard = "0/1";
  unsigned jobs = 0;  ///< 0: the CPUs this process may use
  bool resume = false, quiet = false;
};
int run(const RunOptions& o);
/// run() on a spec given as text (o.spec unused): `name` calls the spec in messages ("spec: args.T:
/// ...") and its folder resolves the files [args] name (none: the working folder). Python's
/// hapstab.sweep with a dict or TOML text, which has no file.
int run_text(const std::string& text, const std::string& name, const RunOptions& o);

int merge(const std::vector<std::string>& dirs, const std::string& out, bool quiet);

struct SlurmOptions {
  std::string spec, out, partition, time;
  unsigned shards = 0, cpus = 1;
  bool submit = false;
};
int slurm(const SlurmOptions& o);

struct PlotOptions {
  std::string dir, x, y, z, format = "png";
  std::string xlabel, ylabel, zlabel, title, levels, size, name;  ///< empty: the defaults (labels "NAME [unit]")
  bool contour = false;
};
int plot(const PlotOptions& o);

// ---- what `sweep plot` draws (sweep_plot.cpp), public for its tests -------------------------

/// One row of points.csv as the plot sees it.
struct PlotRow {
  double x = 0, y = 0, z = 0;
  std::string group;  ///< the line plot: the other axes' values ("B = 1/2, c = 3")
  int kind = 0;       ///< 0 proven (certified/exact), 1 numeric, 2 infinite (z not a number), 3 failed
};

/// The cell of each distinct value v_0 < v_1 < ... of one axis: halfway to each neighbour
/// (geometric halfway on a log axis), the outer edges as far out as the inner ones, so uneven
/// values get cells as wide as their gaps that touch and never overlap.
std::map<double, std::pair<double, double>> cell_edges(std::vector<double> v, bool log);

/// What sweep plot read from DIR: the rows; which of x, y are log axes of the spec; whether (x, y)
/// is a full grid with x the slower axis (level lines need one); the range of the finite z values
/// (the colour bar's); a listed axis of a map (values = [...]) as positions 0, 1, ... with its
/// values as gnuplot tics; the line plot's groups.
struct PlotData {
  std::vector<PlotRow> rows;
  bool xlog = false, ylog = false, full_grid = false;
  std::string xtics, ytics;  ///< ("1/2" 1, ...) for a listed axis drawn as equal rows/columns
  double zmin = 0, zmax = 0;
  std::vector<std::string> groups;  ///< line plot: group names in order of first appearance
};

/// The spec DIR/spec.toml when the folder has one (read as a regular file inside DIR).
std::optional<study::Spec> spec_of(const std::filesystem::path& sweep);

/// Reads DIR/points.csv: column z over x and y (y empty: one line per combination of the spec's
/// other axes); `categorical`: the spec's listed axes as equal rows/columns (the map).
PlotData read_plot_data(const std::filesystem::path& sweep, const std::string& x, const std::string& y,
                        const std::string& z, const std::optional<study::Spec>& spec, bool categorical = false);

}  // namespace hapstab::cli::sweep
