// cli/tf_options.hpp -- the options of every command that takes a virtual environment H(z):
// --H EXPR, or --num "c0 c1 ..." --den "d0 d1 ..." (descending powers of z, the python-control
// and MATLAB convention), or --mat FILE:VAR (a MATLAB .mat file, cli/mat_file.hpp); with
// --T T, --set NAME=VALUE (repeatable, for --H) and, where the command has it, --delay n.
// One parser for all of them, so each error names the option in the same way:
//   "--H: column 7: expected ')' ...", "--T: the sample period must be > 0, got '0'",
//   "--den: the leading coefficient (of z^2) is 0".
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/tf.hpp"

namespace hapstab::cli {

struct TfOptions {
  std::string H, T;
  std::string num, den;  ///< --num/--den: coefficients in descending powers of z
  std::string mat;       ///< --mat FILE[:VAR[,VAR]]
  std::vector<std::string> sets;
  int delay = 0;  ///< --delay n (z^-n), only where add_tf_options was asked for it
};

struct TfRules {
  bool period_required = true;  ///< false: T = 1 when --T is absent (H(z) alone does not depend on T)
  bool causal = true;           ///< deg num <= deg den required
  bool with_delay = false;      ///< the command has --delay
  /// A pole H as written has and its lowest terms lose, on or outside the circle (lti/parse.hpp):
  /// refused, or (`bound`: b* sees the frequency response only) allowed while H as written is
  /// marginally stable.
  HiddenPoles hidden_poles = HiddenPoles::refuse;
};

/// Adds --H, --num, --den, --mat, --T, --set (and --delay) to `app`; `h_help` describes H for this command.
void add_tf_options(CLI::App& app, TfOptions& o, const TfRules& rules, const std::string& h_help);

/// True when the options name H in some way (--H, --num/--den or --mat).
bool has_tf(const TfOptions& o);

/// The exact discrete transfer function of the options, or InputError naming the option.
TransferFunction parse_tf_options(const TfOptions& o, const TfRules& rules);

/// --H as H = H0 + NAME H1 (split_affine, lti/parse.hpp), for `--max NAME`: InputError naming
/// `option` when H is not given by --H, when --set gives NAME too, or when --H is not affine in NAME.
AffineSplit parse_tf_affine(const TfOptions& o, const TfRules& rules, const std::string& name, const std::string& option);

/// The exact sample period of --T (T = 1 when absent and not required); InputError naming --T.
rational parse_period(const TfOptions& o, const TfRules& rules);

/// A coefficient list "c0 c1 ...", "[1, -0.5]", "1,1/3 2e-3": exact rationals separated by
/// spaces and/or commas, optionally inside MATLAB's [ ]. InputError naming `option` when it is
/// empty, holds a non-number, or has more than limits::model_degree + 1 entries.
std::vector<rational> parse_coefficients(const std::string& text, const std::string& option);

/// H(z) = num(z)/den(z) from coefficients in descending powers of z (leading zeros of the
/// numerator are dropped, as MATLAB's tfdata pads it); the leading denominator coefficient must
/// not be 0. `num_name`/`den_name` name the inputs in errors ("--num", "plant.mat: den"). A
/// factor num and den share whose roots are not all inside the unit circle is refused (InputError):
/// realised as written it is a hidden mode (lti/tf.hpp's unstable_cancelled_factor).
TransferFunction tf_from_coefficients(const std::vector<rational>& num, const std::vector<rational>& den,
                                      const rational& T, const std::string& num_name, const std::string& den_name,
                                      HiddenPoles hidden_poles = HiddenPoles::refuse);

}  // namespace hapstab::cli
