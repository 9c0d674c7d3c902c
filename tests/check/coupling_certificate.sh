#!/bin/bash
# Issue 47 item 1, `multidof design --certificate` (kind multidof-coupling): the designed V meets
# Theorem 4 through Theorem 5. Paper 000's case ii writes examples/certificates/
# multidof-coupling-case-ii.json byte for byte, and 8 identical contacts write theirs; both checkers
# verify both. V's feedthrough doubled (Lemma 1 for V-hat then fails) and P_V's first entry negated
# are refuted by both. 128 contacts, designed on the split (Theorem 4's program on the whole is beyond
# its size), write multidof-coupling-symmetric: both checkers verify it, and refute it with one
# class's g doubled (no longer the image of the blocks' points) or one DOF's V-hat storage negated.
# Usage: coupling_certificate.sh HAPSTAB
set -u
h=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
py() { /usr/bin/python3 "$root/checks/hapstab_check.py" "$@"; }
fail() { echo "coupling_certificate: $*"; exit 1; }
ex="$root/examples/certificates/multidof-coupling-case-ii.json"
"$h" multidof design --quiet --scene "$root/examples/multidof_case_ii_nominal.toml" --certificate "$d/ii.json" > /dev/null ||
  fail "case ii: multidof design did not exit 0"
cmp "$d/ii.json" "$ex" || fail "case ii: not the example of docs/certificates.md"
"$h" multidof design --quiet --scene "$root/tests/cli/scenes/contact_8_identical.toml" --certificate "$d/c8.json" > /dev/null ||
  fail "8 contacts: multidof design did not exit 0"
for f in "$ex" "$d/c8.json"; do
  "$h" check "$f" > /dev/null || fail "$f: hapstab check did not verify"
  py "$f" > /dev/null || fail "$f: the independent checker did not verify"
done
/usr/bin/python3 - "$ex" "$d" <<'PY'
import copy, json, sys
from fractions import Fraction
c = json.load(open(sys.argv[1]))
v = copy.deepcopy(c)
v["model"]["coupling"]["D"] = [[str(2 * Fraction(x)) for x in r] for r in v["model"]["coupling"]["D"]]
json.dump(v, open(sys.argv[2] + "/dv.json", "w"))
p = copy.deepcopy(c)
p["evidence"]["P_V"][0][0] = str(-Fraction(p["evidence"]["P_V"][0][0]))
json.dump(p, open(sys.argv[2] + "/pv.json", "w"))
PY
for m in dv pv; do
  "$h" check "$d/$m.json" > /dev/null; a=$?
  py "$d/$m.json" > /dev/null; b=$?
  test $a -eq 1 -a $b -eq 1 || fail "mutant $m: exits $a and $b, expected 1 and 1"
done
/usr/bin/python3 "$root/bench/contact_scene.py" 128 --compact > "$d/s128.toml"
"$h" multidof design --quiet --scene "$d/s128.toml" --certificate "$d/c128.json" > /dev/null || fail "128 contacts: multidof design did not exit 0"
grep -q '"kind": *"multidof-coupling-symmetric"' "$d/c128.json" || fail "128 contacts: not the multidof-coupling-symmetric kind"
"$h" check "$d/c128.json" > /dev/null || fail "128 contacts: hapstab check did not verify"
py "$d/c128.json" > /dev/null || fail "128 contacts: the independent checker did not verify"
/usr/bin/python3 - "$d/c128.json" "$d" <<'PY'
import copy, json, sys
from fractions import Fraction
c = json.load(open(sys.argv[1]))
g = copy.deepcopy(c)
g["evidence"]["g"][1] = str(2 * Fraction(g["evidence"]["g"][1]))
json.dump(g, open(sys.argv[2] + "/sg.json", "w"))
p = copy.deepcopy(c)
p["evidence"]["P_V"][7][0][0] = str(-Fraction(p["evidence"]["P_V"][7][0][0]))
json.dump(p, open(sys.argv[2] + "/sp.json", "w"))
PY
for m in sg sp; do
  "$h" check "$d/$m.json" > /dev/null; a=$?
  py "$d/$m.json" > /dev/null; b=$?
  test $a -eq 1 -a $b -eq 1 || fail "mutant $m: exits $a and $b, expected 1 and 1"
done
echo "coupling_certificate: case ii, 8 and 128 contacts verified by both checkers, 4 mutants refuted by both"
