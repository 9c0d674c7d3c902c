#include "cli/figure.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "cli/process.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;

std::vector<Figure>& figures() {
  static std::vector<Figure> f;
  return f;
}

fs::path plots_dir() {
  if (const char* env = std::getenv("HAPSTAB_DATA_DIR")) return fs::path(env) / "plots";
  std::error_code ec;  // an installed hapstab: PREFIX/bin/hapstab next to PREFIX/share/hapstab
  const fs::path installed = fs::read_symlink("/proc/self/exe", ec).parent_path().parent_path() / "share" / "hapstab";
  if (!ec && fs::exists(installed / "plots" / "common.gp")) return installed / "plots";
#ifdef HAPSTAB_SOURCE_DIR
  if (fs::exists(fs::path(HAPSTAB_SOURCE_DIR) / "plots" / "common.gp")) return fs::path(HAPSTAB_SOURCE_DIR) / "plots";
#endif
#ifdef HAPSTAB_INSTALL_DATADIR
  if (fs::exists(fs::path(HAPSTAB_INSTALL_DATADIR) / "plots" / "common.gp"))
    return fs::path(HAPSTAB_INSTALL_DATADIR) / "plots";
#endif
  throw InputError("cannot find the gnuplot scripts (plots/common.gp); set HAPSTAB_DATA_DIR to the hapstab tree");
}

fs::path examples_dir() { return plots_dir().parent_path() / "examples"; }

void run_gnuplot(const std::string& script, const fs::path& datadir, const fs::path& figdir, const std::string& format) {
  const fs::path dir = plots_dir();
  const fs::path outdir = format == "tex" ? figdir / "tex" : figdir;  // cairolatex also writes NAME.pdf
  const fs::path gp = dir / (script + ".gp");
  if (!fs::exists(gp)) throw InputError("no gnuplot script " + gp.string());
  // gnuplot strings are single-quoted too: the paths handed to it must not hold a quote
  for (const auto& p : {datadir, outdir, dir})
    if (p.string().find('\'') != std::string::npos) throw InputError("path must not contain a quote: " + p.string());
  fs::create_directories(outdir);
  std::ostringstream vars;
  vars << "plotdir='" << dir.string() << "'; datadir='" << fs::absolute(datadir).string() << "'; outdir='"
       << fs::absolute(outdir).string() << "'; fmt='" << format << "'";
  run_logged("gnuplot -e " + shell_quote(vars.str()) + " " + shell_quote(gp.string()),
             fs::absolute(outdir) / (script + "." + format + ".log"), "gnuplot on " + gp.string() + " (" + format + ")");
}

void write_bench_chart_data(const std::string& bench, const fs::path& datadir) {
  const fs::path script = plots_dir().parent_path() / "bench" / ("chart-" + bench);
  const fs::path build = self_exe().parent_path();
  if (!fs::exists(script)) throw FigureSkipped("bench/chart-" + bench + " is not in this installation (source tree only)");
  if (!fs::exists(build / "bench" / ("bench_" + bench)))
    throw FigureSkipped("benchmark program bench_" + bench + " not built next to this hapstab (configure with "
                        "-DHAPSTAB_BENCH=ON and build the target bench_" + bench + ")");
  run_logged(shell_quote(script.string()) + " " + shell_quote(fs::absolute(datadir).string()) + " " +
                 shell_quote(build.string()),
             fs::absolute(datadir) / ("chart-" + bench + ".log"), "bench/chart-" + bench);
}

void draw_figure(const Figure& fig, const fs::path& datadir, const fs::path& outdir,
                 const std::vector<std::string>& formats) {
  fs::create_directories(datadir);
  fig.write_data(datadir);
  for (const auto& f : formats) run_gnuplot(fig.name, datadir, outdir, f);
}

}  // namespace hapstab::cli
