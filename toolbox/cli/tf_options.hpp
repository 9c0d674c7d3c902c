// cli/tf_options.hpp -- the options of every command that takes a virtual environment H(z):
// --H EXPR, --T T, --set NAME=VALUE (repeatable) and, where the command has it, --delay n.
// One parser for all of them, so each error names the option in the same way:
//   "--H: column 7: expected ')' ...", "--T: the sample period must be > 0, got '0'".
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "hapstab/lti/tf.hpp"

namespace hapstab::cli {

struct TfOptions {
  std::string H, T;
  std::vector<std::string> sets;
  int delay = 0;  ///< --delay n (z^-n), only where add_tf_options was asked for it
};

struct TfRules {
  bool period_required = true;  ///< false: T = 1 when --T is absent (H(z) alone does not depend on T)
  bool causal = true;           ///< deg num <= deg den required
  bool with_delay = false;      ///< the command has --delay
};

/// Adds --H, --T, --set (and --delay) to `app`; `h_help` describes H for this command.
void add_tf_options(CLI::App& app, TfOptions& o, const TfRules& rules, const std::string& h_help);

/// The exact discrete transfer function of the options, or InputError naming the option.
TransferFunction parse_tf_options(const TfOptions& o, const TfRules& rules);

}  // namespace hapstab::cli
