// hapstab/check/stability_loop_verdicts_check.hpp -- the checker of a `stability-loop-verdicts` certificate:
// the certified verdicts that `hapstab stability --scene S --max p --certificate FILE` states where the closed loop
// is not affine in p (a coupling with a feedthrough: the bisection on verdicts, conservatism/theorem5_max.hpp).
// There no supremum is proven (stability between the values tried is not), and the command claims exactly:
// "stable at a, NOT stable at b" (the verdict changes in [a, b]), or "NOT stable at every value tried", or
// "stable at every value tried" -- one verdict per value.
//
// Model: {scene, set, name}: the scene as written, the --set values, the parameter p (not in set).
// Claim: {quantity, status "certified", verdicts: [{at: "p/q", stable: true | false}, ...]} (1..64 values,
// distinct). Evidence: {verdicts: [...]}, one whole certificate per claimed value, of kind stability-loop or
// stability-loop-symmetric (check/stability_loop_check.hpp, stability_loop_symmetric_check.hpp: the Stein
// inertia theorem on the closed-loop matrix built from the scene), whose model is exactly {scene, set + {p:
// at}} and whose claim.stable is the claimed verdict. Each is checked by its own kind's checker; nothing of
// the verdicts is taken from the producer. Theorem: none beyond those kinds' -- this kind is their conjunction,
// tied to one scene and one parameter. Verified when every part is; refuted when one is (named by its index);
// malformed when one is or when a part's model or verdict is not the claim's.
#pragma once

#include <nlohmann/json.hpp>

#include "hapstab/check/certificate.hpp"

namespace hapstab::check {

Verdict check_stability_loop_verdicts(const nlohmann::json& certificate);

}  // namespace hapstab::check
