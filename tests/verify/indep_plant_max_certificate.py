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

  indep_plant_max_certificate.py HAPSTAB [--cases N] [--seed S] [--mutants-every K]   (as indep_loop_max_certificate.py)
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
import indep_loop_max_certificate as ILM  # noqa: E402
import indep_plant_loop_certificate as IPL  # noqa: E402
from indep_common import cases_and_seed  # noqa: E402


def rho(c, K):
    with mp.workdps(IL.DPS):
        return IPL.reference_rho(dict(c, K=Q(K)))


def options(c):
    return IPL.plant_options(c) + ["--H", "K + %s*(z-1)/(T*z)" % c["B"]]


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
    verdicts = ILM.checkers_exit(exe, cert)
    if verdicts not in ((0, 0), (0, 3)):  # 3: beyond the independent checker's stated limit
        return False, "a checker does not verify the certificate: exits %s" % (verdicts,), None
    ok, what, ab = ILM.judge(exe, cl, verdicts, lambda K: rho(c, K), "K", bad)
    if ok is not True or ab is None:
        return ok, what, "sup = 0" if ok else None
    (a, b), lo, hi = ab, Q(cl["claim"]["lo"]), Q(cl["claim"]["hi"])
    fo = "first_order" in cl["evidence"]
    return True, "sup K in [%.12g, %.12g] (reference crossing %.12g; %d intervals%s, order %d), verified by %s, %s" % (
        float(lo), float(hi), float((a + b) / 2), len(cl["evidence"]["cover"]), ", the first-order start" if fo else "",
        len(cl["evidence"]["unstable_at"]["P"]), "both" if verdicts == (0, 0) else "hapstab check (beyond the independent one's limit)",
        ILM.mutants_said()), \
        "certified sup" + (" (first-order start)" if fo else "")


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, 12, 1)
    ILM.mutants_every(argv)
    rng = random.Random("plant-max-certificate:%d" % seed)
    counts, bad = {}, 0
    with tempfile.TemporaryDirectory(prefix="hapstab-plant-max-") as tmp:
        for k in range(cases):
            c = IPL.draw(rng)
            ILM.MUTATE["case"] = k
            try:
                ok, what, branch = run_case(exe, c, tmp)
            except subprocess.TimeoutExpired:
                ok, what, branch = None, "timeout", "timeout"
            print("%s case %d (%s): %s" % ({True: "ok  ", False: "MISS", None: "skip"}[ok], k,
                                          ", ".join("%s %s" % kv for kv in c["tags"].items()), what), flush=True)
            bad += ok is False
            counts[branch or "disagree"] = counts.get(branch or "disagree", 0) + 1
    print("indep_plant_max_certificate: %d cases, %d disagree; %s; mutants of the certificates %d, each rejected as it must be" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), ILM.MUTANTS[0]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
