"""`stability --plant P --H "K + B*(z-1)/(T*z)" --max K --certificate` for devices with a pole off s = 0
(the `stability-max` kind's resultant has no exact form there), whose certificate is of kind
stability-loop-max with the one-DOF model as written (check/stability_loop_max_check.hpp: K proven affine
in H, a cover of Stein P's, the first-order start where the wall at K = 0 is a damper, Stein inertia at hi).
The reference shares none of it: indep_plant_loop_certificate's draw (mass-dampers with two or three lags, a
zero, a second integrator or a spring instead, an operator damper, delays 0-3) and its loop
(indep_loop.build_loop_1dof: P realised here, held by mpmath.expm, the spectral radius at 50 digits).

Required of a certificate (exit 0): both checkers verify it; the reference's rho < 1 at lo k/6, k = 1..6,
rho > 1 at hi, its own first crossing (bisection on rho - 1) inside [lo, hi] (1e-9 relative); every mutant
of tests/check/loop_max_case.py (the plant, H, the delay edited; the claim moved; ...) rejected by both as
it must be (a mutant beyond the independent checker's stated limit, exit 3, is not checked there). sup K = 0
(exit 1): rho > 1 at K = 10^-6. Refusals by name (exit 2) and undecided (exit 3)
are counted apart, never as agreement.

  indep_plant_max_certificate.py HAPSTAB [--cases N] [--seed S]
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

import indep_loop as IL  # noqa: E402
import indep_plant_loop_certificate as IPL  # noqa: E402
from indep_common import cases_and_seed, fstr, poly_str  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "check"))
import loop_max_case as LMC  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MUTANTS = [0]


def rho(c, K):
    with mp.workdps(IL.DPS):
        return IPL.reference_rho(dict(c, K=Q(K)))


def crossing(c, lo, hi):
    """The reference's first crossing in [lo, hi]: bisection on rho - 1 to 1e-12 relative."""
    a, b = Q(lo), Q(hi)
    for _ in range(60):
        if b - a <= b * Q(1, 10 ** 12):
            break
        m = (a + b) / 2
        a, b = (m, b) if rho(c, m) < 1 else (a, m)
    return a, b


def options(c):
    a = ["--plant", "(%s)/(%s)" % (poly_str(c["num"], "s"), poly_str(c["den"], "s")), "--H", "K + %s*(z-1)/(T*z)" % c["B"],
         "--T", "%s" % c["T"], "--delay", str(c["n"])]
    if c["bo"] is not None:
        a += ["--operator", fstr(c["bo"])]
    return a


def checkers_exit(exe, path):
    return tuple(subprocess.run(cmd + [path], capture_output=True, timeout=900).returncode
                 for cmd in ([exe, "check"], ["/usr/bin/python3", os.path.join(TOP, "checks", "hapstab_check.py")]))


def run_case(exe, c, tmp):
    cert, bad = os.path.join(tmp, "c.json"), os.path.join(tmp, "b.json")
    if os.path.exists(cert):
        os.remove(cert)
    r = subprocess.run([exe, "stability"] + options(c) + ["--max", "K", "--json", "--certificate", cert],
                       capture_output=True, text=True, timeout=900)
    if r.returncode == 2:
        return None, "refused by name: " + r.stderr.strip()[:200], "refused"
    if r.returncode == 3:
        return None, "undecided: " + r.stderr.strip()[:200], "undecided"
    if r.returncode not in (0, 1) or not os.path.exists(cert):
        return False, "exit %d without a certificate: %s" % (r.returncode, r.stderr.strip()[:300]), None
    cl = json.load(open(cert))
    if cl["kind"] != "stability-loop-max":
        return None, "kind %s (every pole at s = 0: another campaign's)" % cl["kind"], "other kind"
    verdicts = checkers_exit(exe, cert)
    if verdicts not in ((0, 0), (0, 3)):  # 3: beyond the independent checker's stated limit
        return False, "a checker does not verify the certificate: exits %s" % (verdicts,), None
    lo, hi = Q(cl["claim"]["lo"]), Q(cl["claim"]["hi"])
    if hi == 0:
        r0 = rho(c, Q(1, 10 ** 6))
        if not r0 > 1:
            return False, "sup K = 0 certified, but the reference's rho at K = 1e-6 is %s" % mp.nstr(r0, 15), None
        return True, "sup K = 0 (rho = %s), verified by both" % mp.nstr(r0, 12), "sup = 0"
    for K in [lo * k / 6 for k in range(1, 7)]:
        rk = rho(c, K)
        if not rk < 1:
            return False, "stable on (0, %s] certified, but the reference's rho at %s is %s" % (float(lo), float(K), mp.nstr(rk, 15)), None
    rh = rho(c, hi)
    if not rh > 1:
        return False, "NOT stable at %s certified, but the reference's rho there is %s" % (float(hi), mp.nstr(rh, 15)), None
    a, b = crossing(c, lo, hi)
    tol = hi * Q(1, 10 ** 9)
    if b < lo - tol or a > hi + tol:
        return False, "the reference's crossing [%s, %s] is outside [%s, %s]" % (float(a), float(b), float(lo), float(hi)), None
    for what, mc, want in LMC.mutants(cl, "K")[1:]:
        with open(bad, "w") as f:
            json.dump(mc, f)
        got = checkers_exit(exe, bad)
        if got[1] == 3:  # the mutant (a longer delay, say) beyond the independent checker's stated limit: not checked
            got = (got[0], got[0])
        if not LMC.agrees(got, want):
            return False, "%s: the checkers exit %s (want %s)" % (what, got, "1 or 2" if want is None else want), None
        MUTANTS[0] += 1
    fo = "first_order" in cl["evidence"]
    return True, "sup K in [%.12g, %.12g] (reference crossing %.12g; %d intervals%s, order %d), verified by %s, its mutants rejected" % (
        float(lo), float(hi), float((a + b) / 2), len(cl["evidence"]["cover"]), ", the first-order start" if fo else "",
        len(cl["evidence"]["unstable_at"]["P"]), "both" if verdicts == (0, 0) else "hapstab check (beyond the independent one's limit)"), \
        "certified sup" + (" (first-order start)" if fo else "")


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, 12, 1)
    rng = random.Random("plant-max-certificate:%d" % seed)
    counts, bad = {}, 0
    with tempfile.TemporaryDirectory(prefix="hapstab-plant-max-") as tmp:
        for k in range(cases):
            c = IPL.draw(rng)
            try:
                ok, what, branch = run_case(exe, c, tmp)
            except subprocess.TimeoutExpired:
                ok, what, branch = None, "timeout", "timeout"
            print("%s case %d (%s): %s" % ({True: "ok  ", False: "MISS", None: "skip"}[ok], k,
                                          ", ".join("%s %s" % kv for kv in c["tags"].items()), what), flush=True)
            bad += ok is False
            counts[branch or "disagree"] = counts.get(branch or "disagree", 0) + 1
    print("indep_plant_max_certificate: %d cases, %d disagree; %s; mutants of the certificates %d, each rejected as it must be" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), MUTANTS[0]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
