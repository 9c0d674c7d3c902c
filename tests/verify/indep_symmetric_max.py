"""`stability --scene S --max g` on loops of identical DOFs (stability/loop_max_symmetric.hpp: the supremum as the
least of the small loops' suprema, where the loop splits and has more than 8 DOFs or a class of three or more)
against the whole loop built here in numpy/scipy from the numbers drawn (indep_symmetric_certificate.py's
scenes and reference_rho: per DOF m v' = -(b + b_o) v - k_o x + u, held by scipy's expm, the wall and links
E = g (K0 - D1 z^-1), the delay's buffer), never from hapstab or its checkers.

Scenes: N = 3-24 DOFs in 2-3 interleaved classes, the same draws as the certificate campaign (operators none,
a damper or a damper and a spring; delays 0-2), the maximised parameter the environment's gain g, or (a quarter
of the draws) Kx added inside every wall, diagonal "Kx + K[i] + B[i]*(z-1)/(T*z)" (Kx = 100 in the scene; the
reference adds it to every class's K); with no delay, in 40 % of those draws a coupling V = cv/z on every DOF
(cv = 1/5000, 1/20000 or 1/100000; the reference: x_e = x + V u, u_k = -(E x_e)_k); since stop 77, in 15 % of the
draws (a stream of its own) links that push the first class's DOFs apart, v_0 = -(1.1..2) K_0 / u_0, so that its
zero-sum stiffness is negative and g may move free positions out at first order (sup = 0 by the mirror). The reference's supremum: the whole's
spectral radius rho(g) in double on 400 points geometric in [g0 10^-4, g0 10^4] (g0 the drawn value; Kx: 100), the first
point with rho >= 1 - 1e-12 bisected against the last below to 1e-13 relative: sup_ref; every point below it
stable (rho < 1 - 1e-12) is what the grid can show. Required: hapstab's certified sup (exit 0) within 1e-6
relative of sup_ref (double eigenvalues of a matrix with eigenvalues repeated k - 1 times near |z| = 1: the
crossing's error is ~ sqrt(eps) times the conditioning at worst; 1e-6 leaves three decades) and its path
"symmetry" where the split pays (N > 8, or a class of three or more), and elsewhere only where the loop splits at all
(since stop 77 the split answers where the whole matrix is undecided); sup = 0 (exit 1) only where the
reference's rho at g0 10^-4 is >= 1, and where hapstab says why by the first-order mirror (JSON unstable_on [0, eps]) the
reference's rho > 1 at eps/10 and eps too; undecided (exit 3) counted apart, never as either answer. Where the split
was used, the certificate (kind stability-loop-max-symmetric) verified by both checkers (the independent one within
its 128 DOFs) and, on every K-th such case (--mutants-every K, default 1), each hand edit of
tests/cli/symmetric_max_case.py's max_mutants() given its exit code by both. A certificate refused by name (exit
2 naming --certificate: beyond the kind; until stop 78 Kx with conserved quantities) is counted apart, the answer
compared without it.

  indep_symmetric_max.py HAPSTAB [--cases N] [--seed S] [--mutants-every K]
exit 0 when every compared case agrees, else 1.
"""
import json
import os
import random
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from indep_common import case_files, cases_and_seed, run_cases  # noqa: E402
import indep_symmetric_certificate as ISC  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "cli"))
from symmetric_max_case import max_mutants  # noqa: E402

CHECKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "checks", "hapstab_check.py")
MUTATE = {"every": 1, "split": 0, "mutants": 0}


KX0 = 100  # the scene's value of Kx where it is maximised (inside every wall, K[i] + Kx)


def at(c, x):
    """The case with the maximised parameter at x: the gain g, or Kx added to every class's wall stiffness."""
    if c["max"] == "g":
        return dict(c, g=float(x))
    return dict(c, classes=[dict(k, K=k["K"] + float(x)) for k in c["classes"]])


def reference_sup(c):
    """sup_ref (header), or 0.0 when rho >= 1 at the grid's first point; None when no crossing below x0 10^4."""
    grid = (c["g"] if c["max"] == "g" else KX0) * np.geomspace(1e-4, 1e4, 400)

    def rho(x):
        return ISC.reference_rho(at(c, x))
    prev = None
    for g in grid:
        if rho(g) >= 1 - 1e-12:
            if prev is None:
                return 0.0
            lo, hi = prev, g
            while hi - lo > 1e-13 * hi:
                mid = (lo + hi) / 2
                lo, hi = (mid, hi) if rho(mid) < 1 - 1e-12 else (lo, mid)
            return (lo + hi) / 2
        prev = g
    return None


def splits(c):
    """(the split pays: N > 8 or a class of three or more; the loop splits at all: the path hapstab may take where the
    whole matrix is undecided, since stop 77)."""
    sizes = [c["cls"].count(a) for a in range(len(c["classes"]))]
    alike = len(set(json.dumps(x, sort_keys=True) for x in c["classes"])) < len(c["classes"])
    can = not alike and sum(k >= 2 for k in sizes) >= 1
    return can and (c["N"] > 8 or max(sizes) >= 3), can


def certificate_fails(exe, cert, bad):
    """What is wrong with the split supremum's certificate, or "": verified by both checkers, its mutants (every K-th)."""
    def exits(p):
        return tuple(subprocess.run(cmd, capture_output=True, timeout=600).returncode
                     for cmd in ([exe, "check", p], ["/usr/bin/python3", CHECKER, p]))
    c = json.load(open(cert))
    if c.get("kind") != "stability-loop-max-symmetric":
        return "certificate kind %s" % c.get("kind")
    got = exits(cert)
    if got not in ((0, 0), (0, 3)):
        return "the checkers exit %s on the certificate" % (got,)
    MUTATE["split"] += 1
    if MUTATE["split"] % MUTATE["every"]:
        return ""
    for what, m, code in max_mutants(c):
        with open(bad, "w") as f:
            json.dump(m, f)
        gm = exits(bad)
        if gm not in ((code, code), (code, 3)):
            return "%s: the checkers exit %s (want %d)" % (what, gm, code)
        MUTATE["mutants"] += 1
    return ""


def scene(c):
    """ISC's scene; maximising Kx, Kx added inside every wall (the environment's tf: diagonal)."""
    text = ISC.scene(c)
    if c["max"] == "Kx":
        text = text.replace('diagonal = "K[i] + ', 'diagonal = "Kx + K[i] + ').replace("\n[[device]]", '\nKx = "%d"\n\n[[device]]' % KX0, 1)
    return text


def run_case(exe, c, tmp):
    path, cert, bad = case_files(tmp, scene(c))
    cmd = [exe, "stability", "--scene", path, "--max", c["max"], "--json", "--quiet", "--digits", "12"]
    r = subprocess.run(cmd + ["--certificate", cert], capture_output=True, text=True, timeout=600)
    refused = r.returncode == 2 and "--certificate:" in r.stderr  # no certificate form (named): the answer compared all the same
    if refused:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    ref = reference_sup(c)
    tag = "%s, N %d, %d classes, delay %d, springs %d%s%s" % (c["max"], c["N"], len(c["classes"]), c["n"], sum(x["ko"] > 0 for x in c["classes"]),
                                                          ", coupling 1/%d z" % round(1 / c["cv"]) if c.get("cv") else "",
                                                          ", pushing links" if c.get("push") else "")
    if r.returncode == 3:
        return None, "undecided (sup_ref %s; %s)" % (ref, tag), "undecided"
    if r.returncode not in (0, 1):
        return False, "exit %d: %s (%s)" % (r.returncode, r.stderr.strip()[:300], tag), None
    j = json.loads(r.stdout)
    pays, can = splits(c)
    path_ok = (j.get("path") == "symmetry") == pays or (j.get("path") == "symmetry" and can) or r.returncode == 1
    if r.returncode == 1:
        if ref != 0.0:
            return False, "hapstab: sup = 0, the reference's sup is %s (%s)" % (ref, tag), None
        why = certificate_fails(exe, cert, bad) if j.get("path") == "symmetry" and not refused else ""
        if why:
            return False, "sup = 0 agrees, but %s (%s)" % (why, tag), None
        if "unstable_on" in j:  # the first-order mirror: NOT stable on (0, eps], checked at eps/10 and eps
            eps = float(j["unstable_on"][1])
            rhos = [ISC.reference_rho(at(c, x)) for x in (eps / 10, eps)]
            if min(rhos) <= 1:
                return False, "hapstab: NOT stable on (0, %s], the reference's rho at eps/10, eps: %s (%s)" % (eps, rhos, tag), None
            return True, "sup = 0 by the first-order mirror, rho at eps/10, eps %s (%s)" % (["%.3g" % (x - 1) for x in rhos], tag), "sup = 0 (mirror)"
        return True, "sup = 0 (%s)" % tag, "sup = 0"
    if ref is None or ref == 0.0:
        return False, "hapstab: sup = %s, the reference's %s (%s)" % (j["max"], ref, tag), None
    sup = float(j["sup_enclosure"][0])
    if abs(sup - ref) > 1e-6 * ref:
        return False, "hapstab: sup = %s, the reference's %.15g (%s)" % (j["max"], ref, tag), None
    if not path_ok:
        return False, "path %s, but the split %s (%s)" % (j.get("path"), "pays" if pays else "does not pay", tag), None
    branch = "%s%s: %s" % (c["max"], " coupled" if c.get("cv") else "", "split%s, %s block" % ("" if pays else " (the whole undecided)", "fixed" if j.get("deciding_block") == 0 else "zero-sum") if j.get("path") == "symmetry" else "whole")
    if refused:
        branch += ", certificate refused by name"
    elif j.get("path") == "symmetry":
        why = certificate_fails(exe, cert, bad)
        if why:
            return False, "sup = %s agrees, but %s (%s)" % (j["max"], why, tag), None
    return True, "sup = %s, reference %.12g (%s; %s)" % (j["max"], ref, tag, branch), branch


def main(argv):
    exe = argv[1]
    cases, seed = cases_and_seed(argv, 6, 1)
    if "--mutants-every" in argv:
        MUTATE["every"] = int(argv[argv.index("--mutants-every") + 1])
    rng = random.Random("symmetric-max:%d" % seed)
    push = random.Random("symmetric-max-push:%d" % seed)  # its own stream: the draws above stay those of earlier stops
    def draw():
        c = ISC.draw(rng, (3, 24))
        c["max"] = "Kx" if rng.random() < 0.25 else "g"
        if c["n"] == 0 and rng.random() < 0.4:  # a coupling V = cv/z on every DOF (split with E by both checkers)
            c["cv"] = 1 / rng.choice([5000, 20000, 100000])
        if push.random() < 0.15 and c["classes"][0]["u"] > 0:  # links that push class 0's DOFs apart (v < 0): its zero-sum
            k0 = c["classes"][0]  # stiffness K - u |v| < 0, so g may move free positions OUT at first order (the mirror)
            k0["v"] = -round(k0["K"] / k0["u"] * push.uniform(1.1, 2.0))
            c["push"] = True
        return c
    counts, bad = run_cases(cases, draw, lambda c, tmp: run_case(exe, c, tmp), "hapstab-sym-max-")
    print("indep_symmetric_max: %d cases, %d disagree; %s; %d certificates verified, %d mutants each given its exit code by both" % (
        cases, bad, "; ".join("%s %d" % kv for kv in sorted(counts.items())), MUTATE["split"], MUTATE["mutants"]))
    if cases >= 6 and not any("split" in k for k in counts):
        print("indep_symmetric_max: TOO FEW COMPARED: no split supremum agreed")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
