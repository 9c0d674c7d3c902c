// cli/main.cpp -- the `hapstab` command: dispatches to the registered subcommands and maps
// errors to exit codes (0 ok, 1 property fails, 2 bad input, 3 numerical failure).
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/escape.hpp"
#include "hapstab/scene/schema.hpp"  // edit_distance, the one "did you mean" metric

namespace {
// Messages quote input (a scene's name, an expression): on a terminal a control character in it
// could move the cursor or retitle the window, so they are printed through report::text.
std::string shown(const std::exception& e) { return hapstab::report::text(e.what(), true); }

/// "bound", "sweep plot": the words of a (sub)command below `hapstab`.
std::string path_of(const CLI::App* a) {
  std::string p;
  for (; a && a->get_parent(); a = a->get_parent()) p = a->get_name() + (p.empty() ? "" : " " + p);
  return p;
}

/// The message for a parse error of `hapstab args...` (args without the program name): where a
/// command is expected and the word given is none (`hapstab boundd`, `hapstab multidof analyse`),
/// "unknown command 'boundd'; did you mean 'bound'?" (the nearest command by edit distance, a
/// prefix counting as near, else the list of commands); where a command is expected and none is
/// given, which ones there are; where an option is not one of the command's (`hapstab bound
/// --dealy 3`), "unknown option '--dealy' of 'hapstab bound'; did you mean '--delay'?" (the same
/// nearness); otherwise CLI11's own message.
std::string parse_error_message(const CLI::App& app, const std::vector<std::string>& args, const CLI::ParseError& e) {
  const CLI::App* level = &app;
  std::string path = "hapstab";
  for (size_t i = 0; i <= args.size(); ++i) {
    const auto subs = level->get_subcommands([](const CLI::App*) { return true; });
    if (subs.empty() || level->get_require_subcommand_min() == 0) break;  // options and operands from here on
    if (i < args.size() && !args[i].empty() && args[i][0] == '-') break;  // an option where a command belongs: CLI11 says
    std::vector<std::string> names;
    for (const CLI::App* s : subs) names.push_back(s->get_name());
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    if (i == args.size()) return path + " needs a command: " + list + " (" + path + " --help says what each does)";
    const std::string& word = args[i];
    const auto match = std::find(names.begin(), names.end(), word);
    if (match != names.end()) {
      level = level->get_subcommand(word);
      path += " " + word;
      continue;
    }
    std::string best;
    size_t best_d = std::string::npos;
    for (const auto& n : names) {
      const size_t d = n.rfind(word, 0) == 0 ? 1 : hapstab::scene::edit_distance(word, n);  // a prefix counts as near
      if (d < best_d) best_d = d, best = n;
    }
    const std::string where = path == "hapstab" ? "" : " of '" + path.substr(8) + "'";
    if (best_d <= std::max<size_t>(2, word.size() / 3))
      return "unknown command '" + word + "'" + where + "; did you mean '" + best + "'?";
    return "unknown command '" + word + "'" + where + " (commands: " + list + ")";
  }
  // an unknown option (`hapstab bound --dealy 3`): the nearest option of the command being parsed
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    const CLI::App* at = &app;
    for (std::vector<CLI::App*> parsed = at->get_subcommands(); !parsed.empty(); parsed = at->get_subcommands())
      at = parsed.front();
    std::vector<std::string> options;
    for (const CLI::Option* o : at->get_options())
      for (const std::string& n : o->get_lnames()) options.push_back("--" + n);
    for (const std::string& arg : args) {
      if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
      const std::string word = arg.substr(0, arg.find('='));
      if (std::find(options.begin(), options.end(), word) != options.end()) continue;
      std::string best;
      size_t best_d = std::string::npos;
      for (const auto& n : options) {
        const size_t d = n.rfind(word, 0) == 0 ? 1 : hapstab::scene::edit_distance(word, n);  // a prefix counts as near
        if (d < best_d) best_d = d, best = n;
      }
      const std::string cmd = at == &app ? "hapstab" : "hapstab " + path_of(at);
      if (!best.empty() && best_d <= std::max<size_t>(2, word.size() / 3))
        return "unknown option '" + word + "' of '" + cmd + "'; did you mean '" + best + "'?";
      return "unknown option '" + word + "' of '" + cmd + "' (" + cmd + " --help lists its options)";
    }
  }
  return e.what();
}

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
    // every error starts "hapstab: error:", the parser's included (an unknown command named)
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::cerr << "hapstab: error: " << hapstab::report::text(parse_error_message(app, args, e), true) << "\n";
    return exit_bad_input;
  } catch (const hapstab::InputError& e) {
    std::cerr << "hapstab: error: " << shown(e) << "\n";
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
