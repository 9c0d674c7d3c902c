// hapstab/study/spec.hpp -- a sweep spec (TOML): the command, its options and the exact axes
// whose product is the set of points; point i's option list for run_in_process.
//
//   command = "bound"                      # "multidof analyze" for a command with a sub-command
//   [args]                                 # the command's options: key = "value" | integer | true
//   H = "K + B*(z-1)/(T*z)"
//   [axes]                                 # in file order; the last axis varies fastest
//   K = { from = "0", to = "40000", points = 7 }                 # exact linear grid
//   B = { values = ["0", "1/2", "5"] }                           # as given
//   c = { from = "1e-3", to = "10", points = 9, scale = "log", digits = 6 }
//   d = { random = 100, from = "0", to = "1", seed = 7 }         # reproducible everywhere
//   [set]                                  # constants: --set NAME=VALUE at every point
//   B = "1/2"
//   [units]                                # for plots: the unit of an axis or a column
//   K = "N/m"
//   bound = "N s/m"
//
// Every axis value is an exact rational written exactly: as given, or as a terminating decimal,
// or p/q. Log-scale values are 10-based geometric points rounded to `digits` significant digits
// (default 6; the rounded value is the point). Random values are from + (to - from) u / 2^53 with u
// the top 53 bits of splitmix64 draws from `seed`: integer arithmetic only, the same on every
// machine. The spec is untrusted: size and count limits, every error names its key (InputError).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hapstab/numeric/scalar.hpp"

namespace hapstab::study {

struct Axis {
  std::string name;                ///< the parameter set with --set NAME=VALUE
  std::vector<std::string> values; ///< exact values as shown in points.csv and passed to --set
  bool log = false;                ///< scale = "log" (a plot draws this axis logarithmic)
  bool listed = false;             ///< values = [...] (a map draws one equal row or column per value)
};

/// A constant of the spec's [set] table: --set NAME=VALUE at every point, before the axes.
struct Constant {
  std::string name, value;  ///< value: an exact number as written
};

/// An option of the command: `--key value`; `--key` alone when flag (true); left out when omit (false).
struct Arg {
  std::string key;
  std::string value;
  bool flag = false;
  bool omit = false;
};

struct Spec {
  std::vector<std::string> command;  ///< {"bound"} or {"multidof", "analyze"}
  std::vector<Arg> args;
  std::vector<Axis> axes;
  std::vector<Constant> constants;                              ///< [set], in file order
  std::vector<std::pair<std::string, std::string>> units;       ///< [units]: name -> unit, for plots
  uint64_t points = 1;   ///< product of the axis sizes
  std::string sha256;    ///< of the spec file's bytes
};

constexpr size_t max_spec_bytes = 1u << 20;
constexpr uint64_t max_points = 1000000000;     ///< 10^9 points per sweep
constexpr uint64_t max_axis_values = 10000000;  ///< 10^7 values per axis
/// Bits of the numerator and denominator of one exact number of a spec (from, to, values): about
/// 300 digits. "1e-200000" is 9 bytes of text and 660,000 bits.
constexpr size_t max_value_bits = 1024;
/// Bytes of all axis values as text (checked as they are generated; the number of points is
/// checked from the axes' sizes before that).
constexpr size_t max_values_bytes = size_t(256) << 20;

/// Parses a spec from its text; `file` names it in messages.
Spec parse_spec(const std::string& text, const std::string& file);
/// The bytes of a spec file (InputError when unreadable or larger than max_spec_bytes).
std::string read_spec_file(const std::string& path);

/// The axis values of point `index` (last axis fastest).
std::vector<std::string> point_values(const Spec& spec, uint64_t index);
/// The command line of point `index` without the program name: command words, the spec's
/// options, then one `--set NAME=VALUE` per constant and per axis. `extra` goes before the --set
/// options.
std::vector<std::string> point_args(const Spec& spec, uint64_t index, const std::vector<std::string>& extra);

/// An exact rational written exactly: integer, terminating decimal ("0.125"), else "p/q".
std::string exact_text(const rational& q);

/// The unit [units] gives `name`, or "".
std::string unit_of(const Spec& spec, const std::string& name);

/// The k-th draw of splitmix64 seeded with `seed` (k = 0, 1, ...).
uint64_t splitmix64(uint64_t seed, uint64_t k);

}  // namespace hapstab::study
