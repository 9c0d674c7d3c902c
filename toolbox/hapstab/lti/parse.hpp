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
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hapstab/lti/tf.hpp"

namespace hapstab {

/// Parenthesised groups already parsed, for parses that repeat one long subexpression (a
/// scene's N x N environment writes the same "(M*s^2 + (B+B1+...+BN)*s + k+k1+...+kN)" in every
/// entry: parsing it N^2 times was a quarter of `multidof analyze` at N = 128). A group of at
/// least `kMinTokens` tokens is taken from the memo only when every parameter it names has the
/// value it was parsed with (and T too, when it names T), in the same variable, and when the
/// parse's limits (nesting depth, bits expanded so far) admit it as they did: so a parse with a
/// memo gives the same result, and the same error, as one without. Bounded: groups stop being
/// added once their text and coefficients fill `kBudgetBytes`.
class ParseMemo {
 public:
  static constexpr size_t kMinTokens = 16;
  static constexpr size_t kBudgetBytes = size_t(32) << 20;
  struct Group {
    QRatFun value;
    std::vector<std::pair<std::string, rational>> parameters;  ///< the parameters it names, as parsed
    bool used_T = false;
    rational T;         ///< when used_T
    long bits = 0;      ///< the bits its parse expanded (the parser's expansion limit)
    int depth = 0;      ///< the nesting depth it reaches, its own parentheses included
  };
  /// The group stored under `key` (the variable, then the group's text), or nullptr.
  const Group* find(const std::string& key) const;
  void add(std::string key, Group g);

 private:
  std::unordered_map<std::string, Group> groups_;
  size_t used_bytes_ = 0;
};

/// What parse_tf does with a pole the expression writes and an operation cancels, on or outside
/// the stable region ((z - 2)/(z - 2); realised as written, a hidden mode of H).
enum class HiddenPoles {
  refuse,           ///< InputError naming the operation: a loop around H as written is NOT stable
  allow_marginal,   ///< (z only) kept out of H while H as written -- its denominator times the
                    ///< cancelled factors -- is marginally stable (roots in |z| <= 1, those on the
                    ///< circle simple): b* sees H's frequency response only, and (45) allows such H
  allow_integrator, ///< (s only) the factor s cancelled once and nothing else: a checker's plant
                    ///< "(G)/s" from a scene device's velocity G(s), whose position offset is a
                    ///< conserved quantity (hapstab's scene loop reads the device so)
};

struct ParseOptions {
  /// 'z', 's', or 0 to infer from the expression (z if it names z, s if it names s,
  /// z when it names neither and T is given, else s).
  char variable = 0;
  /// Sample period; required when the expression uses `T` or the variable is z.
  rational T = 0;
  std::map<std::string, rational> parameters;
  /// Optional (not owned): more parameters, looked up after `parameters` and used exactly as they
  /// are, for a caller with many parameters and many expressions (a scene: copying the ones each
  /// expression names cost more than parsing it). Their names must be identifiers; a map that
  /// holds T, s or z is copied as `parameters` would hold the names the expression uses, so that
  /// its checks are those of `parameters`.
  const std::map<std::string, rational>* shared_parameters = nullptr;
  /// Optional (not owned): see ParseMemo.
  ParseMemo* memo = nullptr;
  /// How the caller takes parameters and the sample period, for the messages of an unknown name
  /// and of a missing T: the command line's words by default; the Python module says
  /// "pass params={'K': ...}" ({} stands for the unknown name) and "T=...".
  HiddenPoles hidden_poles = HiddenPoles::refuse;
  std::string parameter_hint = "give parameters with --set NAME=VALUE";
  std::string period_hint = "--T";
};

/// The names `text` refers to (parameters, T, the variable), found by the parser's own lexer:
/// "K*(1e-3 + B_2)" -> {B_2, K}. For resolving parameters in dependency order.
std::set<std::string> names_in(std::string_view text);

/// Parses `text` into an exact transfer function, in lowest terms. Throws InputError on malformed
/// input, an unknown name, division by zero, a missing/invalid T, or an operation that cancels a
/// pole the expression writes on or outside the stable region (|z| >= 1, Re s >= 0; see
/// HiddenPoles): realised as written, (z - 2)/(z - 2) keeps the mode z = 2, and hapstab does not
/// reduce it away silently. Cancelled poles inside the region (hidden stable modes, which change
/// no verdict) are dropped.
TransferFunction parse_tf(std::string_view text, const ParseOptions& options = {});

/// `text` as H = H0 + K H1 in its parameter `name` (a gain to maximise: `stability --max`, `bound
/// --max`), PROVEN: with H = P(K, z)/Q(K, z), the numerator of H - H0 - K H1 is a polynomial in K
/// of degree at most D = max(deg_K P, deg_K Q + 1), bounded from the parse (degree_bound); it is
/// identically 0 when it vanishes at D + 1 distinct K: parsed at K = 0 and 1 (giving H0, H1) and
/// checked equal to H0 + k H1 at D - 1 more values (values where the expression divides by zero
/// or cancels a pole on or outside the circle are skipped: there are finitely many). The value of `name` in options.parameters is ignored.
/// InputError when `text` does not depend on `name`, is not affine in it, or its degree bound in
/// `name` exceeds 64 (refused by name: not proven affine).
struct AffineSplit {
  TransferFunction H0, H1;
};
AffineSplit split_affine(std::string_view text, const ParseOptions& options, const std::string& name);

/// An expression parsed once for many values of some of its parameters (`varying`), e.g. b* of
/// one wall over 10^5 stiffnesses (Python's hapstab.bound with params={"K": array}): the text is
/// read once, and every subexpression that names none of the varying parameters is computed
/// once; at(values) computes the rest. at(values) is parse_tf(text, options with `values`), the
/// same transfer function or the same InputError: it replays the parser's own operations and
/// checks in the parser's order, and asks parse_tf itself whenever the replay raises.
/// Construction raises what every value would (a malformed expression, an unknown name). at() is
/// const and may run on several threads at once.
class ParsedExpression {
 public:
  ParsedExpression(std::string_view text, const ParseOptions& options, std::set<std::string> varying);
  ~ParsedExpression();
  /// The transfer function at `values` (one value for each varying parameter).
  TransferFunction at(const std::map<std::string, rational>& values) const;
  /// The operations left for at() (0: the expression does not depend on the varying parameters).
  size_t operations() const;
  /// Upper bounds of the degrees of the numerator and the denominator of the expression as a
  /// rational function of the varying parameters (jointly), read off the operations: a name is
  /// (1, 0), a known value (0, 0); a + b (max(na + db, nb + da), da + db); a b (na + nb, da + db);
  /// a / b (na + db, da + nb); a^k (k na, k da), a^-k (k da, k na). Saturates at 10^6.
  std::pair<long, long> degree_bound() const;
  struct Tape;

 private:
  struct State;
  std::shared_ptr<const State> state_;
};

}  // namespace hapstab
