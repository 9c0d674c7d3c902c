// cli/command.hpp -- how a `hapstab <command>` registers itself, and the shared option
// parsing and output helpers every command uses.
//
// A command file does
//   static const hapstab::cli::Register reg({"r", "Evaluate r(jw) ...", [](CLI::App& app) {
//       auto opts = std::make_shared<Opts>(); app.add_option(...);
//       return [opts]() -> int { ...; return hapstab::cli::exit_ok; };
//   }});
// Exit codes (DESIGN.md): 0 success, 1 the property does not hold, 2 bad input,
// 3 numerical failure. Errors are thrown as hapstab::InputError / NumericalError and
// printed by main without a stack.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hapstab/numeric/result.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::cli {

enum ExitCode { exit_ok = 0, exit_property_fails = 1, exit_bad_input = 2, exit_numerical = 3 };

/// How an error ends the command: its exit code and the word printed before its message.
/// InputError and CLI11's parse errors -> 2 "error"; NumericalError -> 3 "numerical failure";
/// anything else -> 3 "internal error". The one mapping main and `bound --batch` share.
struct ErrorExit {
  ExitCode code;
  const char* kind;
};
ErrorExit exit_code_for(const std::exception& e);

using Runner = std::function<int()>;
struct Command {
  std::string name;
  std::string help;
  std::function<Runner(CLI::App&)> setup;  ///< adds options to the subcommand, returns its body
};

std::vector<Command>& commands();

struct Register {
  explicit Register(Command c) { commands().push_back(std::move(c)); }
};

/// The `hapstab` application with every registered command as a subcommand; `runners` receives
/// each subcommand's body. main and run_in_process build it the same way.
std::unique_ptr<CLI::App> make_app(std::vector<std::pair<CLI::App*, Runner>>& runners);

/// One in-process run of a command: its exit code and the last JSON it printed (null if none).
struct InProcessRun {
  int code;
  nlohmann::json json;
};
/// Runs `hapstab args...` (without the program name) in this process, capturing what print_json
/// prints on this thread instead of writing it. Errors propagate as exceptions (exit_code_for
/// maps them). `hapstab sweep` and the Python module call this, so their numbers are the
/// command's own, by construction.
InProcessRun run_in_process(const std::vector<std::string>& args);

/// One command's parser, built once, run many times in this process with the same option names
/// and other values: a sweep's points. Building CLI11's options cost a `bound --method fast` point
/// as much as the bound itself. run(args) is run_in_process(args) without the rebuilding. CLI11
/// does not reset a variable when its option is left out, so every run must name the same
/// options in the same order (only the values change); run() throws std::logic_error otherwise.
class PreparedCommand {
 public:
  explicit PreparedCommand(const std::string& command);
  InProcessRun run(const std::vector<std::string>& args);

 private:
  std::vector<std::pair<CLI::App*, Runner>> runners_;  // before app_: make_app_for fills it
  std::unique_ptr<CLI::App> app_;
  std::vector<std::string> names_;  ///< the option names of the first run
  bool ran_ = false;
};

/// Parses an exact rational option value; the error names the option.
rational option_rational(const std::string& text, const std::string& option);

/// Parses repeated `--set NAME=VALUE` into exact parameters (error names the bad entry).
std::map<std::string, rational> parse_sets(const std::vector<std::string>& sets);

/// InputError when a `--set NAME` names a parameter that none of `expressions` (option, text)
/// names: a typo is never ignored (the Python module's params and a scene's --set refuse it too).
void refuse_unnamed_sets(const std::vector<std::string>& sets,
                         const std::vector<std::pair<std::string, std::string>>& expressions);

/// Creates the output folder `dir` of option `option` ("--out") before any work, and checks that
/// a file can be written in it; InputError (exit 2) naming the option otherwise.
std::filesystem::path output_folder(const std::string& dir, const std::string& option);

/// The options that name a file hapstab reads: "scene", "ss", "mat" (without "--"; --batch and
/// the spec itself are the files these are named in). tests/cli/test_untrusted.cpp checks that
/// every option whose help says it reads a file is here.
const std::vector<std::string>& input_file_options();

/// The value of option `option` (without "--") as named by an untrusted file in `folder` (a sweep
/// spec's [args], a --batch line): for an option of input_file_options(), the file must be inside
/// `folder` under the rule of the files a scene names (report::input_file_inside: relative, no
/// "..", no link out, a regular file of at most 64 MB), and the value returned names it by its
/// resolved path (for --mat FILE:VAR, the FILE part); any other option's value is returned as is.
/// InputError naming `what` otherwise.
std::string input_file_in_folder(const std::filesystem::path& folder, const std::string& option,
                                 const std::string& value, const std::string& what);

/// Prints JSON (2-space indented) to stdout (or into run_in_process's capture on its thread).
void print_json(const nlohmann::json& j);

/// The JSON of a printed bound, for every command and format (issue 40): a decimal string with
/// `digits` significant digits rounded OUTWARD (numeric/decimal.hpp, decimal_outward) -- a lower
/// bound toward -inf, an upper bound toward +inf -- so that what is printed still bounds the value;
/// null when there is none. An enclosure is [lower, upper]. A value known exactly is printed
/// exactly beside its bounds (exact_json: "55/96").
nlohmann::json lower_bound_json(const std::optional<rational>& q, int digits);
nlohmann::json upper_bound_json(const std::optional<rational>& q, int digits);
nlohmann::json enclosure_json(const Enclosure<rational>& e, int digits);
/// "p/q" of an exact value, null when there is none.
nlohmann::json exact_json(const std::optional<rational>& q);

}  // namespace hapstab::cli
