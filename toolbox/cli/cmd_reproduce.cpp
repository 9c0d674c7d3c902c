// `hapstab reproduce`: the main job. Every proof (proofs/), every example scene (examples/*.toml,
// cli/scenes.hpp), every figure (plots/*.gp but common*.gp and `hapstab plot`'s user_*.gp: data +
// gnuplot, in every requested format), then
// DIR/report.md and DIR/index.html. The certificate of every claim instance a proof asks for goes to
// DIR/certificates/, checked by `hapstab check` and the independent checker (cli/reproduce_certificates.hpp).
// With --table, the claim table is compared as `proofs --table` does (the main job passes proofs/README.md).
// Exit 1 when a claim fails or differs from its row of that table, a certificate is not written, not the claim's, refuted or malformed, a
// scene does not behave as its [reproduce] table says, a figure cannot be drawn, or a plots/ script
// has no figure behind it.
// The bench charts run the bench programs (bench/README.md); without them they are reported
// "not reproduced" (not a failure).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/python_examples.hpp"
#include "cli/reproduce.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli::cmd_reproduce {  // its own namespace: the commands compile in unity batches
namespace {

namespace fs = std::filesystem;

std::vector<std::string> parse_formats(const std::string& text) {
  std::vector<std::string> out = figure_formats(text);
  if (out.front() != "png" && std::find(out.begin(), out.end(), "png") == out.end())
    out.insert(out.begin(), "png");  // the HTML report shows PNGs
  return out;
}

struct Opts {
  std::string out = "out", only, format = "png,pdf,svg,tex", table;
  bool quiet = false;
};

int run(const Opts& o) {
  static const std::set<std::string> papers{"", "000", "001", "002", "ext", "toolbox", "python"};
  if (!papers.count(o.only))
    throw InputError("--only: unknown paper '" + o.only + "' (expected 000, 001, 002, ext, toolbox or python)");
  const auto formats = parse_formats(o.format);
  const bool proofs_run = o.only != "toolbox" && o.only != "python";
  if (!o.table.empty() && !proofs_run)
    throw InputError("--table: --only " + o.only + " runs no proof, so there is no claim to compare with the table");
  if (!o.table.empty() && !std::ifstream(o.table)) throw InputError("--table: cannot read '" + o.table + "'");
  const fs::path dir = output_folder(o.out, "--out");
  auto t0 = std::chrono::steady_clock::now();
  ReportInput rep;
  if (!o.quiet) std::cerr << "reproduce: running the proofs\n";
  double s = 0;
  if (proofs_run) rep.claims = run_proofs(o.only, true, s);
  size_t claim_fails = 0;
  for (const auto& c : rep.claims) {
    claim_fails += !c.holds;
    if (!c.holds) std::cerr << "reproduce: claim " << c.id << " FAILS: " << c.evidence << "\n";
  }
  // as `proofs --table` does: every claim has its row in the claim table, each column equal
  const int table_diffs = o.table.empty() ? 0 : claim_table_differences(rep.claims, o.table, o.only, "reproduce");
  if (!o.quiet) std::cerr << "reproduce: " << rep.claims.size() << " claims checked in " << s << " s\n";
  if (!o.quiet) std::cerr << "reproduce: running the example scenes (examples/*.toml)\n";
  rep.scenes = run_scenes(o.only, dir, o.quiet);
  if (!rep.claims.empty() || !rep.scenes.empty()) {  // the claims' certificates, then the scenes' analyses'
    if (!o.quiet) std::cerr << "reproduce: writing and checking the certificates (DIR/certificates)\n";
    rep.certificates = produce_certificates(rep.claims, dir, true);
    for (auto& e : produce_scene_certificates(rep.scenes, dir)) rep.certificates.push_back(std::move(e));
    rep.certificate_summary = check_certificates(rep.certificates, dir, false);  // failures printed, as a failed claim is
    write_certificate_index(rep.certificates, rep.certificate_summary, dir);
    if (!o.quiet)
      std::cerr << "reproduce: " << certificate_counts(rep.certificate_summary, false) << "; written in "
                << rep.certificate_summary.produce_seconds << " s, checked in " << rep.certificate_summary.wall_seconds << " s\n";
  }
  for (const auto& r : rep.scenes)
    if (!r.ok) std::cerr << "reproduce: scene " << r.file << " (" << r.command << ") FAILS: " << r.error << "\n";
  // Every plots/ script is a figure, except common*.gp (shared pieces the scripts load) and
  // user_*.gp (`hapstab plot`'s figures of the user's own H: no data of their own to reproduce).
  std::set<std::string> registered;
  for (const auto& f : figures()) registered.insert(f.name);
  for (const auto& e : fs::directory_iterator(plots_dir())) {
    const std::string stem = e.path().stem().string();
    const bool piece = stem.rfind("common", 0) == 0 || stem.rfind("user_", 0) == 0;
    if (e.path().extension() == ".gp" && !piece && !registered.count(stem) && o.only.empty()) {
      FigureEntry f{stem, "toolbox", "plots/" + stem + ".gp"};
      f.ok = false;
      f.error = "plots/" + stem + ".gp has no registered figure (RegisterFigure) to write its data";
      std::cerr << "reproduce: " << f.error << "\n";
      rep.figures.push_back(f);
    }
  }
  size_t n = 0, total = 0;
  for (const auto& f : figures()) total += o.only.empty() || o.only == f.paper;
  for (const auto& f : figures()) {
    if (!o.only.empty() && o.only != f.paper) continue;
    ++n;
    FigureEntry e{f.name, f.paper, f.caption};
    auto f0 = std::chrono::steady_clock::now();
    try {
      draw_figure(f, dir / "data", dir / "figures", formats);
    } catch (const FigureSkipped& ex) {
      e.ok = false;
      e.skipped = true;
      e.error = ex.what();
      std::cerr << "reproduce: figure " << f.name << " not reproduced on this build: " << ex.what() << "\n";
    } catch (const std::exception& ex) {
      e.ok = false;
      e.error = ex.what();
      std::cerr << "reproduce: figure " << f.name << " NOT drawn: " << ex.what() << "\n";
    }
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - f0).count();
    if (!o.quiet) std::cerr << "reproduce: [figure " << n << "/" << total << "] " << f.name << " (" << e.seconds << " s)\n";
    rep.figures.push_back(e);
  }
  if (o.only.empty() || o.only == "python") {
    if (!o.quiet) std::cerr << "reproduce: running the Python examples (examples/python)\n";
    for (auto& e : run_python_examples(dir / "figures", o.quiet)) rep.figures.push_back(std::move(e));
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_report_md(rep, dir);
  write_index_html(rep, dir);
  size_t fig_fails = 0, fig_skipped = 0, scene_fails = 0;
  for (const auto& f : rep.figures) fig_fails += !f.ok && !f.skipped, fig_skipped += f.skipped;
  for (const auto& r : rep.scenes) scene_fails += !r.ok;
  const size_t cert_fails = rep.certificate_summary.failed;
  std::cout << "reproduce: " << rep.claims.size() - claim_fails << " claims hold, " << claim_fails << " fail; "
            << certificate_counts(rep.certificate_summary, false) << "; " << rep.scenes.size() - scene_fails << " scene runs as expected, " << scene_fails << " not; "
            << rep.figures.size() - fig_fails - fig_skipped << " figures drawn, " << fig_fails << " failed, "
            << fig_skipped << " not reproduced on this build; "
            << (o.table.empty() ? "" : std::to_string(table_diffs) + " differences from the claim table " + o.table + "; ")
            << rep.seconds << " s; report: "
            << (dir / "report.md").string() << " and " << (dir / "index.html").string() << "\n";
  return (claim_fails || table_diffs || cert_fails || fig_fails || scene_fails) ? exit_property_fails : exit_ok;
}

const Register reg({"reproduce",
                    "The main job: every proof, example scene and figure of the three papers -> DIR/report.md, "
                    "DIR/index.html, DIR/figures/, DIR/data/",
                    [](CLI::App& app) {
                      auto o = std::make_shared<Opts>();
                      app.add_option("--out", o->out, "Output folder")->capture_default_str();
                      app.add_option("--only", o->only, "Only this part: a paper (000, 001, 002), ext (beyond the papers), toolbox (own charts) or python (the Python examples)");
                      app.add_option("--format", o->format, "Figure formats, comma-separated: png,pdf,svg,tex (tex = cairolatex, in figures/tex/)")
                          ->capture_default_str();
                      app.add_flag("--quiet", o->quiet, "No progress on stderr");
                      app.add_option("--table", o->table,
                                     "Also fail unless every claim has its row, every column equal, in this claim table "
                                     "(proofs/README.md), as `proofs --table` does");
                      return [o]() { return run(*o); };
                    }});

const Register fig_reg({"figure", "Draw one figure (or --list them): data into DIR/data, figures into DIR/figures",
                        [](CLI::App& app) {
                          auto name = std::make_shared<std::string>();
                          auto out = std::make_shared<std::string>("out");
                          auto format = std::make_shared<std::string>("png,pdf,svg,tex");
                          auto list = std::make_shared<bool>(false);
                          app.add_option("name", *name, "Figure name (see --list)");
                          app.add_option("--out", *out, "Output folder")->capture_default_str();
                          app.add_option("--format", *format, "Figure formats, comma-separated: png,pdf,svg,tex (tex = cairolatex, in figures/tex/)")
                              ->capture_default_str();
                          app.add_flag("--list", *list, "List the figures");
                          return [=]() {
                            if (*list || name->empty()) {
                              std::vector<Figure> sorted = figures();  // by paper, then name
                              std::sort(sorted.begin(), sorted.end(), [](const Figure& a, const Figure& b) {
                                return std::make_pair(std::string(a.paper), std::string(a.name)) <
                                       std::make_pair(std::string(b.paper), std::string(b.name));
                              });
                              for (const auto& f : sorted)
                                std::cout << f.name << "  [" << f.paper << "]  " << f.caption << "\n";
                              if (!*list) throw InputError("figure: give a figure name (see --list)");
                              return int(exit_ok);
                            }
                            for (const auto& f : figures())
                              if (*name == f.name) {
                                const auto formats = parse_formats(*format);
                                output_folder(*out, "--out");
                                try {
                                  draw_figure(f, fs::path(*out) / "data", fs::path(*out) / "figures", formats);
                                } catch (const FigureSkipped& e) {
                                  throw InputError("figure " + *name + " cannot be drawn here: " + e.what());
                                }
                                std::cout << "figure " << f.name << " -> " << (fs::path(*out) / "figures").string()
                                          << "\n";
                                return int(exit_ok);
                              }
                            throw InputError("figure: unknown figure '" + *name + "' (see hapstab figure --list)");
                          };
                        }});

}  // namespace
}  // namespace hapstab::cli::cmd_reproduce
