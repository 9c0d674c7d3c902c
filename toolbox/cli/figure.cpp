#include "cli/figure.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {

namespace fs = std::filesystem;

std::vector<Figure>& figures() {
  static std::vector<Figure> f;
  return f;
}

fs::path plots_dir() {
  if (const char* env = std::getenv("HAPSTAB_DATA_DIR")) return fs::path(env) / "plots";
#ifdef HAPSTAB_SOURCE_DIR
  if (fs::exists(fs::path(HAPSTAB_SOURCE_DIR) / "plots" / "common.gp")) return fs::path(HAPSTAB_SOURCE_DIR) / "plots";
#endif
#ifdef HAPSTAB_INSTALL_DATADIR
  if (fs::exists(fs::path(HAPSTAB_INSTALL_DATADIR) / "plots" / "common.gp"))
    return fs::path(HAPSTAB_INSTALL_DATADIR) / "plots";
#endif
  throw InputError("cannot find the gnuplot scripts (plots/common.gp); set HAPSTAB_DATA_DIR to the hapstab tree");
}

namespace {
// Single-quoted for the shell; gnuplot strings are single-quoted too, so paths must not hold '.
std::string shell_quote(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return o + "'";
}
}  // namespace

void run_gnuplot(const std::string& script, const fs::path& datadir, const fs::path& outdir, const std::string& format) {
  const fs::path dir = plots_dir();
  const fs::path gp = dir / (script + ".gp");
  if (!fs::exists(gp)) throw InputError("no gnuplot script " + gp.string());
  for (const auto& p : {datadir, outdir, dir})
    if (p.string().find('\'') != std::string::npos) throw InputError("path must not contain a quote: " + p.string());
  fs::create_directories(outdir);
  std::ostringstream vars;
  vars << "plotdir='" << dir.string() << "'; datadir='" << fs::absolute(datadir).string() << "'; outdir='"
       << fs::absolute(outdir).string() << "'; fmt='" << format << "'";
  const fs::path log = fs::absolute(outdir) / (script + "." + format + ".log");
  std::string cmd = "gnuplot -e " + shell_quote(vars.str()) + " " + shell_quote(gp.string()) + " > " +
                    shell_quote(log.string()) + " 2>&1";
  int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    throw NumericalError("gnuplot failed on " + gp.string() + " (" + format + "):\n" + ss.str());
  }
  fs::remove(log);
}

void draw_figure(const Figure& fig, const fs::path& datadir, const fs::path& outdir,
                 const std::vector<std::string>& formats) {
  fs::create_directories(datadir);
  fig.write_data(datadir);
  for (const auto& f : formats) run_gnuplot(fig.name, datadir, outdir, f);
}

}  // namespace hapstab::cli
