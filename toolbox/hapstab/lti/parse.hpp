// hapstab/lti/parse.hpp -- the exact expression parser for transfer functions.
//
//   "K + B*(z-1)/(T*z)"  with  K=1000, B=5, T=1/1000   ->  (1005 z - 5000 ... ) exactly
//
// Grammar: numbers (exact decimals: 0.001, 1e-3, 1/1000 via division), + - * / ^ (integer
// powers, negative too: z^-1, (z-1)^(-2)), unary minus, parentheses, the variable z (or s),
// `T` (the sample period) and named parameters. Errors are InputError and name the column
// and what was expected, e.g. "column 7: expected ')' to close '(' at column 3".
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>

#include "hapstab/lti/tf.hpp"

namespace hapstab {

struct ParseOptions {
  /// 'z', 's', or 0 to infer from the expression (z if it names z, s if it names s,
  /// z when it names neither and T is given, else s).
  char variable = 0;
  /// Sample period; required when the expression uses `T` or the variable is z.
  rational T = 0;
  std::map<std::string, rational> parameters;
};

/// The names `text` refers to (parameters, T, the variable), found by the parser's own lexer:
/// "K*(1e-3 + B_2)" -> {B_2, K}. For resolving parameters in dependency order.
std::set<std::string> names_in(std::string_view text);

/// Parses `text` into an exact transfer function. Throws InputError on malformed input, an
/// unknown name, division by zero, or a missing/invalid T.
TransferFunction parse_tf(std::string_view text, const ParseOptions& options = {});

}  // namespace hapstab
