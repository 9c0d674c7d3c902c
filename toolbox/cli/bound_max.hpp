// cli/bound_max.hpp -- `hapstab bound --max NAME --damping b`: the largest NAME (a parameter of
// --H, affine in it) that the device's damping b keeps passive (passivity::bound_max in
// passivity/max_gain.hpp: K_max, the closed form of Secs. VI-VII that applies and, with --explain,
// b* itself at the ends of the answer's enclosure, b* = b there), printed as text or JSON.
// cmd_bound.cpp parses the options and calls these.
// JSON keys: name, max ("inf"; "0" when not passive at NAME = 0), digits_certified (max_digits:
// its deprecated old name), enclosure [lo, hi],
// status, exact (p/q when rational), damping, b_at_zero {bound, enclosure, status}, omega [lo, hi]
// (where b* = b at the answer) or null, where, closed_form (name or null), closed_form_equation,
// closed_form_formula, closed_form_value, closed_form_tight, closed_form_agrees, method, path,
// note, digits; check {holds, bound_at_lo, bound_at_hi} with --explain.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/passivity/max_gain.hpp"

namespace hapstab::cli {

nlohmann::json bound_max_json(const passivity::BoundMax& r, int digits);
void print_bound_max(const passivity::BoundMax& r, int digits);
/// 0 when K_max > 0 (finite or infinite), 1 when K_max = 0 (not passive at NAME = 0, or for no NAME > 0).
int bound_max_exit(const passivity::BoundMax& r);

}  // namespace hapstab::cli
