// cli/cmd_sweep.cpp -- `hapstab sweep`: a command run over the product of exact parameter axes,
// in worker processes, sharded, resumable (docs/sweep.md).
//
//   hapstab sweep SPEC --out DIR [--jobs N] [--shard I/N] [--resume] [--quiet]
//   hapstab sweep merge DIR... --out DIR
//   hapstab sweep slurm SPEC --shards N --out DIR [--submit] [--partition P] [--time T] [--cpus C]
//   hapstab sweep plot DIR --x K [--y B] --z bound [--format png,pdf,svg,tex] [--contour] [--levels L]
//                      [--xlabel ..] [--ylabel ..] [--zlabel ..] [--title ..] [--size W,H] [--name NAME]
// Exit codes: 0 every point ran, 1 some points failed (their rows say why), 2 bad spec or
// options (the message names the key), 3 a worker died (rerun with --resume).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/sweep_cli.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/study/run.hpp"
#include "hapstab/study/sha256.hpp"
#include "hapstab/study/table.hpp"

namespace hapstab::cli::sweep {

namespace fs = std::filesystem;
using study::Spec;

namespace {

// Options the sweep sets itself, or that would write files outside --out.
const std::vector<std::string> reserved_keys{"set", "json", "out", "curve", "batch", "quiet", "help", "version"};

CLI::App* find_command(CLI::App& app, const std::vector<std::string>& words) {
  CLI::App* at = &app;
  for (const auto& w : words) {
    CLI::App* next = nullptr;
    for (CLI::App* s : at->get_subcommands([](CLI::App*) { return true; }))
      if (s->get_name() == w) next = s;
    if (!next) return nullptr;
    at = next;
  }
  return at;
}

/// What a point's command line needs beyond the spec: --json, and --out/--quiet when it has them.
struct CommandShape {
  bool has_out = false, has_quiet = false;
};

/// Checks the spec's command and [args] against the registry, and resolves the files [args] name
/// inside the spec's folder (input_file_in_folder: a spec cannot read /etc/passwd or /dev/zero).
CommandShape check_command(Spec& spec, const std::string& file) {
  std::vector<std::pair<CLI::App*, Runner>> runners;
  auto app = make_app(runners);
  std::string name;
  for (const auto& w : spec.command) name += (name.empty() ? "" : " ") + w;
  CLI::App* cmd = find_command(*app, spec.command);
  if (!cmd || name == "sweep") throw InputError(file + ": command: no command '" + name + "' to sweep");
  if (!cmd->get_option_no_throw("--set") || !cmd->get_option_no_throw("--json"))
    throw InputError(file + ": command: '" + name + "' cannot be swept (it takes no --set NAME=VALUE and --json)");
  for (auto& a : spec.args) {
    if (a.key == "set")
      throw InputError(file + ": args.set: constants go in a [set] table (B = \"1/2\"), axes in [axes]");
    if (std::find(reserved_keys.begin(), reserved_keys.end(), a.key) != reserved_keys.end())
      throw InputError(file + ": args." + a.key + ": set by the sweep itself (or writes files): not allowed in a spec");
    if (!cmd->get_option_no_throw("--" + a.key))
      throw InputError(file + ": args." + a.key + ": '" + name + "' has no option --" + a.key);
    const fs::path folder = fs::path(file).parent_path();
    a.value = input_file_in_folder(folder.empty() ? "." : folder, a.key, a.value, file + ": args." + a.key);
  }
  return {cmd->get_option_no_throw("--out") != nullptr, cmd->get_option_no_throw("--quiet") != nullptr};
}

/// The record of one point: the command's own code, run in this (worker) process.
nlohmann::json run_point(const Spec& spec, const CommandShape& shape, const fs::path& dir, uint64_t index) {
  std::vector<std::string> extra{"--json"};
  if (shape.has_quiet) extra.push_back("--quiet");
  if (shape.has_out) extra.insert(extra.end(), {"--out", (dir / "points" / std::to_string(index)).string()});
  try {
    // one parser per process for all its points: every point names the same options
    static std::unique_ptr<PreparedCommand> prepared;
    if (!prepared) prepared = std::make_unique<PreparedCommand>(spec.command.front());
    InProcessRun r = prepared->run(study::point_args(spec, index, extra));
    if (r.json.is_null())
      return {{"exit", r.code}, {"error", "the command printed no JSON (exit code " + std::to_string(r.code) + ")"}};
    return {{"exit", r.code}, {"json", std::move(r.json)}};
  } catch (const std::exception& e) {
    // the cell is the message (its column is already named "error"; exit 2 says bad input); a
    // numerical failure or an internal error says which it is
    const ErrorExit x = exit_code_for(e);
    return {{"exit", static_cast<int>(x.code)},
            {"error", x.code == exit_bad_input ? std::string(e.what()) : std::string(x.kind) + ": " + e.what()}};
  }
}

std::pair<uint64_t, uint64_t> parse_shard(const std::string& s) {
  const auto slash = s.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument(s);
    size_t a = 0, b = 0;
    const uint64_t i = std::stoull(s.substr(0, slash), &a), n = std::stoull(s.substr(slash + 1), &b);
    if (a != slash || b != s.size() - slash - 1 || n == 0 || n > 1000000 || i >= n || s[0] == '-' || s[slash + 1] == '-')
      throw std::invalid_argument(s);
    return {i, n};
  } catch (const std::exception&) {
    throw InputError("--shard '" + s + "': expected I/N with 0 <= I < N <= 10^6, e.g. --shard 0/4");
  }
}

std::string read_text(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

/// DIR/sweep.json: which spec and shard a folder holds, checked by --resume.
nlohmann::json folder_identity(const Spec& spec, const std::string& shard) {
  return {{"spec_sha256", spec.sha256}, {"shard", shard}};
}

void write_manifest(const fs::path& dir, const Spec& spec, const std::string& shard, uint64_t here,
                    const study::TableCounts& c, unsigned jobs, double seconds) {
  nlohmann::ordered_json m;
  m["spec_sha256"] = spec.sha256;
  m["hapstab_version"] = HAPSTAB_VERSION;
  std::string command;
  for (const auto& w : spec.command) command += (command.empty() ? "" : " ") + w;
  m["command"] = command;
  m["shard"] = shard;
  m["points"] = {{"sweep", spec.points}, {"here", here}, {"ok", c.ok}, {"failed", c.failed}};
  if (jobs) m["jobs"] = jobs;
  m["wall_seconds"] = seconds;
  study::write_atomically(dir / "manifest.json", m.dump(2) + "\n");
}

void check_resumable(const fs::path& dir, const Spec& spec, const std::string& shard, bool resume) {
  if (!fs::exists(dir / "sweep.json")) {
    if (fs::exists(dir / "checkpoints") || fs::exists(dir / "results.txt"))
      throw InputError("--out: '" + dir.string() + "' holds sweep files without sweep.json: choose another folder");
    return;
  }
  if (!resume)
    throw InputError("--out: '" + dir.string() + "' holds a sweep already: add --resume to continue it, or choose another folder");
  const auto before = nlohmann::json::parse(read_text(dir / "sweep.json"), nullptr, false);
  if (before != folder_identity(spec, shard))
    throw InputError("--resume: '" + dir.string() + "' holds another sweep (" + before.dump() + "), not spec sha256 " +
                     spec.sha256 + " shard " + shard);
}

}  // namespace

Spec load_spec(const std::string& path) {
  Spec spec = study::parse_spec(study::read_spec_file(path), path);
  check_command(spec, path);
  return spec;
}

int run(const RunOptions& o) { return run_text(study::read_spec_file(o.spec), o.spec, o); }

int run_text(const std::string& text, const std::string& name, const RunOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  Spec spec = study::parse_spec(text, name);
  const CommandShape shape = check_command(spec, name);
  const auto [shard, shards] = parse_shard(o.shard);
  const std::string shard_text = std::to_string(shard) + "/" + std::to_string(shards);
  const fs::path dir = output_folder(o.out, "--out");
  check_resumable(dir, spec, shard_text, o.resume);
  study::write_atomically(dir / "spec.toml", text);
  study::write_atomically(dir / "sweep.json", folder_identity(spec, shard_text).dump() + "\n");

  const study::PointRange range = study::PointRange::shard_of(spec.points, shard, shards);
  auto load = [&] {
    auto store = std::make_unique<study::RecordStore>(range);
    if (fs::exists(dir / "results.txt")) store->add_file(dir / "results.txt");
    for (const auto& f : study::checkpoint_files(dir)) store->add_file(f);
    return store;
  };
  const unsigned jobs = o.jobs ? o.jobs : study::available_cpus();
  study::RunPlan plan{dir, range, jobs, o.quiet};
  const study::RunResult ran =
      study::run_pending(plan, *load(), [&](uint64_t i) { return run_point(spec, shape, dir, i); });
  if (!ran.workers_ok)
    throw NumericalError(ran.worker_error + "; the finished points are kept: run again with --resume");
  const auto store = load();
  if (store->present() != range.count)
    throw NumericalError("points without a record after the run (e.g. " + std::to_string(store->missing(1).at(0)) +
                         "): run again with --resume");
  const study::TableCounts counts = study::write_table(spec, *store, dir);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_manifest(dir, spec, shard_text, range.count, counts, jobs, seconds);
  fs::remove_all(dir / "checkpoints");
  if (!o.quiet)
    std::cerr << "sweep: " << range.count << " points (" << ran.ran << " run now), " << counts.failed << " failed -> "
              << (dir / "points.csv").string() << "\n";
  return counts.failed ? exit_property_fails : exit_ok;
}

int merge(const std::vector<std::string>& dirs, const std::string& out, bool quiet) {
  std::string text, first;
  for (const auto& d : dirs) {
    if (!fs::exists(fs::path(d) / "manifest.json"))
      throw InputError("merge: '" + d + "' is not a finished sweep folder (no manifest.json): run its shard (with --resume)");
    const std::string t = study::read_spec_file((fs::path(d) / "spec.toml").string());
    if (first.empty()) text = t, first = d;
    else if (t != text)
      throw InputError("merge: '" + d + "' comes from another spec (sha256 " + study::sha256_hex(t) + ") than '" + first +
                       "' (sha256 " + study::sha256_hex(text) + ")");
  }
  if (dirs.empty()) throw InputError("merge: no shard folders given");
  const Spec spec = study::parse_spec(text, (fs::path(first) / "spec.toml").string());
  study::RecordStore store(study::PointRange{0, 1, spec.points});
  for (const auto& d : dirs) store.add_file(fs::path(d) / "results.txt");
  auto list = [](const std::vector<uint64_t>& v, size_t n) {
    std::string s;
    for (size_t k = 0; k < v.size() && k < n; ++k) s += (k ? ", " : "") + std::to_string(v[k]);
    return s + (v.size() > n ? ", ..." : "");
  };
  if (!store.duplicates().empty())
    throw InputError("merge: points in more than one shard: " + list(store.duplicates(), 10));
  if (store.present() != spec.points)
    throw InputError("merge: " + std::to_string(spec.points - store.present()) + " points missing: " +
                     list(store.missing(11), 10));
  const fs::path dir = output_folder(out, "--out");
  study::write_atomically(dir / "spec.toml", text);
  const study::TableCounts counts = study::write_table(spec, store, dir);
  write_manifest(dir, spec, "merged from " + std::to_string(dirs.size()) + " folders", spec.points, counts, 0, 0);
  if (!quiet)
    std::cerr << "sweep merge: " << spec.points << " points, " << counts.failed << " failed -> "
              << (dir / "points.csv").string() << "\n";
  return counts.failed ? exit_property_fails : exit_ok;
}

}  // namespace hapstab::cli::sweep

namespace hapstab::cli::cmd_sweep {  // its own namespace: the commands compile in unity batches
namespace {

using namespace hapstab::cli;

Runner setup(CLI::App& app) {
  auto r = std::make_shared<sweep::RunOptions>();
  app.add_option("spec", r->spec, "Spec file (TOML: command, [args], [axes]; docs/sweep.md)");
  app.add_option("--out", r->out, "Output folder: points.csv, manifest.json, results.txt");
  app.add_option("--jobs", r->jobs, "Worker processes (default: the CPUs available)")->check(CLI::Range(1u, 1024u));
  app.add_option("--shard", r->shard, "Run shard I of N (points I, I+N, ...), e.g. 0/4");
  app.add_flag("--resume", r->resume, "Continue a killed run in --out (its finished points are kept)");
  app.add_flag("--quiet", r->quiet, "No progress on stderr");

  auto m = std::make_shared<std::pair<std::vector<std::string>, std::string>>();
  CLI::App* merge = app.add_subcommand("merge", "Merge finished shard folders into one points.csv");
  merge->add_option("dirs", m->first, "Shard folders")->required();
  merge->add_option("--out", m->second, "Output folder")->required();
  merge->add_flag("--quiet", r->quiet, "No summary on stderr");

  auto s = std::make_shared<sweep::SlurmOptions>();
  CLI::App* slurm = app.add_subcommand("slurm", "Write (and --submit) a Slurm array job and its merge job");
  slurm->add_option("spec", s->spec, "Spec file")->required();
  slurm->add_option("--shards", s->shards, "Array tasks (shards)")->required()->check(CLI::Range(1u, 100000u));
  slurm->add_option("--out", s->out, "Output folder (shards/K, logs/, the merged points.csv)")->required();
  slurm->add_flag("--submit", s->submit, "Submit both jobs with sbatch");
  slurm->add_option("--partition", s->partition, "Slurm partition");
  slurm->add_option("--time", s->time, "Time limit per task, e.g. 02:00:00");
  slurm->add_option("--cpus", s->cpus, "CPUs per task (= --jobs of each shard)")->check(CLI::Range(1u, 1024u));

  auto p = std::make_shared<sweep::PlotOptions>();
  CLI::App* plot = app.add_subcommand("plot", "Draw a sweep's map with gnuplot");
  plot->add_option("dir", p->dir, "Sweep folder (points.csv)")->required();
  plot->add_option("--x", p->x, "Column on the x axis")->required();
  plot->add_option("--y", p->y, "Column on the y axis (without it: a line plot of --z over --x, one line per value of the other axes)");
  plot->add_option("--z", p->z, "Column coloured (the y axis of a line plot)")->required();
  plot->add_option("--xlabel", p->xlabel, "x axis label (default: the column and its unit from the spec's [units], \"K [N/m]\")");
  plot->add_option("--ylabel", p->ylabel, "y axis label (default as --xlabel)");
  plot->add_option("--zlabel", p->zlabel, "colour bar label, or the line plot's y axis (default as --xlabel)");
  plot->add_option("--title", p->title, "title (default: none; a paper's caption says it)");
  plot->add_option("--levels", p->levels, "level lines: a count (10) or values (1,2,5): drawn over the map, or with --contour");
  plot->add_option("--size", p->size, "W,H in cm (pdf, tex; png and svg scaled alike), e.g. 8.5,6; default 15.2,9.5");
  plot->add_option("--format", p->format, "comma-separated: png (default), pdf, svg, tex (cairolatex: figures/tex/NAME.tex + .pdf)");
  plot->add_option("--name", p->name, "file name of the figure (default sweep_map, sweep_contour or sweep_line)");
  plot->add_flag("--contour", p->contour, "Contour lines instead of a heat map");

  return [=]() -> int {
    if (merge->parsed()) return sweep::merge(m->first, m->second, r->quiet);
    if (slurm->parsed()) return sweep::slurm(*s);
    if (plot->parsed()) return sweep::plot(*p);
    if (r->spec.empty() || r->out.empty())
      throw hapstab::InputError("sweep: give a spec file and --out DIR (see hapstab sweep --help)");
    return sweep::run(*r);
  };
}

const Register reg({"sweep", "Run a command over a grid of exact parameter values (in parallel, sharded, resumable)",
                    setup});

}  // namespace
}  // namespace hapstab::cli::cmd_sweep
