// hapstab/numeric/limits.hpp -- the resource limits on input (docs/security.md): each is
// checked before the work it bounds starts, and an input beyond it is an InputError (exit 2)
// that names the limit. They are far above any physical model (a 1 s delay at T = 1 ms is a
// degree-1000 polynomial) and far below what would exhaust memory or the stack.
#pragma once

#include <cstddef>

namespace hapstab::limits {

/// Characters of one expression (--H, a scene's tf, a --batch line).
inline constexpr std::size_t expression_chars = 100000;
/// Nested parentheses in one expression (each level is a few stack frames of the parser).
inline constexpr int nesting_depth = 200;
/// Degree of the numerator or denominator of a parsed transfer function.
inline constexpr int degree = 10000;
/// Bits of one exact coefficient (numerator + denominator): about 315,000 decimal digits.
inline constexpr long coefficient_bits = 1L << 20;
/// Degree of the passivity bound's objective, max(deg N, deg D + n) (passivity/bound.hpp): the
/// exact path costs about degree^4 (0.8 s at 100, 4 s at 160, 18 s at 200 on one core).
inline constexpr long bound_degree = 200;
/// States, inputs or outputs of a state space read from a file (--ss).
inline constexpr int state_space_dim = 500;

}  // namespace hapstab::limits
