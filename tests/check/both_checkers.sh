# tests/check/both_checkers.sh -- sourced by the certificate scripts of tests/check (their $1: the
# hapstab binary): sets h (that binary), root (the source tree) and d (a temporary folder, removed
# at exit); both checkers on certificate files, and mutants.
set -u
h=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
py() { /usr/bin/python3 "$root/checks/hapstab_check.py" "$@"; }
fail() { echo "$(basename "$0"): $*"; exit 1; }
kind() { /usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["kind"])' "$1"; }
# both checkers say "verified" (exit 0) on every file
both_verify() {
  for f in "$@"; do
    "$h" check "$f" > /dev/null || fail "$f: hapstab check did not verify"
    py "$f" > /dev/null || fail "$f: the independent checker did not verify"
  done
}
# both checkers refute (exit 1) every file
both_refute() {
  local f a b
  for f in "$@"; do
    "$h" check "$f" > /dev/null; a=$?
    py "$f" > /dev/null; b=$?
    test $a -eq 1 -a $b -eq 1 || fail "$f: exits $a and $b, expected 1 and 1"
  done
}
# mutant IN OUT STATEMENT: OUT is the certificate of IN after the Python STATEMENT on it (c; F = Fraction)
mutant() {
  /usr/bin/python3 - "$1" "$2" "$3" <<'PY'
import json, sys
from fractions import Fraction as F
c = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(c, open(sys.argv[2], "w"))
PY
}
