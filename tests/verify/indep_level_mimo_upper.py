"""`passivity-level --ss FILE --kind osp --certificate` where the OSP value is <= 0: the certificate
claims only delta* <= hi ("upper_bound", check/passivity_level_mimo_check.hpp), against a reference
in mpmath that shares no code with hapstab: G(e^{j theta}) = C (zI - A)^-1 B + D by mpmath's own
solve, lambda_min of He G^-1 (2x2, closed form) on 2000 points of [0, pi] and both ends, refined by
golden section around the best three, at 30 digits: ref = the least value found, an upper estimate of
delta* (a sampled minimum).

Drawn: 2x2 stable systems of order 2-3 (A diagonal or a rotation-scaled pair, poles |z| <= 0.9,
dyadic-free small rationals), B, C small integers, D with a negative or small diagonal so that
delta* <= 0 in most draws; a draw with det G near 0 on the circle (the level there unbounded) is
skipped. Required: where hapstab writes an upper bound, both checkers verify it; its hi is not below
the reference (the claim holds: delta* <= ref <= hi... up to 10^-25 relative) nor above it by more
than 10^-12 relative (it is the value printed, not a loose bound); with hi lowered by 1 % both
checkers refute it. Where the LMI's level is the printed result the certificate is "bounds": its lo
(Lemma 1 at P) must not exceed hi, and with lo raised by 1 % + 10^-3 (above hi, so above the level,
as the LMI's lo lies within ~10^-5 of hi in these draws; hi raised to it) both checkers refute it.

  indep_level_mimo_upper.py HAPSTAB [--cases N] [--seed S]
exit 0 when every compared case agrees, else 1.
"""
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as Q

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mpmath as mp  # noqa: E402

from indep_common import both_checkers, cases_and_seed, golden_section  # noqa: E402

def s(q):
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def draw(rng):
    n = rng.choice([2, 2, 3])
    A = [[Q(0)] * n for _ in range(n)]
    if rng.random() < 0.5 or n == 3:
        for i in range(n):
            A[i][i] = Q(rng.randint(-9, 9), 10)
    if n == 2 and A[0][0] == 0 and A[1][1] == 0:  # a rotation-scaled pair: poles r e^{+-j phi}
        a, b = Q(rng.randint(-6, 6), 10), Q(rng.randint(1, 6), 10)
        A = [[a, b], [-b, a]]
    B = [[Q(rng.randint(-2, 2)) for _ in range(2)] for _ in range(n)]
    C = [[Q(rng.randint(-2, 2)) for _ in range(n)] for _ in range(2)]
    D = [[Q(rng.randint(-3, 3), 2), Q(rng.randint(-1, 1), 4)], [Q(rng.randint(-1, 1), 4), Q(rng.randint(-3, 3), 2)]]
    return A, B, C, D


def reference(A, B, C, D):
    """(least lambda_min(He G^-1) found, least |det G| on the grid)."""
    n = len(A)
    Am, Bm, Cm, Dm = (mp.matrix([[mp.mpf(x.numerator) / x.denominator for x in r] for r in M]) for M in (A, B, C, D))

    def lam(th):
        z = mp.expj(th)
        G = Cm * mp.inverse(z * mp.eye(n) - Am) * Bm + Dm
        Gi = mp.inverse(G)
        a, d = mp.re(Gi[0, 0]), mp.re(Gi[1, 1])
        b = (Gi[0, 1] + mp.conj(Gi[1, 0])) / 2
        return (a + d) / 2 - mp.sqrt(((a - d) / 2) ** 2 + abs(b) ** 2), abs(mp.det(G))
    pts = [mp.pi * k / 2000 for k in range(2001)]
    vals = [lam(t) for t in pts]
    dmin = min(v[1] for v in vals)
    order = sorted(range(len(pts)), key=lambda k: vals[k][0])[:3]
    best = min(v[0] for v in vals)
    for k in order:
        lo, hi = pts[max(k - 1, 0)], pts[min(k + 1, 2000)]
        r = golden_section(lambda t: lam(t)[0], lo, hi, it=120)
        best = min(best, r[4], r[5])
    return best, dmin


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv)
    rng = random.Random("level-mimo-upper:%d" % seed)
    agree = bad = 0
    branch = {"upper bound": 0, "bounds (Lemma 1's lo beside hi)": 0, "a level > 0 (not compared)": 0,
              "skipped (det G ~ 0 or refused)": 0}
    with tempfile.TemporaryDirectory(prefix="hapstab-mimo-upper-") as tmp:
        ss, cert, low = (os.path.join(tmp, f) for f in ("ss.json", "c.json", "l.json"))
        for i in range(cases):
            A, B, C, D = draw(rng)
            with open(ss, "w") as f:
                json.dump({"A": [[s(x) for x in r] for r in A], "B": [[s(x) for x in r] for r in B],
                           "C": [[s(x) for x in r] for r in C], "D": [[s(x) for x in r] for r in D], "T": "1/100"}, f)
            if os.path.exists(cert):
                os.remove(cert)
            r = subprocess.run([exe, "passivity-level", "--ss", ss, "--kind", "osp", "--certificate", cert], capture_output=True,
                               text=True, timeout=300)
            what = "case %d: A %s, D %s" % (i, [[s(x) for x in row] for row in A], [[s(x) for x in row] for row in D])
            if not os.path.exists(cert):
                branch["skipped (det G ~ 0 or refused)"] += 1  # unstable A, a zero of G on the circle, no level
                print("skip %s: exit %d, no certificate: %s" % (what, r.returncode, (r.stdout + r.stderr).strip()[:160]))
                continue
            c = json.load(open(cert))
            if c["claim"]["status"] not in ("upper_bound", "bounds"):
                branch["a level > 0 (not compared)"] += 1
                continue
            with mp.workdps(30):
                ref, dmin = reference(A, B, C, D)
            if dmin < mp.mpf(10) ** -8:
                branch["skipped (det G ~ 0 or refused)"] += 1
                print("skip %s: det G ~ %s on the circle" % (what, mp.nstr(dmin, 3)))
                continue
            hi = Q(c["claim"]["hi"])
            ok, line = True, "delta* <= %s (reference %s)" % (c["claim"]["printed_hi"], mp.nstr(ref, 15))
            with mp.workdps(30):  # hi has 17 digits: compared at the reference's precision, not mpmath's default 15
                hif = mp.mpf(hi.numerator) / hi.denominator
                scale = max(1, abs(hif))
                below = hif < ref - mp.mpf(10) ** -25 * scale
                above = hif > ref + mp.mpf(10) ** -12 * scale
            if below:
                ok, line = False, "hi = %s is below the reference's sampled minimum %s: the claim may be false" % (hi, mp.nstr(ref, 20))
            elif above:
                ok, line = False, "hi = %s is above the reference's minimum %s by more than 1e-12 (not the printed value)" % (hi, mp.nstr(ref, 20))
            elif "lo" in c["claim"] and Q(c["claim"]["lo"]) > hi:
                ok, line = False, "lo = %s above hi" % c["claim"]["lo"]
            else:
                c["claim"].pop("printed_hi", None)
                c["claim"]["hi"] = s(hi - abs(hi) / 100 - Q(1, 1000))
                json.dump(c, open(low, "w"))
                good, why = both_checkers(exe, cert, low, "hi lowered by 1 %")
                if good and "lo" in c["claim"]:  # Lemma 1's lo raised by 1 % (past the level <= hi): refuted
                    c = json.load(open(cert))
                    lo = Q(c["claim"].pop("lo"))
                    c["claim"].pop("printed_lo", None)
                    c["claim"]["lo"] = s(lo + abs(lo) / 100 + Q(1, 1000))
                    c["claim"]["hi"] = s(max(hi, Q(c["claim"]["lo"])))
                    c["claim"].pop("printed_hi", None)
                    json.dump(c, open(low, "w"))
                    good, why = both_checkers(exe, cert, low, "Lemma 1's lo raised by 1 %")
                if not good:
                    ok, line = False, why
                elif "lo" in json.load(open(cert))["claim"]:
                    line += ", lo %s by Lemma 1" % json.load(open(cert))["claim"]["printed_lo"]
            if ok:
                branch["bounds (Lemma 1's lo beside hi)" if "lo" in json.load(open(cert))["claim"] else "upper bound"] += 1
            agree += ok
            bad += not ok
            print("%s %s: %s" % ("ok  " if ok else "MISS", what, line))
    print("indep_level_mimo_upper: %d cases, %d agree, %d disagree; %s" % (cases, agree, bad, ", ".join("%s %d" % kv for kv in branch.items())))
    if cases >= 12 and branch["upper bound"] == 0:
        print("indep_level_mimo_upper: TOO FEW COMPARED: no upper bound reached")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
