"""`stability --certificate` beyond degree 2000 (every device pole at s = 0, z^n never expanded:
evidence.argument_principle) against a closed form that shares nothing with hapstab: the delayed
integrator 1/s behind a zero-order hold at T = 1 under H = K, c(z) = z^n (z - 1) + K, is stable iff
0 < K < K* = 2 sin(pi/(2 (2n + 1))) (on the circle |z - 1| = K and n theta + (theta + pi)/2 = pi, so
the first crossing is at theta = pi/(2n + 1); Jury's delayed integrator). For each n and K = K*(1 -+ r)
hapstab's verdict must be the closed form's, and both checkers (`hapstab check`,
checks/hapstab_check.py) must verify the certificate it writes; the claim flipped must be refuted.

Then devices with poles off s = 0 beyond the checkers' degree 150 (a mass-damper 1/(m s^2 + b s), a
spring 1/(m s^2 + b s + k): e^{pT}, e^{A_c T} in balls) under K + B (z - 1)/(T z), n = 151-500, against
a double-precision reference built here: scipy's zero-order hold (cont2discrete) and numpy's roots
of c(z) = z^n z den_d(z) + ((K + B/T) z - B/T) num_d(z); compared where |1 - rho| > 1e-8 (a
degree-500 companion matrix's eigenvalues near the circle are good to ~1e-12).

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


DEVICES = [("1/(m*s^2 + b*s)", {"m": "1", "b": "1"}, "1/100", "1/10", 200),      # a mass-damper, stable
            ("1/(m*s^2 + b*s + k)", {"m": "1", "b": "1", "k": "1000"}, "3", "1/2", 300),  # a spring
            # the wall's K cancels the spring's k < 0: a root at z = 1 exactly (and one outside)
            ("1/(m*s^2 + b*s + k)", {"m": "1/2", "b": "5", "k": "-50"}, "50", "1/2", 265)]


def reference_rho(plant, sets, K, B, n, T=Fraction(1, 1000)):
    """max |root| of c(z), the sampled loop built in double here (scipy ZOH, numpy roots)."""
    import numpy as np
    import scipy.signal as sg
    m, b, k = (float(Fraction(sets.get(x, "0"))) for x in ("m", "b", "k"))
    num, den, _ = sg.cont2discrete(([1.0], [m, b, k]), float(T), method="zoh")
    num = np.trim_zeros(np.atleast_1d(np.squeeze(num)), "f")
    A = [float(Fraction(K) + Fraction(B) / T), -float(Fraction(B) / T)]
    c = np.polyadd(np.polymul(np.concatenate([[1.0], np.zeros(n + 1)]), den), np.polymul(A, num))
    return float(max(abs(np.roots(c))))


def device_case(exe, plant, sets, K, B, n, tmp):
    rho = reference_rho(plant, sets, K, B, n)
    what = "%s %s K=%s B=%s n=%d (rho %.10f by the double reference)" % (plant, sets, K, B, n, rho)
    if abs(1 - rho) <= 1e-8:
        return None, what + ": too close for the double reference, not compared"
    cert = os.path.join(tmp, "d.json")
    if os.path.exists(cert):
        os.remove(cert)
    args = [exe, "stability", "--plant", plant, "--H", "K + B*(z-1)/(T*z)", "--set", "K=" + K, "--set", "B=" + B,
            "--T", "1/1000", "--delay", str(n), "--certificate", cert]
    for name, v in sets.items():
        args += ["--set", "%s=%s" % (name, v)]
    r = subprocess.run(args, capture_output=True, text=True, timeout=300)
    stable = rho < 1
    if r.returncode == 3:
        return None, what + ": hapstab undecided (exit 3), not compared"
    if r.returncode != (0 if stable else 1) or not os.path.exists(cert):
        return False, what + ": hapstab exits %d: %s" % (r.returncode, (r.stdout + r.stderr).strip()[:200])
    c = json.load(open(cert))
    if c["evidence"] != {"argument_principle": True} or c["claim"]["stable"] != stable:
        return False, what + ": certificate claims %s with evidence %s" % (c["claim"]["stable"], c["evidence"])
    for checker in ([exe, "check", cert], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py"), cert]):
        v = subprocess.run(checker, capture_output=True, text=True, timeout=600)
        if v.returncode != 0:
            return False, what + ": %s exits %d: %s" % (os.path.basename(checker[1]), v.returncode, (v.stdout + v.stderr).strip()[:200])
    return True, what + ": %s, verified by both" % ("stable" if stable else "NOT stable")


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
        devices = list(DEVICES)
        for _ in range(cases):
            plant, sets = rng.choice([("1/(m*s^2 + b*s)", {"m": rng.choice(["1/2", "1", "3"]), "b": rng.choice(["1/5", "1", "2"])}),
                                      ("1/(m*s^2 + b*s + k)", {"m": rng.choice(["1/2", "1"]), "b": rng.choice(["0", "1", "5"]),
                                                               "k": rng.choice(["100", "1000", "-50"])})])
            devices.append((plant, sets, rng.choice(["1/100", "1/10", "1", "5", "50"]), rng.choice(["0", "1/10", "1/2"]),
                            rng.randint(151, 500)))
        compared = skipped = 0
        for case in devices:
            ok, line = device_case(exe, *case, tmp)
            print(("skip " if ok is None else "ok   " if ok else "MISS ") + line)
            skipped += ok is None
            sys.stdout.flush()
            compared += ok is not None
            bad += ok is False
    print("long_delay_certificate: %d integrator loops, %d device loops compared (%d not: too close for the double "
          "reference, or hapstab undecided), %d disagree" % (2 * len(todo), compared, skipped, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
