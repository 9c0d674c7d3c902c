// cli/tf_options.cpp -- see tf_options.hpp.
#include "cli/tf_options.hpp"

#include "cli/command.hpp"
#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::cli {

void add_tf_options(CLI::App& app, TfOptions& o, const TfRules& rules, const std::string& h_help) {
  app.add_option("--H", o.H, h_help);
  app.add_option("--T", o.T,
                 rules.period_required ? "sample period T > 0 (exact: 0.001 or 1/1000)"
                                       : "sample period T > 0 (exact; only if the expression names T)");
  app.add_option("--set", o.sets, "parameter NAME=VALUE (repeatable)");
  if (rules.with_delay) app.add_option("--delay", o.delay, "integer delay n >= 0: z^-n")->capture_default_str();
}

TransferFunction parse_tf_options(const TfOptions& o, const TfRules& rules) {
  if (o.H.empty()) throw InputError("--H is required (the virtual environment H(z))");
  ParseOptions po;
  po.variable = 'z';
  po.T = 1;
  if (!o.T.empty()) {
    po.T = option_rational(o.T, "--T");
    if (po.T <= 0) throw InputError("--T: the sample period must be > 0, got '" + o.T + "'");
  } else if (rules.period_required) {
    throw InputError("--T is required (the sample period)");
  }
  po.parameters = parse_sets(o.sets);
  if (rules.with_delay && o.delay < 0) throw InputError("--delay must be >= 0 (got " + std::to_string(o.delay) + ")");
  TransferFunction H;
  try {
    H = parse_tf(o.H, po);
  } catch (const InputError& e) {
    throw InputError(std::string("--H: ") + e.what());
  }
  if (!H.is_discrete()) throw InputError("--H: expected a transfer function in z");
  if (H.den().is_zero()) throw InputError("--H has a zero denominator");
  if (rules.causal && !H.is_proper())
    throw InputError("--H: H(z) = " + H.to_string() + " is not causal (deg num > deg den)");
  return H;
}

}  // namespace hapstab::cli
