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
/// Copies of one repeated scene table (`count`, docs/scene.md "Repeated blocks") and values of one
/// list parameter: 4096 devices is four times the largest haptic arrays of issue 48 (1024
/// actuators); the environment over them is already a 4096 x 4096 matrix.
inline constexpr int scene_copies = 4096;
/// States plus inputs of the block a scene's compact matrix (diagonal / off_diagonal) realises,
/// column by column: its A, B, C and D together are this squared in exact rationals (4096: 16.8
/// million, ~1 GB; a large analysis holds two copies). A 1024-device contact scene realises 3072
/// states on 1024 inputs: 4096 (its analysis: 3.6 GB resident).
inline constexpr long scene_block_order = 4096;
/// Periods of one simulated run (simulate.steps, or simulate.duration / T rounded up), and the
/// range of every time a scene turns into a sample index (an impulse's time, a bias's start, a
/// profile file's t): checked before the conversion (a bias start of 1e16 s at T = 1 ms was 10^19
/// periods, beyond a long, and acted from t = 0).
inline constexpr long run_steps = 4000000000000L;
/// Computation delay of a simulated loop in sample periods (t_d / T): 10^7 is almost 3 hours at
/// T = 1 ms. The delay line holds min(delay, run length) + 2 forces, so a delay longer than the
/// run costs no more memory than the run.
inline constexpr long delay_samples = 10000000;
/// Paper 000's multi-DOF problems (`multidof analyze|design`, multidof/scene_multidof.hpp),
/// checked when the scene is read, before any realisation is built:
/// states of one block V_i of the designed coupling ([multidof.coupling] nbar_i): a coupling
/// filter of order 32 per block is far above the first-order controllers of paper 000 (27);
/// `nbar = [200]` ran 56 s into the design program before it ran out of memory.
inline constexpr int coupling_block_states = 32;
/// ... and of the whole coupling (sum of nbar_i): the block-wise design solves one small program
/// per block, the generic one a program in (sum nbar_i + m)^2 unknowns.
inline constexpr int coupling_states = 256;
/// States of the environment realisation Theorem 5 analyses: the minimal E plus n m shift states
/// of a [delay] of n samples folded into it (z^-n E). The exact re-check of (16) is on matrices
/// of twice this order.
inline constexpr int multidof_states = 1000;
/// Order of the closed-loop matrix of a loop as written (sim/closed_loop.hpp: plant + controller +
/// N (n + 1) delay states): its certified Schur decision costs O(order^3) in double and in Arb balls
/// (1.5 s at 500 states). A one-DOF loop with a long delay does not need it (the one-DOF test's
/// long-delay path takes any n up to criterion_delay).
inline constexpr long closed_loop_states = 1500;
/// Continuous states (devices and operators) of a loop that `multidof design` simulates as its
/// numeric cross-check (never a verdict): the exact zero-order hold of the plant is dense, and a
/// contact scene of 256 devices (768 such states) took 9.8 s and 0.9 GB, 512 devices 54 s and
/// 3.5 GB, 1024 devices over 12 GB. Beyond it the cross-check is skipped and says so; the
/// closed-loop decision still decides (`hapstab simulate` runs any size).
inline constexpr long crosscheck_simulation_states = 1000;
/// Memory of the generic SDP's Schur complement (8 v^2 bytes for v scalar unknowns), checked
/// before the program is posed: a scene whose structure needs the generic path beyond it is
/// refused, naming the order that makes it so.
inline constexpr double generic_sdp_bytes = 2e9;
/// Scalar unknowns of the OPTIONAL least-dissipative program that `multidof analyze` runs after a
/// feasible verdict (multidof/least_dissipative.cpp) on the generic SDP: a 4-DOF contact scene
/// behind 14 samples (62 states, ~2000 unknowns) spent over 4 minutes in DSDP there after its
/// verdict took a second (the witness certificate's mutation campaign, issue 47). Beyond it the
/// search is skipped and the output says so; the verdict and its certified point stand.
inline constexpr double least_dissipative_unknowns = 600;
/// Scalar unknowns of Theorem 5's generic SDP (16) for the VERDICT (multidof/path_generic.cpp), the
/// path tried last, when the structured paths and the witness did not decide -- near the
/// boundary of (16), where its point usually fails the exact re-check anyway. Its interior-point
/// work grows like v^3 per iteration, and faster near the boundary: a 3-DOF linked-walls scene
/// behind 10 samples (678 unknowns) took 6 s, behind 14 (1,188) 10 s, behind 17 (1,653) 200 s,
/// behind 20 (2,223) 400 s, then "undecided". Beyond the limit the path is skipped and named in
/// the verdict, which is then undecided (exit 3) unless an earlier path has one of its own.
inline constexpr double generic_sdp_unknowns = 1200;

/// Decimal digits of the integer part of an argument reduced modulo 2 pi (r(jw) of paper 001 at
/// |w T| < 10^this: `hapstab r`). The reduction computes pi to that many digits (10^5 digits:
/// about 0.1 s); the exact parser takes exponents up to 10^6 and quotients square them.
inline constexpr long periodic_argument_digits = 100000;
/// Depth of a node of a TOML text (scene, sweep spec): table header components + dotted-key
/// components + enclosing arrays and inline tables (report/toml_limits.hpp). The deepest example
/// scene is 6 levels deep; toml++ recursed over 50,000 dotted components until the stack ended.
inline constexpr int toml_depth = 64;

}  // namespace hapstab::limits
