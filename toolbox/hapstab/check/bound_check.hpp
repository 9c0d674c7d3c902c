// hapstab/check/bound_check.hpp -- the checker of a `bound` certificate: b* of paper 001,
//   b* = sup_{0 <= w <= pi/T} Re{ T H(z) z^-n / (1 - z) } + eta,   z = e^{jwT}     (45), (54)
// for an exact H(z) (the expression as written, its --set values), T > 0, an integer delay
// n >= 0 and eta >= 0. (A fractional delay has no certificate yet.)
//
// Derivation (the checker's own; not passivity::objective): put c = cos(wT), s = sin(wT), so
// z = c + js with s^2 = 1 - c^2, and write every polynomial in z as a(c) + js b(c) (multiplying
// two such: (a1 a2 - (1 - c^2) b1 b2) + js (a1 b2 + a2 b1)). With H = N/D,
//   N(z) conj(z)^n = Nr + js Ni,   D(z) = Dr + js Di,   N conj(z)^n conj(D) = X + js Y,
//   X = Nr Dr + (1 - c^2) Ni Di,   Y = Ni Dr - Nr Di,   and conj(1 - z) = (1 - c) + js, so
//   Re{T W/(1 - z)} = T (1 - c)[X - (1 + c) Y] / (|D|^2 |1 - z|^2),  |1 - z|^2 = 2 (1 - c):
//   f(c) = A(c)/B(c) + eta,  A = T [X - (1 + c) Y],  B = 2 (Dr^2 + (1 - c^2) Di^2) >= 0 on [-1, 1].
// w in [0, pi/T] <-> c in [-1, 1] one to one; f is defined where B(c) > 0 (B = 0 only at poles of
// H on the unit circle, finitely many: b* is the sup over the rest).
//
// Theorem checked (claim "b* in [lo, hi]", or "b* = v" with lo = hi = v):
//   (upper) b* <= hi  iff  P = (hi - eta) B - A >= 0 on [-1, 1]   (B > 0 off finitely many points,
//           and P, B continuous) -- decided exactly by check/nonnegative.hpp (Yun + Sturm);
//   (lower) b* >= lo  if the witness c0 (a rational in [-1, 1], evidence.witness_c) has
//           Ar(c0)/Br(c0) + eta >= lo, exactly, with Ar/Br = A/B reduced (g = gcd(A, B)) and
//           Br(c0) != 0: Ar/Br is continuous at c0 and equals f off the finitely many zeros of B,
//           so it is f's value or limit at c0, and the supremum is at least that.
// Size limit: max(deg N, deg D + n) <= 1000 (the check expands z^-n; degree 300 takes ~7 s), else
// the certificate is refused (InputError) rather than checked for hours.
// Hypotheses verified on the data: T > 0, n >= 0 an integer (at most 100000), eta >= 0, lo <= hi,
// the printed decimals (claim.printed_lo/hi, claim.printed) are the numbers claimed, exactly.
// Not verified here: that H is stable (the premise under which b* is the passivity bound of
// paper 001, not part of the value of the sup); b* = +inf has no certificate yet.
//
// Implements: paper 001 (45), (54).
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_bound(const nlohmann::json& certificate);

}  // namespace hapstab::check
