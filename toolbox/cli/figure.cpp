#include "cli/figure.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <iomanip>
#include <set>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/report/paths.hpp"
#include "hapstab/report/process.hpp"

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

fs::path self_exe() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw NumericalError("cannot find the hapstab executable (/proc/self/exe): " + ec.message());
  return p;
}

std::string GnuplotVars::assignments() const {
  auto name = [](const std::string& n) {
    const bool ok = !n.empty() && !std::isdigit(static_cast<unsigned char>(n[0])) &&
                    std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (!ok) throw std::logic_error("GnuplotVars: '" + n + "' is not a gnuplot variable name");
    return n;
  };
  std::ostringstream o;
  o << std::setprecision(17);
  for (const auto& [k, v] : text)
    o << "; " << name(k) << "=" << report::gnuplot::quote(v) << "; " << k << "_tex=" << report::gnuplot::quote(report::latex::escape(v));
  for (const auto& [k, v] : numbers) o << "; " << name(k) << "=" << (std::isfinite(v) ? v : 0.0);
  return o.str();
}

void run_gnuplot(const std::string& script, const fs::path& datadir, const fs::path& figdir, const std::string& format,
                 const std::string& figname, const GnuplotVars& extra) {
  const fs::path dir = plots_dir();
  const fs::path outdir = format == "tex" ? figdir / "tex" : figdir;  // cairolatex also writes NAME.pdf
  report::file_component(script, "figure name");
  const fs::path gp = dir / (script + ".gp");
  if (!fs::exists(gp)) throw InputError("no gnuplot script " + report::text(gp.string()));
  // The folders reach gnuplot as string literals (report::gnuplot::quote); a control character
  // in a path would be replaced there and point gnuplot elsewhere, so such a path is refused.
  for (const auto& p : {datadir, outdir, dir})
    if (!report::is_clean_text(p.string()))
      throw InputError("--out: the path '" + report::text(p.string()) + "' holds control characters");
  fs::create_directories(outdir);
  using report::gnuplot::quote;
  const std::string vars = "plotdir=" + quote(dir.string()) + "; datadir=" + quote(fs::absolute(datadir).string()) +
                           "; outdir=" + quote(fs::absolute(outdir).string()) + "; fmt=" + quote(format) +
                           (figname.empty() ? "" : "; figname=" + quote(report::file_component(figname, "figure name"))) +
                           extra.assignments();
  report::ProcessOptions po;
  po.time_limit = 600;  // the slowest figure takes a few seconds; a hung gnuplot must not hang the job
  report::run_checked({"gnuplot", "-e", vars, gp.string()}, "gnuplot on " + gp.string() + " (" + format + ")", po);
}

std::vector<std::string> figure_formats(const std::string& text) {
  static const std::set<std::string> known{"png", "pdf", "svg", "tex"};
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string f;
  while (std::getline(ss, f, ','))
    if (!f.empty()) {
      if (!known.count(f)) throw InputError("--format: unknown format '" + report::text(f) + "' (expected png, pdf, svg, tex)");
      out.push_back(f);
    }
  if (out.empty()) throw InputError("--format: no format given (expected e.g. png,pdf,svg,tex)");
  return out;
}

std::ofstream open_data_file(const fs::path& p) {
  std::ofstream o(p);
  if (!o) throw InputError("cannot write " + report::text(p.string()));
  o << std::setprecision(12);
  return o;
}

void close_data_file(std::ofstream& o, const fs::path& p) {
  o.close();
  if (!o) throw NumericalError("cannot write " + report::text(p.string()) + " (disk full?)");
}

std::vector<std::pair<double, double>> clip_to_halfplane(const std::vector<std::pair<double, double>>& P, double nx,
                                                         double ny) {
  std::vector<std::pair<double, double>> out;
  auto f = [&](const std::pair<double, double>& p) { return nx * (p.first + 1) + ny * p.second; };
  for (size_t i = 0; i < P.size(); ++i) {
    auto a = P[i], b = P[(i + 1) % P.size()];
    double fa = f(a), fb = f(b);
    if (fa <= 0) out.push_back(a);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      double t = fa / (fa - fb);
      out.push_back({a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)});
    }
  }
  return out;
}

void write_bench_chart_data(const std::string& bench, const fs::path& datadir) {
  const fs::path script = plots_dir().parent_path() / "bench" / ("chart-" + bench);
  const fs::path build = self_exe().parent_path();
  if (!fs::exists(script)) throw FigureSkipped("bench/chart-" + bench + " is not in this installation (source tree only)");
  if (!fs::exists(build / "bench" / ("bench_" + bench)))
    throw FigureSkipped("benchmark program bench_" + bench + " not built next to this hapstab (configure with "
                        "-DHAPSTAB_BENCH=ON and build the target bench_" + bench + ")");
  report::run_checked({script.string(), fs::absolute(datadir).string(), build.string()}, "bench/chart-" + bench);
}

namespace {
/// Google Benchmark writes a non-finite counter as a bare Infinity, -Infinity or NaN, which JSON
/// (and nlohmann's reader) does not have: each such token outside a string becomes null.
std::string json_without_nonfinite(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    bool replaced = false;
    for (const char* token : {"-Infinity", "Infinity", "NaN"})
      if (!replaced && text.compare(i, std::strlen(token), token) == 0) {
        out += "null";
        i += std::strlen(token) - 1;
        replaced = true;
      }
    if (!replaced) out += c;
  }
  return out;
}
}  // namespace

GnuplotVars bench_timing_vars(const std::string& bench, const fs::path& datadir) {
  std::string note = "timing conditions not recorded";
  try {
    std::ifstream in(datadir / (bench + "_bench.json"));
    if (in) {
      const std::string text{std::istreambuf_iterator<char>(in), {}};
      const nlohmann::json c = nlohmann::json::parse(json_without_nonfinite(text)).at("context");
      const long cpus = c.at("num_cpus").get<long>();
      const double load = c.at("load_avg").at(0).get<double>();
      std::ostringstream o;
      o << std::fixed << std::setprecision(1) << "timed " << c.at("date").get<std::string>().substr(0, 10) << " on "
        << cpus << " CPUs at " << c.at("mhz_per_cpu").get<long>() << " MHz, load average " << load;
      if (load > double(cpus)) o << " (loaded: compare the methods, not absolute times)";
      note = o.str();
    }
  } catch (const nlohmann::json::exception&) {
    note = "timing conditions not recorded (" + bench + "_bench.json unreadable)";
  }
  GnuplotVars v;
  v.text.push_back({"timing", note});
  return v;
}

void draw_figure(const Figure& fig, const fs::path& datadir, const fs::path& outdir,
                 const std::vector<std::string>& formats) {
  fs::create_directories(datadir);
  fig.write_data(datadir);
  const GnuplotVars vars = fig.vars ? fig.vars(datadir) : GnuplotVars{};
  for (const auto& f : formats) run_gnuplot(fig.name, datadir, outdir, f, "", vars);
}

}  // namespace hapstab::cli
