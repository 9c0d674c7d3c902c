// hapstab/stability/loop_from_text.cpp -- see loop_from_text.hpp.
#include "hapstab/stability/loop_from_text.hpp"

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::stability {
namespace {

TransferFunction parse_input(const std::string& text, const std::string& name, char variable, const rational& T,
                             const std::map<std::string, rational>& params, const LoopNames& names) {
  if (text.empty()) throw InputError(name + " is required");
  ParseOptions po;
  po.variable = variable;
  po.T = T;
  po.parameters = params;
  po.parameter_hint = names.parameter_hint;
  po.period_hint = names.period;
  try {
    return parse_tf(text, po);
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.what());
  }
}

bool same(const TransferFunction& a, const TransferFunction& b) { return a.num() == b.num() && a.den() == b.den(); }

/// H = H0 + K H1 from the expression of H (lti/parse.hpp: split_affine, the one affine check).
void split_gain(Loop& loop, const LoopText& t, const std::map<std::string, rational>& params, const LoopNames& names) {
  if (t.H.empty()) throw InputError(names.H + " is required");
  ParseOptions po;
  po.variable = 'z';
  po.T = t.T;
  po.parameters = params;
  po.parameter_hint = names.parameter_hint;
  po.period_hint = names.period;
  try {
    const AffineSplit h = split_affine(t.H, po, t.gain);
    loop.H = h.H0;
    loop.H_gain = h.H1;
  } catch (const InputError& e) {
    throw InputError(names.gain + " " + t.gain + ": " + names.H + ": " + e.what());
  }
}

}  // namespace

Loop loop_from_text(const LoopText& t, const LoopNames& names) {
  if (t.delay < 0 || t.delay > limits::criterion_delay)
    throw InputError(names.delay + " must be in [0, " + std::to_string(limits::criterion_delay) + "] samples, got " +
                     std::to_string(t.delay));
  Loop loop;
  loop.T = t.T;
  loop.delay = t.delay;
  auto device_at = [&](const std::optional<rational>& k) {
    std::map<std::string, rational> p = t.params;
    if (k) p[t.gain] = *k;
    return std::make_pair(parse_input(t.plant, names.plant, 's', t.T, p, names),
                          t.op.empty() ? std::optional<TransferFunction>()
                                       : parse_input(t.op, names.op, 's', t.T, p, names));
  };
  if (t.gain.empty()) {
    std::tie(loop.plant, loop.operator_impedance) = device_at(std::nullopt);
    loop.H = parse_input(t.H, names.H, 'z', t.T, t.params, names);
    return loop;
  }
  const auto a = device_at(rational(1)), b = device_at(rational(2));
  if (!same(a.first, b.first) || (a.second && !same(*a.second, *b.second)))
    throw InputError(names.gain + " " + t.gain + ": only a gain of " + names.H + " can be maximised, but " + t.gain +
                     " appears in " + names.plant + " or " + names.op);
  std::tie(loop.plant, loop.operator_impedance) = a;
  split_gain(loop, t, t.params, names);
  return loop;
}

}  // namespace hapstab::stability
