// hapstab/multidof/assumptions.hpp -- Assumption 1 of paper 000, checked on the data.
//
// Both parts are frequency-domain matrix inequalities on a continuous square transfer matrix
// G(s). Over a common denominator, G = N(s)/d(s) (d the lcm of the entries' denominators), so
// for real w
//   |d|^2 He G(jw)                 = (N conj(d) + N^* d)/2                     (He X = (X + X^*)/2)
//   |d|^2 (He G - delta G^* G)(jw) = (N conj(d) + N^* d)/2 - delta N^* N
// are Hermitian matrices of polynomials in w: PSD for every real w iff each principal minor (a
// real polynomial in w) is >= 0 on R, which exact root isolation decides (sign at a rational
// point of every gap between real roots). Up to 4 x 4 blocks (Leibniz minors); larger blocks
// are `undecided`, never failed.
//
//  (b) operator passivity: H(s) (velocity -> force) positive real. Poles: with q = gcd(d(s),
//      d(-s)) (the roots symmetric about the imaginary axis) and d = q h, h must be Hurwitz
//      (exact Routh) and q square-free with all its roots on the axis (q(jw), a real polynomial
//      up to j, has deg q distinct real roots); at each pole s = j w0 the residue
//      N(j w0)/d'(j w0) must be Hermitian PSD -- decided by the signs of the principal minors of
//      N(jw) conj(d'(jw)) at the root w0 of q(jw) (exact: rational w0 evaluated, otherwise a gcd
//      for zero and bisection of the isolating interval for the sign). Then |d|^2 He H(jw) >= 0
//      on R (at the poles by continuity). So a spring k/s, a resonant pair k s/(s^2 + w0^2) and
//      the hand m s + b + k/s (inertia handled by the simulator, lossless) are passive, exactly.
//  (a) device OSP levels: the largest delta with He G - delta G^* G >= 0 and every pole in
//      Re s < 0 (a pole on the axis allows no delta > 0). A mass-damper 1/(m s + b) has level b
//      exactly (storage 1/2 m v^2: d/dt(1/2 m v^2) = v f - b v^2); any other device gets a
//      certified enclosure [lo, hi] by bisection on the exact delta-OSP decision (lo proven
//      OSP, hi proven not). A declared level is accepted only when the device is proven
//      delta-OSP at it (a lower level is conservative).
//
// Implements: paper 000 Assumption 1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hapstab/lti/realization.hpp"
#include "hapstab/multidof/structure.hpp"
#include "hapstab/numeric/result.hpp"

namespace hapstab::multidof {

/// Is the operator H positive real (passive)? holds / fails, exact, the evidence naming the
/// pole, residue or minor that fails, or what was proven; undecided for blocks beyond 4 x 4.
/// H must be square, continuous (Domain::s), with proper entries (InputError otherwise).
Verdict operator_passive(const TransferMatrix& H);

/// A real w and a principal minor (its 0-based rows) of He H(jw) that is < 0 there, exactly (on
/// |d|^2 He H(jw), d the entries' common denominator: negative only where d(jw) != 0): H is not
/// positive real. nullopt when every principal minor is >= 0 on the whole axis, or H is above 4 x 4.
struct NegativeMinor {
  std::vector<size_t> rows;
  rational w;
};
std::optional<NegativeMinor> negative_minor(const TransferMatrix& H);

/// Is the device G (force -> velocity, square, continuous, proper) delta-OSP? Exact.
Verdict device_is_osp(const TransferMatrix& G, const rational& delta);

/// A device's OSP level: `lo` is proven (the device is lo-OSP), `hi` is proven not to be a level
/// (or equal to lo when exact). `verdict` holds when a positive level was proven.
struct DeviceLevel {
  rational lo = 0, hi = 0;
  bool exact = false;
  Verdict verdict;  ///< evidence: how the level was obtained
};
/// `mass_damper`: (m, b) of a 1/(m s + b) device (level b, exact); otherwise bisection.
DeviceLevel device_osp_level(const TransferMatrix& G, const std::optional<std::pair<rational, rational>>& mass_damper);

/// One line of Assumption 1 as checked on a problem's data.
struct AssumptionCheck {
  std::string name;  ///< e.g. "Assumption 1(b): operator 'H1' passive (positive real)"
  Verdict verdict;
};
/// (b) for every operator (its Z_O(s) and name) and (a) for every device of `structure`
/// (OSP level positive definite, exactly; `device_evidence[k]`, when given, says where the k-th
/// device's level comes from). Theorem 5/6's conclusions need every line to hold.
std::vector<AssumptionCheck> check_assumptions(const Structure& structure, const std::vector<TransferMatrix>& operators,
                                               const std::vector<std::string>& operator_names,
                                               const std::vector<std::string>& device_evidence = {});
bool all_hold(const std::vector<AssumptionCheck>& checks);

}  // namespace hapstab::multidof
