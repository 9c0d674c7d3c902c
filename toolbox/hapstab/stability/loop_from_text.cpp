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

/// H = H0 + K H1 from the expression of H: checked affine in K at three more values.
void split_gain(Loop& loop, const LoopText& t, std::map<std::string, rational> params, const LoopNames& names) {
  const std::string& K = t.gain;
  auto at = [&](const rational& k) {
    params[K] = k;
    return parse_input(t.H, names.H, 'z', t.T, params, names);
  };
  const TransferFunction H0 = at(0), H1 = tf((at(1).H - H0.H).num(), (at(1).H - H0.H).den(), t.T);
  if (H1.H.is_zero()) throw InputError(names.gain + " " + K + ": " + names.H + " does not depend on " + K);
  for (const rational& k : {rational(2), rational(1, 3), rational(-7, 2)}) {
    const RationalFunction<rational> affine = H0.H + RationalFunction<rational>(k) * H1.H;
    if (!same(at(k), tf(affine.num(), affine.den(), t.T)))
      throw InputError(names.gain + " " + K + ": " + names.H + " must be affine in " + K + " (H = H0 + " + K +
                       " H1), e.g. a stiffness");
  }
  loop.H = H0;
  loop.H_gain = H1;
}

}  // namespace

Loop loop_from_text(const LoopText& t, const LoopNames& names) {
  if (t.delay < 0 || t.delay > limits::model_degree)
    throw InputError(names.delay + " must be in [0, " + std::to_string(limits::model_degree) + "], got " +
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
