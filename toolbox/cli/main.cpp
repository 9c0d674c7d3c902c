// cli/main.cpp -- the `hapstab` command: dispatches to the registered subcommands and maps
// errors to exit codes (0 ok, 1 property fails, 2 bad input, 3 numerical failure).
#include <iostream>

#include "cli/command.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"

namespace {
// Messages quote input (a scene's name, an expression): on a terminal a control character in it
// could move the cursor or retitle the window, so they are printed through report::text.
std::string shown(const std::exception& e) { return hapstab::report::text(e.what(), true); }
}  // namespace

int main(int argc, char** argv) {
  using namespace hapstab::cli;
  restore_gmp_allocator();
  std::vector<std::pair<CLI::App*, Runner>> runners;
  const auto app_ptr = make_app(runners);
  CLI::App& app = *app_ptr;
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
