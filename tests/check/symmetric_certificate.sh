#!/bin/bash
# Issue 47 item 6: the 128-contact scene (bench/contact_scene.py 128 --compact, 4 classes of 32
# identical DOFs). Its (16) is certified by the split of identical DOFs and written block by block
# (kind multidof-feasible-symmetric): the lifted whole point, 258 states, is beyond the checkers'
# order. Both checkers verify it; an entry of E edited (E no longer invariant) and a block's point
# edited are refuted by both. On 16 contacts, the whole program (--no-symmetry, no split) certifies
# the same claim with a multidof-feasible certificate that `hapstab check` verifies. N = 16's
# certificate is examples/certificates/multidof-feasible-symmetric-contact16.json, byte for byte.
# Usage: symmetric_certificate.sh HAPSTAB
. "$(dirname "$0")/both_checkers.sh"  # sets h (the binary, $1), root, d (a temporary folder)
/usr/bin/python3 "$root/bench/contact_scene.py" 128 --compact > "$d/s128.toml"
cp "$root/tests/cli/scenes/contact_16_identical.toml" "$d/s16.toml"  # bench/contact_scene.py 16 --compact
for n in 128 16; do
  # exit 1: (16) is feasible, but the loop without a coupling is proven NOT stable
  "$h" multidof analyze --quiet --scene "$d/s$n.toml" --certificate "$d/c$n.json" > /dev/null
  test $? -eq 1 || fail "N = $n: multidof analyze did not exit 1"
  test "$(kind "$d/c$n.json")" = multidof-feasible-symmetric || fail "N = $n: kind $(kind "$d/c$n.json")"
  both_verify "$d/c$n.json"
done
cmp "$d/c16.json" "$root/examples/certificates/multidof-feasible-symmetric-contact16.json" ||
  fail "N = 16: not the example of docs/certificates.md"
mutant "$d/c128.json" "$d/e.json" 'c["model"]["environment"]["E"][5][7] = "(" + c["model"]["environment"]["E"][5][7] + ") + 1/1000"'
mutant "$d/c128.json" "$d/p.json" 'P = c["evidence"]["zero_sum"][0]["point"]["P"]; P[0][0] = str(-F(P[0][0]))'
both_refute "$d/e.json" "$d/p.json"
"$h" multidof analyze --quiet --no-symmetry --scene "$d/s16.toml" --certificate "$d/w16.json" > /dev/null
test $? -eq 1 -a "$(kind "$d/w16.json")" = multidof-feasible || fail "N = 16 --no-symmetry: no whole certificate"
"$h" check "$d/w16.json" > /dev/null || fail "N = 16 --no-symmetry: hapstab check did not verify"
echo "symmetric_certificate: N = 128 and 16 verified by both checkers, 2 mutants refuted by both, N = 16's whole point verified"
