// cli/main.cpp -- the `hapstab` command: dispatches to the registered subcommands and maps
// errors to exit codes (0 ok, 1 property fails, 2 bad input, 3 numerical failure).
#include <fstream>
#include <iostream>

#include "cli/command.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

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

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

ErrorExit exit_code_for(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const CLI::ParseError*>(&e))
    return {exit_bad_input, "error"};
  if (dynamic_cast<const NumericalError*>(&e)) return {exit_numerical, "numerical failure"};
  return {exit_numerical, "internal error"};
}

}  // namespace hapstab::cli

namespace {
// Messages quote input (a scene's name, an expression): on a terminal a control character in it
// could move the cursor or retitle the window, so they are printed through report::text.
std::string shown(const std::exception& e) { return hapstab::report::text(e.what(), true); }
}  // namespace

int main(int argc, char** argv) {
  using namespace hapstab::cli;
  CLI::App app{"hapstab -- passivity and stability of sampled-data haptic systems.\n"
               "Exit codes: 0 success, 1 the property does not hold, 2 bad input, 3 numerical failure."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hapstab " HAPSTAB_VERSION);
  std::vector<std::pair<CLI::App*, Runner>> runners;
  for (auto& c : commands()) {
    CLI::App* sub = app.add_subcommand(c.name, c.help);
    runners.emplace_back(sub, c.setup(*sub));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_bad_input;
  } catch (const hapstab::InputError& e) {
    std::cerr << "hapstab: " << shown(e) << "\n";
    return exit_bad_input;
  }
  try {
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
  } catch (const std::exception& e) {
    const ErrorExit exit = exit_code_for(e);
    std::cerr << "hapstab: " << exit.kind << ": " << shown(e) << "\n";
    return exit.code;
  }
  return exit_bad_input;
}
