// hapstab/numeric/limits.hpp -- the resource limits on input (docs/security.md): each is
// checked before the work it bounds starts, and an input beyond it is an InputError (exit 2)
// that names the limit. They are far above any physical model (a wall or filter of degree 200;
// a delay of n samples is given apart, --delay or [delay]) and far below what would exhaust
// memory, time or the stack.
#pragma once

#include <cstddef>

namespace hapstab::limits {

/// Characters of one expression (--H, a scene's tf, a --batch line).
inline constexpr std::size_t expression_chars = 100000;
/// Nested parentheses in one expression (each level is a few stack frames of the parser).
inline constexpr int nesting_depth = 200;
/// Degree of the numerator or denominator of an intermediate result inside one expression
/// ("(z^100-1)^50/z^5000" is sparse and cheap; the result's degree is limited by model_degree).
inline constexpr int intermediate_degree = 10000;
/// Degree of a model, one limit for every command: the numerator and denominator of a parsed
/// expression (--H, a scene's tf; checked by the parser), of --num/--den and of a .mat model,
/// and the polynomials the exact paths expand from them -- the passivity bound's exact objective
/// max(deg N, deg D + n) (passivity/bound.hpp; it costs about degree^4: 0.8 s at 100, 4 s at 160,
/// 18 s at 200 on one core) and the stability test's exact characteristic polynomial (delay +
/// wall + device). Beyond it the 1-DOF criteria take their long-delay paths, which never expand
/// z^-n (criterion_delay). `wedge --H "1/(2*z^9999 + 1)"` reached 5.7 GB before this applied to
/// every command.
inline constexpr int model_degree = 200;
/// Delay n (+ t_d/T) in samples that the 1-DOF criteria take (`bound`, `stability`, a scene's
/// [delay] there): their long-delay paths never expand z^-n and their work grows like n --
/// about 4n + 64 evaluations of a low-order formula in ball arithmetic (passivity/bound.hpp,
/// stability/sampled_loop.hpp): measured at 10^5 samples 3 s and 22 MB for `bound`, 10 s and
/// 26 MB for `stability --max` (its queue of arcs grows like n), so 10^6 is about half a minute
/// and under two minutes, a few hundred MB at most.
inline constexpr long criterion_delay = 1000000;
/// Size of one exact intermediate result of an expression: the bits of all its coefficients,
/// numerator and denominator polynomials together (2^20 bits = 128 KB; a dense degree-100
/// model with 1000-bit coefficients is a tenth of it). The cost of one operation (a FLINT
/// product, quotient or gcd) is bounded by the size of its operands.
inline constexpr long expression_bits = 1L << 20;
/// Bits produced by all the operations of one expression together (2^24 = 16 x the above): an
/// expression cannot repeat a near-limit operation thousands of times.
inline constexpr long expansion_bits = 1L << 24;
/// States, inputs or outputs of a state space read from a file (--ss).
inline constexpr int state_space_dim = 500;
/// Parameters of one scene ([parameters]); each is resolved once, after those it names.
inline constexpr int scene_parameters = 1000;
/// Computation delay of a simulated loop in sample periods (t_d / T): 10^7 is almost 3 hours at
/// T = 1 ms. The delay line holds min(delay, run length) + 2 forces, so a delay longer than the
/// run costs no more memory than the run.
inline constexpr long delay_samples = 10000000;
/// Depth of a node of a TOML text (scene, sweep spec): table header components + dotted-key
/// components + enclosing arrays and inline tables (report/toml_limits.hpp). The deepest example
/// scene is 6 levels deep; toml++ recursed over 50,000 dotted components until the stack ended.
inline constexpr int toml_depth = 64;

}  // namespace hapstab::limits
