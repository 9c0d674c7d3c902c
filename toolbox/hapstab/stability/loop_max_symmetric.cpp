// hapstab/stability/loop_max_symmetric.cpp -- see loop_max_symmetric.hpp.
#include "hapstab/stability/loop_max_symmetric.hpp"

#include <algorithm>
#include <map>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/stability/symmetry.hpp"

namespace hapstab::stability {

namespace {

// The whole loop split at p: the same classes as at the reference and no isolated state, else an
// InputError naming what moved (the header's argument needs both).
detail::LoopSymmetry split_at(const LoopAt& at, const rational& p, const std::vector<std::vector<int>>& classes, const std::string& name) {
  std::string why;
  auto s = detail::split_by_symmetry(at(p), why);
  if (!s) throw InputError("--max " + name + ": at " + name + " = " + p.str() + " the DOFs no longer split (" + why + ")");
  if (s->classes != classes)
    throw InputError("--max " + name + ": at " + name + " = " + p.str() + " the classes of identical DOFs are not those at the scene's value");
  if (!s->isolated.empty())
    throw InputError("--max " + name + ": the environment has " + std::to_string(s->isolated.size()) +
                     " state(s) no input reaches, whose dynamics " + name + " could move: beyond the split supremum");
  return *s;
}

// The block's crossing mode on the whole's DOFs: the fixed space's mode is its class's on every DOF of the
// class; a zero-sum block's is e_f - e_s on its class's first two DOFs (any zero-sum vector over the class
// carries it: that one is shown).
std::vector<double> lifted_mode(const LoopMaxSplit& s, const LoopMaxBlock& b, size_t dofs) {
  std::vector<double> mode(dofs, 0.0);
  if (b.max.mode.empty()) return mode;
  if (b.cls < 0) {
    for (size_t a = 0; a < s.classes.size() && a < b.max.mode.size(); ++a)
      for (int i : s.classes[a]) mode[static_cast<size_t>(i)] = b.max.mode[a];
  } else {
    const auto& c = s.classes[static_cast<size_t>(b.cls)];
    mode[static_cast<size_t>(c[0])] = mode[static_cast<size_t>(c[1])] = 1.0;
  }
  return mode;
}

// A proven-stable interval rounded inward ("every p in it"), or an enclosure rounded outward.
std::string interval(const rational& lo, const rational& hi, bool open) {
  return std::string(open ? "(" : "[") + decimal_outward(lo, 17, +1) + ", " + decimal_outward(hi, 17, -1) + "]";
}
std::string enclosure(const rational& lo, const rational& hi) { return "[" + decimal_outward(lo, 17, -1) + ", " + decimal_outward(hi, 17, +1) + "]"; }

// The header's combination of the blocks' suprema.
void combine(LoopMaxSplit& s, const std::string& name, size_t dofs) {
  LoopMax& w = s.whole;
  const std::string head = "by the permutations of identical DOFs, " + s.group + " (proven exactly on the realisations as written at " +
                           "every value evaluated, affine in " + name + "), the closed loop's spectrum is that of " +
                           std::to_string(s.blocks.size()) + " small loops (stability/loop_max_symmetric.hpp)";
  for (size_t k = 0; k < s.blocks.size(); ++k)
    if (s.blocks[k].max.outcome == Outcome::fails) {
      s.deciding = static_cast<int>(k);
      const LoopMax& b = s.blocks[k].max;
      w.outcome = Outcome::fails;
      w.status = b.status;
      w.T = b.T;
      w.first_order_to = b.first_order_to;  // > 0: that block NOT stable on (0, first_order_to] by the first-order mirror
      w.note = head + "; " + s.blocks[k].label + ": " + b.note;
      return;
    }
  for (size_t k = 0; k < s.blocks.size(); ++k)
    if (s.blocks[k].max.outcome != Outcome::holds) {
      s.deciding = static_cast<int>(k);
      w.outcome = Outcome::undecided;
      w.status = Status::failed;
      w.note = head + "; " + s.blocks[k].label + " is undecided: " + s.blocks[k].max.note;
      // what every block proves at once: [max stable_from, min stable_to], where each has one
      rational from = 0, to = -1;
      bool open = false;
      for (const auto& b : s.blocks) {
        if (b.max.stable_to <= b.max.stable_from) return;
        from = std::max(from, b.max.stable_from);
        to = to < 0 ? b.max.stable_to : std::min(to, b.max.stable_to);
        open = open || (b.max.open_at_zero && b.max.stable_from == 0);
      }
      if (to > from) w.stable_from = from, w.stable_to = to, w.open_at_zero = open && from == 0, w.status = Status::certified;
      return;
    }
  size_t d = 0;
  for (size_t k = 1; k < s.blocks.size(); ++k)
    if (s.blocks[k].max.sup.hi < s.blocks[d].max.sup.hi) d = k;
  s.deciding = static_cast<int>(d);
  const LoopMax& b = s.blocks[d].max;
  w = b;
  w.outcome = Outcome::holds;
  w.status = Status::certified;
  w.states = w.fixed_modes = w.cover_intervals = 0;
  w.open_at_zero = false;
  for (const auto& x : s.blocks) {
    w.sup.lo = std::min(w.sup.lo, x.max.sup.lo);
    w.states += x.max.states;
    w.fixed_modes += x.max.fixed_modes;
    w.cover_intervals += x.max.cover_intervals;
    w.open_at_zero = w.open_at_zero || x.max.open_at_zero;
    w.precision_bits = std::max(w.precision_bits, x.max.precision_bits);
  }
  w.stable_from = 0;
  w.stable_to = w.sup.lo;
  w.gap = w.crossing.lo > 0 ? static_cast<double>((w.crossing.lo - w.stable_to) / w.crossing.lo) : 0.0;
  // stable_at: the deciding block's decide_loop point where every other block's cover reaches it, else the
  // covers' common end (every block stable there by its cover); unstable_at: one block NOT stable suffices
  if (!w.stable_at || *w.stable_at > w.stable_to) {
    w.stable_at = w.stable_to;
    w.confirmed_by = "stable at " + decimal_outward(w.stable_to, 17, -1) + " by every block's cover; " +
                     (b.confirmed_by.empty() ? "NOT stable at the unstable point by " + s.blocks[d].label + "'s decide_loop" : b.confirmed_by);
  }
  w.mode = lifted_mode(s, s.blocks[d], dofs);
  std::string each;
  for (size_t k = 0; k < s.blocks.size(); ++k) {
    const auto& x = s.blocks[k];
    each += " block " + std::to_string(k + 1) + ", " + x.label + ": sup in " + enclosure(x.max.sup.lo, x.max.sup.hi) + " (" + std::to_string(x.max.states) + " states, " +
            std::to_string(x.max.cover_intervals) + " cover steps);";
  }
  each.pop_back();
  w.note = head + "; sup " + name + " is the least of theirs (block " + std::to_string(d + 1) + "); every " + name + " in " +
           interval(w.stable_from, w.stable_to, w.open_at_zero) + " is proven stable by every block:" + each;
}

}  // namespace

bool split_pays(const sim::LoopSpec& loop) {
  if (loop.dofs() > kSplitMaxDofs) return true;
  std::string why;
  const auto s = detail::split_by_symmetry(loop, why);
  return s && std::any_of(s->classes.begin(), s->classes.end(), [](const auto& c) { return c.size() >= 3; });
}

namespace {

// The split at the reference, checked again at 2 reference (classes, no isolated state); nullopt with why_not.
std::optional<detail::LoopSymmetry> reference_split(const LoopAt& at, const rational& reference, const std::string& name, std::string& why_not) {
  auto s0 = detail::split_by_symmetry(at(reference), why_not);
  if (!s0) {
    if (why_not.empty()) why_not = "no two DOFs are alike";
    return std::nullopt;
  }
  if (!s0->isolated.empty()) {
    why_not = "the environment has states no input reaches";
    return std::nullopt;
  }
  try {
    split_at(at, 2 * reference, s0->classes, name);
  } catch (const InputError& e) {
    why_not = e.what();
    return std::nullopt;
  }
  return s0;
}

// Block k's loop at p (k < 0: the fixed space; else standard[k]), the whole split once per p (memo).
struct BlockLoops {
  const LoopAt& at;
  const std::vector<std::vector<int>>& classes;
  const std::string& name;
  std::map<rational, detail::LoopSymmetry> memo;
  LoopAt block(int k) {
    return [this, k](const rational& p) {
      auto it = memo.find(p);
      if (it == memo.end()) {
        if (memo.size() > 64) memo.clear();
        it = memo.emplace(p, split_at(at, p, classes, name)).first;
      }
      return k < 0 ? it->second.fixed : it->second.standard[static_cast<size_t>(k)];
    };
  }
};

}  // namespace

std::optional<std::string> split_not_affine(const LoopAt& at, const rational& reference, const std::string& name, long points) {
  std::string why;
  const auto s0 = reference_split(at, reference, name, why);
  if (!s0) return std::nullopt;
  BlockLoops loops{at, s0->classes, name, {}};
  try {
    for (int k = -1; k < static_cast<int>(s0->standard.size()); ++k) loop_family(loops.block(k), reference, name, points);
  } catch (const ParameterAbsent&) {
    // a block the parameter does not reach (identical DOFs where p is not, e.g. the scene's p = 0 making a wall like
    // its neighbours'): no split, the whole loop answers (its supremum is not a least of the blocks' here)
    return std::nullopt;
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::string();
}

std::optional<LoopMaxSplit> max_parameter_by_symmetry(const LoopAt& at, const rational& reference, const std::string& name, long points,
                                                      int digits, std::string& why_not) {
  const auto s0 = reference_split(at, reference, name, why_not);
  if (!s0) return std::nullopt;
  LoopMaxSplit out;
  out.classes = s0->classes;
  out.group = s0->group();
  BlockLoops loops{at, out.classes, name, {}};
  out.blocks.push_back({"the loop of " + std::to_string(out.classes.size()) + " DOF" + (out.classes.size() > 1 ? "s" : "") +
                            " on the space fixed by the group",
                        -1, max_parameter(loops.block(-1), reference, name, points, digits)});
  for (size_t k = 0; k < s0->standard.size(); ++k) {
    const int a = s0->standard_class[k];
    const auto& c = out.classes[static_cast<size_t>(a)];
    out.blocks.push_back({"the one-DOF loop of class " + std::to_string(a + 1) + " (DOFs " + std::to_string(c.front() + 1) + ", " +
                              std::to_string(c[1] + 1) + (c.size() > 2 ? ", ..." : "") + "), multiplicity " + std::to_string(c.size() - 1),
                          a, max_parameter(loops.block(static_cast<int>(k)), reference, name, points, digits)});
  }
  size_t dofs = 0;
  for (const auto& c : out.classes) dofs += c.size();
  combine(out, name, dofs);
  return out;
}

}  // namespace hapstab::stability
