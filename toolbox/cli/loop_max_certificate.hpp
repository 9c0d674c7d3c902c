// cli/loop_max_certificate.hpp -- the producer of a `stability-loop-max` certificate
// (check/stability_loop_max_check.hpp): `hapstab stability --scene S --max p --certificate FILE`
// beyond one DOF (or with a [coupling]), where p is the whole gain of [environment] or [coupling] or is
// inside one of their tf; and `stability --plant P --H H --max K` with a device pole off s = 0.
//
// From the checker's own closed-loop matrices M(1) and M(2) (check/stability_loop_check.hpp), M(p) =
// (2 - p) M(1) + (p - 1) M(2) in balls. NOT stable at hi: schur_decide's Stein P and w at M(hi).
// The claim's ends a relative delta outside the crossing's enclosure (Krawczyk's, stability/loop_max.hpp,
// is too narrow for a Stein P solved in double; the certificate proves the wider one it prints).
// Where M(0) is only marginally stable (the slow rows L M(0) = L exist), first the first-order start on (0, eps]: P0 and S of
// check/stability_loop_max_check.hpp by an SDP at p = 0 and eps (eps the producer's own first-order cover's
// end, else lo / 4^j), its rounding checked by the checker's own test.
// Stable on [0, lo] (or [eps, lo]): a cover built downward from lo -- at each right end b, the Stein P of the midpoint
// of [a, b] (schur_decide), the width doubled from the last one and halved until that P passes at both
// ends (at most 60 halvings); then as wide as an SDP finds one P for (4, 16, 64, 256 times: P >= I, P -
// M^T P M > 0 at both ends, the margin maximised, lmi/), and b := a, until a = 0. Every piece is checked
// by the checker's test as it is made, and the whole certificate by check/ before it is returned.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hapstab/stability/loop_max.hpp"
#include "hapstab/stability/sampled_loop.hpp"

namespace hapstab::cli {

/// The certificate of sup p in [lo, hi] (claim.printed_lo, printed_hi: decimals of 16 digits, the
/// caller prints them) with lo <= stable_to and hi above the crossing, each a relative delta = 10^-12,
/// 10^-10, 10^-8, 10^-6 or 10^-4 outside the crossing's enclosure (the first that a double Stein solve
/// proves: the certificate's digits, fewer than the crossing's own); sup p = 0 where m fails (M(0) with
/// an eigenvalue outside the circle). InputError (exit 2, no file) naming what has no certificate: p not
/// the gain alone, a loop not affine in it, no first-order start where M(0) is marginal, no Stein P at a
/// point, more than 2048 intervals, an undecided m.
/// What hapstab answered: sup p's outcome, the crossing's enclosure, stable up to stable_to (and, where its
/// own first-order cover served, on (0, first_order_to]).
struct SupClaim {
  Outcome outcome = Outcome::undecided;
  Enclosure<rational> crossing{0, 0};
  rational stable_to = 0, first_order_to = 0, no_crossing_to = 0;
};
/// Of a scene's loop (stability/loop_max.hpp), and of the one-DOF loop (stability/sampled_loop.hpp; +infinity:
/// InputError, no certificate form).
SupClaim sup_claim(const stability::LoopMax& m);
SupClaim sup_claim(const stability::MaxGain& m);

/// `model`: the scene's ({scene, set}, check/scene_model.hpp) or the one-DOF --plant/--H loop's ({plant, H,
/// operator, set, T, delay}: a device pole off s = 0, where the `stability-max` kind's resultant has no
/// exact form).
nlohmann::json stability_loop_max_certificate(const nlohmann::json& model, const std::string& name, const SupClaim& m);
/// The same for a supremum found on the split by identical DOFs (stability/loop_max_symmetric.hpp): kind
/// stability-loop-max-symmetric (check/stability_loop_max_symmetric_check.hpp), the classes the checker's own
/// (identical_dofs), each block's evidence built as above on the block's loops at p = 1 and 2 (the first-order
/// start from lo / 4^j), unstable_at on the first block whose Stein inertia shows M_b(hi) NOT stable. p must be the
/// whole gain of [environment] or inside its tf (else InputError, by name).
nlohmann::json stability_loop_max_symmetric_certificate(const nlohmann::json& model, const std::string& name, const SupClaim& m);
/// sup p = 0 [exact] by a hidden mode unstable for every p (check/stability_loop_max_check.hpp, the hidden form):
/// the scene's model, the claim exact, value 0, and `hidden`, the stability-loop kind's evidence.hidden of the
/// scene's loop (hidden_mode_certificate). Verified before it is returned, else InputError by name.
nlohmann::json stability_loop_max_hidden_certificate(const nlohmann::json& model, const std::string& name, const nlohmann::json& hidden);

}  // namespace hapstab::cli
