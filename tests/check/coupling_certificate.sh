#!/bin/bash
# Issue 47 item 1, `multidof design --certificate` (kind multidof-coupling): the designed V meets
# Theorem 4 through Theorem 5. Paper 000's case ii writes examples/certificates/
# multidof-coupling-case-ii.json byte for byte, and 8 identical contacts write theirs; both checkers
# verify both. V's feedthrough doubled (Lemma 1 for V-hat then fails) and P_V's first entry negated
# are refuted by both. 128 contacts, designed on the split (Theorem 4's program on the whole is beyond
# its size), write multidof-coupling-symmetric: both checkers verify it, and refute it with one
# class's g doubled (no longer the image of the blocks' points) or one DOF's V-hat storage negated.
# Usage: coupling_certificate.sh HAPSTAB
. "$(dirname "$0")/both_checkers.sh"  # sets h (the binary, $1), root, d (a temporary folder)
ex="$root/examples/certificates/multidof-coupling-case-ii.json"
"$h" multidof design --quiet --scene "$root/examples/multidof_case_ii_nominal.toml" --certificate "$d/ii.json" > /dev/null ||
  fail "case ii: multidof design did not exit 0"
cmp "$d/ii.json" "$ex" || fail "case ii: not the example of docs/certificates.md"
"$h" multidof design --quiet --scene "$root/tests/cli/scenes/contact_8_identical.toml" --certificate "$d/c8.json" > /dev/null ||
  fail "8 contacts: multidof design did not exit 0"
/usr/bin/python3 "$root/bench/contact_scene.py" 128 --compact > "$d/s128.toml"
"$h" multidof design --quiet --scene "$d/s128.toml" --certificate "$d/c128.json" > /dev/null || fail "128 contacts: multidof design did not exit 0"
test "$(kind "$d/c128.json")" = multidof-coupling-symmetric || fail "128 contacts: kind $(kind "$d/c128.json")"
both_verify "$ex" "$d/c8.json" "$d/c128.json"
mutant "$ex" "$d/dv.json" 'c["model"]["coupling"]["D"] = [[str(2 * F(x)) for x in r] for r in c["model"]["coupling"]["D"]]'
mutant "$ex" "$d/pv.json" 'P = c["evidence"]["P_V"]; P[0][0] = str(-F(P[0][0]))'
mutant "$d/c128.json" "$d/sg.json" 'g = c["evidence"]["g"]; g[1] = str(2 * F(g[1]))'
mutant "$d/c128.json" "$d/sp.json" 'P = c["evidence"]["P_V"][7]; P[0][0] = str(-F(P[0][0]))'
both_refute "$d/dv.json" "$d/pv.json" "$d/sg.json" "$d/sp.json"
echo "coupling_certificate: case ii, 8 and 128 contacts verified by both checkers, 4 mutants refuted by both"
