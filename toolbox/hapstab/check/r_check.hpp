// hapstab/check/r_check.hpp -- the checker of an `r` certificate: r(jw) = T/(e^{jwT} - 1),
// paper 001 (44), at an exact T > 0 and w != 0.
//
// Theorem: with x = wT (not a multiple of 2 pi, which a non-zero rational never is),
//   T/(e^{jx} - 1) = T e^{-jx/2}/(e^{jx/2} - e^{-jx/2}) = T (cos(x/2) - j sin(x/2))/(2j sin(x/2))
//                  = -T/2 - j (T/2) cot(x/2),
// so Re r = -T/2 exactly and Im r = -(T/2) cot(x/2).
// Checked: claim.re equals -T/2 exactly; claim [im_lo, im_hi] (exact rationals) contains
// -(T/2) cot(wT/2): an MPFI enclosure (mpfi_cot, outward rounding, the error of every operation
// inside the interval) at 128, 256, ... bits until it lies inside [im_lo, im_hi] (verified) or
// outside it (refuted); cot of a non-zero rational is irrational (Lindemann), so an enclosure that
// straddles an end only needs more bits -- up to 2^16 bits, then the claim is refuted as not shown.
// The printed decimal claim.printed_im, when given, must lie in [im_lo, im_hi].
//
// Implements: paper 001 (44).
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_r(const nlohmann::json& certificate);

}  // namespace hapstab::check
