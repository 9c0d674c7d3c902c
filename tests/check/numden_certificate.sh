#!/bin/bash
# Issue 47 item 1: H as numbers. `bound`, `wedge`, `limit-cycle --exact` and `passivity-level` with
# --num/--den, or a .mat's num and den, write certificates whose model holds the coefficients as
# written ("num", "den": docs/certificates.md); the claim is the one of the same H written by --H,
# and both checkers verify each. A .mat state space writes the `passivity-level-mimo` kind (its A, B,
# C, D exactly), as a one-input --ss does; for `bound` it is refused by name. A coefficient doubled
# is refuted by both checkers.
# Usage: numden_certificate.sh HAPSTAB
. "$(dirname "$0")/both_checkers.sh"  # sets h (the binary, $1), root, d (a temporary folder)
claim() { /usr/bin/python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))["claim"], sort_keys=True))' "$1"; }
same_claim() { test "$(claim "$1")" = "$(claim "$2")" || fail "$1 and $2: different claims: $(claim "$1") / $(claim "$2")"; }
run() {  # run OUT ARGS...: hapstab ARGS --certificate OUT, exit 0 or 1 (a verdict), and OUT written
  local out=$1
  shift
  "$h" "$@" --certificate "$out" > /dev/null
  local e=$?
  test $e -le 1 -a -f "$out" || fail "$* --certificate: exit $e, or no file"
}
run "$d/b.json" bound --num "6000 -5000" --den "1 0" --T 1/1000 --delay 1
run "$d/bH.json" bound --H "6000 - 5000/z" --T 1/1000 --delay 1
same_claim "$d/b.json" "$d/bH.json"
run "$d/bm.json" bound --mat "$root/examples/data/wall.mat" --T 1/1000
run "$d/bmH.json" bound --H "6000 - 5000/z" --T 1/1000
same_claim "$d/bm.json" "$d/bmH.json"
run "$d/w.json" wedge --num "1 -0.9" --den "1 -0.5 0.06"
run "$d/wH.json" wedge --H "(z - 0.9)/(z^2 - 0.5*z + 0.06)"
same_claim "$d/w.json" "$d/wH.json"
run "$d/lc.json" limit-cycle --num "0 0.9 0.9" --den "1 -0.5 0" --gain 1.2 --steps 20000 --exact
run "$d/lcH.json" limit-cycle --H "0.9*(z+1)/(z^2-0.5*z)" --gain 1.2 --steps 20000 --exact
same_claim "$d/lc.json" "$d/lcH.json"
run "$d/pl.json" passivity-level --num "2 0.2 0.5" --den "1 -0.9 0.3" --T 1/100 --kind osp
run "$d/plH.json" passivity-level --H "(2*z^2 + 0.2*z + 0.5)/(z^2 - 0.9*z + 0.3)" --T 1/100 --kind osp
same_claim "$d/pl.json" "$d/plH.json"
run "$d/pm.json" passivity-level --mat "$root/examples/data/plant.mat" --T 1/100 --kind isp
test "$(kind "$d/pm.json")" = passivity-level-mimo || fail "--mat A, B, C, D: kind $(kind "$d/pm.json")"
printf '{"A": [["1/10"]], "B": [["1"]], "C": [["1"]], "D": [["1"]], "T": "1/100"}' > "$d/siso.json"
run "$d/ps.json" passivity-level --ss "$d/siso.json" --kind osp
grep -q '"value": "9/19"' "$d/ps.json" || fail "one-input --ss: the OSP level is not 9/19 exactly"
both_verify "$d/b.json" "$d/bm.json" "$d/w.json" "$d/lc.json" "$d/pl.json" "$d/pm.json" "$d/ps.json"
"$h" bound --mat "$root/examples/data/plant.mat" --T 1/100 --certificate "$d/no.json" > /dev/null 2> "$d/err"
test $? -eq 2 -a ! -f "$d/no.json" || fail "bound --mat of a state space: not refused (exit 2, no file)"
grep -q "holds a state space" "$d/err" || fail "bound --mat of a state space: the refusal does not say why: $(cat "$d/err")"
mutant "$d/b.json" "$d/b2.json" 'c["model"]["num"][0] = str(2 * F(c["model"]["num"][0]))'
mutant "$d/pl.json" "$d/pl2.json" 'c["model"]["den"][2] = str(2 * F(c["model"]["den"][2]))'
both_refute "$d/b2.json" "$d/pl2.json"
echo "numden_certificate: 7 certificates of H as numbers verified by both checkers (claims as by --H), 2 mutants refuted by both"
