// hapstab/stability/loop_from_text.hpp -- the sampled loop of sampled_loop.hpp from its
// expressions: device P(s), wall H(z), operator Z_op(s), period T, delay n and parameters; with a
// gain named to maximise, H is split as H = H0 + K H1 (checked affine in K at three more values,
// and K must not appear in P or Z_op). The one builder of `hapstab stability` and of Python's
// hapstab.stability; `names` says how the caller calls each input in its messages.
#pragma once

#include <map>
#include <string>

#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::stability {

struct LoopText {
  std::string plant, H, op;  ///< op empty: no operator
  rational T = 0;            ///< > 0 (checked by the caller, who parsed it)
  int delay = 0;
  std::map<std::string, rational> params;
  std::string gain;  ///< the gain of H to maximise ("" for a plain decision)
};

/// The words of messages: the command line's options by default.
struct LoopNames {
  std::string plant = "--plant", H = "--H", op = "--operator", gain = "--max", delay = "--delay";
  std::string parameter_hint = "give parameters with --set NAME=VALUE", period = "--T";
};

/// The loop; with t.gain set, loop.H = H0 and loop.H_gain = H1. InputError naming the input.
Loop loop_from_text(const LoopText& t, const LoopNames& names = {});

}  // namespace hapstab::stability
