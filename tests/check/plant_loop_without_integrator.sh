#!/bin/bash
# Issue 47: `stability --plant` whose device has three poles off s = 0 and none at it (kind
# stability-loop). The checkers realise G = s P and integrate the position: G(0) = 0 makes that one
# conserved quantity of their own, set aside and not claimed (docs/certificates.md). Two loops of
# P = 1/((s + 1)(m s^2 + b s + k)), m = 1, b = 1, k = 5, under H = K at T = 1/1000: the continuous loop
# s^3 + 2 s^2 + 6 s + 5 + K is Hurwitz iff 12 > 5 + K (Routh), so K = 2 is stable and K = 10 is not
# (rho ~ e^{0.135 T}, sampling at 1 kHz keeps both sides). Each certificate is verified by both
# checkers; its claim flipped, or with "conserved": 1, is refuted by both.
# Usage: plant_loop_without_integrator.sh HAPSTAB
. "$(dirname "$0")/both_checkers.sh"  # sets h (the binary, $1), root, d (a temporary folder)
for K in 2 10; do
  "$h" stability --plant '1/((s + 1)*(m*s^2 + b*s + k))' --H K --T 1/1000 --set m=1 --set b=1 --set k=5 --set K=$K \
    --certificate "$d/$K.json" > /dev/null
  e=$?
  want=$([ $K = 2 ] && echo 0 || echo 1)
  test $e -eq "$want" || fail "K = $K: exit $e, expected $want (Routh)"
  test "$(kind "$d/$K.json")" = stability-loop || fail "K = $K: kind $(kind "$d/$K.json")"
  grep -q conserved "$d/$K.json" && fail "K = $K: a conserved quantity claimed (the checkers' own integrator is not the model's)"
  both_verify "$d/$K.json"
  mutant "$d/$K.json" "$d/${K}c.json" 'c["claim"]["conserved"] = 1'
  mutant "$d/$K.json" "$d/${K}f.json" '
s = c["claim"]["stable"]
c["claim"]["stable"] = not s
if s: c["evidence"]["w"] = ["1"] + ["0"] * (len(c["evidence"]["P"]) - 1)
else: del c["evidence"]["w"]'
  both_refute "$d/${K}c.json" "$d/${K}f.json"
done
echo "plant_loop_without_integrator: K = 2 stable, K = 10 NOT stable, verified by both checkers; claim flipped and conserved = 1 refuted by both"
