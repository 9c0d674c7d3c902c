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
/// Size of one exact intermediate result of an expression: the bits of all its coefficients,
/// numerator and denominator polynomials together (2^20 bits = 128 KB; a dense degree-100
/// model with 1000-bit coefficients is a tenth of it). The cost of one operation (a FLINT
/// product, quotient or gcd) is bounded by the size of its operands.
inline constexpr long expression_bits = 1L << 20;
/// Bits produced by all the operations of one expression together (2^24 = 16 x the above): an
/// expression cannot repeat a near-limit operation thousands of times.
inline constexpr long expansion_bits = 1L << 24;
/// Degree of the passivity bound's objective, max(deg N, deg D + n) (passivity/bound.hpp): the
/// exact path costs about degree^4 (0.8 s at 100, 4 s at 160, 18 s at 200 on one core).
inline constexpr long bound_degree = 200;
/// States, inputs or outputs of a state space read from a file (--ss).
inline constexpr int state_space_dim = 500;

}  // namespace hapstab::limits
