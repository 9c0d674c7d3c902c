"""`stability --scene S --max g` on 96 held devices in two classes of 48 (tests/cli/scenes/symmetric_held_96.toml):
the supremum by the split of identical DOFs (stability/loop_max_symmetric.hpp). Before the split the whole
closed-loop matrix (384 states) ran for more than 11 minutes; the subprocess here is cut at 120 s (a hang is
a failure, not a timing). Required:
  * exit 0, path "symmetry", three blocks (the fixed space's loop of 2 DOFs, one zero-sum loop per class), the
    supremum the least of the blocks' and its enclosure inside the deciding block's;
  * the reference, the whole loop of 384 states built in numpy/scipy from the scene's numbers
    (tests/check/symmetric_loop_case.py's reference_rho, no code shared with hapstab): spectral radius < 1 at
    12 points geometric in [sup 10^-3, sup (1 - 10^-6)] and > 1 at sup (1 + 10^-6) (a crossing's error in double
    ~ 1e-10 relative here: 10^-6 leaves four decades);
  * --certificate refused by name (no kind holds a split supremum yet: exit 2, "split"), --no-symmetry refused
    by name beyond 64 DOFs (exit 2), and a scene of 8 DOFs in two classes of 4 (a class of three or more) split
    too, its supremum the 96's zero-sum block's (the same one-DOF loop).

  symmetric_max_case.py HAPSTAB
exit 0 when every expectation holds, else 1."""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.join(HERE, "..", "..")
SCENE = os.path.join(HERE, "scenes", "symmetric_held_96.toml")
sys.path.insert(0, os.path.join(TOP, "tests", "check"))
from symmetric_loop_case import reference_rho  # noqa: E402


def main():
    hapstab = sys.argv[1]
    failures = 0

    def expect(what, ok):
        nonlocal failures
        failures += not ok
        print("%s %s" % ("ok  " if ok else "FAIL", what))

    def run(*args, scene=SCENE):
        return subprocess.run([hapstab, "stability", "--scene", scene, "--max", "g", "--quiet"] + list(args),
                              capture_output=True, text=True, timeout=120)
    r = run("--json")
    expect("96 DOFs: exit %d (want 0)" % r.returncode, r.returncode == 0)
    if r.returncode != 0:
        print(r.stderr[:500])
        return 1
    j = json.loads(r.stdout)
    lo, hi = (float(x) for x in j["sup_enclosure"])
    blocks = j.get("blocks", [])
    d = blocks[j["deciding_block"]] if blocks else {}
    expect("path %s, %d blocks, classes %s" % (j.get("path"), len(blocks), [b.get("class") for b in blocks]),
           j.get("path") == "symmetry" and [b.get("class") for b in blocks] == [None, 0, 1])
    expect("sup in [%r, %r], the least of the blocks' (deciding block %s)" % (lo, hi, j.get("deciding_block")),
           all(float(b["sup_enclosure"][1]) >= hi for b in blocks) and float(d["sup_enclosure"][0]) <= lo + 1e-15 * lo)
    sup = (lo + hi) / 2
    below = [reference_rho(g) for g in sup * np.geomspace(1e-3, 1 - 1e-6, 12)]
    above = reference_rho(sup * (1 + 1e-6))
    expect("the reference: max rho below sup %.9f (< 1), rho at sup (1 + 1e-6) %.9f (> 1)" % (max(below), above),
           max(below) < 1 and above > 1)
    with tempfile.TemporaryDirectory() as tmp:
        c = run("--certificate", os.path.join(tmp, "c.json"))
        expect("--certificate: exit %d, '%s'" % (c.returncode, c.stderr.strip()[:120]), c.returncode == 2 and "split" in c.stderr)
        w = run("--no-symmetry")
        expect("--no-symmetry: exit %d, '%s'" % (w.returncode, w.stderr.strip()[:120]), w.returncode == 2 and "64 DOFs" in w.stderr)
        small = os.path.join(tmp, "held_8.toml")
        with open(SCENE) as f:
            open(small, "w").write(f.read().replace("times = 48", "times = 4").replace("count = 96", "count = 8"))
        s = run("--json", scene=small)
        js = json.loads(s.stdout) if s.returncode == 0 else {}
        expect("8 DOFs in two classes of 4: exit %d, path %s, sup %s (the 96's %s)" % (s.returncode, js.get("path"), js.get("max"), j["max"]),
               s.returncode == 0 and js.get("path") == "symmetry" and js.get("max") == j["max"])
    print("symmetric_max_case: %d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
