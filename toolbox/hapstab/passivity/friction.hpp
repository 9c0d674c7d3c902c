// hapstab/passivity/friction.hpp -- the Coulomb-friction condition of a quantized sampled wall
// (Abbott and Okamura 2005, extended to any FIR wall with delay; derivation in docs/friction.md).
//
// The loop: a mass-damper device (viscous b, Coulomb friction f_c), its position measured by an
// encoder of resolution Delta (round or floor quantizer), the wall W(z) = H(z) z^{-n} =
// sum_k w_k z^{-k} (FIR) applied to the quantized samples, zero-order hold. Then
//
//   passive  <=  b > b* (paper 001 (45)) and f_c >= f_c* = (Delta/2) sum_k |w_k|       (sufficient)
//   f_c >= f_c* is also necessary (for every b) when a sign witness exists: a periodic +-1
//   sequence s whose every switch j (s_{j+1} = -s_j) has s_{j-k} = sign(w_k) s_j for all w_k != 0.
//
// For the spring K (Abbott-Okamura) f_c* = K Delta/2; for the spring-damper K + B(z-1)/(Tz)
// with any integer delay n, f_c* = Delta (K/2 + B/T) (K, B >= 0; witnesses: blocks of n + 1).
// Everything here is exact (rational arithmetic; the witness is searched exhaustively over
// periods up to 2(L + 1), L the last tap, for L <= 7).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/numeric/scalar.hpp"
#include "hapstab/poly/rational_function.hpp"

namespace hapstab::passivity {

/// f_c* of a quantized FIR wall. `tight`: f_c >= f_c* is necessary too (a witness was found);
/// otherwise f_c* is a sufficient level only. `witness`: one period of the sign sequence.
struct FrictionCondition {
  std::vector<rational> taps;  ///< w_0 .. w_L of W(z) = H z^{-n} (powers of z^{-1})
  rational l1 = 0;             ///< sum |w_k|
  rational fc_star = 0;        ///< (Delta/2) l1, exact
  bool tight = false;
  std::vector<int> witness;    ///< +1/-1, one period (empty when none was found)
  std::string why;             ///< how tightness was decided, in words
};

/// The taps of H z^{-n} when it is FIR (reduced denominator a power of z), nullopt otherwise.
/// InputError when H z^{-n} is not causal.
std::optional<std::vector<rational>> fir_taps(const RationalFunction<rational>& H, int delay);

/// A sign witness for the taps (see the header comment), searched over periods 2 .. 2(L + 1);
/// empty when none exists there or L > 7 (not searched).
std::vector<int> sign_witness(const std::vector<rational>& taps);

/// The friction condition. InputError when quantum <= 0 or H z^{-n} is not FIR (the condition is
/// derived for FIR walls only; for IIR walls the l1 norm of the impulse response would be needed).
/// `fractional_delay`: the force switches inside the period; f_c* stays sufficient, tightness is
/// not claimed.
FrictionCondition friction_condition(const RationalFunction<rational>& H, int delay, const rational& quantum,
                                     bool fractional_delay = false);

}  // namespace hapstab::passivity
