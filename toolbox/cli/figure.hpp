// cli/figure.hpp -- the registry of figures: each one writes its data files into a folder and
// names the gnuplot script in plots/ that draws them (plots/README.md gives the convention).
// `hapstab figure NAME --out DIR` draws one; `hapstab reproduce` draws them all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hapstab::cli {

struct Figure {
  const char* name;     ///< plots/<name>.gp draws it; files <name>.png/.pdf/.svg/.tex
  const char* paper;    ///< "000", "001", "002", or "toolbox" for the toolbox's own charts
  const char* caption;  ///< one sentence: what it shows
  void (*write_data)(const std::filesystem::path& datadir);  ///< writes the .dat files the script reads
};

std::vector<Figure>& figures();

struct RegisterFigure {
  explicit RegisterFigure(Figure f) { figures().push_back(f); }
};

/// Where plots/ lives: $HAPSTAB_DATA_DIR, else the source tree, else the install's share/hapstab.
std::filesystem::path plots_dir();

/// Writes the data of `fig` into datadir and draws it with gnuplot in each format
/// (png, pdf, svg, tex) into outdir. Throws NumericalError when gnuplot fails.
void draw_figure(const Figure& fig, const std::filesystem::path& datadir, const std::filesystem::path& outdir,
                 const std::vector<std::string>& formats);

/// Runs gnuplot on plots/<script>.gp with datadir/outdir/fmt set (for scripts whose data
/// another step wrote, e.g. bench charts).
void run_gnuplot(const std::string& script, const std::filesystem::path& datadir, const std::filesystem::path& outdir,
                 const std::string& format);

}  // namespace hapstab::cli
