// cli/figure.hpp -- the registry of figures: each one writes its data files into a folder and
// names the gnuplot script in plots/ that draws them (plots/README.md gives the convention).
// `hapstab figure NAME --out DIR` draws one; `hapstab reproduce` draws them all.
// Formats png, pdf and svg go to DIR/figures/NAME.*; the LaTeX-ready cairolatex pair
// (NAME.tex + its NAME.pdf) goes to DIR/figures/tex/ so it never overwrites the PDF.
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hapstab::cli {

/// Values a figure script shows (titles, labels, window limits), handed to gnuplot as `-e`
/// assignments: each text as a gnuplot literal (report::gnuplot::quote) NAME, and LaTeX-escaped
/// as NAME_tex for the cairolatex terminal; each number as itself (0 when not finite). Strings
/// from input reach a script this way only, never through a file the script loads.
struct GnuplotVars {
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
  /// "name='...'; name_tex='...'; x=1.5" (names checked: letters, digits, _).
  std::string assignments() const;
};

struct Figure {
  const char* name;     ///< plots/<name>.gp draws it; files <name>.png/.pdf/.svg/.tex
  const char* paper;    ///< "000", "001", "002", or "toolbox" for the toolbox's own charts
  const char* caption;  ///< one sentence: what it shows
  void (*write_data)(const std::filesystem::path& datadir);  ///< writes the .dat files the script reads
  GnuplotVars (*vars)(const std::filesystem::path& datadir) = nullptr;  ///< values the script shows, if any
  const char* file = "";  ///< where it is registered (RegisterFigure fills both): the order of figures()
  int line = 0;
};

/// The figures in the order of the names of the files that register them, then of their lines: the same whatever
/// order the linker gave the static registrations (a unity build merges files into one object).
std::vector<Figure>& figures();

struct RegisterFigure {
  explicit RegisterFigure(Figure f, const char* file = __builtin_FILE(), int line = __builtin_LINE());
};

/// Thrown by a figure's write_data when the figure cannot be made on this build for a reason
/// that is not a failure (a benchmark program that was not built): reported "not reproduced".
struct FigureSkipped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Where plots/ lives: $HAPSTAB_DATA_DIR, else ../share/hapstab next to the executable (an install),
/// else the source tree, else the configured install prefix's share/hapstab.
std::filesystem::path plots_dir();
/// The example scenes (examples/*.toml), next to plots/.
std::filesystem::path examples_dir();
/// The path of the running `hapstab` executable (/proc/self/exe).
std::filesystem::path self_exe();

/// Data of a bench/ speed-accuracy chart: runs `bench/chart-NAME DATADIR BUILD_DIR`, which runs
/// the Google Benchmark program bench_NAME built next to this executable and converts its JSON.
/// Throws FigureSkipped when the program or the script is not there (an installed hapstab).
void write_bench_chart_data(const std::string& bench, const std::filesystem::path& datadir);

/// The conditions a bench chart's timings were taken in, for the figure to print: the text
/// variable `timing` ("timed DATE on N CPUs at F MHz, load average L", and a warning when L > N)
/// from the Google Benchmark context in DATADIR/<bench>_bench.json ("not recorded" without it).
GnuplotVars bench_timing_vars(const std::string& bench, const std::filesystem::path& datadir);

/// The formats of a --format list "png,pdf,svg,tex" (InputError naming --format otherwise).
std::vector<std::string> figure_formats(const std::string& text);

/// A data file of a figure, opened for writing with 12 significant digits (InputError otherwise).
std::ofstream open_data_file(const std::filesystem::path& p);
/// Closes a file written through open_data_file; NumericalError when any write to it failed.
void close_data_file(std::ofstream& o, const std::filesystem::path& p);

/// Writes the data of `fig` into datadir and draws it with gnuplot in each format
/// (png, pdf, svg, tex) into outdir. Throws NumericalError when gnuplot fails.
void draw_figure(const Figure& fig, const std::filesystem::path& datadir, const std::filesystem::path& outdir,
                 const std::vector<std::string>& formats);

/// Runs gnuplot on plots/<script>.gp with datadir/outdir/fmt set (for scripts whose data
/// another step wrote, e.g. bench charts); a non-empty `figname` is passed as the variable
/// figname (scripts drawing a figure of the user's, whose file name the user picks), and `vars`
/// as further variables.
void run_gnuplot(const std::string& script, const std::filesystem::path& datadir, const std::filesystem::path& outdir,
                 const std::string& format, const std::string& figname = "", const GnuplotVars& vars = {});

/// Polygon P (points in the Nyquist plane) clipped to the half-plane {nx (re + 1) + ny im <= 0}
/// through -1 (Sutherland-Hodgman): the forbidden regions of paper 002's criteria in a window.
std::vector<std::pair<double, double>> clip_to_halfplane(const std::vector<std::pair<double, double>>& P, double nx,
                                                         double ny);

}  // namespace hapstab::cli
