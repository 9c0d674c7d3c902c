"""A stability-loop certificate beyond the old limits (order 160, 64 DOFs): `stability --scene S --certificate`
on a 32-device contact scene (closed loop of order 224), verified by `hapstab check`; the independent
checker states its limit (order 100) and does not check it (exit 3, named); two hand edits refuted by
`hapstab check` (w zero: w^T P w = 0; the claim flipped to stable: P indefinite).

  large_loop_case.py HAPSTAB SCENE
exit 0 when every expectation holds, else 1 (each failure printed)."""
import json
import os
import subprocess
import sys
import tempfile

from cert_edit import with_field

HERE = os.path.dirname(os.path.abspath(__file__))
INDEPENDENT = os.path.join(HERE, "..", "..", "checks", "hapstab_check.py")


def main():
    hapstab, scene = sys.argv[1:3]
    failures = 0

    def expect(what, ok):
        nonlocal failures
        failures += not ok
        print("%s %s" % ("ok  " if ok else "FAIL", what))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "c.json")
        r = subprocess.run([hapstab, "stability", "--scene", scene, "--certificate", path, "--quiet"], capture_output=True, text=True)
        if r.returncode not in (0, 1) or not os.path.exists(path):
            print("FAIL: no certificate (exit %d): %s" % (r.returncode, r.stderr.strip()))
            return 1
        cert = json.load(open(path))
        n = len(cert["evidence"]["P"])
        expect("a stability-loop certificate of order %d (> 160)" % n, cert["kind"] == "stability-loop" and n > 160)
        c = subprocess.run([hapstab, "check", path], capture_output=True, text=True)
        expect("hapstab check: verified (exit %d)" % c.returncode, c.returncode == 0 and "verified" in c.stdout)
        i = subprocess.run(["/usr/bin/python3", INDEPENDENT, path], capture_output=True, text=True)
        expect("the independent checker: not checked, its limit named (exit %d: %s)" % (i.returncode, (i.stdout + i.stderr).strip()[:120]),
               i.returncode == 3 and "above this checker's limit" in i.stdout + i.stderr)
        stable = cert["claim"]["stable"]
        flipped = with_field(cert, ["claim", "stable"], not stable)
        flipped["evidence"].pop("w", None)  # a stable claim has P alone
        edits = [("the claim flipped (stable: %s, w dropped)" % (not stable), flipped)]
        if "w" in cert["evidence"]:
            edits.append(("w zero (w^T P w = 0)", with_field(cert, ["evidence", "w"], ["0"] * n)))
        for what, e in edits:
            mpath = os.path.join(tmp, "m.json")
            json.dump(e, open(mpath, "w"))
            m = subprocess.run([hapstab, "check", mpath], capture_output=True, text=True)
            expect("%s: hapstab check refutes it (exit %d)" % (what, m.returncode), m.returncode == 1)
    print("large_loop_case: %d failed" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
