// cli/command.cpp -- the command registry, the shared option helpers, the one exception-to-exit-code
// mapping, and the in-process runner that `hapstab sweep` and the Python module use.
#include "cli/command.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>

#include "cli/mat_file.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/paths.hpp"

namespace hapstab::cli {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

rational option_rational(const std::string& text, const std::string& option) {
  return parse_rational(text, option);
}

std::map<std::string, rational> parse_sets(const std::vector<std::string>& sets) {
  std::map<std::string, rational> out;
  for (const auto& s : sets) {
    auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set '" + s + "': expected NAME=VALUE, e.g. --set K=1000");
    std::string name = s.substr(0, eq);
    out[name] = parse_rational(s.substr(eq + 1), "--set " + name);
  }
  return out;
}

void refuse_unnamed_sets(const std::vector<std::string>& sets,
                         const std::vector<std::pair<std::string, std::string>>& expressions) {
  std::set<std::string> named;
  std::string options;
  int given = 0;
  for (const auto& [option, text] : expressions) {
    if (text.empty()) continue;
    for (const auto& n : names_in(text)) named.insert(n);
    options += (options.empty() ? "" : ", ") + option;
    ++given;
  }
  for (const auto& [name, value] : parse_sets(sets)) {
    if (named.count(name)) continue;
    std::string list;
    for (const auto& n : named)
      if (n != "T" && n != "s" && n != "z") list += (list.empty() ? "" : ", ") + n;
    throw InputError("--set " + name + ": no expression names " + name + " (" + options + (given == 1 ? " names " : " name ") +
                     (list.empty() ? "no parameter" : list) + "): a typo is never ignored");
  }
}

std::filesystem::path output_folder(const std::string& dir, const std::string& option) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw InputError(option + ": an empty folder name");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw InputError(option + ": cannot create '" + dir + "': " + (ec ? ec.message() : "not a folder"));
  const fs::path probe = fs::path(dir) / ".hapstab-write-test";
  {
    std::ofstream f(probe);
    if (!f) throw InputError(option + ": cannot write in '" + dir + "'");
  }
  fs::remove(probe, ec);
  return dir;
}

const std::vector<std::string>& input_file_options() {
  static const std::vector<std::string> names{"scene", "ss", "mat"};
  return names;
}

std::string input_file_in_folder(const std::filesystem::path& folder, const std::string& option,
                                 const std::string& value, const std::string& what) {
  const auto& names = input_file_options();
  if (std::find(names.begin(), names.end(), option) == names.end()) return value;
  const auto [file, vars] = option == "mat" ? split_mat_spec(value) : std::pair{value, std::string()};
  return report::input_file_inside(folder, file, what, 64u << 20).string() + vars;
}

namespace {
// Where print_json writes on this thread: stdout, or the capture of run_in_process.
thread_local std::vector<nlohmann::json>* json_capture = nullptr;
}  // namespace

void print_json(const nlohmann::json& j) {
  if (json_capture) json_capture->push_back(j);
  else std::cout << j.dump(2) << std::endl;
}

nlohmann::json lower_bound_json(const std::optional<rational>& q, int digits) {
  return q ? nlohmann::json(decimal_outward(*q, digits, -1)) : nlohmann::json(nullptr);
}
nlohmann::json upper_bound_json(const std::optional<rational>& q, int digits) {
  return q ? nlohmann::json(decimal_outward(*q, digits, +1)) : nlohmann::json(nullptr);
}
nlohmann::json enclosure_json(const Enclosure<rational>& e, int digits) {
  return {decimal_outward(e.lo, digits, -1), decimal_outward(e.hi, digits, +1)};
}
nlohmann::json exact_json(const std::optional<rational>& q) { return q ? nlohmann::json(q->str()) : nlohmann::json(nullptr); }

namespace {
// The order and the groups of `hapstab --help`: the papers' commands in the README's order, then
// the tools beyond them, then the reproduction. A command missing here is listed last, under "Other".
const std::vector<std::pair<std::string, std::vector<std::string>>>& help_groups() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> g{
      {"Paper 001 (passivity bound)", {"r", "bound"}},
      {"Paper 002 (unilateral contact)", {"wedge", "limit-cycle"}},
      {"Paper 000 (multi-DOF LMI framework)", {"passivity-level", "multidof"}},
      {"Tools", {"stability", "simulate", "plot", "sweep"}},
      {"Reproduction", {"proofs", "figure", "reproduce"}},
  };
  return g;
}

}  // namespace

std::unique_ptr<CLI::App> make_app(std::vector<std::pair<CLI::App*, Runner>>& runners) {
  auto app = std::make_unique<CLI::App>(
      "hapstab -- passivity and stability of sampled-data haptic systems.\n"
      "Exit codes: 0 success, 1 the property does not hold, 2 bad input, 3 numerical failure.");
  app->require_subcommand(1);
  app->set_version_flag("--version", "hapstab " HAPSTAB_VERSION);
  runners.clear();
  std::vector<const Command*> ordered;
  for (const auto& [group, names] : help_groups())
    for (const auto& name : names)
      for (const auto& c : commands())
        if (c.name == name) ordered.push_back(&c);
  for (const auto& c : commands())
    if (std::find(ordered.begin(), ordered.end(), &c) == ordered.end()) ordered.push_back(&c);
  for (const Command* c : ordered) {
    CLI::App* sub = app->add_subcommand(c->name, c->help);
    std::string group = "Other";
    for (const auto& [g, names] : help_groups())
      if (std::find(names.begin(), names.end(), c->name) != names.end()) group = g;
    sub->group(group);
    runners.emplace_back(sub, c->setup(*sub));
  }
  return app;
}

namespace {
// The application with only the command `name` (a point of `hapstab sweep` runs one command; building
// every command's options for each point cost more than a fast-path bound). Fresh each call, so no
// option value can pass from one run to the next. nullptr when no command has that name.
std::unique_ptr<CLI::App> make_app_for(const std::string& name, std::vector<std::pair<CLI::App*, Runner>>& runners) {
  for (auto& c : commands())
    if (c.name == name) {
      auto app = std::make_unique<CLI::App>("hapstab");
      app->require_subcommand(1);
      runners.clear();
      CLI::App* sub = app->add_subcommand(c.name, c.help);
      runners.emplace_back(sub, c.setup(*sub));
      return app;
    }
  return nullptr;
}

// Parses `args` with `app` and runs the subcommand parsed, capturing what it prints as JSON.
InProcessRun parse_and_run(CLI::App& app, std::vector<std::pair<CLI::App*, Runner>>& runners,
                           const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  app.parse(reversed);
  struct Capture {
    std::vector<nlohmann::json> printed;
    Capture() { json_capture = &printed; }
    ~Capture() { json_capture = nullptr; }
  } capture;
  InProcessRun out{exit_bad_input, nullptr};
  for (auto& [sub, run] : runners)
    if (sub->parsed()) {
      out.code = run();
      break;
    }
  if (!capture.printed.empty()) out.json = std::move(capture.printed.back());
  return out;
}
}  // namespace

InProcessRun run_in_process(const std::vector<std::string>& args) {
  std::vector<std::pair<CLI::App*, Runner>> runners;
  auto app = args.empty() ? nullptr : make_app_for(args.front(), runners);
  if (!app) app = make_app(runners);
  return parse_and_run(*app, runners, args);
}

PreparedCommand::PreparedCommand(const std::string& command) : app_(make_app_for(command, runners_)) {
  if (!app_) throw InputError("no command '" + command + "'");
}

InProcessRun PreparedCommand::run(const std::vector<std::string>& args) {
  std::vector<std::string> names;
  for (const auto& a : args)
    if (a.rfind("--", 0) == 0) names.push_back(a.substr(0, a.find('=')));
  if (!ran_) names_ = names, ran_ = true;
  if (names != names_) throw std::logic_error("PreparedCommand::run: the options differ from the first run's");
  app_->clear();
  return parse_and_run(*app_, runners_, args);
}

ErrorExit exit_code_for(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const CLI::ParseError*>(&e))
    return {exit_bad_input, "error"};
  if (dynamic_cast<const NumericalError*>(&e)) return {exit_numerical, "numerical failure"};
  return {exit_numerical, "internal error"};
}

}  // namespace hapstab::cli
