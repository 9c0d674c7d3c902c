// cli/tf_options.cpp -- see tf_options.hpp.
#include "cli/tf_options.hpp"

#include "cli/command.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/poly/stability.hpp"

namespace hapstab::cli {

void add_tf_options(CLI::App& app, TfOptions& o, const TfRules& rules, const std::string& h_help) {
  app.add_option("--H", o.H, h_help);
  app.add_option("--num", o.num, "numerator coefficients, descending powers of z: \"1 -0.5\" or \"[1, -1/2]\" (instead of --H)");
  app.add_option("--den", o.den, "denominator coefficients, descending powers of z (with --num)");
  app.add_option("--mat", o.mat, "MATLAB .mat file (save -v7): FILE (variables num, den), FILE:VAR or FILE:NUM,DEN (instead of --H)");
  app.add_option("--T", o.T,
                 rules.period_required ? "sample period T > 0 (exact: 0.001 or 1/1000)"
                                       : "sample period T > 0 (exact; only if the expression names T)");
  app.add_option("--set", o.sets, "parameter NAME=VALUE of --H (repeatable)");
  if (rules.with_delay) app.add_option("--delay", o.delay, "integer delay n >= 0: z^-n")->capture_default_str();
}

bool has_tf(const TfOptions& o) { return !o.H.empty() || !o.num.empty() || !o.den.empty() || !o.mat.empty(); }

rational parse_period(const TfOptions& o, const TfRules& rules) {
  if (o.T.empty()) {
    if (rules.period_required) throw InputError("--T is required (the sample period)");
    return 1;
  }
  const rational T = option_rational(o.T, "--T");
  if (T <= 0) throw InputError("--T: the sample period must be > 0, got '" + o.T + "'");
  return T;
}

std::vector<rational> parse_coefficients(const std::string& text, const std::string& option) {
  if (text.size() > limits::expression_chars)
    throw InputError(option + ": " + std::to_string(text.size()) + " characters, more than the limit of " +
                     std::to_string(limits::expression_chars));
  std::string s = text;
  const auto first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
  if (first != std::string::npos && s[first] == '[') {  // MATLAB's brackets, both or none
    if (s[last] != ']') throw InputError(option + ": '[' without a closing ']'");
    s = s.substr(first + 1, last - first - 1);
  }
  std::vector<rational> c;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ' || s[i] == ',' || s[i] == '\t') {
      ++i;
      continue;
    }
    const std::size_t j = s.find_first_of(" ,\t", i);
    const std::string word = s.substr(i, j == std::string::npos ? std::string::npos : j - i);
    if (c.size() > static_cast<std::size_t>(limits::model_degree))
      throw InputError(option + ": more than " + std::to_string(limits::model_degree + 1) + " coefficients (degree limit " +
                       std::to_string(limits::model_degree) + ")");
    c.push_back(parse_rational(word, option + ": coefficient " + std::to_string(c.size() + 1)));
    i = j == std::string::npos ? s.size() : j;
  }
  if (c.empty()) throw InputError(option + ": no coefficients (expected e.g. \"1 -0.5\", descending powers of z)");
  return c;
}

namespace {
// InputError when H in lowest terms lost a pole of `written` (its denominator as written) on or
// outside the stable region: realised as written, a hidden mode (lti/tf.hpp).
void refuse_unstable_cancellation(const TransferFunction& H, const Polynomial<rational>& written, const std::string& name,
                                  const std::string& how, HiddenPoles hidden_poles) {
  const Polynomial<rational> lost = unstable_cancelled_factor(written, H.den(), H.domain);
  if (!lost.is_zero() && (hidden_poles == HiddenPoles::refuse || !marginally_stable(written)))
    throw InputError(name + ": " + how + " the factor " + to_string(lost, H.variable()) + ", a pole " +
                     (H.is_discrete() ? "on or outside the unit circle" : "in Re s >= 0") +
                     " that H in lowest terms loses: realised as written it stays a hidden mode, and hapstab does not "
                     "reduce it away (give H without it if the reduced model is meant)");
}
}  // namespace

TransferFunction tf_from_coefficients(const std::vector<rational>& num, const std::vector<rational>& den,
                                      const rational& T, const std::string& num_name, const std::string& den_name,
                                      HiddenPoles hidden_poles) {
  const auto too_long = [](const std::vector<rational>& v) { return v.size() > static_cast<std::size_t>(limits::model_degree) + 1; };
  if (too_long(num) || too_long(den))
    throw InputError((too_long(num) ? num_name : den_name) + ": more than " + std::to_string(limits::model_degree + 1) +
                     " coefficients (degree limit " + std::to_string(limits::model_degree) + ")");
  if (den.empty() || num.empty()) throw InputError((num.empty() ? num_name : den_name) + ": no coefficients");
  if (den.front() == 0)
    throw InputError(den_name + ": the leading coefficient (of z^" + std::to_string(den.size() - 1) +
                     ") is 0; drop it (descending powers of z)");
  // descending -> ascending; the numerator's leading zeros (tfdata pads it) vanish in trim()
  Polynomial<rational> written(std::vector<rational>(den.rbegin(), den.rend()));
  TransferFunction H = tf(Polynomial<rational>(std::vector<rational>(num.rbegin(), num.rend())), written, T);
  if (!H.num().is_zero())  // H = 0 (a zero gain) has no modes
    refuse_unstable_cancellation(H, written, num_name + "/" + den_name, "num and den share", hidden_poles);
  return H;
}

namespace {

TransferFunction parse_expression(const TfOptions& o, const rational& T, HiddenPoles hidden_poles) {
  refuse_unnamed_sets(o.sets, {{"--H", o.H}});
  ParseOptions po;
  po.hidden_poles = hidden_poles;
  po.variable = 'z';
  po.T = T;
  po.parameters = parse_sets(o.sets);
  try {
    return parse_tf(o.H, po);
  } catch (const InputError& e) {
    throw InputError(std::string("--H: ") + e.what());
  }
}

// A SISO state space of at most this many states becomes H = C (zI - A)^-1 B + D exactly (the
// exact characteristic polynomial of a matrix of 53-bit entries grows fast with its size).
constexpr int max_ss2tf_states = 50;

TransferFunction from_mat(const TfOptions& o, const rational& T, HiddenPoles hidden_poles) {
  const MatModel m = read_mat_model(o.mat, "--mat");
  if (m.tf) return tf_from_coefficients(m.tf->first, m.tf->second, T, m.where + " num", m.where + " den", hidden_poles);
  StateSpace<double> s = *m.ss;
  s.T = T;
  s.validate(m.where);
  if (s.inputs() != 1 || s.outputs() != 1 || s.states() > max_ss2tf_states)
    throw InputError(m.where + ": a state space with " + std::to_string(s.inputs()) + " input(s), " +
                     std::to_string(s.outputs()) + " output(s) and " + std::to_string(s.states()) +
                     " states; this command takes a SISO H (num, den, or A, B, C, D of at most " +
                     std::to_string(max_ss2tf_states) + " states)");
  auto exact = [](const Mat<double>& M) {
    Mat<rational> Q(M.rows(), M.cols());
    for (Eigen::Index i = 0; i < M.rows(); ++i)
      for (Eigen::Index j = 0; j < M.cols(); ++j) Q(i, j) = exact_rational(M(i, j));
    return Q;
  };
  const StateSpace<rational> q{exact(s.A), exact(s.B), exact(s.C), exact(s.D), T};
  TransferFunction H = ss2tf(q)(0, 0);
  refuse_unstable_cancellation(H, charpoly(q.A), m.where, "C (zI - A)^-1 B + D cancels", hidden_poles);
  return H;
}

}  // namespace

TransferFunction parse_tf_options(const TfOptions& o, const TfRules& rules) {
  const bool expr = !o.H.empty(), coeffs = !o.num.empty() || !o.den.empty(), mat = !o.mat.empty();
  if (int(expr) + int(coeffs) + int(mat) != 1)
    throw InputError(int(expr) + int(coeffs) + int(mat) == 0
                         ? "--H is required (the virtual environment H(z)), or --num/--den, or --mat FILE:VAR"
                         : "give only one of --H, --num/--den and --mat");
  if (coeffs && (o.num.empty() || o.den.empty())) throw InputError(o.num.empty() ? "--den needs --num" : "--num needs --den");
  if (!expr && !o.sets.empty()) throw InputError("--set names parameters of --H; --num/--den and --mat hold numbers");
  const rational T = parse_period(o, rules);
  if (rules.with_delay && o.delay < 0) throw InputError("--delay must be >= 0 (got " + std::to_string(o.delay) + ")");
  const TransferFunction H =
      expr ? parse_expression(o, T, rules.hidden_poles)
           : mat ? from_mat(o, T, rules.hidden_poles)
                 : tf_from_coefficients(parse_coefficients(o.num, "--num"), parse_coefficients(o.den, "--den"), T, "--num",
                                        "--den", rules.hidden_poles);
  const std::string name = expr ? "--H" : mat ? "--mat" : "--num/--den";
  if (!H.is_discrete()) throw InputError(name + ": expected a transfer function in z");
  if (H.den().is_zero()) throw InputError(name + " has a zero denominator");
  if (rules.causal && !H.is_proper())
    throw InputError(name + ": H(z) = " + H.to_string() + " is not causal (deg num > deg den)");
  return H;
}

AffineSplit parse_tf_affine(const TfOptions& o, const TfRules& rules, const std::string& name, const std::string& option) {
  const std::string what = option + " " + name;
  if (o.H.empty()) throw InputError(what + ": needs H as an expression in " + name + " (--H), not --num/--den or --mat");
  if (parse_sets(o.sets).count(name)) throw InputError(what + ": " + name + " is the parameter maximised; do not --set it");
  refuse_unnamed_sets(o.sets, {{"--H", o.H}});
  const rational T = parse_period(o, rules);
  if (rules.with_delay && o.delay < 0) throw InputError("--delay must be >= 0 (got " + std::to_string(o.delay) + ")");
  ParseOptions po;
  po.variable = 'z';
  po.T = T;
  po.parameters = parse_sets(o.sets);
  po.hidden_poles = rules.hidden_poles;
  AffineSplit s;
  try {
    s = split_affine(o.H, po, name);
  } catch (const InputError& e) {
    throw InputError(what + ": --H: " + e.what());
  }
  for (const TransferFunction* h : {&s.H0, &s.H1})
    if (!h->is_discrete()) throw InputError("--H: expected a transfer function in z");
  return s;
}

}  // namespace hapstab::cli
