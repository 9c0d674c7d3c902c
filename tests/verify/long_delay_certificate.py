"""`stability --certificate` beyond degree 2000 (every device pole at s = 0, z^n never expanded:
evidence.argument_principle) against a closed form that shares nothing with hapstab: the delayed
integrator 1/s behind a zero-order hold at T = 1 under H = K, c(z) = z^n (z - 1) + K, is stable iff
0 < K < K* = 2 sin(pi/(2 (2n + 1))) (on the circle |z - 1| = K and n theta + (theta + pi)/2 = pi, so
the first crossing is at theta = pi/(2n + 1); Jury's delayed integrator). For each n and K = K*(1 -+ r)
hapstab's verdict must be the closed form's, and both checkers (`hapstab check`,
checks/hapstab_check.py) must verify the certificate it writes; the claim flipped must be refuted.

  long_delay_certificate.py HAPSTAB [--cases N] [--seed S]
exit 0 when every case agrees, else 1.
"""
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction

import mpmath as mp

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FIXED = [(2500, "1e-3"), (2001, "1e-2"), (4000, "1e-4")]  # (n, relative distance r of K from K*)


def kstar(n):
    with mp.workdps(40):
        return 2 * mp.sin(mp.pi / (2 * (2 * n + 1)))


def run(exe, n, K, tmp):
    cert = os.path.join(tmp, "c.json")
    if os.path.exists(cert):
        os.remove(cert)
    r = subprocess.run([exe, "stability", "--plant", "1/s", "--H", "K", "--set", "K=%s" % K, "--T", "1", "--delay", str(n),
                        "--certificate", cert], capture_output=True, text=True, timeout=300)
    return r, cert


def main(argv):
    exe = argv[1]
    cases = int(argv[argv.index("--cases") + 1]) if "--cases" in argv else 0
    seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 1
    rng = random.Random(seed)
    todo = list(FIXED) + [(rng.randint(2001, 6000), rng.choice(["1e-2", "1e-3", "1e-5"])) for _ in range(cases)]
    bad = 0
    with tempfile.TemporaryDirectory(prefix="hapstab-long-cert-") as tmp:
        for n, rel in todo:
            ks = kstar(n)
            for side in (-1, 1):
                with mp.workdps(40):
                    K = Fraction(mp.nstr(ks * (1 + side * mp.mpf(rel)), 25))
                stable = side < 0
                r, cert = run(exe, n, "%d/%d" % (K.numerator, K.denominator), tmp)
                what = "n=%d K=K*(1 %s %s) (%s by the closed form)" % (n, "-" if side < 0 else "+", rel, "stable" if stable else "NOT stable")
                ok = r.returncode == (0 if stable else 1) and os.path.exists(cert)
                why = "exit %d: %s" % (r.returncode, (r.stdout + r.stderr).strip()[:200]) if not ok else ""
                if ok:
                    c = json.load(open(cert))
                    ok = c["claim"]["stable"] == stable and c["evidence"] == {"argument_principle": True}
                    why = "" if ok else "certificate claims %s, evidence %s" % (c["claim"]["stable"], c["evidence"])
                if ok:
                    for checker in ([exe, "check", cert], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), cert]):
                        v = subprocess.run(checker, capture_output=True, text=True, timeout=600)
                        if v.returncode != 0:
                            ok, why = False, "%s exits %d: %s" % (os.path.basename(checker[1]), v.returncode, (v.stdout + v.stderr).strip()[:200])
                    flipped = dict(c, claim=dict(c["claim"], stable=not stable))
                    fpath = os.path.join(tmp, "f.json")
                    json.dump(flipped, open(fpath, "w"))
                    v = subprocess.run([exe, "check", fpath], capture_output=True, text=True, timeout=600)
                    if v.returncode != 1:
                        ok, why = False, "the flipped claim: hapstab check exits %d" % v.returncode
                print(("ok   " if ok else "MISS ") + what + (": " + why if why else ""))
                sys.stdout.flush()
                bad += not ok
    print("long_delay_certificate: %d loops, %d disagree" % (2 * len(todo), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
